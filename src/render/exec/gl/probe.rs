//! One draw of any vertex/fragment pair with inputs made up from what the
//! linked program declares, for comparing programs that should draw the
//! same picture (umbrac's stages mixed with daslang's generator's, say)
//! without a scene written for them. Every input is a fixed function of
//! its name and type, so two programs declaring the same interface get
//! the same inputs:
//! - attributes: a grid of triangles over most of the viewport; component
//!   0 and 1 of every float attribute are the vertex's x and y, 2 a
//!   name-dependent slope, 3 is 1 (no vertex attributes: three vertices,
//!   for programs that place them by `gl_VertexID`);
//! - uniforms, plain or in blocks (at the driver's offsets and strides):
//!   floats in [0.25, 0.75], matrices near the identity, small integers;
//! - samplers: `sampler2D` and `samplerCube` a colour pattern,
//!   `sampler2DShadow` a depth ramp compared `LEQUAL`.
//!
//! A fragment shader that reads `gl_PointCoord` is drawn as one point per
//! grid vertex. Colour output 0 is drawn into one RGBA8 target and read
//! back.

use glow::HasContext;

use super::objects::Obj;
use super::{ExecError, GlExecutor};

/// What [`GlExecutor::probe`] drew: RGBA8 rows, bottom row first.
#[derive(Clone, Debug, PartialEq)]
pub struct ProbeImage {
    pub size: u32,
    pub rgba: Vec<u8>,
}

/// A number in [0, 1) fixed by `name` and `k` (FNV-1a, then a mix).
fn unit(name: &str, k: u32) -> f32 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes().chain(k.to_le_bytes()) {
        h = (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
    }
    h ^= h >> 29;
    ((h >> 40) as f32) / (1u64 << 24) as f32
}

/// Component `k` of the made-up value of float uniform `name`.
fn float_value(name: &str, k: u32) -> f32 {
    0.25 + 0.5 * unit(name, k)
}

/// Element (column `c`, row `r`) of the made-up value of matrix `name`
/// (element `e` of an array): the identity, each element moved by under
/// 0.05, so a wrong layout shows.
fn matrix_value(name: &str, e: u32, c: u32, r: u32) -> f32 {
    let id = if c == r { 1.0 } else { 0.0 };
    id + 0.1 * (unit(name, e * 16 + c * 4 + r) - 0.5)
}

/// Component `k` of the made-up value of integer (or bool) uniform `name`.
fn int_value(name: &str, k: u32, bool_like: bool) -> i32 {
    let v = (unit(name, k) * 4.0) as i32;
    if bool_like {
        v & 1
    } else {
        v
    }
}

/// (components per column, columns, scalar kind) of a GL uniform type:
/// kind 0 float, 1 int, 2 uint, 3 bool.
fn shape(ty: u32) -> Option<(u32, u32, u8)> {
    Some(match ty {
        glow::FLOAT => (1, 1, 0),
        glow::FLOAT_VEC2 => (2, 1, 0),
        glow::FLOAT_VEC3 => (3, 1, 0),
        glow::FLOAT_VEC4 => (4, 1, 0),
        glow::INT => (1, 1, 1),
        glow::INT_VEC2 => (2, 1, 1),
        glow::INT_VEC3 => (3, 1, 1),
        glow::INT_VEC4 => (4, 1, 1),
        glow::UNSIGNED_INT => (1, 1, 2),
        glow::UNSIGNED_INT_VEC2 => (2, 1, 2),
        glow::UNSIGNED_INT_VEC3 => (3, 1, 2),
        glow::UNSIGNED_INT_VEC4 => (4, 1, 2),
        glow::BOOL => (1, 1, 3),
        glow::BOOL_VEC2 => (2, 1, 3),
        glow::BOOL_VEC3 => (3, 1, 3),
        glow::BOOL_VEC4 => (4, 1, 3),
        glow::FLOAT_MAT2 => (2, 2, 0),
        glow::FLOAT_MAT3 => (3, 3, 0),
        glow::FLOAT_MAT4 => (4, 4, 0),
        glow::FLOAT_MAT2x3 => (3, 2, 0),
        glow::FLOAT_MAT2x4 => (4, 2, 0),
        glow::FLOAT_MAT3x2 => (2, 3, 0),
        glow::FLOAT_MAT3x4 => (4, 3, 0),
        glow::FLOAT_MAT4x2 => (2, 4, 0),
        glow::FLOAT_MAT4x3 => (3, 4, 0),
        _ => return None,
    })
}

