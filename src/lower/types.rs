//! DSL types as naga types: scalars, vectors and matrices from a small
//! table, arrays and structs with WGSL's natural layout.

use naga::{Handle, Module, Type, TypeInner};
use rustc_hash::FxHashMap;

use crate::sema::{self, Scalar, Ty};

pub(super) fn naga_scalar(s: Scalar) -> naga::Scalar {
    match s {
        Scalar::Float => naga::Scalar::F32,
        Scalar::Int => naga::Scalar::I32,
        Scalar::Uint => naga::Scalar::U32,
        Scalar::Bool => naga::Scalar::BOOL,
        Scalar::Half => naga::Scalar::F16,
    }
}

/// The naga scalar of `half` in a module of `flavor`: `f16`, except in the
/// GL modules, which stand in `f32`. The checker refuses `half` whenever a
/// GLSL target is requested, so a GL module with `half` in it serves only
/// the names GL hosts bind by (`emit` runs the GLSL writer for them) and
/// its text is never written.
pub(super) fn half_scalar(flavor: super::interface::Flavor) -> naga::Scalar {
    match flavor {
        super::interface::Flavor::Gl => naga::Scalar::F32,
        super::interface::Flavor::Gpu(_) => naga::Scalar::F16,
    }
}

const SMALL_TYPE_SLOTS: usize = 5 * 4 + 3 * 3;

/// The slot in `TypeTable::small` of a scalar, vector or matrix.
fn small_type_slot(ty: &Ty) -> Option<usize> {
    // As `vector_size` reads a size.
    let dim = |n: u8| match n {
        2 => 0,
        3 => 1,
        _ => 2,
    };
    let scalar = |s: Scalar| match s {
        Scalar::Float => 0,
        Scalar::Int => 1,
        Scalar::Uint => 2,
        Scalar::Bool => 3,
        Scalar::Half => 4,
    };
    match *ty {
        Ty::Scalar(s) => Some(scalar(s) * 4),
        Ty::Vector(s, n) => Some(scalar(s) * 4 + 1 + dim(n)),
        Ty::Matrix(c, r) => Some(20 + dim(c) * 3 + dim(r)),
        _ => None,
    }
}

pub(super) fn vector_size(n: u8) -> naga::VectorSize {
    match n {
        2 => naga::VectorSize::Bi,
        3 => naga::VectorSize::Tri,
        _ => naga::VectorSize::Quad,
    }
}

/// A new type in `module` (naga's arena returns the existing handle for an
/// identical type).
pub(super) fn add_type(module: &mut Module, name: Option<String>, inner: TypeInner) -> Handle<Type> {
    module.types.insert(Type { name, inner }, naga::Span::UNDEFINED)
}

/// The DSL spelling of a type (`float4`, `Light[4]`), for the interface.
pub(super) fn show_ty(ty: &Ty, struct_names: &[String]) -> String {
    // The common spellings without the formatting machinery.
    if let Some(name) = ty.builtin_name() {
        return name.to_string();
    }
    sema::types::TyDisplay { ty, struct_names, enum_names: &[] }.to_string()
}

/// The naga types made so far for DSL types, and their layouts.
#[derive(Default)]
pub(super) struct TypeTable {
    /// Scalar, vector and matrix types by `small_type_slot`, which every
    /// expression asks for: no hashing of `Ty`.
    small: [Option<Handle<Type>>; SMALL_TYPE_SLOTS],
    /// Other types (arrays, structs).
    other: FxHashMap<Ty, Handle<Type>>,
    layouter: naga::proc::Layouter,
    /// What `half` is in this module ([`half_scalar`]).
    pub(super) half: Option<naga::Scalar>,
}

impl TypeTable {
    pub(super) fn for_flavor(flavor: super::interface::Flavor) -> TypeTable {
        TypeTable { half: Some(half_scalar(flavor)), ..TypeTable::default() }
    }

    pub(super) fn layout(&mut self, module: &Module, ty: Handle<Type>) -> naga::proc::TypeLayout {
        // The layouter only ever appends; types are never removed.
        if self.layouter.update(module.to_ctx()).is_err() {
            return naga::proc::TypeLayout { size: 0, alignment: naga::proc::Alignment::ONE };
        }
        self.layouter[ty]
    }

