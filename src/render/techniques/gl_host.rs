//! The technique scenes on the GL consumer (OpenGL 3.3 core or ES 3.0
//! through EGL, [`GlRenderer`]'s context): the compiler's GLSL with the
//! reflection's block names, sampler names, texture units and attribute
//! locations, and the GL state each technique needs (front-face culling,
//! polygon offset, depth textures with or without compare mode, an RGBA8
//! colour target for encoded depth).

use glow::HasContext;
use image::RgbaImage;

use crate::emit::reflect_types::Reflection;
use crate::render::gl::GlRenderer;
use crate::render::glsl_set::GlslSet;
use crate::render::scene::{self, FrameParams, Object};

use super::{block_bytes, entry, sampler_layer, ShadowTarget, TechFrame, Technique, DRAWS, PASSES};

struct Pass {
    program: glow::Program,
    /// Reflection block indices (bound at binding point = index).
    blocks: Vec<usize>,
    /// (texture unit, shadow layer, comparison) per sampler it reads.
    textures: Vec<(u32, usize, bool)>,
    vaos: [glow::VertexArray; 2],
}

/// A technique's linked programs on one GL context.
pub struct GlTechProgram {
    pub technique: Technique,
    reflection: Reflection,
    passes: [Pass; 2],
    ubos: Vec<(glow::Buffer, usize)>,
    meshes: Vec<(glow::Buffer, glow::Buffer, i32)>,
}

fn gl_err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// Compiles and links both passes and binds them by the reflection.
pub fn prepare(r: &GlRenderer, technique: Technique, compiled: &crate::Compiled) -> Result<GlTechProgram, String> {
    let set = GlslSet::from_compiled(technique.name(), compiled, r.api().target())?;
    let gl = r.context().map_err(gl_err)?;
    let refl = &set.reflection;
    // SAFETY: GL calls on the current context with objects it creates.
    unsafe {
        let mut meshes = Vec::new();
        for m in [scene::cube_mesh(), scene::floor_mesh()] {
            let vb = gl.create_buffer()?;
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vb));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&m.vertices), glow::STATIC_DRAW);
            let ib = gl.create_buffer()?;
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(ib));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&m.indices), glow::STATIC_DRAW);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            meshes.push((vb, ib, m.indices.len() as i32));
        }
        let mut passes = Vec::new();
        for (vs, fs) in PASSES {
            let mut shaders = Vec::new();
            for (stage, name) in [(glow::VERTEX_SHADER, vs), (glow::FRAGMENT_SHADER, fs)] {
                let (file, text) = set.entry(name)?;
                let s = gl.create_shader(stage)?;
                gl.shader_source(s, text);
                gl.compile_shader(s);
                if !gl.get_shader_compile_status(s) {
                    return Err(format!("{file} does not compile: {}", gl.get_shader_info_log(s)));
                }
                shaders.push(s);
            }
            let program = gl.create_program()?;
            for &s in &shaders {
                gl.attach_shader(program, s);
            }
            gl.link_program(program);
            for s in shaders {
                gl.detach_shader(program, s);
                gl.delete_shader(s);
            }
            if !gl.get_program_link_status(program) {
                return Err(format!("{vs} + {fs} do not link: {}", gl.get_program_info_log(program)));
            }
            let (v, f) = (entry(refl, vs)?, entry(refl, fs)?);
            gl.use_program(Some(program));
            let mut blocks = Vec::new();
            let mut textures = Vec::new();
            for e in [v, f] {
                for name in &e.uniform_blocks {
                    let i = refl.uniform_blocks.iter().position(|b| &b.name == name).ok_or("undeclared block")?;
                    if blocks.contains(&i) {
                        continue;
                    }
                    let glsl = &refl.uniform_blocks[i].glsl_block;
                    let index = gl.get_uniform_block_index(program, glsl).ok_or_else(|| format!("block `{glsl}` is not in the linked program"))?;
                    gl.uniform_block_binding(program, index, i as u32);
                    blocks.push(i);
                }
                for name in &e.samplers {
                    let s = refl.samplers.iter().find(|s| &s.name == name).ok_or("undeclared sampler")?;
                    let loc = gl
                        .get_uniform_location(program, &s.glsl_name)
                        .ok_or_else(|| format!("sampler `{}` is not in the linked program", s.glsl_name))?;
                    gl.uniform_1_i32(Some(&loc), s.texture_unit as i32);
                    textures.push((s.texture_unit, sampler_layer(s), s.comparison));
                }
            }
            gl.use_program(None);
            let mut vaos = Vec::new();
            for &(vb, ib, _) in &meshes {
                let vao = gl.create_vertex_array()?;
                gl.bind_vertex_array(Some(vao));
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(vb));
                gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ib));
                for input in &v.inputs {
                    let offset = scene::attribute_offset(&input.name).ok_or_else(|| format!("vertex input `{}` is not in the meshes", input.name))?;
                    gl.enable_vertex_attrib_array(input.location);
                    gl.vertex_attrib_pointer_f32(input.location, 3, glow::FLOAT, false, scene::VERTEX_STRIDE as i32, offset as i32);
                }
                gl.bind_vertex_array(None);
                vaos.push(vao);
            }
            passes.push(Pass { program, blocks, textures, vaos: [vaos[0], vaos[1]] });
        }
        let mut ubos = Vec::new();
        for b in &refl.uniform_blocks {
            let ubo = gl.create_buffer()?;
            let size = (b.size as usize).max(16);
            gl.bind_buffer(glow::UNIFORM_BUFFER, Some(ubo));
            gl.buffer_data_size(glow::UNIFORM_BUFFER, size as i32, glow::DYNAMIC_DRAW);
            ubos.push((ubo, size));
        }
        gl.bind_buffer(glow::UNIFORM_BUFFER, None);
        let main = passes.pop().expect("two");
        let shadow = passes.pop().expect("two");
        check(gl, "preparing")?;
        Ok(GlTechProgram { technique, reflection: set.reflection.clone(), passes: [shadow, main], ubos, meshes })
    }
}

