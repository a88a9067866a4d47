//! Enumerations: declared with their values, named `Enum.value`, compared
//! with each other, converted with `int(e)` / `uint(e)`, used as indices.
//! A value is an `int` (or `uint`) constant of the enumeration's own type.

use super::decls::ConstEnvAdapter;
use super::*;

/// The storage types daslang allows, as the scalar a shader holds them in
/// and their width in bits (values are truncated to it, as daslang does).
fn storage(name: &str) -> Option<(Scalar, u32)> {
    Some(match name {
        "int" => (Scalar::Int, 32),
        "uint" => (Scalar::Uint, 32),
        "int8" => (Scalar::Int, 8),
        "int16" => (Scalar::Int, 16),
        "uint8" => (Scalar::Uint, 8),
        "uint16" => (Scalar::Uint, 16),
        _ => return None,
    })
}

/// `v` truncated to `bits` bits of `base` (sign-extended for `Int`).
fn truncate(v: i64, base: Scalar, bits: u32) -> i64 {
    let shift = 64 - bits;
    match base {
        Scalar::Int => (v << shift) >> shift,
        _ => ((v as u64) << shift >> shift) as i64,
    }
}

impl<'a, 'd> Checker<'a, 'd> {
    /// Declares every enumeration's name and storage type, so that types
    /// anywhere can name it; values come later ([`Self::enum_values`]).
    pub(super) fn declare_enums(&mut self, seen: &mut FxHashMap<&'a str, Span>) {
        for item in &self.ast.items {
            let ast::Item::Enum(e) = item else { continue };
            self.check_unique(seen, &e.name);
            let base = match &e.base {
                None => Scalar::Int,
                Some(b) => match storage(&b.name) {
                    Some((s, _)) => s,
                    None => {
                        let d = Diagnostic::error(format!("an enumeration is stored as `int`, `uint`, `int8`, `int16`, `uint8` or `uint16`, not `{}`", b.name), b.span);
                        self.diags.push(d);
                        Scalar::Int
                    }
                },
            };
            let id = self.out.enums.len() as EnumId;
            self.enums.insert(&e.name.name, id);
            self.out.enums.push(EnumDef { name: e.name.name.as_str().to_string(), base, values: Vec::new(), span: e.span });
        }
    }

    /// Evaluates every enumeration's values: as written (a constant
    /// expression), or one more than the previous (the first: 0).
    pub(super) fn enum_values(&mut self) {
        for item in &self.ast.items {
            let ast::Item::Enum(e) = item else { continue };
            let id = self.enums[e.name.name.as_str()] as usize;
            let base = self.out.enums[id].base;
            let bits = e.base.as_ref().and_then(|b| storage(&b.name)).map_or(32, |s| s.1);
            let mut values: Vec<(String, i64)> = Vec::with_capacity(e.values.len());
            let mut spans: Vec<Span> = Vec::with_capacity(e.values.len());
            let mut next = 0i64;
            for (name, value) in &e.values {
                let v = match value {
                    None => next,
                    Some(x) => {
                        let mut names = Vec::new();
                        crate::sema::consts::collect_names(x, &mut names);
                        for n in names {
                            if self.const_decls.contains_key(n) {
                                self.const_id(n, x.span);
                            }
                        }
                        match eval_const(x, &ConstEnvAdapter { c: self }) {
                            Ok((ConstValue::Int(v), _)) => v,
                            Ok((ConstValue::Uint(v), _)) => v as i64,
                            Ok((_, ty)) => {
                                let d = Diagnostic::error(format!("an enumeration value is an integer, not a `{}`", self.show(&ty)), x.span);
                                self.diags.push(d);
                                next
                            }
                            Err(d) => {
                                self.diags.push(d);
                                next
                            }
                        }
                    }
                };
                if let Some(k) = values.iter().position(|(n, _)| *n == *name.name) {
                    let d = Diagnostic::error(format!("enumeration `{}` has two values named `{}`", e.name.name, name.name), name.span).with_secondary(spans[k], "first one here");
                    self.diags.push(d);
                }
                let v = truncate(v, base, bits);
                values.push((name.name.as_str().to_string(), v));
                spans.push(name.span);
                next = v.wrapping_add(1);
            }
            self.out.enums[id].values = values;
        }
    }

    /// `Enum.value`, where `ty` names an enumeration (and no variable).
    pub(super) fn enum_value_expr(&mut self, cx: &FnCtx<'a>, ty: &ast::Ident, member: &ast::Ident, span: Span) -> Option<Expr> {
        let name = ty.name.as_str();
        if cx.lookup(name).is_some() || self.globals.contains_key(name) || self.const_decls.contains_key(name) {
            return None;
        }
        let &id = self.enums.get(name)?;
        let def = &self.out.enums[id as usize];
        let Some((_, v)) = def.values.iter().find(|(n, _)| *n == *member.name) else {
            let names: Vec<&str> = def.values.iter().map(|(n, _)| n.as_str()).collect();
            let mut d = Diagnostic::error(format!("enumeration `{name}` has no value `{}`", member.name), member.span);
            d = match suggest(&member.name, names.iter().copied()) {
                Some(s) => d.with_note(format!("help: did you mean `{s}`?")),
                None => d.with_note(format!("its values are: {}", names.join(", "))),
            };
            self.diags.push(d);
            return Some(err_expr(span));
        };
        let kind = if def.base == Scalar::Uint { ExprKind::Uint(*v as u32 as u64) } else { ExprKind::Int(*v) };
        Some(Expr { kind, ty: Ty::Enum(id), span })
    }

    /// `l op r` where an operand is an enumeration: values of one
    /// enumeration compare (`== != < <= > >=`); nothing else applies.
    pub(super) fn enum_binary(&mut self, op: BinaryOp, l: &Ty, r: &Ty, span: Span) -> Option<Ty> {
        use BinaryOp::*;
        let comparison = matches!(op, Eq | Ne | Lt | Le | Gt | Ge);
        if l == r && comparison {
            return Some(BOOL);
        }
        let msg = format!("type mismatch: `{}` cannot be applied to `{}` and `{}`", op_text(op), self.show(l), self.show(r));
        let help = if comparison {
            "help: compare values of one enumeration, or convert both with `int(...)`"
        } else {
            "help: enumeration values only compare; convert with `int(...)` for arithmetic"
        };
        self.diags.push(Diagnostic::error(msg, span).with_note(help));
        None
    }

    /// The value of `Enum.member` for the constant evaluator.
    pub(super) fn enum_const(&self, ty: &str, member: &str) -> Option<(ConstValue, Ty)> {
        let &id = self.enums.get(ty)?;
        let def = &self.out.enums[id as usize];
        let (_, v) = def.values.iter().find(|(n, _)| n == member)?;
        let value = if def.base == Scalar::Uint { ConstValue::Uint(*v as u32 as u64) } else { ConstValue::Int(*v) };
        Some((value, Ty::Enum(id)))
    }
}
