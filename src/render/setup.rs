//! How the scene's shadow is made, beyond the tutorial's fixed choices: the
//! shadow filter, how the light's frustum is fitted, the shadow map's depth
//! format, whether the floor is drawn into the shadow map; and the variants
//! of the scene that the hard numerical cases need (a sun direction
//! override, a spot light, a scaled and moved world).
//!
//! [`Setup::default()`] is the tutorial, exactly: every default picture is
//! unchanged. [`Setup::tuned()`] is the configuration that
//! docs/performance.md found to halve the tutorial's shadow error at no more
//! frame time (`umbrac render --quality tuned`).
//!
//! Some choices live in the shader (the PCF footprint, the texel step, the
//! checker frequency): [`Setup::defines`] gives the `-D` definitions that
//! `shaders/shadow.das` takes for them. The renderer only knows the host
//! side (sampler filter, depth format, which draws, matrices); a program
//! compiled without the matching definitions still renders, with the
//! tutorial's 3x3 footprint.

use glam::camera::rh::proj::opengl;
use glam::camera::rh::view::look_at_mat4;
use glam::{Mat4, Vec3, Vec4, Vec4Swizzles};

use super::tutorial as scene;

/// The shadow lookup.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Filter {
    /// One depth compare with a nearest-filtering sampler: hard, blocky edges.
    Tap1,
    /// One depth compare with a linear comparison sampler: the hardware
    /// blends the four nearest compares (2x2 PCF).
    Hardware2x2,
    /// 3 x 3 linear compares one texel apart (the tutorial's).
    #[default]
    Pcf3x3,
    /// 5 x 5 linear compares one texel apart.
    Pcf5x5,
}

impl Filter {
    pub const ALL: [Filter; 4] = [Filter::Tap1, Filter::Hardware2x2, Filter::Pcf3x3, Filter::Pcf5x5];

    pub fn name(self) -> &'static str {
        match self {
            Filter::Tap1 => "1tap",
            Filter::Hardware2x2 => "2x2",
            Filter::Pcf3x3 => "3x3",
            Filter::Pcf5x5 => "5x5",
        }
    }

    /// `PCF_RADIUS` of shaders/shadow.das: taps from -r to r in x and y.
    pub fn radius(self) -> u32 {
        match self {
            Filter::Tap1 | Filter::Hardware2x2 => 0,
            Filter::Pcf3x3 => 1,
            Filter::Pcf5x5 => 2,
        }
    }

    /// Whether the comparison sampler filters linearly (2x2 per tap).
    pub fn linear(self) -> bool {
        self != Filter::Tap1
    }
}

/// How the light's projection box is chosen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Fit {
    /// The tutorial's box: +-4 around the origin, near 0.1, far 20 (scaled
    /// with the world).
    #[default]
    Fixed,
    /// Fitted in light space to what can matter: across the light, the
    /// shadow casters' extent intersected with the visible receivers'
    /// (floor clipped to the camera's frustum, and the cube); along it, from
    /// the nearest caster to the farthest visible receiver. A margin of
    /// texels is kept for the filter's footprint, and lookups outside the
    /// box count as lit.
    Tight,
    /// Fitted each frame to the receivers the camera sees, measured on the
    /// GPU (sample-distribution shadow maps): a camera depth pre-pass, the
    /// DSL compute program `shaders/compute/depth_bounds.das` reducing it
    /// to light-space bounds ([`crate::render::visible`]), then the rule of
    /// [`Fit::Tight`] with those bounds as the receivers. Needs a consumer
    /// that runs compute and frames (Vulkan, GL 4.3); a frame without measured bounds (the CPU
    /// reference, nothing visible) gets the fixed box.
    Visible,
}

impl Fit {
    pub const ALL: [Fit; 3] = [Fit::Fixed, Fit::Tight, Fit::Visible];

    pub fn name(self) -> &'static str {
        match self {
            Fit::Fixed => "fixed",
            Fit::Tight => "tight",
            Fit::Visible => "visible",
        }
    }

    /// Whether the box may leave out receivers that nothing shadows, so
    /// that lookups outside it must count as lit.
    pub fn lit_outside(self) -> bool {
        self != Fit::Fixed
    }
}

/// The shadow map's format.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DepthFormat {
    Depth16,
    Depth24Plus,
    #[default]
    Depth32Float,
}

