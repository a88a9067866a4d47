//! Module-level lowering: types, constants, globals, and validation.

use naga::{Handle, Module, Type, TypeInner};
use rustc_hash::FxHashMap;

use super::Flavor;
use crate::diag::Diagnostic;
use crate::lower::{Resource, ResourceKind};
use crate::sema::{self, ConstValue, GlobalKind, Scalar, Ty};
use crate::source::Span;

/// How one sema global lives in the naga module.
#[derive(Clone, Copy, Debug)]
pub enum GlobalSlot {
    /// A uniform (Uniform space) or an interface/builtin copy (Private space).
    Var(Handle<naga::GlobalVariable>),
    /// A sampler or an array of samplers: `count` elements from `first` in
    /// `ModuleBuilder::sampler_elems`, each a separate image and sampler
    /// global (naga's GLSL writer cannot write binding arrays).
    Sampler { first: usize, count: u32 },
    /// Not declared: the module is built for one entry point, which does not
    /// use this global, or it is an input or output that every entry point
    /// using it holds itself (see `ModuleBuilder::declare_globals`).
    Absent,
}

pub struct ModuleBuilder<'p> {
    pub p: &'p sema::Program,
    pub module: Module,
    pub flavor: Flavor,
    /// Scalar, vector and matrix types by `small_type_slot`, which every
    /// expression asks for: no hashing of `Ty`.
    small_types: [Option<Handle<Type>>; SMALL_TYPE_SLOTS],
    /// Other types (arrays, structs).
    types: FxHashMap<Ty, Handle<Type>>,
    layouter: naga::proc::Layouter,
    pub globals: Vec<GlobalSlot>,
    /// Per sema constant, once declared (all up front for a whole-program
    /// module, on first use for a one-entry module).
    consts: Vec<Option<Handle<naga::Constant>>>,
    /// Per sema function; `None` where a one-entry module leaves it out.
    pub functions: Vec<Option<Handle<naga::Function>>>,
    /// The level-0 copy of a helper that samples with implicit LOD, where a
    /// vertex entry point reaches it and a fragment one does too.
    pub vertex_functions: Vec<Option<Handle<naga::Function>>>,
    /// Helpers with sampler parameters, one per set of samplers they are
    /// called with (few: a list).
    pub specialised: Vec<Specialised>,
    /// `inverse_2x2` .. `inverse_4x4`, once used (`lower::inverse`).
    pub inverse_functions: [Option<Handle<naga::Function>>; 3],
    /// The resources, for the interface; empty in a GL module.
    pub resources: Vec<Resource>,
    /// Indices into `resources` per sema global (one per element of a
    /// sampler array; empty for a global that is not a resource, and in a
    /// GL module).
    pub resource_of: Vec<std::ops::Range<usize>>,
    /// (image, sampler) globals of every sampler element.
    pub sampler_elems: Vec<(Handle<naga::GlobalVariable>, Handle<naga::GlobalVariable>)>,
    /// The program's struct names, for DSL type spellings in the interface.
    struct_names: Vec<String>,
}

/// A helper lowered for the samplers its sampler parameters stand for.
pub struct Specialised {
    pub function: sema::FuncId,
    pub vertex_lod: bool,
    pub samplers: Vec<super::func::SamplerRef>,
    pub handle: Handle<naga::Function>,
}

pub fn naga_scalar(s: Scalar) -> naga::Scalar {
    match s {
        Scalar::Float => naga::Scalar::F32,
        Scalar::Int => naga::Scalar::I32,
        Scalar::Uint => naga::Scalar::U32,
        Scalar::Bool => naga::Scalar::BOOL,
    }
}

const SMALL_TYPE_SLOTS: usize = 4 * 4 + 3 * 3;

/// The slot in `ModuleBuilder::small_types` of a scalar, vector or matrix.
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
    };
    match *ty {
        Ty::Scalar(s) => Some(scalar(s) * 4),
        Ty::Vector(s, n) => Some(scalar(s) * 4 + 1 + dim(n)),
        Ty::Matrix(c, r) => Some(16 + dim(c) * 3 + dim(r)),
        _ => None,
    }
}

pub fn vector_size(n: u8) -> naga::VectorSize {
    match n {
        2 => naga::VectorSize::Bi,
        3 => naga::VectorSize::Tri,
        _ => naga::VectorSize::Quad,
    }
}

