//! The reflection manifest (`STEM.reflect.json`), built from the interface,
//! naga's `Layouter` on `Lowered::gpu`, and the names the GLSL writer used.
//!
//! Uniform block layouts: the WGSL uniform layout of the `gpu` module is the
//! one reported, for each block's members and (`Reflection::structs`) for
//! every struct type in a block, so that hosts (and `bindgen`) lay buffers
//! out from the manifest alone. GLSL declares the same blocks
//! `layout(std140)` without explicit offsets, so the driver computes std140
//! itself; the two must agree. Which DSL types have the same layout under
//! both rules is decided, with messages for the user, by the checker
//! (`uniform_layout` in `sema/check/decls.rs`), whatever targets are
//! requested. Here every block of the lowered module is checked again,
//! member by member against std140, as a consistency check of the lowering:
//! a difference (an offset, array stride or matrix stride the lowering got
//! wrong) is an internal error, never shaders that disagree about their own
//! buffers.

use std::collections::BTreeMap;

use naga::proc::Layouter;
use naga::{ArraySize, Handle, Module, ScalarKind, ShaderStage, Type, TypeInner, VectorSize};

use super::glsl::{self, EntryNames};
use super::glsl_names::digit;
use super::reflect_types::{EntryPoint, Io, Member, ProgramLink, Reflection, Requirements, Sampler, SpecConstant, StorageBuffer, StorageImage, StructLayout, Uniform, UniformBuffer, REFLECTION_FORMAT};
use crate::diag::Diagnostic;
use crate::lower::{EntryInterface, GlUniforms, Interface, IoVar, Lowered, ResourceKind};
use crate::sema::{ConstValue, SamplerKind, Ty};
use crate::target::Target;

pub fn file_name(stem: &str) -> String {
    [stem, ".reflect.json"].concat()
}

/// The layout of one uniform block.
#[derive(Clone, Debug)]
pub struct BlockLayout {
    pub size: u32,
    pub members: Vec<Member>,
}

/// The layouts of the uniform blocks and of the struct types in them.
#[derive(Clone, Debug)]
pub struct UniformLayouts {
    /// Indexed like `interface.resources`; `None` for samplers.
    pub blocks: Vec<Option<BlockLayout>>,
    /// [`Reflection::structs`].
    pub structs: Vec<StructLayout>,
}

fn round_up(align: u32, x: u32) -> u32 {
    x.div_ceil(align.max(1)) * align.max(1)
}

/// Layouts of every uniform resource and of every struct type in them. A
/// block whose std140 layout differs from its WGSL layout in the IR is a
/// lowering bug (the checker refuses every DSL type whose layouts differ),
/// reported as one.
pub fn uniform_layouts(lowered: &Lowered) -> Result<UniformLayouts, Diagnostic> {
    let module = &lowered.gpu;
    let mut layouter = Layouter::default();
    layouter
        .update(module.to_ctx())
        .map_err(|e| Diagnostic::bug(format!("cannot lay out the types of the GPU module: {e}"), None))?;

    let mut out = Vec::with_capacity(lowered.interface.resources.len());
    let mut structs = Structs::default();
    for (ri, r) in lowered.interface.resources.iter().enumerate() {
        let ResourceKind::Uniform { ty, loose, .. } = &r.kind else {
            out.push(None);
            continue;
        };
        let Ok(t) = module.types.get_handle(*ty) else {
            return Err(Diagnostic::bug(format!("uniform `{}` has a type that is not in the GPU module", r.name), Some(r.span)));
        };
        if let Err(why) = std140(module, *ty, &|| r.name.clone()) {
            return Err(Diagnostic::bug(
                format!("the lowering produced uniform buffer `{}` whose layout differs between GLSL std140 and the WGSL uniform rules: {why}", r.name),
                Some(r.span),
            ));
        }
        structs.visit_members(module, &layouter, *ty)?;
        if !*loose {
            structs.visit(module, &layouter, *ty)?;
        }
        // A uniform of another module than umbrac's own (a test's WGSL)
        // may be a loose value: a buffer of that one member.
        let one = [naga::StructMember { name: Some(r.name.clone()), ty: *ty, binding: None, offset: 0 }];
        let fields: &[naga::StructMember] = match &t.inner {
            TypeInner::Struct { members, .. } => members,
            _ => &one,
        };
        let mut members: Vec<Member> = fields
            .iter()
            .enumerate()
            .map(|(i, m)| member(module, &layouter, m.name.clone().unwrap_or_else(|| format!("_{i}")), dsl_name(module, m.ty), m.ty, m.offset))
            .collect();
        let bad = |why: String| Diagnostic::bug(format!("the default of uniform `{}` does not fit its type: {why}", r.name), Some(r.span));
        if *loose {
            // Members are the loose uniforms: their own types, and how
            // the buffer stores them.
            for u in lowered.interface.loose.iter().filter(|u| u.buffer == ri) {
                let Some((m, field)) = members.get_mut(u.member as usize).zip(fields.get(u.member as usize)) else {
                    return Err(Diagnostic::bug(format!("uniform `{}` is no member of its buffer `{}`", u.name, r.name), Some(u.span)));
                };
                m.ty = u.dsl_type.clone();
                m.storage = u.storage.clone();
                if let Ty::Matrix(..) = u.ty {
                    // Columns stored as an array of `float4`.
                    m.matrix_stride = m.matrix_stride.or(m.array_stride.take());
                }
                if let Some(v) = u.stored_default() {
                    m.default = Some(default_words(module, &layouter, field.ty, &v).map_err(bad)?);
                }
            }
        } else if let Some(v) = &r.default {
            let ConstValue::Composite(values) = v else { return Err(bad("a struct default that is no composite".into())) };
            for ((m, field), value) in members.iter_mut().zip(fields.iter()).zip(values) {
                m.default = Some(default_words(module, &layouter, field.ty, value).map_err(bad)?);
            }
        }
        out.push(Some(BlockLayout { size: round_up(16, layouter[*ty].size), members }));
    }
    Ok(UniformLayouts { blocks: out, structs: structs.list })
}

