//! Binding a frame plan to a program: which entry points each pass runs,
//! which mesh field feeds which vertex input, which uniform blocks and
//! samplers each pass uses and which texture each sampler reads. Pure
//! data, no GPU.
//!
//! [`fit`] checks a program's manifest against a plan (everything wrong is
//! listed, not just the first thing) and says what each pass uses, by
//! index into the manifest. What those uses become on an API is per target
//! family, each in one small module: [`wgpu`] (bind groups, buffers filled
//! at the manifest's offsets: WGSL and SPIR-V) and [`gl`] (uniform blocks
//! by GLSL name, sampler units, attribute locations, default-block uniforms
//! by name: GLSL 330 and ES 3.00, on a GL context or in WebGL2). [`bytes`]
//! puts values at a layout, for both.

pub mod bytes;
pub mod compute;
pub mod gl;
pub mod wgpu;

use std::collections::BTreeMap;

use crate::emit::reflect_types::{EntryPoint, Reflection, UniformBuffer};
pub use crate::scene::infer::{leaves, leaves_at, Leaf};

use super::plan::{Field, FramePlan, Geometry, Pass};

/// A program that does not fit a plan, with everything that is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InterfaceError {
    pub program: String,
    /// The plan's scene (`the shadow scene`).
    pub scene: String,
    pub problems: Vec<String>,
}

impl std::fmt::Display for InterfaceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "{} does not fit {}'s interface:", self.program, self.scene)?;
        for p in &self.problems {
            writeln!(f, "  - {p}")?;
        }
        Ok(())
    }
}

/// Which stages use a resource.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Stages {
    pub vertex: bool,
    pub fragment: bool,
}

/// One vertex input and the mesh field that feeds it.
#[derive(Clone, Debug, PartialEq)]
pub struct AttributeFit {
    /// The DSL name (`a_pos`).
    pub name: String,
    /// The GLSL identifier the manifest gives.
    pub glsl_name: String,
    pub location: u32,
    pub field: Field,
}

/// A sampler a pass reads and the plan texture (index into the pass's
/// `textures`) it reads.
#[derive(Clone, Debug, PartialEq)]
pub struct SamplerFit {
    /// Index into `Reflection::samplers`.
    pub sampler: usize,
    pub texture: usize,
    pub stages: Stages,
}

/// What one pass of a plan uses of a program.
#[derive(Clone, Debug, PartialEq)]
pub struct PassFit {
    pub attributes: Vec<AttributeFit>,
    /// Indices into `Reflection::uniform_buffers`, with the stages that use them.
    pub blocks: Vec<(usize, Stages)>,
    /// Indices into `Reflection::uniforms` of the loose uniforms the pass
    /// reads (GLSL declares them plain, unless `gl_uniforms` is `blocks`).
    pub uniforms: Vec<usize>,
    /// The fragment entry point's colour outputs: (GLSL name, location,
    /// whether the GLSL declares the location).
    pub outputs: Vec<(String, u32, bool)>,
    pub samplers: Vec<SamplerFit>,
}

/// A program fitted to a plan: one [`PassFit`] per pass.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    pub passes: Vec<PassFit>,
    /// Portable conventions: the image arrives bottom row first on WebGPU
    /// and Vulkan, and front faces are clockwise there.
    pub portable: bool,
    /// The plan's vertex entry points are in daslang's Vulkan dialect:
    /// with portable conventions every target stores the picture's top in
    /// memory row 0 (docs/targets.md), so nothing is flipped on read-back.
    pub vulkan: bool,
}

impl Fit {
    /// Whether the image arrives bottom row first on WebGPU/Vulkan and
    /// front faces are clockwise there: portable conventions mirror
    /// GL-dialect code, native ones leave Vulkan-dialect code (y down)
    /// under WebGPU's y-up NDC.
    pub fn mirrored_on_webgpu(&self) -> bool {
        self.portable != self.vulkan
    }
}

