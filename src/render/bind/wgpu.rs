//! The WGSL / SPIR-V family: what a pass binds in which group at which
//! binding, and each uniform buffer's bytes, from the manifest's groups,
//! bindings, sizes and member offsets. The wgpu executor makes these into
//! bind group layouts and bind groups; nothing else there reads the
//! manifest's uniform section.

use std::collections::BTreeMap;

use crate::emit::reflect_types::Reflection;
use crate::render::plan::{Draw, Pass, Unset};

use super::{bytes, PassFit, Stages};

/// What one binding holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Resource {
    /// Uniform buffer `block` (index into the manifest) of `size` bytes.
    Buffer { block: usize, size: u64 },
    /// A sampler's texture: the pass's `textures[i]`, or (`None`) a 1x1
    /// stand-in where a pass binds what it does not read (SPIR-V
    /// passthrough layouts). `depth`: a depth sample type; else floats,
    /// `filterable` when the plan filters them linearly; `dim`: the
    /// sampler's dimension.
    Texture { texture: Option<usize>, depth: bool, filterable: bool, dim: ViewDim },
    /// A sampler's sampler state: of the pass's `textures[i]`, or a
    /// stand-in; `comparison`: a comparison sampler; `filtering`: linear.
    Sampler { texture: Option<usize>, comparison: bool, filtering: bool },
}

/// A texture binding's view dimension (the manifest's sampler `dimension`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ViewDim {
    D2,
    Cube,
    D3,
    D2Array,
}

impl ViewDim {
    pub fn of(dimension: &str) -> ViewDim {
        match dimension {
            "cube" => ViewDim::Cube,
            "3d" => ViewDim::D3,
            "2d-array" => ViewDim::D2Array,
            _ => ViewDim::D2,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Entry {
    pub binding: u32,
    pub stages: Stages,
    pub resource: Resource,
}

/// A pass's bind groups: entries by group number, sorted by binding.
pub type Groups = BTreeMap<u32, Vec<Entry>>;

/// The bind groups of a pass. With `passthrough` (SPIR-V handed to the
/// driver unchanged) every group holds every resource the manifest puts in
/// it, visible to both stages: wgpu's Vulkan backend numbers descriptors
/// by their position in a layout and, for WGSL, rewrites the shader's
/// bindings to match; a passthrough module keeps its own, so position and
/// binding must agree, which needs bindings 0, 1, 2 ... (umbrac numbers
/// them so).
pub fn groups(r: &Reflection, pass: &Pass, fit: &PassFit, passthrough: bool) -> Result<Groups, Vec<String>> {
    let mut groups: Groups = BTreeMap::new();
    let mut problems = Vec::new();
    let mut add = |group: u32, binding: u32, stages: Stages, resource: Resource, what: String, problems: &mut Vec<String>| {
        let list = groups.entry(group).or_default();
        match list.iter_mut().find(|e| e.binding == binding) {
            Some(e) if e.resource == resource => {
                e.stages.vertex |= stages.vertex;
                e.stages.fragment |= stages.fragment;
            }
            Some(_) => problems.push(format!("{what} shares group {group} binding {binding} with another resource")),
            None => list.push(Entry { binding, stages, resource }),
        }
    };
    for &(b, stages) in &fit.blocks {
        let block = &r.uniform_buffers[b];
        add(block.group, block.binding, stages, Resource::Buffer { block: b, size: block.size as u64 }, format!("uniform buffer `{}`", block.name), &mut problems);
    }
    for s in &fit.samplers {
        let m = &r.samplers[s.sampler];
        let linear = !m.comparison && pass.textures[s.texture].sampling.linear;
        let texture = Resource::Texture { texture: Some(s.texture), depth: m.comparison, filterable: linear, dim: ViewDim::of(&m.dimension) };
        let sampler = Resource::Sampler { texture: Some(s.texture), comparison: m.comparison, filtering: linear };
        add(m.group, m.texture_binding, s.stages, texture, format!("texture of `{}`", m.name), &mut problems);
        add(m.group, m.sampler_binding, s.stages, sampler, format!("sampler of `{}`", m.name), &mut problems);
    }
    if passthrough {
        let both = Stages { vertex: true, fragment: true };
        for (i, block) in r.uniform_buffers.iter().enumerate() {
            let list = groups.entry(block.group).or_default();
            if !list.iter().any(|e| e.binding == block.binding) {
                list.push(Entry { binding: block.binding, stages: both, resource: Resource::Buffer { block: i, size: block.size as u64 } });
            }
        }
        for m in &r.samplers {
            let list = groups.entry(m.group).or_default();
            if !list.iter().any(|e| e.binding == m.texture_binding) {
                list.push(Entry { binding: m.texture_binding, stages: both, resource: Resource::Texture { texture: None, depth: m.comparison, filterable: false, dim: ViewDim::of(&m.dimension) } });
            }
            if !list.iter().any(|e| e.binding == m.sampler_binding) {
                list.push(Entry { binding: m.sampler_binding, stages: both, resource: Resource::Sampler { texture: None, comparison: m.comparison, filtering: false } });
            }
        }
        for e in groups.values_mut().flatten() {
            e.stages = both;
        }
    }
    for (group, list) in groups.iter_mut() {
        list.sort_by_key(|e| e.binding);
        if passthrough {
            if let Some((i, e)) = list.iter().enumerate().find(|(i, e)| e.binding != *i as u32) {
                problems.push(format!(
                    "group {group} has binding {} in place {i}: SPIR-V passed to wgpu unchanged needs bindings 0, 1, 2 ... with no gaps",
                    e.binding
                ));
            }
        }
    }
    if problems.is_empty() {
        Ok(groups)
    } else {
        Err(problems)
    }
}

/// The bytes of uniform block `block` for one draw of `pass`, at the
/// manifest's offsets (the WGSL uniform layout).
pub fn buffer_bytes(r: &Reflection, block: usize, pass: &Pass, draw: &Draw, unset: Unset) -> Result<Vec<u8>, String> {
    let layout = super::manifest_layout(r, &r.uniform_buffers[block]);
    bytes::fill(&layout, |n| pass.value(draw, n), &pass.value_names(draw), unset).map_err(|e| e.join("; "))
}