/// The struct types reached from uniform blocks, in [`Reflection::structs`]
/// order.
#[derive(Default)]
struct Structs {
    list: Vec<StructLayout>,
    seen: Vec<Handle<Type>>,
}

impl Structs {
    /// Adds the struct types inside the members of struct `ty`.
    fn visit_members(&mut self, module: &Module, layouter: &Layouter, ty: Handle<Type>) -> Result<(), Diagnostic> {
        if let TypeInner::Struct { members, .. } = &module.types[ty].inner {
            for m in members {
                self.visit(module, layouter, m.ty)?;
            }
        }
        Ok(())
    }

    /// Adds the struct types inside `ty` (and `ty` itself), each after the
    /// structs it contains.
    fn visit(&mut self, module: &Module, layouter: &Layouter, ty: Handle<Type>) -> Result<(), Diagnostic> {
        match &module.types[ty].inner {
            TypeInner::Array { base, .. } => self.visit(module, layouter, *base),
            TypeInner::Struct { members, .. } => {
                if self.seen.contains(&ty) {
                    return Ok(());
                }
                for m in members {
                    self.visit(module, layouter, m.ty)?;
                }
                let name = dsl_name(module, ty);
                if self.list.iter().any(|s| s.name == name) {
                    return Err(Diagnostic::bug(format!("two struct types in uniform blocks are both named `{name}`"), None));
                }
                self.seen.push(ty);
                self.list.push(StructLayout {
                    name,
                    size: layouter[ty].size,
                    members: members
                        .iter()
                        .enumerate()
                        .map(|(i, m)| member(module, layouter, m.name.clone().unwrap_or_else(|| format!("_{i}")), dsl_name(module, m.ty), m.ty, m.offset))
                        .collect(),
                });
                Ok(())
            }
            _ => Ok(()),
        }
    }
}

fn member(module: &Module, layouter: &Layouter, name: String, ty_name: String, ty: Handle<Type>, offset: u32) -> Member {
    let inner = &module.types[ty].inner;
    Member {
        name,
        ty: ty_name,
        offset,
        size: layouter[ty].size,
        array_stride: match *inner {
            TypeInner::Array { stride, .. } => Some(stride),
            _ => None,
        },
        matrix_stride: match *inner {
            TypeInner::Matrix { rows, scalar, .. } => Some(vec_align(rows, scalar.width as u32)),
            _ => None,
        },
        storage: None,
        glsl_name: None,
        default: None,
    }
}