/// The name inputs are made from: a uniform's without `[0]` and without
/// the `Block.` of a block with an instance name, so that the same member
/// gets the same value however its block is spelled.
fn plain(name: &str) -> &str {
    let name = name.strip_suffix("[0]").unwrap_or(name);
    name.rsplit_once('.').map_or(name, |(_, m)| m)
}

/// The made-up value of uniform `name` of `(rows, columns, kind)`,
/// element `e`, as 32-bit words in column order.
fn words(name: &str, (rows, cols, kind): (u32, u32, u8), e: u32) -> Vec<u32> {
    let mut out = Vec::with_capacity((rows * cols) as usize);
    for c in 0..cols {
        for r in 0..rows {
            let k = e * 16 + c * 4 + r;
            out.push(match kind {
                0 if cols > 1 => matrix_value(name, e, c, r).to_bits(),
                0 => float_value(name, k).to_bits(),
                _ => int_value(name, k, kind == 3) as u32,
            });
        }
    }
    out
}

const GRID: u32 = 8;

/// The grid's vertex positions in [-0.9, 0.9]^2 and its triangles.
fn grid() -> (Vec<[f32; 2]>, Vec<u32>) {
    let n = GRID + 1;
    let xy = (0..n * n).map(|i| [-0.9 + 1.8 * (i % n) as f32 / GRID as f32, -0.9 + 1.8 * (i / n) as f32 / GRID as f32]).collect();
    let mut idx = Vec::new();
    for y in 0..GRID {
        for x in 0..GRID {
            let a = y * n + x;
            idx.extend([a, a + 1, a + n, a + 1, a + n + 1, a + n]);
        }
    }
    (xy, idx)
}

/// An 8x8 RGBA8 pattern, tinted by `tint`.
fn pattern(tint: u8) -> Vec<u8> {
    (0..64u32).flat_map(|i| [(i % 8) as u8 * 32, ((i / 8) as u8 * 32) ^ tint, (((i % 8) ^ (i / 8)) as u8 * 32).wrapping_add(tint), 255]).collect()
}

/// The GL type of sampler uniform type `ty` the probe makes a texture
/// for, `None` for a type that is no sampler.
fn sampler_kind(ty: u32) -> Result<Option<u32>, ExecError> {
    match ty {
        glow::SAMPLER_2D | glow::SAMPLER_CUBE | glow::SAMPLER_2D_SHADOW => Ok(Some(ty)),
        glow::SAMPLER_3D
        | glow::SAMPLER_2D_ARRAY
        | glow::SAMPLER_2D_ARRAY_SHADOW
        | glow::SAMPLER_CUBE_SHADOW
        | glow::INT_SAMPLER_2D
        | glow::UNSIGNED_INT_SAMPLER_2D
        | glow::INT_SAMPLER_3D
        | glow::UNSIGNED_INT_SAMPLER_3D => Err(ExecError::Unsupported(format!("the probe has no texture for sampler type {ty:#06x}"))),
        _ => Ok(None),
    }
}

