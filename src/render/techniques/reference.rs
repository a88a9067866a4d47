//! The CPU reference for the technique scenes: the tutorial reference's ray
//! caster ([`crate::render::reference`]) with each technique's light and
//! shading, deciding visibility exactly with a shadow ray towards the light
//! (the spot light's position, or the sun's direction).

use glam::{DVec3, DVec4, Vec3};
use image::{Rgba, RgbaImage};

use crate::render::reference::{self as base, Scene};
use crate::render::scene::{self, FrameParams};

use super::{TechFrame, Technique, SPOT_COS_INNER, SPOT_COS_OUTER, SPOT_SHADOW_FACTOR};

/// A reference frame.
pub struct TechRef {
    /// With exact shadows.
    pub image: RgbaImage,
    /// The same frame with every point fully visible to the light.
    pub lit: RgbaImage,
    /// Pixels whose surface the light reaches (N.L > 0, inside the cone for
    /// the spot) but whose shadow ray is blocked.
    pub shadowed: Vec<bool>,
}

fn unorm(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// `spot_light.das`'s main_fs with its shadow factor given.
pub fn shade_spot(frame: &TechFrame, pos: Vec3, normal: Vec3, is_floor: bool, shadow: f32) -> [f32; 3] {
    let n = normal.normalize();
    let l = (frame.spot_pos - pos).normalize();
    let v = (frame.base.cam_pos - pos).normalize();
    let ndotl = n.dot(l).max(0.0);
    let light = smoothstep(SPOT_COS_OUTER, SPOT_COS_INNER, (-l).dot(frame.spot_dir.normalize())) * shadow;
    let (albedo, gloss) = if is_floor {
        let cells = (pos.x * 0.5 + 100.0).floor() + (pos.z * 0.5 + 100.0).floor();
        let odd = cells - 2.0 * (cells * 0.5).floor();
        (Vec3::splat(if odd < 0.5 { 0.85 } else { 0.30 }) * Vec3::new(0.80, 0.82, 0.88), 0.15)
    } else {
        (Vec3::new(0.85, 0.45, 0.30), 0.5)
    };
    let ambient = Vec3::new(0.10, 0.09, 0.08).lerp(Vec3::new(0.30, 0.34, 0.42), n.y * 0.5 + 0.5);
    let h = (l + v).normalize();
    let spec = if ndotl > 0.0 { n.dot(h).max(0.0).powf(48.0) * gloss } else { 0.0 };
    let color = Vec3::new(1.25, 1.15, 0.95);
    (albedo * (ambient + color * (ndotl * light)) + Vec3::splat(spec * light)).to_array()
}

/// Renders the reference of a technique frame.
pub fn render(technique: Technique, params: &FrameParams) -> TechRef {
    let frame = TechFrame::new(technique, params);
    let scene = Scene::new(&frame.base);
    let (w, h) = (params.width, params.height);
    let inv_vp = (frame.base.proj * frame.base.view).as_dmat4().inverse();
    let to_sun = frame.base.light_dir.as_dvec3().normalize();
    let c = scene::CLEAR;
    let clear = Rgba([unorm(c[0] as f32), unorm(c[1] as f32), unorm(c[2] as f32), 255]);
    let mut image = RgbaImage::from_pixel(w, h, clear);
    let mut lit = image.clone();
    let mut shadowed = vec![false; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let nx = (x as f64 + 0.5) / w as f64 * 2.0 - 1.0;
            let ny = 1.0 - (y as f64 + 0.5) / h as f64 * 2.0;
            let near = inv_vp * DVec4::new(nx, ny, -1.0, 1.0);
            let far = inv_vp * DVec4::new(nx, ny, 1.0, 1.0);
            let o = near.truncate() / near.w;
            let d = (far.truncate() / far.w - o).normalize();
            let Some(hit) = scene.cast(o, d) else { continue };
            let start = hit.pos + hit.normal * 1e-6;
            let (pos, normal) = (hit.pos.as_vec3(), hit.normal.as_vec3());
            let (blocked, reached) = if technique.is_spot() {
                let to_light: DVec3 = frame.spot_pos.as_dvec3() - hit.pos;
                let dist = to_light.length();
                let dir = to_light / dist;
                let blocked = scene.cube(start, dir, 0.0).is_some_and(|(t, _)| t < dist);
                let in_cone = (-dir.as_vec3()).dot(frame.spot_dir) > SPOT_COS_OUTER;
                (blocked, in_cone && hit.normal.dot(dir) > 0.0)
            } else {
                let faces = hit.normal.dot(to_sun) >= 0.05;
                (faces && scene.cube(start, to_sun, 0.0).is_some(), faces)
            };
            let i = (y * w + x) as usize;
            shadowed[i] = blocked && reached;
            let shade = |visible: bool| {
                if technique.is_spot() {
                    shade_spot(&frame, pos, normal, hit.floor, if visible { 1.0 } else { SPOT_SHADOW_FACTOR })
                } else {
                    base::shade(&frame.base, pos, normal, hit.floor, if visible { 1.0 } else { 0.0 })
                }
            };
            let px = |rgb: [f32; 3]| Rgba([unorm(rgb[0]), unorm(rgb[1]), unorm(rgb[2]), 255]);
            image.put_pixel(x, y, px(shade(!blocked)));
            lit.put_pixel(x, y, px(shade(true)));
        }
    }
    TechRef { image, lit, shadowed }
}
