//! The classic shadow techniques as scenes the runner renders: each is a DSL
//! program under `shaders/techniques/` plus the host state it needs (light
//! matrices, one or three shadow targets of depth or RGBA8, culling, bias),
//! described as a frame plan ([`TechFrame::plan`]) that every executor
//! runs, and checked against a CPU ray-cast reference ([`reference`]) with
//! exact visibility from the same light.
//!
//! The meshes, camera, cube motion and sun direction are the tutorial
//! scene's ([`super::scene`]). What differs per technique is here, and what
//! each program binds comes from its reflection, by name.

pub mod reference;

use std::path::{Path, PathBuf};

use glam::camera::rh::proj::opengl;
use glam::camera::rh::view::look_at_mat4;
use glam::{Mat4, Vec3};

use super::plan::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, Sampling, TargetId, TextureInput, Value, Values};
use super::scene::{self, Frame, FrameParams, Object};

/// One technique scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Technique {
    /// A spot light, perspective shadow map, manual compare on a sampler2D.
    Spot,
    /// The sun with a table-driven PCF (`taps` = 1, 2, 4 or 9).
    Pcf { taps: u32 },
    /// The sun with three cascade maps picked by light-space bounds.
    Cascades,
    /// The sun through a bias matrix and `textureProj`.
    Proj,
    /// The sun with front faces culled in the shadow pass and no bias.
    Cull,
    /// Depth encoded into an RGBA8 colour target.
    Rgba8Depth,
}

/// What the shadow pass renders into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowTarget {
    /// A Depth32Float texture, sampled as depth.
    Depth,
    /// An RGBA8 colour texture holding encoded depth (plus a depth buffer).
    Rgba8,
}

/// The technique scene's sun box: larger than the tutorial's so that the
/// whole floor is inside the map (no clamped-edge lookups to excuse).
pub const SUN_BOX: f32 = 7.5;
pub const SUN_DISTANCE: f32 = 10.0;
pub const SUN_NEAR: f32 = 0.1;
pub const SUN_FAR: f32 = 25.0;
/// Half-extents of the three cascades' boxes, finest first.
pub const CASCADE_BOXES: [f32; 3] = [2.0, 4.0, SUN_BOX];
/// The spot light: full field of view of its shadow map, near and far.
pub const SPOT_FOV_DEG: f32 = 75.0;
pub const SPOT_NEAR: f32 = 1.0;
pub const SPOT_FAR: f32 = 20.0;
/// Cone cosines, as in `spot_light.das`.
pub const SPOT_COS_INNER: f32 = 0.9063;
pub const SPOT_COS_OUTER: f32 = 0.8480;
pub const SPOT_SHADOW_FACTOR: f32 = 0.5;

impl Technique {
    pub const ALL: [Technique; 6] =
        [Technique::Spot, Technique::Pcf { taps: 9 }, Technique::Cascades, Technique::Proj, Technique::Cull, Technique::Rgba8Depth];

