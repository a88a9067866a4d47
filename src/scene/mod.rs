//! A scene: what a host draws a program with, as plain data. Render
//! targets, textures (built-in patterns or an image file), passes (which
//! program, which attachments, which texture each sampler reads), draws
//! (a built-in mesh, maybe as an instance grid, with each vertex input fed
//! by a named attribute of that mesh) and uniform values (numbers, or a
//! documented convention such as `time` or `view`), plus a control hint
//! for every uniform a page can show.
//!
//! Written by hand as a TOML or JSON file (`umbrac render --scene FILE`,
//! docs/runner.md, "Scene files"), or inferred from a program's manifest
//! ([`Scene::infer`], in [`infer`]). The native runner turns one into a
//! frame plan (`render::scene_file`); the preview page reads the same
//! value from the bundle's `scene` key. Nothing here needs a GPU.

pub mod infer;
mod names;

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

pub use infer::InferError;

/// The name of the image a scene shows: the window, or the PNG written.
pub const SCREEN: &str = "screen";

/// A whole scene. Field names are the file format's keys.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// The orbit camera the matrix conventions (`view`, `projection`,
    /// `camera_position`, ...) are computed from.
    #[serde(default)]
    pub camera: OrbitCamera,
    /// Textures made before the frame: patterns or image files.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub textures: Vec<Texture>,
    /// Render targets passes draw into and later passes sample.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub targets: Vec<RenderTarget>,
    /// In order.
    pub passes: Vec<Pass>,
    /// The target shown (written): [`SCREEN`] or a target's name.
    #[serde(default = "screen")]
    pub output: String,
    /// Values every pass sets, by uniform (or uniform block member) name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub values: BTreeMap<String, ValueSpec>,
    /// The light the `light_*` conventions describe; none: [`Light`]'s
    /// default, a still sun.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "checked")]
    pub light: Option<Light>,
    /// One per uniform the program reads: how a page lets the user set it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub controls: Vec<Control>,
}

fn screen() -> String {
    SCREEN.to_string()
}

/// A camera circling `target`: at `distance`, `yaw` degrees about +y from
/// +z, `pitch` degrees above the horizon; right-handed, y up, GL clip
/// space (z in [-1, 1]) for `projection`. `spin` turns the yaw by that many
/// degrees a second of `time`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OrbitCamera {
    pub target: [f32; 3],
    pub distance: f32,
    pub yaw: f32,
    pub pitch: f32,
    pub spin: f32,
    /// Vertical field of view, degrees.
    pub fov_y: f32,
    pub near: f32,
    pub far: f32,
}

impl Default for OrbitCamera {
    fn default() -> OrbitCamera {
        OrbitCamera { target: [0.0; 3], distance: 3.0, yaw: 35.0, pitch: 25.0, spin: 0.0, fov_y: 45.0, near: 0.1, far: 100.0 }
    }
}

impl OrbitCamera {
    /// The eye's position at `time` seconds.
    pub fn eye(&self, time: f32) -> [f32; 3] {
        let yaw = (self.yaw + self.spin * time).to_radians();
        let pitch = self.pitch.to_radians();
        let t = self.target;
        [
            t[0] + self.distance * pitch.cos() * yaw.sin(),
            t[1] + self.distance * pitch.sin(),
            t[2] + self.distance * pitch.cos() * yaw.cos(),
        ]
    }
}

/// A texture made before the frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Texture {
    pub name: String,
    /// A built-in pattern ...
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pattern: Option<Pattern>,
    /// ... or a PNG or JPEG file, relative to the scene file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub image: Option<String>,
    /// Texels of a pattern (an image has its own size); a cube's faces
    /// are square.
    #[serde(default = "pattern_size")]
    pub size: [u32; 2],
    /// What a sampler sees: a 2D texture, a cube map, a 3D texture or a
    /// 2D array (patterns only).
    #[serde(default, skip_serializing_if = "TextureKind::is_2d")]
    pub kind: TextureKind,
    /// Slices of a `3d` texture, layers of a `2d_array` (1 to 256).
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub layers: u32,
}

fn one() -> u32 {
    1
}

fn is_one(n: &u32) -> bool {
    *n == 1
}

/// The kinds of texture a sampler reads (a sampler's `dimension` in the
/// manifest: `2d`, `cube`, `3d`, `2d-array`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TextureKind {
    #[default]
    #[serde(rename = "2d")]
    D2,
    Cube,
    #[serde(rename = "3d")]
    D3,
    #[serde(rename = "2d_array")]
    D2Array,
}

impl TextureKind {
    fn is_2d(&self) -> bool {
        *self == TextureKind::D2
    }