impl GlExecutor {
    /// Links `vertex` with `fragment` (GLSL of this context's profile),
    /// draws them once into a `size` x `size` RGBA8 target with inputs
    /// made up from their names (see the module docs) and reads it back.
    pub fn probe(&self, vertex: &str, fragment: &str, size: u32) -> Result<ProbeImage, ExecError> {
        let vs = self.compile(glow::VERTEX_SHADER, "vertex shader", vertex)?;
        let fs = self.compile(glow::FRAGMENT_SHADER, "fragment shader", fragment)?;
        let ctx = &self.ctx;
        let gl = ctx.current()?;
        let api = |e: String| ExecError::Api(e);
        // SAFETY (whole body): objects and queries of the current context;
        // every object is held by an `Obj` and deleted on every path.
        let image = unsafe {
            let program = Obj::new(ctx, gl.create_program().map_err(api)?);
            let p = program.raw();
            gl.attach_shader(p, vs.raw());
            gl.attach_shader(p, fs.raw());
            gl.link_program(p);
            gl.detach_shader(p, vs.raw());
            gl.detach_shader(p, fs.raw());
            if !gl.get_program_link_status(p) {
                return Err(ExecError::Link { pass: "probe".into(), log: gl.get_program_info_log(p) });
            }
            gl.use_program(Some(p));

            // Uniforms: plain ones set now, block members into bytes.
            let blocks = gl.get_program_parameter_i32(p, glow::ACTIVE_UNIFORM_BLOCKS).max(0) as u32;
            let mut block_bytes: Vec<Vec<u8>> =
                (0..blocks).map(|b| vec![0u8; gl.get_active_uniform_block_parameter_i32(p, b, glow::UNIFORM_BLOCK_DATA_SIZE).max(0) as usize]).collect();
            let count = gl.get_active_uniforms(p);
            let indices: Vec<u32> = (0..count).collect();
            let param = |q| if count == 0 { Vec::new() } else { gl.get_active_uniforms_parameter(p, &indices, q) };
            let (block, offset, array_stride, matrix_stride) =
                (param(glow::UNIFORM_BLOCK_INDEX), param(glow::UNIFORM_OFFSET), param(glow::UNIFORM_ARRAY_STRIDE), param(glow::UNIFORM_MATRIX_STRIDE));
            let mut textures = Vec::new();
            for i in 0..count as usize {
                let Some(u) = gl.get_active_uniform(p, i as u32) else { continue };
                if u.name.starts_with("gl_") {
                    continue;
                }
                let name = plain(&u.name);
                let elements = u.size.max(1) as u32;
                if let Some(kind) = sampler_kind(u.utype)? {
                    // One unit per element of an array of samplers.
                    let loc = gl.get_uniform_location(p, u.name.strip_suffix("[0]").unwrap_or(&u.name));
                    let first = textures.len() as i32;
                    let units: Vec<i32> = (0..elements as i32).map(|k| first + k).collect();
                    gl.uniform_1_i32_slice(loc.as_ref(), &units);
                    textures.extend(std::iter::repeat_n(kind, elements as usize));
                    continue;
                }
                let Some(sh) = shape(u.utype) else {
                    return Err(ExecError::Unsupported(format!("the probe has no value for uniform `{}` (GL type {:#06x})", u.name, u.utype)));
                };
                if block[i] >= 0 {
                    let bytes = &mut block_bytes[block[i] as usize];
                    for e in 0..elements {
                        let base = offset[i].max(0) as usize + (e * array_stride[i].max(0) as u32) as usize;
                        let w = words(name, sh, e);
                        for c in 0..sh.1 {
                            for r in 0..sh.0 {
                                let at = base + (c * matrix_stride[i].max(0) as u32 + r * 4) as usize;
                                if let Some(slot) = bytes.get_mut(at..at + 4) {
                                    slot.copy_from_slice(&w[(c * sh.0 + r) as usize].to_le_bytes());
                                }
                            }
                        }
                    }
                    continue;
                }
                let loc = gl.get_uniform_location(p, u.name.strip_suffix("[0]").unwrap_or(&u.name));
                let all: Vec<u32> = (0..elements).flat_map(|e| words(name, sh, e)).collect();
                let f: Vec<f32> = all.iter().map(|w| f32::from_bits(*w)).collect();
                let i32s: Vec<i32> = all.iter().map(|w| *w as i32).collect();
                let l = loc.as_ref();
                match sh {
                    (n, 1, 2) => match n {
                        1 => gl.uniform_1_u32_slice(l, &all),
                        2 => gl.uniform_2_u32_slice(l, &all),
                        3 => gl.uniform_3_u32_slice(l, &all),
                        _ => gl.uniform_4_u32_slice(l, &all),
                    },
                    (n, 1, 1 | 3) => match n {
                        1 => gl.uniform_1_i32_slice(l, &i32s),
                        2 => gl.uniform_2_i32_slice(l, &i32s),
                        3 => gl.uniform_3_i32_slice(l, &i32s),
                        _ => gl.uniform_4_i32_slice(l, &i32s),
                    },
                    (n, 1, _) => match n {
                        1 => gl.uniform_1_f32_slice(l, &f),
                        2 => gl.uniform_2_f32_slice(l, &f),
                        3 => gl.uniform_3_f32_slice(l, &f),
                        _ => gl.uniform_4_f32_slice(l, &f),
                    },
                    _ => match u.utype {
                        glow::FLOAT_MAT2 => gl.uniform_matrix_2_f32_slice(l, false, &f),
                        glow::FLOAT_MAT3 => gl.uniform_matrix_3_f32_slice(l, false, &f),
                        glow::FLOAT_MAT4 => gl.uniform_matrix_4_f32_slice(l, false, &f),
                        glow::FLOAT_MAT2x3 => gl.uniform_matrix_2x3_f32_slice(l, false, &f),
                        glow::FLOAT_MAT2x4 => gl.uniform_matrix_2x4_f32_slice(l, false, &f),
                        glow::FLOAT_MAT3x2 => gl.uniform_matrix_3x2_f32_slice(l, false, &f),
                        glow::FLOAT_MAT3x4 => gl.uniform_matrix_3x4_f32_slice(l, false, &f),
                        glow::FLOAT_MAT4x2 => gl.uniform_matrix_4x2_f32_slice(l, false, &f),
                        _ => gl.uniform_matrix_4x3_f32_slice(l, false, &f),
                    },
                }
            }
            let mut buffers = Vec::new();
            for (b, bytes) in block_bytes.iter().enumerate() {
                let buf = Obj::new(ctx, gl.create_buffer().map_err(api)?);
                gl.bind_buffer(glow::UNIFORM_BUFFER, Some(buf.raw()));
                gl.buffer_data_u8_slice(glow::UNIFORM_BUFFER, bytes, glow::STATIC_DRAW);
                gl.uniform_block_binding(p, b as u32, b as u32);
                gl.bind_buffer_base(glow::UNIFORM_BUFFER, b as u32, Some(buf.raw()));
                buffers.push(buf);
            }

            // Attributes: one buffer of four floats per vertex each.
            let vao = Obj::new(ctx, gl.create_vertex_array().map_err(api)?);
            gl.bind_vertex_array(Some(vao.raw()));
            let (xy, idx) = grid();
            let mut attribute_buffers = Vec::new();
            for i in 0..gl.get_active_attributes(p) {
                let Some(a) = gl.get_active_attribute(p, i) else { continue };
                if a.name.starts_with("gl_") {
                    continue;
                }
                if !matches!(a.atype, glow::FLOAT | glow::FLOAT_VEC2 | glow::FLOAT_VEC3 | glow::FLOAT_VEC4) {
                    return Err(ExecError::Unsupported(format!("the probe feeds float attributes only, not `{}` ({:#06x})", a.name, a.atype)));
                }
                let Some(loc) = gl.get_attrib_location(p, &a.name) else { continue };
                let slope = unit(&a.name, 7) - 0.5;
                let data: Vec<f32> = xy.iter().flat_map(|&[x, y]| [x, y, slope * (x + y), 1.0]).collect();
                let buf = Obj::new(ctx, gl.create_buffer().map_err(api)?);
                gl.bind_buffer(glow::ARRAY_BUFFER, Some(buf.raw()));
                gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytemuck::cast_slice(&data), glow::STATIC_DRAW);
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, 4, glow::FLOAT, false, 16, 0);
                attribute_buffers.push(buf);
            }
            let index_buffer = Obj::new(ctx, gl.create_buffer().map_err(api)?);
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(index_buffer.raw()));
            gl.buffer_data_u8_slice(glow::ELEMENT_ARRAY_BUFFER, bytemuck::cast_slice(&idx), glow::STATIC_DRAW);

            // The target.
            let target = Obj::new(ctx, gl.create_texture().map_err(api)?);
            gl.bind_texture(glow::TEXTURE_2D, Some(target.raw()));
            gl.tex_image_2d(glow::TEXTURE_2D, 0, glow::RGBA8 as i32, size as i32, size as i32, 0, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelUnpackData::Slice(None));
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
            let fbo = Obj::new(ctx, gl.create_framebuffer().map_err(api)?);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo.raw()));
            gl.framebuffer_texture_2d(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::TEXTURE_2D, Some(target.raw()), 0);
            gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
            if gl.check_framebuffer_status(glow::FRAMEBUFFER) != glow::FRAMEBUFFER_COMPLETE {
                return Err(ExecError::Api("the probe's target is not complete".into()));
            }
            // Textures last bound to their units (the target is unit 0's
            // TEXTURE_2D binding until now).
            let mut texture_objects = Vec::new();
            for (unit, kind) in textures.iter().enumerate() {
                texture_objects.push(self.make_probe_texture(*kind, unit as u32)?);
            }
            gl.viewport(0, 0, size as i32, size as i32);
            gl.disable(glow::DEPTH_TEST);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::BLEND);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            if fragment.contains("gl_PointCoord") {
                // A point sprite program: each grid vertex a point, its
                // size the vertex shader's (GL 3.3 core asks for that).
                if self.consumer == crate::render::consumer::Consumer::Gl330 {
                    gl.enable(glow::PROGRAM_POINT_SIZE);
                }
                gl.draw_arrays(glow::POINTS, 0, xy.len() as i32);
                if self.consumer == crate::render::consumer::Consumer::Gl330 {
                    gl.disable(glow::PROGRAM_POINT_SIZE);
                }
            } else if attribute_buffers.is_empty() {
                gl.draw_arrays(glow::TRIANGLES, 0, 3);
            } else {
                gl.draw_elements(glow::TRIANGLES, idx.len() as i32, glow::UNSIGNED_INT, 0);
            }
            let mut rgba = vec![0u8; (size * size * 4) as usize];
            gl.read_pixels(0, 0, size as i32, size as i32, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelPackData::Slice(Some(&mut rgba)));
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.bind_vertex_array(None);
            gl.use_program(None);
            drop((texture_objects, buffers, attribute_buffers, index_buffer));
            ProbeImage { size, rgba }
        };
        ctx.check("drawing the probe")?;
        Ok(image)
    }

    /// A texture for a sampler of GL type `ty`, bound to `unit`.
    fn make_probe_texture(&self, ty: u32, unit: u32) -> Result<Obj<glow::Texture>, ExecError> {
        let gl = self.ctx.current()?;
        // SAFETY: texture uploads on the current context.
        unsafe {
            let t = Obj::new(&self.ctx, gl.create_texture().map_err(ExecError::Api)?);
            gl.active_texture(glow::TEXTURE0 + unit);
            let linear = glow::LINEAR as i32;
            match ty {
                glow::SAMPLER_CUBE => {
                    gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(t.raw()));
                    for face in 0..6 {
                        let data = pattern(face as u8 * 40);
                        gl.tex_image_2d(glow::TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, glow::RGBA8 as i32, 8, 8, 0, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelUnpackData::Slice(Some(&data)));
                    }
                    gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_MIN_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_MAG_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE as i32);
                    gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE as i32);
                }
                glow::SAMPLER_2D_SHADOW => {
                    gl.bind_texture(glow::TEXTURE_2D, Some(t.raw()));
                    let depth: Vec<u32> = (0..64u32).map(|i| ((i % 8 + i / 8) as f64 / 14.0 * u32::MAX as f64) as u32).collect();
                    gl.tex_image_2d(
                        glow::TEXTURE_2D,
                        0,
                        glow::DEPTH_COMPONENT24 as i32,
                        8,
                        8,
                        0,
                        glow::DEPTH_COMPONENT,
                        glow::UNSIGNED_INT,
                        glow::PixelUnpackData::Slice(Some(bytemuck::cast_slice(&depth))),
                    );
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_COMPARE_MODE, glow::COMPARE_REF_TO_TEXTURE as i32);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL as i32);
                }
                _ => {
                    gl.bind_texture(glow::TEXTURE_2D, Some(t.raw()));
                    let data = pattern(0);
                    gl.tex_image_2d(glow::TEXTURE_2D, 0, glow::RGBA8 as i32, 8, 8, 0, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelUnpackData::Slice(Some(&data)));
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, linear);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_S, glow::REPEAT as i32);
                    gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_T, glow::REPEAT as i32);
                }
            }
            gl.active_texture(glow::TEXTURE0);
            Ok(t)
        }
    }
}
