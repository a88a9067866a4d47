//! Fits a program's reflection to the scene: which uniform value goes to
//! which binding at which offset, which mesh field feeds which attribute
//! location, which resources each pass binds. Pure data, no GPU: every
//! number the renderer binds comes from here, and here only from the
//! reflection.

use std::collections::BTreeMap;

use crate::emit::reflect_types::{EntryPoint, Reflection};

use super::scene::{self, Draw, Frame};

/// A shader program that does not fit the scene, with everything that is
/// wrong (not just the first thing).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InterfaceError {
    pub program: String,
    pub problems: Vec<String>,
}

impl std::fmt::Display for InterfaceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "{} does not fit the shadow scene's interface:", self.program)?;
        for p in &self.problems {
            writeln!(f, "  - {p}")?;
        }
        Ok(())
    }
}

/// Where one scene value is written inside a uniform block.
#[derive(Clone, Debug, PartialEq)]
pub struct ValueSlot {
    /// The scene uniform's name (`u_model`, ...).
    pub value: String,
    pub offset: u32,
    pub matrix_stride: u32,
}

/// One uniform block as the renderer fills it.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockPlan {
    pub name: String,
    pub group: u32,
    pub binding: u32,
    pub size: u32,
    pub slots: Vec<ValueSlot>,
    /// Members the scene does not set, filled with their default
    /// (`var @uniform x : T = value`): (offset, words).
    pub defaults: Vec<(u32, Vec<u32>)>,
}

impl BlockPlan {
    /// The block's bytes for one draw.
    pub fn bytes(&self, frame: &Frame, draw: &Draw) -> Vec<u8> {
        let mut out = vec![0u8; self.size as usize];
        for (offset, words) in &self.defaults {
            for (i, w) in words.iter().enumerate() {
                let at = *offset as usize + 4 * i;
                if let Some(dst) = out.get_mut(at..at + 4) {
                    dst.copy_from_slice(&w.to_le_bytes());
                }
            }
        }
        for s in &self.slots {
            let v = frame.uniform(&s.value, draw).expect("slot names were checked against the scene");
            let ok = v.write(&mut out[s.offset as usize..], s.matrix_stride as usize);
            debug_assert!(ok, "slot bounds were checked against the block size");
        }
        out
    }
}

/// What a bind group layout entry holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResourceKind {
    /// Index into `Plan::blocks`.
    Uniform(usize),
    /// The shadow map's depth texture.
    ShadowTexture,
    /// The shadow map's comparison sampler.
    ShadowSampler,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stages {
    pub vertex: bool,
    pub fragment: bool,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutEntry {
    pub binding: u32,
    pub kind: ResourceKind,
    pub stages: Stages,
}

/// One vertex attribute: the shader's location fed from a mesh field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Attribute {
    pub name: String,
    pub location: u32,
    /// Byte offset in `scene::Vertex`.
    pub offset: u64,
    /// wgpu's name for the format (`Float32x3`).
    pub format: String,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PassPlan {
    pub vertex_entry: String,
    pub fragment_entry: String,
    pub attributes: Vec<Attribute>,
    /// Bind group layouts by group number, entries sorted by binding.
    pub groups: BTreeMap<u32, Vec<LayoutEntry>>,
}

/// Everything needed to bind a program to the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    pub program: String,
    pub blocks: Vec<BlockPlan>,
    pub shadow: PassPlan,
    pub main: PassPlan,
    /// Portable conventions: the image arrives bottom row first; flip it,
    /// and front faces are clockwise.
    pub portable: bool,
}

