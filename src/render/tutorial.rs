//! The tutorial's scene as numbers: the floor, the cube, the sun's orbit
//! and box, the camera's lens, the clear colour. Everything the host side
//! (`scene`, `setup`) and the CPU reference build on; it depends on nothing
//! else of the runner.

use glam::Vec3;

/// Half the floor's side: the floor spans [-5, 5] in x and z at y = 0.
pub const FLOOR_HALF: f32 = 5.0;
/// Height of the cube's centre.
pub const CUBE_HOVER: f32 = 1.5;
/// Uniform scale of the [-1, 1] cube.
pub const CUBE_SCALE: f32 = 0.55;
/// Spin rate about [`cube_axis`], radians per second.
pub const CUBE_SPIN: f32 = 0.7;
/// Half-extent of the sun's orthographic box (x and y).
pub const LIGHT_BOX: f32 = 4.0;
pub const LIGHT_NEAR: f32 = 0.1;
pub const LIGHT_FAR: f32 = 20.0;
/// Distance of the sun's eye from the origin.
pub const LIGHT_DISTANCE: f32 = 8.0;
pub const CAMERA_FOVY_DEG: f32 = 50.0;
pub const CAMERA_NEAR: f32 = 0.1;
pub const CAMERA_FAR: f32 = 50.0;
/// Background colour (linear RGB written straight to a UNORM target).
pub const CLEAR: [f64; 3] = [0.04, 0.05, 0.09];
pub const DEFAULT_SHADOW_SIZE: u32 = 1024;

/// Unit vector from the scene towards the sun at time `t`.
pub fn light_dir(t: f32) -> Vec3 {
    let yaw = t * 0.6;
    Vec3::new(yaw.cos(), 1.4, yaw.sin()).normalize()
}