/// `v`, a value of type `ty`, as the 32-bit words of its layout (`out`
/// holds `ty`'s size; `at` is a word index into it).
fn value_words(module: &Module, ty: Handle<Type>, v: &ConstValue, out: &mut [u32], at: usize) -> Result<(), String> {
    let word = |v: &ConstValue| match *v {
        ConstValue::Float(f) => Ok((f as f32).to_bits()),
        ConstValue::Int(i) => Ok(i as i32 as u32),
        ConstValue::Uint(u) => Ok(u as u32),
        ConstValue::Bool(b) => Ok(b as u32),
        ConstValue::Composite(_) => Err("a composite where a scalar belongs".to_string()),
    };
    let mut put = |k: usize, w: u32| match out.get_mut(k) {
        Some(slot) => {
            *slot = w;
            Ok(())
        }
        None => Err(format!("word {k} is outside the value's {} words", out.len())),
    };
    let parts = |v: &ConstValue| match v {
        ConstValue::Composite(p) => Ok(p.clone()),
        _ => Err("a scalar where a composite belongs".to_string()),
    };
    match &module.types[ty].inner {
        TypeInner::Scalar(_) => put(at, word(v)?),
        TypeInner::Vector { .. } => {
            for (i, c) in parts(v)?.iter().enumerate() {
                put(at + i, word(c)?)?;
            }
            Ok(())
        }
        TypeInner::Matrix { rows, scalar, .. } => {
            let stride = vec_align(*rows, scalar.width as u32) as usize / 4;
            for (c, col) in parts(v)?.iter().enumerate() {
                for (r, x) in parts(col)?.iter().enumerate() {
                    put(at + c * stride + r, word(x)?)?;
                }
            }
            Ok(())
        }
        TypeInner::Array { base, stride, .. } => {
            for (i, e) in parts(v)?.iter().enumerate() {
                value_words(module, *base, e, out, at + i * *stride as usize / 4)?;
            }
            Ok(())
        }
        TypeInner::Struct { members, .. } => {
            for (m, f) in members.iter().zip(parts(v)?.iter()) {
                value_words(module, m.ty, f, out, at + m.offset as usize / 4)?;
            }
            Ok(())
        }
        other => Err(format!("{other:?} has no value")),
    }
}

/// A value's components in order, as 32-bit words, no padding (what
/// `glUniform*v` takes).
fn flat_words(v: &ConstValue) -> Vec<u32> {
    fn walk(v: &ConstValue, out: &mut Vec<u32>) {
        match *v {
            ConstValue::Float(f) => out.push((f as f32).to_bits()),
            ConstValue::Int(i) => out.push(i as i32 as u32),
            ConstValue::Uint(u) => out.push(u as u32),
            ConstValue::Bool(b) => out.push(b as u32),
            ConstValue::Composite(ref parts) => parts.iter().for_each(|p| walk(p, out)),
        }
    }
    let mut out = Vec::new();
    walk(v, &mut out);
    out
}

/// The default words of a member of type `ty` holding `v`.
fn default_words(module: &Module, layouter: &Layouter, ty: Handle<Type>, v: &ConstValue) -> Result<Vec<u32>, String> {
    let mut out = vec![0u32; layouter[ty].size as usize / 4];
    value_words(module, ty, v, &mut out, 0)?;
    Ok(out)
}

fn vec_align(size: VectorSize, width: u32) -> u32 {
    match size {
        VectorSize::Bi => 2 * width,
        _ => 4 * width,
    }
}

/// std140 size and alignment of `ty`, or why its explicit layout in the IR
/// (struct offsets, array strides, matrix column strides) differs from it.
/// `path` spells where `ty` is (`u_light.colors[]`); it is formatted only
/// for an error, as this runs for every uniform of every compile.
fn std140(module: &Module, ty: Handle<Type>, path: &dyn Fn() -> String) -> Result<(u32, u32), String> {
    let t = &module.types[ty];
    match t.inner {
        TypeInner::Scalar(s) if s.kind != ScalarKind::Bool => Ok((s.width as u32, s.width as u32)),
        TypeInner::Vector { size, scalar } if scalar.kind != ScalarKind::Bool => {
            let w = scalar.width as u32;
            Ok((size as u32 * w, vec_align(size, w)))
        }
        TypeInner::Matrix { columns, rows, scalar } => {
            if rows == VectorSize::Bi {
                return Err(format!("`{}` is a {}: std140 column stride 16, WGSL column stride 8", path(), dsl_name(module, ty)));
            }
            let _ = scalar;
            Ok((columns as u32 * 16, 16))
        }
        TypeInner::Array { base, size: ArraySize::Constant(n), stride } => {
            let (bs, ba) = std140(module, base, &|| [path().as_str(), "[]"].concat())?;
            let align = round_up(16, ba);
            let std_stride = round_up(align, bs);
            if std_stride != stride {
                return Err(format!("`{}`: std140 array stride {std_stride}, WGSL array stride {stride}", path()));
            }
            Ok((n.get() * stride, align))
        }
        TypeInner::Struct { ref members, .. } => {
            let mut end = 0;
            let mut align = 16;
            for (i, m) in members.iter().enumerate() {
                let member_path = || {
                    let name = m.name.clone().unwrap_or_else(|| format!("_{i}"));
                    format!("{}.{name}", path())
                };
                let (ms, ma) = std140(module, m.ty, &member_path)?;
                let offset = round_up(ma, end);
                if offset != m.offset {
                    return Err(format!("`{}`: std140 offset {offset}, WGSL offset {}", member_path(), m.offset));
                }
                end = offset + ms;
                align = align.max(ma);
            }
            let align = round_up(16, align);
            Ok((round_up(align, end), align))
        }
        _ => Err(format!("`{}` has type {}, which cannot be in a uniform block", path(), dsl_name(module, ty))),
    }
}

