//! The GL executor: runs a frame plan with the compiler's GLSL 330 core
//! output on an OpenGL 3.3 core context, or its GLSL ES 3.00 output on an
//! OpenGL ES 3.0 context, both through EGL's surfaceless platform (no
//! window, no display server; on a machine without a GPU, Mesa's
//! llvmpipe).
//!
//! What a program binds comes from [`bind::gl`] (from the manifest), or,
//! for a set without a manifest, from the linked program itself
//! ([`by_name`]: everything looked up by its source name, as GL hosts
//! written for daslang's own generator do). Either way the linked program
//! must agree: a block, sampler, uniform or attribute it lacks, or an
//! attribute at another location, is an error naming it, not a black
//! picture. GL conventions throughout: nothing is flipped on the way in,
//! and rows come back bottom first and are reversed. Every GL object is
//! held by an [`objects::Obj`] and deleted on every path.

mod by_name;
pub mod objects;

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use glow::HasContext;
use image::RgbaImage;
use khronos_egl as egl;

use crate::render::bind::{self, gl::GlProgram, gl::UniformCall};
use crate::render::consumers::Consumer;
use crate::render::plan::{Cull, Format, FramePlan, Geometry, Mesh, Pass, Sampling, Value};
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

/// A program ready to run plans on one GL context.
pub struct GlPrepared {
    set: ShaderSet,
    linked: RefCell<HashMap<(String, String), Rc<Linked>>>,
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

