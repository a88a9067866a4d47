//! The compute builtins: barriers, atomics on `@ssbo` members and
//! `@groupshared` variables, storage image loads, stores and sizes, and
//! the length of a run-time-sized array; subgroup operations.

use naga::{Block, Expression as E, Handle, Statement};

use super::function::FnBuilder;
use super::module::GlobalSlot;
use crate::sema::builtins::{AtomicOp, Builtin, Gather, SubgroupFn};
use crate::sema::types::ImageDim;
use crate::sema::{Expr, ExprKind, Scalar, Ty};
use crate::source::Span;

impl FnBuilder<'_, '_> {
    /// The compute builtin `b`, or `None` for any other builtin.
    pub(super) fn compute_builtin(&mut self, b: Builtin, args: &[Expr], ret: &Ty, s: Span, block: &mut Block) -> Option<Handle<E>> {
        Some(match b {
            Builtin::Barrier { control, flags } => {
                let stmt = if control { Statement::ControlBarrier(flags) } else { Statement::MemoryBarrier(flags) };
                self.push(block, stmt, s);
                self.literal(naga::Literal::Bool(false), s)
            }
            Builtin::SetMeshOutputs => {
                self.set_mesh_outputs(args, block, s);
                self.literal(naga::Literal::Bool(false), s)
            }
            Builtin::EmitMeshTasks => {
                self.emit_mesh_tasks(args, block, s);
                self.literal(naga::Literal::Bool(false), s)
            }
            Builtin::Atomic(op) => {
                let pointer = self.pointer(&args[0], block).expect("sema checks that an atomic operates on a place");
                let value = self.expr(&args[args.len() - 1], block);
                let scalar = match args[0].ty {
                    Ty::Scalar(Scalar::Int) => naga::Scalar::I32,
                    _ => naga::Scalar::U32,
                };
                let fun = match op {
                    AtomicOp::Add => naga::AtomicFunction::Add,
                    AtomicOp::Min => naga::AtomicFunction::Min,
                    AtomicOp::Max => naga::AtomicFunction::Max,
                    AtomicOp::And => naga::AtomicFunction::And,
                    AtomicOp::Or => naga::AtomicFunction::InclusiveOr,
                    AtomicOp::Xor => naga::AtomicFunction::ExclusiveOr,
                    AtomicOp::Exchange => naga::AtomicFunction::Exchange { compare: None },
                    AtomicOp::CompSwap => naga::AtomicFunction::Exchange { compare: Some(self.expr(&args[1], block)) },
                };
                if op == AtomicOp::CompSwap {
                    // naga's compare-exchange gives `{ old_value, exchanged }`.
                    let ty = self.m.module.generate_predeclared_type(naga::PredeclaredType::AtomicCompareExchangeWeakResult(scalar));
                    let result = self.append_plain(E::AtomicResult { ty, comparison: true }, s);
                    self.push(block, Statement::Atomic { pointer, fun, value, result: Some(result) }, s);
                    self.append(E::AccessIndex { base: result, index: 0 }, s)
                } else {
                    let ty = self.m.ty(ret);
                    let result = self.append_plain(E::AtomicResult { ty, comparison: false }, s);
                    self.push(block, Statement::Atomic { pointer, fun, value, result: Some(result) }, s);
                    result
                }
            }
            Builtin::ImageLoad | Builtin::ImageStore | Builtin::ImageSize => {
                let (image, dim) = self.image_global(&args[0], s);
                match b {
                    Builtin::ImageSize => {
                        let size = self.append(E::ImageQuery { image, query: naga::ImageQuery::Size { level: None } }, s);
                        let size = match dim {
                            // GLSL's imageSize of an array image has the layer count as z.
                            ImageDim::D2Array => {
                                let layers = self.append(E::ImageQuery { image, query: naga::ImageQuery::NumLayers }, s);
                                let ty = self.m.ty(&Ty::Vector(Scalar::Uint, 3));
                                let x = self.append(E::AccessIndex { base: size, index: 0 }, s);
                                let y = self.append(E::AccessIndex { base: size, index: 1 }, s);
                                self.append(E::Compose { ty, components: vec![x, y, layers] }, s)
                            }
                            _ => size,
                        };
                        self.append(E::As { expr: size, kind: naga::ScalarKind::Sint, convert: Some(4) }, s)
                    }
                    _ => {
                        let coord = self.expr(&args[1], block);
                        let (coordinate, array_index) = match dim {
                            ImageDim::D2Array => {
                                let x = self.append(E::AccessIndex { base: coord, index: 0 }, s);
                                let y = self.append(E::AccessIndex { base: coord, index: 1 }, s);
                                let z = self.append(E::AccessIndex { base: coord, index: 2 }, s);
                                let ty = self.m.ty(&Ty::Vector(Scalar::Int, 2));
                                (self.append(E::Compose { ty, components: vec![x, y] }, s), Some(z))
                            }
                            _ => (coord, None),
                        };
                        if b == Builtin::ImageLoad {
                            self.append(E::ImageLoad { image, coordinate, array_index, sample: None, level: None }, s)
                        } else {
                            let value = self.expr(&args[2], block);
                            self.push(block, Statement::ImageStore { image, coordinate, array_index, value }, s);
                            self.literal(naga::Literal::Bool(false), s)
                        }
                    }
                }
            }
            Builtin::ArrayLength => {
                let p = self.pointer(&args[0], block).expect("sema takes the length of a buffer's member only");
                self.append(E::ArrayLength(p), s)
            }
            Builtin::NonUniform => self.expr(&args[0], block),
            Builtin::Subgroup(f) => self.subgroup(f, args, ret, s, block),
            _ => return None,
        })
    }

