//! Texture calls: sampling (with level, bias, gradients, depth compare,
//! projection and texel offsets), texel fetches and size queries, on one
//! sampler or on an element of a sampler array picked at run time.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::{span, FnBuilder};
use super::module::GlobalSlot;
use crate::sema::builtins::Builtin;
use crate::sema::{Expr, GlobalKind, SamplerKind, Scalar, Ty};
use crate::source::Span;

/// A texture call with its image left open (so one call on an array of
/// samplers can be applied to each element).
pub(super) enum TexOp {
    Sample { coordinate: Handle<E>, array_index: Option<Handle<E>>, depth_ref: Option<Handle<E>>, level: naga::SampleLevel, offset: Option<Handle<E>> },
    Load { coordinate: Handle<E>, array_index: Option<Handle<E>>, level: Handle<E> },
    Size { level: Handle<E> },
}

/// The sampler of a texture call: a global, or the element `index` of a
/// binding array of samplers.
enum SamplerAt {
    Global(Handle<naga::GlobalVariable>),
    Element(Handle<naga::GlobalVariable>, Handle<E>),
}

impl FnBuilder<'_, '_> {
    pub(super) fn texture(&mut self, b: Builtin, args: &[Expr], ret: &Ty, s: Span, block: &mut Block) -> Handle<E> {
        // The sampler global, and the element when known here.
        let (g, constant, index) = match self.sampler_of(&args[0]) {
            Some(Ok(r)) => (r.global, Some(r.elem), None),
            Some(Err((g, i))) => (g, None, Some(i)),
            None => unreachable!("sema checks the sampler argument"),
        };
        let GlobalSlot::Sampler { first, count, binding_array } = self.m.globals[g] else { unreachable!("sema checks the sampler argument") };
        let GlobalKind::Sampler { kind, .. } = self.m.p.globals[g].kind else { unreachable!("sema checks the sampler argument") };
        // An `...Offset` call: the call it offsets, with the offset (a
        // constant, checked by sema) as a const-expression as naga wants.
        let (b, offset_at) = b.split_offset();
        let rest: Vec<Handle<E>> = args.iter().enumerate().skip(1).filter(|(i, _)| Some(*i) != offset_at).map(|(_, a)| self.expr(a, block)).collect();
        let offset = offset_at.map(|at| self.texel_offset(&args[at], s));
        let op = self.texture_op(b, kind, &rest, offset, args, s);
        if binding_array {
            // A descriptor array: the element picked by the index (clamped
            // like every other array index); naga marks it NonUniform in
            // SPIR-V where its uniformity analysis finds the index varies.
            let i = match (constant, index) {
                (Some(k), _) => self.literal(naga::Literal::I32(k.min(count - 1) as i32), s),
                (None, Some(index)) => self.clamped_index(index, count, block, s),
                (None, None) => unreachable!("a sampler reference is a constant or a dynamic index"),
            };
            let (images, samplers) = self.m.sampler_elems[first];
            let base = self.append_plain(E::GlobalVariable(images), s);
            let image = self.append(E::Access { base, index: i }, s);
            return self.texture_apply_to(&op, kind, image, SamplerAt::Element(samplers, i), ret, s);
        }
        if let Some(k) = constant {
            let (image, sampler) = self.m.sampler_elems[first + k.min(count - 1) as usize];
            return self.texture_apply(&op, kind, image, sampler, ret, s);
        }
        // A dynamic index into an array of samplers: a switch over the
        // elements (each a separate global), the index clamped like every
        // other array index.
        let index = index.expect("a dynamic index");
        let i = self.clamped_index(index, count, block, s);
        let ty = self.m.ty(ret);
        let var = self.func.local_variables.append(naga::LocalVariable { name: Some("texel".into()), ty, init: None }, span(s));
        self.flush(block);
        let mut cases = Vec::new();
        for k in 0..count {
            let mut body = Block::with_capacity(2);
            let (image, sampler) = self.m.sampler_elems[first + k as usize];
            let v = self.texture_apply(&op, kind, image, sampler, ret, s);
            let ptr = self.append_plain(E::LocalVariable(var), s);
            self.push(&mut body, Statement::Store { pointer: ptr, value: v }, s);
            let value = if k + 1 == count { naga::SwitchValue::Default } else { naga::SwitchValue::I32(k as i32) };
            cases.push(naga::SwitchCase { value, body, fall_through: false });
        }
        self.push(block, Statement::Switch { selector: i, cases }, s);
        let ptr = self.append_plain(E::LocalVariable(var), s);
        self.append(E::Load { pointer: ptr }, s)
    }

