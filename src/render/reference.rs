//! The CPU reference: ray casts the same cube and floor through the same
//! pixel centres as the GPU, shades hits with the same formula as the
//! scene's fragment program, but decides sun visibility exactly, with a
//! shadow ray towards the sun, instead of with a shadow map.
//!
//! Where the two can legitimately disagree, it says so: the sun's
//! orthographic box is +-4 while the floor reaches +-5, so floor points
//! outside the box are looked up in clamped edge texels of the shadow map
//! and get an arbitrary answer on the GPU. [`RefFrame::outside_shadow_map`]
//! marks those pixels.

use glam::{DMat4, DVec3, DVec4, Vec3};
use image::{Rgba, RgbaImage};

use super::scene::{self, Frame, FrameParams, View};

/// A reference frame and what is known about its pixels.
pub struct RefFrame {
    pub image: RgbaImage,
    /// Pixels showing a surface point outside the sun's box (plus a margin
    /// of the PCF footprint), where the shadow map has no data for it.
    pub outside_shadow_map: Vec<bool>,
    /// Pixels showing a surface that faces the sun (N.L >= 0.05) but whose
    /// shadow ray hits the cube.
    pub shadowed: Vec<bool>,
    /// Pixels showing the floor.
    pub floor: Vec<bool>,
}

/// The reference image of a frame.
pub fn render(params: &FrameParams) -> RgbaImage {
    render_frame(params).image
}

/// What a ray hit.
pub(crate) struct Hit {
    pub(crate) t: f64,
    pub(crate) pos: DVec3,
    pub(crate) normal: DVec3,
    pub(crate) floor: bool,
}

pub(crate) struct Scene {
    model: DMat4,
    inv_model: DMat4,
    /// The floor: its height, centre (x, z) and half side in world units.
    floor_y: f64,
    floor_centre: (f64, f64),
    floor_half: f64,
}

impl Scene {
    pub(crate) fn new(frame: &Frame) -> Scene {
        let model = frame.cube_model.as_dmat4();
        let fm = frame.floor_model.as_dmat4();
        let c = fm.transform_point3(DVec3::ZERO);
        let half = fm.transform_vector3(DVec3::X).length() * scene::FLOOR_HALF as f64;
        Scene { model, inv_model: model.inverse(), floor_y: c.y, floor_centre: (c.x, c.z), floor_half: half }
    }

    /// Nearest entry into the cube along `o + t d`, t > `min_t`.
    pub(crate) fn cube(&self, o: DVec3, d: DVec3, min_t: f64) -> Option<(f64, DVec3)> {
        let oo = self.inv_model.transform_point3(o);
        let dd = self.inv_model.transform_vector3(d);
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut axis = 0;
        for a in 0..3 {
            if dd[a].abs() < 1e-15 {
                if oo[a].abs() > 1.0 {
                    return None;
                }
                continue;
            }
            let (mut near, mut far) = ((-1.0 - oo[a]) / dd[a], (1.0 - oo[a]) / dd[a]);
            if near > far {
                std::mem::swap(&mut near, &mut far);
            }
            if near > t0 {
                t0 = near;
                axis = a;
            }
            t1 = t1.min(far);
        }
        if t0 > t1 || t0 <= min_t {
            // Misses, or starts inside / behind: the scene never looks out
            // of the cube, and shadow rays leave surfaces facing the sun.
            return None;
        }
        let mut n = DVec3::ZERO;
        n[axis] = -dd[axis].signum();
        Some((t0, self.model.transform_vector3(n).normalize()))
    }

    fn floor(&self, o: DVec3, d: DVec3, min_t: f64) -> Option<f64> {
        if d.y.abs() < 1e-15 {
            return None;
        }
        let t = (self.floor_y - o.y) / d.y;
        let p = o + d * t;
        let h = self.floor_half;
        (t > min_t && (p.x - self.floor_centre.0).abs() <= h && (p.z - self.floor_centre.1).abs() <= h).then_some(t)
    }