    /// A subgroup operation: a statement whose result the call is.
    fn subgroup(&mut self, f: SubgroupFn, args: &[Expr], ret: &Ty, s: Span, block: &mut Block) -> Handle<E> {
        use naga::{CollectiveOperation as C, SubgroupOperation as O};
        match f {
            SubgroupFn::Ballot => {
                let predicate = Some(self.expr(&args[0], block));
                let result = self.append_plain(E::SubgroupBallotResult, s);
                self.push(block, Statement::SubgroupBallot { result, predicate }, s);
                result
            }
            // naga has no elect: the lowest active lane is the one whose
            // exclusive count of active lanes below it is 0.
            SubgroupFn::Elect => {
                let one = self.literal(naga::Literal::U32(1), s);
                let ty = self.m.ty(&Ty::Scalar(Scalar::Uint));
                let result = self.append_plain(E::SubgroupOperationResult { ty }, s);
                self.push(block, Statement::SubgroupCollectiveOperation { op: O::Add, collective_op: C::ExclusiveScan, argument: one, result }, s);
                let zero = self.literal(naga::Literal::U32(0), s);
                self.append(E::Binary { op: naga::BinaryOperator::Equal, left: result, right: zero }, s)
            }
            SubgroupFn::Collective(collective_op, op) => {
                let argument = self.expr(&args[0], block);
                let ty = self.m.ty(ret);
                let result = self.append_plain(E::SubgroupOperationResult { ty }, s);
                self.push(block, Statement::SubgroupCollectiveOperation { op, collective_op, argument, result }, s);
                result
            }
            SubgroupFn::Gather(g) => {
                let argument = self.expr(&args[0], block);
                let index = args.get(1).map(|a| self.expr(a, block));
                let mode = match (g, index) {
                    (Gather::BroadcastFirst, _) => naga::GatherMode::BroadcastFirst,
                    (Gather::Broadcast, Some(i)) => naga::GatherMode::Broadcast(i),
                    (Gather::Shuffle, Some(i)) => naga::GatherMode::Shuffle(i),
                    (Gather::ShuffleXor, Some(i)) => naga::GatherMode::ShuffleXor(i),
                    (Gather::ShuffleUp, Some(i)) => naga::GatherMode::ShuffleUp(i),
                    (Gather::ShuffleDown, Some(i)) => naga::GatherMode::ShuffleDown(i),
                    (_, None) => unreachable!("sema checks the lane argument"),
                };
                let ty = self.m.ty(ret);
                let result = self.append_plain(E::SubgroupOperationResult { ty }, s);
                self.push(block, Statement::SubgroupGather { mode, argument, result }, s);
                result
            }
        }
    }

    /// The image global a storage image argument names, and its shape.
    fn image_global(&mut self, e: &Expr, s: Span) -> (Handle<E>, ImageDim) {
        let (ExprKind::Global(g), Ty::Image(kind)) = (&e.kind, &e.ty) else { unreachable!("sema takes a storage image global only") };
        let GlobalSlot::Image(h) = self.m.globals[*g] else { unreachable!("an image global used is declared") };
        (self.append_plain(E::GlobalVariable(h), s), kind.dim)
    }
}
