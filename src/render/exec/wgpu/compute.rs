//! Compute plans on wgpu: the program's module (WGSL, or SPIR-V handed to
//! Vulkan unchanged), a pipeline with the layout the manifest gives,
//! storage buffers and textures filled from the plan, one dispatch, and
//! the plan's read-backs copied out.

use std::collections::BTreeMap;
use std::sync::Arc;

use wgpu::util::DeviceExt;

use super::WgpuExecutor;
use crate::render::bind::compute::{self, texel_bytes, ComputeFit};
use crate::render::consumers::Consumer;
use crate::render::exec::{ComputeReadback, ExecError};
use crate::render::plan::compute::ComputePlan;
use crate::render::program::{ShaderCode, ShaderSet};
use crate::sema::types::{Access, ImageDim, ImageFormat};
use crate::Target;

fn texture_format(f: ImageFormat) -> wgpu::TextureFormat {
    use wgpu::TextureFormat as T;
    match f {
        ImageFormat::Rgba8 => T::Rgba8Unorm,
        ImageFormat::Rgba8Snorm => T::Rgba8Snorm,
        ImageFormat::Rgba8ui => T::Rgba8Uint,
        ImageFormat::Rgba8i => T::Rgba8Sint,
        ImageFormat::Rgba16f => T::Rgba16Float,
        ImageFormat::Rgba16ui => T::Rgba16Uint,
        ImageFormat::Rgba16i => T::Rgba16Sint,
        ImageFormat::Rgba32f => T::Rgba32Float,
        ImageFormat::Rgba32ui => T::Rgba32Uint,
        ImageFormat::Rgba32i => T::Rgba32Sint,
        ImageFormat::R32f => T::R32Float,
        ImageFormat::R32ui => T::R32Uint,
        ImageFormat::R32i => T::R32Sint,
    }
}

/// What a texture holds: the resource and where its bytes come back.
enum Held {
    Buffer(wgpu::Buffer, u64),
    Texture(wgpu::Texture, [u32; 3], u32),
}

impl WgpuExecutor {
    /// Runs `plan` with `set` (WGSL, or SPIR-V on Vulkan) and reads back
    /// what it asks for.
    pub fn run_compute(&self, set: &ShaderSet, plan: &ComputePlan) -> Result<ComputeReadback, ExecError> {
        let r = set.manifest().map_err(ExecError::Program)?;
        let fit = compute::fit(&set.label, r, plan)?;
        if set.target == Target::Spirv && (self.consumer != Consumer::VulkanWgsl || !self.supports_passthrough()) {
            return Err(ExecError::Unsupported(format!("{}: SPIR-V runs unchanged only on a Vulkan device with PASSTHROUGH_SHADERS ({})", set.label, self.adapter_name())));
        }
        // lavapipe lost a SPIR-V compute program's storage image writes, or
        // crashed in its worker thread, when the module was handed to it
        // unchanged and other pipelines had run on the device (about half
        // the runs of tests/gpu/compute.rs; the same SPIR-V through wgpu's
        // own naga path, and storage buffers and read-only images through
        // passthrough, never).
        if set.target == Target::Spirv && fit.images.iter().any(|i| i.access != Access::Read) && (self.info.name.contains("llvmpipe") || self.info.driver.contains("llvmpipe")) {
            return Err(ExecError::Unsupported(format!(
                "{}: storage images written by SPIR-V passed through unchanged are not run on lavapipe ({}), which loses their writes or crashes; run the WGSL (`--via wgsl`)",
                set.label,
                self.adapter_name()
            )));
        }
        let module_index = set.module_of(&fit.entry);
        let code = set.modules.get(module_index).ok_or_else(|| ExecError::Program(format!("{}: no module for `{}`", set.label, fit.entry)))?;
        let out = self
            .scoped(|| self.dispatch(set, code, plan, &fit))
            .map_err(|e| ExecError::Api(format!("wgpu error: {e}")))??;
        Ok(out)
    }