/// The DSL spelling of a naga type (`float3`, `float4x4`, `Light`, `float[4]`).
pub fn dsl_name(module: &Module, ty: Handle<Type>) -> String {
    let t = &module.types[ty];
    let scalar = |k: ScalarKind| match k {
        ScalarKind::Float | ScalarKind::AbstractFloat => "float",
        ScalarKind::Sint | ScalarKind::AbstractInt => "int",
        ScalarKind::Uint => "uint",
        ScalarKind::Bool => "bool",
    };
    match t.inner {
        TypeInner::Scalar(s) => scalar(s.kind).to_string(),
        TypeInner::Vector { size, scalar: s } => [scalar(s.kind), digit(size)].concat(),
        TypeInner::Matrix { columns, rows, .. } => ["float", digit(columns), "x", digit(rows)].concat(),
        TypeInner::Array { base, size: ArraySize::Constant(n), .. } => format!("{}[{n}]", dsl_name(module, base)),
        TypeInner::Struct { .. } => t.name.clone().unwrap_or_else(|| "struct".into()),
        _ => t.name.clone().unwrap_or_else(|| format!("{:?}", t.inner)),
    }
}

/// wgpu's name for a vertex attribute of this type, and its packed size.
fn vertex_format(module: &Module, ty: Handle<Type>) -> (Option<String>, u32) {
    let (kind, n, width) = match module.types[ty].inner {
        TypeInner::Scalar(s) => (s.kind, 1, s.width as u32),
        TypeInner::Vector { size, scalar } => (scalar.kind, size as u32, scalar.width as u32),
        TypeInner::Matrix { columns, rows, scalar } => return (None, columns as u32 * rows as u32 * scalar.width as u32),
        _ => return (None, 0),
    };
    let base = match (kind, width) {
        (ScalarKind::Float, 4) => "Float32",
        (ScalarKind::Sint, 4) => "Sint32",
        (ScalarKind::Uint, 4) => "Uint32",
        _ => return (None, n * width),
    };
    let name = if n == 1 { base.to_string() } else { format!("{base}x{n}") };
    (Some(name), n * width)
}

fn stage_name(stage: ShaderStage) -> &'static str {
    match stage {
        ShaderStage::Vertex => "vertex",
        ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Mesh => "mesh",
        naga::ShaderStage::Task => "task",
        _ => "compute",
    }
}

