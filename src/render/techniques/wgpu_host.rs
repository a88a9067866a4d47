//! The technique scenes on wgpu: pipelines, bind groups and targets from the
//! program's reflection, on the device of a [`Renderer`].

use std::collections::BTreeMap;
use std::num::NonZeroU64;

use image::RgbaImage;
use wgpu::util::DeviceExt;

use crate::emit::reflect_types::Reflection;
use crate::render::gpu::{begin_main_pass, Renderer, ShaderCode, ShaderSet, Via};
use crate::render::scene::{self, FrameParams};

use super::{block_bytes, entry, sampler_layer, ShadowTarget, TechFrame, Technique, DRAWS};

const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const COLOR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// What one binding of a pass holds.
#[derive(Clone, Copy, Debug)]
enum Res {
    /// Uniform block index in the reflection.
    Block(usize),
    /// Texture of the reflection's sampler at this index.
    Texture(usize),
    /// Sampler of the reflection's sampler at this index.
    Sampler(usize),
}

struct Pass {
    pipeline: wgpu::RenderPipeline,
    groups: BTreeMap<u32, (wgpu::BindGroupLayout, Vec<(u32, Res)>)>,
}

/// A technique's program with its pipelines.
pub struct TechProgram {
    pub technique: Technique,
    reflection: Reflection,
    portable: bool,
    shadow: Pass,
    main: Pass,
}

/// Draws technique scenes on a [`Renderer`]'s device.
pub struct TechRenderer<'r> {
    renderer: &'r Renderer,
    compare: wgpu::Sampler,
    nearest: wgpu::Sampler,
}

fn gpu_err(e: impl std::fmt::Display) -> String {
    format!("wgpu error: {e}")
}