impl Plan {
    /// The plan for SPIR-V handed to Vulkan unchanged (passthrough).
    /// wgpu's Vulkan backend numbers descriptors by their position in a
    /// bind group layout and, for WGSL, rewrites the shader's bindings to
    /// match; a passthrough module keeps its own. So every pass gets every
    /// binding of each group, in order, and the bindings must be 0, 1, 2 ...
    /// (umbrac numbers them so): then position and binding agree.
    pub fn for_passthrough(&self) -> Result<Plan, InterfaceError> {
        let mut all: BTreeMap<u32, Vec<LayoutEntry>> = BTreeMap::new();
        for pass in [&self.shadow, &self.main] {
            for (&group, entries) in &pass.groups {
                let list = all.entry(group).or_default();
                for e in entries {
                    match list.iter_mut().find(|x| x.binding == e.binding) {
                        Some(x) => {
                            x.stages.vertex |= e.stages.vertex;
                            x.stages.fragment |= e.stages.fragment;
                        }
                        None => list.push(e.clone()),
                    }
                }
            }
        }
        let mut problems = Vec::new();
        for (group, list) in all.iter_mut() {
            list.sort_by_key(|e| e.binding);
            if let Some((i, e)) = list.iter().enumerate().find(|(i, e)| e.binding != *i as u32) {
                problems.push(format!("group {group} has binding {} in place {i}: SPIR-V passed to wgpu unchanged needs bindings 0, 1, 2 ... with no gaps", e.binding));
            }
        }
        if !problems.is_empty() {
            return Err(InterfaceError { program: self.program.clone(), problems });
        }
        let mut plan = self.clone();
        plan.shadow.groups = all.clone();
        plan.main.groups = all;
        Ok(plan)
    }
}

/// A resource the reflection declares, by name.
#[derive(Clone, Copy)]
enum Declared {
    Block(usize),
    /// Index into `Reflection::samplers`.
    Sampler(usize),
}

