//! The scene a program gets without a scene file, from its manifest alone
//! (docs/runner.md, "Inference"):
//!
//! - a vertex program with no vertex inputs draws three vertices (a
//!   full-screen triangle placed from `gl_VertexID`); one whose position
//!   input is a `float2` draws the built-in full-screen triangle; any
//!   other draws the cube, with a depth buffer (none for a skybox: a
//!   vertex program reading a rotation-only view, `view_rotation`, whose
//!   camera looks 10 degrees up at the horizon);
//! - each vertex input is fed by the mesh attribute its name asks for
//!   (`names::attribute`); when one looks per-instance (`offset`,
//!   `instance`), the draw is a 3 x 3 instance grid and every input the
//!   mesh does not have is per instance too;
//! - colour output 0 goes to the screen;
//! - each 2D sampler reads a built-in pattern (a flat normal for names
//!   that say normal, white for occlusion, checker otherwise), a cube
//!   sampler the sky, a 3D one 32 slices and an array one 4 layers of
//!   the name's pattern; a 2D shadow sampler reads a depth target cleared
//!   to 1 (everything lit);
//! - each uniform: a per-frame convention its name asks for, else the
//!   manifest's default, else a convention for the camera and light
//!   names, else a fallback (`names::fallback`); and a control; a struct
//!   uniform member by member, by path (`u_instances[3].color`), an array
//!   of them as a table of the instance grid's cells ([`leaf_value`]).
//!
//! A program that writes `gl_PointSize` or reads `gl_PointCoord` (a point
//! sprite) draws the sphere's vertices as points. A vertex stage that
//! writes no `gl_Position` (transform feedback) is refused.

use std::collections::BTreeMap;

use super::names;
use super::{Attribute, Control, Convention, Draw, Filter, InstanceGrid, MeshKind, OrbitCamera, Pass, Pattern, Primitive, RenderTarget, SamplerInput, Scene, TargetFormat, Texture, TextureKind, ValueSpec, SCREEN};
use crate::emit::reflect_types::{EntryPoint, Reflection};

/// Why a program gets no inferred scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InferError(pub String);

impl std::fmt::Display for InferError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InferError {}

/// The vertex and fragment entry points of every program of a manifest,
/// in its order (each vertex entry point with the first fragment one,
/// where the manifest links none).
pub fn programs(r: &Reflection) -> Vec<(String, String)> {
    if !r.programs.is_empty() {
        return r.programs.iter().map(|p| (p.vertex.clone(), p.fragment.clone())).collect();
    }
    let fragment = r.entry_points.iter().find(|e| e.stage == "fragment");
    match fragment {
        Some(f) => r.entry_points.iter().filter(|e| e.stage == "vertex").map(|v| (v.name.clone(), f.name.clone())).collect(),
        None => Vec::new(),
    }
}

/// Per-frame conventions a name asks for even where the manifest has a
/// default: the default is a placeholder for what the host knows.
const PER_FRAME: [Convention; 6] = [Convention::Time, Convention::Frame, Convention::Resolution, Convention::Aspect, Convention::Mouse, Convention::TexelSize];

impl Scene {
    /// The scene of the manifest's first program.
    pub fn infer(r: &Reflection) -> Result<Scene, InferError> {
        let (vertex, fragment) = programs(r)
            .into_iter()
            .next()
            .ok_or_else(|| {
                InferError(format!(
                    "{} has no vertex and fragment entry points to draw (a compute program runs no scene; a lone fragment program is drawn with `fullscreen_vertex` appended)",
                    r.source
                ))
            })?;
        Scene::infer_program(r, &vertex, &fragment)
    }

