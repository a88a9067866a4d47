//! The GL executor: runs a frame plan with the compiler's GLSL 330 core
//! output on an OpenGL 3.3 core context, or its GLSL ES 3.00 output on an
//! OpenGL ES 3.0 context, both through EGL's surfaceless platform (no
//! window, no display server; on a machine without a GPU, Mesa's
//! llvmpipe).
//!
//! What a program binds comes from [`bind::gl`] (from the manifest), or,
//! for a set without a manifest, from the linked program itself
//! (`by_name`: everything looked up by its source name, as GL hosts
//! written for daslang's own generator do). Either way the linked program
//! must agree: a block, sampler, uniform or attribute it lacks, or an
//! attribute at another location, is an error naming it, not a black
//! picture. GL conventions throughout: nothing is flipped on the way in,
//! and rows come back bottom first and are reversed. Every GL object is
//! held by an [`objects::Obj`] and deleted on every path.

mod by_name;
mod compute;
mod frame;
pub mod probe;
pub mod objects;

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use glow::HasContext;
use khronos_egl as egl;

use crate::render::bind::{self, gl::GlProgram};
use crate::render::consumer::Consumer;
use crate::render::plan::{FramePlan, Mesh, Pass};
use crate::render::program::ShaderSet;
use crate::Target;

use super::{ExecError, Executor, Readback};
use objects::Obj;

/// How to install what the GL consumers need.
pub const INSTALL_HINT: &str =
    "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri libgles2 (Mesa's EGL and llvmpipe; no GPU needed)";

const EGL_PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

type Egl = egl::DynamicInstance<egl::EGL1_5>;

/// An EGL context and its GL functions. Every use makes it current on the
/// calling thread first.
pub struct Context {
    egl: Egl,
    display: egl::Display,
    context: egl::Context,
    gl: glow::Context,
}

impl Context {
    /// The GL functions, with this context current.
    pub fn current(&self) -> Result<&glow::Context, ExecError> {
        if self.egl.get_current_context() == Some(self.context) {
            return Ok(&self.gl);
        }
        self.egl
            .make_current(self.display, None, None, Some(self.context))
            .map_err(|e| ExecError::Api(format!("eglMakeCurrent: {e}")))?;
        Ok(&self.gl)
    }

    /// Drains GL errors; any is an error saying `what` was going on.
    fn check(&self, what: &str) -> Result<(), ExecError> {
        let gl = self.current()?;
        let mut errors = Vec::new();
        loop {
            // SAFETY: glGetError on the current context.
            let e = unsafe { gl.get_error() };
            if e == glow::NO_ERROR || errors.len() > 8 {
                break;
            }
            errors.push(format!("{e:#06x}"));
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(ExecError::Api(format!("GL error {} while {what}", errors.join(", "))))
        }
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        // The display is shared by every context of this process (wgpu's GL
        // backend included), so it is not terminated.
        let _ = self.egl.make_current(self.display, None, None, None);
        let _ = self.egl.destroy_context(self.display, self.context);
    }
}

struct GlMesh {
    vertices: Obj<glow::Buffer>,
    indices: Obj<glow::Buffer>,
    index_count: i32,
}

/// One GL context of one profile, with the meshes plans use.
pub struct GlExecutor {
    consumer: Consumer,
    ctx: Rc<Context>,
    version: String,
    renderer: String,
    meshes: RefCell<Vec<(usize, Rc<GlMesh>)>>,
}

/// A linked program of one pass shape, with what it binds.
struct Linked {
    program: Obj<glow::Program>,
    binding: GlProgram,
    /// Size of each block's buffer by binding point: the layout's, or the
    /// driver's `GL_UNIFORM_BLOCK_DATA_SIZE` if larger.
    block_sizes: HashMap<u32, usize>,
    uniform_locations: HashMap<String, glow::UniformLocation>,
    /// Attribute locations as linked, with their mesh field.
    attributes: Vec<(u32, crate::render::plan::Field)>,
    /// One vertex array per mesh (by address), and one with no buffers.
    vaos: RefCell<Vec<(usize, Obj<glow::VertexArray>)>>,
}

