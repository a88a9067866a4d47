//! The shadow scene's host side: meshes, per-frame matrices and the uniform
//! values each draw sets. All math is OpenGL-convention (right-handed view
//! space, clip z in [-w, w]), exactly as the tutorial's host computes it; the
//! shaders adapt to WebGPU/Vulkan clip space, the host does not.

use glam::camera::rh::proj::opengl;
use glam::camera::rh::view::look_at_mat4;
use std::sync::LazyLock;

use glam::{Mat4, Quat, Vec3};

use super::plan;

pub use super::tutorial::*;

/// What a render produces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum View {
    /// The lit, shadowed scene.
    #[default]
    Final,
    /// The sun's depth texture as greyscale (near = dark).
    ShadowMap,
    /// The scene with every surface in sunlight: the main pass samples an
    /// empty shadow map (cleared to the far plane), so only the N.L cut-off
    /// darkens faces turned from the sun. `final` divided by `lit` isolates
    /// the shadowing; comparing `lit` images isolates the lighting formula.
    Lit,
}

impl View {
    pub const ALL: [View; 3] = [View::Final, View::ShadowMap, View::Lit];

    pub fn name(self) -> &'static str {
        match self {
            View::Final => "final",
            View::ShadowMap => "shadow-map",
            View::Lit => "lit",
        }
    }
}

/// One frame's request.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameParams {
    /// Scene time in seconds.
    pub time: f32,
    pub width: u32,
    pub height: u32,
    /// Side of the square shadow map.
    pub shadow_size: u32,
    pub view: View,
    /// Shadow technique and scene variants; the default is the tutorial.
    pub setup: super::setup::Setup,
    /// The light-space bounds (low, high corner) of the receivers the
    /// camera sees, measured on the GPU for [`super::setup::Fit::Visible`]
    /// ([`super::visible`]); `None` until measured.
    pub visible_bounds: Option<(Vec3, Vec3)>,
}

impl FrameParams {
    pub fn new(time: f32, width: u32, height: u32) -> FrameParams {
        FrameParams { time, width, height, shadow_size: DEFAULT_SHADOW_SIZE, view: View::Final, setup: Default::default(), visible_bounds: None }
    }

    pub fn with_view(mut self, view: View) -> FrameParams {
        self.view = view;
        self
    }

    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height.max(1) as f32
    }
}

/// A vertex as the meshes store it: position then normal, 24 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub pos: [f32; 3],
    pub normal: [f32; 3],
}

/// Byte offsets of the vertex fields, by the attribute names the scene's
/// shaders use.
pub const VERTEX_STRIDE: u64 = std::mem::size_of::<Vertex>() as u64;
pub const ATTR_POS: &str = "a_pos";
pub const ATTR_NORMAL: &str = "a_normal";

/// The scene's meshes as frame plans draw them (uploaded once per
/// executor): `a_pos` at byte 0 and `a_normal` at 12, both `Float32x3`.
pub fn mesh(object: Object) -> &'static plan::Mesh {
    static CUBE: LazyLock<plan::Mesh> = LazyLock::new(|| plan_mesh("cube", cube_mesh()));
    static FLOOR: LazyLock<plan::Mesh> = LazyLock::new(|| plan_mesh("floor", floor_mesh()));
    match object {
        Object::Cube => &CUBE,
        Object::Floor => &FLOOR,
    }
}

fn plan_mesh(name: &'static str, m: Mesh) -> plan::Mesh {
    let field = |name, offset| plan::Field { name, offset, format: plan::VertexFormat::Float32x3, per_instance: false };
    plan::Mesh {
        name,
        vertices: bytemuck::cast_slice(&m.vertices).to_vec(),
        stride: VERTEX_STRIDE as u32,
        fields: vec![field(ATTR_POS, 0), field(ATTR_NORMAL, 12)],
        indices: m.indices,
        position: ATTR_POS,
        instances: None,
        points: false,
    }
}