    /// The `--scene` name.
    pub fn name(self) -> &'static str {
        match self {
            Technique::Spot => "spot",
            Technique::Pcf { .. } => "pcf",
            Technique::Cascades => "cascades",
            Technique::Proj => "proj",
            Technique::Cull => "cull",
            Technique::Rgba8Depth => "rgba8-depth",
        }
    }

    /// The program, relative to the repository root.
    pub fn program(self) -> &'static str {
        match self {
            Technique::Spot => "shaders/techniques/spot_light.das",
            Technique::Pcf { .. } => "shaders/techniques/pcf_table.das",
            Technique::Cascades => "shaders/techniques/cascades.das",
            Technique::Proj => "shaders/techniques/proj_lookup.das",
            Technique::Cull => "shaders/techniques/cull_front.das",
            Technique::Rgba8Depth => "shaders/techniques/rgba8_depth.das",
        }
    }

    /// `-D` defines the program is compiled with.
    pub fn defines(self) -> Vec<(String, Option<String>)> {
        match self {
            Technique::Pcf { taps } if taps != 9 => vec![(format!("PCF_TAPS_{taps}"), None)],
            _ => Vec::new(),
        }
    }

    pub fn layers(self) -> usize {
        if self == Technique::Cascades {
            3
        } else {
            1
        }
    }

    pub fn target(self) -> ShadowTarget {
        if self == Technique::Rgba8Depth {
            ShadowTarget::Rgba8
        } else {
            ShadowTarget::Depth
        }
    }

    /// Front faces culled in the shadow pass (and no depth bias there).
    pub fn cull_front(self) -> bool {
        self == Technique::Cull
    }

    /// The pipeline's polygon offset in the shadow pass. Off for culling
    /// (not needed) and for the RGBA8 encoding (gl_FragCoord.z does not
    /// include it on every API: the program biases instead).
    pub fn depth_bias(self) -> bool {
        !matches!(self, Technique::Cull | Technique::Rgba8Depth)
    }

    pub fn is_spot(self) -> bool {
        self == Technique::Spot
    }

    /// Parses a `--scene` name (`pcf` takes the taps from `pcf_taps`).
    pub fn parse(name: &str, pcf_taps: u32) -> Option<Technique> {
        Some(match name {
            "spot" => Technique::Spot,
            "pcf" => Technique::Pcf { taps: pcf_taps },
            "cascades" => Technique::Cascades,
            "proj" => Technique::Proj,
            "cull" => Technique::Cull,
            "rgba8-depth" => Technique::Rgba8Depth,
            _ => return None,
        })
    }

    /// Compiles the program (found under the working directory, else under
    /// the crate's own source tree).
    pub fn compile(self) -> Result<crate::Compiled, String> {
        let rel = Path::new(self.program());
        let path: PathBuf = if rel.exists() { rel.to_path_buf() } else { Path::new(env!("CARGO_MANIFEST_DIR")).join(rel) };
        let opts = crate::Options { defines: self.defines(), ..Default::default() };
        let c = crate::compile_file(&path, &opts);
        let failed = c.has_errors();
        let diagnostics = c.render_diagnostics();
        match c.result {
            Some(compiled) if !failed => Ok(compiled),
            _ => Err(format!("{} does not compile:\n{diagnostics}", path.display())),
        }
    }
}

/// Everything a technique frame computes on the host.
#[derive(Clone, Debug)]
pub struct TechFrame {
    pub technique: Technique,
    /// The tutorial scene's frame (camera, cube, sun direction); its
    /// `light_vp` is replaced by the technique's map 0.
    pub base: Frame,
    /// Light view-projection per shadow layer.
    pub layer_vp: Vec<Mat4>,
    /// Spot light position and axis (spot only).
    pub spot_pos: Vec3,
    pub spot_dir: Vec3,
}

pub fn spot_position(t: f32) -> Vec3 {
    let a = 0.4 * t + 0.8;
    Vec3::new(3.2 * a.cos(), 4.8, 3.2 * a.sin())
}

pub fn spot_target() -> Vec3 {
    Vec3::new(0.0, 0.3, 0.0)
}

impl TechFrame {
    pub fn new(technique: Technique, params: &FrameParams) -> TechFrame {
        let mut base = Frame::of(params);
        let (spot_pos, spot_dir) = (spot_position(params.time), (spot_target() - spot_position(params.time)).normalize());
        let layer_vp: Vec<Mat4> = if technique.is_spot() {
            let view = look_at_mat4(spot_pos, spot_target(), Vec3::Y);
            let proj = opengl::perspective(SPOT_FOV_DEG.to_radians(), 1.0, SPOT_NEAR, SPOT_FAR);
            vec![proj * view]
        } else {
            let view = look_at_mat4(base.light_dir * SUN_DISTANCE, Vec3::ZERO, Vec3::Y);
            let boxes: &[f32] = if technique == Technique::Cascades { &CASCADE_BOXES } else { &[SUN_BOX] };
            boxes.iter().map(|&b| opengl::orthographic(-b, b, -b, b, SUN_NEAR, SUN_FAR) * view).collect()
        };
        base.light_vp = layer_vp[0];
        TechFrame { technique, base, layer_vp, spot_pos, spot_dir }
    }

