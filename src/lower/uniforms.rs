//! Loose uniforms (every `@uniform` that is not a struct) in a uniform
//! buffer: one per `@set` group, a struct with a member per loose uniform
//! the program reads, in declaration order.
//!
//! The buffer is laid out by WGSL's uniform rules, which are std140's for
//! what it holds: a type whose layouts differ, or that a uniform buffer
//! cannot hold, is stored as one that can, and read back into the DSL type
//! where it is used:
//! - `bool` as `uint` (0 or 1), `boolN` as `uintN`;
//! - an array of scalars or 2-vectors as an array of 4-vectors, each
//!   element in the first components (the 16-byte stride std140 gives);
//! - a two-row matrix (`float2x2`, `float3x2`, `float4x2`) as an array of
//!   `float4` columns (std140's column stride, 16).
//!
//! Reads go through [`Stored`]: a place inside a loose uniform is followed
//! in the stored type, and the value is converted where it is loaded, so
//! `u_weights[i]` loads one `float4` and takes `.x`.

use naga::{Block, Expression as E, Handle};

use super::function::FnBuilder;
use super::interface::{Flavor, GlUniforms, LooseUniform, Resource, ResourceKind};
use super::module::{GlobalSlot, ModuleBuilder};
use crate::sema::{self, ConstValue, Expr, ExprKind, Scalar, Ty};
use crate::source::Span;

/// How a value inside a loose uniform is stored, against its DSL type.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Stored {
    /// As the DSL type.
    Same,
    /// A `bool` or `boolN` as `uint` or `uintN`.
    Bool,
    /// A scalar or 2-vector (of `bool`: of `uint`) in the first components
    /// of a 4-vector: an array element, or a column of a two-row matrix.
    Padded,
    /// A two-row matrix as an array of `float4` columns.
    Columns,
    /// An array whose elements are stored as given.
    Elements(Box<Stored>),
}

/// How a value of type `ty` is stored in a uniform buffer.
pub(super) fn stored(ty: &Ty) -> Stored {
    match ty {
        Ty::Scalar(Scalar::Bool) | Ty::Vector(Scalar::Bool, _) => Stored::Bool,
        Ty::Matrix(_, 2) => Stored::Columns,
        Ty::Array(elem, _) => match &**elem {
            Ty::Scalar(_) | Ty::Vector(_, 2) => Stored::Elements(Box::new(Stored::Padded)),
            e => match stored(e) {
                Stored::Same => Stored::Same,
                s => Stored::Elements(Box::new(s)),
            },
        },
        _ => Stored::Same,
    }
}

fn uint_for_bool(s: Scalar) -> Scalar {
    match s {
        Scalar::Bool => Scalar::Uint,
        s => s,
    }
}

/// The type a value of type `ty` is stored as (see the module docs).
pub(super) fn storage_ty(ty: &Ty) -> Ty {
    match ty {
        Ty::Scalar(Scalar::Bool) => Ty::Scalar(Scalar::Uint),
        Ty::Vector(Scalar::Bool, n) => Ty::Vector(Scalar::Uint, *n),
        Ty::Matrix(c, 2) => Ty::Array(Box::new(Ty::Vector(Scalar::Float, 4)), *c as u32),
        Ty::Array(elem, n) => match &**elem {
            Ty::Scalar(s) | Ty::Vector(s, 2) => Ty::Array(Box::new(Ty::Vector(uint_for_bool(*s), 4)), *n),
            e => Ty::Array(Box::new(storage_ty(e)), *n),
        },
        t => t.clone(),
    }
}