    /// The scene of one program: `vertex` with `fragment`.
    pub fn infer_program(r: &Reflection, vertex: &str, fragment: &str) -> Result<Scene, InferError> {
        let entry = |name: &str, stage: &str| {
            r.entry_points
                .iter()
                .find(|e| e.name == name && e.stage == stage)
                .ok_or_else(|| InferError(format!("{} has no {stage} entry point `{name}`", r.source)))
        };
        let (vs, fs) = (entry(vertex, "vertex")?, entry(fragment, "fragment")?);
        if !vs.builtins.iter().any(|b| b == "gl_Position") {
            return Err(InferError(format!("`{vertex}` writes no gl_Position (a transform-feedback stage?): it places nothing to draw")));
        }
        // A point sprite: the sphere's vertices drawn as points.
        let points = fs.builtins.iter().any(|b| b == "gl_PointCoord") || vs.builtins.iter().any(|b| b == "gl_PointSize");
        let mut scene = Scene {
            camera: OrbitCamera::default(),
            textures: Vec::new(),
            targets: Vec::new(),
            passes: Vec::new(),
            output: SCREEN.to_string(),
            values: BTreeMap::new(),
            light: None,
            controls: Vec::new(),
        };
        let mut draw = infer_draw(vs);
        if points {
            if draw.mesh != MeshKind::Cube {
                return Err(InferError(format!(
                    "`{vertex}` + `{fragment}` draw point sprites with no 3D position input: the runner's point lists are a mesh's vertices"
                )));
            }
            draw.mesh = MeshKind::Sphere;
            draw.primitive = Primitive::Points;
        }
        let mut pass = Pass {
            name: format!("{vertex} + {fragment}"),
            vertex: vertex.to_string(),
            fragment: Some(fragment.to_string()),
            color: Some(SCREEN.into()),
            clear: [0.0, 0.0, 0.0, 1.0],
            depth: None,
            cull: super::Cull::None,
            depth_bias: false,
            samplers: BTreeMap::new(),
            values: BTreeMap::new(),
            draws: Vec::new(),
        };
        // A skybox (its vertex program reads a rotation-only view) puts its
        // depth at the far plane, which a LESS test against 1 would reject;
        // seen from inside, the cube needs no depth test.
        let skybox = uniforms(r, &[vs]).iter().any(|(n, ty, _)| names::convention(n, ty) == Some(Convention::ViewRotation));
        if !skybox && !matches!(draw.mesh, MeshKind::None | MeshKind::FullscreenTriangle) {
            scene.targets.push(RenderTarget { name: "depth".into(), format: TargetFormat::Depth32float, size: None });
            pass.depth = Some("depth".into());
        }
        if skybox {
            // Looking 10 degrees up: the horizon, sky above and ground below.
            scene.camera.pitch = -10.0;
        }
        pass.draws.push(draw);
        let mut clears = Vec::new();
        for name in vs.samplers.iter().chain(&fs.samplers) {
            if pass.samplers.contains_key(name) {
                continue;
            }
            let s = r.samplers.iter().find(|s| &s.name == name).ok_or_else(|| InferError(format!("sampler `{name}` is not in the manifest")))?;
            let kind = TextureKind::of_dimension(&s.dimension).ok_or_else(|| InferError(format!("sampler `{name}` is a {}: the runner's scenes have no {} textures", s.ty, s.dimension)))?;
            let texture = format!("{name}_texture");
            match s.sample_type.as_str() {
                "float" => {
                    let (pattern, size, layers) = match kind {
                        TextureKind::D2 => (pattern_for(name), 64, 1),
                        TextureKind::Cube => (Pattern::Sky, 64, 1),
                        TextureKind::D3 => (pattern_for(name), 32, 32),
                        TextureKind::D2Array => (pattern_for(name), 64, 4),
                    };
                    scene.textures.push(Texture { name: texture.clone(), pattern: Some(pattern), image: None, size: [size, size], kind, layers });
                }
                "depth" if kind == TextureKind::D2 => {
                    // A depth target no pass draws into but one that clears
                    // it: depth 1 everywhere, every compare passes.
                    scene.targets.push(RenderTarget { name: texture.clone(), format: TargetFormat::Depth32float, size: Some([64, 64]) });
                    clears.push(texture.clone());
                }
                "depth" => return Err(InferError(format!("sampler `{name}` is a {}: the runner's depth targets are 2D only (no cube or array shadow maps yet)", s.ty))),
                other => return Err(InferError(format!("sampler `{name}` reads {other} texels: the runner's patterns are float colours"))),
            }
            pass.samplers.insert(name.clone(), SamplerInput { texture, filter: Filter::Linear });
        }
        for target in clears {
            scene.passes.push(Pass {
                name: format!("clear {target}"),
                vertex: vertex.to_string(),
                fragment: None,
                color: None,
                clear: [0.0, 0.0, 0.0, 1.0],
                depth: Some(target),
                cull: super::Cull::None,
                depth_bias: false,
                samplers: BTreeMap::new(),
                values: BTreeMap::new(),
                draws: Vec::new(),
            });
        }
        let grid = pass.draws[0].instances.clone().unwrap_or(InstanceGrid { count: [3, 3, 1], spacing: 1.6 });
        for (name, ty, default) in uniforms(r, &[vs, fs]) {
            let parts = leaves(r, &name, &ty);
            if parts.len() != 1 || parts[0].path != name {
                // A struct (an instance table): each member by its path.
                scene.controls.push(names::control(&name, &ty, None));
                for l in parts {
                    if let Some(v) = leaf_value(&l, &grid) {
                        scene.values.insert(l.path, v);
                    }
                }
                continue;
            }
            let value = value_for(&name, &ty, default.as_deref());
            scene.controls.push(names::control(&name, &ty, value.as_ref()));
            if let Some(v) = value {
                scene.values.insert(name, v);
            }
        }
        scene.passes.push(pass);
        Ok(scene)
    }
}

