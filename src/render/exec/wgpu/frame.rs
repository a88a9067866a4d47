//! Encoding one frame of a plan on a wgpu device: the targets, every
//! (pass, draw)'s uniform buffers in one buffer, bind groups, the passes,
//! and the copy of the read-back target.

use std::collections::HashMap;
use std::num::NonZeroU64;
use std::sync::Arc;

use image::RgbaImage;
use wgpu::util::DeviceExt;

use crate::render::bind::{self, wgpu::{Resource, ViewDim}, Fit};
use crate::render::plan::{Dim, Format, FramePlan, Geometry, Sampling, Unset};

use super::{texture_format, PipelineKey, WgpuExecutor, WgpuProgram};
use crate::render::exec::{ExecError, Readback};

/// Where each (pass, draw, block)'s bytes sit in the frame's one buffer.
struct Uniforms {
    buffer: wgpu::Buffer,
    offsets: HashMap<(usize, usize, usize), u64>,
}

impl WgpuExecutor {
    pub(super) fn encode(&self, program: &WgpuProgram, plan: &FramePlan, fit: &Fit) -> Result<Readback, ExecError> {
        let read = plan.target(plan.readback).format;
        if read == Format::Depth24Plus {
            return Err(ExecError::Unsupported("a depth24plus target cannot be read back (wgpu cannot copy it)".into()));
        }
        let textures = self.targets(plan);
        let views: Vec<wgpu::TextureView> = textures
            .iter()
            .zip(&plan.targets)
            .map(|(t, p)| t.create_view(&wgpu::TextureViewDescriptor { dimension: Some(view_dimension(ViewDim::of(p.dim.name()))), ..Default::default() }))
            .collect();
        let keys = plan.passes.iter().zip(&fit.passes).map(|(pass, pf)| self.key(program, plan, pass, pf)).collect::<Result<Vec<_>, _>>()?;
        let uniforms = self.uniforms(program, plan, fit, &keys)?;
        let mut encoder = self.device.create_command_encoder(&Default::default());
        for (p, key) in keys.iter().enumerate() {
            self.encode_pass(&mut encoder, program, plan, fit, p, key, &views, &uniforms)?;
        }
        self.read_back(encoder, plan, &textures[plan.readback.0], fit.mirrored_on_webgpu())
    }