impl<'r> TechRenderer<'r> {
    pub fn new(renderer: &'r Renderer) -> TechRenderer<'r> {
        let (device, _) = renderer.device();
        let clamp = wgpu::AddressMode::ClampToEdge;
        let compare = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow compare"),
            address_mode_u: clamp,
            address_mode_v: clamp,
            address_mode_w: clamp,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        let nearest = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow nearest"),
            address_mode_u: clamp,
            address_mode_v: clamp,
            address_mode_w: clamp,
            ..Default::default()
        });
        TechRenderer { renderer, compare, nearest }
    }

    fn device(&self) -> &wgpu::Device {
        self.renderer.device().0
    }

    /// Compiles nothing: takes the technique's compiled program and builds
    /// its two pipelines.
    pub fn prepare(&self, technique: Technique, compiled: &crate::Compiled) -> Result<TechProgram, String> {
        let set = ShaderSet::from_compiled(technique.name(), compiled, Via::Wgsl).map_err(|e| e.to_string())?;
        let r = &set.reflection;
        let portable = r.conventions == "portable";
        let device = self.device();
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let modules: Vec<wgpu::ShaderModule> = set
            .modules
            .iter()
            .map(|c| match c {
                ShaderCode::Wgsl(text) => device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(technique.name()),
                    source: wgpu::ShaderSource::Wgsl(text.as_str().into()),
                }),
                ShaderCode::Spirv(_) => unreachable!("asked for WGSL"),
            })
            .collect();
        let module = |name: &str| &modules[set.entry_module.get(name).copied().unwrap_or(0)];
        let mut passes = Vec::new();
        for (i, (vs, fs)) in technique.passes().iter().enumerate() {
            let (vs, fs) = (vs.as_str(), fs.as_str());
            let shadow = i == 0;
            let (v, f) = (entry(r, vs)?, entry(r, fs)?);
            // Bindings this pass uses, by group.
            let mut used: BTreeMap<u32, BTreeMap<u32, (Res, wgpu::ShaderStages)>> = BTreeMap::new();
            for (e, stage) in [(v, wgpu::ShaderStages::VERTEX), (f, wgpu::ShaderStages::FRAGMENT)] {
                let mut add = |group: u32, binding: u32, res: Res| {
                    let slot = used.entry(group).or_default().entry(binding).or_insert((res, wgpu::ShaderStages::NONE));
                    slot.1 |= stage;
                };
                for name in &e.uniform_blocks {
                    let i = r.uniform_blocks.iter().position(|b| &b.name == name).ok_or_else(|| format!("undeclared block `{name}`"))?;
                    add(r.uniform_blocks[i].group, r.uniform_blocks[i].binding, Res::Block(i));
                }
                for name in &e.samplers {
                    let i = r.samplers.iter().position(|s| &s.name == name).ok_or_else(|| format!("undeclared sampler `{name}`"))?;
                    if shadow {
                        return Err(format!("`{}` samples `{name}` in the shadow pass, which renders it", e.name));
                    }
                    let s = &r.samplers[i];
                    add(s.group, s.texture_binding, Res::Texture(i));
                    add(s.group, s.sampler_binding, Res::Sampler(i));
                }
            }
            let mut groups = BTreeMap::new();
            for (group, bindings) in used {
                let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
                    .iter()
                    .map(|(&binding, &(res, visibility))| {
                        let ty = match res {
                            Res::Block(b) => wgpu::BindingType::Buffer {
                                ty: wgpu::BufferBindingType::Uniform,
                                has_dynamic_offset: false,
                                min_binding_size: NonZeroU64::new(r.uniform_blocks[b].size as u64),
                            },
                            Res::Texture(s) => wgpu::BindingType::Texture {
                                sample_type: if r.samplers[s].comparison {
                                    wgpu::TextureSampleType::Depth
                                } else {
                                    wgpu::TextureSampleType::Float { filterable: false }
                                },
                                view_dimension: wgpu::TextureViewDimension::D2,
                                multisampled: false,
                            },
                            Res::Sampler(s) => wgpu::BindingType::Sampler(if r.samplers[s].comparison {
                                wgpu::SamplerBindingType::Comparison
                            } else {
                                wgpu::SamplerBindingType::NonFiltering
                            }),
                        };
                        wgpu::BindGroupLayoutEntry { binding, visibility, ty, count: None }
                    })
                    .collect();
                let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &entries });
                groups.insert(group, (layout, bindings.iter().map(|(&b, &(res, _))| (b, res)).collect()));
            }
            let max_group = groups.keys().max().map_or(0, |g| g + 1);
            let list: Vec<Option<&wgpu::BindGroupLayout>> = (0..max_group).map(|g| groups.get(&g).map(|(l, _)| l)).collect();
            let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: &list,
                immediate_size: 0,
            });
            let mut attributes = Vec::new();
            for input in &v.inputs {
                let offset = scene::attribute_offset(&input.name)
                    .ok_or_else(|| format!("vertex input `{}` is not in the meshes (a_pos, a_normal)", input.name))?;
                attributes.push(wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset, shader_location: input.location });
            }
            let buffers = [Some(wgpu::VertexBufferLayout {
                array_stride: scene::VERTEX_STRIDE,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })];
            let color_target = [Some(wgpu::ColorTargetState { format: COLOR, blend: None, write_mask: wgpu::ColorWrites::ALL })];
            let targets: &[Option<wgpu::ColorTargetState>] =
                if shadow && technique.target() == ShadowTarget::Depth { &[] } else { &color_target };
            let bias = if shadow && technique.depth_bias() {
                wgpu::DepthBiasState { constant: 4, slope_scale: 2.0, clamp: 0.0 }
            } else {
                wgpu::DepthBiasState::default()
            };
            let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(if shadow { "technique shadow pass" } else { "technique main pass" }),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: module(vs),
                    entry_point: Some(vs),
                    compilation_options: Default::default(),
                    buffers: &buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    // Portable conventions mirror y: GL's CCW fronts arrive CW.
                    front_face: if portable { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
                    cull_mode: (shadow && technique.cull_front()).then_some(wgpu::Face::Front),
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias,
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: module(fs),
                    entry_point: Some(fs),
                    compilation_options: Default::default(),
                    targets,
                }),
                multiview_mask: None,
                cache: None,
            });
            passes.push(Pass { pipeline, groups });
        }
        if let Some(e) = pollster::block_on(validation.pop()) {
            return Err(format!("{}: {}", technique.name(), gpu_err(e)));
        }
        let main = passes.pop().expect("two passes");
        let shadow = passes.pop().expect("two passes");
        Ok(TechProgram { technique, reflection: set.reflection.clone(), portable, shadow, main })
    }

    /// Draws one frame and reads it back, top row first.
    pub fn draw(&self, p: &TechProgram, params: &FrameParams) -> Result<RgbaImage, String> {
        let device = self.device();
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let image = self.encode(p, params);
        if let Some(e) = pollster::block_on(validation.pop()) {
            return Err(gpu_err(e));
        }
        image
    }

    fn encode(&self, p: &TechProgram, params: &FrameParams) -> Result<RgbaImage, String> {
        let (device, queue) = self.renderer.device();
        let t = p.technique;
        let frame = TechFrame::new(t, params);
        let r = &p.reflection;
        // One copy of every block per (pass layer, draw), each aligned for binding.
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        let mut data = Vec::new();
        let mut offsets: BTreeMap<(Option<usize>, usize, usize), u64> = BTreeMap::new();
        let layers: Vec<Option<usize>> = (0..t.layers()).map(Some).chain([None]).collect();
        for &layer in &layers {
            for (d, &object) in DRAWS.iter().enumerate() {
                for b in 0..r.uniform_blocks.len() {
                    let at = (data.len() as u64).next_multiple_of(align);
                    data.resize(at as usize, 0);
                    data.extend(block_bytes(&frame, r, b, object, layer, 0)?);
                    offsets.insert((layer, d, b), at);
                }
            }
        }
        data.resize(data.len().max(16), 0);
        let uniforms = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("technique uniforms"),
            contents: &data,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        use wgpu::TextureUsages as U;
        let texture = |w: u32, h: u32, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let n = params.shadow_size;
        let map_format = if t.target() == ShadowTarget::Rgba8 { COLOR } else { DEPTH };
        let maps: Vec<wgpu::TextureView> = (0..t.layers())
            .map(|_| texture(n, n, map_format, U::RENDER_ATTACHMENT | U::TEXTURE_BINDING).create_view(&Default::default()))
            .collect();
        let map_depth = texture(n, n, DEPTH, U::RENDER_ATTACHMENT).create_view(&Default::default());
        let color = texture(params.width, params.height, COLOR, U::RENDER_ATTACHMENT | U::COPY_SRC);
        let color_view = color.create_view(&Default::default());
        let depth = texture(params.width, params.height, DEPTH, U::RENDER_ATTACHMENT).create_view(&Default::default());

        let bind = |pass: &Pass, layer: Option<usize>, d: usize| -> Vec<(u32, wgpu::BindGroup)> {
            pass.groups
                .iter()
                .map(|(&group, (layout, bindings))| {
                    let entries: Vec<wgpu::BindGroupEntry> = bindings
                        .iter()
                        .map(|&(binding, res)| wgpu::BindGroupEntry {
                            binding,
                            resource: match res {
                                Res::Block(b) => wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                                    buffer: &uniforms,
                                    offset: offsets[&(layer, d, b)],
                                    size: NonZeroU64::new(r.uniform_blocks[b].size as u64),
                                }),
                                Res::Texture(s) => wgpu::BindingResource::TextureView(&maps[sampler_layer(&r.samplers[s]).min(maps.len() - 1)]),
                                Res::Sampler(s) => {
                                    wgpu::BindingResource::Sampler(if r.samplers[s].comparison { &self.compare } else { &self.nearest })
                                }
                            },
                        })
                        .collect();
                    (group, device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout, entries: &entries }))
                })
                .collect()
        };
        let mut encoder = device.create_command_encoder(&Default::default());
        for (i, map) in maps.iter().enumerate() {
            let groups: Vec<_> = (0..DRAWS.len()).map(|d| bind(&p.shadow, Some(i), d)).collect();
            let rgba = t.target() == ShadowTarget::Rgba8;
            let color_attachment = [Some(wgpu::RenderPassColorAttachment {
                view: map,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::WHITE), store: wgpu::StoreOp::Store },
            })];
            let color_attachments: &[Option<wgpu::RenderPassColorAttachment>] = if rgba { &color_attachment } else { &[] };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("technique shadow pass"),
                color_attachments,
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: if rgba { &map_depth } else { map },
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                ..Default::default()
            });
            pass.set_pipeline(&p.shadow.pipeline);
            for (d, &object) in DRAWS.iter().enumerate() {
                self.renderer.draw_mesh(&mut pass, object, &groups[d]);
            }
        }
        {
            let groups: Vec<_> = (0..DRAWS.len()).map(|d| bind(&p.main, None, d)).collect();
            let mut pass = begin_main_pass(&mut encoder, "technique main pass", &color_view, &depth);
            pass.set_pipeline(&p.main.pipeline);
            for (d, &object) in DRAWS.iter().enumerate() {
                self.renderer.draw_mesh(&mut pass, object, &groups[d]);
            }
        }
        let (w, h) = (params.width, params.height);
        let row = 4 * w;
        let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: padded as u64 * h as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo { texture: &color, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect: wgpu::TextureAspect::All },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: Some(h) },
            },
            wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        );
        queue.submit([encoder.finish()]);
        let slice = readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        device.poll(wgpu::PollType::wait_indefinitely()).map_err(gpu_err)?;
        rx.recv().map_err(gpu_err)?.map_err(gpu_err)?;
        let mapped = slice.get_mapped_range().map_err(gpu_err)?;
        let mut pixels = Vec::with_capacity((row * h) as usize);
        for y in 0..h {
            let src = if p.portable { h - 1 - y } else { y };
            let start = (src * padded) as usize;
            pixels.extend_from_slice(&mapped[start..start + row as usize]);
        }
        drop(mapped);
        readback.unmap();
        RgbaImage::from_raw(w, h, pixels).ok_or_else(|| "short readback".to_string())
    }
}