/// The value an inferred scene gives a uniform (module docs).
fn value_for(name: &str, ty: &str, default: Option<&[u32]>) -> Option<ValueSpec> {
    let convention = names::convention(name, ty);
    if let Some(c) = convention.filter(|c| PER_FRAME.contains(c)) {
        return Some(ValueSpec::Convention(c));
    }
    if let Some(v) = default.and_then(|w| names::from_words(ty, w)) {
        return Some(v);
    }
    convention.map(ValueSpec::Convention).or_else(|| names::fallback(name, ty))
}

/// The value of a leaf of a struct uniform (`u_instances[3].offset_scale`):
/// a table indexed by instance reads the instance grid's cell `i mod n` for
/// element `i`: an offset or position member its centre (a 4th component
/// 0.45 when the name also says scale, else 1), a colour member its
/// colour (alpha 1), a scale or size 0.45, a phase its phase; any other
/// member what a uniform of its name gets.
fn leaf_value(l: &Leaf, grid: &InstanceGrid) -> Option<ValueSpec> {
    let member = l.path.rsplit('.').next().unwrap_or(&l.path);
    // Only an array is a table: a lone struct's members are named uniforms.
    let Some(i) = l.path.rsplit_once('[').and_then(|(_, rest)| rest.split(']').next()?.parse::<u32>().ok()) else {
        return value_for(member, &l.ty, None);
    };
    let (offset, colour, phase) = grid.instance(i % grid.total().max(1));
    let w = names::words(member);
    let has = |any: &[&str]| w.iter().any(|x| any.contains(&x.as_str()));
    let n = match l.ty.as_str() {
        "float" => 1,
        "float2" => 2,
        "float3" => 3,
        "float4" => 4,
        _ => return value_for(member, &l.ty, None),
    };
    let scale = 0.45;
    let xyz = |v: [f32; 3], w: f64| vec![f64::from(v[0]), f64::from(v[1]), f64::from(v[2]), w];
    let v: Vec<f64> = if has(&["offset", "position", "pos", "translate", "translation", "center", "centre"]) {
        xyz(offset, if has(&["scale", "size"]) { scale } else { 1.0 })
    } else if has(&["color", "colour", "tint", "albedo"]) {
        xyz(colour, 1.0)
    } else if has(&["scale", "size"]) {
        vec![scale; 4]
    } else if has(&["phase"]) {
        vec![f64::from(phase); 4]
    } else {
        return value_for(member, &l.ty, None);
    };
    Some(if n == 1 { ValueSpec::Number(v[0]) } else { ValueSpec::Numbers(v[..n].to_vec()) })
}