/// A pass's vertex entry point and its fragment one (none: vertex-only).
type StagePair = (String, Option<String>);

/// A program ready to run plans on one GL context.
pub struct GlPrepared {
    set: ShaderSet,
    linked: RefCell<HashMap<StagePair, Rc<Linked>>>,
}

impl GlExecutor {
    /// Opens an EGL surfaceless context for `consumer`: an OpenGL 3.3
    /// core context for [`Consumer::Gl330`], an OpenGL ES 3.0 context for
    /// [`Consumer::Gles300`].
    pub fn new(consumer: Consumer) -> Result<GlExecutor, ExecError> {
        let (api, renderable, attribs) = match consumer {
            Consumer::Gl330 => (
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
            Consumer::Gles300 => (egl::OPENGL_ES_API, egl::OPENGL_ES3_BIT, vec![egl::CONTEXT_MAJOR_VERSION, 3, egl::CONTEXT_MINOR_VERSION, 0, egl::NONE]),
            // Compute, storage buffers and images (`compute.rs`).
            Consumer::Gl430 => (
                egl::OPENGL_API,
                egl::OPENGL_BIT,
                vec![
                    egl::CONTEXT_MAJOR_VERSION,
                    4,
                    egl::CONTEXT_MINOR_VERSION,
                    3,
                    egl::CONTEXT_OPENGL_PROFILE_MASK,
                    egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
                    egl::NONE,
                ],
            ),
            Consumer::Gles310 => (egl::OPENGL_ES_API, egl::OPENGL_ES3_BIT, vec![egl::CONTEXT_MAJOR_VERSION, 3, egl::CONTEXT_MINOR_VERSION, 1, egl::NONE]),
            other => return Err(ExecError::Unsupported(format!("{} is not a GL context consumer", other.name()))),
        };
        let unavailable = |why: String| ExecError::Unavailable { consumer, why, install: INSTALL_HINT.into() };
        let name = consumer.name();
        // SAFETY: loading the system's libEGL; its symbols are the EGL API.
        let egl = unsafe { Egl::load_required() }.map_err(|e| unavailable(format!("cannot load libEGL.so.1 with EGL 1.5 ({e})")))?;
        // SAFETY: the surfaceless platform takes no native display.
        let display = unsafe { egl.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, egl::DEFAULT_DISPLAY, &[egl::ATTRIB_NONE]) }
            .map_err(|e| unavailable(format!("no EGL surfaceless display (EGL_PLATFORM_SURFACELESS_MESA): {e}")))?;
        egl.initialize(display).map_err(|e| unavailable(format!("eglInitialize failed: {e}")))?;
        egl.bind_api(api).map_err(|e| unavailable(format!("eglBindAPI for {name} failed: {e}")))?;
        let config = egl
            .choose_first_config(display, &[egl::RENDERABLE_TYPE, renderable, egl::SURFACE_TYPE, egl::PBUFFER_BIT, egl::NONE])
            .map_err(|e| unavailable(format!("eglChooseConfig failed: {e}")))?
            .ok_or_else(|| unavailable(format!("no EGL config renders {name}")))?;
        let context = egl.create_context(display, config, None, &attribs).map_err(|e| unavailable(format!("no {name} context: {e}")))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| unavailable(format!("cannot make the {name} context current without a surface: {e}")))?;
        // SAFETY: the context is current; the loader returns its entry points.
        let gl = unsafe { glow::Context::from_loader_function(|n| egl.get_proc_address(n).map_or(std::ptr::null(), |p| p as *const _)) };
        let ctx = Rc::new(Context { egl, display, context, gl });
        let gl = ctx.current()?;
        // SAFETY: plain queries on the current context.
        let (version, renderer) = unsafe { (gl.get_parameter_string(glow::VERSION), gl.get_parameter_string(glow::RENDERER)) };
        ctx.check("creating the context")?;
        Ok(GlExecutor { consumer, ctx, version, renderer, meshes: RefCell::default() })
    }

    pub fn consumer(&self) -> Consumer {
        self.consumer
    }

    /// The driver's renderer and version strings, e.g.
    /// `llvmpipe (LLVM 15.0.6, 256 bits), OpenGL ES 3.2 Mesa 22.3.6`.
    pub fn adapter_name(&self) -> String {
        format!("{}, {}", self.renderer, self.version)
    }

    /// Whether the context has GL_KHR_shader_subgroup (what the GLSL 430
    /// files of a program with subgroup operations require).
    pub fn supports_subgroups(&self) -> Result<bool, ExecError> {
        let gl = self.ctx.current()?;
        Ok(gl.supported_extensions().contains("GL_KHR_shader_subgroup"))
    }

    /// The driver's limits that umbrac's device limits stand for
    /// (`emit::limits`), by their GL names, as this context reports them.
    pub fn reported_limits(&self) -> Result<Vec<(&'static str, i32)>, ExecError> {
        let es = matches!(self.consumer, Consumer::Gles300 | Consumer::Gles310);
        let mut names = vec![
            ("GL_MAX_VERTEX_ATTRIBS", glow::MAX_VERTEX_ATTRIBS),
            ("GL_MAX_VERTEX_UNIFORM_COMPONENTS", glow::MAX_VERTEX_UNIFORM_COMPONENTS),
            ("GL_MAX_FRAGMENT_UNIFORM_COMPONENTS", glow::MAX_FRAGMENT_UNIFORM_COMPONENTS),
            ("GL_MAX_VARYING_COMPONENTS", glow::MAX_VARYING_COMPONENTS),
            ("GL_MAX_VERTEX_UNIFORM_BLOCKS", glow::MAX_VERTEX_UNIFORM_BLOCKS),
            ("GL_MAX_FRAGMENT_UNIFORM_BLOCKS", glow::MAX_FRAGMENT_UNIFORM_BLOCKS),
            ("GL_MAX_COMBINED_UNIFORM_BLOCKS", glow::MAX_COMBINED_UNIFORM_BLOCKS),
            ("GL_MAX_UNIFORM_BLOCK_SIZE", glow::MAX_UNIFORM_BLOCK_SIZE),
            ("GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS", glow::MAX_VERTEX_TEXTURE_IMAGE_UNITS),
            ("GL_MAX_TEXTURE_IMAGE_UNITS", glow::MAX_TEXTURE_IMAGE_UNITS),
            ("GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS", glow::MAX_COMBINED_TEXTURE_IMAGE_UNITS),
            ("GL_MAX_DRAW_BUFFERS", glow::MAX_DRAW_BUFFERS),
        ];
        if es {
            // GLES states uniforms and varyings in vectors too.
            names.extend([
                ("GL_MAX_VERTEX_UNIFORM_VECTORS", glow::MAX_VERTEX_UNIFORM_VECTORS),
                ("GL_MAX_FRAGMENT_UNIFORM_VECTORS", glow::MAX_FRAGMENT_UNIFORM_VECTORS),
                ("GL_MAX_VARYING_VECTORS", glow::MAX_VARYING_VECTORS),
            ]);
        }
        let gl = self.ctx.current()?;
        // SAFETY: plain queries on the current context.
        let values = names.into_iter().map(|(name, pname)| (name, unsafe { gl.get_parameter_i32(pname) })).collect();
        self.ctx.check("querying limits")?;
        Ok(values)
    }

    /// Compiles and links a vertex and a fragment shader (file name, text),
    /// nothing more: whether the driver takes the pair within its limits.
    pub fn link(&self, vertex: (&str, &str), fragment: (&str, &str)) -> Result<(), ExecError> {
        let vs = self.compile(glow::VERTEX_SHADER, vertex.0, vertex.1)?;
        let fs = self.compile(glow::FRAGMENT_SHADER, fragment.0, fragment.1)?;
        let gl = self.ctx.current()?;
        // SAFETY: a program object on the current context.
        unsafe {
            let program = Obj::new(&self.ctx, gl.create_program().map_err(ExecError::Api)?);
            gl.attach_shader(program.raw(), vs.raw());
            gl.attach_shader(program.raw(), fs.raw());
            gl.link_program(program.raw());
            if !gl.get_program_link_status(program.raw()) {
                return Err(ExecError::Link { pass: format!("{} + {}", vertex.0, fragment.0), log: gl.get_program_info_log(program.raw()) });
            }
        }
        self.ctx.check("linking")
    }

    fn target(&self) -> Target {
        match self.consumer {
            Consumer::Gl330 => Target::Glsl330,
            Consumer::Gl430 => Target::Glsl430,
            Consumer::Gles310 => Target::Gles310,
            _ => Target::Gles300,
        }
    }

    fn mesh(&self, mesh: &'static Mesh) -> Result<Rc<GlMesh>, ExecError> {
        let key = mesh as *const Mesh as usize;
        if let Some((_, m)) = self.meshes.borrow().iter().find(|(k, _)| *k == key) {
            return Ok(m.clone());
        }
        let gl = self.ctx.current()?;
        // SAFETY: buffer uploads on the current context.
        let m = unsafe {
            let vertices = Obj::new(&self.ctx, gl.create_buffer().map_err(ExecError::Api)?);
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vertices.raw()));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &mesh.vertices, glow::STATIC_DRAW);
            let indices = Obj::new(&self.ctx, gl.create_buffer().map_err(ExecError::Api)?);
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(indices.raw()));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&mesh.indices), glow::STATIC_DRAW);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            Rc::new(GlMesh { vertices, indices, index_count: mesh.indices.len() as i32 })
        };
        self.meshes.borrow_mut().push((key, m.clone()));
        Ok(m)
    }

    fn compile(&self, stage: u32, file: &str, source: &str) -> Result<Obj<glow::Shader>, ExecError> {
        let gl = self.ctx.current()?;
        // SAFETY: shader objects on the current context.
        unsafe {
            let shader = Obj::new(&self.ctx, gl.create_shader(stage).map_err(ExecError::Api)?);
            gl.shader_source(shader.raw(), source);
            gl.compile_shader(shader.raw());
            if !gl.get_shader_compile_status(shader.raw()) {
                return Err(ExecError::Compile { file: file.to_string(), log: gl.get_shader_info_log(shader.raw()) });
            }
            Ok(shader)
        }
    }

    /// Links the program of `pass` (once per vertex / fragment pair) and
    /// binds what it binds.
    fn linked(&self, prepared: &GlPrepared, plan: &FramePlan, index: usize) -> Result<Rc<Linked>, ExecError> {
        let pass = &plan.passes[index];
        let key = (pass.vertex.clone(), pass.fragment.clone());
        if let Some(l) = prepared.linked.borrow().get(&key) {
            return Ok(l.clone());
        }
        let set = &prepared.set;
        let (vs_file, vs_text) = set.glsl(&pass.vertex).map_err(ExecError::Program)?;
        let (fs_file, fs_text) = set.glsl_fragment(pass.fragment.as_deref(), vs_text).map_err(ExecError::Program)?;
        let vs = self.compile(glow::VERTEX_SHADER, vs_file, vs_text)?;
        let fs = self.compile(glow::FRAGMENT_SHADER, &fs_file, &fs_text)?;
        // With a manifest, what the program binds is known before linking:
        // attributes and colour outputs are bound to its locations then.
        let from_manifest = match &set.reflection {
            Some(r) => {
                let fit = bind::fit(&set.label, r, plan)?;
                Some(bind::gl::program(r, &fit.passes[index]))
            }
            None => None,
        };
        let gl = self.ctx.current()?;
        // SAFETY: program objects and queries on the current context.
        let program = unsafe {
            let program = Obj::new(&self.ctx, gl.create_program().map_err(ExecError::Api)?);
            gl.attach_shader(program.raw(), vs.raw());
            gl.attach_shader(program.raw(), fs.raw());
            if let Some(b) = &from_manifest {
                for a in &b.attributes {
                    if let Some(location) = a.location {
                        gl.bind_attrib_location(program.raw(), location, &a.glsl_name);
                    }
                }
                // GLES has no glBindFragDataLocation: its outputs carry layout locations.
                if self.consumer != Consumer::Gles300 {
                    for (name, location) in &b.outputs {
                        gl.bind_frag_data_location(program.raw(), *location, name);
                    }
                }
            }
            gl.link_program(program.raw());
            gl.detach_shader(program.raw(), vs.raw());
            gl.detach_shader(program.raw(), fs.raw());
            if !gl.get_program_link_status(program.raw()) {
                return Err(ExecError::Link { pass: pass.name.clone(), log: gl.get_program_info_log(program.raw()) });
            }
            program
        };
        drop((vs, fs));
        let (binding, what) = match from_manifest {
            Some(b) => (b, "its reflection"),
            // SAFETY: queries of the linked program on the current context.
            None => (unsafe { by_name::interface(gl, program.raw(), plan, pass) }.map_err(|problems| problems_error(set, pass, "the scene", problems))?, "the scene"),
        };
        let linked = self.bind(program, binding).map_err(|problems| problems_error(set, pass, what, problems))?;
        let linked = Rc::new(linked);
        prepared.linked.borrow_mut().insert(key, linked.clone());
        self.ctx.check("linking")?;
        Ok(linked)
    }

    /// Binds blocks to their points and samplers to their units, and finds
    /// every uniform and attribute, listing what the program lacks.
    fn bind(&self, program: Obj<glow::Program>, binding: GlProgram) -> Result<Linked, Vec<String>> {
        let gl = self.ctx.current().map_err(|e| vec![e.to_string()])?;
        let p = program.raw();
        let mut problems = Vec::new();
        let mut block_sizes = HashMap::new();
        // SAFETY (whole block): calls on the current context with `p`, linked.
        unsafe {
            gl.use_program(Some(p));
            for b in &binding.blocks {
                match gl.get_uniform_block_index(p, &b.glsl_name) {
                    Some(index) => {
                        gl.uniform_block_binding(p, index, b.point);
                        let driver = gl.get_active_uniform_block_parameter_i32(p, index, glow::UNIFORM_BLOCK_DATA_SIZE);
                        block_sizes.insert(b.point, (b.layout.size as usize).max(driver.max(0) as usize));
                    }
                    None => problems.push(format!("uniform block `{}` is not in the linked program", b.glsl_name)),
                }
            }
            for s in &binding.samplers {
                match gl.get_uniform_location(p, &s.glsl_name) {
                    Some(loc) => gl.uniform_1_i32(Some(&loc), s.unit as i32),
                    None => problems.push(format!("sampler `{}` is not in the linked program", s.glsl_name)),
                }
            }
            let mut uniform_locations = HashMap::new();
            // A driver may drop a uniform the program does not need: one
            // the linked program lacks is set nowhere, not an error.
            for u in &binding.uniforms {
                if let Some(loc) = gl.get_uniform_location(p, &u.glsl_name) {
                    uniform_locations.insert(u.glsl_name.clone(), loc);
                }
            }
            gl.use_program(None);
            let mut attributes = Vec::new();
            for a in &binding.attributes {
                match (gl.get_attrib_location(p, &a.glsl_name), a.location) {
                    (Some(loc), Some(want)) if loc != want => {
                        problems.push(format!("attribute `{}` is at location {loc} in the linked program, {want} in the reflection", a.glsl_name))
                    }
                    (Some(loc), _) => attributes.push((loc, a.field.clone())),
                    (None, _) => problems.push(format!("attribute `{}` is not in the linked program", a.glsl_name)),
                }
            }
            if !problems.is_empty() {
                return Err(problems);
            }
            Ok(Linked { program, binding, block_sizes, uniform_locations, attributes, vaos: RefCell::default() })
        }
    }

    /// The vertex array of `linked` for a mesh (or none), made once.
    fn vao(&self, linked: &Linked, mesh: Option<&'static Mesh>) -> Result<glow::VertexArray, ExecError> {
        let key = mesh.map_or(0, |m| m as *const Mesh as usize);
        if let Some((_, v)) = linked.vaos.borrow().iter().find(|(k, _)| *k == key) {
            return Ok(v.raw());
        }
        let buffers = mesh.map(|m| self.mesh(m)).transpose()?;
        let gl = self.ctx.current()?;
        // SAFETY: vertex array setup on the current context.
        let vao = unsafe {
            let vao = Obj::new(&self.ctx, gl.create_vertex_array().map_err(ExecError::Api)?);
            gl.bind_vertex_array(Some(vao.raw()));
            if let (Some(m), Some(b)) = (mesh, &buffers) {
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(b.vertices.raw()));
                gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(b.indices.raw()));
                for (loc, field) in &linked.attributes {
                    gl.enable_vertex_attrib_array(*loc);
                    // Instance records follow the vertices in the same buffer.
                    let (stride, offset, divisor) = match m.instances.filter(|_| field.per_instance) {
                        Some(i) => (i.stride, i.base + field.offset, 1),
                        None => (m.stride, field.offset, 0),
                    };
                    gl.vertex_attrib_pointer_f32(*loc, field.format.components() as i32, glow::FLOAT, false, stride as i32, offset as i32);
                    gl.vertex_attrib_divisor(*loc, divisor);
                }
            }
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            vao
        };
        let raw = vao.raw();
        linked.vaos.borrow_mut().push((key, vao));
        Ok(raw)
    }
}