    /// A run-time index into an array of `count` samplers, as an `int`
    /// clamped to the array.
    fn clamped_index(&mut self, index: &Expr, count: u32, block: &mut Block, s: Span) -> Handle<E> {
        let mut i = self.expr(index, block);
        i = self.convert(i, &index.ty, Scalar::Int, s);
        let lo = self.literal(naga::Literal::I32(0), s);
        let hi = self.literal(naga::Literal::I32(count as i32 - 1), s);
        self.math(naga::MathFunction::Clamp, &[i, lo, hi], s)
    }

    /// A texel offset as the const-expression naga wants: a vector of
    /// literals (sema checked that `e` is a constant in range).
    pub(super) fn texel_offset(&mut self, e: &Expr, s: Span) -> Handle<E> {
        let ks = e.const_ints(&self.m.p.consts).expect("sema checks that a texel offset is constant");
        let components: Vec<Handle<E>> = ks.iter().map(|&k| self.literal(naga::Literal::I32(k as i32), s)).collect();
        let ty = self.m.ty(&e.ty);
        self.append(E::Compose { ty, components }, s)
    }

    /// The image-independent part of a texture call: coordinates, level,
    /// reference depth, texel offset.
    pub(super) fn texture_op(&mut self, b: Builtin, kind: SamplerKind, rest: &[Handle<E>], offset: Option<Handle<E>>, args: &[Expr], s: Span) -> TexOp {
        let f32s = Ty::Scalar(Scalar::Float);
        match b {
            Builtin::Texture | Builtin::TextureLod | Builtin::TextureCompare | Builtin::TextureProj | Builtin::TextureGrad => {
                let (coordinate, array_index, depth_ref) = if b == Builtin::TextureProj {
                    let v = rest[0];
                    let n = args[1].ty.width().unwrap_or(4);
                    let q = self.append(E::AccessIndex { base: v, index: n as u32 - 1 }, s);
                    let xy = self.swizzle(v, &[0, 1], s);
                    let q2 = self.append(E::Splat { size: naga::VectorSize::Bi, value: q }, s);
                    let uv = self.append(E::Binary { op: naga::BinaryOperator::Divide, left: xy, right: q2 }, s);
                    let dref = if kind.is_shadow() {
                        let z = self.append(E::AccessIndex { base: v, index: 2 }, s);
                        Some(self.append(E::Binary { op: naga::BinaryOperator::Divide, left: z, right: q }, s))
                    } else {
                        None
                    };
                    (uv, None, dref)
                } else if kind.is_array() {
                    // Split an array coordinate into uv and a rounded integer layer.
                    let coord = rest[0];
                    let uv = self.swizzle(coord, &[0, 1], s);
                    let layer = self.append(E::AccessIndex { base: coord, index: 2 }, s);
                    let layer = self.math(naga::MathFunction::Round, &[layer], s);
                    let layer = self.convert(layer, &f32s, Scalar::Int, s);
                    (uv, Some(layer), (b == Builtin::TextureCompare).then(|| rest[1]))
                } else {
                    (rest[0], None, (b == Builtin::TextureCompare).then(|| rest[1]))
                };
                let level = match b {
                    Builtin::TextureLod => naga::SampleLevel::Exact(rest[1]),
                    Builtin::TextureGrad => naga::SampleLevel::Gradient { x: rest[1], y: rest[2] },
                    // No implicit derivatives outside fragment shaders: the
                    // base level, plus the bias if one is given.
                    Builtin::Texture if rest.len() == 2 && self.vertex_lod => naga::SampleLevel::Exact(rest[1]),
                    Builtin::Texture if rest.len() == 2 => naga::SampleLevel::Bias(rest[1]),
                    _ if self.vertex_lod => naga::SampleLevel::Zero,
                    _ => naga::SampleLevel::Auto,
                };
                TexOp::Sample { coordinate, array_index, depth_ref, level, offset }
            }
            Builtin::TexelFetch => {
                let (coordinate, array_index) = if kind.is_array() {
                    let c = rest[0];
                    let xy = self.swizzle(c, &[0, 1], s);
                    (xy, Some(self.append(E::AccessIndex { base: c, index: 2 }, s)))
                } else {
                    (rest[0], None)
                };
                // Loads take no offset in WGSL: the texel `offset` away is
                // the one at coordinate + offset, which is what GLSL's
                // texelFetchOffset reads.
                let coordinate = match offset {
                    Some(o) => self.append(E::Binary { op: naga::BinaryOperator::Add, left: coordinate, right: o }, s),
                    None => coordinate,
                };
                TexOp::Load { coordinate, array_index, level: rest[1] }
            }
            _ => TexOp::Size { level: rest[0] },
        }
    }

