//! Drawing one frame of a plan on a GL context: the targets as textures,
//! a framebuffer per pass, the pass's state, textures on their units
//! through sampler objects, each draw's blocks and uniforms, and the
//! read-back target through a framebuffer of its own. Every object is an
//! [`Obj`], deleted when the frame ends, however it ends.

use std::collections::hash_map::Entry;
use std::collections::HashMap;

use glow::HasContext;
use image::RgbaImage;

use crate::render::bind::{self, gl::UniformCall};
use crate::render::consumer::Consumer;
use crate::render::plan::{Cull, Dim, Format, FramePlan, Geometry, Sampling, TargetId, Value};

use super::objects::Obj;
use super::{ExecError, GlExecutor, GlPrepared, Readback};

/// (internal format, format, type, bytes per texel) of a target format.
fn texel_format(f: Format) -> (u32, u32, u32, usize) {
    match f {
        Format::Rgba8 => (glow::RGBA8, glow::RGBA, glow::UNSIGNED_BYTE, 4),
        Format::Rgba32Uint => (glow::RGBA32UI, glow::RGBA_INTEGER, glow::UNSIGNED_INT, 16),
        Format::Depth16 => (glow::DEPTH_COMPONENT16, glow::DEPTH_COMPONENT, glow::UNSIGNED_SHORT, 2),
        Format::Depth24Plus => (glow::DEPTH_COMPONENT24, glow::DEPTH_COMPONENT, glow::UNSIGNED_INT, 4),
        Format::Depth32Float => (glow::DEPTH_COMPONENT32F, glow::DEPTH_COMPONENT, glow::FLOAT, 4),
    }
}

impl GlExecutor {
    pub(super) fn frame(&self, prepared: &GlPrepared, plan: &FramePlan) -> Result<Readback, ExecError> {
        let textures = self.targets(plan)?;
        // Vulkan-dialect code keeps its picture's top in row 0 on GL too:
        // GL sees it upside down, its counter-clockwise fronts clockwise.
        let top_first = prepared.set.reflection.as_ref().is_some_and(|r| bind::is_vulkan(r, plan));
        let gl = self.ctx.current()?;
        // SAFETY: state calls on the current context.
        unsafe {
            gl.disable(glow::BLEND);
            // As GLES, WebGL2 and Vulkan always are: cube maps filter across faces.
            if matches!(self.consumer, Consumer::Gl330 | Consumer::Gl430) {
                gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
                // A point's size is its gl_PointSize (always so on ES).
                gl.enable(glow::PROGRAM_POINT_SIZE);
            }
            gl.front_face(if top_first { glow::CW } else { glow::CCW });
            gl.depth_func(glow::LESS);
            gl.depth_mask(true);
        }
        for index in 0..plan.passes.len() {
            self.pass(prepared, plan, index, &textures)?;
        }
        // SAFETY: state calls on the current context.
        unsafe {
            gl.disable(glow::POLYGON_OFFSET_FILL);
            gl.disable(glow::CULL_FACE);
        }
        self.read_back(plan, &textures, top_first)
    }

