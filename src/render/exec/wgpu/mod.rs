//! The wgpu executor: runs a frame plan headless on Vulkan (WGSL, or
//! SPIR-V handed to the driver unchanged) or on wgpu's GL backend (WGSL),
//! and reads the target back. Bind groups and buffers come from
//! [`bind::wgpu`]; pipelines are made once per pass shape and kept.

mod compute;
mod frame;

use std::collections::{BTreeMap, HashMap};
use std::num::NonZeroU64;
use std::sync::{Arc, Mutex};

use wgpu::util::DeviceExt;

use crate::emit::reflect_types::Reflection;
use crate::render::bind::{self, wgpu::Groups, wgpu::Resource, PassFit};
use crate::render::consumer::Consumer;
use crate::render::plan::{Cull, Format, FramePlan, Geometry, Mesh, Pass, Sampling, VertexFormat};
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
        VertexFormat::Float32 => wgpu::VertexFormat::Float32,
        VertexFormat::Float32x2 => wgpu::VertexFormat::Float32x2,
        VertexFormat::Float32x3 => wgpu::VertexFormat::Float32x3,
        VertexFormat::Float32x4 => wgpu::VertexFormat::Float32x4,
    }
}

struct MeshBuffers {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

/// A compute pipeline and its bind group layouts, group by group.
type ComputePipeline = (wgpu::ComputePipeline, Vec<wgpu::BindGroupLayout>);

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
    /// Compute programs' modules, by a hash of their code and entry point,
    /// kept for the device's life (`compute.rs`).
    compute_modules: Mutex<HashMap<(u64, String), Arc<wgpu::ShaderModule>>>,
    /// Their pipelines and group layouts, by module, entry and layout.
    compute_pipelines: Mutex<HashMap<String, Arc<ComputePipeline>>>,
}

