//! The GL consumer: the compiler's GLSL 330 core output on an OpenGL 3.3
//! core context and its GLSL ES 3.00 output on a GLES 3.0 context, both
//! through EGL's surfaceless platform (no window, no display server; on a
//! machine without a GPU, Mesa's llvmpipe).
//!
//! The host does what docs/targets.md asks of a GL host and nothing more:
//! uniform blocks are bound by their GLSL block names
//! (`glGetUniformBlockIndex` + `glUniformBlockBinding`), the shadow sampler
//! by its GLSL name (`glGetUniformLocation` + `glUniform1i` with the texture
//! unit the reflection gives), attributes at the reflection's locations
//! (checked against `glGetAttribLocation`), uniform buffers filled at the
//! reflection's offsets. Everything comes from the reflection through
//! [`interface::plan`], as for the wgpu runner. The GL state is the
//! tutorial's: a DEPTH_COMPONENT32F shadow texture with
//! COMPARE_REF_TO_TEXTURE, LEQUAL, linear filtering and clamp to edge, a
//! depth-only framebuffer with draw buffer NONE, polygon offset 2.0 / 4.0,
//! depth test LESS, no culling, an RGBA8 colour framebuffer read back with
//! glReadPixels. GL conventions throughout: no y flip anywhere, rows come
//! back bottom first and are reversed into a top-first image.

use std::collections::BTreeSet;

use glow::HasContext;
use image::RgbaImage;
use khronos_egl as egl;

use super::glsl_set::GlslSet;
use super::interface::{self, InterfaceError, PassPlan, Plan, ResourceKind};
use super::scene::{self, Frame, FrameParams, Object, View};
use crate::Target;

/// Which GL profile (and which of the compiler's GLSL outputs) to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlApi {
    /// OpenGL 3.3 core, running the `.330.*` files.
    Gl330,
    /// OpenGL ES 3.0, running the `.300es.*` files.
    Gles300,
}

impl GlApi {
    pub fn name(self) -> &'static str {
        match self {
            GlApi::Gl330 => "gl330",
            GlApi::Gles300 => "gles300",
        }
    }

    /// The compiler target whose files this profile runs.
    pub fn target(self) -> Target {
        match self {
            GlApi::Gl330 => Target::Glsl330,
            GlApi::Gles300 => Target::Gles300,
        }
    }

    pub fn install_hint() -> &'static str {
        "on Debian/Ubuntu: `apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri libgles2` (Mesa's EGL and llvmpipe; no GPU needed)"
    }
}

/// What can stop a GL render.
#[derive(Clone, Debug)]
pub enum GlError {
    /// No EGL library, display or context for the profile.
    Unavailable(String),
    /// A shader did not compile: the driver's log.
    Compile { file: String, log: String },
    /// A program did not link: the driver's log.
    Link { pass: String, log: String },
    /// The program does not fit the scene, or the linked program does not
    /// match its reflection.
    Interface(String),
    /// A GL error or an incomplete framebuffer.
    Gl(String),
    Unsupported(String),
}

impl std::fmt::Display for GlError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GlError::Unavailable(m) => write!(f, "{m}; {}", GlApi::install_hint()),
            GlError::Compile { file, log } => write!(f, "{file} does not compile: {}", log.trim_end()),
            GlError::Link { pass, log } => write!(f, "the {pass} pass's program does not link: {}", log.trim_end()),
            GlError::Interface(m) | GlError::Gl(m) | GlError::Unsupported(m) => write!(f, "{}", m.trim_end()),
        }
    }
}

impl std::error::Error for GlError {}

impl From<InterfaceError> for GlError {
    fn from(e: InterfaceError) -> Self {
        GlError::Interface(e.to_string())
    }
}

const EGL_PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

type Egl = egl::DynamicInstance<egl::EGL1_5>;

struct GlMesh {
    vertices: glow::Buffer,
    indices: glow::Buffer,
    index_count: i32,
}

/// An EGL context of one profile, with the scene's meshes uploaded.
/// Every call makes its context current on the calling thread first.
pub struct GlRenderer {
    api: GlApi,
    egl: Egl,
    display: egl::Display,
    context: egl::Context,
    gl: glow::Context,
    version: String,
    renderer: String,
    cube: GlMesh,
    floor: GlMesh,
}

