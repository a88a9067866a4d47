//! The wgpu renderer: draws the scene with a compiled (or hand-written)
//! program, headless, and reads the image back.
//!
//! Everything bound comes from the program's reflection through
//! [`interface::plan`]: uniform buffer sizes, member offsets, binding
//! numbers, attribute locations and formats.

use std::collections::BTreeMap;
use std::num::NonZeroU64;
use std::sync::{Arc, Mutex};

use image::RgbaImage;
use wgpu::util::DeviceExt;

use crate::emit::reflect_types::Reflection;

use super::interface::{self, InterfaceError, PassPlan, Plan, ResourceKind};
use super::scene::{self, Frame, FrameParams, Object, View};

/// Which wgpu backend to render with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Backend {
    /// Vulkan (on a machine without a GPU: Mesa's lavapipe).
    #[default]
    Vulkan,
    /// OpenGL / GLES through EGL (without a GPU: Mesa's llvmpipe).
    Gl,
}

impl Backend {
    pub fn name(self) -> &'static str {
        match self {
            Backend::Vulkan => "vulkan",
            Backend::Gl => "gl",
        }
    }

    fn backends(self) -> wgpu::Backends {
        match self {
            Backend::Vulkan => wgpu::Backends::VULKAN,
            Backend::Gl => wgpu::Backends::GL,
        }
    }

    fn install_hint(self) -> &'static str {
        match self {
            Backend::Vulkan => "on Debian/Ubuntu without a GPU: `apt-get install mesa-vulkan-drivers libvulkan1` (lavapipe)",
            Backend::Gl => "on Debian/Ubuntu without a GPU: `apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri` (llvmpipe)",
        }
    }
}

/// The form of the shader code handed to wgpu.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Via {
    /// WGSL text, translated by wgpu's naga like any WebGPU program.
    #[default]
    Wgsl,
    /// SPIR-V words passed to the driver unchanged
    /// (`Features::PASSTHROUGH_SHADERS`; Vulkan only).
    Spirv,
}