/// A value of type `ty` as its stored form holds it (`true` as `1u`, a
/// `float` array element as a `float4` with zeros after it).
fn storage_value(ty: &Ty, v: &ConstValue) -> ConstValue {
    let zero = |s: Scalar| match s {
        Scalar::Int => ConstValue::Int(0),
        Scalar::Uint | Scalar::Bool => ConstValue::Uint(0),
        _ => ConstValue::Float(0.0),
    };
    let to_uint = |v: &ConstValue| match v {
        ConstValue::Bool(b) => ConstValue::Uint(*b as u64),
        v => v.clone(),
    };
    let parts = |v: &ConstValue| match v {
        ConstValue::Composite(p) => p.clone(),
        v => vec![v.clone()],
    };
    // The first components of a 4-vector of scalar `s`.
    let padded = |s: Scalar, v: &ConstValue| {
        let mut p: Vec<ConstValue> = parts(v).iter().map(to_uint).collect();
        p.resize(4, zero(s));
        ConstValue::Composite(p)
    };
    match (ty, v) {
        (Ty::Scalar(Scalar::Bool), v) => to_uint(v),
        (Ty::Vector(Scalar::Bool, _), ConstValue::Composite(p)) => ConstValue::Composite(p.iter().map(to_uint).collect()),
        (Ty::Matrix(_, 2), ConstValue::Composite(cols)) => ConstValue::Composite(cols.iter().map(|c| padded(Scalar::Float, c)).collect()),
        (Ty::Array(elem, _), ConstValue::Composite(items)) => match &**elem {
            Ty::Scalar(s) | Ty::Vector(s, 2) => ConstValue::Composite(items.iter().map(|x| padded(*s, x)).collect()),
            e => ConstValue::Composite(items.iter().map(|x| storage_value(e, x)).collect()),
        },
        (_, v) => v.clone(),
    }
}

impl LooseUniform {
    /// The default value in its stored form (see [`storage_ty`]).
    pub fn stored_default(&self) -> Option<ConstValue> {
        self.default.as_ref().map(|v| storage_value(&self.ty, v))
    }
}

/// The name of group `group`'s buffer and of its struct type.
fn buffer_names(p: &sema::Program, group: u32) -> (String, String) {
    let (mut var, mut ty) = match group {
        0 => ("uniforms".to_string(), "Uniforms".to_string()),
        g => (format!("set{g}_uniforms"), format!("Set{g}Uniforms")),
    };
    // Apart from every name of the program (a host may see both).
    let taken = |n: &str| p.globals.iter().any(|g| g.name == n) || p.structs.iter().any(|s| s.name == n);
    while taken(&var) {
        var.push('_');
    }
    while taken(&ty) {
        ty.push('_');
    }
    (var, ty)
}

impl ModuleBuilder<'_> {
    /// Whether loose uniforms live in uniform buffers in this module (all
    /// but the GL modules of the plain form).
    pub(super) fn packs_uniforms(&self) -> bool {
        self.flavor != Flavor::Gl || self.gl_uniforms == GlUniforms::Blocks
    }

    /// The slot of loose uniform `gid`: its member of its group's buffer,
    /// declared with the first member asked for. The buffer holds every
    /// loose uniform of the group that some entry point reads, whichever
    /// entry point this module is for, so that every module (and the
    /// manifest) agrees on its layout.
    pub(super) fn uniform_buffer_member(&mut self, gid: sema::GlobalId) -> GlobalSlot {
        let bind = self.p.globals[gid].bind.expect("a used resource is bound");
        if let Some(&(_, buffer, ref members)) = self.uniform_buffers.iter().find(|(b, ..)| *b == bind) {
            let member = members.iter().position(|&g| g == gid).expect("a loose uniform of the group") as u32;
            return GlobalSlot::Packed { buffer, member };
        }
        let p = self.p;
        let members: Vec<sema::GlobalId> = (0..p.globals.len()).filter(|&g| p.globals[g].is_loose_uniform() && p.globals[g].bind == Some(bind)).collect();
        let (var_name, ty_name) = buffer_names(p, bind.group);
        let stored: Vec<Handle<naga::Type>> = members.iter().map(|&g| self.ty(&storage_ty(&p.globals[g].ty))).collect();
        let fields = members.iter().zip(&stored).map(|(&g, &t)| (p.globals[g].name.clone(), t)).collect();
        let ty = self.types.uniform_struct_type(&mut self.module, ty_name.clone(), fields);
        let span: naga::Span = p.globals[members[0]].span.into();
        let with_binding = self.flavor != Flavor::Gl;
        let buffer = self.add_global(var_name.clone(), naga::AddressSpace::Uniform, with_binding.then_some(naga::ResourceBinding { group: bind.group, binding: bind.binding }), ty, None, span);
        if self.flavor != Flavor::Gl {
            let index = self.resources.len();
            self.resources.push(Resource {
                name: var_name,
                span: p.globals[members[0]].span,
                kind: ResourceKind::Uniform { ty, dsl_type: ty_name, loose: true },
                global: buffer,
                sampler_global: None,
                group: bind.group,
                binding: bind.binding,
                sampler_binding: None,
                texture_unit: None,
                default: None,
                count: None,
            });
            for (k, (&g, &stored_ty)) in members.iter().zip(&stored).enumerate() {
                let global = &p.globals[g];
                let storage_of = storage_ty(&global.ty);
                let value_ty = self.ty(&global.ty);
                self.loose_of[g] = Some(self.loose.len());
                self.loose.push(LooseUniform {
                    name: global.name.clone(),
                    span: global.span,
                    dsl_type: self.show_ty(&global.ty),
                    storage: (storage_of != global.ty).then(|| self.show_ty(&storage_of)),
                    ty: global.ty.clone(),
                    stored_ty,
                    value_ty,
                    buffer: index,
                    member: k as u32,
                    default: match &global.kind {
                        sema::GlobalKind::Uniform { default } => default.clone(),
                        _ => None,
                    },
                });
            }
        }
        let member = members.iter().position(|&g| g == gid).expect("a loose uniform of the group") as u32;
        self.uniform_buffers.push((bind, buffer, members));
        GlobalSlot::Packed { buffer, member }
    }
}