pub struct Mesh {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// The [-1, 1] cube: 6 faces of 4 vertices, each with its face normal, two
/// triangles per face wound counter-clockwise seen from outside.
pub fn cube_mesh() -> Mesh {
    // For each face: normal n and two in-face axes (u, v) with u x v = n, so
    // corners n + su*u + sv*v in the order (+,+) (-,+) (-,-) (+,-) run CCW.
    let faces: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ];
    let mut vertices = Vec::with_capacity(24);
    let mut indices = Vec::with_capacity(36);
    for (n, u, v) in faces {
        let (n, u, v) = (Vec3::from(n), Vec3::from(u), Vec3::from(v));
        debug_assert!(u.cross(v).abs_diff_eq(n, 1e-6));
        let base = vertices.len() as u32;
        for (su, sv) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
            let p = n + u * su + v * sv;
            vertices.push(Vertex { pos: p.into(), normal: n.into() });
        }
        indices.extend_from_slice(&[base, base + 1, base + 2, base + 2, base + 3, base]);
    }
    Mesh { vertices, indices }
}

/// The floor: a square of side `2 * FLOOR_HALF` at y = 0, normal +y, CCW seen
/// from above.
pub fn floor_mesh() -> Mesh {
    let h = FLOOR_HALF;
    let up = [0.0, 1.0, 0.0];
    let corners = [[-h, 0.0, -h], [-h, 0.0, h], [h, 0.0, h], [h, 0.0, -h]];
    Mesh {
        vertices: corners.iter().map(|&pos| Vertex { pos, normal: up }).collect(),
        indices: vec![0, 1, 2, 2, 3, 0],
    }
}

/// The axis the cube spins about.
pub fn cube_axis() -> Vec3 {
    Vec3::new(0.3, 1.0, 0.2).normalize()
}

/// Object-to-world matrix of the cube at time `t`: translate * rotate * scale.
pub fn cube_model(t: f32) -> Mat4 {
    let rot = Quat::from_axis_angle(cube_axis(), t * CUBE_SPIN);
    Mat4::from_scale_rotation_translation(Vec3::splat(CUBE_SCALE), rot, Vec3::new(0.0, CUBE_HOVER, 0.0))
}

pub fn camera_pos(t: f32) -> Vec3 {
    let a = t * 0.35;
    Vec3::new(a.cos() * 5.0, 3.2, a.sin() * 5.0)
}

pub fn camera_target() -> Vec3 {
    Vec3::new(0.0, CUBE_HOVER * 0.5, 0.0)
}

/// Everything the host computes once per frame.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub light_dir: Vec3,
    pub light_view: Mat4,
    pub light_proj: Mat4,
    pub light_vp: Mat4,
    pub cam_pos: Vec3,
    pub view: Mat4,
    pub proj: Mat4,
    pub cube_model: Mat4,
    /// Object-to-world matrix of the floor (identity unless the world is
    /// scaled or moved).
    pub floor_model: Mat4,
}

impl Frame {
    pub fn at(t: f32, aspect: f32) -> Frame {
        let light_dir = light_dir(t);
        let light_view = look_at_mat4(light_dir * LIGHT_DISTANCE, Vec3::ZERO, Vec3::Y);
        let light_proj = opengl::orthographic(-LIGHT_BOX, LIGHT_BOX, -LIGHT_BOX, LIGHT_BOX, LIGHT_NEAR, LIGHT_FAR);
        let cam_pos = camera_pos(t);
        let view = look_at_mat4(cam_pos, camera_target(), Vec3::Y);
        let proj = opengl::perspective(CAMERA_FOVY_DEG.to_radians(), aspect, CAMERA_NEAR, CAMERA_FAR);
        Frame {
            light_dir,
            light_view,
            light_proj,
            light_vp: light_proj * light_view,
            cam_pos,
            view,
            proj,
            cube_model: cube_model(t),
            floor_model: Mat4::IDENTITY,
        }
    }