    fn dispatch(&self, set: &ShaderSet, code: &ShaderCode, plan: &ComputePlan, fit: &ComputeFit) -> Result<ComputeReadback, ExecError> {
        let device = &self.device;
        let [x, y, z] = fit.workgroup_size;
        // Modules and pipelines are kept for the device's life: lavapipe lost
        // a second dispatch's image writes (or crashed) when the compute
        // pipeline of a SPIR-V module handed to it unchanged was made afresh
        // (`image_writes_survive_alternating_programs`).
        // wgpu 30 hands a passthrough module to Vulkan without its
        // pipeline constants (wgpu-hal makes no `VkSpecializationInfo`):
        // SPIR-V whose specialization constants the plan sets goes through
        // wgpu's naga front end instead, which reads each `OpSpecConstant`
        // with `SpecId N` as the override `@id(N)` that takes them.
        let specialized = !plan.constants.is_empty();
        let key = {
            use std::hash::{Hash, Hasher};
            let mut h = std::collections::hash_map::DefaultHasher::new();
            match code {
                ShaderCode::Wgsl(text) => text.hash(&mut h),
                ShaderCode::Spirv(words) => (words, specialized).hash(&mut h),
                ShaderCode::Glsl { text, .. } => text.hash(&mut h),
            }
            (h.finish(), fit.entry.clone())
        };
        if let Some(m) = self.compute_modules.lock().unwrap_or_else(|p| p.into_inner()).get(&key) {
            return self.dispatch_with(&m.clone(), plan, fit);
        }
        let module = match code {
            ShaderCode::Wgsl(text) => device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(&set.label), source: wgpu::ShaderSource::Wgsl(crate::emit::wgsl::for_naga(text)) }),
            ShaderCode::Spirv(words) if specialized => device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(&set.label), source: wgpu::ShaderSource::SpirV(words.as_slice().into()) }),
            // SAFETY: a SPIR-V module umbrac emitted and naga validated
            // (the contract of `--via spirv`).
            ShaderCode::Spirv(words) => unsafe {
                device.create_shader_module_passthrough(wgpu::ShaderModuleDescriptorPassthrough {
                    label: Some(&set.label),
                    entry_points: vec![wgpu::PassthroughShaderEntryPoint { name: fit.entry.clone().into(), workgroup_size: (x, y, z) }].into(),
                    spirv: Some(words.as_slice().into()),
                    ..Default::default()
                })
            },
            ShaderCode::Glsl { file, .. } => return Err(ExecError::Unsupported(format!("{file}: wgpu does not take GLSL files"))),
        };
        let module = Arc::new(module);
        self.compute_modules.lock().unwrap_or_else(|p| p.into_inner()).insert(key, module.clone());
        self.dispatch_with(&module, plan, fit)
    }

    fn dispatch_with(&self, module: &wgpu::ShaderModule, plan: &ComputePlan, fit: &ComputeFit) -> Result<ComputeReadback, ExecError> {
        let device = &self.device;
        // Layout entries and resources per group.
        let mut layouts: BTreeMap<u32, Vec<wgpu::BindGroupLayoutEntry>> = BTreeMap::new();
        let mut held: BTreeMap<String, (u32, u32, Held, Option<wgpu::TextureView>)> = BTreeMap::new();
        for b in &fit.buffers {
            let bytes = &plan.buffers[b.input].bytes;
            let size = bytes.len() as u64;
            let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(&b.name),
                contents: bytes,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            });
            layouts.entry(b.group).or_default().push(wgpu::BindGroupLayoutEntry {
                binding: b.binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer { ty: wgpu::BufferBindingType::Storage { read_only: b.read_only }, has_dynamic_offset: false, min_binding_size: None },
                count: None,
            });
            held.insert(b.name.clone(), (b.group, b.binding, Held::Buffer(buffer, size), None));
        }
        for i in &fit.images {
            let input = &plan.images[i.input];
            let format = texture_format(i.format);
            let (dimension, view_dimension) = match i.dim {
                ImageDim::D2 => (wgpu::TextureDimension::D2, wgpu::TextureViewDimension::D2),
                ImageDim::D3 => (wgpu::TextureDimension::D3, wgpu::TextureViewDimension::D3),
                ImageDim::D2Array => (wgpu::TextureDimension::D2, wgpu::TextureViewDimension::D2Array),
            };
            let extent = wgpu::Extent3d { width: input.width, height: input.height, depth_or_array_layers: input.layers };
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some(&i.name),
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension,
                format,
                usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let texel = texel_bytes(i.format);
            // Zeros where the plan gives none, written like given texels.
            let zeros;
            let texels = match &input.texels {
                Some(t) => Some(t),
                None => {
                    zeros = vec![0u8; (input.width * texel) as usize * input.height as usize * input.layers as usize];
                    Some(&zeros)
                }
            };
            if let Some(t) = texels {
                self.queue.write_texture(
                    wgpu::TexelCopyTextureInfo { texture: &texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect: wgpu::TextureAspect::All },
                    t,
                    wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(input.width * texel), rows_per_image: Some(input.height) },
                    extent,
                );
            }
            let access = match i.access {
                Access::Read => wgpu::StorageTextureAccess::ReadOnly,
                Access::Write => wgpu::StorageTextureAccess::WriteOnly,
                Access::ReadWrite => wgpu::StorageTextureAccess::ReadWrite,
            };
            layouts.entry(i.group).or_default().push(wgpu::BindGroupLayoutEntry {
                binding: i.binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::StorageTexture { access, format, view_dimension },
                count: None,
            });
            let view = texture.create_view(&wgpu::TextureViewDescriptor { dimension: Some(view_dimension), ..Default::default() });
            held.insert(i.name.clone(), (i.group, i.binding, Held::Texture(texture, [input.width, input.height, input.layers], texel), Some(view)));
        }
        // The pipeline, made once per module and layout and kept with the
        // module (see `dispatch`).
        let pipeline_key = format!("{:p} {} {layouts:?} {:?}", module as *const wgpu::ShaderModule, fit.entry, plan.constants);
        // Overrides by id (WGSL's `@id(N)`, SPIR-V's `SpecId N`), as wgpu
        // keys them.
        let constant_ids: Vec<String> = plan.constants.iter().map(|(id, _)| id.to_string()).collect();
        let constants: Vec<(&str, f64)> = constant_ids.iter().zip(&plan.constants).map(|(k, (_, v))| (k.as_str(), *v)).collect();
        let cached = self.compute_pipelines.lock().unwrap_or_else(|p| p.into_inner()).get(&pipeline_key).cloned();
        let made = match cached {
            Some(m) => m,
            None => {
                // Groups 0..=max, the unused ones empty.
                let max_group = layouts.keys().last().copied();
                let group_layouts: Vec<wgpu::BindGroupLayout> = (0..max_group.map_or(0, |g| g + 1))
                    .map(|g| device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(&plan.name), entries: layouts.get(&g).map_or(&[][..], |v| v.as_slice()) }))
                    .collect();
                let layout_refs: Vec<Option<&wgpu::BindGroupLayout>> = group_layouts.iter().map(Some).collect();
                let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor { label: Some(&plan.name), bind_group_layouts: &layout_refs, immediate_size: 0 });
                let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some(&plan.name),
                    layout: Some(&pipeline_layout),
                    module,
                    entry_point: Some(&fit.entry),
                    compilation_options: wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() },
                    cache: None,
                });
                let m = Arc::new((pipeline, group_layouts));
                self.compute_pipelines.lock().unwrap_or_else(|p| p.into_inner()).insert(pipeline_key, m.clone());
                m
            }
        };
        let (pipeline, group_layouts) = (&made.0, &made.1);
        let groups: Vec<wgpu::BindGroup> = group_layouts
            .iter()
            .enumerate()
            .map(|(g, layout)| {
                let entries: Vec<wgpu::BindGroupEntry> = held
                    .values()
                    .filter(|(group, ..)| *group == g as u32)
                    .map(|(_, binding, h, view)| wgpu::BindGroupEntry {
                        binding: *binding,
                        resource: match (h, view) {
                            (_, Some(v)) => wgpu::BindingResource::TextureView(v),
                            (Held::Buffer(b, _), None) => b.as_entire_binding(),
                            (Held::Texture(..), None) => unreachable!("every texture has its view"),
                        },
                    })
                    .collect();
                device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(&plan.name), layout, entries: &entries })
            })
            .collect();
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(&plan.name) });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some(&plan.name), timestamp_writes: None });
            pass.set_pipeline(pipeline);
            for (g, group) in groups.iter().enumerate() {
                pass.set_bind_group(g as u32, group, &[]);
            }
            let [gx, gy, gz] = plan.workgroups;
            pass.dispatch_workgroups(gx, gy, gz);
        }
        // Read-backs: buffers copied whole; textures with rows padded to 256.
        let mut staged = Vec::new();
        for name in &plan.readback {
            let Some((_, _, h, _)) = held.get(name) else {
                return Err(ExecError::Program(format!("{}: `{name}` is read back but the program does not use it", plan.name)));
            };
            match h {
                Held::Buffer(b, size) => {
                    let s = device.create_buffer(&wgpu::BufferDescriptor { label: Some(name), size: *size, usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ, mapped_at_creation: false });
                    encoder.copy_buffer_to_buffer(b, 0, &s, 0, *size);
                    staged.push((name.clone(), s, None));
                }
                Held::Texture(t, [w, hgt, layers], texel) => {
                    let row = (w * texel).div_ceil(256) * 256;
                    let s = device.create_buffer(&wgpu::BufferDescriptor {
                        label: Some(name),
                        size: row as u64 * *hgt as u64 * *layers as u64,
                        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                        mapped_at_creation: false,
                    });
                    encoder.copy_texture_to_buffer(
                        wgpu::TexelCopyTextureInfo { texture: t, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect: wgpu::TextureAspect::All },
                        wgpu::TexelCopyBufferInfo { buffer: &s, layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: Some(*hgt) } },
                        wgpu::Extent3d { width: *w, height: *hgt, depth_or_array_layers: *layers },
                    );
                    staged.push((name.clone(), s, Some((row as usize, (*w * *texel) as usize))));
                }
            }
        }
        self.queue.submit([encoder.finish()]);
        let mut out = ComputeReadback::default();
        for (name, s, rows) in staged {
            let slice = s.slice(..);
            slice.map_async(wgpu::MapMode::Read, |_| {});
            device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| ExecError::Api(format!("waiting for the dispatch: {e}")))?;
            let data = slice.get_mapped_range().map_err(|e| ExecError::Api(format!("mapping `{name}`: {e}")))?;
            let bytes = match rows {
                None => data.to_vec(),
                Some((padded, tight)) => data.chunks(padded).flat_map(|r| r[..tight].iter().copied()).collect(),
            };
            drop(data);
            s.unmap();
            out.resources.insert(name, bytes);
        }
        Ok(out)
    }
}