/// Builds the manifest. `glsl_names[i]` holds the GLSL identifiers of
/// `interface.entry_points[i]`.
pub fn build(
    lowered: &Lowered,
    stem: &str,
    source_name: &str,
    targets: &[Target],
    glsl_names: &[EntryNames],
    layouts: &UniformLayouts,
) -> Result<Reflection, Diagnostic> {
    let iface = &lowered.interface;
    let module = &lowered.gpu;

    // GLSL names of each resource, agreed by every entry point using it.
    let mut res_glsl: BTreeMap<usize, String> = BTreeMap::new();
    for (ep, names) in iface.entry_points.iter().zip(glsl_names) {
        let mut declared: Vec<(usize, &String)> = names.blocks.iter().chain(names.samplers.iter()).map(|(g, n)| (*g, n)).collect();
        declared.sort();
        for (global, name) in declared {
            let Some(ri) = iface.resources.iter().position(|r| r.global.index() == global) else {
                return Err(Diagnostic::bug(format!("GLSL of `{}` declares `{name}`, which is no resource of the interface", ep.name), None));
            };
            if !ep.resources.contains(&ri) {
                return Err(Diagnostic::bug(
                    format!("GLSL of `{}` declares `{name}`, but the interface does not list it as used by that entry point", ep.name),
                    None,
                ));
            }
            match res_glsl.get(&ri) {
                Some(prev) if prev != name => {
                    return Err(Diagnostic::bug(format!("resource `{}` has GLSL names `{prev}` and `{name}` in different stages", iface.resources[ri].name), None))
                }
                _ => {
                    res_glsl.insert(ri, name.clone());
                }
            }
        }
    }

    // The GLSL name of each plain uniform, agreed by every entry point.
    let mut uniform_glsl: BTreeMap<&str, &String> = BTreeMap::new();
    for (ep, names) in iface.entry_points.iter().zip(glsl_names) {
        for (source, name) in &names.uniforms {
            match uniform_glsl.insert(source, name) {
                Some(prev) if prev != name => {
                    return Err(Diagnostic::bug(format!("uniform `{source}` has GLSL names `{prev}` and `{name}` in different stages (`{}`)", ep.name), None))
                }
                _ => {}
            }
        }
    }

    let image_glsl: BTreeMap<&String, &String> = glsl_names.iter().flat_map(|n| n.images.iter()).collect();
    let mut block_members: BTreeMap<usize, &Vec<String>> = BTreeMap::new();
    for names in glsl_names {
        for (global, members) in &names.block_members {
            if block_members.insert(*global, members).is_some_and(|prev| prev != members) {
                return Err(Diagnostic::bug(format!("a uniform block declares different members in different stages: {members:?}"), None));
            }
        }
    }
    let mut uniform_buffers = Vec::new();
    let mut samplers = Vec::new();
    let mut storage_buffers = Vec::new();
    let mut storage_images = Vec::new();
    let mut next_unit = 0;
    for (ri, r) in iface.resources.iter().enumerate() {
        match &r.kind {
            ResourceKind::Uniform { dsl_type, loose, .. } => {
                let Some(Some(layout)) = layouts.blocks.get(ri) else {
                    return Err(Diagnostic::bug(format!("no layout for uniform `{}`", r.name), Some(r.span)));
                };
                let glsl_block = match (*loose, iface.gl_uniforms) {
                    (true, GlUniforms::Plain) => None,
                    _ => Some(res_glsl.get(&ri).cloned().unwrap_or_else(|| super::glsl::block_name(&r.name))),
                };
                let mut members = layout.members.clone();
                if let (Some(block), Some(glsl)) = (&glsl_block, block_members.get(&r.global.index())) {
                    // The names the GLSL declares the block's members by
                    // (agreed by every stage).
                    for (m, name) in members.iter_mut().zip(glsl.iter()) {
                        m.glsl_name = Some([block.as_str(), ".", name].concat());
                    }
                }
                uniform_buffers.push(UniformBuffer {
                    name: r.name.clone(),
                    ty: dsl_type.clone(),
                    loose: *loose,
                    size: layout.size,
                    group: r.group,
                    binding: r.binding,
                    glsl_binding: glsl_block.as_ref().and_then(|_| iface.gl_block_points.get(ri).copied().flatten()),
                    glsl_block,
                    members,
                    push_constant: iface.push_constants.contains(&r.name).then_some(true),
                });
            }
            ResourceKind::Sampler(kind) => {
                let Some(sampler_binding) = r.sampler_binding else {
                    return Err(Diagnostic::bug(format!("sampler `{}` has no sampler binding", r.name), Some(r.span)));
                };
                let texture_unit = r.texture_unit.unwrap_or(next_unit);
                next_unit = next_unit.max(texture_unit + 1);
                samplers.push(Sampler {
                    name: r.name.clone(),
                    ty: kind.name().to_string(),
                    glsl_name: res_glsl.get(&ri).cloned().unwrap_or_else(|| r.name.clone()),
                    texture_unit,
                    group: r.group,
                    texture_binding: r.binding,
                    sampler_binding,
                    dimension: dimension(*kind).into(),
                    sample_type: sample_type(*kind).into(),
                    comparison: kind.is_shadow(),
                    count: r.count,
                });
            }
            ResourceKind::Storage { ty, dsl_type, access } => {
                let (members, size, runtime_stride) = storage_members(module, *ty);
                storage_buffers.push(StorageBuffer {
                    name: r.name.clone(),
                    ty: dsl_type.clone(),
                    access: access.name().to_string(),
                    size,
                    runtime_stride,
                    group: r.group,
                    binding: r.binding,
                    glsl_block: super::glsl::storage_block_name(&r.name),
                    glsl_binding: r.texture_unit.unwrap_or(0),
                    members,
                });
            }
            ResourceKind::Image { kind, format, access } => {
                storage_images.push(StorageImage {
                    name: r.name.clone(),
                    ty: kind.name(),
                    format: format.name().to_string(),
                    wgpu_format: format.wgsl_name().to_string(),
                    access: access.name().to_string(),
                    dimension: match kind.dim {
                        crate::sema::types::ImageDim::D2 => "2d",
                        crate::sema::types::ImageDim::D3 => "3d",
                        crate::sema::types::ImageDim::D2Array => "2d-array",
                    }
                    .to_string(),
                    group: r.group,
                    binding: r.binding,
                    glsl_name: image_glsl.get(&r.name).map_or_else(|| r.name.clone(), |n| (*n).clone()),
                    image_unit: r.texture_unit.unwrap_or(0),
                });
            }
        }
    }

    let uniforms = iface
        .loose
        .iter()
        .map(|u| Uniform {
            name: u.name.clone(),
            ty: u.dsl_type.clone(),
            buffer: iface.resources.get(u.buffer).map(|r| r.name.clone()).unwrap_or_default(),
            glsl_name: match iface.gl_uniforms {
                GlUniforms::Plain => Some(uniform_glsl.get(u.name.as_str()).map_or_else(|| u.name.clone(), |n| (*n).clone())),
                GlUniforms::Blocks => None,
            },
            glsl_type: super::glsl_names::glsl_type(module, u.value_ty),
            default: u.default.as_ref().map(flat_words),
        })
        .collect();

    // The per-module file names, made once for every entry point.
    let module_files = ModuleFiles { wgsl: [stem, ".wgsl"].concat(), spirv: [stem, ".spv"].concat() };
    let mut entry_points = Vec::with_capacity(iface.entry_points.len());
    for (ep, names) in iface.entry_points.iter().zip(glsl_names) {
        entry_points.push(entry_point(module, ep, names, &module_files, targets, iface)?);
    }

    let programs = iface
        .links
        .iter()
        .map(|&(v, f)| ProgramLink { vertex: iface.entry_points[v].name.clone(), fragment: iface.entry_points[f].name.clone() })
        .collect();
    Ok(Reflection {
        format: REFLECTION_FORMAT,
        source: source_name.to_string(),
        conventions: iface.conventions.as_str().to_string(),
        entry_points,
        programs,
        gl_uniforms: iface.gl_uniforms.as_str().to_string(),
        uniform_buffers,
        uniforms,
        structs: layouts.structs.clone(),
        samplers,
        storage_buffers: (!storage_buffers.is_empty()).then_some(storage_buffers),
        storage_images: (!storage_images.is_empty()).then_some(storage_images),
        required_limits: if targets.iter().any(|t| matches!(t, Target::Wgsl | Target::Spirv)) { super::limits::webgpu_requirements(lowered) } else { None },
        requires: requirements(module),
        specialization_constants: spec_constants(module),
    })
}

