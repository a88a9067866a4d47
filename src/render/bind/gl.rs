//! The GLSL family (330 core and ES 3.00, on a GL context or in WebGL2):
//! what a linked program binds, by GLSL name, from the manifest: uniform
//! blocks (`glGetUniformBlockIndex` + `glUniformBlockBinding` to a binding
//! point, a buffer filled at the manifest's offsets), samplers
//! (`glGetUniformLocation` + `glUniform1i` with the manifest's texture
//! unit), attributes (at the manifest's locations, checked against
//! `glGetAttribLocation`), and default-block uniforms set by name
//! (`glUniform*`). The GL executor and the WebGL2 page both run what this
//! module says; a by-name GL host builds the same [`GlProgram`] from the
//! linked program instead of the manifest.

use crate::emit::reflect_types::Reflection;
use crate::render::plan::{Draw, Field, Pass, Scalar, Shape, Unset, Value};

use super::bytes::{self, BufferLayout};
use super::PassFit;

/// A uniform block: bound to binding point `point` under its GLSL name.
#[derive(Clone, Debug, PartialEq)]
pub struct GlBlock {
    pub glsl_name: String,
    pub point: u32,
    pub layout: BufferLayout,
}

/// A sampler uniform on a texture unit.
#[derive(Clone, Debug, PartialEq)]
pub struct GlSampler {
    pub glsl_name: String,
    pub unit: u32,
    /// The DSL name, which the plan's textures use.
    pub name: String,
}

/// A vertex attribute and the mesh field that feeds it. `location`: where
/// the manifest puts it (bound before linking, and checked after), or
/// `None` for wherever the linker put it (a by-name host asks
/// `glGetAttribLocation`).
#[derive(Clone, Debug, PartialEq)]
pub struct GlAttribute {
    pub glsl_name: String,
    pub location: Option<u32>,
    pub field: Field,
}

/// A default-block uniform, set by its GLSL name with `glUniform*`.
#[derive(Clone, Debug, PartialEq)]
pub struct GlUniform {
    pub glsl_name: String,
    /// The plan's value that sets it.
    pub value: String,
    /// The DSL type it has.
    pub ty: String,
    /// What it is set to when the plan sets nothing: the manifest's
    /// default (`var @uniform x : T = value`).
    pub default: Option<Value>,
}

/// Everything a linked program binds, the same for every frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GlProgram {
    pub blocks: Vec<GlBlock>,
    pub samplers: Vec<GlSampler>,
    pub attributes: Vec<GlAttribute>,
    pub uniforms: Vec<GlUniform>,
    /// Colour outputs the GLSL declares without a location, to bind with
    /// `glBindFragDataLocation` before linking (GL 3.3; an ES program's
    /// lone output is location 0): (GLSL name, location).
    pub outputs: Vec<(String, u32)>,
}

/// What one draw sets: each block's bytes at its binding point, each
/// default-block uniform's value.
#[derive(Clone, Debug, PartialEq)]
pub struct GlDraw {
    pub blocks: Vec<(u32, Vec<u8>)>,
    pub uniforms: Vec<(String, Value)>,
}

/// A pass's program as the manifest binds it. Uniform blocks get the
/// manifest's binding point (`glsl_binding`; a manifest without one: the
/// block's index); a loose buffer GLSL declares no
/// block for is its plain uniforms, set by name. Attributes are bound to
/// the manifest's locations before linking (`glBindAttribLocation`; the
/// GLSL declares one only where the source gives it), and so are the
/// colour outputs that have none in the GLSL.
pub fn program(r: &Reflection, fit: &PassFit) -> GlProgram {
    let blocks = fit
        .blocks
        .iter()
        .filter_map(|&(b, _)| {
            let block = &r.uniform_buffers[b];
            let glsl_name = block.glsl_block.clone()?;
            let point = block.glsl_binding.unwrap_or(b as u32);
            Some(GlBlock { glsl_name, point, layout: super::manifest_layout(r, block) })
        })
        .collect();
    let mut uniforms = Vec::new();
    for &u in &fit.uniforms {
        let u = &r.uniforms[u];
        let Some(glsl_name) = u.glsl_name.clone() else { continue };
        let default = u.default.as_ref().and_then(|w| Value::from_words(&u.ty, w));
        let leaves = super::leaves(r, &u.name, &u.ty);
        if leaves.len() == 1 && leaves[0].path == u.name {
            uniforms.push(GlUniform { glsl_name, value: u.name.clone(), ty: u.ty.clone(), default });
            continue;
        }
        // A struct uniform is set member by member, by its GLSL path
        // (`u_instances[3].color`: members keep their names in GLSL).
        for l in leaves {
            let suffix = &l.path[u.name.len()..];
            uniforms.push(GlUniform { glsl_name: format!("{glsl_name}{suffix}"), value: l.path.clone(), ty: l.ty, default: None });
        }
    }
    let outputs = fit.outputs.iter().filter(|(_, _, declared)| !declared).map(|(name, location, _)| (name.clone(), *location)).collect();
    let samplers = fit
        .samplers
        .iter()
        .map(|s| {
            let m = &r.samplers[s.sampler];
            GlSampler { glsl_name: m.glsl_name.clone(), unit: m.texture_unit, name: m.name.clone() }
        })
        .collect();
    let attributes = fit
        .attributes
        .iter()
        .map(|a| GlAttribute { glsl_name: a.glsl_name.clone(), location: Some(a.location), field: a.field.clone() })
        .collect();
    GlProgram { blocks, samplers, attributes, uniforms, outputs }
}