/// The value names a uniform buffer's members take: each member is the
/// value of its name (a loose uniform of the group's buffer, or a field of
/// a struct uniform).
pub fn value_names(b: &UniformBuffer) -> Vec<String> {
    b.members.iter().map(|m| m.name.clone()).collect()
}

/// A uniform buffer of the manifest as a buffer layout: its members at
/// their offsets, filled by the values [`value_names`] gives them. A loose
/// member stored as another type (`bool` as `uint`, `float[9]` as
/// `float4[9]`, `float3x2` as `float4` columns) is written as its own type
/// at the strides the manifest states for the stored one.
pub fn manifest_layout(r: &Reflection, b: &UniformBuffer) -> bytes::BufferLayout {
    let mut slots = Vec::new();
    for m in &b.members {
        let leaves = leaves_at(r, &m.name, &m.ty, m.array_stride, m.matrix_stride);
        if leaves.len() == 1 && leaves[0].path == m.name {
            slots.push(bytes::Slot {
                value: m.name.clone(),
                ty: m.ty.clone(),
                offset: m.offset,
                array_stride: m.array_stride,
                matrix_stride: m.matrix_stride,
                default: m.default.clone(),
            });
            continue;
        }
        // A struct (or an array of them): one slot per leaf, by its path.
        for l in leaves {
            slots.push(bytes::Slot { value: l.path, ty: l.ty, offset: m.offset + l.offset, array_stride: l.array_stride, matrix_stride: l.matrix_stride, default: None });
        }
    }
    bytes::BufferLayout { name: b.name.clone(), size: b.size, slots }
}

fn entry<'r>(r: &'r Reflection, name: &str, stage: &str, problems: &mut Vec<String>) -> Option<&'r EntryPoint> {
    match r.entry_points.iter().find(|e| e.name == name) {
        Some(e) if e.stage == stage => Some(e),
        Some(e) => {
            problems.push(format!("entry point `{name}` is a {} program; the scene runs it as a {stage} program", e.stage));
            None
        }
        None => {
            problems.push(format!("no {stage} entry point `{name}`"));
            None
        }
    }
}

/// Fits `r` to `plan`. `program` names the program in messages.
pub fn fit(program: &str, r: &Reflection, plan: &FramePlan) -> Result<Fit, InterfaceError> {
    let mut problems = Vec::new();
    let portable = match r.conventions.as_str() {
        "portable" => true,
        "native" => false,
        other => {
            problems.push(format!("unknown conventions `{other}` (expected `portable` or `native`)"));
            true
        }
    };
    if let Err(e) = plan.check() {
        problems.push(e);
    }
    // Every value a block member takes must be declared once.
    let mut declared: BTreeMap<String, &str> = BTreeMap::new();
    for b in &r.uniform_buffers {
        for v in value_names(b) {
            if let Some(prev) = declared.insert(v.clone(), &b.name) {
                problems.push(format!("uniform `{v}` is declared twice (buffers `{prev}` and `{}`)", b.name));
            }
        }
    }
    for need in &plan.required {
        if !declared.contains_key(&need.value) {
            problems.push(format!("no `{}` uniform: {}", need.value, need.why));
        }
    }
    let passes: Vec<PassFit> = plan.passes.iter().map(|pass| fit_pass(r, plan, pass, &mut problems)).collect();
    let vulkan = is_vulkan(r, plan);
    // Every draw's values fill the blocks its pass uses.
    for (pass, pf) in plan.passes.iter().zip(&passes) {
        for draw in &pass.draws {
            let known = pass.value_names(draw);
            for &(b, _) in &pf.blocks {
                if let Err(e) = bytes::fill(&manifest_layout(r, &r.uniform_buffers[b]), |n| pass.value(draw, n), &known, plan.unset) {
                    problems.extend(e);
                }
            }
        }
    }
    if problems.is_empty() {
        Ok(Fit { passes, portable, vulkan })
    } else {
        let mut seen = std::collections::BTreeSet::new();
        problems.retain(|p| seen.insert(p.clone()));
        Err(InterfaceError { program: program.to_string(), scene: plan.scene.clone(), problems })
    }
}