    /// The frame as a plan: one shadow pass per layer into its map, then
    /// the lit scene sampling every map, cube then floor in each.
    pub fn plan(&self, params: &FrameParams) -> FramePlan {
        let t = self.technique;
        let f = &self.base;
        let mut plan = FramePlan {
            scene: format!("the {} scene", t.name()),
            targets: Vec::new(),
            passes: Vec::new(),
            readback: TargetId(0),
            required: Vec::new(),
            unset: Default::default(),
        };
        let n = params.shadow_size;
        let rgba = t.target() == ShadowTarget::Rgba8;
        let maps: Vec<TargetId> = (0..t.layers())
            .map(|i| plan.add_target(&format!("shadow map {i}"), n, n, if rgba { Format::Rgba8 } else { Format::Depth32Float }))
            .collect();
        let map_depth = rgba.then(|| plan.add_target("shadow map depth", n, n, Format::Depth32Float));
        let color = plan.add_target("colour", params.width, params.height, Format::Rgba8);
        let depth = plan.add_target("depth", params.width, params.height, Format::Depth32Float);
        let values = Values::new()
            .with("u_view", Value::mat4(f.view))
            .with("u_proj", Value::mat4(f.proj))
            .with("u_cam_pos", Value::vec3(f.cam_pos))
            .with("u_light_vp", Value::mat4(self.layer_vp[0]))
            .with("u_light_dir", Value::vec3(f.light_dir))
            .with("u_cascade_vp", Value::array(self.layer_vp.iter().map(|m| Value::mat4(*m)).collect()))
            .with("u_light_pos", Value::vec3(self.spot_pos))
            .with("u_spot_dir", Value::vec3(self.spot_dir));
        let draws: Vec<Draw> = DRAWS
            .iter()
            .map(|&object| Draw {
                geometry: Geometry::Mesh(scene::mesh(object)),
                values: Values::new()
                    .with("u_model", Value::mat4(if object == Object::Cube { f.cube_model } else { Mat4::IDENTITY }))
                    .with("u_is_floor", Value::float(if object == Object::Floor { 1.0 } else { 0.0 })),
            })
            .collect();
        let [(shadow_vs, shadow_fs), (main_vs, main_fs)] = t.passes();
        for (i, &map) in maps.iter().enumerate() {
            plan.passes.push(Pass {
                name: if maps.len() > 1 { format!("shadow {i}") } else { "shadow".into() },
                vertex: shadow_vs.clone(),
                fragment: Some(shadow_fs.clone()),
                color: rgba.then_some(Attachment { target: map, clear: [1.0; 4] }),
                more_colors: Vec::new(),
                depth: Some(Attachment { target: map_depth.unwrap_or(map), clear: 1.0 }),
                cull: if t.cull_front() { Cull::Front } else { Cull::None },
                depth_bias: t.depth_bias(),
                textures: Vec::new(),
                values: values.clone().with("u_light_vp", Value::mat4(self.layer_vp[i])),
                draws: draws.clone(),
            });
        }
        let textures = match t {
            Technique::Cascades => {
                maps.iter().enumerate().map(|(i, &m)| TextureInput { sampler: format!("cascade_maps[{i}]"), target: m, sampling: Sampling::SHADOW }).collect()
            }
            Technique::Spot => vec![TextureInput { sampler: "shadow_map".into(), target: maps[0], sampling: Sampling::NEAREST }],
            Technique::Rgba8Depth => vec![TextureInput { sampler: "shadow_rgba".into(), target: maps[0], sampling: Sampling::NEAREST }],
            _ => vec![TextureInput { sampler: "shadow_map".into(), target: maps[0], sampling: Sampling::SHADOW }],
        };
        let c = scene::CLEAR;
        plan.passes.push(Pass {
            name: "main".into(),
            vertex: main_vs,
            fragment: Some(main_fs),
            color: Some(Attachment { target: color, clear: [c[0], c[1], c[2], 1.0] }),
            more_colors: Vec::new(),
            depth: Some(Attachment { target: depth, clear: 1.0 }),
            cull: Cull::None,
            depth_bias: false,
            textures,
            values,
            draws,
        });
        plan.readback = color;
        plan
    }
}

/// The draws of either pass: cube, then floor.
pub const DRAWS: [Object; 2] = [Object::Cube, Object::Floor];

/// The technique scene `technique` at `params` as a plan.
pub fn plan(technique: Technique, params: &FrameParams) -> FramePlan {
    TechFrame::new(technique, params).plan(params)
}

impl Technique {
    /// The prefix of the program's entry point names.
    pub fn entry_prefix(self) -> &'static str {
        match self {
            Technique::Rgba8Depth => "rgba8",
            t => t.name(),
        }
    }

    /// Entry points of the two passes: (shadow vs, fs), (main vs, fs), as
    /// `PREFIX_shadow_vs` ... (one directory of programs needs distinct
    /// entry names: each entry point is an output file of its own).
    pub fn passes(self) -> [(String, String); 2] {
        let p = self.entry_prefix();
        [
            (format!("{p}_{}", scene::SHADOW_VS), format!("{p}_{}", scene::SHADOW_FS)),
            (format!("{p}_{}", scene::MAIN_VS), format!("{p}_{}", scene::MAIN_FS)),
        ]
    }
}