impl FnBuilder<'_, '_> {
    /// Whether `e` is (a part of) a loose uniform held in a buffer. Asked
    /// of every expression lowered: inline, so the common answer (not a
    /// place) costs no call.
    #[inline]
    fn in_uniform_buffer(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Global(g) => self.global_slot(*g).is_none() && matches!(self.m.globals[*g], GlobalSlot::Packed { .. }),
            ExprKind::Field(b, _) | ExprKind::Index(b, _) => self.in_uniform_buffer(b),
            ExprKind::Swizzle(b, c) => c.len() == 1 && self.in_uniform_buffer(b),
            _ => false,
        }
    }

    /// The value of `e` if it is (a part of) a loose uniform held in a
    /// buffer: loaded from the stored place and converted.
    #[inline]
    pub(super) fn uniform_buffer_value(&mut self, e: &Expr, block: &mut Block) -> Option<Handle<E>> {
        if self.m.uniform_buffers.is_empty() || !self.in_uniform_buffer(e) {
            return None;
        }
        Some(self.load_from_uniform_buffer(e, block))
    }

    #[inline(never)]
    fn load_from_uniform_buffer(&mut self, e: &Expr, block: &mut Block) -> Handle<E> {
        let (ptr, how) = self.stored_place(e, block);
        self.load_stored(ptr, &how, &e.ty, e.span)
    }

    /// A pointer to where `e` (inside a loose uniform) is stored, and how.
    fn stored_place(&mut self, e: &Expr, block: &mut Block) -> (Handle<E>, Stored) {
        let s = e.span;
        match &e.kind {
            ExprKind::Global(g) => {
                let GlobalSlot::Packed { buffer, member } = self.m.globals[*g] else { unreachable!("checked by in_uniform_buffer") };
                let b = self.append_plain(E::GlobalVariable(buffer), s);
                (self.append(E::AccessIndex { base: b, index: member }, s), stored(&e.ty))
            }
            ExprKind::Field(base, idx) => {
                // A struct is stored as itself (the checker's layout rule).
                let (p, _) = self.stored_place(base, block);
                (self.append(E::AccessIndex { base: p, index: *idx }, s), Stored::Same)
            }
            ExprKind::Index(base, index) => {
                let (p, how) = self.stored_place(base, block);
                let q = match index.kind {
                    ExprKind::Int(k) if k >= 0 => self.append(E::AccessIndex { base: p, index: k as u32 }, s),
                    ExprKind::Uint(k) => self.append(E::AccessIndex { base: p, index: k as u32 }, s),
                    _ => {
                        let i = self.expr(index, block);
                        self.append(E::Access { base: p, index: i }, s)
                    }
                };
                (q, element_storage(how, &e.ty))
            }
            ExprKind::Swizzle(base, comps) => {
                let (p, how) = self.stored_place(base, block);
                (self.append(E::AccessIndex { base: p, index: comps[0] as u32 }, s), element_storage(how, &e.ty))
            }
            _ => unreachable!("checked by in_uniform_buffer"),
        }
    }

    /// Loads a value of type `ty` stored at `ptr` as `how`.
    fn load_stored(&mut self, ptr: Handle<E>, how: &Stored, ty: &Ty, s: Span) -> Handle<E> {
        match how {
            Stored::Same => self.append(E::Load { pointer: ptr }, s),
            Stored::Bool => {
                let v = self.append(E::Load { pointer: ptr }, s);
                self.nonzero(v, ty, s)
            }
            Stored::Padded => {
                let v = self.append(E::Load { pointer: ptr }, s);
                let part = match ty {
                    Ty::Vector(_, n) => self.swizzle(v, &(0..*n).collect::<Vec<u8>>(), s),
                    _ => self.append(E::AccessIndex { base: v, index: 0 }, s),
                };
                match ty.scalar() {
                    Some(Scalar::Bool) => self.nonzero(part, ty, s),
                    _ => part,
                }
            }
            Stored::Columns => {
                let Ty::Matrix(c, r) = ty else { unreachable!("two-row matrices are stored as columns") };
                let column = Ty::Vector(Scalar::Float, *r);
                let cols = (0..*c as u32)
                    .map(|i| {
                        let p = self.append(E::AccessIndex { base: ptr, index: i }, s);
                        self.load_stored(p, &Stored::Padded, &column, s)
                    })
                    .collect();
                let t = self.m.ty(ty);
                self.append(E::Compose { ty: t, components: cols }, s)
            }
            Stored::Elements(inner) => {
                let Ty::Array(elem, n) = ty else { unreachable!("only arrays have elements") };
                let items = (0..*n)
                    .map(|i| {
                        let p = self.append(E::AccessIndex { base: ptr, index: i }, s);
                        self.load_stored(p, inner, elem, s)
                    })
                    .collect();
                let t = self.m.ty(ty);
                self.append(E::Compose { ty: t, components: items }, s)
            }
        }
    }

    /// `v != 0` for a `uint` or `uintN` `v` standing for `ty` (`bool`s).
    fn nonzero(&mut self, v: Handle<E>, ty: &Ty, s: Span) -> Handle<E> {
        let zero = match ty {
            Ty::Vector(_, n) => {
                let t = self.m.ty(&Ty::Vector(Scalar::Uint, *n));
                self.append_plain(E::ZeroValue(t), s)
            }
            _ => self.literal(naga::Literal::U32(0), s),
        };
        self.append(E::Binary { op: naga::BinaryOperator::NotEqual, left: v, right: zero }, s)
    }
}