    pub(crate) fn cast(&self, o: DVec3, d: DVec3) -> Option<Hit> {
        let cube = self.cube(o, d, 0.0).map(|(t, n)| Hit { t, pos: o + d * t, normal: n, floor: false });
        let floor = self.floor(o, d, 0.0).map(|t| Hit { t, pos: o + d * t, normal: DVec3::Y, floor: true });
        match (cube, floor) {
            (Some(c), Some(f)) => Some(if c.t <= f.t { c } else { f }),
            (c, f) => c.or(f),
        }
    }
}

/// The scene's fragment program, with `lit` (the sun's visibility) given.
pub fn shade(frame: &Frame, pos: Vec3, normal: Vec3, is_floor: bool, sun_visible: f32) -> [f32; 3] {
    shade_with(frame, pos, normal, is_floor, sun_visible, 0.5)
}

/// [`shade`] with the checker frequency (`CHECKER_FREQ`) given.
pub fn shade_with(frame: &Frame, pos: Vec3, normal: Vec3, is_floor: bool, sun_visible: f32, checker_freq: f32) -> [f32; 3] {
    let n = normal.normalize();
    let l = frame.light_dir.normalize();
    let v = (frame.cam_pos - pos).normalize();
    let n_dot_l = n.dot(l).max(0.0);
    let lit = if n_dot_l < 0.05 { 0.0 } else { sun_visible };
    let sky = n.y * 0.5 + 0.5;
    let ambient = Vec3::new(0.10, 0.09, 0.08).lerp(Vec3::new(0.30, 0.34, 0.42), sky);
    let (albedo, gloss) = if is_floor {
        let cells = (pos.x * checker_freq + 100.0).floor() + (pos.z * checker_freq + 100.0).floor();
        let odd = cells - 2.0 * (cells * 0.5).floor();
        let grey = if odd < 0.5 { 0.85 } else { 0.30 };
        (Vec3::splat(grey) * Vec3::new(0.80, 0.82, 0.88), 0.15)
    } else {
        (Vec3::new(0.85, 0.45, 0.30), 0.5)
    };
    let h = (l + v).normalize();
    let spec = n.dot(h).max(0.0).powf(48.0) * lit * gloss;
    let sun = Vec3::new(1.30, 1.15, 0.90);
    (albedo * (ambient + sun * (n_dot_l * lit)) + Vec3::splat(spec)).to_array()
}