impl Via {
    pub fn name(self) -> &'static str {
        match self {
            Via::Wgsl => "wgsl",
            Via::Spirv => "spirv",
        }
    }

    /// The reflection's target key for this form.
    pub fn target(self) -> crate::Target {
        match self {
            Via::Wgsl => crate::Target::Wgsl,
            Via::Spirv => crate::Target::Spirv,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ShaderCode {
    Wgsl(String),
    Spirv(Vec<u32>),
}

impl ShaderCode {
    pub fn via(&self) -> Via {
        match self {
            ShaderCode::Wgsl(_) => Via::Wgsl,
            ShaderCode::Spirv(_) => Via::Spirv,
        }
    }

    /// SPIR-V words from little-endian bytes.
    pub fn spirv_from_bytes(bytes: &[u8]) -> Result<ShaderCode, String> {
        if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
            return Err(format!("{} bytes is not a SPIR-V module", bytes.len()));
        }
        let words: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
        if words[0] != 0x0723_0203 {
            return Err(format!("bad SPIR-V magic number {:#010x}", words[0]));
        }
        Ok(ShaderCode::Spirv(words))
    }
}

/// A program to render the scene with: its code (one module, or one per
/// entry point) and its reflection.
#[derive(Clone, Debug)]
pub struct ShaderSet {
    /// Names the program in messages.
    pub label: String,
    pub modules: Vec<ShaderCode>,
    /// Module index per entry point name; entry points not listed use module 0.
    pub entry_module: BTreeMap<String, usize>,
    pub reflection: Reflection,
}

impl ShaderSet {
    /// One module holding every entry point.
    pub fn single(label: impl Into<String>, code: ShaderCode, reflection: Reflection) -> ShaderSet {
        ShaderSet { label: label.into(), modules: vec![code], entry_module: BTreeMap::new(), reflection }
    }

    /// The program's WGSL or SPIR-V from a compilation, found through the
    /// reflection's per-entry-point file names.
    pub fn from_compiled(label: impl Into<String>, compiled: &crate::Compiled, via: Via) -> Result<ShaderSet, RenderError> {
        let label = label.into();
        let target = via.target().name();
        let mut files: Vec<String> = Vec::new();
        let mut entry_module = BTreeMap::new();
        for e in &compiled.reflection.entry_points {
            let file = e.files.get(target).ok_or_else(|| {
                RenderError::Program(format!("{label}: entry point `{}` has no {target} output in the reflection", e.name))
            })?;
            let index = match files.iter().position(|f| f == file) {
                Some(i) => i,
                None => {
                    files.push(file.clone());
                    files.len() - 1
                }
            };
            entry_module.insert(e.name.clone(), index);
        }
        let mut modules = Vec::new();
        for file in &files {
            let a = compiled
                .artifact(file)
                .ok_or_else(|| RenderError::Program(format!("{label}: the reflection names `{file}` but the compiler did not produce it")))?;
            modules.push(match via {
                Via::Wgsl => ShaderCode::Wgsl(a.text().into_owned()),
                Via::Spirv => ShaderCode::spirv_from_bytes(&a.contents).map_err(|e| RenderError::Program(format!("{label}: {file}: {e}")))?,
            });
        }
        if modules.is_empty() {
            return Err(RenderError::Program(format!("{label}: the program has no entry points")));
        }
        Ok(ShaderSet { label, modules, entry_module, reflection: compiled.reflection.clone() })
    }

    pub fn via(&self) -> Via {
        self.modules[0].via()
    }

    fn module_of(&self, entry: &str) -> usize {
        self.entry_module.get(entry).copied().unwrap_or(0)
    }
}

/// Everything that can stop a render. Displayed as a one-paragraph message
/// for the command line.
#[derive(Clone, Debug)]
pub enum RenderError {
    /// No adapter for the backend.
    NoAdapter { backend: Backend, detail: String },
    /// The adapter lacks a feature the request needs.
    MissingFeature { feature: &'static str, why: String },
    /// The program does not fit the scene.
    Interface(InterfaceError),
    /// The program could not be loaded or compiled.
    Program(String),
    /// wgpu reported an error (validation, out of memory, internal).
    Gpu(String),
    /// A request the renderer cannot do (`--via spirv` on GL, a zero size).
    Unsupported(String),
}

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RenderError::NoAdapter { backend, detail } => {
                write!(f, "no {} adapter found ({detail}); {}", backend.name(), backend.install_hint())
            }
            RenderError::MissingFeature { feature, why } => write!(f, "the adapter does not support {feature}, needed {why}"),
            RenderError::Interface(e) => write!(f, "{}", e.to_string().trim_end()),
            RenderError::Program(m) | RenderError::Unsupported(m) => write!(f, "{m}"),
            RenderError::Gpu(m) => write!(f, "wgpu error: {m}"),
        }
    }
}

impl std::error::Error for RenderError {}

impl From<InterfaceError> for RenderError {
    fn from(e: InterfaceError) -> Self {
        RenderError::Interface(e)
    }
}

const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

