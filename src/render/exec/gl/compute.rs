//! Compute plans on an OpenGL 4.3 core or OpenGL ES 3.1 context: the
//! entry point's `.430.comp` / `.310es.comp` file linked alone, storage
//! buffers at the manifest's GL binding points (`glBindBufferBase`),
//! images on its image units (`glBindImageTexture`), one
//! `glDispatchCompute`, a `glMemoryBarrier`, and the read-backs: buffers
//! mapped, images read through a framebuffer (`glReadPixels`, which GLES
//! has; rgba8 and the 32-bit integer formats).

use glow::HasContext;

use super::objects::Obj;
use super::GlExecutor;
use crate::render::bind::compute::{self, texel_bytes};
use crate::render::consumers::Consumer;
use crate::render::exec::{ComputeReadback, ExecError};
use crate::render::plan::compute::ComputePlan;
use crate::render::program::ShaderSet;
use crate::sema::types::{Access, ImageDim, ImageFormat};

/// The sized internal format of an image format, and how `glReadPixels`
/// reads it back (where it can: `None`).
fn gl_format(f: ImageFormat) -> (u32, Option<(u32, u32)>) {
    match f {
        ImageFormat::Rgba8 => (glow::RGBA8, Some((glow::RGBA, glow::UNSIGNED_BYTE))),
        ImageFormat::Rgba8Snorm => (glow::RGBA8_SNORM, None),
        ImageFormat::Rgba8ui => (glow::RGBA8UI, None),
        ImageFormat::Rgba8i => (glow::RGBA8I, None),
        ImageFormat::Rgba16f => (glow::RGBA16F, None),
        ImageFormat::Rgba16ui => (glow::RGBA16UI, None),
        ImageFormat::Rgba16i => (glow::RGBA16I, None),
        ImageFormat::Rgba32f => (glow::RGBA32F, None),
        ImageFormat::Rgba32ui => (glow::RGBA32UI, Some((glow::RGBA_INTEGER, glow::UNSIGNED_INT))),
        ImageFormat::Rgba32i => (glow::RGBA32I, Some((glow::RGBA_INTEGER, glow::INT))),
        ImageFormat::R32f => (glow::R32F, None),
        ImageFormat::R32ui => (glow::R32UI, None),
        ImageFormat::R32i => (glow::R32I, None),
    }
}

