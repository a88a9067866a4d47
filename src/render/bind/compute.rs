//! Binding a compute plan to a program: the entry point and its workgroup
//! size, and for each storage buffer and image it uses, where it is bound
//! (WGSL/SPIR-V group and binding, GL binding point or image unit) and
//! the plan's contents for it, checked against the manifest's layout.
//! Pure data, no GPU.

use crate::emit::reflect_types::Reflection;
use crate::render::plan::compute::ComputePlan;
use crate::sema::types::{Access, ImageDim, ImageFormat};

use super::InterfaceError;

/// A storage buffer of the dispatch.
#[derive(Clone, Debug, PartialEq)]
pub struct FitBuffer {
    pub name: String,
    pub group: u32,
    pub binding: u32,
    pub gl_binding: u32,
    pub read_only: bool,
    /// Index into `ComputePlan::buffers`.
    pub input: usize,
}

/// A storage image of the dispatch.
#[derive(Clone, Debug, PartialEq)]
pub struct FitImage {
    pub name: String,
    pub group: u32,
    pub binding: u32,
    pub unit: u32,
    pub format: ImageFormat,
    pub access: Access,
    pub dim: ImageDim,
    /// Index into `ComputePlan::images`.
    pub input: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ComputeFit {
    pub entry: String,
    pub workgroup_size: [u32; 3],
    pub buffers: Vec<FitBuffer>,
    pub images: Vec<FitImage>,
}

/// Bytes of one texel of a storage image format.
pub fn texel_bytes(f: ImageFormat) -> u32 {
    match f {
        ImageFormat::Rgba8 | ImageFormat::Rgba8Snorm | ImageFormat::Rgba8ui | ImageFormat::Rgba8i | ImageFormat::R32f | ImageFormat::R32ui | ImageFormat::R32i => 4,
        ImageFormat::Rgba16f | ImageFormat::Rgba16ui | ImageFormat::Rgba16i => 8,
        ImageFormat::Rgba32f | ImageFormat::Rgba32ui | ImageFormat::Rgba32i => 16,
    }
}

/// Checks `r` against `plan` (every problem listed) and says what the
/// dispatch binds.
pub fn fit(program: &str, r: &Reflection, plan: &ComputePlan) -> Result<ComputeFit, InterfaceError> {
    let mut problems = Vec::new();
    if let Err(e) = plan.check() {
        problems.push(e);
    }
    let err = |problems: Vec<String>| InterfaceError { program: program.to_string(), scene: plan.name.clone(), problems };
    for (id, _) in &plan.constants {
        if !r.specialization_constants.iter().flatten().any(|c| c.id == *id) {
            problems.push(format!("it has no specialization constant with `@constant_id = {id}`"));
        }
    }
    let Some(ep) = r.entry_points.iter().find(|e| e.name == plan.entry) else {
        problems.push(format!("it has no entry point `{}`", plan.entry));
        return Err(err(problems));
    };
    let Some(workgroup_size) = ep.workgroup_size else {
        problems.push(format!("`{}` is a {} entry point, not a compute one", ep.name, ep.stage));
        return Err(err(problems));
    };
    if !ep.uniform_buffers.is_empty() || !ep.samplers.is_empty() {
        problems.push(format!("`{}` uses uniforms or samplers, which compute plans do not bind (only storage buffers and images)", ep.name));
    }
    let mut buffers = Vec::new();
    for name in ep.storage_buffers.iter().flatten() {
        let Some(b) = r.storage_buffers.iter().flatten().find(|b| &b.name == name) else {
            problems.push(format!("the manifest lists `{name}` for `{}` but describes no such storage buffer", ep.name));
            continue;
        };
        let Some(input) = plan.buffers.iter().position(|i| &i.name == name) else {
            problems.push(format!("storage buffer `{name}` is given no contents by the plan"));
            continue;
        };
        let len = plan.buffers[input].bytes.len() as u32;
        let fits = match b.runtime_stride {
            Some(stride) => len >= b.size + stride && (len - b.size).is_multiple_of(stride),
            None => len == b.size,
        };
        if !fits {
            let want = match b.runtime_stride {
                Some(s) => format!("{} bytes and a whole number (at least one) of {s}-byte elements", b.size),
                None => format!("{} bytes", b.size),
            };
            problems.push(format!("storage buffer `{name}` is given {len} bytes; its layout takes {want}"));
            continue;
        }
        buffers.push(FitBuffer { name: name.clone(), group: b.group, binding: b.binding, gl_binding: b.glsl_binding, read_only: b.access == "read", input });
    }
    let mut images = Vec::new();
    for name in ep.storage_images.iter().flatten() {
        let Some(m) = r.storage_images.iter().flatten().find(|i| &i.name == name) else {
            problems.push(format!("the manifest lists `{name}` for `{}` but describes no such storage image", ep.name));
            continue;
        };
        let Some(input) = plan.images.iter().position(|i| &i.name == name) else {
            problems.push(format!("storage image `{name}` is given no image by the plan"));
            continue;
        };
        let (Some(format), Some(dim)) = (ImageFormat::from_name(&m.format), image_dim(&m.dimension)) else {
            problems.push(format!("storage image `{name}` has format `{}` and dimension `{}`, which this runner does not know", m.format, m.dimension));
            continue;
        };
        let access = match m.access.as_str() {
            "read" => Access::Read,
            "write" => Access::Write,
            _ => Access::ReadWrite,
        };
        let i = &plan.images[input];
        if dim == ImageDim::D2 && i.layers != 1 {
            problems.push(format!("storage image `{name}` is 2D; the plan gives it {} layers", i.layers));
        }
        if let Some(t) = &i.texels {
            let want = i.width as usize * i.height as usize * i.layers as usize * texel_bytes(format) as usize;
            if t.len() != want {
                problems.push(format!("storage image `{name}` is given {} bytes of texels; {}x{}x{} of `{}` take {want}", t.len(), i.width, i.height, i.layers, m.format));
            }
        }
        images.push(FitImage { name: name.clone(), group: m.group, binding: m.binding, unit: m.image_unit, format, access, dim, input });
    }
    for b in &plan.buffers {
        if !buffers.iter().any(|f| f.name == b.name) && !problems.iter().any(|p| p.contains(&format!("`{}`", b.name))) {
            problems.push(format!("the plan fills storage buffer `{}`, which `{}` does not use", b.name, ep.name));
        }
    }
    if problems.is_empty() {
        Ok(ComputeFit { entry: ep.name.clone(), workgroup_size, buffers, images })
    } else {
        Err(err(problems))
    }
}

fn image_dim(d: &str) -> Option<ImageDim> {
    Some(match d {
        "2d" => ImageDim::D2,
        "3d" => ImageDim::D3,
        "2d-array" => ImageDim::D2Array,
        _ => return None,
    })
}