/// Whether the plan's vertex entry points are Vulkan-dialect code (the
/// manifest's `dialect`); a plan mixing dialects has no one orientation.
pub fn is_vulkan(r: &Reflection, plan: &FramePlan) -> bool {
    plan.passes.iter().any(|p| r.entry_points.iter().any(|e| e.name == p.vertex && e.dialect.as_deref() == Some("vulkan")))
}

fn fit_pass(r: &Reflection, plan: &FramePlan, pass: &Pass, problems: &mut Vec<String>) -> PassFit {
    let v = entry(r, &pass.vertex, "vertex", problems);
    let f = pass.fragment.as_ref().and_then(|f| entry(r, f, "fragment", problems));
    let mut attributes = Vec::new();
    // A pass that draws nothing (the empty shadow map of `lit`) feeds no inputs.
    if let Some(v) = v.filter(|_| !pass.draws.is_empty()) {
        let meshes: Vec<_> = pass
            .draws
            .iter()
            .filter_map(|d| match d.geometry {
                Geometry::Mesh(m) => Some(m),
                Geometry::Vertices(_) => None,
            })
            .collect();
        for m in &meshes {
            if !v.inputs.iter().any(|i| i.name == m.position) {
                problems.push(format!("no `{}` vertex input in `{}`: nothing positions the vertices", m.position, v.name));
            }
        }
        for input in &v.inputs {
            let Some(first) = meshes.first() else {
                problems.push(format!(
                    "vertex input `{}` of `{}`: the {} pass draws without vertex buffers",
                    input.name, v.name, pass.name
                ));
                continue;
            };
            let Some(field) = first.field(&input.name) else {
                let have: Vec<&str> = first.fields.iter().map(|f| f.name).collect();
                problems.push(format!("vertex input `{}` of `{}` is not in the scene's meshes (they have {})", input.name, v.name, have.join(", ")));
                continue;
            };
            let format = input.vertex_format.clone().unwrap_or_default();
            if format != field.format.name() {
                problems.push(format!(
                    "vertex input `{}` of `{}` is {} ({format}); the scene's meshes give it {}",
                    input.name,
                    v.name,
                    input.ty,
                    field.format.name()
                ));
                continue;
            }
            if meshes.iter().any(|m| m.field(&input.name) != Some(field)) {
                problems.push(format!("the meshes of the {} pass lay out `{}` differently", pass.name, input.name));
            }
            attributes.push(AttributeFit { name: input.name.clone(), glsl_name: input.glsl_name.clone(), location: input.location, field: field.clone() });
        }
    }
    let mut blocks: Vec<(usize, Stages)> = Vec::new();
    let mut samplers: Vec<SamplerFit> = Vec::new();
    let mut uniforms: Vec<usize> = Vec::new();
    let outputs = f.map_or_else(Vec::new, |f| f.outputs.iter().map(|o| (o.glsl_name.clone(), o.location, o.glsl_location.is_some())).collect());
    for (e, vertex) in [(v, true), (f, false)] {
        let Some(e) = e else { continue };
        let stage = |s: &mut Stages| if vertex { s.vertex = true } else { s.fragment = true };
        for name in &e.uniforms {
            match r.uniforms.iter().position(|u| &u.name == name) {
                Some(i) if !uniforms.contains(&i) => uniforms.push(i),
                Some(_) => {}
                None => problems.push(format!("entry point `{}` uses `{name}`, which the reflection does not declare", e.name)),
            }
        }
        for name in &e.uniform_buffers {
            let Some(i) = r.uniform_buffers.iter().position(|b| &b.name == name) else {
                problems.push(format!("entry point `{}` uses `{name}`, which the reflection does not declare", e.name));
                continue;
            };
            match blocks.iter_mut().find(|(b, _)| *b == i) {
                Some((_, s)) => stage(s),
                None => {
                    let mut s = Stages::default();
                    stage(&mut s);
                    blocks.push((i, s));
                }
            }
        }
        for name in &e.samplers {
            let Some(i) = r.samplers.iter().position(|s| &s.name == name) else {
                problems.push(format!("entry point `{}` uses `{name}`, which the reflection does not declare", e.name));
                continue;
            };
            if let Some(s) = samplers.iter_mut().find(|s| s.sampler == i) {
                stage(&mut s.stages);
                continue;
            }
            let s = &r.samplers[i];
            let Some(texture) = pass.textures.iter().position(|t| t.sampler == s.name) else {
                let elsewhere = plan.passes.iter().flat_map(|p| &p.textures).find(|t| t.sampler == s.name);
                match elsewhere {
                    Some(t) if pass.writes(t.target) => problems.push(format!(
                        "`{}` samples `{}` in the {} pass, which renders that texture",
                        e.name, s.name, pass.name
                    )),
                    _ => {
                        let have: Vec<&str> = plan.passes.iter().flat_map(|p| &p.textures).map(|t| t.sampler.as_str()).collect();
                        problems.push(format!(
                            "sampler `{}` is not a texture the scene provides in its {} pass (it provides {})",
                            s.name,
                            pass.name,
                            if have.is_empty() { "none".to_string() } else { have.join(", ") }
                        ))
                    }
                }
                continue;
            };
            let t = &pass.textures[texture];
            let target = plan.target(t.target);
            if s.dimension != target.dim.name() {
                problems.push(format!("sampler `{}` is a {}, but the scene's `{}` is a {} texture", s.name, s.ty, target.name, target.dim.name()));
            }
            if s.comparison != t.sampling.compare {
                problems.push(format!(
                    "sampler `{}` is a {} ({}), but the scene reads `{}` {}",
                    s.name,
                    s.ty,
                    if s.comparison { "a depth compare" } else { "no compare" },
                    target.name,
                    if t.sampling.compare { "with a depth compare" } else { "without a compare" }
                ));
            }
            if s.sample_type == "depth" && !target.format.is_depth() {
                problems.push(format!("sampler `{}` is a {} but `{}` is a colour target", s.name, s.ty, target.name));
            }
            let mut stages = Stages::default();
            stage(&mut stages);
            samplers.push(SamplerFit { sampler: i, texture, stages });
        }
    }
    PassFit { attributes, blocks, samplers, uniforms, outputs }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::hand;
    use crate::render::plan::tutorial;
    use crate::render::FrameParams;

    fn plan() -> FramePlan {
        tutorial::plan(&FrameParams::new(1.0, 16, 12))
    }

    #[test]
    fn hand_reflection_fits() {
        let f = fit("hand", &hand::reflection(), &plan()).unwrap();
        assert_eq!(f.passes.len(), 2);
        // One buffer of loose uniforms; the shadow pass reads two of them.
        assert_eq!(f.passes[0].blocks.len(), 1);
        assert_eq!(f.passes[0].uniforms.len(), 2);
        assert_eq!(f.passes[1].samplers.len(), 1);
        assert_eq!(f.passes[1].attributes.iter().map(|a| a.location).collect::<Vec<_>>(), [0, 1]);
    }

    #[test]
    fn misfits_are_all_reported() {
        let mut r = hand::reflection();
        r.uniforms[5].name = "u_eye".into();
        r.entry_points.retain(|e| e.name != "shadow_fs");
        r.samplers[0].comparison = false;
        let text = fit("broken", &r, &plan()).unwrap_err().to_string();
        assert!(text.contains("no fragment entry point `shadow_fs`"), "{text}");
        assert!(text.contains("uses `u_cam_pos`, which the reflection does not declare"), "{text}");
        assert!(text.contains("reads `shadow map` with a depth compare"), "{text}");
    }

    #[test]
    fn sampling_in_the_pass_that_renders_it_is_refused() {
        let mut r = hand::reflection();
        r.entry_points.iter_mut().find(|e| e.name == "shadow_fs").unwrap().samplers = vec!["shadow_map".into()];
        let text = fit("loop", &r, &plan()).unwrap_err().to_string();
        assert!(text.contains("`shadow_fs` samples `shadow_map` in the shadow pass, which renders that texture"), "{text}");
    }
}