struct PassProgram {
    program: glow::Program,
    /// Plan block indices this pass's program uses (each bound at binding
    /// point = its index).
    blocks: Vec<usize>,
    /// The texture unit of the shadow sampler, when the pass samples it.
    shadow_unit: Option<u32>,
    /// One vertex array per object: cube, floor.
    vaos: [glow::VertexArray; 2],
}

/// A linked program pair, bound to the scene.
pub struct GlProgram {
    pub plan: Plan,
    shadow: PassProgram,
    main: PassProgram,
    /// One uniform buffer per plan block.
    ubos: Vec<glow::Buffer>,
    /// Size of each buffer: the reflection's block size, or the driver's
    /// if larger.
    ubo_sizes: Vec<usize>,
}

impl GlRenderer {
    /// Opens an EGL surfaceless context of `api` (OpenGL 3.3 core, or
    /// OpenGL ES 3.0) and uploads the meshes.
    pub fn new(api: GlApi) -> Result<GlRenderer, GlError> {
        // SAFETY: loading the system's libEGL; its symbols are the EGL API.
        let egl = unsafe { Egl::load_required() }
            .map_err(|e| GlError::Unavailable(format!("cannot load libEGL.so.1 with EGL 1.5 ({e})")))?;
        // SAFETY: the surfaceless platform takes no native display.
        let display = unsafe { egl.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, egl::DEFAULT_DISPLAY, &[egl::ATTRIB_NONE]) }
            .map_err(|e| GlError::Unavailable(format!("no EGL surfaceless display (EGL_PLATFORM_SURFACELESS_MESA): {e}")))?;
        egl.initialize(display).map_err(|e| GlError::Unavailable(format!("eglInitialize failed: {e}")))?;
        let (bind, renderable, context_attribs) = match api {
            GlApi::Gl330 => (
                egl::OPENGL_API,
                egl::OPENGL_BIT,
                vec![
                    egl::CONTEXT_MAJOR_VERSION,
                    3,
                    egl::CONTEXT_MINOR_VERSION,
                    3,
                    egl::CONTEXT_OPENGL_PROFILE_MASK,
                    egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
                    egl::NONE,
                ],
            ),
            GlApi::Gles300 => (
                egl::OPENGL_ES_API,
                egl::OPENGL_ES3_BIT,
                vec![egl::CONTEXT_MAJOR_VERSION, 3, egl::CONTEXT_MINOR_VERSION, 0, egl::NONE],
            ),
        };
        egl.bind_api(bind).map_err(|e| GlError::Unavailable(format!("eglBindAPI for {} failed: {e}", api.name())))?;
        let config = egl
            .choose_first_config(display, &[egl::RENDERABLE_TYPE, renderable, egl::SURFACE_TYPE, egl::PBUFFER_BIT, egl::NONE])
            .map_err(|e| GlError::Unavailable(format!("eglChooseConfig failed: {e}")))?
            .ok_or_else(|| GlError::Unavailable(format!("no EGL config renders {}", api.name())))?;
        let context = egl
            .create_context(display, config, None, &context_attribs)
            .map_err(|e| GlError::Unavailable(format!("no {} context: {e}", api.name())))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| GlError::Unavailable(format!("cannot make the {} context current without a surface: {e}", api.name())))?;
        // SAFETY: the context is current; the loader returns its entry points.
        let gl = unsafe {
            glow::Context::from_loader_function(|name| egl.get_proc_address(name).map_or(std::ptr::null(), |p| p as *const _))
        };
        // SAFETY: plain queries and uploads on the current context.
        let (version, renderer, cube, floor) = unsafe {
            let version = gl.get_parameter_string(glow::VERSION);
            let renderer = gl.get_parameter_string(glow::RENDERER);
            let upload = |mesh: scene::Mesh| -> Result<GlMesh, GlError> {
                let vertices = gl.create_buffer().map_err(GlError::Gl)?;
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(vertices));
                gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&mesh.vertices), glow::STATIC_DRAW);
                let indices = gl.create_buffer().map_err(GlError::Gl)?;
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(indices));
                gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&mesh.indices), glow::STATIC_DRAW);
                gl.bind_buffer(glow::ARRAY_BUFFER, None);
                Ok(GlMesh { vertices, indices, index_count: mesh.indices.len() as i32 })
            };
            (version, renderer, upload(scene::cube_mesh())?, upload(scene::floor_mesh())?)
        };
        let r = GlRenderer { api, egl, display, context, gl, version, renderer, cube, floor };
        r.check("creating the context")?;
        Ok(r)
    }

    pub fn api(&self) -> GlApi {
        self.api
    }

    /// The driver's renderer and version strings, e.g.
    /// `llvmpipe (LLVM 15.0.6, 256 bits), OpenGL ES 3.2 Mesa 22.3.6`.
    pub fn adapter_name(&self) -> String {
        format!("{}, {}", self.renderer, self.version)
    }

    /// The context, made current on this thread, for hosts of other scenes
    /// (`render::techniques`).
    pub fn context(&self) -> Result<&glow::Context, GlError> {
        self.current()?;
        Ok(&self.gl)
    }

    fn current(&self) -> Result<(), GlError> {
        self.egl
            .make_current(self.display, None, None, Some(self.context))
            .map_err(|e| GlError::Gl(format!("eglMakeCurrent: {e}")))
    }

    fn check(&self, what: &str) -> Result<(), GlError> {
        // SAFETY: glGetError on the current context.
        let mut errors = Vec::new();
        loop {
            let e = unsafe { self.gl.get_error() };
            if e == glow::NO_ERROR || errors.len() > 8 {
                break;
            }
            errors.push(format!("{e:#06x}"));
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(GlError::Gl(format!("GL error {} while {what}", errors.join(", "))))
        }
    }

    /// Renders one frame: [`prepare`](Self::prepare) then [`draw`](Self::draw).
    pub fn render(&self, set: &GlslSet, params: &FrameParams) -> Result<RgbaImage, GlError> {
        let program = self.prepare(set)?;
        let image = self.draw(&program, params);
        self.release(program);
        image
    }

    /// Compiles and links both passes' programs and binds their uniform
    /// blocks, sampler and attributes by the reflection's names.
    pub fn prepare(&self, set: &GlslSet) -> Result<GlProgram, GlError> {
        if set.target != self.api.target() {
            return Err(GlError::Unsupported(format!(
                "{}: {} sources cannot run on a {} context",
                set.label,
                set.target.name(),
                self.api.name()
            )));
        }
        self.current()?;
        let plan = interface::plan(&set.label, &set.reflection)?;
        let shadow = self.link_pass(set, &plan, &plan.shadow, "shadow")?;
        let main = match self.link_pass(set, &plan, &plan.main, "main") {
            Ok(m) => m,
            Err(e) => {
                self.release_pass(&shadow);
                return Err(e);
            }
        };
        // SAFETY: buffer creation and queries on the current context.
        let mut ubos = Vec::new();
        let mut ubo_sizes = Vec::new();
        for (i, block) in plan.blocks.iter().enumerate() {
            let mut size = block.size as usize;
            for pass in [&shadow, &main] {
                if pass.blocks.contains(&i) {
                    let glsl = &set.reflection.uniform_blocks[i].glsl_block;
                    let index = unsafe { self.gl.get_uniform_block_index(pass.program, glsl) }.expect("found when linking");
                    let driver = unsafe {
                        self.gl.get_active_uniform_block_parameter_i32(pass.program, index, glow::UNIFORM_BLOCK_DATA_SIZE)
                    };
                    size = size.max(driver.max(0) as usize);
                }
            }
            let ubo = unsafe { self.gl.create_buffer() }.map_err(GlError::Gl)?;
            unsafe {
                self.gl.bind_buffer(glow::UNIFORM_BUFFER, Some(ubo));
                self.gl.buffer_data_size(glow::UNIFORM_BUFFER, size as i32, glow::DYNAMIC_DRAW);
                self.gl.bind_buffer(glow::UNIFORM_BUFFER, None);
            }
            ubos.push(ubo);
            ubo_sizes.push(size);
        }
        self.check("preparing the program")?;
        Ok(GlProgram { plan, shadow, main, ubos, ubo_sizes })
    }

    /// Frees a program's GL objects.
    pub fn release(&self, program: GlProgram) {
        if self.current().is_err() {
            return;
        }
        self.release_pass(&program.shadow);
        self.release_pass(&program.main);
        // SAFETY: deleting objects this context created.
        unsafe {
            for b in program.ubos {
                self.gl.delete_buffer(b);
            }
        }
    }

    fn release_pass(&self, pass: &PassProgram) {
        // SAFETY: deleting objects this context created.
        unsafe {
            self.gl.delete_program(pass.program);
            for v in pass.vaos {
                self.gl.delete_vertex_array(v);
            }
        }
    }

    fn compile(&self, stage: u32, file: &str, source: &str) -> Result<glow::Shader, GlError> {
        // SAFETY: shader objects on the current context.
        unsafe {
            let shader = self.gl.create_shader(stage).map_err(GlError::Gl)?;
            self.gl.shader_source(shader, source);
            self.gl.compile_shader(shader);
            if !self.gl.get_shader_compile_status(shader) {
                let log = self.gl.get_shader_info_log(shader);
                self.gl.delete_shader(shader);
                return Err(GlError::Compile { file: file.to_string(), log });
            }
            Ok(shader)
        }
    }

    fn link_pass(&self, set: &GlslSet, plan: &Plan, pass: &PassPlan, label: &str) -> Result<PassProgram, GlError> {
        let (vs_file, vs_text) = set.entry(&pass.vertex_entry).map_err(GlError::Interface)?;
        let (fs_file, fs_text) = set.entry(&pass.fragment_entry).map_err(GlError::Interface)?;
        let vs = self.compile(glow::VERTEX_SHADER, vs_file, vs_text)?;
        let fs = match self.compile(glow::FRAGMENT_SHADER, fs_file, fs_text) {
            Ok(fs) => fs,
            Err(e) => {
                // SAFETY: deleting the shader made above.
                unsafe { self.gl.delete_shader(vs) };
                return Err(e);
            }
        };
        let gl = &self.gl;
        // SAFETY: program objects and queries on the current context.
        unsafe {
            let program = gl.create_program().map_err(GlError::Gl)?;
            gl.attach_shader(program, vs);
            gl.attach_shader(program, fs);
            gl.link_program(program);
            let linked = gl.get_program_link_status(program);
            gl.detach_shader(program, vs);
            gl.detach_shader(program, fs);
            gl.delete_shader(vs);
            gl.delete_shader(fs);
            if !linked {
                let log = gl.get_program_info_log(program);
                gl.delete_program(program);
                return Err(GlError::Link { pass: label.to_string(), log });
            }
            let mut problems = Vec::new();
            let r = &set.reflection;
            // Uniform blocks and the sampler this pass uses, as the plan
            // (from the reflection's per-entry-point lists) says.
            let mut blocks = BTreeSet::new();
            let mut samples_shadow = false;
            for entry in pass.groups.values().flatten() {
                match entry.kind {
                    ResourceKind::Uniform(i) => {
                        blocks.insert(i);
                    }
                    ResourceKind::ShadowTexture | ResourceKind::ShadowSampler => samples_shadow = true,
                }
            }
            gl.use_program(Some(program));
            for &i in &blocks {
                let glsl = &r.uniform_blocks[i].glsl_block;
                match gl.get_uniform_block_index(program, glsl) {
                    Some(index) => gl.uniform_block_binding(program, index, i as u32),
                    None => problems.push(format!("uniform block `{glsl}` (for `{}`) is not in the linked program", r.uniform_blocks[i].name)),
                }
            }
            let mut shadow_unit = None;
            if samples_shadow {
                for s in &r.samplers {
                    match gl.get_uniform_location(program, &s.glsl_name) {
                        Some(loc) => {
                            gl.uniform_1_i32(Some(&loc), s.texture_unit as i32);
                            shadow_unit = Some(s.texture_unit);
                        }
                        None => problems.push(format!("sampler `{}` is not in the linked program", s.glsl_name)),
                    }
                }
            }
            gl.use_program(None);
            let vertex = r.entry_points.iter().find(|e| e.name == pass.vertex_entry).expect("the plan found it");
            for a in &pass.attributes {
                let glsl = vertex.inputs.iter().find(|i| i.name == a.name).map_or(a.name.as_str(), |i| i.glsl_name.as_str());
                match gl.get_attrib_location(program, glsl) {
                    Some(loc) if loc == a.location => {}
                    Some(loc) => problems.push(format!(
                        "attribute `{glsl}` is at location {loc} in the linked program, {} in the reflection",
                        a.location
                    )),
                    None => problems.push(format!("attribute `{glsl}` is not in the linked program")),
                }
            }
            if !problems.is_empty() {
                gl.delete_program(program);
                return Err(GlError::Interface(format!(
                    "the {label} pass of {} does not match its reflection:\n  - {}",
                    plan.program,
                    problems.join("\n  - ")
                )));
            }
            let mut vaos = Vec::new();
            for mesh in [&self.cube, &self.floor] {
                let vao = gl.create_vertex_array().map_err(GlError::Gl)?;
                gl.bind_vertex_array(Some(vao));
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(mesh.vertices));
                gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(mesh.indices));
                for a in &pass.attributes {
                    gl.enable_vertex_attrib_array(a.location);
                    gl.vertex_attrib_pointer_f32(a.location, 3, glow::FLOAT, false, scene::VERTEX_STRIDE as i32, a.offset as i32);
                }
                gl.bind_vertex_array(None);
                gl.bind_buffer(glow::ARRAY_BUFFER, None);
                vaos.push(vao);
            }
            let vaos = [vaos[0], vaos[1]];
            Ok(PassProgram { program, blocks: blocks.into_iter().collect(), shadow_unit, vaos })
        }
    }

    /// Draws one frame and reads it back, top row first.
    pub fn draw(&self, program: &GlProgram, params: &FrameParams) -> Result<RgbaImage, GlError> {
        if params.width == 0 || params.height == 0 || params.shadow_size == 0 {
            return Err(GlError::Unsupported("every size must be at least 1".into()));
        }
        if params.view == View::ShadowMap && self.api == GlApi::Gles300 {
            return Err(GlError::Unsupported("--view shadow-map reads depth back, which OpenGL ES cannot (glReadPixels of DEPTH_COMPONENT)".into()));
        }
        self.current()?;
        // SAFETY: GL calls on the current context with objects it created;
        // read_pixels writes into a buffer of exactly w * h * 4 bytes.
        let result = unsafe { self.frame(program, params) };
        self.check("drawing")?;
        result
    }

    unsafe fn frame(&self, program: &GlProgram, params: &FrameParams) -> Result<RgbaImage, GlError> {
        let gl = &self.gl;
        let frame = Frame::of(params);
        let draws = frame.draws();
        let n = params.shadow_size as i32;
        let (w, h) = (params.width as i32, params.height as i32);

        // The shadow map: a depth texture sampled with hardware compare.
        let shadow_tex = gl.create_texture().map_err(GlError::Gl)?;
        gl.bind_texture(glow::TEXTURE_2D, Some(shadow_tex));
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            glow::DEPTH_COMPONENT32F as i32,
            n,
            n,
            0,
            glow::DEPTH_COMPONENT,
            glow::FLOAT,
            glow::PixelUnpackData::Slice(None),
        );
        for (p, v) in [
            (glow::TEXTURE_MIN_FILTER, glow::LINEAR),
            (glow::TEXTURE_MAG_FILTER, glow::LINEAR),
            (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
            (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
            (glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE),
            (glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL),
        ] {
            gl.tex_parameter_i32(glow::TEXTURE_2D, p, v as i32);
        }
        gl.bind_texture(glow::TEXTURE_2D, None);
        let shadow_fbo = gl.create_framebuffer().map_err(GlError::Gl)?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(shadow_fbo));
        gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, Some(shadow_tex), 0);
        gl.draw_buffers(&[glow::NONE]);
        gl.read_buffer(glow::NONE);
        let shadow_status = gl.check_framebuffer_status(glow::FRAMEBUFFER);

        // The main pass's target: RGBA8 colour and a 32-bit float depth buffer.
        let color_rb = gl.create_renderbuffer().map_err(GlError::Gl)?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color_rb));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA8, w, h);
        let depth_rb = gl.create_renderbuffer().map_err(GlError::Gl)?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth_rb));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT32F, w, h);
        gl.bind_renderbuffer(glow::RENDERBUFFER, None);
        let color_fbo = gl.create_framebuffer().map_err(GlError::Gl)?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(color_fbo));
        gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::RENDERBUFFER, Some(color_rb));
        gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::RENDERBUFFER, Some(depth_rb));
        let color_status = gl.check_framebuffer_status(glow::FRAMEBUFFER);

        let cleanup = || {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.delete_framebuffer(shadow_fbo);
            gl.delete_framebuffer(color_fbo);
            gl.delete_renderbuffer(color_rb);
            gl.delete_renderbuffer(depth_rb);
            gl.delete_texture(shadow_tex);
        };
        if shadow_status != glow::FRAMEBUFFER_COMPLETE || color_status != glow::FRAMEBUFFER_COMPLETE {
            cleanup();
            return Err(GlError::Gl(format!(
                "incomplete framebuffer (shadow {shadow_status:#06x}, colour {color_status:#06x})"
            )));
        }

        let bind_blocks = |pass: &PassProgram, d: usize| {
            for &i in &pass.blocks {
                let mut bytes = program.plan.blocks[i].bytes(&frame, &draws[d]);
                bytes.resize(program.ubo_sizes[i].max(bytes.len()), 0);
                gl.bind_buffer(glow::UNIFORM_BUFFER, Some(program.ubos[i]));
                gl.buffer_sub_data_u8_slice(glow::UNIFORM_BUFFER, 0, &bytes);
                gl.bind_buffer_base(glow::UNIFORM_BUFFER, i as u32, Some(program.ubos[i]));
            }
        };
        let draw_mesh = |pass: &PassProgram, object: Object| {
            let (vao, mesh) = match object {
                Object::Cube => (pass.vaos[0], &self.cube),
                Object::Floor => (pass.vaos[1], &self.floor),
            };
            gl.bind_vertex_array(Some(vao));
            gl.draw_elements(glow::TRIANGLES, mesh.index_count, glow::UNSIGNED_INT, 0);
            gl.bind_vertex_array(None);
        };

        gl.disable(glow::CULL_FACE);
        gl.disable(glow::BLEND);
        gl.enable(glow::DEPTH_TEST);
        gl.depth_func(glow::LESS);
        gl.depth_mask(true);

        // Pass 1: depth from the sun.
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(shadow_fbo));
        gl.viewport(0, 0, n, n);
        gl.clear_depth_f32(1.0);
        gl.clear(glow::DEPTH_BUFFER_BIT);
        if params.view != View::Lit {
            gl.enable(glow::POLYGON_OFFSET_FILL);
            gl.polygon_offset(2.0, 4.0);
            gl.use_program(Some(program.shadow.program));
            for (d, draw) in draws.iter().enumerate() {
                bind_blocks(&program.shadow, d);
                draw_mesh(&program.shadow, draw.object);
            }
            gl.disable(glow::POLYGON_OFFSET_FILL);
        }

        let pixels = if params.view == View::ShadowMap {
            // Desktop GL only (checked above): read the depth texels.
            let mut depth = vec![0u8; (n * n * 4) as usize];
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(0, 0, n, n, glow::DEPTH_COMPONENT, glow::FLOAT, glow::PixelPackData::Slice(Some(&mut depth)));
            flip_rows(&depth, n as usize * 4)
        } else {
            // Pass 2: the lit scene.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(color_fbo));
            gl.viewport(0, 0, w, h);
            let c = scene::CLEAR;
            gl.clear_color(c[0] as f32, c[1] as f32, c[2] as f32, 1.0);
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            gl.use_program(Some(program.main.program));
            if let Some(unit) = program.main.shadow_unit {
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(glow::TEXTURE_2D, Some(shadow_tex));
            }
            for (d, draw) in draws.iter().enumerate() {
                bind_blocks(&program.main, d);
                draw_mesh(&program.main, draw.object);
            }
            if let Some(unit) = program.main.shadow_unit {
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(glow::TEXTURE_2D, None);
                gl.active_texture(glow::TEXTURE0);
            }
            let mut rgba = vec![0u8; (w * h * 4) as usize];
            gl.read_buffer(glow::COLOR_ATTACHMENT0);
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(0, 0, w, h, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelPackData::Slice(Some(&mut rgba)));
            flip_rows(&rgba, w as usize * 4)
        };
        gl.use_program(None);
        cleanup();
        Ok(match params.view {
            View::ShadowMap => super::image_ops::depth_to_grey(n as u32, n as u32, &pixels),
            _ => RgbaImage::from_raw(w as u32, h as u32, pixels).expect("w * h * 4 bytes"),
        })
    }
}

/// GL returns rows bottom first; images are top row first.
fn flip_rows(bytes: &[u8], row: usize) -> Vec<u8> {
    bytes.chunks_exact(row).rev().flatten().copied().collect()
}

impl Drop for GlRenderer {
    fn drop(&mut self) {
        if self.current().is_ok() {
            // SAFETY: deleting the meshes this context created.
            unsafe {
                for m in [&self.cube, &self.floor] {
                    self.gl.delete_buffer(m.vertices);
                    self.gl.delete_buffer(m.indices);
                }
            }
        }
        // The display is shared by every context of this process (wgpu's GL
        // backend included), so it is not terminated.
        let _ = self.egl.make_current(self.display, None, None, None);
        let _ = self.egl.destroy_context(self.display, self.context);
    }
}