struct MeshBuffers {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

/// A device, a queue and the scene's meshes. Create once, render many.
pub struct Renderer {
    backend: Backend,
    info: wgpu::AdapterInfo,
    device: wgpu::Device,
    queue: wgpu::Queue,
    cube: MeshBuffers,
    floor: MeshBuffers,
    sampler: wgpu::Sampler,
    /// Comparison samplers for the other filters and fits, by
    /// (linear, clamp to border); `sampler` is (true, false).
    samplers: BTreeMap<(bool, bool), wgpu::Sampler>,
    uncaptured: Arc<Mutex<Vec<String>>>,
}

/// A program's pipelines, ready to draw many frames.
pub struct Program {
    pub plan: Plan,
    via: Via,
    shadow: PassObjects,
    main: PassObjects,
    /// Kept for shadow pipelines of other depth formats, made on first use.
    modules: Vec<wgpu::ShaderModule>,
    entry_module: BTreeMap<String, usize>,
    other_shadow: Mutex<Vec<(wgpu::TextureFormat, Arc<PassObjects>)>>,
}

struct PassObjects {
    pipeline: wgpu::RenderPipeline,
    /// Layout per group number (the plan's groups).
    layouts: BTreeMap<u32, wgpu::BindGroupLayout>,
}

impl Renderer {
    /// Opens the first adapter of `backend` (a hardware one when there is one).
    pub fn new(backend: Backend) -> Result<Renderer, RenderError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = backend.backends();
        desc.flags = wgpu::InstanceFlags::empty().with_env();
        let instance = wgpu::Instance::new(desc);
        let mut adapters = pollster::block_on(instance.enumerate_adapters(backend.backends()));
        if adapters.is_empty() {
            return Err(RenderError::NoAdapter { backend, detail: "wgpu enumerated none".into() });
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
        let required_features =
            adapter.features() & (wgpu::Features::PASSTHROUGH_SHADERS | wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("umbrac render"),
            required_features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| RenderError::NoAdapter { backend, detail: format!("{} could not open a device: {e}", info.name) })?;
        let uncaptured = Arc::new(Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            sink.lock().unwrap_or_else(|p| p.into_inner()).push(e.to_string());
        }));
        let upload = |mesh: scene::Mesh, name: &str| MeshBuffers {
            vertices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(name),
                contents: bytemuck::cast_slice(&mesh.vertices),
                usage: wgpu::BufferUsages::VERTEX,
            }),
            indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(name),
                contents: bytemuck::cast_slice(&mesh.indices),
                usage: wgpu::BufferUsages::INDEX,
            }),
            index_count: mesh.indices.len() as u32,
        };
        let cube = upload(scene::cube_mesh(), "cube");
        let floor = upload(scene::floor_mesh(), "floor");
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow compare"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            address_mode_w: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        let samplers = super::setup_gpu::comparison_samplers(&device);
        Ok(Renderer { backend, info, device, queue, cube, floor, sampler, samplers, uncaptured })
    }

    pub fn backend(&self) -> Backend {
        self.backend
    }

    /// The adapter's name and driver, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (lavapipe)`.
    pub fn adapter_name(&self) -> String {
        let i = &self.info;
        format!("{} ({}{})", i.name, i.driver, if i.driver_info.is_empty() { String::new() } else { format!(" {}", i.driver_info) })
    }

    /// The device and queue, for hosts of other scenes (`techniques`).
    pub fn device(&self) -> (&wgpu::Device, &wgpu::Queue) {
        (&self.device, &self.queue)
    }

    /// Whether this device takes SPIR-V unchanged.
    pub fn supports_passthrough(&self) -> bool {
        self.device.features().contains(wgpu::Features::PASSTHROUGH_SHADERS)
    }

    /// Renders one frame: [`prepare`](Self::prepare) then [`draw`](Self::draw).
    pub fn render(&self, set: &ShaderSet, params: &FrameParams) -> Result<RgbaImage, RenderError> {
        let program = self.prepare(set)?;
        self.draw(&program, params)
    }

    /// Fits the program to the scene and builds its pipelines.
    pub fn prepare(&self, set: &ShaderSet) -> Result<Program, RenderError> {
        let via = set.via();
        let plan = interface::plan(&set.label, &set.reflection)?;
        let plan = if via == Via::Spirv { plan.for_passthrough()? } else { plan };
        if set.modules.iter().any(|m| m.via() != via) {
            return Err(RenderError::Program(format!("{}: mixes WGSL and SPIR-V modules", set.label)));
        }
        if via == Via::Spirv {
            if self.backend != Backend::Vulkan {
                return Err(RenderError::Unsupported(format!(
                    "--via spirv hands the SPIR-V to the driver unchanged, which only the Vulkan backend can take (this is {})",
                    self.backend.name()
                )));
            }
            if !self.supports_passthrough() {
                return Err(RenderError::MissingFeature {
                    feature: "PASSTHROUGH_SHADERS",
                    why: format!("to pass SPIR-V to {} unchanged (--via spirv); use --via wgsl", self.adapter_name()),
                });
            }
        }
        self.scoped(|| {
            let entries_of = |index: usize| -> Vec<String> {
                set.reflection.entry_points.iter().filter(|e| set.module_of(&e.name) == index).map(|e| e.name.clone()).collect()
            };
            let modules: Vec<wgpu::ShaderModule> = set
                .modules
                .iter()
                .enumerate()
                .map(|(i, code)| match code {
                    ShaderCode::Wgsl(text) => self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
                        label: Some(&set.label),
                        source: wgpu::ShaderSource::Wgsl(text.as_str().into()),
                    }),
                    ShaderCode::Spirv(words) => {
                        let entry_points: Vec<wgpu::PassthroughShaderEntryPoint> = entries_of(i)
                            .into_iter()
                            .map(|name| wgpu::PassthroughShaderEntryPoint { name: name.into(), workgroup_size: (0, 0, 0) })
                            .collect();
                        // SAFETY: the words are a SPIR-V module that umbrac
                        // emitted and naga validated; that is the contract of
                        // `--via spirv`.
                        unsafe {
                            self.device.create_shader_module_passthrough(wgpu::ShaderModuleDescriptorPassthrough {
                                label: Some(&set.label),
                                entry_points: entry_points.into(),
                                spirv: Some(words.as_slice().into()),
                                ..Default::default()
                            })
                        }
                    }
                })
                .collect();
            let module = |entry: &str| &modules[set.module_of(entry)];
            let shadow = self.pass_objects(&plan, &plan.shadow, &module, true, DEPTH_FORMAT);
            let main = self.pass_objects(&plan, &plan.main, &module, false, DEPTH_FORMAT);
            let entry_module = set.reflection.entry_points.iter().map(|e| (e.name.clone(), set.module_of(&e.name))).collect();
            Program { plan: plan.clone(), via, shadow, main, modules, entry_module, other_shadow: Mutex::new(Vec::new()) }
        })
        .map_err(|e| RenderError::Program(format!("{}: {e}", set.label)))
    }

    fn pass_objects<'m>(
        &self,
        plan: &Plan,
        pass: &PassPlan,
        module: &impl Fn(&str) -> &'m wgpu::ShaderModule,
        shadow: bool,
        depth_format: wgpu::TextureFormat,
    ) -> PassObjects {
        let layouts: BTreeMap<u32, wgpu::BindGroupLayout> = pass
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
                        let ty = match e.kind {
                            ResourceKind::Uniform(i) => wgpu::BindingType::Buffer {
                                ty: wgpu::BufferBindingType::Uniform,
                                has_dynamic_offset: false,
                                min_binding_size: NonZeroU64::new(plan.blocks[i].size as u64),
                            },
                            ResourceKind::ShadowTexture => wgpu::BindingType::Texture {
                                sample_type: wgpu::TextureSampleType::Depth,
                                view_dimension: wgpu::TextureViewDimension::D2,
                                multisampled: false,
                            },
                            ResourceKind::ShadowSampler => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
                        };
                        wgpu::BindGroupLayoutEntry { binding: e.binding, visibility, ty, count: None }
                    })
                    .collect();
                let layout = self
                    .device
                    .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some("scene group"), entries: &entries });
                (group, layout)
            })
            .collect();
        let max_group = layouts.keys().max().map_or(0, |g| g + 1);
        let layout_list: Vec<Option<&wgpu::BindGroupLayout>> = (0..max_group).map(|g| layouts.get(&g)).collect();
        let pipeline_layout = self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene"),
            bind_group_layouts: &layout_list,
            immediate_size: 0,
        });
        let attributes: Vec<wgpu::VertexAttribute> = pass
            .attributes
            .iter()
            .map(|a| wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: a.offset, shader_location: a.location })
            .collect();
        let buffers = [Some(wgpu::VertexBufferLayout {
            array_stride: scene::VERTEX_STRIDE,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &attributes,
        })];
        let targets = [Some(wgpu::ColorTargetState { format: COLOR_FORMAT, blend: None, write_mask: wgpu::ColorWrites::ALL })];
        let bias = if shadow {
            wgpu::DepthBiasState { constant: 4, slope_scale: 2.0, clamp: 0.0 }
        } else {
            wgpu::DepthBiasState::default()
        };
        let pipeline = self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(if shadow { "shadow pass" } else { "main pass" }),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: module(&pass.vertex_entry),
                entry_point: Some(&pass.vertex_entry),
                compilation_options: Default::default(),
                buffers: &buffers,
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                // Portable conventions mirror y, which turns GL's
                // counter-clockwise fronts clockwise. Nothing is culled.
                front_face: if plan.portable { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: depth_format,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias,
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: module(&pass.fragment_entry),
                entry_point: Some(&pass.fragment_entry),
                compilation_options: Default::default(),
                // The shadow pass has no colour attachment: the fragment
                // program runs and its colour is dropped, as in the tutorial.
                targets: if shadow { &[] } else { &targets },
            }),
            multiview_mask: None,
            cache: None,
        });
        PassObjects { pipeline, layouts }
    }

    /// Runs `f` inside validation, out-of-memory and internal error scopes
    /// and turns what they caught into an error.
    fn scoped<T>(&self, f: impl FnOnce() -> T) -> Result<T, String> {
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let internal = self.device.push_error_scope(wgpu::ErrorFilter::Internal);
        let value = f();
        let errors: Vec<wgpu::Error> = [internal.pop(), memory.pop(), validation.pop()]
            .into_iter()
            .filter_map(pollster::block_on)
            .collect();
        let mut uncaptured = self.uncaptured.lock().unwrap_or_else(|p| p.into_inner());
        let mut messages: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
        messages.append(&mut uncaptured);
        if messages.is_empty() {
            Ok(value)
        } else {
            Err(messages.join("\n"))
        }
    }

    /// Draws one frame of `program` and reads it back, top row first.
    pub fn draw(&self, program: &Program, params: &FrameParams) -> Result<RgbaImage, RenderError> {
        if params.width == 0 || params.height == 0 || params.shadow_size == 0 {
            return Err(RenderError::Unsupported(format!(
                "image {}x{} with a {} shadow map: every size must be at least 1",
                params.width, params.height, params.shadow_size
            )));
        }
        let limit = self.device.limits().max_texture_dimension_2d;
        let biggest = params.width.max(params.height).max(params.shadow_size);
        if biggest > limit {
            return Err(RenderError::Unsupported(format!("{biggest} pixels exceeds this adapter's texture limit of {limit}")));
        }
        self.scoped(|| self.encode_and_read(program, params))
            .map_err(RenderError::Gpu)?
    }

    fn encode_and_read(&self, program: &Program, params: &FrameParams) -> Result<RgbaImage, RenderError> {
        let plan = &program.plan;
        let frame = Frame::of(params);
        let draws = frame.draws();

        // Uniform data: for each (pass, draw) a copy of every block, each at
        // an offset aligned for binding. Per-draw values (u_model,
        // u_is_floor) must live in separate memory: queue writes between
        // draws of one submission would all land before the first draw.
        let align = self.device.limits().min_uniform_buffer_offset_alignment as u64;
        let mut data: Vec<u8> = Vec::new();
        let mut offsets = [[Vec::new(), Vec::new()], [Vec::new(), Vec::new()]];
        for pass_offsets in offsets.iter_mut() {
            for (d, draw) in draws.iter().enumerate() {
                for block in &plan.blocks {
                    let at = (data.len() as u64).next_multiple_of(align);
                    data.resize(at as usize, 0);
                    data.extend_from_slice(&block.bytes(&frame, draw));
                    pass_offsets[d].push(at);
                }
            }
        }
        if data.is_empty() {
            data.resize(16, 0);
        }
        let uniforms = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("uniforms"),
            contents: &data,
            usage: wgpu::BufferUsages::UNIFORM,
        });

        let texture = |label: &str, w: u32, h: u32, format, usage| {
            self.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        use wgpu::TextureUsages as U;
        let n = params.shadow_size;
        let shadow_options = params.setup.shadow;
        let shadow_format = shadow_options.depth.wgpu();
        let shadow_objects = self.shadow_objects(program, shadow_format);
        let compare_sampler = self.compare_sampler(&params.setup);
        let mut shadow_usage = U::RENDER_ATTACHMENT | U::TEXTURE_BINDING;
        if shadow_format != wgpu::TextureFormat::Depth24Plus {
            shadow_usage |= U::COPY_SRC;
        }
        let shadow_map = texture("shadow map", n, n, shadow_format, shadow_usage);
        let shadow_view = shadow_map.create_view(&Default::default());
        let color = texture("colour", params.width, params.height, COLOR_FORMAT, U::RENDER_ATTACHMENT | U::COPY_SRC);
        let color_view = color.create_view(&Default::default());
        let depth = texture("depth", params.width, params.height, DEPTH_FORMAT, U::RENDER_ATTACHMENT);
        let depth_view = depth.create_view(&Default::default());

        // The shadow pass draws into the shadow map, so where its layout
        // holds the shadow texture (SPIR-V passthrough layouts hold every
        // binding) a stand-in is bound.
        let stand_in = texture("stand-in shadow map", 1, 1, shadow_format, U::TEXTURE_BINDING);
        let stand_in_view = stand_in.create_view(&Default::default());
        let bind_groups = |objects: &PassObjects, pass: &PassPlan, pass_index: usize, d: usize| -> Vec<(u32, wgpu::BindGroup)> {
            objects
                .layouts
                .iter()
                .map(|(&group, layout)| {
                    let entries: Vec<wgpu::BindGroupEntry> = pass.groups[&group]
                        .iter()
                        .map(|e| wgpu::BindGroupEntry {
                            binding: e.binding,
                            resource: match e.kind {
                                ResourceKind::Uniform(i) => wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                                    buffer: &uniforms,
                                    offset: offsets[pass_index][d][i],
                                    size: NonZeroU64::new(plan.blocks[i].size as u64),
                                }),
                                ResourceKind::ShadowTexture if pass_index == 0 => wgpu::BindingResource::TextureView(&stand_in_view),
                                ResourceKind::ShadowTexture => wgpu::BindingResource::TextureView(&shadow_view),
                                ResourceKind::ShadowSampler => wgpu::BindingResource::Sampler(compare_sampler),
                            },
                        })
                        .collect();
                    let bg = self.device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout, entries: &entries });
                    (group, bg)
                })
                .collect()
        };
        let shadow_groups: Vec<_> = (0..2).map(|d| bind_groups(&shadow_objects, &plan.shadow, 0, d)).collect();
        let main_groups: Vec<_> = (0..2).map(|d| bind_groups(&program.main, &plan.main, 1, d)).collect();

        let mut encoder = self.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("shadow pass"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &shadow_view,
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                ..Default::default()
            });
            // `lit` leaves the map empty (every compare passes).
            if params.view != View::Lit {
                pass.set_pipeline(&shadow_objects.pipeline);
                for (d, draw) in draws.iter().enumerate() {
                    // Casters only: the floor shadows nothing.
                    if shadow_options.casters_only && draw.object == Object::Floor {
                        continue;
                    }
                    self.draw_mesh(&mut pass, draw.object, &shadow_groups[d]);
                }
            }
        }
        if params.view != View::ShadowMap {
            let mut pass = begin_main_pass(&mut encoder, "main pass", &color_view, &depth_view);
            pass.set_pipeline(&program.main.pipeline);
            for (d, draw) in draws.iter().enumerate() {
                self.draw_mesh(&mut pass, draw.object, &main_groups[d]);
            }
        }

        let (source, w, h, aspect) = match params.view {
            View::ShadowMap => (&shadow_map, n, n, wgpu::TextureAspect::DepthOnly),
            _ => (&color, params.width, params.height, wgpu::TextureAspect::All),
        };
        // 4 bytes per texel for both Rgba8Unorm and Depth32Float, 2 for Depth16Unorm.
        let texel = if params.view == View::ShadowMap && shadow_format == wgpu::TextureFormat::Depth16Unorm { 2 } else { 4 };
        if params.view == View::ShadowMap && shadow_format == wgpu::TextureFormat::Depth24Plus {
            return Err(RenderError::Unsupported("--view shadow-map cannot read back a depth24plus shadow map".into()));
        }
        let row = texel * w;
        let padded_row = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: padded_row as u64 * h as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo { texture: source, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded_row), rows_per_image: Some(h) },
            },
            wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        );
        self.queue.submit([encoder.finish()]);

        let slice = readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| RenderError::Gpu(format!("waiting for the frame: {e}")))?;
        rx.recv()
            .map_err(|_| RenderError::Gpu("the readback was never mapped".into()))?
            .map_err(|e| RenderError::Gpu(format!("mapping the readback: {e}")))?;
        let mapped = slice.get_mapped_range().map_err(|e| RenderError::Gpu(format!("reading the readback: {e}")))?;
        let mut pixels = Vec::with_capacity((row * h) as usize);
        for y in 0..h {
            // Portable conventions render GL's bottom row into row 0: read
            // rows in reverse so the image is top row first.
            let src = if plan.portable { h - 1 - y } else { y };
            let start = (src * padded_row) as usize;
            pixels.extend_from_slice(&mapped[start..start + row as usize]);
        }
        drop(mapped);
        readback.unmap();

        let image = match params.view {
            View::ShadowMap if texel == 2 => {
                let f: Vec<u8> = pixels
                    .chunks_exact(2)
                    .flat_map(|c| (u16::from_le_bytes([c[0], c[1]]) as f32 / 65535.0).to_le_bytes())
                    .collect();
                super::image_ops::depth_to_grey(w, h, &f)
            }
            View::ShadowMap => super::image_ops::depth_to_grey(w, h, &pixels),
            _ => RgbaImage::from_raw(w, h, pixels).expect("readback has w * h * 4 bytes"),
        };
        Ok(image)
    }

    /// Binds `groups` and draws one of the scene's meshes (shared with the
    /// technique scenes, which use the same cube and floor).
    pub(crate) fn draw_mesh(&self, pass: &mut wgpu::RenderPass<'_>, object: Object, groups: &[(u32, wgpu::BindGroup)]) {
        let mesh = match object {
            Object::Cube => &self.cube,
            Object::Floor => &self.floor,
        };
        for (group, bg) in groups {
            pass.set_bind_group(*group, bg, &[]);
        }
        pass.set_vertex_buffer(0, mesh.vertices.slice(..));
        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..mesh.index_count, 0, 0..1);
    }
}

