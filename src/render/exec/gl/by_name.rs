//! A GL host that binds by source names alone, with no manifest: what the
//! linked program says it has (`glGetActiveUniform`, `glGetActiveAttrib`,
//! `glGetActiveUniformBlockName`, the offsets and strides the driver gives
//! for block members), matched to the plan's values, textures and mesh
//! fields by name. This is how hosts written for daslang's own generator
//! bind its programs (`glGetUniformLocation`, `glUniform*`).

use glow::HasContext;

use crate::render::bind::bytes::{BufferLayout, Slot};
use crate::render::bind::gl::{GlAttribute, GlBlock, GlProgram, GlSampler, GlUniform};
use crate::render::plan::{FramePlan, Geometry, Pass};

/// The DSL type of a GL uniform type, `None` for samplers and types
/// plans have no values of.
fn dsl_type(ty: u32) -> Option<&'static str> {
    Some(match ty {
        glow::FLOAT => "float",
        glow::FLOAT_VEC2 => "float2",
        glow::FLOAT_VEC3 => "float3",
        glow::FLOAT_VEC4 => "float4",
        glow::INT => "int",
        glow::INT_VEC2 => "int2",
        glow::INT_VEC3 => "int3",
        glow::INT_VEC4 => "int4",
        glow::UNSIGNED_INT => "uint",
        glow::UNSIGNED_INT_VEC2 => "uint2",
        glow::UNSIGNED_INT_VEC3 => "uint3",
        glow::UNSIGNED_INT_VEC4 => "uint4",
        glow::BOOL => "bool",
        glow::BOOL_VEC2 => "bool2",
        glow::BOOL_VEC3 => "bool3",
        glow::BOOL_VEC4 => "bool4",
        glow::FLOAT_MAT2 => "float2x2",
        glow::FLOAT_MAT3 => "float3x3",
        glow::FLOAT_MAT4 => "float4x4",
        glow::FLOAT_MAT2x3 => "float2x3",
        glow::FLOAT_MAT2x4 => "float2x4",
        glow::FLOAT_MAT3x2 => "float3x2",
        glow::FLOAT_MAT3x4 => "float3x4",
        glow::FLOAT_MAT4x2 => "float4x2",
        glow::FLOAT_MAT4x3 => "float4x3",
        _ => return None,
    })
}

fn is_sampler(ty: u32) -> bool {
    matches!(
        ty,
        glow::SAMPLER_2D
            | glow::SAMPLER_2D_SHADOW
            | glow::SAMPLER_2D_ARRAY
            | glow::SAMPLER_2D_ARRAY_SHADOW
            | glow::SAMPLER_3D
            | glow::SAMPLER_CUBE
            | glow::SAMPLER_CUBE_SHADOW
            | glow::INT_SAMPLER_2D
            | glow::UNSIGNED_INT_SAMPLER_2D
    )
}

/// A uniform's name without the `[0]` GL appends to arrays, and without
/// the `Block.` it prefixes to members of a block with an instance name.
fn plain(name: &str) -> &str {
    let name = name.strip_suffix("[0]").unwrap_or(name);
    name.rsplit_once('.').map_or(name, |(_, m)| m)
}