    fn target(&self) -> Target {
        if self.consumer == Consumer::Gl330 {
            Target::Glsl330
        } else {
            Target::Gles300
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
        let (fs_file, fs_text) = set.glsl(&pass.fragment).map_err(ExecError::Program)?;
        let vs = self.compile(glow::VERTEX_SHADER, vs_file, vs_text)?;
        let fs = self.compile(glow::FRAGMENT_SHADER, fs_file, fs_text)?;
        let gl = self.ctx.current()?;
        // SAFETY: program objects and queries on the current context.
        let program = unsafe {
            let program = Obj::new(&self.ctx, gl.create_program().map_err(ExecError::Api)?);
            gl.attach_shader(program.raw(), vs.raw());
            gl.attach_shader(program.raw(), fs.raw());
            gl.link_program(program.raw());
            gl.detach_shader(program.raw(), vs.raw());
            gl.detach_shader(program.raw(), fs.raw());
            if !gl.get_program_link_status(program.raw()) {
                return Err(ExecError::Link { pass: pass.name.clone(), log: gl.get_program_info_log(program.raw()) });
            }
            program
        };
        drop((vs, fs));
        let (binding, what) = match &set.reflection {
            Some(r) => {
                let fit = bind::fit(&set.label, r, plan)?;
                (bind::gl::program(r, &fit.passes[index]), "its reflection")
            }
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
            for u in &binding.uniforms {
                match gl.get_uniform_location(p, &u.glsl_name) {
                    Some(loc) => {
                        uniform_locations.insert(u.glsl_name.clone(), loc);
                    }
                    None => problems.push(format!("uniform `{}` is not in the linked program", u.glsl_name)),
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
                    gl.vertex_attrib_pointer_f32(*loc, field.format.components() as i32, glow::FLOAT, false, m.stride as i32, field.offset as i32);
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

    fn frame(&self, prepared: &GlPrepared, plan: &FramePlan) -> Result<Readback, ExecError> {
        let gl = self.ctx.current()?;
        let es = self.consumer == Consumer::Gles300;
        let obj = |r: Result<glow::Texture, String>| r.map(|t| Obj::new(&self.ctx, t)).map_err(ExecError::Api);
        // SAFETY (whole body): GL calls on the current context with objects
        // made here, each held by an `Obj`; read_pixels fills buffers of the
        // exact size.
        unsafe {
            let mut textures = Vec::new();
            for t in &plan.targets {
                let tex = obj(gl.create_texture())?;
                gl.bind_texture(glow::TEXTURE_2D, Some(tex.raw()));
                let (internal, format, ty) = match t.format {
                    Format::Rgba8 => (glow::RGBA8, glow::RGBA, glow::UNSIGNED_BYTE),
                    Format::Rgba32Uint => (glow::RGBA32UI, glow::RGBA_INTEGER, glow::UNSIGNED_INT),
                    Format::Depth16 => (glow::DEPTH_COMPONENT16, glow::DEPTH_COMPONENT, glow::UNSIGNED_SHORT),
                    Format::Depth24Plus => (glow::DEPTH_COMPONENT24, glow::DEPTH_COMPONENT, glow::UNSIGNED_INT),
                    Format::Depth32Float => (glow::DEPTH_COMPONENT32F, glow::DEPTH_COMPONENT, glow::FLOAT),
                };
                gl.tex_image_2d(glow::TEXTURE_2D, 0, internal as i32, t.width as i32, t.height as i32, 0, format, ty, glow::PixelUnpackData::Slice(None));
                // One level, complete without a sampler object too.
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, 0);
                textures.push(tex);
            }
            gl.bind_texture(glow::TEXTURE_2D, None);
            let framebuffer = |color: Option<usize>, depth: Option<usize>| -> Result<Obj<glow::Framebuffer>, ExecError> {
                let fbo = Obj::new(&self.ctx, gl.create_framebuffer().map_err(ExecError::Api)?);
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo.raw()));
                match color {
                    Some(c) => {
                        gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::TEXTURE_2D, Some(textures[c].raw()), 0);
                        gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
                        gl.read_buffer(glow::COLOR_ATTACHMENT0);
                    }
                    None => {
                        gl.draw_buffers(&[glow::NONE]);
                        gl.read_buffer(glow::NONE);
                    }
                }
                if let Some(d) = depth {
                    gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, Some(textures[d].raw()), 0);
                }
                let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
                if status != glow::FRAMEBUFFER_COMPLETE {
                    return Err(ExecError::Api(format!("incomplete framebuffer {status:#06x}")));
                }
                Ok(fbo)
            };
            gl.disable(glow::BLEND);
            gl.front_face(glow::CCW);
            gl.depth_func(glow::LESS);
            gl.depth_mask(true);
            for (index, pass) in plan.passes.iter().enumerate() {
                let linked = self.linked(prepared, plan, index)?;
                let fbo = framebuffer(pass.color.map(|a| a.target.0), pass.depth.map(|a| a.target.0))?;
                let drawn = pass.color.map(|a| a.target).or(pass.depth.map(|a| a.target)).expect("a pass has an attachment (checked)");
                let (w, h) = (plan.target(drawn).width as i32, plan.target(drawn).height as i32);
                gl.viewport(0, 0, w, h);
                if let Some(c) = pass.color {
                    if plan.target(c.target).format == Format::Rgba32Uint {
                        gl.clear_buffer_u32_slice(glow::COLOR, 0, &c.clear.map(|x| x as u32));
                    } else {
                        gl.clear_color(c.clear[0] as f32, c.clear[1] as f32, c.clear[2] as f32, c.clear[3] as f32);
                        gl.clear(glow::COLOR_BUFFER_BIT);
                    }
                }
                match pass.depth {
                    Some(d) => {
                        gl.enable(glow::DEPTH_TEST);
                        gl.clear_depth_f32(d.clear);
                        gl.clear(glow::DEPTH_BUFFER_BIT);
                    }
                    None => gl.disable(glow::DEPTH_TEST),
                }
                match pass.cull {
                    Cull::None => gl.disable(glow::CULL_FACE),
                    Cull::Front | Cull::Back => {
                        gl.enable(glow::CULL_FACE);
                        gl.cull_face(if pass.cull == Cull::Front { glow::FRONT } else { glow::BACK });
                    }
                }
                if pass.depth_bias {
                    gl.enable(glow::POLYGON_OFFSET_FILL);
                    gl.polygon_offset(2.0, 4.0);
                } else {
                    gl.disable(glow::POLYGON_OFFSET_FILL);
                }
                gl.use_program(Some(linked.program.raw()));
                let units = bind::gl::textures(&linked.binding, pass).map_err(ExecError::Program)?;
                let mut samplers = Vec::new();
                for &(unit, t) in &units {
                    let input = &pass.textures[t];
                    samplers.push(self.sampler(input.sampling, es)?);
                    gl.active_texture(glow::TEXTURE0 + unit);
                    gl.bind_texture(glow::TEXTURE_2D, Some(textures[input.target.0].raw()));
                    gl.bind_sampler(unit, Some(samplers.last().expect("pushed").raw()));
                }
                gl.active_texture(glow::TEXTURE0);
                let mut ubos: HashMap<u32, Obj<glow::Buffer>> = HashMap::new();
                for draw in &pass.draws {
                    let data = bind::gl::draw(&linked.binding, pass, draw, plan.unset).map_err(ExecError::Program)?;
                    for (point, mut bytes) in data.blocks {
                        bytes.resize(linked.block_sizes.get(&point).copied().unwrap_or(0).max(bytes.len()), 0);
                        let ubo = match ubos.get(&point) {
                            Some(b) => b.raw(),
                            None => {
                                let b = Obj::new(&self.ctx, gl.create_buffer().map_err(ExecError::Api)?);
                                let raw = b.raw();
                                ubos.insert(point, b);
                                raw
                            }
                        };
                        gl.bind_buffer(glow::UNIFORM_BUFFER, Some(ubo));
                        gl.buffer_data_u8_slice(glow::UNIFORM_BUFFER, &bytes, glow::DYNAMIC_DRAW);
                        gl.bind_buffer_base(glow::UNIFORM_BUFFER, point, Some(ubo));
                    }
                    for (name, value) in &data.uniforms {
                        set_uniform(gl, linked.uniform_locations.get(name), value);
                    }
                    match draw.geometry {
                        Geometry::Mesh(m) => {
                            let count = self.mesh(m)?.index_count;
                            gl.bind_vertex_array(Some(self.vao(&linked, Some(m))?));
                            gl.draw_elements(glow::TRIANGLES, count, glow::UNSIGNED_INT, 0);
                        }
                        Geometry::Vertices(n) => {
                            gl.bind_vertex_array(Some(self.vao(&linked, None)?));
                            gl.draw_arrays(glow::TRIANGLES, 0, n as i32);
                        }
                    }
                    gl.bind_vertex_array(None);
                }
                for &(unit, _) in &units {
                    gl.active_texture(glow::TEXTURE0 + unit);
                    gl.bind_texture(glow::TEXTURE_2D, None);
                    gl.bind_sampler(unit, None);
                }
                gl.active_texture(glow::TEXTURE0);
                gl.use_program(None);
                gl.bind_buffer(glow::UNIFORM_BUFFER, None);
                drop(fbo);
            }
            gl.disable(glow::POLYGON_OFFSET_FILL);
            gl.disable(glow::CULL_FACE);

            // Read the target back through a framebuffer of its own.
            let t = plan.target(plan.readback);
            let (w, h) = (t.width as i32, t.height as i32);
            let depth = t.format.is_depth();
            let fbo = if depth { framebuffer(None, Some(plan.readback.0))? } else { framebuffer(Some(plan.readback.0), None)? };
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            let (format, ty, texel) = match t.format {
                Format::Rgba8 => (glow::RGBA, glow::UNSIGNED_BYTE, 4),
                Format::Rgba32Uint => (glow::RGBA_INTEGER, glow::UNSIGNED_INT, 16),
                _ => (glow::DEPTH_COMPONENT, glow::FLOAT, 4),
            };
            let mut bytes = vec![0u8; (w * h) as usize * texel];
            gl.read_pixels(0, 0, w, h, format, ty, glow::PixelPackData::Slice(Some(&mut bytes)));
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            drop(fbo);
            // GL returns rows bottom first; pictures are top row first.
            let row = w as usize * texel;
            let bytes: Vec<u8> = bytes.chunks_exact(row).rev().flatten().copied().collect();
            let (w, h) = (w as u32, h as u32);
            Ok(match t.format {
                Format::Rgba8 => Readback::Rgba8(RgbaImage::from_raw(w, h, bytes).expect("w * h * 4 bytes")),
                Format::Rgba32Uint => Readback::Words { width: w, height: h, words: bytemuck::cast_slice(&bytes).to_vec() },
                _ => Readback::Depth { width: w, height: h, depths: bytemuck::cast_slice(&bytes).to_vec() },
            })
        }
    }