/// What the GPU module needs a host to enable, if anything.
fn requirements(module: &naga::Module) -> Option<Requirements> {
    use naga::BuiltIn as B;
    let mut r = Requirements::default();
    let reads = |b: B| module.entry_points.iter().any(|ep| ep.function.arguments.iter().any(|a| a.binding == Some(naga::Binding::BuiltIn(b))));
    let subgroups = super::wgsl::uses_subgroups(module);
    if subgroups {
        r.wgpu_features.push("SUBGROUP".into());
        r.wgsl_enable.push("subgroups".into());
        r.vulkan.push("subgroupSupportedOperations (basic, vote, arithmetic, ballot, shuffle, shuffle_relative as used) in compute and fragment stages".into());
    }
    if reads(B::PrimitiveIndex) {
        r.wgpu_features.push("PRIMITIVE_INDEX".into());
        r.wgsl_enable.push("primitive_index".into());
        r.vulkan.push("geometryShader (PrimitiveId in fragment shaders)".into());
    }
    if reads(B::DrawIndex) {
        r.vulkan.push("shaderDrawParameters".into());
    }
    let mesh = module.entry_points.iter().any(|e| matches!(e.stage, naga::ShaderStage::Mesh | naga::ShaderStage::Task));
    if mesh {
        r.vulkan.push("VK_EXT_mesh_shader: meshShader, taskShader (as the program has them)".into());
    }
    let primitive_id_written = module.entry_points.iter().filter_map(|e| e.mesh_info.as_ref()).any(|m| match &module.types[m.primitive_output_type].inner {
        naga::TypeInner::Struct { members, .. } => members.iter().any(|mb| mb.binding == Some(naga::Binding::BuiltIn(B::PrimitiveIndex))),
        _ => false,
    });
    if primitive_id_written {
        r.vulkan.push("geometryShader (the Geometry capability naga declares for a mesh shader's gl_PrimitiveID)".into());
    }
    // A Vulkan-dialect descriptor array (a binding array of images).
    if module.global_variables.iter().any(|(_, g)| matches!(module.types[g.ty].inner, naga::TypeInner::BindingArray { .. })) {
        r.vulkan.push("shaderSampledImageArrayNonUniformIndexing (descriptor arrays indexed with nonuniformEXT; VK_EXT_descriptor_indexing)".into());
    }
    if r == Requirements::default() {
        return None;
    }
    let (major, minor) = super::spirv::version(module);
    r.spirv_version = format!("{major}.{minor}");
    Some(r)
}

/// The module's overrides, with their defaults.
fn spec_constants(module: &naga::Module) -> Option<Vec<SpecConstant>> {
    let list: Vec<SpecConstant> = module
        .overrides
        .iter()
        .filter_map(|(_, o)| {
            let naga::Expression::Literal(l) = module.global_expressions[o.init?] else { return None };
            let (ty, default, default_bits) = match l {
                naga::Literal::Bool(b) => ("bool", f64::from(u8::from(b)), u32::from(b)),
                naga::Literal::I32(v) => ("int", f64::from(v), v as u32),
                naga::Literal::U32(v) => ("uint", f64::from(v), v),
                naga::Literal::F32(v) => ("float", f64::from(v), v.to_bits()),
                _ => return None,
            };
            Some(SpecConstant {
                name: o.name.clone().unwrap_or_default(),
                id: u32::from(o.id?),
                ty: ty.into(),
                default,
                default_bits,
                wgsl: "override".into(),
                spirv: "spec_constant".into(),
                glsl: "default".into(),
            })
        })
        .collect();
    (!list.is_empty()).then_some(list)
}

