//! The differential check of the `compile` target: umbrac's WGSL, read by
//! naga's WGSL front end and converted by naga's SPIR-V back end, must
//! agree with umbrac's own SPIR-V (read by naga's SPIR-V front end) and
//! with the reflection manifest on what a host binds against: the entry
//! points, their stages, the locations of their inputs and outputs, and
//! the (group, binding) pairs of the resources. The interfaces of the naga
//! modules are compared, not the bytes: two back ends may order or name
//! things differently and both be right.

use std::collections::BTreeSet;

/// One entry point as a host sees it.
#[derive(Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Entry {
    pub name: String,
    pub stage: &'static str,
    pub inputs: BTreeSet<u32>,
    pub outputs: BTreeSet<u32>,
}

/// The whole interface: entry points and resource bindings.
#[derive(Debug, PartialEq, Eq)]
pub struct Interface {
    pub entries: BTreeSet<Entry>,
    pub bindings: BTreeSet<(u32, u32)>,
}

fn stage_name(stage: naga::ShaderStage) -> &'static str {
    match stage {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Compute => "compute",
        _ => "other",
    }
}

/// The locations a binding, or the members of a struct without one, carry.
fn locations(module: &naga::Module, ty: naga::Handle<naga::Type>, binding: Option<&naga::Binding>, out: &mut BTreeSet<u32>) {
    match binding {
        Some(naga::Binding::Location { location, .. }) => {
            out.insert(*location);
        }
        Some(naga::Binding::BuiltIn(_)) => {}
        None => {
            if let naga::TypeInner::Struct { members, .. } = &module.types[ty].inner {
                for m in members {
                    locations(module, m.ty, m.binding.as_ref(), out);
                }
            }
        }
    }
}

/// The interface of a naga module.
pub fn of_module(module: &naga::Module) -> Interface {
    let entries = module
        .entry_points
        .iter()
        .map(|ep| {
            let mut inputs = BTreeSet::new();
            for arg in &ep.function.arguments {
                locations(module, arg.ty, arg.binding.as_ref(), &mut inputs);
            }
            let mut outputs = BTreeSet::new();
            if let Some(r) = &ep.function.result {
                locations(module, r.ty, r.binding.as_ref(), &mut outputs);
            }
            Entry { name: ep.name.clone(), stage: stage_name(ep.stage), inputs, outputs }
        })
        .collect();
    let bindings =
        module.global_variables.iter().filter_map(|(_, g)| g.binding.as_ref().map(|b| (b.group, b.binding))).collect();
    Interface { entries, bindings }
}

fn u32_at(v: &serde_json::Value, key: &str) -> Option<u32> {
    v.get(key).and_then(|x| x.as_u64()).map(|x| x as u32)
}

/// The interface the reflection manifest describes.
pub fn of_manifest(json: &[u8]) -> Result<Interface, String> {
    let v: serde_json::Value = serde_json::from_slice(json).map_err(|e| format!("the manifest is not JSON: {e}"))?;
    let list = |v: &serde_json::Value, key: &str| v.get(key).and_then(|x| x.as_array()).cloned().unwrap_or_default();
    let mut entries = BTreeSet::new();
    for ep in list(&v, "entry_points") {
        let locs = |key: &str| list(&ep, key).iter().filter_map(|io| u32_at(io, "location")).collect::<BTreeSet<_>>();
        let stage = match ep.get("stage").and_then(|s| s.as_str()) {
            Some("vertex") => "vertex",
            Some("fragment") => "fragment",
            Some("compute") => "compute",
            other => return Err(format!("an entry point of stage {other:?}")),
        };
        let name = ep.get("name").and_then(|s| s.as_str()).ok_or("an entry point without a name")?.to_string();
        entries.insert(Entry { name, stage, inputs: locs("inputs"), outputs: locs("outputs") });
    }
    let mut bindings = BTreeSet::new();
    for key in ["uniform_buffers", "storage_buffers", "storage_images"] {
        for b in list(&v, key) {
            if let (Some(g), Some(n)) = (u32_at(&b, "group"), u32_at(&b, "binding")) {
                bindings.insert((g, n));
            }
        }
    }
    for s in list(&v, "samplers") {
        if let Some(g) = u32_at(&s, "group") {
            for key in ["texture_binding", "sampler_binding"] {
                if let Some(n) = u32_at(&s, key) {
                    bindings.insert((g, n));
                }
            }
        }
    }
    Ok(Interface { entries, bindings })
}

/// umbrac's WGSL (already parsed and validated) through naga's SPIR-V back
/// end and front end: the interface a SPIR-V consumer of the WGSL sees.
pub fn wgsl_as_spirv(module: &naga::Module, info: &naga::valid::ModuleInfo) -> Result<Interface, String> {
    let opts = naga::back::spv::Options::default();
    let words = naga::back::spv::write_vec(module, info, &opts, None).map_err(|e| format!("naga cannot write the WGSL as SPIR-V: {e}"))?;
    spirv(bytes_of(&words).as_slice()).map_err(|e| format!("naga's SPIR-V of the WGSL does not read back: {e}"))
}

fn bytes_of(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

/// The interface of a SPIR-V binary, as naga's SPIR-V front end reads it.
pub fn spirv(bytes: &[u8]) -> Result<Interface, String> {
    let opts = naga::front::spv::Options::default();
    naga::front::spv::parse_u8_slice(bytes, &opts).map(|m| of_module(&m)).map_err(|e| format!("{e:?}"))
}

/// Every difference between two interfaces, for a finding's message.
pub fn differences(a: &Interface, a_name: &str, b: &Interface, b_name: &str) -> Option<String> {
    if a == b {
        return None;
    }
    let mut out = String::new();
    for e in a.entries.difference(&b.entries) {
        out += &format!("  only in {a_name}: {e:?}\n");
    }
    for e in b.entries.difference(&a.entries) {
        out += &format!("  only in {b_name}: {e:?}\n");
    }
    if a.bindings != b.bindings {
        out += &format!("  bindings: {a_name} {:?}, {b_name} {:?}\n", a.bindings, b.bindings);
    }
    Some(out)
}