    /// The kind a manifest's sampler `dimension` asks for.
    pub fn of_dimension(dimension: &str) -> Option<TextureKind> {
        match dimension {
            "2d" => Some(TextureKind::D2),
            "cube" => Some(TextureKind::Cube),
            "3d" => Some(TextureKind::D3),
            "2d-array" => Some(TextureKind::D2Array),
            _ => None,
        }
    }
}

impl Texture {
    /// A pattern texture's texels: each layer (a cube's faces +x, -x, +y,
    /// -y, +z, -z) after the other, each row 0 first; and how many layers.
    pub fn pattern_texels(&self, pattern: Pattern) -> (Vec<u8>, u32) {
        let [w, h] = self.size;
        match self.kind {
            TextureKind::D2 => (pattern.texels(w, h), 1),
            TextureKind::Cube => ((0..6).flat_map(|f| pattern.layer(w, h, f)).collect(), 6),
            TextureKind::D3 | TextureKind::D2Array => ((0..self.layers).flat_map(|l| pattern.layer(w, h, l)).collect(), self.layers),
        }
    }
}

fn pattern_size() -> [u32; 2] {
    [64, 64]
}

/// The built-in patterns (RGBA8; docs/runner.md says which texels each has).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Pattern {
    /// 8 x 8 squares, light grey and dark grey.
    Checker,
    /// Value noise, grey, the same texels everywhere (a fixed hash).
    Noise,
    /// Red = u, green = v, blue 0.5.
    Uv,
    /// The flat normal (0.5, 0.5, 1) a normal map holds where it is level.
    FlatNormal,
    /// Every texel white.
    White,
    /// Cube maps only: a sky over a ground whose colour tells the
    /// compass direction (docs/runner.md, "Textures").
    Sky,
}

/// Tints of the layers (cube faces) of a layered pattern, by index mod 6.
const LAYER_TINTS: [[u32; 3]; 6] = [[255, 120, 120], [120, 255, 255], [120, 255, 120], [255, 120, 255], [120, 120, 255], [255, 255, 120]];

impl Pattern {
    pub const ALL: [Pattern; 6] = [Pattern::Checker, Pattern::Noise, Pattern::Uv, Pattern::FlatNormal, Pattern::White, Pattern::Sky];

    /// Layer (cube face) `l` of a layered pattern: the sky's face `l`, or
    /// the 2D pattern (the checker's squares swapping with each layer)
    /// times the layer's tint. Integer arithmetic, as [`Pattern::texels`].
    fn layer(self, width: u32, height: u32, l: u32) -> Vec<u8> {
        if self == Pattern::Sky {
            return sky_face(width, l);
        }
        let mut out = self.texels(width, height);
        let swap = self == Pattern::Checker && l % 2 == 1;
        let tint = LAYER_TINTS[(l % 6) as usize];
        for px in out.chunks_mut(4) {
            for k in 0..3 {
                // The checker's 200 and 60 trade places.
                let c = if swap { 260 - px[k] as u32 } else { px[k] as u32 };
                px[k] = (c * tint[k] / 255) as u8;
            }
        }
        out
    }

    /// The RGBA8 texels of a `width` x `height` pattern, top row first.
    /// Pure integer arithmetic, so a page computes the same bytes.
    pub fn texels(self, width: u32, height: u32) -> Vec<u8> {
        let mut out = Vec::with_capacity((width * height * 4) as usize);
        for y in 0..height {
            for x in 0..width {
                let px: [u8; 4] = match self {
                    Pattern::Checker => {
                        let c = if ((x / 8) + (y / 8)) % 2 == 0 { 200 } else { 60 };
                        [c, c, c, 255]
                    }
                    Pattern::Noise => {
                        let c = noise(x, y);
                        [c, c, c, 255]
                    }
                    Pattern::Uv => [(x * 255 / (width - 1).max(1)) as u8, (y * 255 / (height - 1).max(1)) as u8, 128, 255],
                    Pattern::FlatNormal => [128, 128, 255, 255],
                    Pattern::White => [255; 4],
                    // Checked: a sky is a cube map's; as 2D, its +z face.
                    Pattern::Sky => {
                        let f = sky_face(width, 4);
                        let i = 4 * (y.min(width - 1) * width + x) as usize;
                        [f[i], f[i + 1], f[i + 2], 255]
                    }
                };
                out.extend_from_slice(&px);
            }
        }
        out
    }
}