impl GlExecutor {
    /// Runs `plan` with the GLSL 430 (on [`Consumer::Gl430`]) or ES 3.10
    /// (on [`Consumer::Gles310`]) files of `set`.
    pub fn run_compute(&self, set: &ShaderSet, plan: &ComputePlan) -> Result<ComputeReadback, ExecError> {
        if !matches!(self.consumer, Consumer::Gl430 | Consumer::Gles310) {
            return Err(ExecError::Unsupported(format!("{} has no compute shaders (OpenGL 4.3 / OpenGL ES 3.1 do: gl430, gles310)", self.consumer.name())));
        }
        if set.target != self.target() {
            return Err(ExecError::Unsupported(format!("{}: {} runs {} files, not {}", set.label, self.consumer.name(), self.target().name(), set.target.name())));
        }
        if !plan.constants.is_empty() {
            return Err(ExecError::Unsupported(format!(
                "{}: GLSL has no specialization constants (the file holds each one's default as `const T NAME = default;`): {} cannot set them",
                set.label,
                self.consumer.name()
            )));
        }
        let r = set.manifest().map_err(ExecError::Program)?;
        let fit = compute::fit(&set.label, r, plan)?;
        let (file, text) = set.glsl(&fit.entry).map_err(ExecError::Program)?;
        let shader = self.compile(glow::COMPUTE_SHADER, file, text)?;
        let ctx = &self.ctx;
        let gl = ctx.current()?;
        // SAFETY: GL objects and calls on the current context; every object
        // is held by an `Obj` and deleted on every path.
        unsafe {
            let program = Obj::new(ctx, gl.create_program().map_err(ExecError::Api)?);
            gl.attach_shader(program.raw(), shader.raw());
            gl.link_program(program.raw());
            gl.detach_shader(program.raw(), shader.raw());
            if !gl.get_program_link_status(program.raw()) {
                return Err(ExecError::Link { pass: plan.name.clone(), log: gl.get_program_info_log(program.raw()) });
            }
            gl.use_program(Some(program.raw()));
            let mut buffers = Vec::new();
            for b in &fit.buffers {
                let buffer = Obj::new(ctx, gl.create_buffer().map_err(ExecError::Api)?);
                gl.bind_buffer(glow::SHADER_STORAGE_BUFFER, Some(buffer.raw()));
                gl.buffer_data_u8_slice(glow::SHADER_STORAGE_BUFFER, &plan.buffers[b.input].bytes, glow::DYNAMIC_COPY);
                gl.bind_buffer_base(glow::SHADER_STORAGE_BUFFER, b.gl_binding, Some(buffer.raw()));
                buffers.push((b.name.clone(), buffer, plan.buffers[b.input].bytes.len()));
            }
            let mut images = Vec::new();
            for i in &fit.images {
                let input = &plan.images[i.input];
                let (internal, read) = gl_format(i.format);
                let texture = Obj::new(ctx, gl.create_texture().map_err(ExecError::Api)?);
                let (target, layered) = match i.dim {
                    ImageDim::D2 => (glow::TEXTURE_2D, false),
                    ImageDim::D3 => (glow::TEXTURE_3D, true),
                    ImageDim::D2Array => (glow::TEXTURE_2D_ARRAY, true),
                };
                gl.bind_texture(target, Some(texture.raw()));
                if layered {
                    gl.tex_storage_3d(target, 1, internal, input.width as i32, input.height as i32, input.layers as i32);
                } else {
                    gl.tex_storage_2d(target, 1, internal, input.width as i32, input.height as i32);
                }
                if let Some(t) = &input.texels {
                    let (fmt, ty) = upload_format(i.format);
                    gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
                    if layered {
                        gl.tex_sub_image_3d(target, 0, 0, 0, 0, input.width as i32, input.height as i32, input.layers as i32, fmt, ty, glow::PixelUnpackData::Slice(Some(t)));
                    } else {
                        gl.tex_sub_image_2d(target, 0, 0, 0, input.width as i32, input.height as i32, fmt, ty, glow::PixelUnpackData::Slice(Some(t)));
                    }
                }
                let access = match i.access {
                    Access::Read => glow::READ_ONLY,
                    Access::Write => glow::WRITE_ONLY,
                    Access::ReadWrite => glow::READ_WRITE,
                };
                gl.bind_image_texture(i.unit, Some(texture.raw()), 0, layered, 0, access, internal);
                images.push((i.name.clone(), texture, target, [input.width, input.height, input.layers], i.format, read));
            }
            ctx.check("binding the compute plan's buffers and images")?;
            let [x, y, z] = plan.workgroups;
            gl.dispatch_compute(x, y, z);
            gl.memory_barrier(glow::ALL_BARRIER_BITS);
            ctx.check("dispatching")?;
            let mut out = ComputeReadback::default();
            for name in &plan.readback {
                if let Some((_, buffer, len)) = buffers.iter().find(|b| &b.0 == name) {
                    gl.bind_buffer(glow::SHADER_STORAGE_BUFFER, Some(buffer.raw()));
                    let mut bytes = vec![0u8; *len];
                    let p = gl.map_buffer_range(glow::SHADER_STORAGE_BUFFER, 0, *len as i32, glow::MAP_READ_BIT);
                    if p.is_null() {
                        ctx.check("mapping a storage buffer")?;
                        return Err(ExecError::Api(format!("glMapBufferRange of `{name}` returned nothing")));
                    }
                    std::ptr::copy_nonoverlapping(p, bytes.as_mut_ptr(), *len);
                    gl.unmap_buffer(glow::SHADER_STORAGE_BUFFER);
                    out.resources.insert(name.clone(), bytes);
                } else if let Some((_, texture, target, [w, h, layers], format, read)) = images.iter().find(|i| &i.0 == name) {
                    let Some((fmt, ty)) = read else {
                        return Err(ExecError::Unsupported(format!("{}: reading back a `{}` image is not supported on GL (rgba8, rgba32ui, rgba32i are)", plan.name, format.name())));
                    };
                    let fb = Obj::new(ctx, gl.create_framebuffer().map_err(ExecError::Api)?);
                    gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.raw()));
                    let texel = texel_bytes(*format) as usize;
                    let mut bytes = vec![0u8; *w as usize * *h as usize * *layers as usize * texel];
                    let layer_bytes = *w as usize * *h as usize * texel;
                    for layer in 0..*layers {
                        if *target == glow::TEXTURE_2D {
                            gl.framebuffer_texture_2d(glow::READ_FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::TEXTURE_2D, Some(texture.raw()), 0);
                        } else {
                            gl.framebuffer_texture_layer(glow::READ_FRAMEBUFFER, glow::COLOR_ATTACHMENT0, Some(texture.raw()), 0, layer as i32);
                        }
                        if gl.check_framebuffer_status(glow::READ_FRAMEBUFFER) != glow::FRAMEBUFFER_COMPLETE {
                            return Err(ExecError::Api(format!("image `{name}` cannot be read through a framebuffer")));
                        }
                        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
                        let at = layer as usize * layer_bytes;
                        gl.read_pixels(0, 0, *w as i32, *h as i32, *fmt, *ty, glow::PixelPackData::Slice(Some(&mut bytes[at..at + layer_bytes])));
                    }
                    gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
                    out.resources.insert(name.clone(), bytes);
                } else {
                    return Err(ExecError::Program(format!("{}: `{name}` is read back but the program does not use it", plan.name)));
                }
            }
            gl.use_program(None);
            ctx.check("reading back the compute plan's results")?;
            Ok(out)
        }
    }
}

/// The `glTexSubImage` format and type of a texel upload.
fn upload_format(f: ImageFormat) -> (u32, u32) {
    match f {
        ImageFormat::Rgba8 => (glow::RGBA, glow::UNSIGNED_BYTE),
        ImageFormat::Rgba8Snorm => (glow::RGBA, glow::BYTE),
        ImageFormat::Rgba8ui => (glow::RGBA_INTEGER, glow::UNSIGNED_BYTE),
        ImageFormat::Rgba8i => (glow::RGBA_INTEGER, glow::BYTE),
        ImageFormat::Rgba16f => (glow::RGBA, glow::HALF_FLOAT),
        ImageFormat::Rgba16ui => (glow::RGBA_INTEGER, glow::UNSIGNED_SHORT),
        ImageFormat::Rgba16i => (glow::RGBA_INTEGER, glow::SHORT),
        ImageFormat::Rgba32f => (glow::RGBA, glow::FLOAT),
        ImageFormat::Rgba32ui => (glow::RGBA_INTEGER, glow::UNSIGNED_INT),
        ImageFormat::Rgba32i => (glow::RGBA_INTEGER, glow::INT),
        ImageFormat::R32f => (glow::RED, glow::FLOAT),
        ImageFormat::R32ui => (glow::RED_INTEGER, glow::UNSIGNED_INT),
        ImageFormat::R32i => (glow::RED_INTEGER, glow::INT),
    }
}