fn check(gl: &glow::Context, what: &str) -> Result<(), String> {
    // SAFETY: glGetError on the current context.
    let e = unsafe { gl.get_error() };
    if e == glow::NO_ERROR {
        Ok(())
    } else {
        Err(format!("GL error {e:#06x} while {what}"))
    }
}

/// Frees a program's objects.
pub fn release(r: &GlRenderer, p: GlTechProgram) {
    let Ok(gl) = r.context() else { return };
    // SAFETY: deleting objects this context created.
    unsafe {
        for pass in &p.passes {
            gl.delete_program(pass.program);
            for v in pass.vaos {
                gl.delete_vertex_array(v);
            }
        }
        for (b, _) in p.ubos {
            gl.delete_buffer(b);
        }
        for (v, i, _) in p.meshes {
            gl.delete_buffer(v);
            gl.delete_buffer(i);
        }
    }
}

/// Draws one frame and reads it back, top row first.
pub fn draw(r: &GlRenderer, p: &GlTechProgram, params: &FrameParams) -> Result<RgbaImage, String> {
    let gl = r.context().map_err(gl_err)?;
    // SAFETY: GL calls on the current context; read_pixels fills w * h * 4 bytes.
    let image = unsafe { frame(gl, p, params) };
    check(gl, "drawing")?;
    image
}