/// Face `f` (+x, -x, +y, -y, +z, -z) of the sky cube map, `n` x `n`, row 0
/// at the face's t = 0 (GL's cube map table). The direction through a
/// texel's centre, times `n`, is integers; its elevation stands in as
/// `256 * y / (|y| + max(|x|, |z|))`: 0 at the horizon, 128 at a top
/// face's edge, near 256 overhead. Above it the sky goes from a pale
/// horizon to blue; below it the ground is darker downwards and coloured
/// by the compass direction (+x red, -x green, +z blue, -z yellow).
fn sky_face(n: u32, f: u32) -> Vec<u8> {
    let n = n as i32;
    let mut out = Vec::with_capacity((n * n * 4) as usize);
    for y in 0..n {
        for x in 0..n {
            let (a, b) = (2 * x + 1 - n, 2 * y + 1 - n);
            let (rx, ry, rz) = match f {
                0 => (n, -b, -a),
                1 => (-n, -b, a),
                2 => (a, n, b),
                3 => (a, -n, -b),
                4 => (a, -b, n),
                _ => (-a, -b, -n),
            };
            let e = 256 * ry / (ry.abs() + rx.abs().max(rz.abs()));
            let mix = |from: i32, to: i32, t: i32| (from + (to - from) * t / 256) as u8;
            let px = if e >= 0 {
                [mix(215, 40, e), mix(228, 100, e), mix(250, 210, e)]
            } else {
                let ground: [i32; 3] = if rx.abs() >= rz.abs() {
                    if rx > 0 { [170, 70, 50] } else { [60, 150, 60] }
                } else if rz > 0 {
                    [60, 90, 170]
                } else {
                    [170, 150, 50]
                };
                [mix(ground[0], 20, -e), mix(ground[1], 20, -e), mix(ground[2], 20, -e)]
            };
            out.extend_from_slice(&[px[0], px[1], px[2], 255]);
        }
    }
    out
}

/// A hash of the texel's cell corners, blended: 4-texel cells.
fn noise(x: u32, y: u32) -> u8 {
    let h = |cx: u32, cy: u32| -> u32 {
        let mut v = cx.wrapping_mul(374_761_393) ^ cy.wrapping_mul(668_265_263);
        v = (v ^ (v >> 13)).wrapping_mul(1_274_126_177);
        (v ^ (v >> 16)) & 255
    };
    let (cx, cy, fx, fy) = (x / 4, y / 4, x % 4, y % 4);
    let top = h(cx, cy) * (4 - fx) + h(cx + 1, cy) * fx;
    let bottom = h(cx, cy + 1) * (4 - fx) + h(cx + 1, cy + 1) * fx;
    ((top * (4 - fy) + bottom * fy) / 16) as u8
}

/// A texture passes draw into.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderTarget {
    pub name: String,
    pub format: TargetFormat,
    /// Texels; none: the output's size.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<[u32; 2]>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetFormat {
    /// 8-bit UNORM colour (the screen's format).
    Rgba8,
    /// 32-bit float depth.
    Depth32float,
    Depth24plus,
    Depth16,
}

impl TargetFormat {
    pub fn is_depth(self) -> bool {
        !matches!(self, TargetFormat::Rgba8)
    }
}

/// Which faces are culled (counter-clockwise faces are front faces, as a
/// GL host's default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Cull {
    #[default]
    None,
    Front,
    Back,
}

/// One render pass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pass {
    pub name: String,
    /// The vertex entry point.
    pub vertex: String,
    /// The fragment entry point; none: a depth-only pass.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fragment: Option<String>,
    /// Where the colour outputs go: [`SCREEN`] or a colour target's name
    /// (output 0), or a list of colour targets (output location i -> the
    /// i-th: a G-buffer); none: no colour.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<ColorTargets>,
    /// The colour it is cleared to first.
    #[serde(default = "black")]
    pub clear: [f32; 4],
    /// A depth target's name (depth test LESS, writes on, cleared to 1);
    /// none: no depth test.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth: Option<String>,
    #[serde(default)]
    pub cull: Cull,
    /// Slope-scaled depth bias, for shadow maps.
    #[serde(default, skip_serializing_if = "is_false")]
    pub depth_bias: bool,
    /// What each sampler reads, by sampler name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub samplers: BTreeMap<String, SamplerInput>,
    /// Values this pass's draws set (over the scene's).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub values: BTreeMap<String, ValueSpec>,
    pub draws: Vec<Draw>,
}

/// A pass's `color`: one name, or several colour targets by output location.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "a target name or a list of target names")]
pub enum ColorTargets {
    One(String),
    Many(Vec<String>),
}

impl ColorTargets {
    /// The names, output location 0 first.
    pub fn names(&self) -> &[String] {
        match self {
            ColorTargets::One(n) => std::slice::from_ref(n),
            ColorTargets::Many(v) => v,
        }
    }

    /// The name output location 0 goes to (the only one of the single form).
    pub fn first(&self) -> Option<&str> {
        self.names().first().map(String::as_str)
    }
}

impl From<&str> for ColorTargets {
    fn from(name: &str) -> Self {
        ColorTargets::One(name.to_string())
    }
}