/// The GL binding point of each uniform block GLSL declares, by resource
/// index, as daslang's GL binder (dasOpenGL) assigns them, so that a host
/// written for daslang binds umbrac's blocks at the same points: every
/// struct `@uniform` of the program, used or not, sorted by name; one
/// with `@binding = N` takes point N, the others the lowest free points
/// in that order. The loose buffers of `--gl-uniforms blocks` (which
/// daslang does not have) follow, by group, at the next free points.
/// Of several blocks asking for one point (the same `@binding` in two
/// `@set`s), the first by name has it; the others take free points.
pub(super) fn gl_block_points(p: &sema::Program, resources: &[Resource], gl_uniforms: GlUniforms) -> Vec<Option<u32>> {
    let mut blocks: Vec<(&str, Option<u32>)> = p
        .globals
        .iter()
        .enumerate()
        .filter(|(_, g)| matches!(g.kind, sema::GlobalKind::Uniform { .. }) && matches!(g.ty, Ty::Struct(_)))
        .map(|(id, g)| (g.name.as_str(), p.written_bindings.get(&id).copied()))
        .collect();
    blocks.sort();
    let mut taken = std::collections::BTreeSet::new();
    let mut point: Vec<(&str, u32)> = Vec::new();
    for &(name, written) in &blocks {
        if let Some(n) = written.filter(|n| taken.insert(*n)) {
            point.push((name, n));
        }
    }
    let mut next = 0;
    let mut free = |taken: &mut std::collections::BTreeSet<u32>| {
        while !taken.insert(next) {
            next += 1;
        }
        next
    };
    for &(name, _) in &blocks {
        if !point.iter().any(|(n, _)| *n == name) {
            let n = free(&mut taken);
            point.push((name, n));
        }
    }
    let mut loose: Vec<(u32, usize)> = Vec::new();
    let out = resources
        .iter()
        .enumerate()
        .map(|(i, r)| match r.kind {
            ResourceKind::Uniform { loose: false, .. } => point.iter().find(|(n, _)| *n == r.name).map(|&(_, n)| n),
            ResourceKind::Uniform { loose: true, .. } if gl_uniforms == GlUniforms::Blocks => {
                loose.push((r.group, i));
                None
            }
            _ => None,
        })
        .collect::<Vec<_>>();
    let mut out = out;
    loose.sort();
    for (_, i) in loose {
        out[i] = Some(free(&mut taken));
    }
    out
}

