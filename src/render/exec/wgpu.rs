//! The wgpu executor: runs a frame plan headless on Vulkan (WGSL, or
//! SPIR-V handed to the driver unchanged) or on wgpu's GL backend (WGSL),
//! and reads the target back. Bind groups and buffers come from
//! [`bind::wgpu`]; pipelines are made once per pass shape and kept.

use std::collections::{BTreeMap, HashMap};
use std::num::NonZeroU64;
use std::sync::{Arc, Mutex};

use image::RgbaImage;
use wgpu::util::DeviceExt;

use crate::emit::reflect_types::Reflection;
use crate::render::bind::{self, wgpu::Groups, wgpu::Resource, Fit, PassFit};
use crate::render::consumers::Consumer;
use crate::render::plan::{Cull, Format, FramePlan, Geometry, Mesh, Pass, Sampling, Unset, VertexFormat};
use crate::render::program::{ShaderCode, ShaderSet};
use crate::Target;

use super::{ExecError, Executor, Readback};

fn texture_format(f: Format) -> wgpu::TextureFormat {
    match f {
        Format::Rgba8 => wgpu::TextureFormat::Rgba8Unorm,
        Format::Rgba32Uint => wgpu::TextureFormat::Rgba32Uint,
        Format::Depth16 => wgpu::TextureFormat::Depth16Unorm,
        Format::Depth24Plus => wgpu::TextureFormat::Depth24Plus,
        Format::Depth32Float => wgpu::TextureFormat::Depth32Float,
    }
}

fn vertex_format(f: VertexFormat) -> wgpu::VertexFormat {
    match f {
        VertexFormat::Float32x3 => wgpu::VertexFormat::Float32x3,
    }
}

struct MeshBuffers {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

/// A wgpu device and queue, with the meshes and samplers plans use.
/// Create once, run many.
pub struct WgpuExecutor {
    /// `VulkanWgsl` (a Vulkan device, which also takes SPIR-V) or `WgpuGl`.
    consumer: Consumer,
    info: wgpu::AdapterInfo,
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// Uploaded meshes, by the address of the plan's `&'static Mesh`.
    meshes: Mutex<Vec<(usize, Arc<MeshBuffers>)>>,
    samplers: Mutex<HashMap<Sampling, Arc<wgpu::Sampler>>>,
    uncaptured: Arc<Mutex<Vec<String>>>,
}

/// The shape of a pass's pipeline: everything a pipeline depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct PipelineKey {
    vertex: String,
    fragment: String,
    color: Option<Format>,
    depth: Option<Format>,
    cull: Cull,
    depth_bias: bool,
    /// (location, byte offset, format) per attribute, and the stride.
    attributes: Vec<(u32, u32, VertexFormat)>,
    stride: u32,
    groups: Groups,
}

struct Pipeline {
    pipeline: wgpu::RenderPipeline,
    layouts: BTreeMap<u32, wgpu::BindGroupLayout>,
}

/// A program's modules on one device, and its pipelines by pass shape.
pub struct WgpuProgram {
    pub label: String,
    target: Target,
    reflection: Reflection,
    modules: Vec<wgpu::ShaderModule>,
    entry_module: BTreeMap<String, usize>,
    pipelines: Mutex<HashMap<PipelineKey, Arc<Pipeline>>>,
}

impl WgpuProgram {
    /// [`Target::Wgsl`] or [`Target::Spirv`].
    pub fn target(&self) -> Target {
        self.target
    }
}