/// `STEM.wgsl` and `STEM.spv`.
struct ModuleFiles {
    wgsl: String,
    spirv: String,
}

fn entry_point(
    module: &Module,
    ep: &EntryInterface,
    names: &EntryNames,
    module_files: &ModuleFiles,
    targets: &[Target],
    iface: &crate::lower::Interface,
) -> Result<EntryPoint, Diagnostic> {
    let mut files = BTreeMap::new();
    for t in targets {
        let f = match t {
            Target::Glsl330 => glsl::file_name(&ep.name, ep.stage, glsl::Profile::Desktop330),
            Target::Gles300 => glsl::file_name(&ep.name, ep.stage, glsl::Profile::Es300),
            Target::Glsl430 => glsl::file_name(&ep.name, ep.stage, glsl::Profile::Desktop430),
            Target::Gles310 => glsl::file_name(&ep.name, ep.stage, glsl::Profile::Es310),
            Target::Wgsl => module_files.wgsl.clone(),
            Target::Spirv => module_files.spirv.clone(),
        };
        files.insert(t.name().to_string(), f);
    }
    let vertex = ep.stage == ShaderStage::Vertex;
    let io = |vars: &[IoVar], glsl: &BTreeMap<u32, String>, output: bool, attributes: bool, varyings: bool| -> Result<Vec<Io>, Diagnostic> {
        let mut v = vars
            .iter()
            .map(|var| {
                let (format, size) = vertex_format(module, var.ty);
                // A mesh entry point has no GLSL: its per-vertex outputs
                // are named as the GLSL fragment stage names its inputs.
                let mesh = (ep.stage == ShaderStage::Mesh).then(|| glsl::vulkan_varying_name(var.location));
                let glsl_name = mesh.or_else(|| glsl.get(&var.location).cloned()).ok_or_else(|| {
                    Diagnostic::bug(format!("GLSL of `{}` has no variable for `{}` at location {}", ep.name, var.name, var.location), None)
                })?;
                Ok(Io {
                    name: var.name.clone(),
                    location: var.location,
                    ty: var.dsl_type.clone(),
                    vertex_format: if attributes { format } else { None },
                    size,
                    interpolation: if varyings {
                        Some(
                            match var.interpolation.unwrap_or(naga::Interpolation::Perspective) {
                                naga::Interpolation::Flat => "flat",
                                naga::Interpolation::Linear => "linear",
                                _ => "perspective",
                            }
                            .to_string(),
                        )
                    } else {
                        None
                    },
                    glsl_location: names.located.contains(&(output, var.location)).then_some(var.location),
                    glsl_name,
                })
            })
            .collect::<Result<Vec<_>, Diagnostic>>()?;
        v.sort_by_key(|io| io.location);
        Ok(v)
    };
    let inputs = io(&ep.inputs, &names.inputs, false, vertex, !vertex)?;
    let outputs = io(&ep.outputs, &names.outputs, true, false, vertex)?;

    let mut uniform_buffers = Vec::new();
    let mut samplers = Vec::new();
    let (mut storage_buffers, mut storage_images) = (Vec::new(), Vec::new());
    for &ri in &ep.resources {
        let Some(r) = iface.resources.get(ri) else {
            return Err(Diagnostic::bug(format!("entry point `{}` uses resource #{ri}, which does not exist", ep.name), None));
        };
        match r.kind {
            ResourceKind::Uniform { .. } => uniform_buffers.push(r.name.clone()),
            ResourceKind::Sampler(_) => samplers.push(r.name.clone()),
            ResourceKind::Storage { .. } => storage_buffers.push(r.name.clone()),
            ResourceKind::Image { .. } => storage_images.push(r.name.clone()),
        }
    }
    let uniforms = ep.loose.iter().filter_map(|&u| iface.loose.get(u)).map(|u| u.name.clone()).collect();
    let clip_space = vulkan_clip_space(ep, iface, &files);
    Ok(EntryPoint {
        name: ep.name.clone(),
        stage: stage_name(ep.stage).into(),
        files,
        inputs,
        outputs,
        builtins: ep.builtins.clone(),
        uniform_buffers,
        uniforms,
        samplers,
        workgroup_size: matches!(ep.stage, ShaderStage::Compute | ShaderStage::Mesh | ShaderStage::Task).then_some(ep.workgroup_size),
        storage_buffers: (!storage_buffers.is_empty()).then_some(storage_buffers),
        storage_images: (!storage_images.is_empty()).then_some(storage_images),
        dialect: (ep.dialect == crate::syntax::ast::Dialect::Vulkan).then(|| "vulkan".to_string()),
        clip_space,
    })
}