/// How an element (or component) of a value stored as `how` is stored,
/// the element being of type `ty`.
fn element_storage(how: Stored, ty: &Ty) -> Stored {
    match how {
        Stored::Elements(inner) => *inner,
        // A column of a two-row matrix.
        Stored::Columns => Stored::Padded,
        // A component of a padded vector or of a `uintN`.
        Stored::Padded | Stored::Bool if ty.scalar() == Some(Scalar::Bool) => Stored::Bool,
        _ => Stored::Same,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A program of struct uniforms `(name, written @binding)`, each bound
    /// in group 0, as resources in declaration order.
    fn blocks(decls: &[(&str, Option<u32>)]) -> (sema::Program, Vec<Resource>) {
        let mut p = sema::Program::default();
        let mut resources = Vec::new();
        let mut m = naga::Module::default();
        let ty = m.types.insert(naga::Type { name: None, inner: naga::TypeInner::Scalar(naga::Scalar::F32) }, naga::Span::UNDEFINED);
        let global = m.global_variables.append(naga::GlobalVariable { name: None, space: naga::AddressSpace::Uniform, binding: None, ty, init: None, memory_decorations: Default::default() }, naga::Span::UNDEFINED);
        for (i, &(name, written)) in decls.iter().enumerate() {
            p.globals.push(sema::Global { name: name.into(), ty: Ty::Struct(0), kind: sema::GlobalKind::Uniform { default: None }, span: Span::default(), bind: None });
            if let Some(b) = written {
                p.written_bindings.insert(i, b);
            }
            resources.push(Resource {
                name: name.into(),
                span: Span::default(),
                kind: ResourceKind::Uniform { ty, dsl_type: "S".into(), loose: false },
                global,
                sampler_global: None,
                group: 0,
                binding: i as u32,
                sampler_binding: None,
                texture_unit: None,
                default: None,
                count: None,
            });
        }
        (p, resources)
    }

    #[test]
    fn gl_block_points_follow_daslangs_binder() {
        // Sorted by name, whatever the declaration order.
        let (p, r) = blocks(&[("u_light", None), ("u_cam", None), ("u_mat", None)]);
        assert_eq!(gl_block_points(&p, &r, GlUniforms::Plain), [Some(1), Some(0), Some(2)]);
        // An `@binding` keeps its point; the others fill the free ones.
        let (p, r) = blocks(&[("a", None), ("b", Some(0)), ("c", None)]);
        assert_eq!(gl_block_points(&p, &r, GlUniforms::Plain), [Some(1), Some(0), Some(2)]);
        let (p, r) = blocks(&[("a", Some(5)), ("b", None)]);
        assert_eq!(gl_block_points(&p, &r, GlUniforms::Plain), [Some(5), Some(0)]);
        // One `@binding` in two `@set`s: the first by name keeps it.
        let (p, r) = blocks(&[("b", Some(0)), ("a", Some(0)), ("c", None)]);
        assert_eq!(gl_block_points(&p, &r, GlUniforms::Plain), [Some(1), Some(0), Some(2)]);
    }

    #[test]
    fn storage_of_types_whose_layouts_differ() {
        let f = Ty::Scalar(Scalar::Float);
        assert_eq!(storage_ty(&Ty::Scalar(Scalar::Bool)), Ty::Scalar(Scalar::Uint));
        assert_eq!(storage_ty(&Ty::Array(Box::new(f.clone()), 9)), Ty::Array(Box::new(Ty::Vector(Scalar::Float, 4)), 9));
        assert_eq!(storage_ty(&Ty::Matrix(3, 2)), Ty::Array(Box::new(Ty::Vector(Scalar::Float, 4)), 3));
        assert_eq!(storage_ty(&Ty::Matrix(4, 4)), Ty::Matrix(4, 4));
        assert_eq!(stored(&Ty::Array(Box::new(Ty::Vector(Scalar::Float, 3)), 2)), Stored::Same);
        assert_eq!(stored(&Ty::Array(Box::new(Ty::Matrix(2, 2)), 2)), Stored::Elements(Box::new(Stored::Columns)));
        let v = storage_value(&Ty::Array(Box::new(Ty::Scalar(Scalar::Bool)), 2), &ConstValue::Composite(vec![ConstValue::Bool(true), ConstValue::Bool(false)]));
        let padded = |x| ConstValue::Composite(vec![ConstValue::Uint(x), ConstValue::Uint(0), ConstValue::Uint(0), ConstValue::Uint(0)]);
        assert_eq!(v, ConstValue::Composite(vec![padded(1), padded(0)]));
    }
}