fn black() -> [f32; 4] {
    [0.0, 0.0, 0.0, 1.0]
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// A texture or target a sampler reads.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SamplerInput {
    /// A texture's or a render target's name.
    pub texture: String,
    #[serde(default)]
    pub filter: Filter,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    #[default]
    Linear,
    Nearest,
}

/// One draw call.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Draw {
    pub mesh: MeshKind,
    /// With `mesh = "none"`: this many vertices, no vertex buffers (the
    /// vertex program places them from `gl_VertexID`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices: Option<u32>,
    /// What feeds each vertex input, by its name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub attributes: BTreeMap<String, Attribute>,
    /// Drawn once per cell of a grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub instances: Option<InstanceGrid>,
    /// This draw's values (over the pass's).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub values: BTreeMap<String, ValueSpec>,
    /// Where the mesh is, maybe moving with `time`: the `model` conventions
    /// of this draw (none: a slow turn about y).
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "checked")]
    pub transform: Option<Transform>,
    /// What the mesh is drawn as: its triangles, or each vertex once as a
    /// point (sized by `gl_PointSize` where the consumer honours it).
    #[serde(default, skip_serializing_if = "Primitive::is_triangles")]
    pub primitive: Primitive,
}

/// A table whose values must make sense together, checked as it is read,
/// so that a mistake is placed at the table (the parser knows where).
trait Check {
    fn check(&self) -> Result<(), String>;
}

fn checked<'de, D: serde::Deserializer<'de>, T: Deserialize<'de> + Check>(d: D) -> Result<Option<T>, D::Error> {
    let t = T::deserialize(d)?;
    t.check().map_err(serde::de::Error::custom)?;
    Ok(Some(t))
}

impl Check for Transform {
    fn check(&self) -> Result<(), String> {
        if self.axis == [0.0; 3] {
            return Err("a transform turns about `axis = [0, 0, 0]`".into());
        }
        if self.scale.axes().contains(&0.0) {
            return Err("a transform has a `scale` of 0, which no normal survives".into());
        }
        Ok(())
    }
}

/// A draw's object-to-world matrix: `translate * rotate * scale`, the turn
/// `angle + spin * time` degrees about `axis`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Transform {
    pub translate: [f32; 3],
    /// Need not be unit length; not zero.
    pub axis: [f32; 3],
    /// Degrees at time 0.
    pub angle: f32,
    /// Degrees a second of `time`.
    pub spin: f32,
    pub scale: Scale,
}

impl Default for Transform {
    fn default() -> Transform {
        Transform { translate: [0.0; 3], axis: [0.0, 1.0, 0.0], angle: 0.0, spin: 0.0, scale: Scale::Uniform(1.0) }
    }
}

/// One factor for every axis, or one per axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Scale {
    Uniform(f32),
    Axes([f32; 3]),
}

impl Scale {
    pub fn axes(self) -> [f32; 3] {
        match self {
            Scale::Uniform(s) => [s; 3],
            Scale::Axes(a) => a,
        }
    }
}

/// What the `light_*` conventions are computed from: a sun (a direction,
/// an orthographic shadow box, maybe several for cascades) or a spot (a
/// position and a perspective shadow frustum), both aimed at `target`,
/// turning `spin` degrees a second of `time` about the world's +y axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Light {
    pub kind: LightKind,
    /// A sun's direction towards the light at time 0 (normalised).
    pub direction: [f32; 3],
    /// A spot's position at time 0.
    pub position: [f32; 3],
    /// What the light looks at: the centre of a sun's box, a spot's aim.
    pub target: [f32; 3],
    pub spin: f32,
    /// A sun's eye: `distance` from `target` along the direction.
    pub distance: f32,
    /// A sun's box: x and y from `-half_size` to `half_size`.
    pub half_size: f32,
    /// A sun's cascades: one box half-size each, finest first; none: the
    /// one `half_size` box.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub cascades: Vec<f32>,
    /// A spot's full vertical field of view, degrees (its map is square).
    pub fov_y: f32,
    pub near: f32,
    pub far: f32,
}

impl Default for Light {
    fn default() -> Light {
        Light {
            kind: LightKind::Sun,
            direction: [0.4, 0.8, 0.45],
            position: [0.0, 5.0, 0.0],
            target: [0.0; 3],
            spin: 0.0,
            distance: 10.0,
            half_size: 4.0,
            cascades: Vec::new(),
            fov_y: 60.0,
            near: 0.1,
            far: 20.0,
        }
    }
}