/// One draw's block bytes and uniform values.
pub fn draw(program: &GlProgram, pass: &Pass, draw: &Draw, unset: Unset) -> Result<GlDraw, String> {
    let known = pass.value_names(draw);
    let mut problems = Vec::new();
    let mut blocks = Vec::new();
    for b in &program.blocks {
        match bytes::fill(&b.layout, |n| pass.value(draw, n), &known, unset) {
            Ok(bytes) => blocks.push((b.point, bytes)),
            Err(e) => problems.extend(e),
        }
    }
    let mut uniforms = Vec::new();
    for u in &program.uniforms {
        match pass.value(draw, &u.value) {
            Some(v) if v.dsl_type() == u.ty => uniforms.push((u.glsl_name.clone(), v.clone())),
            Some(v) => problems.push(format!("uniform `{}` is {} but the scene sets a {}", u.value, u.ty, v.dsl_type())),
            None if u.default.is_some() => uniforms.push((u.glsl_name.clone(), u.default.clone().expect("checked"))),
            None if unset == Unset::Zero => {}
            None => problems.push(format!("uniform `{}` is not a value the scene sets (it sets {})", u.value, known.join(", "))),
        }
    }
    if problems.is_empty() {
        Ok(GlDraw { blocks, uniforms })
    } else {
        Err(problems.join("; "))
    }
}

/// The textures a pass binds: (texture unit, index into `pass.textures`).
pub fn textures(program: &GlProgram, pass: &Pass) -> Result<Vec<(u32, usize)>, String> {
    program
        .samplers
        .iter()
        .map(|s| {
            pass.textures
                .iter()
                .position(|t| t.sampler == s.name)
                .map(|i| (s.unit, i))
                .ok_or_else(|| format!("sampler `{}` is not a texture the scene provides in its {} pass", s.name, pass.name))
        })
        .collect()
}

/// The `glUniform*` call that sets a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UniformCall {
    /// `glUniform{n}fv`.
    Float(u8),
    /// `glUniform{n}iv` (also bools).
    Int(u8),
    /// `glUniform{n}uiv`.
    Uint(u8),
    /// `glUniformMatrix{c}x{r}fv`.
    Matrix { columns: u8, rows: u8 },
}

impl UniformCall {
    pub fn of(v: &Value) -> UniformCall {
        let n = match v.shape {
            Shape::Scalar => 1,
            Shape::Vector(n) => n,
            Shape::Matrix { columns, rows } => return UniformCall::Matrix { columns, rows },
        };
        match v.scalar {
            Scalar::Float => UniformCall::Float(n),
            Scalar::Int | Scalar::Bool => UniformCall::Int(n),
            Scalar::Uint => UniformCall::Uint(n),
        }
    }

    /// The WebGL2 method name (`uniform3fv`, `uniformMatrix4fv`, `uniformMatrix3x2fv`).
    pub fn webgl(self) -> String {
        match self {
            UniformCall::Float(n) => format!("uniform{n}fv"),
            UniformCall::Int(n) => format!("uniform{n}iv"),
            UniformCall::Uint(n) => format!("uniform{n}uiv"),
            UniformCall::Matrix { columns, rows } if columns == rows => format!("uniformMatrix{columns}fv"),
            UniformCall::Matrix { columns, rows } => format!("uniformMatrix{columns}x{rows}fv"),
        }
    }
}