    /// A texture operation on one image/sampler pair.
    pub(super) fn texture_apply(
        &mut self,
        op: &TexOp,
        kind: SamplerKind,
        image: Handle<naga::GlobalVariable>,
        sampler: Handle<naga::GlobalVariable>,
        ret: &Ty,
        s: Span,
    ) -> Handle<E> {
        let img = self.append_plain(E::GlobalVariable(image), s);
        self.texture_apply_to(op, kind, img, SamplerAt::Global(sampler), ret, s)
    }

    /// A texture operation on image expression `img` with `sampler`.
    fn texture_apply_to(&mut self, op: &TexOp, kind: SamplerKind, img: Handle<E>, sampler: SamplerAt, ret: &Ty, s: Span) -> Handle<E> {
        match op {
            TexOp::Sample { coordinate, array_index, depth_ref, level, offset } => {
                let smp = match sampler {
                    SamplerAt::Global(g) => self.append_plain(E::GlobalVariable(g), s),
                    SamplerAt::Element(array, index) => {
                        let base = self.append_plain(E::GlobalVariable(array), s);
                        self.append(E::Access { base, index }, s)
                    }
                };
                let e = E::ImageSample {
                    image: img,
                    sampler: smp,
                    gather: None,
                    coordinate: *coordinate,
                    array_index: *array_index,
                    offset: *offset,
                    level: *level,
                    depth_ref: *depth_ref,
                    clamp_to_edge: false,
                };
                self.append(e, s)
            }
            TexOp::Load { coordinate, array_index, level } => {
                self.append(E::ImageLoad { image: img, coordinate: *coordinate, array_index: *array_index, sample: None, level: Some(*level) }, s)
            }
            TexOp::Size { level } => {
                let size = self.append(E::ImageQuery { image: img, query: naga::ImageQuery::Size { level: Some(*level) } }, s);
                let dims = if kind.dim() == naga::ImageDimension::D3 { 3 } else { 2 };
                let size = self.convert(size, &Ty::Vector(Scalar::Uint, dims), Scalar::Int, s);
                if kind.is_array() {
                    let layers = self.append(E::ImageQuery { image: img, query: naga::ImageQuery::NumLayers }, s);
                    let layers = self.convert(layers, &Ty::Scalar(Scalar::Uint), Scalar::Int, s);
                    let ty = self.m.ty(ret);
                    return self.append(E::Compose { ty, components: vec![size, layers] }, s);
                }
                size
            }
        }
    }
}