/// What each target does to a Vulkan-dialect vertex entry point's
/// `gl_Position` (`lower::entry`'s adaptation), by the target names of
/// `files`.
fn vulkan_clip_space(ep: &EntryInterface, iface: &Interface, files: &std::collections::BTreeMap<String, String>) -> Option<std::collections::BTreeMap<String, String>> {
    if ep.dialect != crate::syntax::ast::Dialect::Vulkan || ep.stage != ShaderStage::Vertex {
        return None;
    }
    let portable = iface.conventions == crate::lower::Conventions::Portable;
    let what = |t: &str| match (portable, t) {
        (false, _) => "none",
        (true, "wgsl" | "spirv") => "y' = -y",
        (true, _) => "z' = 2z - w",
    };
    Some(files.keys().map(|t| (t.clone(), what(t).to_string())).collect())
}

/// The members of a storage buffer's struct at their std430 offsets (naga's
/// natural layout, WGSL's storage rules, is std430's), the size before a
/// run-time-sized array, and that array's stride.
fn storage_members(module: &Module, ty: naga::Handle<naga::Type>) -> (Vec<Member>, u32, Option<u32>) {
    // dasSpirv's `@ssbo x : array<T>`: the buffer is the run-time array.
    if let naga::TypeInner::Array { size: ArraySize::Dynamic, stride, .. } = module.types[ty].inner {
        return (Vec::new(), 0, Some(stride));
    }
    let naga::TypeInner::Struct { members, span } = &module.types[ty].inner else { return (Vec::new(), 0, None) };
    let mut out = Vec::with_capacity(members.len());
    let mut runtime = None;
    let mut layouter = naga::proc::Layouter::default();
    let _ = layouter.update(module.to_ctx());
    for m in members {
        let (size, array_stride, matrix_stride) = match &module.types[m.ty].inner {
            naga::TypeInner::Array { size: naga::ArraySize::Dynamic, stride, .. } => {
                runtime = Some((*stride, m.offset));
                (0, Some(*stride), None)
            }
            naga::TypeInner::Array { stride, .. } => (layouter[m.ty].size, Some(*stride), None),
            naga::TypeInner::Matrix { rows, .. } => (layouter[m.ty].size, None, Some(if *rows == naga::VectorSize::Bi { 8 } else { 16 })),
            _ => (layouter[m.ty].size, None, None),
        };
        out.push(Member {
            name: m.name.clone().unwrap_or_default(),
            ty: dsl_type_name(module, m.ty),
            offset: m.offset,
            size,
            array_stride,
            matrix_stride,
            storage: None,
            glsl_name: None,
            default: None,
        });
    }
    match runtime {
        Some((stride, offset)) => (out, offset, Some(stride)),
        None => (out, *span, None),
    }
}

/// The DSL spelling of a naga type of a storage buffer (atomics as their
/// integer, run-time arrays as `T[]`).
fn dsl_type_name(module: &Module, ty: naga::Handle<naga::Type>) -> String {
    let scalar = |s: naga::Scalar| match s.kind {
        ScalarKind::Sint => "int",
        ScalarKind::Uint => "uint",
        ScalarKind::Bool => "bool",
        _ if s.width == 2 => "half",
        _ => "float",
    };
    match &module.types[ty].inner {
        naga::TypeInner::Scalar(s) | naga::TypeInner::Atomic(s) => scalar(*s).to_string(),
        naga::TypeInner::Vector { size, scalar: s } => [scalar(*s), digit(*size)].concat(),
        naga::TypeInner::Matrix { columns, rows, .. } => ["float", digit(*columns), "x", digit(*rows)].concat(),
        naga::TypeInner::Array { base, size: naga::ArraySize::Constant(n), .. } => format!("{}[{n}]", dsl_type_name(module, *base)),
        naga::TypeInner::Array { base, .. } => format!("{}[]", dsl_type_name(module, *base)),
        _ => module.types[ty].name.clone().unwrap_or_default(),
    }
}

fn dimension(kind: SamplerKind) -> &'static str {
    match kind.dim() {
        naga::ImageDimension::D3 => "3d",
        naga::ImageDimension::Cube => "cube",
        _ if kind.is_array() => "2d-array",
        _ => "2d",
    }
}

fn sample_type(kind: SamplerKind) -> &'static str {
    match kind.image_class() {
        naga::ImageClass::Depth { .. } => "depth",
        naga::ImageClass::Sampled { kind: ScalarKind::Sint, .. } => "sint",
        naga::ImageClass::Sampled { kind: ScalarKind::Uint, .. } => "uint",
        _ => "float",
    }
}
