//! The module builder: the state of one naga module under construction
//! (its type, constant and global tables), its constants, and the module's
//! diagnostic filter. Types are made in `types`, globals in `globals`.

use naga::{Handle, Module, Type};

use super::interface::{Flavor, GlUniforms, LooseUniform, Resource};
use super::types::{self, TypeTable};
use crate::sema::{self, ConstValue, Scalar, Ty};

/// How one sema global lives in the naga module.
#[derive(Clone, Copy, Debug)]
pub(super) enum GlobalSlot {
    /// A uniform (Uniform space) or an interface/builtin copy (Private space).
    Var(Handle<naga::GlobalVariable>),
    /// A sampler or an array of samplers: `count` elements from `first` in
    /// `ModuleBuilder::sampler_elems`, each a separate image and sampler
    /// global (naga's GLSL writer cannot write binding arrays); or, with
    /// `binding_array`, a Vulkan-dialect descriptor array in the GPU
    /// module: one pair at `first`, a binding array of images and one of
    /// samplers, `count` long.
    Sampler { first: usize, count: u32, binding_array: bool },
    /// A storage image (Handle space): used only through the image builtins.
    Image(Handle<naga::GlobalVariable>),
    /// A loose uniform: member `member` of uniform buffer `buffer`
    /// (`lower::uniforms`).
    Packed { buffer: Handle<naga::GlobalVariable>, member: u32 },
    /// A specialization constant: an override (GPU module) or a constant
    /// (GL module).
    Override(Handle<naga::Override>),
    Const(Handle<naga::Constant>),
    /// Not declared: the module is built for one entry point, which does not
    /// use this global, or it is an input or output that every entry point
    /// using it holds itself (see `ModuleBuilder::declare_globals`).
    Absent,
}

pub(super) struct ModuleBuilder<'p> {
    pub(super) p: &'p sema::Program,
    pub(super) module: Module,
    pub(super) flavor: Flavor,
    /// Portable or native: which clip-space adaptation vertex entry points
    /// get (in the GL modules too, for Vulkan-dialect code).
    pub(super) conventions: super::interface::Conventions,
    pub(super) types: TypeTable,
    pub(super) globals: Vec<GlobalSlot>,
    /// Per sema constant, once declared (all up front for a whole-program
    /// module, on first use for a one-entry module).
    pub(super) consts: Vec<Option<Handle<naga::Constant>>>,
    /// Per sema function; `None` where a one-entry module leaves it out.
    pub(super) functions: Vec<Option<Handle<naga::Function>>>,
    /// The level-0 copy of a helper that samples with implicit LOD, where a
    /// vertex entry point reaches it and a fragment one does too.
    pub(super) vertex_functions: Vec<Option<Handle<naga::Function>>>,
    /// Helpers with sampler parameters, one per set of samplers they are
    /// called with (few: a list).
    pub(super) specialised: Vec<Specialised>,
    /// `inverse_2x2` .. `inverse_4x4`, once used (`lower::inverse`).
    pub(super) inverse_functions: [Option<Handle<naga::Function>>; 3],
    /// The resources, for the interface; empty in a GL module.
    pub(super) resources: Vec<Resource>,
    /// Indices into `resources` per sema global (one per element of a
    /// sampler array; empty for a global that is not a resource, and in a
    /// GL module).
    pub(super) resource_of: Vec<std::ops::Range<usize>>,
    /// (image, sampler) globals of every sampler element.
    pub(super) sampler_elems: Vec<(Handle<naga::GlobalVariable>, Handle<naga::GlobalVariable>)>,
    /// The program's struct names, for DSL type spellings in the interface.
    pub(super) struct_names: Vec<String>,
    /// How a GL module declares loose uniforms.
    pub(super) gl_uniforms: GlUniforms,
    /// The uniform buffers of loose uniforms declared so far: where each
    /// is bound, its global, its members.
    pub(super) uniform_buffers: Vec<(sema::Bind, Handle<naga::GlobalVariable>, Vec<sema::GlobalId>)>,
    /// The loose uniforms, for the interface (empty in a GL module), and
    /// the index there of each sema global that is one.
    pub(super) loose: Vec<LooseUniform>,
    pub(super) loose_of: Vec<Option<usize>>,
    /// A GL module's private globals that stand for plain uniforms
    /// (`GlEntry::uniforms`).
    pub(super) plain_uniforms: Vec<(Handle<naga::GlobalVariable>, String)>,
    /// Specialization constants as `Private` variables of their defaults
    /// (the SPIR-V module, `Lowered::spirv`), not overrides.
    pub(super) spec_private: bool,
}