/// `a > b`, false for NaN.
fn above(a: f32, b: f32) -> bool {
    a > b
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LightKind {
    /// Directional; orthographic shadow boxes.
    #[default]
    Sun,
    /// A point aimed at `target`; a perspective shadow frustum.
    Spot,
}

impl Light {
    /// The shadow boxes' half-sizes: `cascades`, else `half_size` alone
    /// (a spot has one frustum).
    pub fn boxes(&self) -> Vec<f32> {
        match self.kind {
            LightKind::Sun if !self.cascades.is_empty() => self.cascades.clone(),
            _ => vec![self.half_size],
        }
    }
}

impl Check for Light {
    fn check(&self) -> Result<(), String> {
        let zero = |v: [f32; 3]| v.iter().all(|x| *x == 0.0);
        if !above(self.near, 0.0) {
            return Err(format!("the light's `near = {}` is not above 0", self.near));
        }
        if !above(self.far, self.near) {
            return Err(format!("the light's `far = {}` is not beyond its near plane ({})", self.far, self.near));
        }
        match self.kind {
            LightKind::Sun => {
                if zero(self.direction) {
                    return Err("the light's `direction = [0, 0, 0]` points nowhere".into());
                }
                if !above(self.half_size, 0.0) {
                    return Err(format!("the light's `half_size = {}` is not above 0", self.half_size));
                }
                if let Some(h) = self.cascades.iter().find(|h| !above(**h, 0.0)) {
                    return Err(format!("the light's `cascades =` hold a box of half-size {h}, not above 0"));
                }
                if self.cascades.len() > 8 {
                    return Err(format!("the light's `cascades =` are {} boxes (at most 8)", self.cascades.len()));
                }
            }
            LightKind::Spot => {
                if self.position == self.target {
                    return Err("the spot light aims nowhere: its `position =` is its `target =`".into());
                }
                if !(above(self.fov_y, 0.0) && above(180.0, self.fov_y)) {
                    return Err(format!("the spot light's `fov_y = {}` is not between 0 and 180 degrees", self.fov_y));
                }
                if !self.cascades.is_empty() {
                    return Err("the spot light has `cascades =`, which a sun has (`kind = \"sun\"`)".into());
                }
            }
        }
        Ok(())
    }
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Primitive {
    #[default]
    Triangles,
    Points,
}

impl Primitive {
    fn is_triangles(&self) -> bool {
        *self == Primitive::Triangles
    }
}

/// The built-in meshes (docs/runner.md: their vertices).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MeshKind {
    /// One triangle covering clip space: positions (-1,-1), (3,-1),
    /// (-1,3) at z 0, uvs from (0,0) to (2,2).
    FullscreenTriangle,
    /// The cube from -0.5 to 0.5, 24 vertices, a uv square on each face.
    Cube,
    /// Radius 0.5, 24 segments around, 16 rings.
    Sphere,
    /// The square from -1 to 1 in x and z at y 0, facing +y.
    Plane,
    /// No vertex buffers: `vertices` vertices.
    None,
}

impl MeshKind {
    pub fn name(self) -> &'static str {
        match self {
            MeshKind::FullscreenTriangle => "fullscreen_triangle",
            MeshKind::Cube => "cube",
            MeshKind::Sphere => "sphere",
            MeshKind::Plane => "plane",
            MeshKind::None => "none",
        }
    }
}

/// What a mesh gives a vertex input. Each fits the input's components:
/// the first N of a longer value, a 4th component of 1 where the value
/// has 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Attribute {
    /// Object-space position (clip space for the full-screen triangle).
    Position,
    Normal,
    /// The tangent along u, w = 1.
    Tangent,
    Uv,
    /// The position mapped to [0, 1] (x, y, z), alpha 1.
    Color,
    /// Per instance: the cell's centre.
    InstanceOffset,
    /// Per instance: a colour from the cell's place in the grid.
    InstanceColor,
    /// Per instance: `index / count`, in [0, 1).
    InstancePhase,
}

impl Attribute {
    pub fn per_instance(self) -> bool {
        matches!(self, Attribute::InstanceOffset | Attribute::InstanceColor | Attribute::InstancePhase)
    }
}

/// `count` instances on a grid centred on the origin, `spacing` apart in
/// x, then z, then y.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InstanceGrid {
    pub count: [u32; 3],
    #[serde(default = "spacing")]
    pub spacing: f32,
}

fn spacing() -> f32 {
    1.5
}

impl InstanceGrid {
    pub fn total(&self) -> u32 {
        self.count.iter().product()
    }

    /// Instance `i`'s (offset, colour, phase).
    pub fn instance(&self, i: u32) -> ([f32; 3], [f32; 3], f32) {
        let [nx, nz, ny] = self.count.map(|n| n.max(1));
        let (ix, iz, iy) = (i % nx, (i / nx) % nz, i / (nx * nz));
        let centre = |k: u32, n: u32| (k as f32 - (n - 1) as f32 / 2.0) * self.spacing;
        let frac = |k: u32, n: u32| if n > 1 { k as f32 / (n - 1) as f32 } else { 0.5 };
        (
            [centre(ix, nx), centre(iy, ny), centre(iz, nz)],
            [0.25 + 0.7 * frac(ix, nx), 0.8 - 0.5 * frac(iz, nz), 0.3 + 0.6 * frac(iy, ny)],
            i as f32 / self.total() as f32,
        )
    }
}