impl<'p> ModuleBuilder<'p> {
    pub fn new(p: &'p sema::Program, flavor: Flavor) -> Self {
        ModuleBuilder {
            p,
            module: Module::default(),
            flavor,
            small_types: [None; SMALL_TYPE_SLOTS],
            types: FxHashMap::default(),
            layouter: naga::proc::Layouter::default(),
            globals: Vec::with_capacity(p.globals.len()),
            consts: vec![None; p.consts.len()],
            functions: Vec::with_capacity(p.functions.len()),
            vertex_functions: Vec::with_capacity(p.functions.len()),
            specialised: Vec::new(),
            inverse_functions: [None; 3],
            resources: Vec::new(),
            resource_of: Vec::with_capacity(p.globals.len()),
            sampler_elems: Vec::new(),
            // Only the GPU module's interface spells types (`show_ty`).
            struct_names: if flavor == Flavor::Gl { Vec::new() } else { p.struct_names() },
        }
    }

    /// The DSL spelling of a type (`float4`, `Light[4]`), for the interface.
    /// Only the GPU module's interface is kept: a GL module skips the text.
    pub fn show_ty(&self, ty: &Ty) -> String {
        if self.flavor == Flavor::Gl {
            return String::new();
        }
        // The common spellings without the formatting machinery.
        if let Some(name) = ty.builtin_name() {
            return name.to_string();
        }
        crate::sema::types::TyDisplay { ty, struct_names: &self.struct_names }.to_string()
    }

    fn add_type(&mut self, name: Option<String>, inner: TypeInner) -> Handle<Type> {
        self.module.types.insert(Type { name, inner }, naga::Span::UNDEFINED)
    }

    fn layout(&mut self, ty: Handle<Type>) -> naga::proc::TypeLayout {
        // The layouter only ever appends; types are never removed.
        if self.layouter.update(self.module.to_ctx()).is_err() {
            return naga::proc::TypeLayout { size: 0, alignment: naga::proc::Alignment::ONE };
        }
        self.layouter[ty]
    }

    /// The naga type of a DSL type (value types only).
    pub fn ty(&mut self, ty: &Ty) -> Handle<Type> {
        let small = small_type_slot(ty);
        let known = match small {
            Some(i) => self.small_types[i],
            None => self.types.get(ty).copied(),
        };
        if let Some(h) = known {
            return h;
        }
        let h = match ty {
            Ty::Scalar(s) => self.add_type(None, TypeInner::Scalar(naga_scalar(*s))),
            Ty::Vector(s, n) => self.add_type(None, TypeInner::Vector { size: vector_size(*n), scalar: naga_scalar(*s) }),
            Ty::Matrix(c, r) => self.add_type(None, TypeInner::Matrix { columns: vector_size(*c), rows: vector_size(*r), scalar: naga::Scalar::F32 }),
            Ty::Array(elem, n) => {
                let base = self.ty(elem);
                let stride = self.layout(base).to_stride();
                let size = naga::ArraySize::Constant(std::num::NonZeroU32::new(*n).unwrap_or(std::num::NonZeroU32::MIN));
                self.add_type(None, TypeInner::Array { base, size, stride })
            }
            Ty::Struct(id) => {
                let def = &self.p.structs[*id];
                let fields: Vec<(String, Ty)> = def.fields.iter().map(|(n, t, _)| (n.clone(), t.clone())).collect();
                let name = def.name.clone();
                let members = fields.into_iter().map(|(n, t)| (n, self.ty(&t), None)).collect();
                self.struct_type(name, members)
            }
            // Samplers, void and error never reach here: sema only lets
            // value types into variables and expressions that have types.
            Ty::Sampler(_) | Ty::Void | Ty::Error => self.add_type(None, TypeInner::Scalar(naga::Scalar::F32)),
        };
        match small {
            Some(i) => self.small_types[i] = Some(h),
            None => {
                self.types.insert(ty.clone(), h);
            }
        }
        h
    }

    /// A struct type with the natural (WGSL) layout.
    pub fn struct_type(&mut self, name: String, fields: Vec<(String, Handle<Type>, Option<naga::Binding>)>) -> Handle<Type> {
        let mut members = Vec::with_capacity(fields.len());
        let mut offset = 0u32;
        let mut align = naga::proc::Alignment::ONE;
        for (fname, mty, binding) in fields {
            let layout = self.layout(mty);
            offset = layout.alignment.round_up(offset);
            align = align.max(layout.alignment);
            members.push(naga::StructMember { name: Some(fname), ty: mty, binding, offset });
            offset += layout.size;
        }
        let span = align.round_up(offset);
        self.add_type(Some(name), TypeInner::Struct { members, span })
    }