    /// The naga type of a DSL type (value types only) in `module`.
    pub(super) fn ty(&mut self, module: &mut Module, p: &sema::Program, ty: &Ty) -> Handle<Type> {
        let small = small_type_slot(ty);
        let known = match small {
            Some(i) => self.small[i],
            None => self.other.get(ty).copied(),
        };
        if let Some(h) = known {
            return h;
        }
        let scalar = |s: Scalar| match (s, self.half) {
            (Scalar::Half, Some(h)) => h,
            (s, _) => naga_scalar(s),
        };
        let h = match ty {
            Ty::Scalar(s) => add_type(module, None, TypeInner::Scalar(scalar(*s))),
            Ty::Vector(s, n) => add_type(module, None, TypeInner::Vector { size: vector_size(*n), scalar: scalar(*s) }),
            Ty::Matrix(c, r) => add_type(module, None, TypeInner::Matrix { columns: vector_size(*c), rows: vector_size(*r), scalar: naga::Scalar::F32 }),
            Ty::Array(elem, n) => {
                let base = self.ty(module, p, elem);
                let stride = self.layout(module, base).to_stride();
                let size = naga::ArraySize::Constant(std::num::NonZeroU32::new(*n).unwrap_or(std::num::NonZeroU32::MIN));
                add_type(module, None, TypeInner::Array { base, size, stride })
            }
            Ty::Struct(id) => {
                let def = &p.structs[*id];
                let members = def.fields.iter().map(|(n, t, _)| (n.clone(), self.ty(module, p, t), None)).collect();
                self.struct_type(module, def.name.clone(), members)
            }
            // Samplers, void and error never reach here: sema only lets
            // value types into variables and expressions that have types.
            Ty::Enum(id) => add_type(module, None, TypeInner::Scalar(naga_scalar(p.enums[*id as usize].base))),
            Ty::RuntimeArray(elem) => {
                let base = self.ty(module, p, elem);
                let stride = self.layout(module, base).to_stride();
                add_type(module, None, TypeInner::Array { base, size: naga::ArraySize::Dynamic, stride })
            }
            // Images are typed by their global (`globals.rs`), which knows the format.
            Ty::Sampler(_) | Ty::Image(_) | Ty::Void | Ty::Error => add_type(module, None, TypeInner::Scalar(naga::Scalar::F32)),
        };
        match small {
            Some(i) => self.small[i] = Some(h),
            None => {
                self.other.insert(ty.clone(), h);
            }
        }
        h
    }

    /// A struct type laid out for the uniform address space: WGSL's rules
    /// there (array and struct members start at multiples of 16), which
    /// for the types a uniform buffer holds are std140's; the size is
    /// rounded up to 16.
    pub(super) fn uniform_struct_type(&mut self, module: &mut Module, name: String, fields: Vec<(String, Handle<Type>)>) -> Handle<Type> {
        let mut members = Vec::with_capacity(fields.len());
        let mut offset = 0u32;
        for (fname, mty) in fields {
            let layout = self.layout(module, mty);
            let composite = matches!(module.types[mty].inner, TypeInner::Array { .. } | TypeInner::Struct { .. });
            let align = if composite { layout.alignment.max(naga::proc::Alignment::SIXTEEN) } else { layout.alignment };
            offset = align.round_up(offset);
            members.push(naga::StructMember { name: Some(fname), ty: mty, binding: None, offset });
            offset += layout.size;
            if composite {
                // What follows a struct or array starts on the next 16.
                offset = naga::proc::Alignment::SIXTEEN.round_up(offset);
            }
        }
        let span = naga::proc::Alignment::SIXTEEN.round_up(offset.max(16));
        add_type(module, Some(name), TypeInner::Struct { members, span })
    }

    /// `ty` with its integer scalars made atomic: an integer, or an array
    /// of them (an atomic place of `sema::Program::atomics`).
    pub(super) fn atomic_type(&mut self, module: &mut Module, p: &sema::Program, ty: &Ty) -> Handle<Type> {
        match ty {
            Ty::Scalar(s @ (Scalar::Int | Scalar::Uint)) => add_type(module, None, TypeInner::Atomic(naga_scalar(*s))),
            Ty::Array(elem, n) => {
                let base = self.atomic_type(module, p, elem);
                let size = naga::ArraySize::Constant(std::num::NonZeroU32::new(*n).unwrap_or(std::num::NonZeroU32::MIN));
                add_type(module, None, TypeInner::Array { base, size, stride: 4 })
            }
            Ty::RuntimeArray(elem) => {
                let base = self.atomic_type(module, p, elem);
                add_type(module, None, TypeInner::Array { base, size: naga::ArraySize::Dynamic, stride: 4 })
            }
            other => self.ty(module, p, other),
        }
    }

    /// The struct of a storage buffer: the DSL struct, or (where atomics
    /// operate on members, `atomic`) a copy named `NAME_atomic` with
    /// those members atomic. The natural (WGSL storage) layout is std430's.
    pub(super) fn storage_struct_type(&mut self, module: &mut Module, p: &sema::Program, sid: usize, atomic: &[u32]) -> Handle<Type> {
        if atomic.is_empty() {
            return self.ty(module, p, &Ty::Struct(sid));
        }
        let def = &p.structs[sid];
        let members = def
            .fields
            .iter()
            .enumerate()
            .map(|(i, (n, t, _))| {
                let ty = if atomic.contains(&(i as u32)) { self.atomic_type(module, p, t) } else { self.ty(module, p, t) };
                (n.clone(), ty, None)
            })
            .collect();
        self.struct_type(module, [&def.name, "_atomic"].concat(), members)
    }

    /// A struct type with the natural (WGSL) layout.
    pub(super) fn struct_type(&mut self, module: &mut Module, name: String, fields: Vec<(String, Handle<Type>, Option<naga::Binding>)>) -> Handle<Type> {
        let mut members = Vec::with_capacity(fields.len());
        let mut offset = 0u32;
        let mut align = naga::proc::Alignment::ONE;
        for (fname, mty, binding) in fields {
            let layout = self.layout(module, mty);
            offset = layout.alignment.round_up(offset);
            align = align.max(layout.alignment);
            members.push(naga::StructMember { name: Some(fname), ty: mty, binding, offset });
            offset += layout.size;
        }
        let span = align.round_up(offset);
        add_type(module, Some(name), TypeInner::Struct { members, span })
    }
}