    /// A sampler object for `s` (GLES 3.0 has no clamp to border: edge).
    fn sampler(&self, s: Sampling, es: bool) -> Result<Obj<glow::Sampler>, ExecError> {
        let gl = self.ctx.current()?;
        // SAFETY: sampler state on the current context.
        unsafe {
            let sampler = Obj::new(&self.ctx, gl.create_sampler().map_err(ExecError::Api)?);
            let filter = if s.linear { glow::LINEAR } else { glow::NEAREST } as i32;
            let wrap = if s.border && !es { glow::CLAMP_TO_BORDER } else { glow::CLAMP_TO_EDGE } as i32;
            let raw = sampler.raw();
            gl.sampler_parameter_i32(raw, glow::TEXTURE_MIN_FILTER, filter);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_MAG_FILTER, filter);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_WRAP_S, wrap);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_WRAP_T, wrap);
            if s.border && !es {
                gl.sampler_parameter_f32_slice(raw, glow::TEXTURE_BORDER_COLOR, &[1.0; 4]);
            }
            if s.compare {
                gl.sampler_parameter_i32(raw, glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE as i32);
                gl.sampler_parameter_i32(raw, glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL as i32);
            }
            Ok(sampler)
        }
    }
}

fn problems_error(set: &ShaderSet, pass: &Pass, what: &str, problems: Vec<String>) -> ExecError {
    ExecError::Program(format!("the {} pass of {} does not match {what}:\n  - {}", pass.name, set.label, problems.join("\n  - ")))
}