    /// Every target of the plan, usable as what the plan does with it.
    fn targets(&self, plan: &FramePlan) -> Vec<wgpu::Texture> {
        use wgpu::TextureUsages as U;
        plan.targets
            .iter()
            .enumerate()
            .map(|(i, t)| {
                // Only 2D targets are drawn into (checked by the plan).
                let mut usage = if t.dim == Dim::D2 { U::RENDER_ATTACHMENT } else { U::empty() };
                if plan.passes.iter().flat_map(|p| &p.textures).any(|x| x.target.0 == i) {
                    usage |= U::TEXTURE_BINDING;
                }
                if plan.readback.0 == i {
                    usage |= U::COPY_SRC;
                }
                if t.contents.is_some() {
                    usage |= U::COPY_DST;
                }
                let size = wgpu::Extent3d { width: t.width, height: t.height, depth_or_array_layers: t.dim.layers() };
                let texture = self.device.create_texture(&wgpu::TextureDescriptor {
                    label: Some(&t.name),
                    size,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: if matches!(t.dim, Dim::D3(_)) { wgpu::TextureDimension::D3 } else { wgpu::TextureDimension::D2 },
                    format: texture_format(t.format),
                    usage,
                    view_formats: &[],
                });
                if let Some(texels) = &t.contents {
                    let layout = wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(t.width * 4), rows_per_image: Some(t.height) };
                    self.queue.write_texture(texture.as_image_copy(), texels, layout, size);
                }
                texture
            })
            .collect()
    }

    /// Every (pass, draw) gets its own copy of each buffer it binds, at
    /// offsets aligned for binding: queue writes between draws of one
    /// submission would all land before the first.
    fn uniforms(&self, program: &WgpuProgram, plan: &FramePlan, fit: &Fit, keys: &[PipelineKey]) -> Result<Uniforms, ExecError> {
        let align = self.device.limits().min_uniform_buffer_offset_alignment as u64;
        let mut data: Vec<u8> = Vec::new();
        let mut offsets = HashMap::new();
        for (p, ((pass, pf), key)) in plan.passes.iter().zip(&fit.passes).zip(keys).enumerate() {
            for (d, draw) in pass.draws.iter().enumerate() {
                for e in key.groups.values().flatten() {
                    let Resource::Buffer { block, .. } = e.resource else { continue };
                    // What the pass does not read (passthrough layouts) may stay unset.
                    let unset = if pf.blocks.iter().any(|&(b, _)| b == block) { plan.unset } else { Unset::Zero };
                    let bytes = bind::wgpu::buffer_bytes(&program.reflection, block, pass, draw, unset).map_err(ExecError::Program)?;
                    let at = (data.len() as u64).next_multiple_of(align);
                    data.resize(at as usize, 0);
                    data.extend_from_slice(&bytes);
                    offsets.insert((p, d, block), at);
                }
            }
        }
        data.resize(data.len().max(16), 0);
        let buffer = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some("uniforms"), contents: &data, usage: wgpu::BufferUsages::UNIFORM });
        Ok(Uniforms { buffer, offsets })
    }

    /// A 1x1 texture (six faces for a cube) standing in for one a pass
    /// binds but does not read.
    fn stand_in(&self, depth: bool, dim: ViewDim) -> wgpu::TextureView {
        let format = if depth { wgpu::TextureFormat::Depth32Float } else { wgpu::TextureFormat::Rgba8Unorm };
        self.device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("stand-in"),
                size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: if dim == ViewDim::Cube { 6 } else { 1 } },
                mip_level_count: 1,
                sample_count: 1,
                dimension: if dim == ViewDim::D3 { wgpu::TextureDimension::D3 } else { wgpu::TextureDimension::D2 },
                format,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
            .create_view(&wgpu::TextureViewDescriptor { dimension: Some(view_dimension(dim)), ..Default::default() })
    }

    #[allow(clippy::too_many_arguments)]
    fn encode_pass(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        program: &WgpuProgram,
        plan: &FramePlan,
        fit: &Fit,
        p: usize,
        key: &PipelineKey,
        views: &[wgpu::TextureView],
        uniforms: &Uniforms,
    ) -> Result<(), ExecError> {
        let pass = &plan.passes[p];
        // A pass that draws nothing only clears: it needs no pipeline.
        let pipeline = if pass.draws.is_empty() { None } else { Some(self.pipeline(program, key, fit.mirrored_on_webgpu(), &pass.name)?) };
        let samplers: Vec<Arc<wgpu::Sampler>> = pass.textures.iter().map(|t| self.sampler(t.sampling)).collect();
        let stand_ins: HashMap<(bool, ViewDim), wgpu::TextureView> = key
            .groups
            .values()
            .flatten()
            .filter_map(|e| match e.resource {
                Resource::Texture { texture: None, depth, dim, .. } => Some((depth, dim)),
                _ => None,
            })
            .map(|k| (k, self.stand_in(k.0, k.1)))
            .collect();
        let stand_in_samplers = [self.sampler(Sampling::NEAREST), self.sampler(Sampling::SHADOW)];
        let groups: Vec<Vec<(u32, wgpu::BindGroup)>> = (0..pass.draws.len())
            .map(|d| {
                pipeline
                    .iter()
                    .flat_map(|p| &p.layouts)
                    .map(|(&group, layout)| {
                        let entries: Vec<wgpu::BindGroupEntry> = key.groups[&group]
                            .iter()
                            .map(|e| wgpu::BindGroupEntry {
                                binding: e.binding,
                                resource: match e.resource {
                                    Resource::Buffer { block, size } => wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                                        buffer: &uniforms.buffer,
                                        offset: uniforms.offsets[&(p, d, block)],
                                        size: NonZeroU64::new(size),
                                    }),
                                    Resource::Texture { texture: Some(t), .. } => wgpu::BindingResource::TextureView(&views[pass.textures[t].target.0]),
                                    Resource::Texture { texture: None, depth, dim, .. } => wgpu::BindingResource::TextureView(&stand_ins[&(depth, dim)]),
                                    Resource::Sampler { texture: Some(t), .. } => wgpu::BindingResource::Sampler(&samplers[t]),
                                    Resource::Sampler { texture: None, comparison, .. } => wgpu::BindingResource::Sampler(&stand_in_samplers[comparison as usize]),
                                },
                            })
                            .collect();
                        (group, self.device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout, entries: &entries }))
                    })
                    .collect()
            })
            .collect();
        let color_attachments: Vec<_> = pass
            .colors()
            .map(|a| {
                let c = a.clear;
                Some(wgpu::RenderPassColorAttachment {
                    view: &views[a.target.0],
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color { r: c[0], g: c[1], b: c[2], a: c[3] }), store: wgpu::StoreOp::Store },
                })
            })
            .collect();
        let mut rp = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(&pass.name),
            color_attachments: &color_attachments,
            depth_stencil_attachment: pass.depth.map(|a| wgpu::RenderPassDepthStencilAttachment {
                view: &views[a.target.0],
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(a.clear), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        let Some(pipeline) = pipeline else { return Ok(()) };
        rp.set_pipeline(&pipeline.pipeline);
        for (d, draw) in pass.draws.iter().enumerate() {
            for (group, bg) in &groups[d] {
                rp.set_bind_group(*group, bg, &[]);
            }
            match draw.geometry {
                Geometry::Mesh(mesh) => {
                    let m = self.mesh(mesh);
                    rp.set_vertex_buffer(0, m.vertices.slice(..));
                    let mut instances = 1;
                    if let Some(i) = mesh.instances {
                        rp.set_vertex_buffer(1, m.vertices.slice(i.base as u64..));
                        instances = i.count;
                    }
                    rp.set_index_buffer(m.indices.slice(..), wgpu::IndexFormat::Uint32);
                    rp.draw_indexed(0..m.index_count, 0, 0..instances);
                }
                Geometry::Vertices(n) => rp.draw(0..n, 0..1),
            }
        }
        Ok(())
    }

    /// Copies `texture` out, submits, waits, and returns its texels top row
    /// first (mirrored: portable GL-dialect code renders GL's bottom row into row 0).
    fn read_back(&self, mut encoder: wgpu::CommandEncoder, plan: &FramePlan, texture: &wgpu::Texture, mirrored: bool) -> Result<Readback, ExecError> {
        let target = plan.target(plan.readback);
        let (w, h, read) = (target.width, target.height, target.format);
        let texel = match read {
            Format::Rgba8 | Format::Depth32Float | Format::Depth24Plus => 4,
            Format::Depth16 => 2,
            Format::Rgba32Uint => 16,
        };
        let row = texel * w;
        let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: padded as u64 * h as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let aspect = if read.is_depth() { wgpu::TextureAspect::DepthOnly } else { wgpu::TextureAspect::All };
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo { texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
            wgpu::TexelCopyBufferInfo { buffer: &readback, layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: Some(h) } },
            wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        );
        self.queue.submit([encoder.finish()]);
        let slice = readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| ExecError::Api(format!("waiting for the frame: {e}")))?;
        rx.recv()
            .map_err(|_| ExecError::Api("the readback was never mapped".into()))?
            .map_err(|e| ExecError::Api(format!("mapping the readback: {e}")))?;
        let mapped = slice.get_mapped_range().map_err(|e| ExecError::Api(format!("reading the readback: {e}")))?;
        let mut bytes = Vec::with_capacity((row * h) as usize);
        for y in 0..h {
            let src = if mirrored { h - 1 - y } else { y };
            let start = (src * padded) as usize;
            bytes.extend_from_slice(&mapped[start..start + row as usize]);
        }
        drop(mapped);
        readback.unmap();
        Ok(match read {
            Format::Rgba8 => Readback::Rgba8(RgbaImage::from_raw(w, h, bytes).expect("w * h * 4 bytes")),
            Format::Rgba32Uint => Readback::Words { width: w, height: h, words: bytemuck::cast_slice(&bytes).to_vec() },
            Format::Depth16 => Readback::Depth {
                width: w,
                height: h,
                depths: bytes.chunks_exact(2).map(|c| u16::from_le_bytes([c[0], c[1]]) as f32 / 65535.0).collect(),
            },
            _ => Readback::Depth { width: w, height: h, depths: bytemuck::cast_slice(&bytes).to_vec() },
        })
    }
}

/// wgpu's view dimension of a texture binding.
pub(super) fn view_dimension(dim: ViewDim) -> wgpu::TextureViewDimension {
    match dim {
        ViewDim::D2 => wgpu::TextureViewDimension::D2,
        ViewDim::Cube => wgpu::TextureViewDimension::Cube,
        ViewDim::D3 => wgpu::TextureViewDimension::D3,
        ViewDim::D2Array => wgpu::TextureViewDimension::D2Array,
    }
}