    /// The frame a request describes. With the default setup this is
    /// exactly [`Frame::at`].
    pub fn of(params: &FrameParams) -> Frame {
        let setup = &params.setup;
        if *setup == super::setup::Setup::default() {
            return Frame::at(params.time, params.aspect());
        }
        let t = params.time;
        let w = setup.world;
        let world = w.matrix();
        let cube_model = world * Mat4::from_translation(Vec3::new(0.0, setup.cube_lift, 0.0)) * cube_model(t);
        let floor_model = world;
        let cam_pos = w.point(camera_pos(t));
        let view = look_at_mat4(cam_pos, w.point(camera_target()), Vec3::Y);
        let proj = opengl::perspective(CAMERA_FOVY_DEG.to_radians(), params.aspect(), CAMERA_NEAR * w.scale, CAMERA_FAR * w.scale);
        let (light_view, mut light_proj) =
            super::setup::light_matrices(setup, t, cube_model, floor_model, proj * view, params.shadow_size);
        if let (super::setup::Fit::Visible, Some((lo, hi)), super::setup::Light::Sun | super::setup::Light::SunDir(_)) =
            (setup.shadow.fit, params.visible_bounds, setup.light)
        {
            light_proj = super::setup::visible_box(light_view, cube_model, lo, hi, params.shadow_size).unwrap_or(light_proj);
        }
        Frame {
            light_dir: setup.light_dir(t),
            light_view,
            light_proj,
            light_vp: light_proj * light_view,
            cam_pos,
            view,
            proj,
            cube_model,
            floor_model,
        }
    }

    /// The draws of either pass, in the tutorial's order: cube, then floor.
    pub fn draws(&self) -> [Draw; 2] {
        [
            Draw { object: Object::Cube, model: self.cube_model, is_floor: 0.0 },
            Draw { object: Object::Floor, model: self.floor_model, is_floor: 1.0 },
        ]
    }
}

/// Uniforms a program must declare for the scene to draw anything sensible.
pub const REQUIRED_UNIFORMS: [&str; 4] = ["u_model", "u_light_vp", "u_view", "u_proj"];

/// Entry points the scene runs: (shadow pass vertex, fragment), (main pass vertex, fragment).
pub const SHADOW_VS: &str = "shadow_vs";
pub const SHADOW_FS: &str = "shadow_fs";
pub const MAIN_VS: &str = "main_vs";
pub const MAIN_FS: &str = "main_fs";

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    Cube,
    Floor,
}

#[derive(Clone, Copy, Debug)]
pub struct Draw {
    pub object: Object,
    pub model: Mat4,
    pub is_floor: f32,
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4Swizzles;

    #[test]
    fn visible_floor_is_inside_the_floor() {
        let f = Frame::at(2.0, 4.0 / 3.0);
        let poly = crate::render::setup::visible_floor(Mat4::IDENTITY, f.proj * f.view);
        assert!(poly.len() >= 3);
        for p in poly {
            assert!(p.x.abs() <= 5.0 + 1e-4 && p.z.abs() <= 5.0 + 1e-4 && p.y.abs() < 1e-5);
        }
    }

    #[test]
    fn tight_box_holds_the_cube() {
        let setup = crate::render::setup::Setup::tuned();
        let f = Frame::at(1.0, 4.0 / 3.0);
        let (view, proj) = crate::render::setup::light_matrices(&setup, 1.0, f.cube_model, Mat4::IDENTITY, f.proj * f.view, 1024);
        for c in crate::render::setup::cube_corners(f.cube_model) {
            let clip = proj * view * c.extend(1.0);
            let ndc = clip.xyz() / clip.w;
            assert!(ndc.x.abs() < 1.0 && ndc.y.abs() < 1.0 && ndc.z.abs() <= 1.0, "{ndc}");
        }
    }


    #[test]
    fn cube_faces_wind_outwards() {
        let m = cube_mesh();
        assert_eq!(m.vertices.len(), 24);
        for tri in m.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|i| Vec3::from(m.vertices[tri[i] as usize].pos));
            let n = Vec3::from(m.vertices[tri[0] as usize].normal);
            assert!((b - a).cross(c - a).dot(n) > 0.0);
        }
        let f = floor_mesh();
        let [a, b, c] = [0, 1, 2].map(|i| Vec3::from(f.vertices[f.indices[i] as usize].pos));
        assert!((b - a).cross(c - a).y > 0.0);
    }

    #[test]
    fn gl_projection_maps_near_far_to_minus_one_one() {
        let f = Frame::at(0.0, 4.0 / 3.0);
        let eye = light_dir(0.0) * LIGHT_DISTANCE;
        let near = f.light_vp * (eye - light_dir(0.0) * LIGHT_NEAR).extend(1.0);
        let far = f.light_vp * (eye - light_dir(0.0) * LIGHT_FAR).extend(1.0);
        assert!((near.z / near.w + 1.0).abs() < 1e-4);
        assert!((far.z / far.w - 1.0).abs() < 1e-4);
    }
}