    /// Every target of the plan as a one-level texture.
    fn targets(&self, plan: &FramePlan) -> Result<Vec<Obj<glow::Texture>>, ExecError> {
        let gl = self.ctx.current()?;
        let mut textures = Vec::new();
        for t in &plan.targets {
            let (internal, format, ty, _) = texel_format(t.format);
            let target = gl_target(t.dim);
            // SAFETY: texture storage on the current context.
            unsafe {
                let tex = Obj::new(&self.ctx, gl.create_texture().map_err(ExecError::Api)?);
                gl.bind_texture(target, Some(tex.raw()));
                gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                let (w, h) = (t.width as i32, t.height as i32);
                match t.dim {
                    Dim::D2 => gl.tex_image_2d(target, 0, internal as i32, w, h, 0, format, ty, glow::PixelUnpackData::Slice(t.contents.as_deref())),
                    Dim::Cube => {
                        let face = (t.width * t.height * 4) as usize;
                        for f in 0..6 {
                            let data = t.contents.as_deref().map(|c| &c[f * face..(f + 1) * face]);
                            gl.tex_image_2d(glow::TEXTURE_CUBE_MAP_POSITIVE_X + f as u32, 0, internal as i32, w, h, 0, format, ty, glow::PixelUnpackData::Slice(data));
                        }
                    }
                    Dim::D3(n) | Dim::D2Array(n) => {
                        gl.tex_image_3d(target, 0, internal as i32, w, h, n as i32, 0, format, ty, glow::PixelUnpackData::Slice(t.contents.as_deref()))
                    }
                }
                // One level: complete without a sampler object too.
                gl.tex_parameter_i32(target, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
                gl.tex_parameter_i32(target, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
                gl.tex_parameter_i32(target, glow::TEXTURE_MAX_LEVEL, 0);
                gl.bind_texture(target, None);
                textures.push(tex);
            }
        }
        Ok(textures)
    }

    /// A framebuffer drawing into `color` and / or `depth`, bound.
    fn framebuffer(&self, textures: &[Obj<glow::Texture>], colors: &[TargetId], depth: Option<TargetId>) -> Result<Obj<glow::Framebuffer>, ExecError> {
        let gl = self.ctx.current()?;
        // SAFETY: framebuffer setup on the current context with its textures.
        unsafe {
            let fbo = Obj::new(&self.ctx, gl.create_framebuffer().map_err(ExecError::Api)?);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo.raw()));
            // Output location i draws into attachment i.
            let buffers: Vec<u32> = (0..colors.len() as u32).map(|i| glow::COLOR_ATTACHMENT0 + i).collect();
            for (&b, c) in buffers.iter().zip(colors) {
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, b, glow::TEXTURE_2D, Some(textures[c.0].raw()), 0);
            }
            if buffers.is_empty() {
                gl.draw_buffers(&[glow::NONE]);
                gl.read_buffer(glow::NONE);
            } else {
                gl.draw_buffers(&buffers);
                gl.read_buffer(glow::COLOR_ATTACHMENT0);
            }
            if let Some(d) = depth {
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, Some(textures[d.0].raw()), 0);
            }
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            if status != glow::FRAMEBUFFER_COMPLETE {
                return Err(ExecError::Api(format!("incomplete framebuffer {status:#06x}")));
            }
            Ok(fbo)
        }
    }

    /// Pass `index`: clears, state, textures, every draw.
    fn pass(&self, prepared: &GlPrepared, plan: &FramePlan, index: usize, textures: &[Obj<glow::Texture>]) -> Result<(), ExecError> {
        let pass = &plan.passes[index];
        let linked = self.linked(prepared, plan, index)?;
        let units = bind::gl::textures(&linked.binding, pass).map_err(ExecError::Program)?;
        let samplers = units.iter().map(|&(_, t)| self.sampler(pass.textures[t].sampling)).collect::<Result<Vec<_>, _>>()?;
        let colors: Vec<TargetId> = pass.colors().map(|a| a.target).collect();
        let _fbo = self.framebuffer(textures, &colors, pass.depth.map(|a| a.target))?;
        let drawn = plan.target(pass.color.map(|a| a.target).or(pass.depth.map(|a| a.target)).expect("a pass has an attachment (checked)"));
        let gl = self.ctx.current()?;
        // SAFETY (whole block): GL calls on the current context with objects
        // made here or held by `linked` and the executor.
        unsafe {
            gl.viewport(0, 0, drawn.width as i32, drawn.height as i32);
            for (i, c) in pass.colors().enumerate() {
                if plan.target(c.target).format == Format::Rgba32Uint {
                    gl.clear_buffer_u32_slice(glow::COLOR, i as u32, &c.clear.map(|x| x as u32));
                } else {
                    gl.clear_buffer_f32_slice(glow::COLOR, i as u32, &c.clear.map(|x| x as f32));
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
            for (&(unit, t), sampler) in units.iter().zip(&samplers) {
                gl.active_texture(glow::TEXTURE0 + unit);
                let target = pass.textures[t].target;
                gl.bind_texture(gl_target(plan.target(target).dim), Some(textures[target.0].raw()));
                gl.bind_sampler(unit, Some(sampler.raw()));
            }
            gl.active_texture(glow::TEXTURE0);
            // The draws; whatever happens, the state is reset below.
            let mut ubos: HashMap<u32, Obj<glow::Buffer>> = HashMap::new();
            let mut draws = || -> Result<(), ExecError> {
                for draw in &pass.draws {
                    let data = bind::gl::draw(&linked.binding, pass, draw, plan.unset).map_err(ExecError::Program)?;
                    for (point, mut bytes) in data.blocks {
                        bytes.resize(linked.block_sizes.get(&point).copied().unwrap_or(0).max(bytes.len()), 0);
                        if let Entry::Vacant(slot) = ubos.entry(point) {
                            slot.insert(Obj::new(&self.ctx, gl.create_buffer().map_err(ExecError::Api)?));
                        }
                        let ubo = ubos[&point].raw();
                        gl.bind_buffer(glow::UNIFORM_BUFFER, Some(ubo));
                        gl.buffer_data_u8_slice(glow::UNIFORM_BUFFER, &bytes, glow::DYNAMIC_DRAW);
                        gl.bind_buffer_base(glow::UNIFORM_BUFFER, point, Some(ubo));
                    }
                    for (name, value) in &data.uniforms {
                        set_uniform(gl, linked.uniform_locations.get(name), value);
                    }
                    let (mesh, count) = match draw.geometry {
                        Geometry::Mesh(m) => (Some(m), self.mesh(m)?.index_count),
                        Geometry::Vertices(n) => (None, n as i32),
                    };
                    gl.bind_vertex_array(Some(self.vao(&linked, mesh)?));
                    let mode = if mesh.is_some_and(|m| m.points) { glow::POINTS } else { glow::TRIANGLES };
                    if let Some(i) = mesh.and_then(|m| m.instances) {
                        gl.draw_elements_instanced(mode, count, glow::UNSIGNED_INT, 0, i.count as i32);
                    } else if mesh.is_some() {
                        gl.draw_elements(mode, count, glow::UNSIGNED_INT, 0);
                    } else {
                        gl.draw_arrays(glow::TRIANGLES, 0, count);
                    }
                    gl.bind_vertex_array(None);
                }
                Ok(())
            };
            let result = draws();
            gl.bind_vertex_array(None);
            for &(unit, t) in &units {
                gl.active_texture(glow::TEXTURE0 + unit);
                gl.bind_texture(gl_target(plan.target(pass.textures[t].target).dim), None);
                gl.bind_sampler(unit, None);
            }
            gl.active_texture(glow::TEXTURE0);
            gl.use_program(None);
            gl.bind_buffer(glow::UNIFORM_BUFFER, None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            result
        }
    }

    /// The read-back target's texels, top row first (`top_first`: memory
    /// row 0 is already the picture's top).
    fn read_back(&self, plan: &FramePlan, textures: &[Obj<glow::Texture>], top_first: bool) -> Result<Readback, ExecError> {
        let t = plan.target(plan.readback);
        let depth = t.format.is_depth();
        let _fbo = if depth { self.framebuffer(textures, &[], Some(plan.readback))? } else { self.framebuffer(textures, &[plan.readback], None)? };
        let (w, h) = (t.width, t.height);
        let (format, ty, texel) = match t.format {
            Format::Rgba8 => (glow::RGBA, glow::UNSIGNED_BYTE, 4),
            Format::Rgba32Uint => (glow::RGBA_INTEGER, glow::UNSIGNED_INT, 16),
            _ => (glow::DEPTH_COMPONENT, glow::FLOAT, 4),
        };
        let mut bytes = vec![0u8; (w * h) as usize * texel];
        let gl = self.ctx.current()?;
        // SAFETY: `bytes` holds exactly w * h texels of the format read.
        unsafe {
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(0, 0, w as i32, h as i32, format, ty, glow::PixelPackData::Slice(Some(&mut bytes)));
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
        // GL returns rows bottom first; GL-dialect pictures are top row first.
        let bytes: Vec<u8> = if top_first { bytes } else { bytes.chunks_exact(w as usize * texel).rev().flatten().copied().collect() };
        Ok(match t.format {
            Format::Rgba8 => Readback::Rgba8(RgbaImage::from_raw(w, h, bytes).expect("w * h * 4 bytes")),
            Format::Rgba32Uint => Readback::Words { width: w, height: h, words: bytemuck::cast_slice(&bytes).to_vec() },
            _ => Readback::Depth { width: w, height: h, depths: bytemuck::cast_slice(&bytes).to_vec() },
        })
    }

    /// A sampler object for `s` (OpenGL ES 3.0 and 3.1 have no clamp to border: edge).
    fn sampler(&self, s: Sampling) -> Result<Obj<glow::Sampler>, ExecError> {
        let border = s.border && matches!(self.consumer, Consumer::Gl330 | Consumer::Gl430);
        let gl = self.ctx.current()?;
        // SAFETY: sampler state on the current context.
        unsafe {
            let sampler = Obj::new(&self.ctx, gl.create_sampler().map_err(ExecError::Api)?);
            let raw = sampler.raw();
            let filter = if s.linear { glow::LINEAR } else { glow::NEAREST } as i32;
            let wrap = if border {
                glow::CLAMP_TO_BORDER
            } else if s.repeat {
                glow::REPEAT
            } else {
                glow::CLAMP_TO_EDGE
            } as i32;
            gl.sampler_parameter_i32(raw, glow::TEXTURE_MIN_FILTER, filter);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_MAG_FILTER, filter);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_WRAP_S, wrap);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_WRAP_T, wrap);
            gl.sampler_parameter_i32(raw, glow::TEXTURE_WRAP_R, wrap);
            if border {
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

/// The GL texture target of a plan texture's kind.
fn gl_target(dim: Dim) -> u32 {
    match dim {
        Dim::D2 => glow::TEXTURE_2D,
        Dim::Cube => glow::TEXTURE_CUBE_MAP,
        Dim::D3(_) => glow::TEXTURE_3D,
        Dim::D2Array(_) => glow::TEXTURE_2D_ARRAY,
    }
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