fn problems_error(set: &ShaderSet, pass: &Pass, what: &str, problems: Vec<String>) -> ExecError {
    ExecError::Program(format!("the {} pass of {} does not match {what}:\n  - {}", pass.name, set.label, problems.join("\n  - ")))
}

impl Executor for GlExecutor {
    type Prepared = GlPrepared;

    fn prepare(&self, set: &ShaderSet, plan: &FramePlan) -> Result<GlPrepared, ExecError> {
        if set.target != self.target() {
            return Err(ExecError::Unsupported(format!(
                "{}: {} sources cannot run on a {} context",
                set.label,
                set.target.name(),
                self.consumer.name()
            )));
        }
        if let Some(r) = &set.reflection {
            bind::fit(&set.label, r, plan)?;
        }
        let prepared = GlPrepared { set: set.clone(), linked: RefCell::default() };
        for (i, pass) in plan.passes.iter().enumerate() {
            let linked = self.linked(&prepared, plan, i)?;
            // Every draw's values fit what the program binds.
            for draw in &pass.draws {
                bind::gl::draw(&linked.binding, pass, draw, plan.unset).map_err(|e| problems_error(set, pass, "the scene", vec![e]))?;
            }
            bind::gl::textures(&linked.binding, pass).map_err(|e| problems_error(set, pass, "the scene", vec![e]))?;
        }
        Ok(prepared)
    }

    fn run(&self, prepared: &GlPrepared, plan: &FramePlan) -> Result<Readback, ExecError> {
        let gl = self.ctx.current()?;
        // SAFETY: a query on the current context.
        let max = unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_SIZE) }.max(1) as u32;
        super::check_sizes(plan, max)?;
        if self.consumer == Consumer::Gles300 && plan.target(plan.readback).format.is_depth() {
            return Err(ExecError::Unsupported("depth cannot be read back on OpenGL ES (glReadPixels of DEPTH_COMPONENT): no --view shadow-map on gles300".into()));
        }
        let result = self.frame(prepared, plan);
        self.ctx.check("drawing")?;
        result
    }

    fn device_name(&self) -> String {
        self.adapter_name()
    }
}