unsafe fn frame(gl: &glow::Context, p: &GlTechProgram, params: &FrameParams) -> Result<RgbaImage, String> {
    let t = p.technique;
    let tf = TechFrame::new(t, params);
    let n = params.shadow_size as i32;
    let (w, h) = (params.width as i32, params.height as i32);
    let rgba = t.target() == ShadowTarget::Rgba8;
    // Each layer's map: compare mode when a comparison sampler reads it.
    let mut maps = Vec::new();
    let mut fbos = Vec::new();
    let map_depth = gl.create_renderbuffer()?;
    gl.bind_renderbuffer(glow::RENDERBUFFER, Some(map_depth));
    gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT32F, n, n);
    for layer in 0..t.layers() {
        let compare = p.passes[1].textures.iter().any(|&(_, l, c)| l == layer && c);
        let tex = gl.create_texture()?;
        gl.bind_texture(glow::TEXTURE_2D, Some(tex));
        if rgba {
            gl.tex_image_2d(glow::TEXTURE_2D, 0, glow::RGBA8 as i32, n, n, 0, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelUnpackData::Slice(None));
        } else {
            gl.tex_image_2d(glow::TEXTURE_2D, 0, glow::DEPTH_COMPONENT32F as i32, n, n, 0, glow::DEPTH_COMPONENT, glow::FLOAT, glow::PixelUnpackData::Slice(None));
        }
        let filter = if compare { glow::LINEAR } else { glow::NEAREST };
        let mut params_i = vec![
            (glow::TEXTURE_MIN_FILTER, filter),
            (glow::TEXTURE_MAG_FILTER, filter),
            (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
            (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
        ];
        if compare {
            params_i.push((glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE));
            params_i.push((glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL));
        }
        for (k, v) in params_i {
            gl.tex_parameter_i32(glow::TEXTURE_2D, k, v as i32);
        }
        let fbo = gl.create_framebuffer()?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        if rgba {
            gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::TEXTURE_2D, Some(tex), 0);
            gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::RENDERBUFFER, Some(map_depth));
            gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
        } else {
            gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::TEXTURE_2D, Some(tex), 0);
            gl.draw_buffers(&[glow::NONE]);
            gl.read_buffer(glow::NONE);
        }
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        maps.push(tex);
        fbos.push(fbo);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(format!("incomplete shadow framebuffer {status:#06x}"));
        }
    }
    gl.bind_texture(glow::TEXTURE_2D, None);
    let color_rb = gl.create_renderbuffer()?;
    gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color_rb));
    gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA8, w, h);
    let depth_rb = gl.create_renderbuffer()?;
    gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth_rb));
    gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT32F, w, h);
    gl.bind_renderbuffer(glow::RENDERBUFFER, None);
    let color_fbo = gl.create_framebuffer()?;
    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(color_fbo));
    gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::RENDERBUFFER, Some(color_rb));
    gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::RENDERBUFFER, Some(depth_rb));

    let draw_pass = |pass: &Pass, layer: Option<usize>| -> Result<(), String> {
        gl.use_program(Some(pass.program));
        for (d, &object) in DRAWS.iter().enumerate() {
            for &b in &pass.blocks {
                let (ubo, size) = p.ubos[b];
                let bytes = block_bytes(&tf, &p.reflection, b, object, layer, size)?;
                gl.bind_buffer(glow::UNIFORM_BUFFER, Some(ubo));
                gl.buffer_sub_data_u8_slice(glow::UNIFORM_BUFFER, 0, &bytes);
                gl.bind_buffer_base(glow::UNIFORM_BUFFER, b as u32, Some(ubo));
            }
            let (_, _, count) = p.meshes[if object == Object::Cube { 0 } else { 1 }];
            gl.bind_vertex_array(Some(pass.vaos[d]));
            gl.draw_elements(glow::TRIANGLES, count, glow::UNSIGNED_INT, 0);
        }
        gl.bind_vertex_array(None);
        Ok(())
    };

    gl.disable(glow::BLEND);
    gl.enable(glow::DEPTH_TEST);
    gl.depth_func(glow::LESS);
    gl.depth_mask(true);
    gl.front_face(glow::CCW);
    // Pass 1, once per layer.
    if t.cull_front() {
        gl.enable(glow::CULL_FACE);
        gl.cull_face(glow::FRONT);
    }
    if t.depth_bias() {
        gl.enable(glow::POLYGON_OFFSET_FILL);
        gl.polygon_offset(2.0, 4.0);
    }
    let mut result = Ok(());
    for (layer, &fbo) in fbos.iter().enumerate() {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        gl.viewport(0, 0, n, n);
        gl.clear_color(1.0, 1.0, 1.0, 1.0);
        gl.clear_depth_f32(1.0);
        gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
        result = result.and(draw_pass(&p.passes[0], Some(layer)));
    }
    gl.disable(glow::CULL_FACE);
    gl.disable(glow::POLYGON_OFFSET_FILL);
    // Pass 2.
    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(color_fbo));
    gl.viewport(0, 0, w, h);
    let c = scene::CLEAR;
    gl.clear_color(c[0] as f32, c[1] as f32, c[2] as f32, 1.0);
    gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
    for &(unit, layer, _) in &p.passes[1].textures {
        gl.active_texture(glow::TEXTURE0 + unit);
        gl.bind_texture(glow::TEXTURE_2D, Some(maps[layer.min(maps.len() - 1)]));
    }
    result = result.and(draw_pass(&p.passes[1], None));
    for &(unit, _, _) in &p.passes[1].textures {
        gl.active_texture(glow::TEXTURE0 + unit);
        gl.bind_texture(glow::TEXTURE_2D, None);
    }
    gl.active_texture(glow::TEXTURE0);
    gl.use_program(None);
    let mut pixels = vec![0u8; (w * h * 4) as usize];
    gl.read_buffer(glow::COLOR_ATTACHMENT0);
    gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
    gl.read_pixels(0, 0, w, h, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelPackData::Slice(Some(&mut pixels)));
    gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    for f in fbos.into_iter().chain([color_fbo]) {
        gl.delete_framebuffer(f);
    }
    for tex in maps {
        gl.delete_texture(tex);
    }
    for rb in [map_depth, color_rb, depth_rb] {
        gl.delete_renderbuffer(rb);
    }
    result?;
    let row = w as usize * 4;
    let flipped: Vec<u8> = pixels.chunks_exact(row).rev().flatten().copied().collect();
    RgbaImage::from_raw(w as u32, h as u32, flipped).ok_or_else(|| "short readback".into())
}