impl Program {
    pub fn via(&self) -> Via {
        self.via
    }
}

impl Renderer {
    /// The shadow pass objects for a depth format: the prepared ones for
    /// Depth32Float, others made once on first use.
    fn shadow_objects(&self, program: &Program, format: wgpu::TextureFormat) -> Arc<PassObjects> {
        let mut cache = program.other_shadow.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, o)) = cache.iter().find(|(f, _)| *f == format) {
            return o.clone();
        }
        let module = |entry: &str| &program.modules[program.entry_module.get(entry).copied().unwrap_or(0)];
        let objects = Arc::new(if format == DEPTH_FORMAT {
            PassObjects { pipeline: program.shadow.pipeline.clone(), layouts: program.shadow.layouts.clone() }
        } else {
            self.pass_objects(&program.plan, &program.plan.shadow, &module, true, format)
        });
        cache.push((format, objects.clone()));
        objects
    }

    /// The comparison sampler a setup's filter and fit want.
    fn compare_sampler(&self, setup: &super::setup::Setup) -> &wgpu::Sampler {
        let linear = setup.shadow.filter.linear();
        // Lookups outside a tight box or a spot light's frustum are lit.
        let border = setup.shadow.fit == super::setup::Fit::Tight || matches!(setup.light, super::setup::Light::Spot { .. });
        self.samplers.get(&(linear, border)).or_else(|| self.samplers.get(&(linear, false))).unwrap_or(&self.sampler)
    }
}

/// The main pass of a frame: colour cleared to the scene's background and
/// stored, depth cleared and discarded afterwards (only the image is read).
pub(crate) fn begin_main_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    color: &wgpu::TextureView,
    depth: &wgpu::TextureView,
) -> wgpu::RenderPass<'e> {
    let c = scene::CLEAR;
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color { r: c[0], g: c[1], b: c[2], a: 1.0 }),
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
            stencil_ops: None,
        }),
        ..Default::default()
    })
}