    /// Appends a constant value to the global expression arena.
    fn const_expr(&mut self, v: &ConstValue, ty: &Ty) -> Handle<naga::Expression> {
        let expr = match (v, ty) {
            (ConstValue::Float(f), _) => naga::Expression::Literal(naga::Literal::F32(*f as f32)),
            (ConstValue::Int(i), _) => naga::Expression::Literal(naga::Literal::I32(*i as i32)),
            (ConstValue::Uint(u), _) => naga::Expression::Literal(naga::Literal::U32(*u as u32)),
            (ConstValue::Bool(b), _) => naga::Expression::Literal(naga::Literal::Bool(*b)),
            (ConstValue::Composite(cs), ty) => {
                let elem_tys: Vec<Ty> = match ty {
                    Ty::Vector(s, n) => vec![Ty::Scalar(*s); *n as usize],
                    Ty::Matrix(c, r) => vec![Ty::Vector(Scalar::Float, *r); *c as usize],
                    Ty::Array(e, n) => vec![(**e).clone(); *n as usize],
                    Ty::Struct(id) => self.p.structs[*id].fields.iter().map(|f| f.1.clone()).collect(),
                    _ => Vec::new(),
                };
                let components = cs.iter().zip(&elem_tys).map(|(c, t)| self.const_expr(c, t)).collect();
                let ty = self.ty(ty);
                naga::Expression::Compose { ty, components }
            }
        };
        self.module.global_expressions.append(expr, naga::Span::UNDEFINED)
    }

    /// Declares every constant, in source order.
    pub fn declare_consts(&mut self) {
        for c in 0..self.p.consts.len() {
            self.constant(c);
        }
    }

    /// The naga constant of sema constant `c`, declared on first use.
    pub fn constant(&mut self, c: sema::ConstId) -> Handle<naga::Constant> {
        if let Some(h) = self.consts[c] {
            return h;
        }
        let k = &self.p.consts[c];
        let init = self.const_expr(&k.value, &k.ty);
        let ty = self.ty(&k.ty);
        let h = self.module.constants.append(naga::Constant { name: Some(k.name.clone()), ty, init }, k.span.into());
        self.consts[c] = Some(h);
        h
    }

    /// Declares the sema globals, every one or (`only`) those one entry
    /// point uses; resources get bindings in declaration order. `only` is
    /// for the one-entry GL modules, whose resources have no bindings.
    /// Only the GPU module describes its resources (`resources`): a GL
    /// module's interface is not kept.
    /// `private`: per global, whether an input or output needs a private
    /// global (see `lower::EntryIo`); the others are left `Absent`.
    pub fn declare_globals(&mut self, only: Option<&std::collections::BTreeMap<sema::GlobalId, Span>>, private: &[bool]) {
        let mut next_binding = 0u32;
        let with_binding = self.flavor != Flavor::Gl;
        let describe = self.flavor != Flavor::Gl;
        for (gid, g) in self.p.globals.iter().enumerate() {
            let span: naga::Span = g.span.into();
            let first_resource = self.resources.len();
            if only.is_some_and(|uses| !uses.contains_key(&gid)) {
                self.globals.push(GlobalSlot::Absent);
                self.resource_of.push(first_resource..first_resource);
                continue;
            }
            let slot = match &g.kind {
                GlobalKind::Uniform => {
                    let ty = self.ty(&g.ty);
                    let binding = next_binding;
                    next_binding += 1;
                    let h = self.module.global_variables.append(
                        naga::GlobalVariable {
                            name: Some(g.name.clone()),
                            space: naga::AddressSpace::Uniform,
                            binding: with_binding.then_some(naga::ResourceBinding { group: 0, binding }),
                            ty,
                            init: None,
                            memory_decorations: naga::MemoryDecorations::empty(),
                        },
                        span,
                    );
                    if describe {
                        let dsl_type = self.show_ty(&g.ty);
                        self.resources.push(Resource {
                            name: g.name.clone(),
                            span: g.span,
                            kind: ResourceKind::Uniform { ty, dsl_type },
                            global: h,
                            sampler_global: None,
                            group: 0,
                            binding,
                            sampler_binding: None,
                            texture_unit: None,
                        });
                    }
                    GlobalSlot::Var(h)
                }
                GlobalKind::Sampler { kind, texture_unit, count } => {
                    let image_ty = self.add_type(None, TypeInner::Image { dim: kind.dim(), arrayed: kind.is_array(), class: kind.image_class() });
                    let sampler_ty = self.add_type(None, TypeInner::Sampler { comparison: kind.is_shadow() });
                    let first = self.sampler_elems.len();
                    for i in 0..count.unwrap_or(1) {
                        // An array element `texs[i]` is the global `texs_i`.
                        let gname = match count {
                            Some(_) => format!("{}_{i}", g.name),
                            None => g.name.clone(),
                        };
                        let sampler_name = [&gname, "_sampler"].concat();
                        let (tb, sb) = (next_binding, next_binding + 1);
                        next_binding += 2;
                        let image = self.module.global_variables.append(
                            naga::GlobalVariable {
                                name: Some(gname),
                                space: naga::AddressSpace::Handle,
                                binding: with_binding.then_some(naga::ResourceBinding { group: 0, binding: tb }),
                                ty: image_ty,
                                init: None,
                                memory_decorations: naga::MemoryDecorations::empty(),
                            },
                            span,
                        );
                        let sampler = self.module.global_variables.append(
                            naga::GlobalVariable {
                                name: Some(sampler_name),
                                space: naga::AddressSpace::Handle,
                                binding: with_binding.then_some(naga::ResourceBinding { group: 0, binding: sb }),
                                ty: sampler_ty,
                                init: None,
                                memory_decorations: naga::MemoryDecorations::empty(),
                            },
                            span,
                        );
                        self.sampler_elems.push((image, sampler));
                        if !describe {
                            continue;
                        }
                        let name = match count {
                            Some(_) => format!("{}[{i}]", g.name),
                            None => g.name.clone(),
                        };
                        self.resources.push(Resource {
                            name,
                            span: g.span,
                            kind: ResourceKind::Sampler(*kind),
                            global: image,
                            sampler_global: Some(sampler),
                            group: 0,
                            binding: tb,
                            sampler_binding: Some(sb),
                            texture_unit: Some(*texture_unit + i),
                        });
                    }
                    GlobalSlot::Sampler { first, count: count.unwrap_or(1) }
                }
                GlobalKind::Io { .. } | GlobalKind::Builtin(_) if !private[gid] => GlobalSlot::Absent,
                GlobalKind::Io { .. } | GlobalKind::Builtin(_) => {
                    let ty = self.ty(&g.ty);
                    let h = self.module.global_variables.append(
                        naga::GlobalVariable {
                            name: Some(g.name.clone()),
                            space: naga::AddressSpace::Private,
                            binding: None,
                            ty,
                            init: None,
                            memory_decorations: naga::MemoryDecorations::empty(),
                        },
                        span,
                    );
                    GlobalSlot::Var(h)
                }
            };
            self.globals.push(slot);
            self.resource_of.push(first_resource..self.resources.len());
        }
    }