/// A uniform's value in a scene: a number, numbers (components in order,
/// matrices column by column), a bool, or the name of a convention
/// ([`Convention`]) the host computes each frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ValueSpec {
    Bool(bool),
    Number(f64),
    Numbers(Vec<f64>),
    Convention(Convention),
    /// One element of an array convention: `{ convention =
    /// "light_view_projections", index = 1 }`.
    Element(ConventionElement),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConventionElement {
    pub convention: Convention,
    pub index: u32,
}

/// Values the host computes each frame (docs/runner.md, "Conventions").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Convention {
    /// Seconds.
    Time,
    /// The frame's number from 0.
    Frame,
    /// The output's width and height in pixels (a third component 1, a
    /// fourth `time`).
    Resolution,
    /// Width over height.
    Aspect,
    /// The pointer in pixels (x, y; a held button: z, w = the press), from
    /// the bottom left; the output's centre when nothing moved it.
    Mouse,
    /// The orbit camera's world-to-view matrix.
    View,
    /// `view` without its translation (a skybox's).
    ViewRotation,
    /// The orbit camera's perspective projection (GL clip space).
    Projection,
    /// `projection * view`.
    ViewProjection,
    /// The object's model matrix: a slow turn about y with `time`.
    Model,
    /// `projection * view * model`.
    ModelViewProjection,
    /// The inverse transpose of `model`'s upper 3x3.
    NormalMatrix,
    /// The orbit camera's eye, in world space.
    CameraPosition,
    /// The unit vector towards the light (the scene's `light`; by default
    /// a still sun towards normalize(0.4, 0.8, 0.45)).
    LightDirection,
    /// The light's `projection * view`: a sun's orthographic box of
    /// `half_size` (4) seen from `distance` (10) along `light_direction`,
    /// a spot's perspective frustum.
    LightViewProjection,
    /// 1 / `resolution` (x, y).
    TexelSize,
    /// The light's position: a spot's, a sun's eye.
    LightPosition,
    /// The unit vector from the light towards its target (a spot's axis).
    SpotDirection,
    /// One `light_view_projection` per shadow box (the sun's `cascades`).
    LightViewProjections,
    /// `light_view_projection` then clip space to texture space
    /// (`x * 0.5 + 0.5` for x, y and z): a `textureProj` coordinate.
    ShadowMatrix,
}

impl Convention {
    pub const ALL: [Convention; 20] = [
        Convention::Time,
        Convention::Frame,
        Convention::Resolution,
        Convention::Aspect,
        Convention::Mouse,
        Convention::View,
        Convention::ViewRotation,
        Convention::Projection,
        Convention::ViewProjection,
        Convention::Model,
        Convention::ModelViewProjection,
        Convention::NormalMatrix,
        Convention::CameraPosition,
        Convention::LightDirection,
        Convention::LightViewProjection,
        Convention::TexelSize,
        Convention::LightPosition,
        Convention::SpotDirection,
        Convention::LightViewProjections,
        Convention::ShadowMatrix,
    ];

    /// Whether its value depends on the draw's `transform`.
    pub fn per_draw(self) -> bool {
        matches!(self, Convention::Model | Convention::ModelViewProjection | Convention::NormalMatrix)
    }
}

/// How a page lets the user set one uniform.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Control {
    /// The uniform's (or block member's) name.
    pub name: String,
    /// Its DSL type (`float`, `float3`, `bool`, `float4x4`).
    #[serde(rename = "type")]
    pub ty: String,
    pub kind: ControlKind,
    /// A slider's range and step (every component of a vector alike).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ControlKind {
    /// One slider per component.
    Slider,
    /// A colour picker (RGB; an alpha slider for a `float4`).
    Color,
    Checkbox,
    /// Set by its convention each frame (the scene's value names it);
    /// matrices follow the orbit camera, which the page may let the user drag.
    Convention,
    /// Nothing a control can set (a struct, an array).
    None,
}

impl Scene {
    /// Reads a scene file: TOML, or JSON when `name` ends in `.json`.
    /// The error names the file and, where the parser knows it, the line.
    ///
    /// A mistake the checks find after parsing ([`Scene::check`]) is placed
    /// where the text first quotes the name it is about.
    pub fn parse(name: &str, text: &str) -> Result<Scene, String> {
        let scene: Scene = if name.ends_with(".json") {
            serde_json::from_str(text).map_err(|e| located(name, text, e.line(), e.column(), &e.to_string()))?
        } else {
            toml::from_str(text).map_err(|e| match e.span() {
                Some(span) => {
                    let (line, col) = line_col(text, span.start);
                    located(name, text, line, col, e.message())
                }
                None => format!("{name}: {}", e.message()),
            })?
        };
        scene.check().map_err(|e| locate(name, text, &e))?;
        Ok(scene)
    }