fn to_unorm8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// Renders a reference frame. `View::Lit` omits shadow rays;
/// `View::ShadowMap` ray casts the sun's depth texture instead.
pub fn render_frame(params: &FrameParams) -> RefFrame {
    let frame = Frame::of(params);
    let scene = Scene::new(&frame);
    let (w, h) = (params.width, params.height);
    if params.view == View::ShadowMap {
        return shadow_map(&frame, &scene, params.shadow_size);
    }
    let inv_vp = (frame.proj * frame.view).as_dmat4().inverse();
    let light_vp = frame.light_vp.as_dmat4();
    let to_sun = frame.light_dir.as_dvec3().normalize();
    // The PCF footprint reaches 1.5 texels past the lookup point.
    let margin = 2.0 * 1.5 / params.shadow_size as f64;
    let spot = match params.setup.light {
        super::setup::Light::Spot { pos, .. } => Some(params.setup.world.point(pos).as_dvec3()),
        _ => None,
    };
    let tight = params.setup.shadow.fit.lit_outside();
    let clear = Rgba([to_unorm8(scene::CLEAR[0] as f32), to_unorm8(scene::CLEAR[1] as f32), to_unorm8(scene::CLEAR[2] as f32), 255]);
    let mut image = RgbaImage::from_pixel(w, h, clear);
    let mut outside = vec![false; (w * h) as usize];
    let mut shadowed = vec![false; (w * h) as usize];
    let mut floor = vec![false; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            // The GPU's pixel centre, in GL NDC (y up), for row y from the top.
            let nx = (x as f64 + 0.5) / w as f64 * 2.0 - 1.0;
            let ny = 1.0 - (y as f64 + 0.5) / h as f64 * 2.0;
            let near = inv_vp * DVec4::new(nx, ny, -1.0, 1.0);
            let far = inv_vp * DVec4::new(nx, ny, 1.0, 1.0);
            let o = near.truncate() / near.w;
            let d = (far.truncate() / far.w - o).normalize();
            let Some(hit) = scene.cast(o, d) else { continue };
            let i = (y * w + x) as usize;
            let ls = light_vp * hit.pos.extend(1.0);
            let ndc = ls.truncate() / ls.w;
            // A tight box counts lookups outside it as lit, which is right:
            // it holds every caster that can shadow what is seen.
            outside[i] = !tight && (ls.w <= 0.0 || ndc.x.abs() > 1.0 - margin || ndc.y.abs() > 1.0 - margin || ndc.z > 1.0);
            let faces_sun = hit.normal.dot(to_sun) >= 0.05;
            let scale = params.setup.world.scale as f64;
            let start = hit.pos + hit.normal * 1e-6 * scale;
            let occluded = match spot {
                None => scene.cube(start, to_sun, 0.0).is_some(),
                // A point light: only what lies between the point and the light.
                Some(light) => {
                    let to_light = light - start;
                    scene.cube(start, to_light.normalize(), 0.0).is_some_and(|(t, _)| t < to_light.length())
                }
            };
            let blocked = params.view == View::Final && faces_sun && occluded;
            shadowed[i] = blocked;
            floor[i] = hit.floor;
            let rgb = shade_with(
                &frame,
                hit.pos.as_vec3(),
                hit.normal.as_vec3(),
                hit.floor,
                if blocked { 0.0 } else { 1.0 },
                params.setup.checker_freq,
            );
            image.put_pixel(x, y, Rgba([to_unorm8(rgb[0]), to_unorm8(rgb[1]), to_unorm8(rgb[2]), 255]));
        }
    }
    RefFrame { image, outside_shadow_map: outside, shadowed, floor }
}

/// The sun's depth texture by ray casting: one ray per texel centre along
/// the sun's direction, depth in GL's [0, 1] window range.
fn shadow_map(frame: &Frame, scene: &Scene, n: u32) -> RefFrame {
    let inv = frame.light_vp.as_dmat4().inverse();
    let vp = frame.light_vp.as_dmat4();
    let d = -frame.light_dir.as_dvec3().normalize();
    let mut bytes = Vec::with_capacity((n * n * 4) as usize);
    for y in 0..n {
        for x in 0..n {
            let nx = (x as f64 + 0.5) / n as f64 * 2.0 - 1.0;
            let ny = 1.0 - (y as f64 + 0.5) / n as f64 * 2.0;
            let o = (inv * DVec4::new(nx, ny, -1.0, 1.0)).truncate();
            let depth = match scene.cast(o, d) {
                Some(hit) => {
                    let c = vp * hit.pos.extend(1.0);
                    (c.z / c.w * 0.5 + 0.5).min(1.0) as f32
                }
                None => 1.0,
            };
            bytes.extend_from_slice(&depth.to_le_bytes());
        }
    }
    let size = (n * n) as usize;
    RefFrame {
        image: super::image_ops::depth_to_grey(n, n, &bytes),
        outside_shadow_map: vec![false; size],
        shadowed: vec![false; size],
        floor: vec![false; size],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_hit_from_above_is_its_top_face() {
        let f = Frame::at(0.0, 1.0);
        let s = Scene::new(&f);
        let (t, n) = s.cube(DVec3::new(0.0, 10.0, 0.0), DVec3::NEG_Y, 0.0).unwrap();
        assert!(t > 7.5 && t < 8.5 + 0.55 * 3f64.sqrt());
        // At t = 0 the cube is unrotated: the top face's normal is +y.
        assert!(n.abs_diff_eq(DVec3::Y, 1e-9));
    }

    #[test]
    fn reference_has_a_shadow_on_the_floor() {
        let p = FrameParams::new(1.0, 80, 60);
        let r = render_frame(&p);
        assert!(r.shadowed.iter().filter(|s| **s).count() > 5);
    }
}