/// `glUniform*` for a value at `loc` (none: the program does not use it).
unsafe fn set_uniform(gl: &glow::Context, loc: Option<&glow::UniformLocation>, v: &Value) {
    let f = v.as_f32();
    let i: Vec<i32> = v.words.iter().map(|w| *w as i32).collect();
    let u = &v.words;
    // SAFETY: uniform calls on the current context with the program in use.
    unsafe {
        match UniformCall::of(v) {
            UniformCall::Float(1) => gl.uniform_1_f32_slice(loc, &f),
            UniformCall::Float(2) => gl.uniform_2_f32_slice(loc, &f),
            UniformCall::Float(3) => gl.uniform_3_f32_slice(loc, &f),
            UniformCall::Float(_) => gl.uniform_4_f32_slice(loc, &f),
            UniformCall::Int(1) => gl.uniform_1_i32_slice(loc, &i),
            UniformCall::Int(2) => gl.uniform_2_i32_slice(loc, &i),
            UniformCall::Int(3) => gl.uniform_3_i32_slice(loc, &i),
            UniformCall::Int(_) => gl.uniform_4_i32_slice(loc, &i),
            UniformCall::Uint(1) => gl.uniform_1_u32_slice(loc, u),
            UniformCall::Uint(2) => gl.uniform_2_u32_slice(loc, u),
            UniformCall::Uint(3) => gl.uniform_3_u32_slice(loc, u),
            UniformCall::Uint(_) => gl.uniform_4_u32_slice(loc, u),
            UniformCall::Matrix { columns, rows } => match (columns, rows) {
                (2, 2) => gl.uniform_matrix_2_f32_slice(loc, false, &f),
                (2, 3) => gl.uniform_matrix_2x3_f32_slice(loc, false, &f),
                (2, 4) => gl.uniform_matrix_2x4_f32_slice(loc, false, &f),
                (3, 2) => gl.uniform_matrix_3x2_f32_slice(loc, false, &f),
                (3, 3) => gl.uniform_matrix_3_f32_slice(loc, false, &f),
                (3, 4) => gl.uniform_matrix_3x4_f32_slice(loc, false, &f),
                (4, 2) => gl.uniform_matrix_4x2_f32_slice(loc, false, &f),
                (4, 3) => gl.uniform_matrix_4x3_f32_slice(loc, false, &f),
                _ => gl.uniform_matrix_4_f32_slice(loc, false, &f),
            },
        }
    }
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