/// Every uniform the entry points read: loose ones and the members of the
/// uniform blocks they use (by member name), each once, with the
/// manifest's default where a loose one has it.
fn uniforms(r: &Reflection, entries: &[&EntryPoint]) -> Vec<(String, String, Option<Vec<u32>>)> {
    let mut out: Vec<(String, String, Option<Vec<u32>>)> = Vec::new();
    for u in &r.uniforms {
        if entries.iter().any(|e| e.uniforms.contains(&u.name)) {
            out.push((u.name.clone(), u.ty.clone(), u.default.clone()));
        }
    }
    for b in r.uniform_buffers.iter().filter(|b| !b.loose && entries.iter().any(|e| e.uniform_buffers.contains(&b.name))) {
        for m in &b.members {
            if !out.iter().any(|(n, _, _)| n == &m.name) {
                out.push((m.name.clone(), m.ty.clone(), None));
            }
        }
    }
    out
}

fn pattern_for(sampler: &str) -> Pattern {
    let w = names::words(sampler);
    let has = |any: &[&str]| w.iter().any(|x| any.contains(&x.as_str()));
    if has(&["normal", "nrm", "bump"]) {
        Pattern::FlatNormal
    } else if has(&["ao", "occlusion", "occ", "shadow", "mask"]) {
        Pattern::White
    } else if has(&["noise", "rough", "roughness", "arm", "metal", "metallic"]) {
        Pattern::Noise
    } else if has(&["uv", "ramp", "gradient"]) {
        Pattern::Uv
    } else {
        Pattern::Checker
    }
}

/// The draw of a vertex program (module docs).
fn infer_draw(vs: &EntryPoint) -> Draw {
    if vs.inputs.is_empty() {
        return Draw { mesh: MeshKind::None, vertices: Some(3), attributes: BTreeMap::new(), instances: None, values: BTreeMap::new(), transform: None, primitive: Primitive::Triangles };
    }
    let named: Vec<(String, &str, Option<Attribute>)> = vs.inputs.iter().map(|i| (i.name.clone(), i.ty.as_str(), names::attribute(&i.name))).collect();
    let by_id = vs.builtins.iter().any(|b| b == "gl_InstanceID" || b == "gl_InstanceIndex");
    let instanced = named.iter().any(|(_, _, a)| a.is_some_and(Attribute::per_instance));
    // The position: the input that says so, else the first.
    let position = named.iter().position(|(_, _, a)| *a == Some(Attribute::Position)).unwrap_or(0);
    let mesh = if named[position].1 == "float2" { MeshKind::FullscreenTriangle } else { MeshKind::Cube };
    let mut attributes = BTreeMap::new();
    let mut instance_fallbacks = [Attribute::InstanceColor, Attribute::InstancePhase].into_iter().cycle();
    for (i, (name, ty, a)) in named.iter().enumerate() {
        let a = if i == position {
            Attribute::Position
        } else {
            match a {
                Some(Attribute::Color) if instanced => Attribute::InstanceColor,
                Some(Attribute::Position) => Attribute::Color,
                Some(a) => *a,
                None if instanced && *ty == "float" => Attribute::InstancePhase,
                None if instanced => instance_fallbacks.next().unwrap(),
                None if *ty == "float2" => Attribute::Uv,
                None => Attribute::Color,
            }
        };
        attributes.insert(name.clone(), a);
    }
    let instances = (instanced || by_id).then_some(InstanceGrid { count: [3, 3, 1], spacing: 1.6 });
    Draw { mesh, vertices: None, attributes, instances, values: BTreeMap::new(), transform: None, primitive: Primitive::Triangles }
}

/// One value a struct uniform is set by: its path from the uniform
/// (`u_instances[3].color`), DSL type, byte offset from the uniform's
/// start and strides.
#[derive(Clone, Debug, PartialEq)]
pub struct Leaf {
    pub path: String,
    pub ty: String,
    pub offset: u32,
    pub array_stride: Option<u32>,
    pub matrix_stride: Option<u32>,
}