    /// As JSON (the bundle's `scene`, a file `parse` reads back).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).expect("a scene is plain data")
    }

    /// Whether every name a pass uses is declared, sizes are at least 1,
    /// attachments have the right kind and each draw has geometry.
    pub fn check(&self) -> Result<(), String> {
        let mut names: Vec<&str> = vec![SCREEN];
        for n in self.textures.iter().map(|t| t.name.as_str()).chain(self.targets.iter().map(|t| t.name.as_str())) {
            if names.contains(&n) {
                return Err(format!("`{n}` is declared twice (textures, targets and `screen` share one namespace)"));
            }
            names.push(n);
        }
        for t in &self.textures {
            match (&t.pattern, &t.image) {
                (Some(_), None) | (None, Some(_)) => {}
                _ => return Err(format!("texture `{}` needs exactly one of `pattern` and `image`", t.name)),
            }
            if t.size[0] == 0 || t.size[1] == 0 || t.size[0] > 8192 || t.size[1] > 8192 {
                return Err(format!("texture `{}` is {}x{}: sizes go from 1 to 8192", t.name, t.size[0], t.size[1]));
            }
            check_kind(t)?;
        }
        for t in &self.targets {
            if let Some([w, h]) = t.size {
                if w == 0 || h == 0 || w > 8192 || h > 8192 {
                    return Err(format!("target `{}` is {w}x{h}: sizes go from 1 to 8192", t.name));
                }
            }
        }
        let target = |n: &str| self.targets.iter().find(|t| t.name == n);
        if self.output != SCREEN && target(&self.output).is_none() {
            return Err(format!("`output = \"{}\"` names no render target", self.output));
        }
        if let Some(l) = &self.light {
            l.check()?;
        }
        if self.passes.is_empty() {
            return Err("a scene needs at least one pass".into());
        }
        for p in &self.passes {
            check_colors(p, &target)?;
            if let Some(d) = p.depth.as_deref() {
                match target(d) {
                    Some(t) if t.format.is_depth() => {}
                    Some(_) => return Err(format!("pass `{}` tests depth against the colour target `{d}`", p.name)),
                    None => return Err(format!("pass `{}`: `depth = \"{d}\"` names no render target", p.name)),
                }
            }
            if p.color.is_none() && p.depth.is_none() {
                return Err(format!("pass `{}` has neither `color` nor `depth`", p.name));
            }
            for (s, input) in &p.samplers {
                if !names[1..].contains(&input.texture.as_str()) {
                    return Err(format!("pass `{}`: sampler `{s}` reads `{}`, which is no texture or render target", p.name, input.texture));
                }
                if p.color.as_ref().is_some_and(|c| c.names().contains(&input.texture)) || p.depth.as_deref() == Some(input.texture.as_str()) {
                    return Err(format!("pass `{}` samples `{}`, which it draws into", p.name, input.texture));
                }
            }
            for d in &p.draws {
                match (d.mesh, d.vertices) {
                    (MeshKind::None, Some(n)) if n > 0 => {}
                    (MeshKind::None, _) => return Err(format!("pass `{}`: a draw with `mesh = \"none\"` needs `vertices` (at least 1)", p.name)),
                    (_, Some(_)) => return Err(format!("pass `{}`: `vertices` goes with `mesh = \"none\"` only", p.name)),
                    _ => {}
                }
                if d.primitive == Primitive::Points && d.mesh == MeshKind::None {
                    return Err(format!("pass `{}`: `primitive = \"points\"` draws a mesh's vertices; `mesh = \"none\"` has none", p.name));
                }
                if let Some(g) = &d.instances {
                    if g.total() == 0 || g.total() > 65536 {
                        return Err(format!("pass `{}`: an instance grid of {} instances (1 to 65536)", p.name, g.total()));
                    }
                }
                if let Some(t) = &d.transform {
                    t.check().map_err(|e| format!("pass `{}`: {e}", p.name))?;
                }
                if d.instances.is_none() {
                    if let Some((a, _)) = d.attributes.iter().find(|(_, a)| a.per_instance()) {
                        return Err(format!("pass `{}`: attribute `{a}` is per instance, but the draw has no `instances`", p.name));
                    }
                }
            }
        }
        Ok(())
    }

    /// The value `name` has in a draw: the draw's, else its pass's, else
    /// the scene's.
    pub fn value<'a>(&'a self, pass: &'a Pass, draw: &'a Draw, name: &str) -> Option<&'a ValueSpec> {
        draw.values.get(name).or_else(|| pass.values.get(name)).or_else(|| self.values.get(name))
    }
}