/// The shape of a pass's pipeline: everything a pipeline depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct PipelineKey {
    vertex: String,
    fragment: Option<String>,
    /// The colour targets' formats, output location 0 first.
    color: Vec<Format>,
    depth: Option<Format>,
    cull: Cull,
    depth_bias: bool,
    /// (location, byte offset, format) per attribute, and the stride.
    attributes: Vec<(u32, u32, VertexFormat, bool)>,
    stride: u32,
    /// The instance records' stride (0: not instanced).
    instance_stride: u32,
    /// A point list (WebGPU's points are one pixel: no point size).
    points: bool,
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
        // SHADER_F16: programs with `half` (WGSL `f16`), SUBGROUP: programs
        // with subgroup operations, where the device has them.
        let required_features = adapter.features()
            & (wgpu::Features::PASSTHROUGH_SHADERS | wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER | wgpu::Features::SHADER_F16 | wgpu::Features::SUBGROUP);
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
        Ok(WgpuExecutor { consumer, info, device, queue, meshes: Mutex::default(), samplers: Mutex::default(), uncaptured, compute_modules: Mutex::default(), compute_pipelines: Mutex::default() })
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

    /// Whether this device has subgroup operations (`Features::SUBGROUP`,
    /// requested where the adapter has it).
    pub fn supports_subgroups(&self) -> bool {
        self.device.features().contains(wgpu::Features::SUBGROUP)
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
                let address = if border {
                    wgpu::AddressMode::ClampToBorder
                } else if s.repeat {
                    wgpu::AddressMode::Repeat
                } else {
                    wgpu::AddressMode::ClampToEdge
                };
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
        let mesh = pass.draws.iter().find_map(|d| match d.geometry {
            Geometry::Mesh(m) => Some(m),
            Geometry::Vertices(_) => None,
        });
        let stride = mesh.map_or(0, |m| m.stride);
        let instance_stride = mesh.and_then(|m| m.instances).map_or(0, |i| i.stride);
        Ok(PipelineKey {
            vertex: pass.vertex.clone(),
            fragment: pass.fragment.clone(),
            color: pass.colors().map(|a| plan.target(a.target).format).collect(),
            depth: pass.depth.map(|a| plan.target(a.target).format),
            cull: pass.cull,
            depth_bias: pass.depth_bias,
            attributes: fit.attributes.iter().map(|a| (a.location, a.field.offset, a.field.format, a.field.per_instance)).collect(),
            stride,
            instance_stride,
            points: mesh.is_some_and(|m| m.points),
            groups,
        })
    }

    /// The pipeline of a pass shape, made on first use.
    fn pipeline(&self, program: &WgpuProgram, key: &PipelineKey, mirrored: bool, pass_name: &str) -> Result<Arc<Pipeline>, ExecError> {
        if let Some(p) = program.pipelines.lock().unwrap_or_else(|p| p.into_inner()).get(key) {
            return Ok(p.clone());
        }
        let made = self.scoped(|| self.make_pipeline(program, key, mirrored)).map_err(|log| ExecError::Link { pass: pass_name.into(), log })?;
        let made = Arc::new(made);
        program.pipelines.lock().unwrap_or_else(|p| p.into_inner()).insert(key.clone(), made.clone());
        Ok(made)
    }

    fn make_pipeline(&self, program: &WgpuProgram, key: &PipelineKey, mirrored: bool) -> Pipeline {
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
                            Resource::Texture { depth, filterable, dim, .. } => wgpu::BindingType::Texture {
                                sample_type: if depth { wgpu::TextureSampleType::Depth } else { wgpu::TextureSampleType::Float { filterable } },
                                view_dimension: frame::view_dimension(dim),
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
        // Buffer 0 steps per vertex, buffer 1 (the instance records) per instance.
        let attributes = |instance: bool| -> Vec<wgpu::VertexAttribute> {
            key.attributes
                .iter()
                .filter(|a| a.3 == instance)
                .map(|&(location, offset, format, _)| wgpu::VertexAttribute { format: vertex_format(format), offset: offset as u64, shader_location: location })
                .collect()
        };
        let (per_vertex, per_instance) = (attributes(false), attributes(true));
        let buffers = [
            Some(wgpu::VertexBufferLayout { array_stride: key.stride as u64, step_mode: wgpu::VertexStepMode::Vertex, attributes: &per_vertex }),
            Some(wgpu::VertexBufferLayout { array_stride: key.instance_stride as u64, step_mode: wgpu::VertexStepMode::Instance, attributes: &per_instance }),
        ];
        let buffers: &[Option<wgpu::VertexBufferLayout>] = match (key.stride, key.instance_stride) {
            (0, _) => &[],
            (_, 0) => &buffers[..1],
            _ => &buffers,
        };
        let color: Vec<_> = key.color.iter().map(|&f| Some(wgpu::ColorTargetState { format: texture_format(f), blend: None, write_mask: wgpu::ColorWrites::ALL })).collect();
        let module = |entry: &str| &program.modules[program.entry_module.get(entry).copied().unwrap_or(0)];
        let pipeline = self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&key.vertex),
            layout: Some(&layout),
            vertex: wgpu::VertexState { module: module(&key.vertex), entry_point: Some(&key.vertex), compilation_options: Default::default(), buffers },
            primitive: wgpu::PrimitiveState {
                topology: if key.points { wgpu::PrimitiveTopology::PointList } else { wgpu::PrimitiveTopology::TriangleList },
                // A mirrored y (portable GL-dialect code): GL's counter-clockwise fronts arrive clockwise.
                front_face: if mirrored { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
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
            fragment: key.fragment.as_ref().map(|f| wgpu::FragmentState {
                module: module(f),
                entry_point: Some(f),
                compilation_options: Default::default(),
                targets: &color,
            }),
            multiview_mask: None,
            cache: None,
        });
        Pipeline { pipeline, layouts }
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
                            source: wgpu::ShaderSource::Wgsl(crate::emit::wgsl::for_naga(text)),
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
            self.pipeline(&program, &key, fit.mirrored_on_webgpu(), &pass.name)?;
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