/// One sampler: element `elem` of sampler global `global` (0 for a single
/// sampler). What a sampler argument names, known when compiling.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) struct SamplerRef {
    pub(super) global: sema::GlobalId,
    pub(super) elem: u32,
}

/// A helper lowered for the samplers its sampler parameters stand for.
pub(super) struct Specialised {
    pub(super) function: sema::FuncId,
    pub(super) vertex_lod: bool,
    pub(super) samplers: Vec<SamplerRef>,
    pub(super) handle: Handle<naga::Function>,
}

impl<'p> ModuleBuilder<'p> {
    pub(super) fn new(p: &'p sema::Program, flavor: Flavor, conventions: super::interface::Conventions, gl_uniforms: GlUniforms) -> Self {
        ModuleBuilder {
            p,
            module: Module::default(),
            flavor,
            conventions,
            types: TypeTable::for_flavor(flavor),
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
            gl_uniforms,
            uniform_buffers: Vec::new(),
            loose: Vec::new(),
            loose_of: vec![None; p.globals.len()],
            plain_uniforms: Vec::new(),
            spec_private: false,
        }
    }

    /// The naga type of a DSL type (value types only).
    pub(super) fn ty(&mut self, ty: &Ty) -> Handle<Type> {
        self.types.ty(&mut self.module, self.p, ty)
    }

    /// A struct type with the natural (WGSL) layout.
    pub(super) fn struct_type(&mut self, name: String, fields: Vec<(String, Handle<Type>, Option<naga::Binding>)>) -> Handle<Type> {
        self.types.struct_type(&mut self.module, name, fields)
    }

    pub(super) fn add_type(&mut self, name: Option<String>, inner: naga::TypeInner) -> Handle<Type> {
        types::add_type(&mut self.module, name, inner)
    }

    /// The DSL spelling of a type (`float4`, `Light[4]`), for the interface.
    /// Only the GPU module's interface is kept: a GL module skips the text.
    pub(super) fn show_ty(&self, ty: &Ty) -> String {
        match self.flavor {
            Flavor::Gl => String::new(),
            Flavor::Gpu(_) => types::show_ty(ty, &self.struct_names),
        }
    }

    /// A `half` literal: `f16`, or `f32` in a GL module ([`types::half_scalar`]).
    pub(super) fn half_literal(&self, v: f64) -> naga::Literal {
        match self.flavor {
            Flavor::Gl => naga::Literal::F32(v as f32),
            Flavor::Gpu(_) => naga::Literal::F16(half::f16::from_f64(v)),
        }
    }

    /// A float literal of `scalar` (`float` or `half`).
    pub(super) fn float_literal(&self, v: f64, scalar: Scalar) -> naga::Literal {
        match scalar {
            Scalar::Half => self.half_literal(v),
            _ => naga::Literal::F32(v as f32),
        }
    }

    /// Appends a constant value to the global expression arena.
    pub(super) fn const_expr(&mut self, v: &ConstValue, ty: &Ty) -> Handle<naga::Expression> {
        let expr = match (v, ty) {
            (ConstValue::Float(f), Ty::Scalar(Scalar::Half)) => naga::Expression::Literal(self.half_literal(*f)),
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
    pub(super) fn declare_consts(&mut self) {
        for c in 0..self.p.consts.len() {
            self.constant(c);
        }
    }

    /// The value of naga constant `k` (one of the program's constants).
    pub(super) fn constant_value(&self, k: Handle<naga::Constant>) -> Option<ConstValue> {
        let c = self.consts.iter().position(|h| *h == Some(k))?;
        Some(self.p.consts[c].value.clone())
    }

    /// The naga constant of sema constant `c`, declared on first use.
    pub(super) fn constant(&mut self, c: sema::ConstId) -> Handle<naga::Constant> {
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

    /// Turns implicit-LOD sampling in non-uniform control flow from an
    /// error into an accepted construct, as GLSL has it (docs/targets.md).
    pub(super) fn allow_nonuniform_derivatives(&mut self) {
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