/// The leaves of a value `name` of type `ty`: itself, unless it is a
/// struct of the manifest (each member's leaves, `name.member`) or an
/// array of structs (each element's, `name[i]`). Arrays of plain types
/// stay one value.
pub fn leaves(r: &Reflection, name: &str, ty: &str) -> Vec<Leaf> {
    leaves_at(r, name, ty, None, None)
}

/// [`leaves`] of a value whose own strides are these (a block member's).
pub fn leaves_at(r: &Reflection, name: &str, ty: &str, array_stride: Option<u32>, matrix_stride: Option<u32>) -> Vec<Leaf> {
    let mut out = Vec::new();
    collect_leaves(r, name, ty, 0, array_stride, matrix_stride, &mut out);
    out
}

fn collect_leaves(r: &Reflection, name: &str, ty: &str, offset: u32, array_stride: Option<u32>, matrix_stride: Option<u32>, out: &mut Vec<Leaf>) {
    let array = ty.strip_suffix(']').and_then(|t| t.rsplit_once('[')).and_then(|(e, n)| Some((e, n.parse::<u32>().ok()?)));
    let structure = |t: &str| r.structs.iter().find(|s| s.name == t);
    match (array, structure(ty)) {
        (Some((element, n)), _) if structure(element).is_some() => {
            let stride = array_stride.unwrap_or_else(|| structure(element).map_or(16, |s| s.size.next_multiple_of(16)));
            for i in 0..n {
                collect_leaves(r, &format!("{name}[{i}]"), element, offset + i * stride, None, None, out);
            }
        }
        (None, Some(s)) => {
            for m in &s.members {
                collect_leaves(r, &format!("{name}.{}", m.name), &m.ty, offset + m.offset, m.array_stride, m.matrix_stride, out);
            }
        }
        _ => out.push(Leaf { path: name.to_string(), ty: ty.to_string(), offset, array_stride, matrix_stride }),
    }
}

/// The name of the vertex program [`fullscreen_vertex`] writes.
pub const FULLSCREEN_VS: &str = "umbrac_fullscreen_vs";

/// For a GL-dialect file with fragment entry points and no vertex one (a
/// lone fragment program, as Shadertoy's), the DSL text of a vertex program
/// to append to it: [`FULLSCREEN_VS`] places a full-screen triangle from
/// `gl_VertexID` and writes each varying the first fragment entry point
/// reads: a `float2` the uv in [0, 1] over the screen, a `float3` / `float4`
/// that uv with z 0 (and w 1), a `float` 0. The file compiled with it is
/// drawn by the inferred scene (three vertices). `None` for any other file.
pub fn fullscreen_vertex(r: &Reflection) -> Option<String> {
    if r.entry_points.iter().any(|e| e.stage == "vertex" || e.dialect.is_some()) {
        return None;
    }
    let fs = r.entry_points.iter().find(|e| e.stage == "fragment")?;
    let mut body = String::from("    let umbrac_p = float2(float((gl_VertexID & 1) * 4) - 1.0, float((gl_VertexID & 2) * 2) - 1.0)\n");
    for i in &fs.inputs {
        let value = match i.ty.as_str() {
            "float2" => "umbrac_p * 0.5 + float2(0.5)",
            "float3" => "float3(umbrac_p * 0.5 + float2(0.5), 0.0)",
            "float4" => "float4(umbrac_p * 0.5 + float2(0.5), 0.0, 1.0)",
            "float" => "0.0",
            _ => return None,
        };
        body.push_str(&format!("    {} = {value}\n", i.name));
    }
    Some(format!("\n[vertex_program]\ndef {FULLSCREEN_VS} {{\n{body}    gl_Position = float4(umbrac_p, 0.0, 1.0)\n}}\n"))
}

/// The controls of a scene's uniforms, by name (for a page).
pub fn control<'a>(scene: &'a Scene, name: &str) -> Option<&'a Control> {
    scene.controls.iter().find(|c| c.name == name)
}
