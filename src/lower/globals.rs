//! The program's globals in a module: uniforms and samplers (with
//! bindings in the GPU module, none in a GL module, which naga then names
//! after the source; loose uniforms in the buffers of `uniforms`, or as
//! private globals for GLSL's plain `uniform T name;`), private globals
//! for the entry-point inputs and outputs that need one, and module
//! variables.

use naga::TypeInner;

use super::interface::{Flavor, Resource, ResourceKind};
use super::module::{GlobalSlot, ModuleBuilder};
use crate::sema::{self, GlobalKind, Ty};
use crate::source::Span;

impl ModuleBuilder<'_> {
    /// Declares the sema globals, every one or (`only`) those used: by one
    /// entry point for the GL modules (whose resources have no bindings),
    /// by any for the GPU module; resources at the bindings sema gave them.
    /// Only the GPU module describes its resources (`resources`): a GL
    /// module's interface is not kept.
    /// `private`: per global, whether an input or output needs a private
    /// global (see `reach::EntryIo`); the others are left `Absent`.
    pub(super) fn declare_globals(&mut self, only: Option<&std::collections::BTreeMap<sema::GlobalId, Span>>, private: &[bool]) {
        let with_binding = self.flavor != Flavor::Gl;
        let describe = self.flavor != Flavor::Gl;
        // The mesh outputs' arrays hold what the largest mesh entry point writes.
        let mesh_sizes = self.p.entry_points.iter().filter_map(|e| e.mesh).fold([1, 1], |a, b| [a[0].max(b[0]), a[1].max(b[1])]);
        for (gid, g) in self.p.globals.iter().enumerate() {
            let span: naga::Span = g.span.into();
            let first_resource = self.resources.len();
            // A resource no entry point uses has no binding (sema binds
            // only the used ones): no module declares it.
            let unused_resource = g.is_resource() && g.bind.is_none();
            if unused_resource || only.is_some_and(|uses| !uses.contains_key(&gid)) {
                self.globals.push(GlobalSlot::Absent);
                self.resource_of.push(first_resource..first_resource);
                continue;
            }
            let slot = match &g.kind {
                // Workgroup arrays the mesh entry points write (their
                // epilogue copies them into naga's output, `lower::mesh`).
                _ if super::mesh::is_mesh_output(g) => {
                    let (Ty::RuntimeArray(elem), GlobalKind::Builtin(_) | GlobalKind::Io { .. }) = (&g.ty, &g.kind) else { unreachable!("a mesh output is an array") };
                    let n = match g.kind {
                        GlobalKind::Builtin(sema::BuiltinVar::PrimitiveTriangleIndices | sema::BuiltinVar::MeshPrimitives) => mesh_sizes[1],
                        _ => mesh_sizes[0],
                    };
                    let ty = self.ty(&Ty::Array(elem.clone(), n));
                    GlobalSlot::Var(self.add_global(g.name.clone(), naga::AddressSpace::WorkGroup, None, ty, None, span))
                }
                GlobalKind::TaskPayload => {
                    let ty = self.ty(&g.ty);
                    GlobalSlot::Var(self.add_global(g.name.clone(), naga::AddressSpace::TaskPayload, None, ty, None, span))
                }
                GlobalKind::Uniform { .. } if g.is_loose_uniform() && self.packs_uniforms() => {
                    let slot = self.uniform_buffer_member(gid);
                    let buffer = self.resources.iter().position(|r| matches!(slot, GlobalSlot::Packed { buffer, .. } if r.global == buffer));
                    self.globals.push(slot);
                    self.resource_of.push(buffer.map_or(0..0, |b| b..b + 1));
                    continue;
                }
                GlobalKind::Uniform { .. } if g.is_loose_uniform() => {
                    // GLSL's plain form: a private global the GLSL text
                    // then declares `uniform T name;` (`emit::glsl`).
                    let ty = self.ty(&g.ty);
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::Private, None, ty, None, span);
                    self.plain_uniforms.push((h, g.name.clone()));
                    GlobalSlot::Var(h)
                }
                GlobalKind::Uniform { default } => {
                    let ty = self.ty(&g.ty);
                    let sema::Bind { group, binding } = g.bind.expect("a used resource is bound");
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::Uniform, with_binding.then_some(naga::ResourceBinding { group, binding }), ty, None, span);
                    if describe {
                        let dsl_type = self.show_ty(&g.ty);
                        self.resources.push(Resource {
                            name: g.name.clone(),
                            span: g.span,
                            kind: ResourceKind::Uniform { ty, dsl_type, loose: false },
                            global: h,
                            sampler_global: None,
                            group,
                            binding,
                            sampler_binding: None,
                            texture_unit: None,
                            default: default.clone(),
                            count: None,
                        });
                    }
                    GlobalSlot::Var(h)
                }
                GlobalKind::Sampler { kind, texture_unit, count: Some(n) } if self.p.vulkan => self.descriptor_array(gid, g, *kind, *n, *texture_unit),
                GlobalKind::Sampler { kind, texture_unit, count } => {
                    let image_ty = self.add_type(None, TypeInner::Image { dim: kind.dim(), arrayed: kind.is_array(), class: kind.image_class() });
                    let sampler_ty = self.add_type(None, TypeInner::Sampler { comparison: kind.is_shadow() });
                    let first = self.sampler_elems.len();
                    let sema::Bind { group, binding } = g.bind.expect("a used resource is bound");
                    for i in 0..count.unwrap_or(1) {
                        // An array element `texs[i]` is the global `texs_i`.
                        let gname = match count {
                            Some(_) => format!("{}_{i}", g.name),
                            None => g.name.clone(),
                        };
                        let sampler_name = [&gname, "_sampler"].concat();
                        let (tb, sb) = match self.p.vulkan {
                            true => (binding, self.p.sampler_halves[&gid]),
                            false => (binding + 2 * i, binding + 2 * i + 1),
                        };
                        let image = self.add_global(gname, naga::AddressSpace::Handle, with_binding.then_some(naga::ResourceBinding { group, binding: tb }), image_ty, None, span);
                        let sampler = self.add_global(sampler_name, naga::AddressSpace::Handle, with_binding.then_some(naga::ResourceBinding { group, binding: sb }), sampler_ty, None, span);
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
                            group,
                            binding: tb,
                            sampler_binding: Some(sb),
                            texture_unit: Some(*texture_unit + i),
                            default: None,
                            count: None,
                        });
                    }
                    GlobalSlot::Sampler { first, count: count.unwrap_or(1), binding_array: false }
                }
                GlobalKind::Storage { access, unit } => {
                    let sema::Bind { group, binding } = g.bind.expect("a used resource is bound");
                    let atomic: Vec<u32> = self.p.atomics.iter().filter(|(a, _)| *a == gid).filter_map(|(_, m)| *m).collect();
                    let ty = match g.ty {
                        sema::Ty::Struct(sid) => self.types.storage_struct_type(&mut self.module, self.p, sid, &atomic),
                        // A bare run-time array (`array<uint>`) atomics operate on.
                        _ if self.p.atomics.contains(&(gid, None)) => self.types.atomic_type(&mut self.module, self.p, &g.ty),
                        _ => self.ty(&g.ty),
                    };
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::Storage { access: access.naga() }, with_binding.then_some(naga::ResourceBinding { group, binding }), ty, None, span);
                    if describe {
                        let dsl_type = self.show_ty(&g.ty);
                        self.resources.push(Resource {
                            name: g.name.clone(),
                            span: g.span,
                            kind: ResourceKind::Storage { ty, dsl_type, access: *access },
                            global: h,
                            sampler_global: None,
                            group,
                            binding,
                            sampler_binding: None,
                            texture_unit: Some(*unit),
                            default: None,
                            count: None,
                        });
                    }
                    GlobalSlot::Var(h)
                }
                GlobalKind::Image { format, access, unit } => {
                    let sema::Bind { group, binding } = g.bind.expect("a used resource is bound");
                    let sema::Ty::Image(kind) = g.ty else { unreachable!("sema gives an image global an image type") };
                    let (dim, arrayed) = match kind.dim {
                        sema::types::ImageDim::D2 => (naga::ImageDimension::D2, false),
                        sema::types::ImageDim::D3 => (naga::ImageDimension::D3, false),
                        sema::types::ImageDim::D2Array => (naga::ImageDimension::D2, true),
                    };
                    let ty = self.add_type(None, TypeInner::Image { dim, arrayed, class: naga::ImageClass::Storage { format: format.naga(), access: access.naga() } });
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::Handle, with_binding.then_some(naga::ResourceBinding { group, binding }), ty, None, span);
                    if describe {
                        self.resources.push(Resource {
                            name: g.name.clone(),
                            span: g.span,
                            kind: ResourceKind::Image { kind, format: *format, access: *access },
                            global: h,
                            sampler_global: None,
                            group,
                            binding,
                            sampler_binding: None,
                            texture_unit: Some(*unit),
                            default: None,
                            count: None,
                        });
                    }
                    GlobalSlot::Image(h)
                }
                GlobalKind::Workgroup => {
                    let atomic = self.p.atomics.contains(&(gid, None));
                    let ty = if atomic { self.types.atomic_type(&mut self.module, self.p, &g.ty) } else { self.ty(&g.ty) };
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::WorkGroup, None, ty, None, span);
                    GlobalSlot::Var(h)
                }
                GlobalKind::Io { .. } | GlobalKind::Builtin(_) if !private[gid] => GlobalSlot::Absent,
                GlobalKind::Io { .. } | GlobalKind::Builtin(_) => {
                    let ty = self.ty(&g.ty);
                    // A GL module's interface variables take the source
                    // names (see `entry.rs`): the private copy is `io_NAME`.
                    let name = match (self.flavor, &g.kind) {
                        (Flavor::Gl, GlobalKind::Io { .. }) => ["io_", &g.name].concat(),
                        _ => g.name.clone(),
                    };
                    let h = self.add_global(name, naga::AddressSpace::Private, None, ty, None, span);
                    GlobalSlot::Var(h)
                }
                // A WGSL `override` in the GPU module; in the SPIR-V one a
                // `Private` variable of its default, read by loads naga
                // cannot fold, whose initializer `emit::spirv` makes an
                // `OpSpecConstant`; a named constant of its default in a GL
                // module, `const T NAME = default;`.
                GlobalKind::SpecConstant { id, default } => {
                    let ty = self.ty(&g.ty);
                    let init = self.const_expr(default, &g.ty);
                    match self.flavor {
                        Flavor::Gl => GlobalSlot::Const(self.module.constants.append(naga::Constant { name: Some(g.name.clone()), ty, init }, span)),
                        Flavor::Gpu(_) if self.spec_private => GlobalSlot::Var(self.add_global(g.name.clone(), naga::AddressSpace::Private, None, ty, Some(init), span)),
                        Flavor::Gpu(_) => {
                            let id = Some(*id as u16);
                            GlobalSlot::Override(self.module.overrides.append(naga::Override { name: Some(g.name.clone()), id, ty, init: Some(init) }, span))
                        }
                    }
                }
                GlobalKind::Private { init } => {
                    let ty = self.ty(&g.ty);
                    // Every invocation starts from the value, or from zero
                    // (GLSL leaves an uninitialised global undefined).
                    let init = match init {
                        Some(v) => self.const_expr(v, &g.ty),
                        None => self.module.global_expressions.append(naga::Expression::ZeroValue(ty), naga::Span::UNDEFINED),
                    };
                    let h = self.add_global(g.name.clone(), naga::AddressSpace::Private, None, ty, Some(init), span);
                    GlobalSlot::Var(h)
                }
            };
            self.globals.push(slot);
            self.resource_of.push(first_resource..self.resources.len());
        }
    }

    /// A Vulkan-dialect `sampler2D[N]`: one descriptor array at one
    /// binding. The GPU module holds a binding array of N images at the
    /// binding and one of N samplers at the sampler half (naga has no
    /// combined image-samplers), described as one resource with its count.
    /// A GL module, whose text sema lets no target write (GLSL has no
    /// descriptor arrays), holds one element standing in for all, under
    /// the array's name, so that its globals still match the GPU module's
    /// by name.
    fn descriptor_array(&mut self, gid: sema::GlobalId, g: &sema::Global, kind: sema::SamplerKind, n: u32, texture_unit: u32) -> GlobalSlot {
        let span: naga::Span = g.span.into();
        let mut image_ty = self.add_type(None, TypeInner::Image { dim: kind.dim(), arrayed: kind.is_array(), class: kind.image_class() });
        let mut sampler_ty = self.add_type(None, TypeInner::Sampler { comparison: kind.is_shadow() });
        let first = self.sampler_elems.len();
        let sampler_name = [&g.name, "_sampler"].concat();
        if self.flavor == Flavor::Gl {
            let image = self.add_global(g.name.clone(), naga::AddressSpace::Handle, None, image_ty, None, span);
            let sampler = self.add_global(sampler_name, naga::AddressSpace::Handle, None, sampler_ty, None, span);
            self.sampler_elems.push((image, sampler));
            return GlobalSlot::Sampler { first, count: 1, binding_array: false };
        }
        let size = naga::ArraySize::Constant(std::num::NonZeroU32::new(n).expect("sema sizes arrays from 1"));
        image_ty = self.add_type(None, TypeInner::BindingArray { base: image_ty, size });
        sampler_ty = self.add_type(None, TypeInner::BindingArray { base: sampler_ty, size });
        let sema::Bind { group, binding } = g.bind.expect("a used resource is bound");
        let sampler_binding = self.p.sampler_halves[&gid];
        let image = self.add_global(g.name.clone(), naga::AddressSpace::Handle, Some(naga::ResourceBinding { group, binding }), image_ty, None, span);
        let sampler = self.add_global(sampler_name, naga::AddressSpace::Handle, Some(naga::ResourceBinding { group, binding: sampler_binding }), sampler_ty, None, span);
        self.sampler_elems.push((image, sampler));
        self.resources.push(Resource {
            name: g.name.clone(),
            span: g.span,
            kind: ResourceKind::Sampler(kind),
            global: image,
            sampler_global: Some(sampler),
            group,
            binding,
            sampler_binding: Some(sampler_binding),
            texture_unit: Some(texture_unit),
            default: None,
            count: Some(n),
        });
        GlobalSlot::Sampler { first, count: n, binding_array: true }
    }

    /// Appends a module variable (no memory decorations).
    pub(super) fn add_global(
        &mut self,
        name: String,
        space: naga::AddressSpace,
        binding: Option<naga::ResourceBinding>,
        ty: naga::Handle<naga::Type>,
        init: Option<naga::Handle<naga::Expression>>,
        span: naga::Span,
    ) -> naga::Handle<naga::GlobalVariable> {
        let var = naga::GlobalVariable { name: Some(name), space, binding, ty, init, memory_decorations: naga::MemoryDecorations::empty() };
        self.module.global_variables.append(var, span)
    }
}