    /// Turns implicit-LOD sampling in non-uniform control flow from an
    /// error into an accepted construct, as GLSL has it (docs/targets.md).
    pub fn allow_nonuniform_derivatives(&mut self) {
        use naga::diagnostic_filter::{DiagnosticFilter, DiagnosticFilterNode, FilterableTriggeringRule, Severity, StandardFilterableTriggeringRule};
        let node = self.module.diagnostic_filters.append(
            DiagnosticFilterNode {
                inner: DiagnosticFilter {
                    new_severity: Severity::Off,
                    triggering_rule: FilterableTriggeringRule::Standard(StandardFilterableTriggeringRule::DerivativeUniformity),
                },
                parent: None,
            },
            naga::Span::UNDEFINED,
        );
        self.module.diagnostic_filter_leaf = Some(node);
    }
}

/// The validator for modules of `flavor`. One validator can check several
/// modules (naga resets it per module), keeping its tables' memory.
pub fn validator(flavor: Flavor) -> naga::valid::Validator {
    use naga::valid::{Capabilities, ValidationFlags, Validator};
    let (flags, caps) = match flavor {
        Flavor::Gl => (ValidationFlags::all() - ValidationFlags::BINDINGS, naga::back::glsl::supported_capabilities()),
        Flavor::Gpu(_) => (ValidationFlags::all(), Capabilities::default()),
    };
    Validator::new(flags, caps)
}

/// Validates a finished module with a validator from [`validator`]`(flavor)`;
/// a failure is an internal compiler error located at the span naga reports.
pub fn validate(validator: &mut naga::valid::Validator, module: &Module, flavor: Flavor) -> Result<naga::valid::ModuleInfo, Diagnostic> {
    validator.validate(module).map_err(|e| {
        let span = e.spans().next().map(|(s, _)| Span::from(*s)).filter(|s| !s.is_empty());
        let mut msg = e.as_inner().to_string();
        let mut src: Option<&dyn std::error::Error> = std::error::Error::source(e.as_inner());
        while let Some(s) = src {
            msg.push_str(&format!(": {s}"));
            src = s.source();
        }
        let which = match flavor {
            Flavor::Gl => "GLSL",
            Flavor::Gpu(_) => "WGSL/SPIR-V",
        };
        let mut d = Diagnostic::bug(format!("naga rejected the IR built for the {which} targets: {msg}"), span);
        for (_, label) in e.spans().skip(1).take(3) {
            if !label.is_empty() {
                d = d.with_note(label.clone());
            }
        }
        d.with_note("this is a bug in umbrac; no output was written")
    })
}