impl WgpuExecutor {
    /// Opens the first adapter (a hardware one when there is one) of the
    /// backend `consumer` runs on: Vulkan for `VulkanWgsl` and
    /// `VulkanSpirv`, GL for `WgpuGl`.
    pub fn new(consumer: Consumer) -> Result<WgpuExecutor, ExecError> {
        let (consumer, backends, install) = match consumer {
            Consumer::VulkanWgsl | Consumer::VulkanSpirv => (Consumer::VulkanWgsl, wgpu::Backends::VULKAN, "apt-get install mesa-vulkan-drivers libvulkan1 (lavapipe)"),
            Consumer::WgpuGl => (Consumer::WgpuGl, wgpu::Backends::GL, "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri (llvmpipe)"),
            other => return Err(ExecError::Unsupported(format!("{} does not run on wgpu", other.name()))),
        };
        let unavailable = |why: String| ExecError::Unavailable { consumer, why, install: install.into() };
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = backends;
        desc.flags = wgpu::InstanceFlags::empty().with_env();
        let instance = wgpu::Instance::new(desc);
        let mut adapters = pollster::block_on(instance.enumerate_adapters(backends));
        if adapters.is_empty() {
            return Err(unavailable(format!("no wgpu {} adapter (wgpu enumerated none)", backend_name(consumer))));
        }
        adapters.sort_by_key(|a| match a.get_info().device_type {
            wgpu::DeviceType::DiscreteGpu => 0,
            wgpu::DeviceType::IntegratedGpu => 1,
            wgpu::DeviceType::VirtualGpu => 2,
            wgpu::DeviceType::Cpu => 3,
            wgpu::DeviceType::Other => 4,
        });
        let adapter = adapters.remove(0);
        let info = adapter.get_info();
        // SHADER_F16: programs with `half` (WGSL `f16`), where the device has it.
        let required_features =
            adapter.features() & (wgpu::Features::PASSTHROUGH_SHADERS | wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER | wgpu::Features::SHADER_F16);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("umbrac render"),
            required_features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| unavailable(format!("{} could not open a device: {e}", info.name)))?;
        let uncaptured = Arc::new(Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            sink.lock().unwrap_or_else(|p| p.into_inner()).push(e.to_string());
        }));
        Ok(WgpuExecutor { consumer, info, device, queue, meshes: Mutex::default(), samplers: Mutex::default(), uncaptured })
    }

    /// The adapter's name and driver, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (lavapipe)`.
    pub fn adapter_name(&self) -> String {
        let i = &self.info;
        format!("{} ({}{})", i.name, i.driver, if i.driver_info.is_empty() { String::new() } else { format!(" {}", i.driver_info) })
    }

    /// The device and queue (tests ask them for features).
    pub fn device(&self) -> (&wgpu::Device, &wgpu::Queue) {
        (&self.device, &self.queue)
    }

    /// Whether this device takes SPIR-V unchanged.
    pub fn supports_passthrough(&self) -> bool {
        self.device.features().contains(wgpu::Features::PASSTHROUGH_SHADERS)
    }

    /// Runs `f` inside validation, out-of-memory and internal error scopes
    /// and turns what they (and the uncaptured handler) caught into one
    /// message.
    fn scoped<T>(&self, f: impl FnOnce() -> T) -> Result<T, String> {
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let internal = self.device.push_error_scope(wgpu::ErrorFilter::Internal);
        let value = f();
        let errors: Vec<wgpu::Error> = [internal.pop(), memory.pop(), validation.pop()].into_iter().filter_map(pollster::block_on).collect();
        let mut uncaptured = self.uncaptured.lock().unwrap_or_else(|p| p.into_inner());
        let mut messages: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
        messages.append(&mut uncaptured);
        if messages.is_empty() {
            Ok(value)
        } else {
            Err(messages.join("\n"))
        }
    }

    fn mesh(&self, mesh: &'static Mesh) -> Arc<MeshBuffers> {
        let key = mesh as *const Mesh as usize;
        let mut cache = self.meshes.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, m)) = cache.iter().find(|(k, _)| *k == key) {
            return m.clone();
        }
        let buffer = |contents: &[u8], usage| {
            self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(mesh.name), contents, usage })
        };
        let m = Arc::new(MeshBuffers {
            vertices: buffer(&mesh.vertices, wgpu::BufferUsages::VERTEX),
            indices: buffer(bytemuck::cast_slice(&mesh.indices), wgpu::BufferUsages::INDEX),
            index_count: mesh.indices.len() as u32,
        });
        cache.push((key, m.clone()));
        m
    }

    /// The sampler a plan's sampling wants; clamp to border only where the
    /// device has it (else to the edge).
    fn sampler(&self, s: Sampling) -> Arc<wgpu::Sampler> {
        let border = s.border && self.device.features().contains(wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER);
        let mut cache = self.samplers.lock().unwrap_or_else(|p| p.into_inner());
        let key = Sampling { border, ..s };
        cache
            .entry(key)
            .or_insert_with(|| {
                let filter = if s.linear { wgpu::FilterMode::Linear } else { wgpu::FilterMode::Nearest };
                let address = if border { wgpu::AddressMode::ClampToBorder } else { wgpu::AddressMode::ClampToEdge };
                Arc::new(self.device.create_sampler(&wgpu::SamplerDescriptor {
                    label: Some("plan sampler"),
                    address_mode_u: address,
                    address_mode_v: address,
                    address_mode_w: address,
                    mag_filter: filter,
                    min_filter: filter,
                    compare: s.compare.then_some(wgpu::CompareFunction::LessEqual),
                    border_color: border.then_some(wgpu::SamplerBorderColor::OpaqueWhite),
                    ..Default::default()
                }))
            })
            .clone()
    }

    fn key(&self, program: &WgpuProgram, plan: &FramePlan, pass: &Pass, fit: &PassFit) -> Result<PipelineKey, ExecError> {
        let groups = bind::wgpu::groups(&program.reflection, pass, fit, program.target == Target::Spirv).map_err(|problems| {
            ExecError::Interface(bind::InterfaceError { program: program.label.clone(), scene: plan.scene.clone(), problems })
        })?;
        let stride = pass
            .draws
            .iter()
            .find_map(|d| match d.geometry {
                Geometry::Mesh(m) => Some(m.stride),
                Geometry::Vertices(_) => None,
            })
            .unwrap_or(0);
        Ok(PipelineKey {
            vertex: pass.vertex.clone(),
            fragment: pass.fragment.clone(),
            color: pass.color.map(|a| plan.target(a.target).format),
            depth: pass.depth.map(|a| plan.target(a.target).format),
            cull: pass.cull,
            depth_bias: pass.depth_bias,
            attributes: fit.attributes.iter().map(|a| (a.location, a.field.offset, a.field.format)).collect(),
            stride,
            groups,
        })
    }

    /// The pipeline of a pass shape, made on first use.
    fn pipeline(&self, program: &WgpuProgram, key: &PipelineKey, portable: bool, pass_name: &str) -> Result<Arc<Pipeline>, ExecError> {
        if let Some(p) = program.pipelines.lock().unwrap_or_else(|p| p.into_inner()).get(key) {
            return Ok(p.clone());
        }
        let made = self.scoped(|| self.make_pipeline(program, key, portable)).map_err(|log| ExecError::Link { pass: pass_name.into(), log })?;
        let made = Arc::new(made);
        program.pipelines.lock().unwrap_or_else(|p| p.into_inner()).insert(key.clone(), made.clone());
        Ok(made)
    }

    fn make_pipeline(&self, program: &WgpuProgram, key: &PipelineKey, portable: bool) -> Pipeline {
        let layouts: BTreeMap<u32, wgpu::BindGroupLayout> = key
            .groups
            .iter()
            .map(|(&group, entries)| {
                let entries: Vec<wgpu::BindGroupLayoutEntry> = entries
                    .iter()
                    .map(|e| {
                        let mut visibility = wgpu::ShaderStages::NONE;
                        if e.stages.vertex {
                            visibility |= wgpu::ShaderStages::VERTEX;
                        }
                        if e.stages.fragment {
                            visibility |= wgpu::ShaderStages::FRAGMENT;
                        }
                        let ty = match e.resource {
                            Resource::Buffer { size, .. } => wgpu::BindingType::Buffer {
                                ty: wgpu::BufferBindingType::Uniform,
                                has_dynamic_offset: false,
                                min_binding_size: NonZeroU64::new(size),
                            },
                            Resource::Texture { depth, filterable, .. } => wgpu::BindingType::Texture {
                                sample_type: if depth { wgpu::TextureSampleType::Depth } else { wgpu::TextureSampleType::Float { filterable } },
                                view_dimension: wgpu::TextureViewDimension::D2,
                                multisampled: false,
                            },
                            Resource::Sampler { comparison, filtering, .. } => wgpu::BindingType::Sampler(if comparison {
                                wgpu::SamplerBindingType::Comparison
                            } else if filtering {
                                wgpu::SamplerBindingType::Filtering
                            } else {
                                wgpu::SamplerBindingType::NonFiltering
                            }),
                        };
                        wgpu::BindGroupLayoutEntry { binding: e.binding, visibility, ty, count: None }
                    })
                    .collect();
                (group, self.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &entries }))
            })
            .collect();
        let group_count = layouts.keys().max().map_or(0, |g| g + 1);
        let list: Vec<Option<&wgpu::BindGroupLayout>> = (0..group_count).map(|g| layouts.get(&g)).collect();
        let layout = self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor { label: None, bind_group_layouts: &list, immediate_size: 0 });
        let attributes: Vec<wgpu::VertexAttribute> = key
            .attributes
            .iter()
            .map(|&(location, offset, format)| wgpu::VertexAttribute { format: vertex_format(format), offset: offset as u64, shader_location: location })
            .collect();
        let buffers = [Some(wgpu::VertexBufferLayout { array_stride: key.stride as u64, step_mode: wgpu::VertexStepMode::Vertex, attributes: &attributes })];
        let buffers: &[Option<wgpu::VertexBufferLayout>] = if key.stride == 0 { &[] } else { &buffers };
        let color = key.color.map(|f| [Some(wgpu::ColorTargetState { format: texture_format(f), blend: None, write_mask: wgpu::ColorWrites::ALL })]);
        let module = |entry: &str| &program.modules[program.entry_module.get(entry).copied().unwrap_or(0)];
        let pipeline = self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&key.vertex),
            layout: Some(&layout),
            vertex: wgpu::VertexState { module: module(&key.vertex), entry_point: Some(&key.vertex), compilation_options: Default::default(), buffers },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                // Portable conventions mirror y: GL's counter-clockwise fronts arrive clockwise.
                front_face: if portable { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
                cull_mode: match key.cull {
                    Cull::None => None,
                    Cull::Front => Some(wgpu::Face::Front),
                    Cull::Back => Some(wgpu::Face::Back),
                },
                ..Default::default()
            },
            depth_stencil: key.depth.map(|f| wgpu::DepthStencilState {
                format: texture_format(f),
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: if key.depth_bias { wgpu::DepthBiasState { constant: 4, slope_scale: 2.0, clamp: 0.0 } } else { Default::default() },
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: module(&key.fragment),
                entry_point: Some(&key.fragment),
                compilation_options: Default::default(),
                targets: color.as_ref().map_or(&[], |c| c.as_slice()),
            }),
            multiview_mask: None,
            cache: None,
        });
        Pipeline { pipeline, layouts }
    }

    fn encode(&self, program: &WgpuProgram, plan: &FramePlan, fit: &Fit) -> Result<Readback, ExecError> {
        let r = &program.reflection;
        use wgpu::TextureUsages as U;
        let read = plan.target(plan.readback).format;
        if read == Format::Depth24Plus {
            return Err(ExecError::Unsupported("a depth24plus target cannot be read back (wgpu cannot copy it)".into()));
        }
        // Targets.
        let textures: Vec<wgpu::Texture> = plan
            .targets
            .iter()
            .enumerate()
            .map(|(i, t)| {
                let mut usage = U::RENDER_ATTACHMENT;
                if plan.passes.iter().flat_map(|p| &p.textures).any(|x| x.target.0 == i) {
                    usage |= U::TEXTURE_BINDING;
                }
                if plan.readback.0 == i {
                    usage |= U::COPY_SRC;
                }
                self.device.create_texture(&wgpu::TextureDescriptor {
                    label: Some(&t.name),
                    size: wgpu::Extent3d { width: t.width, height: t.height, depth_or_array_layers: 1 },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format: texture_format(t.format),
                    usage,
                    view_formats: &[],
                })
            })
            .collect();
        let views: Vec<wgpu::TextureView> = textures.iter().map(|t| t.create_view(&Default::default())).collect();
        let stand_in = |depth: bool| {
            let format = if depth { wgpu::TextureFormat::Depth32Float } else { wgpu::TextureFormat::Rgba8Unorm };
            self.device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some("stand-in"),
                    size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: 1 },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: U::TEXTURE_BINDING,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        };
        let stand_ins = [stand_in(false), stand_in(true)];

        // Every (pass, draw) gets its own copy of each buffer: queue writes
        // between draws of one submission would all land before the first.
        let align = self.device.limits().min_uniform_buffer_offset_alignment as u64;
        let mut data: Vec<u8> = Vec::new();
        let mut offsets: HashMap<(usize, usize, usize), u64> = HashMap::new();
        let mut keys = Vec::new();
        for (p, (pass, pf)) in plan.passes.iter().zip(&fit.passes).enumerate() {
            let key = self.key(program, plan, pass, pf)?;
            for (d, draw) in pass.draws.iter().enumerate() {
                for e in key.groups.values().flatten() {
                    if let Resource::Buffer { block, .. } = e.resource {
                        let used = pf.blocks.iter().any(|&(b, _)| b == block);
                        let unset = if used { plan.unset } else { Unset::Zero };
                        let bytes = bind::wgpu::buffer_bytes(r, block, pass, draw, unset).map_err(ExecError::Program)?;
                        let at = (data.len() as u64).next_multiple_of(align);
                        data.resize(at as usize, 0);
                        data.extend_from_slice(&bytes);
                        offsets.insert((p, d, block), at);
                    }
                }
            }
            keys.push(key);
        }
        data.resize(data.len().max(16), 0);
        let uniforms = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some("uniforms"), contents: &data, usage: wgpu::BufferUsages::UNIFORM });

        let mut encoder = self.device.create_command_encoder(&Default::default());
        for (p, (pass, key)) in plan.passes.iter().zip(&keys).enumerate() {
            // A pass that draws nothing only clears: it needs no pipeline.
            let pipeline = if pass.draws.is_empty() { None } else { Some(self.pipeline(program, key, fit.portable, &pass.name)?) };
            let samplers: Vec<Arc<wgpu::Sampler>> = pass.textures.iter().map(|t| self.sampler(t.sampling)).collect();
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
                                            buffer: &uniforms,
                                            offset: offsets[&(p, d, block)],
                                            size: NonZeroU64::new(size),
                                        }),
                                        Resource::Texture { texture: Some(t), .. } => wgpu::BindingResource::TextureView(&views[pass.textures[t].target.0]),
                                        Resource::Texture { texture: None, depth, .. } => wgpu::BindingResource::TextureView(&stand_ins[depth as usize]),
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
            let color_attachment = pass.color.map(|a| {
                let c = a.clear;
                [Some(wgpu::RenderPassColorAttachment {
                    view: &views[a.target.0],
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color { r: c[0], g: c[1], b: c[2], a: c[3] }), store: wgpu::StoreOp::Store },
                })]
            });
            let mut rp = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some(&pass.name),
                color_attachments: color_attachment.as_ref().map_or(&[], |c| c.as_slice()),
                depth_stencil_attachment: pass.depth.map(|a| wgpu::RenderPassDepthStencilAttachment {
                    view: &views[a.target.0],
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(a.clear), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                ..Default::default()
            });
            let Some(pipeline) = pipeline else { continue };
            rp.set_pipeline(&pipeline.pipeline);
            for (d, draw) in pass.draws.iter().enumerate() {
                for (group, bg) in &groups[d] {
                    rp.set_bind_group(*group, bg, &[]);
                }
                match draw.geometry {
                    Geometry::Mesh(m) => {
                        let m = self.mesh(m);
                        rp.set_vertex_buffer(0, m.vertices.slice(..));
                        rp.set_index_buffer(m.indices.slice(..), wgpu::IndexFormat::Uint32);
                        rp.draw_indexed(0..m.index_count, 0, 0..1);
                    }
                    Geometry::Vertices(n) => rp.draw(0..n, 0..1),
                }
            }
        }

        let target = plan.target(plan.readback);
        let (w, h) = (target.width, target.height);
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
            wgpu::TexelCopyTextureInfo { texture: &textures[plan.readback.0], mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
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
            // Portable conventions render GL's bottom row into row 0: read
            // rows in reverse so the picture is top row first.
            let src = if fit.portable { h - 1 - y } else { y };
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

fn backend_name(c: Consumer) -> &'static str {
    if c == Consumer::WgpuGl {
        "gl"
    } else {
        "vulkan"
    }
}