impl DepthFormat {
    pub const ALL: [DepthFormat; 3] = [DepthFormat::Depth16, DepthFormat::Depth24Plus, DepthFormat::Depth32Float];

    pub fn name(self) -> &'static str {
        match self {
            DepthFormat::Depth16 => "depth16",
            DepthFormat::Depth24Plus => "depth24plus",
            DepthFormat::Depth32Float => "depth32float",
        }
    }
}

/// How the shadow pass is made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ShadowOptions {
    pub filter: Filter,
    pub fit: Fit,
    pub depth: DepthFormat,
    /// Draw only the cube into the shadow map: the floor is the lowest thing
    /// in the scene and can shadow nothing.
    pub casters_only: bool,
}

/// Where the light is.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Light {
    /// The tutorial's sun, circling with time.
    #[default]
    Sun,
    /// A sun in a fixed direction (towards the sun; need not be normalised).
    SunDir(Vec3),
    /// A spot light at `pos` looking at `target`, with a perspective shadow
    /// map of vertical field of view `fov_deg` from `near` to `far`; the
    /// fragment program's lighting still uses one direction (`pos - target`).
    Spot { pos: Vec3, target: Vec3, fov_deg: f32, near: f32, far: f32 },
}

/// The world transform applied to the whole scene: `p -> p * scale + offset`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct World {
    pub scale: f32,
    pub offset: Vec3,
}

impl Default for World {
    fn default() -> World {
        World { scale: 1.0, offset: Vec3::ZERO }
    }
}

impl World {
    pub fn matrix(&self) -> Mat4 {
        Mat4::from_translation(self.offset) * Mat4::from_scale(Vec3::splat(self.scale))
    }

    pub fn point(&self, p: Vec3) -> Vec3 {
        p * self.scale + self.offset
    }

    pub fn is_identity(&self) -> bool {
        *self == World::default()
    }
}

/// Everything about a frame beyond time, size and view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    pub shadow: ShadowOptions,
    pub light: Light,
    pub world: World,
    /// Checker cells per world unit times 2 (`CHECKER_FREQ` of
    /// shaders/shadow.das; 0.5 gives 2-unit cells).
    pub checker_freq: f32,
    /// Moves the cube up (or, negative, down into the floor: a caster that
    /// touches its receiver, the case where peter-panning shows).
    pub cube_lift: f32,
}

impl Default for Setup {
    fn default() -> Setup {
        Setup { shadow: ShadowOptions::default(), light: Light::default(), world: World::default(), checker_freq: 0.5, cube_lift: 0.0 }
    }
}

/// Named setups for `umbrac render --quality`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Quality {
    /// The tutorial's configuration.
    #[default]
    Tutorial,
    /// Less than half the tutorial's shadow error for no more frame time
    /// (docs/performance.md).
    Tuned,
}

impl Quality {
    pub const ALL: [Quality; 2] = [Quality::Tutorial, Quality::Tuned];

    pub fn name(self) -> &'static str {
        match self {
            Quality::Tutorial => "tutorial",
            Quality::Tuned => "tuned",
        }
    }
}

impl Setup {
    /// The tuned configuration: a light box fitted to the visible receivers
    /// and the casters, only the cube drawn into the map, one hardware 2x2
    /// compare instead of nine, a 32-bit float map. Use with a shadow map of
    /// [`Setup::TUNED_SHADOW_SIZE`].
    pub fn tuned() -> Setup {
        Setup {
            shadow: ShadowOptions { filter: Filter::Hardware2x2, fit: Fit::Tight, depth: DepthFormat::Depth32Float, casters_only: true },
            ..Setup::default()
        }
    }

    /// Shadow map side that goes with [`Setup::tuned`].
    pub const TUNED_SHADOW_SIZE: u32 = 1024;

    pub fn of_quality(q: Quality) -> Setup {
        match q {
            Quality::Tutorial => Setup::default(),
            Quality::Tuned => Setup::tuned(),
        }
    }