/// Fits `r` to the scene. `program` names the program in messages.
pub fn plan(program: &str, r: &Reflection) -> Result<Plan, InterfaceError> {
    let mut problems = Vec::new();
    let scene_list = scene::UNIFORM_NAMES.join(", ");

    let portable = match r.conventions.as_str() {
        "portable" => true,
        "native" => false,
        other => {
            problems.push(format!("unknown conventions `{other}` (expected `portable` or `native`)"));
            true
        }
    };

    // Uniform blocks: each member (or the loose value) must be a value the
    // scene sets, with the scene's type, inside the block.
    let mut provided: BTreeMap<String, String> = BTreeMap::new();
    let mut blocks = Vec::new();
    for b in &r.uniform_blocks {
        let loose = b.members.len() == 1 && (b.members[0].name == b.name || b.members[0].ty == b.ty);
        let mut slots = Vec::new();
        let mut defaults = Vec::new();
        for m in &b.members {
            let value_name = if loose { b.name.as_str() } else { m.name.as_str() };
            let Some(expected) = scene::uniform_type(value_name) else {
                // A value the scene does not know keeps its default.
                match &m.default {
                    Some(words) if m.offset + 4 * words.len() as u32 <= b.size => defaults.push((m.offset, words.clone())),
                    _ => problems.push(format!("uniform `{value_name}` is not a value the scene sets (it sets {scene_list}) and has no default")),
                }
                continue;
            };
            if m.ty != expected {
                problems.push(format!("uniform `{value_name}` is {} but the scene sets a {expected}", m.ty));
                continue;
            }
            let stride = m.matrix_stride.unwrap_or(16);
            let bytes = match expected {
                "float4x4" => 3 * stride + 16,
                "float3" => 12,
                _ => 4,
            };
            if m.offset + bytes > b.size {
                problems.push(format!(
                    "uniform `{value_name}` at offset {} ({bytes} bytes) overruns its block `{}` of {} bytes",
                    m.offset, b.name, b.size
                ));
                continue;
            }
            if let Some(prev) = provided.insert(value_name.to_string(), b.name.clone()) {
                problems.push(format!("uniform `{value_name}` is declared twice (blocks `{prev}` and `{}`)", b.name));
            }
            slots.push(ValueSlot { value: value_name.to_string(), offset: m.offset, matrix_stride: stride });
        }
        blocks.push(BlockPlan { name: b.name.clone(), group: b.group, binding: b.binding, size: b.size, slots, defaults });
    }
    for need in scene::REQUIRED_UNIFORMS {
        if !provided.contains_key(need) {
            problems.push(format!("no `{need}` uniform: the scene cannot place its geometry without it"));
        }
    }

    let mut declared: BTreeMap<&str, Declared> = BTreeMap::new();
    for (i, b) in r.uniform_blocks.iter().enumerate() {
        declared.insert(&b.name, Declared::Block(i));
    }
    for (i, s) in r.samplers.iter().enumerate() {
        declared.insert(&s.name, Declared::Sampler(i));
        if !(s.comparison && s.sample_type == "depth" && s.dimension == "2d") {
            problems.push(format!(
                "sampler `{}` is a {} but the scene's only texture is the shadow map (a 2d depth texture with a comparison sampler, sampler2DShadow)",
                s.name, s.ty
            ));
        }
    }

    // Bindings must be distinct.
    let mut taken: BTreeMap<(u32, u32), String> = BTreeMap::new();
    let mut claim = |group: u32, binding: u32, what: String, problems: &mut Vec<String>| {
        if let Some(prev) = taken.insert((group, binding), what.clone()) {
            problems.push(format!("{what} and {prev} share group {group} binding {binding}"));
        }
    };
    for b in &r.uniform_blocks {
        claim(b.group, b.binding, format!("uniform block `{}`", b.name), &mut problems);
    }
    for s in &r.samplers {
        claim(s.group, s.texture_binding, format!("texture of `{}`", s.name), &mut problems);
        claim(s.group, s.sampler_binding, format!("sampler of `{}`", s.name), &mut problems);
    }

    let find = |name: &str, stage: &str, problems: &mut Vec<String>| -> Option<&EntryPoint> {
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
    };
    let pass = |label: &str, vs: &str, fs: &str, shadow_pass: bool, problems: &mut Vec<String>| -> PassPlan {
        let v = find(vs, "vertex", problems);
        let f = find(fs, "fragment", problems);
        let mut attributes = Vec::new();
        if let Some(v) = v {
            for input in &v.inputs {
                let Some(offset) = scene::attribute_offset(&input.name) else {
                    problems.push(format!(
                        "vertex input `{}` of `{vs}` is not in the scene's meshes (they have {}, {})",
                        input.name,
                        scene::ATTR_POS,
                        scene::ATTR_NORMAL
                    ));
                    continue;
                };
                let format = input.vertex_format.clone().unwrap_or_else(|| match input.ty.as_str() {
                    "float3" => "Float32x3".into(),
                    other => other.to_string(),
                });
                if format != "Float32x3" {
                    problems.push(format!(
                        "vertex input `{}` of `{vs}` is {} ({format}); the scene's meshes give it float3 (Float32x3)",
                        input.name, input.ty
                    ));
                    continue;
                }
                attributes.push(Attribute { name: input.name.clone(), location: input.location, offset, format });
            }
            if !v.inputs.iter().any(|i| i.name == scene::ATTR_POS) {
                problems.push(format!("no `{}` vertex input in `{vs}`: nothing positions the vertices", scene::ATTR_POS));
            }
        }
        let mut groups: BTreeMap<u32, Vec<LayoutEntry>> = BTreeMap::new();
        let mut add = |group: u32, binding: u32, kind: ResourceKind, vertex: bool| {
            let entries = groups.entry(group).or_default();
            match entries.iter_mut().find(|e| e.binding == binding) {
                Some(e) => {
                    e.stages.vertex |= vertex;
                    e.stages.fragment |= !vertex;
                }
                None => entries.push(LayoutEntry { binding, kind, stages: Stages { vertex, fragment: !vertex } }),
            }
        };
        for (e, vertex) in [(v, true), (f, false)] {
            let Some(e) = e else { continue };
            for name in e.uniform_blocks.iter().chain(&e.samplers) {
                match declared.get(name.as_str()) {
                    Some(Declared::Block(i)) => {
                        let b = &r.uniform_blocks[*i];
                        add(b.group, b.binding, ResourceKind::Uniform(*i), vertex);
                    }
                    Some(Declared::Sampler(i)) => {
                        let s = &r.samplers[*i];
                        if shadow_pass {
                            problems.push(format!(
                                "`{}` samples `{}` in the {label} pass, which renders that texture",
                                e.name, s.name
                            ));
                            continue;
                        }
                        add(s.group, s.texture_binding, ResourceKind::ShadowTexture, vertex);
                        add(s.group, s.sampler_binding, ResourceKind::ShadowSampler, vertex);
                    }
                    None => problems.push(format!("entry point `{}` uses `{name}`, which the reflection does not declare", e.name)),
                }
            }
        }
        for entries in groups.values_mut() {
            entries.sort_by_key(|e| e.binding);
        }
        PassPlan { vertex_entry: vs.to_string(), fragment_entry: fs.to_string(), attributes, groups }
    };
    let shadow = pass("shadow", scene::SHADOW_VS, scene::SHADOW_FS, true, &mut problems);
    let main = pass("main", scene::MAIN_VS, scene::MAIN_FS, false, &mut problems);

    if problems.is_empty() {
        Ok(Plan { program: program.to_string(), blocks, shadow, main, portable })
    } else {
        Err(InterfaceError { program: program.to_string(), problems })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::hand;

    #[test]
    fn hand_reflection_fits() {
        let p = plan("hand", &hand::reflection()).unwrap();
        assert_eq!(p.blocks.len(), 7);
        assert!(p.portable);
        assert_eq!(p.shadow.groups[&0].len(), 2);
        assert_eq!(p.main.groups[&0].len(), 9);
        assert_eq!(p.main.attributes.len(), 2);
    }

    #[test]
    fn missing_model_and_position_are_named() {
        let mut r = hand::reflection();
        r.uniform_blocks.retain(|b| b.name != "u_model");
        for e in &mut r.entry_points {
            e.uniform_blocks.retain(|b| b != "u_model");
            e.inputs.retain(|i| i.name != "a_pos");
        }
        let err = plan("broken", &r).unwrap_err();
        let text = err.to_string();
        assert!(text.contains("no `u_model` uniform"), "{text}");
        assert!(text.contains("no `a_pos` vertex input in `main_vs`"), "{text}");
        assert!(text.contains("no `a_pos` vertex input in `shadow_vs`"), "{text}");
    }

    #[test]
    fn wrong_types_and_unknown_names_are_named() {
        let mut r = hand::reflection();
        r.uniform_blocks[6].members[0].ty = "int".into();
        r.uniform_blocks[6].ty = "int".into();
        r.uniform_blocks[5].name = "u_eye".into();
        r.entry_points.retain(|e| e.name != "shadow_fs");
        let text = plan("broken", &r).unwrap_err().to_string();
        assert!(text.contains("`u_is_floor` is int"), "{text}");
        assert!(text.contains("uniform `u_eye` is not a value the scene sets"), "{text}");
        assert!(text.contains("no fragment entry point `shadow_fs`"), "{text}");
    }

    #[test]
    fn struct_blocks_bind_members_by_name() {
        use crate::emit::reflect_types::{Member, UniformBlock};
        let mut r = hand::reflection();
        // Fold the three fragment values into one block, in another order.
        r.uniform_blocks.retain(|b| !["u_light_dir", "u_cam_pos", "u_is_floor"].contains(&b.name.as_str()));
        let m = |name: &str, ty: &str, offset, size| Member {
            name: name.into(),
            ty: ty.into(),
            offset,
            size,
            array_stride: None,
            matrix_stride: None,
            default: None,
        };
        r.uniform_blocks.push(UniformBlock {
            name: "Lighting".into(),
            ty: "Lighting".into(),
            size: 32,
            group: 0,
            binding: 4,
            glsl_block: "Lighting".into(),
            members: vec![m("u_is_floor", "float", 0, 4), m("u_cam_pos", "float3", 16, 12), m("u_light_dir", "float3", 4, 12)],
        });
        for e in &mut r.entry_points {
            if e.name == "main_fs" {
                e.uniform_blocks = vec!["Lighting".into()];
            }
        }
        let p = plan("struct", &r).unwrap();
        let b = p.blocks.iter().find(|b| b.name == "Lighting").unwrap();
        let f = Frame::at(1.0, 1.5);
        let d = f.draws()[1];
        let bytes = b.bytes(&f, &d);
        let at = |o: usize| f32::from_le_bytes(bytes[o..o + 4].try_into().unwrap());
        assert_eq!(at(0), 1.0);
        assert_eq!(at(4), f.light_dir.x);
        assert_eq!(at(16), f.cam_pos.x);
    }
}