impl Executor for WgpuExecutor {
    type Prepared = WgpuProgram;

    fn prepare(&self, set: &ShaderSet, plan: &FramePlan) -> Result<WgpuProgram, ExecError> {
        let r = set.manifest().map_err(ExecError::Program)?;
        let fit = bind::fit(&set.label, r, plan)?;
        match set.target {
            Target::Wgsl => {}
            Target::Spirv if self.consumer != Consumer::VulkanWgsl => {
                return Err(ExecError::Unsupported(format!(
                    "--via spirv hands the SPIR-V to the driver unchanged, which only the Vulkan backend can take (this is {})",
                    backend_name(self.consumer)
                )))
            }
            Target::Spirv if !self.supports_passthrough() => {
                return Err(ExecError::Unavailable {
                    consumer: Consumer::VulkanSpirv,
                    why: format!("{} lacks PASSTHROUGH_SHADERS, needed to pass SPIR-V to it unchanged (--via spirv; use --via wgsl)", self.adapter_name()),
                    install: "a Vulkan driver with it (lavapipe has it)".into(),
                })
            }
            Target::Spirv => {}
            other => return Err(ExecError::Unsupported(format!("{}: wgpu runs WGSL or SPIR-V, not {}", set.label, other.name()))),
        }
        let modules = self
            .scoped(|| {
                set.modules
                    .iter()
                    .enumerate()
                    .map(|(i, code)| match code {
                        ShaderCode::Wgsl(text) => Ok(self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
                            label: Some(&set.label),
                            source: wgpu::ShaderSource::Wgsl(text.as_str().into()),
                        })),
                        ShaderCode::Spirv(words) => {
                            let entry_points: Vec<wgpu::PassthroughShaderEntryPoint> = r
                                .entry_points
                                .iter()
                                .filter(|e| set.module_of(&e.name) == i)
                                .map(|e| wgpu::PassthroughShaderEntryPoint { name: e.name.clone().into(), workgroup_size: (0, 0, 0) })
                                .collect();
                            // SAFETY: the words are a SPIR-V module that umbrac
                            // emitted and naga validated; that is the contract of
                            // `--via spirv`.
                            Ok(unsafe {
                                self.device.create_shader_module_passthrough(wgpu::ShaderModuleDescriptorPassthrough {
                                    label: Some(&set.label),
                                    entry_points: entry_points.into(),
                                    spirv: Some(words.as_slice().into()),
                                    ..Default::default()
                                })
                            })
                        }
                        ShaderCode::Glsl { file, .. } => Err(ExecError::Unsupported(format!("{file}: wgpu does not take GLSL files"))),
                    })
                    .collect::<Result<Vec<_>, _>>()
            })
            .map_err(|log| ExecError::Compile { file: set.label.clone(), log })??;
        let program = WgpuProgram {
            label: set.label.clone(),
            target: set.target,
            reflection: r.clone(),
            modules,
            entry_module: r.entry_points.iter().map(|e| (e.name.clone(), set.module_of(&e.name))).collect(),
            pipelines: Mutex::default(),
        };
        for (pass, pf) in plan.passes.iter().zip(&fit.passes).filter(|(p, _)| !p.draws.is_empty()) {
            let key = self.key(&program, plan, pass, pf)?;
            self.pipeline(&program, &key, fit.portable, &pass.name)?;
        }
        Ok(program)
    }

    fn run(&self, program: &WgpuProgram, plan: &FramePlan) -> Result<Readback, ExecError> {
        super::check_sizes(plan, self.device.limits().max_texture_dimension_2d)?;
        let fit = bind::fit(&program.label, &program.reflection, plan)?;
        self.scoped(|| self.encode(program, plan, &fit)).map_err(|e| ExecError::Api(format!("wgpu error: {e}")))?
    }

    fn device_name(&self) -> String {
        self.adapter_name()
    }
}