    /// The `-D` definitions shaders/shadow.das takes for the shader side of
    /// this setup with a shadow map of side `shadow_size`. Empty for the
    /// tutorial's own choices (1024, 3x3, 2-unit checker), so the default
    /// compile is untouched.
    pub fn defines(&self, shadow_size: u32) -> Vec<(String, Option<String>)> {
        let mut d = Vec::new();
        if self.shadow.filter.radius() != 1 {
            d.push(("PCF_TAPS_RADIUS".to_string(), Some(self.shadow.filter.radius().to_string())));
        }
        if shadow_size != scene::DEFAULT_SHADOW_SIZE {
            d.push(("SHADOW_TEXELS".to_string(), Some(format!("{shadow_size}.0"))));
        }
        if self.checker_freq != 0.5 {
            d.push(("CHECKER_FREQ".to_string(), Some(format!("{:?}", self.checker_freq))));
        }
        d
    }

    /// Unit vector towards the light, used for shading.
    pub fn light_dir(&self, t: f32) -> Vec3 {
        match self.light {
            Light::Sun => scene::light_dir(t),
            Light::SunDir(d) => d.normalize(),
            Light::Spot { pos, target, .. } => (pos - target).normalize(),
        }
    }
}

/// An up vector for a view along `dir` that is never parallel to it: +y,
/// unless `dir` is within about 2.6 degrees of vertical, then +z.
pub fn up_for(dir: Vec3) -> Vec3 {
    if dir.normalize().y.abs() > 0.999 {
        Vec3::Z
    } else {
        Vec3::Y
    }
}

/// The light's view and projection for a frame, before the world scale is
/// applied to anything but the inputs: `cube_model` and `floor_model` are
/// world matrices, `cam_vp` the camera's projection * view.
pub fn light_matrices(setup: &Setup, t: f32, cube_model: Mat4, floor_model: Mat4, cam_vp: Mat4, shadow_size: u32) -> (Mat4, Mat4) {
    let w = setup.world;
    let s = w.scale;
    let centre = w.point(Vec3::ZERO);
    let (view, perspective) = match setup.light {
        Light::Sun | Light::SunDir(_) => {
            let dir = setup.light_dir(t);
            (look_at_mat4(centre + dir * scene::LIGHT_DISTANCE * s, centre, up_for(dir)), None)
        }
        Light::Spot { pos, target, fov_deg, near, far } => {
            let (p, tg) = (w.point(pos), w.point(target));
            let up = up_for(p - tg);
            (look_at_mat4(p, tg, up), Some((fov_deg, near * s, far * s)))
        }
    };
    if let Some((fov, near, far)) = perspective {
        return (view, opengl::perspective(fov.to_radians(), 1.0, near, far));
    }
    let fixed = || {
        let b = scene::LIGHT_BOX * s;
        opengl::orthographic(-b, b, -b, b, scene::LIGHT_NEAR * s, scene::LIGHT_FAR * s)
    };
    match setup.shadow.fit {
        Fit::Fixed => (view, fixed()),
        Fit::Tight => (view, tight_box(view, cube_model, floor_model, cam_vp, shadow_size).unwrap_or_else(fixed)),
        // The measured bounds replace this in `scene::Frame::of`.
        Fit::Visible => (view, fixed()),
    }
}

/// The 8 corners of the [-1, 1] cube under `model`.
pub fn cube_corners(model: Mat4) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        let c = Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, if i & 4 == 0 { -1.0 } else { 1.0 });
        model.transform_point3(c)
    })
}

/// The floor square under `model`, clipped to the camera's frustum: the
/// corners of the visible floor polygon (empty when none is visible).
pub fn visible_floor(floor_model: Mat4, cam_vp: Mat4) -> Vec<Vec3> {
    let h = scene::FLOOR_HALF;
    let mut poly: Vec<Vec3> =
        [[-h, -h], [h, -h], [h, h], [-h, h]].iter().map(|&[x, z]| floor_model.transform_point3(Vec3::new(x, 0.0, z))).collect();
    // Frustum planes from the rows of projection * view (Gribb & Hartmann):
    // a point is inside when row3 . p +- rowN . p >= 0.
    let r = [cam_vp.row(0), cam_vp.row(1), cam_vp.row(2), cam_vp.row(3)];
    let planes = [r[3] + r[0], r[3] - r[0], r[3] + r[1], r[3] - r[1], r[3] + r[2], r[3] - r[2]];
    for plane in planes {
        let dist = |p: Vec3| plane.dot(p.extend(1.0));
        let mut out = Vec::with_capacity(poly.len() + 2);
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            let (da, db) = (dist(a), dist(b));
            if da >= 0.0 {
                out.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                out.push(a + (b - a) * (da / (da - db)));
            }
        }
        poly = out;
        if poly.is_empty() {
            break;
        }
    }
    poly
}