/// Whether a pass's `color` names colour targets: `screen` or one target,
/// or a list of distinct colour targets of one size (never `screen`).
fn check_colors<'a>(p: &Pass, target: &impl Fn(&str) -> Option<&'a RenderTarget>) -> Result<(), String> {
    let Some(colors) = &p.color else { return Ok(()) };
    let list = matches!(colors, ColorTargets::Many(_));
    if list && colors.names().is_empty() {
        return Err(format!("pass `{}`: `color = []` names no target (leave `color` out for a depth-only pass)", p.name));
    }
    let mut seen: Vec<&RenderTarget> = Vec::new();
    for c in colors.names() {
        let t = match target(c) {
            _ if c == SCREEN && !list => return Ok(()),
            _ if c == SCREEN => return Err(format!("pass `{}`: a list of colour targets cannot hold `screen` (draw to targets, then to the screen in a later pass)", p.name)),
            Some(t) if !t.format.is_depth() => t,
            Some(_) => return Err(format!("pass `{}` draws colour into the depth target `{c}`", p.name)),
            None => return Err(format!("pass `{}`: `color` target `{c}` names no render target", p.name)),
        };
        if seen.iter().any(|s| s.name == t.name) {
            return Err(format!("pass `{}` names the colour target `{c}` twice", p.name));
        }
        if let Some(first) = seen.first().filter(|f| f.size != t.size) {
            let size = |t: &RenderTarget| t.size.map_or("the output's size".to_string(), |[w, h]| format!("{w}x{h}"));
            return Err(format!("pass `{}`: colour targets `{}` ({}) and `{c}` ({}) differ in size", p.name, first.name, size(first), size(t)));
        }
        seen.push(t);
    }
    Ok(())
}

/// Whether a texture's `kind`, `layers`, size and pattern go together.
fn check_kind(t: &Texture) -> Result<(), String> {
    let layered = matches!(t.kind, TextureKind::D3 | TextureKind::D2Array);
    if t.kind != TextureKind::D2 && t.image.is_some() {
        return Err(format!("texture `{}`: an image file makes a 2D texture only; a cube, 3D or array texture takes a `pattern`", t.name));
    }
    if t.layers == 0 || t.layers > 256 || (t.layers != 1 && !layered) {
        return Err(format!("texture `{}` has `layers = {}`: 1 to 256, and other than 1 for a `3d` or `2d_array` texture only", t.name, t.layers));
    }
    if t.kind == TextureKind::Cube && (t.size[0] != t.size[1] || t.size[0] > 2048) {
        return Err(format!("texture `{}` is a cube of {}x{} faces: they are square, at most 2048", t.name, t.size[0], t.size[1]));
    }
    if layered && u64::from(t.size[0]) * u64::from(t.size[1]) * u64::from(t.layers) > 1 << 24 {
        return Err(format!("texture `{}`: {}x{}x{} texels, more than 2^24", t.name, t.size[0], t.size[1], t.layers));
    }
    if t.pattern == Some(Pattern::Sky) && t.kind != TextureKind::Cube {
        return Err(format!("texture `{}`: `pattern = \"sky\"` is a cube map's (`kind = \"cube\"`)", t.name));
    }
    Ok(())
}

/// A message about a scene file placed where the text first quotes the
/// name it is about: the last one it quotes (`pass `p`: sampler `s` reads
/// `t``) that the text has, `FILE: message` where none is found.
pub fn locate(name: &str, text: &str, message: &str) -> String {
    let names: Vec<&str> = message.split('`').skip(1).step_by(2).collect();
    let quoted = names.iter().rev().find_map(|n| if n.contains('=') { text.find(n) } else { text.find(&format!("\"{n}\"")) });
    match quoted {
        Some(at) => {
            let (line, col) = line_col(text, at);
            located(name, text, line, col, message)
        }
        None => format!("{name}: {message}"),
    }
}

/// `FILE:LINE:COL: message`, then the line with a caret under the column.
fn located(name: &str, text: &str, line: usize, col: usize, message: &str) -> String {
    let message = message.trim_end();
    let Some(source) = text.lines().nth(line.saturating_sub(1)) else {
        return format!("{name}:{line}:{col}: {message}");
    };
    let gutter = " ".repeat(line.to_string().len());
    let pad: String = source.chars().take(col.saturating_sub(1)).map(|c| if c == '\t' { '\t' } else { ' ' }).collect();
    format!("{name}:{line}:{col}: {message}\n{gutter} |\n{line} | {source}\n{gutter} | {pad}^")
}

/// 1-based line and column of a byte offset.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

#[cfg(test)]
mod tests;