/// What `program` binds, by its own names, for `pass` of `plan`.
///
/// # Safety
/// `gl` is current and `program` linked on it.
pub unsafe fn interface(gl: &glow::Context, program: glow::Program, plan: &FramePlan, pass: &Pass) -> Result<GlProgram, Vec<String>> {
    let mut problems = Vec::new();
    let mut out = GlProgram::default();
    // SAFETY (whole body): queries of a linked program on the current context.
    unsafe {
        let blocks = gl.get_program_parameter_i32(program, glow::ACTIVE_UNIFORM_BLOCKS).max(0) as u32;
        for i in 0..blocks {
            let size = gl.get_active_uniform_block_parameter_i32(program, i, glow::UNIFORM_BLOCK_DATA_SIZE).max(0) as u32;
            let name = gl.get_active_uniform_block_name(program, i);
            out.blocks.push(GlBlock { glsl_name: name.clone(), point: i, layout: BufferLayout { name, size, slots: Vec::new() } });
        }
        let count = gl.get_active_uniforms(program);
        let indices: Vec<u32> = (0..count).collect();
        let param = |p| if count == 0 { Vec::new() } else { gl.get_active_uniforms_parameter(program, &indices, p) };
        let (block, offset, array_stride, matrix_stride) =
            (param(glow::UNIFORM_BLOCK_INDEX), param(glow::UNIFORM_OFFSET), param(glow::UNIFORM_ARRAY_STRIDE), param(glow::UNIFORM_MATRIX_STRIDE));
        let mut unit = 0;
        for i in 0..count as usize {
            let Some(u) = gl.get_active_uniform(program, i as u32) else { continue };
            if u.name.starts_with("gl_") {
                continue;
            }
            let name = plain(&u.name).to_string();
            if is_sampler(u.utype) {
                // An array of samplers is one unit per element, `name[i]`.
                for k in 0..u.size.max(1) {
                    let element = if u.size > 1 { format!("{name}[{k}]") } else { name.clone() };
                    out.samplers.push(GlSampler { glsl_name: element.clone(), unit, name: element });
                    unit += 1;
                }
                continue;
            }
            let Some(element) = dsl_type(u.utype) else {
                problems.push(format!("uniform `{}` has a GL type ({:#06x}) the scene has no values of", u.name, u.utype));
                continue;
            };
            let ty = if u.size > 1 || u.name.ends_with("[0]") { format!("{element}[{}]", u.size) } else { element.to_string() };
            match block[i] {
                b if b >= 0 => {
                    let Some(target) = out.blocks.iter_mut().find(|x| x.point == b as u32) else { continue };
                    let stride = |s: i32| (s > 0).then_some(s as u32);
                    target.layout.slots.push(Slot {
                        value: name,
                        ty,
                        offset: offset[i].max(0) as u32,
                        array_stride: stride(array_stride[i]),
                        matrix_stride: stride(matrix_stride[i]),
                        default: None,
                    });
                }
                _ => out.uniforms.push(GlUniform { glsl_name: plain_location(&u.name).to_string(), value: name, ty, default: None }),
            }
        }
        let meshes: Vec<_> = pass
            .draws
            .iter()
            .filter_map(|d| match d.geometry {
                Geometry::Mesh(m) => Some(m),
                Geometry::Vertices(_) => None,
            })
            .collect();
        for i in 0..gl.get_active_attributes(program) {
            let Some(a) = gl.get_active_attribute(program, i) else { continue };
            if a.name.starts_with("gl_") {
                continue;
            }
            match meshes.first().and_then(|m| m.field(&a.name)) {
                Some(field) => out.attributes.push(GlAttribute { glsl_name: a.name.clone(), location: None, field: field.clone() }),
                None => {
                    let have: Vec<&str> = meshes.first().map_or(Vec::new(), |m| m.fields.iter().map(|f| f.name).collect());
                    problems.push(format!(
                        "attribute `{}` is not in {}'s meshes (they have {})",
                        a.name,
                        plan.scene,
                        if have.is_empty() { "none: the pass draws without vertex buffers".to_string() } else { have.join(", ") }
                    ));
                }
            }
        }
        if let Some(m) = meshes.first() {
            if !out.attributes.iter().any(|a| a.field.name == m.position) {
                problems.push(format!("no `{}` attribute: nothing positions the vertices", m.position));
            }
        }
    }
    if problems.is_empty() {
        Ok(out)
    } else {
        Err(problems)
    }
}

/// The name to ask `glGetUniformLocation` for (an array by its first element).
fn plain_location(name: &str) -> &str {
    name.strip_suffix("[0]").unwrap_or(name)
}

#[cfg(test)]
mod tests {
    #[test]
    fn names() {
        assert_eq!(super::plain("u_cascade_vp[0]"), "u_cascade_vp");
        assert_eq!(super::plain("Lighting.u_cam_pos"), "u_cam_pos");
        assert_eq!(super::plain("u_model"), "u_model");
    }
}