fn bounds(points: impl IntoIterator<Item = Vec3>) -> Option<(Vec3, Vec3)> {
    points.into_iter().fold(None, |acc, p| match acc {
        None => Some((p, p)),
        Some((lo, hi)) => Some((lo.min(p), hi.max(p))),
    })
}

/// The tight orthographic box of [`Fit::Tight`] in the light's view space.
fn tight_box(view: Mat4, cube_model: Mat4, floor_model: Mat4, cam_vp: Mat4, shadow_size: u32) -> Option<Mat4> {
    let to_light = |p: Vec3| (view * p.extend(1.0)).xyz();
    let casters = cube_corners(cube_model);
    let mut receivers: Vec<Vec3> = visible_floor(floor_model, cam_vp);
    receivers.extend_from_slice(&casters);
    let (c_lo, c_hi) = bounds(casters.iter().map(|&p| to_light(p)))?;
    let (r_lo, r_hi) = bounds(receivers.iter().map(|&p| to_light(p)))?;
    Some(fit_box(c_lo, c_hi, r_lo, r_hi, shadow_size))
}

/// The box of [`Fit::Visible`]: [`Fit::Tight`]'s rule with the receivers'
/// light-space bounds `r_lo`..`r_hi` measured from the camera's depth
/// buffer instead of clipped from the scene's geometry.
pub fn visible_box(view: Mat4, cube_model: Mat4, r_lo: Vec3, r_hi: Vec3, shadow_size: u32) -> Option<Mat4> {
    let (c_lo, c_hi) = bounds(cube_corners(cube_model).iter().map(|&p| (view * p.extend(1.0)).xyz()))?;
    Some(fit_box(c_lo, c_hi, r_lo, r_hi, shadow_size))
}

/// The orthographic box over casters `c_lo..c_hi` and receivers
/// `r_lo..r_hi`, both in the light's view space.
fn fit_box(c_lo: Vec3, c_hi: Vec3, r_lo: Vec3, r_hi: Vec3, shadow_size: u32) -> Mat4 {
    // Across the light: where a caster's shadow can land on something seen.
    let lo = c_lo.max(r_lo);
    let hi = c_hi.min(r_hi);
    let (lo, hi) = if lo.x < hi.x && lo.y < hi.y { (lo, hi) } else { (c_lo, c_hi) };
    // Keep 4 texels of margin on each side for the widest filter (5x5
    // linear taps reach 2.5 texels), and square texels.
    let half = ((hi.x - lo.x).max(hi.y - lo.y) * 0.5).max(1e-6);
    let half = half / (1.0 - 8.0 / shadow_size.max(16) as f32);
    let mid = (lo + hi) * 0.5;
    // Along the light (view z is negative ahead): from just before the
    // nearest caster to just past the farthest receiver.
    let near = -c_hi.z.max(r_hi.z);
    let far = -c_lo.z.min(r_lo.z);
    let pad = (far - near).max(1e-6) * 0.01;
    opengl::orthographic(mid.x - half, mid.x + half, mid.y - half, mid.y + half, near - pad, far + pad)
}

/// Whether a point in the light's clip space (`clip = light_vp * p`) is
/// inside the shadow map with `margin_texels` to spare, and in front of
/// the light.
pub fn inside_light(clip: Vec4, shadow_size: u32, margin_texels: f32) -> bool {
    if clip.w <= 0.0 {
        return false;
    }
    let ndc = clip.xyz() / clip.w;
    let m = 1.0 - 2.0 * margin_texels / shadow_size as f32;
    ndc.x.abs() <= m && ndc.y.abs() <= m && ndc.z <= 1.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_down_view_is_finite() {
        let dir = Vec3::Y;
        let v = look_at_mat4(dir * 8.0, Vec3::ZERO, up_for(dir));
        assert!(v.is_finite());
        let naive = look_at_mat4(dir * 8.0, Vec3::ZERO, Vec3::Y);
        assert!(!naive.is_finite(), "glam's look_at with a parallel up should be degenerate");
    }

    #[test]
    fn default_defines_are_empty() {
        assert!(Setup::default().defines(1024).is_empty());
        let d = Setup { shadow: ShadowOptions { filter: Filter::Pcf5x5, ..Default::default() }, ..Default::default() }.defines(2048);
        assert_eq!(d.len(), 2);
    }
}
