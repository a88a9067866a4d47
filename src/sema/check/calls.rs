//! Calls of helper functions: the overload the argument types pick,
//! default values filled in for the parameters a call leaves out, and the
//! variables passed to `var p : T&` parameters. Also struct constructions
//! by field name (`Light(color = c)`), whose unnamed fields take their
//! initial values, and the constant values both defaults come from.

use super::*;

/// Why a checked expression is not a constant value: its first part that
/// reads or does something at run time.
fn not_constant(e: &Expr) -> Option<(Span, &'static str)> {
    let why = match &e.kind {
        ExprKind::Global(_) => Some("reads a shader global"),
        ExprKind::Local(_) => Some("reads a variable"),
        ExprKind::Call(..) => Some("calls a function"),
        ExprKind::Builtin(b, _) if b.is_texture() => Some("samples a texture"),
        ExprKind::Builtin(builtins::Builtin::Derivative(..), _) => Some("takes a derivative"),
        _ => None,
    };
    if let Some(w) = why {
        return Some((e.span, w));
    }
    let mut found = None;
    for_each_child(e, &mut |c| {
        if found.is_none() {
            found = not_constant(c);
        }
    });
    found
}

/// Calls `f` on each operand of `e`.
fn for_each_child<'e>(e: &'e Expr, f: &mut dyn FnMut(&'e Expr)) {
    match &e.kind {
        ExprKind::Unary(_, x) | ExprKind::Swizzle(x, _) | ExprKind::Field(x, _) => f(x),
        ExprKind::Binary(_, lr) => {
            f(&lr.0);
            f(&lr.1);
        }
        ExprKind::Index(a, b) => {
            f(a);
            f(b);
        }
        ExprKind::Select { cond, accept, reject } => {
            f(cond);
            f(accept);
            f(reject);
        }
        ExprKind::Call(_, xs) | ExprKind::Builtin(_, xs) | ExprKind::Construct(xs) => xs.iter().for_each(f),
        ExprKind::Float(_) | ExprKind::Int(_) | ExprKind::Uint(_) | ExprKind::Bool(_) | ExprKind::Local(_) | ExprKind::Global(_) | ExprKind::Const(_) | ExprKind::Zero => {}
    }
}

/// The place a `var p : T&` argument names: its root variable.
pub(super) fn place_root(e: &Expr) -> Option<&Expr> {
    match &e.kind {
        ExprKind::Local(_) | ExprKind::Global(_) => Some(e),
        ExprKind::Field(b, _) | ExprKind::Index(b, _) | ExprKind::Swizzle(b, _) => place_root(b),
        _ => None,
    }
}

impl<'a, 'd> Checker<'a, 'd> {
    /// A value that must be known when compiling (a default parameter
    /// value, a field's initial value), checked where nothing but
    /// constants is in scope, as `ty` (`None`: any type). `what` names it
    /// for messages. The same expression checks the same way every time,
    /// so each call that needs it checks it again to get its own copy.
    pub(super) fn constant_value(&mut self, e: &'a ast::Expr, ty: Option<&Ty>, what: &str) -> Option<Expr> {
        let mut cx = FnCtx::new(Scopes::default(), Ty::Void, self.call_depth, 0);
        let x = self.check_expr(&mut cx, e);
        if x.ty.is_error() {
            return None;
        }
        if let Some(ty) = ty.filter(|t| **t != x.ty) {
            let d = Diagnostic::error(format!("type mismatch: {what} is `{}`, but its type is `{}`", self.show(&x.ty), self.show(ty)), x.span)
                .with_label(format!("this is `{}`", self.show(&x.ty)));
            self.diags.push(d);
            return None;
        }
        if !x.ty.is_value() {
            self.diags.push(Diagnostic::error(format!("{what} has no value"), x.span));
            return None;
        }
        if let Some((span, why)) = not_constant(&x) {
            let d = Diagnostic::error(format!("{what} must be a constant, but this {why}"), span)
                .with_note("help: give literals, top-level `let` constants, enumeration values, constructors and math of those");
            self.diags.push(d);
            return None;
        }
        Some(x)
    }

    /// A parameter's default value as the argument of a call at `span`.
    fn default_argument(&mut self, default: &'a ast::Expr, ty: &Ty, span: Span) -> Option<Expr> {
        self.constant_value(default, Some(ty), "the default value").map(|v| Expr { span, ..v })
    }

    /// A call of helper `callee` with the checked arguments `xs`: the
    /// overload their types pick, with default values for the parameters
    /// left out. `Err(xs)` where no overload takes them and the name is a
    /// struct's too (the call is then that struct's construction).
    pub(super) fn check_helper_call(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, mut xs: Vec<Expr>, span: Span, is_struct: bool) -> Result<Expr, Vec<Expr>> {
        let name = callee.name.as_str();
        let count = self.funcs[name].len();
        let mut matching = arrayvec::ArrayVec::<usize, 4>::new();
        let mut more = 0;
        for k in 0..count {
            let d = self.funcs[name][k];
            let fits = match self.signature(d) {
                Some(sig) => sig.params.len() >= xs.len() && xs.len() >= sig.required && sig.params.iter().zip(&xs).all(|(p, x)| *p == x.ty),
                // A wrong parameter type, already reported.
                None if count == 1 => return Ok(err_expr(span)),
                None => false,
            };
            if fits && matching.try_push(d).is_err() {
                more += 1;
            }
        }
        let idx = match matching.as_slice() {
            [] if is_struct => return Err(xs),
            [] => {
                let decls = self.funcs[name].clone();
                self.report_no_overload(name, &decls, &xs, span);
                return Ok(err_expr(span));
            }
            [one] => *one,
            several => {
                let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
                let mut d = Diagnostic::error(format!("ambiguous call: {} overloads of `{name}` take ({})", several.len() + more, given.join(", ")), span);
                for &k in several {
                    d = d.with_secondary(self.fn_decls[k].name.span, "this one");
                }
                d = d.with_note("help: give the arguments that have default values, or remove an overload");
                self.diags.push(d);
                return Ok(err_expr(span));
            }
        };
        self.call_depth = cx.depth + CALL_DEPTH;
        let Some(fid) = self.function_id(idx, callee.span) else { return Ok(err_expr(span)) };
        // Default values, filled in at the call.
        let decl = self.fn_decls[idx];
        for (i, p) in decl.params.iter().enumerate().skip(xs.len()) {
            let ty = self.out.functions[fid].locals[i].ty.clone();
            let default = p.default.as_ref().expect("the overload matched: the parameters left out have defaults");
            match self.default_argument(default, &ty, span) {
                Some(v) => xs.push(v),
                None => return Ok(err_expr(span)),
            }
        }
        // A sampler argument names one sampler: the global, an element
        // picked by a constant, or the caller's own sampler parameter.
        for x in xs.iter().filter(|x| matches!(x.ty, Ty::Sampler(_))) {
            match &x.kind {
                ExprKind::Global(_) | ExprKind::Local(_) => {}
                ExprKind::Index(_, i) if i.const_int(&self.out.consts).is_some() => {}
                _ => {
                    let d = Diagnostic::error(format!("a sampler argument of `{name}` must be known when compiling"), x.span)
                        .with_label("indexed at run time")
                        .with_note("help: index the array with a constant, or call texture functions on the array element directly where the index varies");
                    self.diags.push(d);
                    return Ok(err_expr(span));
                }
            }
        }
        // What `var p : T&` parameters write must be a variable the
        // caller may write. A `var` struct or array parameter (a reference
        // in daslang too) given anything else works on a copy.
        for (i, x) in xs.iter().enumerate() {
            let f = &self.out.functions[fid];
            if !f.locals[i].by_ref {
                continue;
            }
            let pname = f.locals[i].name.clone();
            let pty = self.show(&f.locals[i].ty);
            let explicit = decl.params[i].by_ref;
            let writable = self.place_ok(cx, x);
            if writable.is_err() && !explicit {
                continue;
            }
            if let Err(why) = writable {
                let d = Diagnostic::error(format!("`{name}` writes its parameter `{pname}` (`var {pname} : {pty}&`), so the argument must be a variable the caller can write"), x.span)
                    .with_label("not writable here")
                    .with_note(why.message)
                    .with_secondary(f.span, "defined here");
                self.diags.push(d);
                return Ok(err_expr(span));
            }
            if let Some(ExprKind::Global(g)) = place_root(x).map(|r| &r.kind) {
                cx.ref_writes.push(*g);
            }
        }
        let f = &self.out.functions[fid];
        // The callee's global uses become the caller's (a sampler
        // global passed to it already is one, as a name read here).
        for &g in f.uses.keys() {
            cx.uses.entry(g).or_insert(span);
        }
        if let Some(fo) = f.fragment_only {
            cx.fragment_only.get_or_insert((span, fo.1));
        }
        if let Some(s) = f.subgroup_op {
            cx.subgroup_op.get_or_insert(s);
        }
        cx.implicit_lod |= f.implicit_lod;
        cx.callees.insert(fid);
        Ok(Expr { kind: ExprKind::Call(fid, xs), ty: f.ret.clone(), span })
    }

    /// No overload of `name` takes `xs`: the arity or the first argument
    /// type that does not fit (one declaration), or every signature.
    fn report_no_overload(&mut self, name: &str, decls: &[usize], xs: &[Expr], span: Span) {
        if let [idx] = *decls {
            let sig = self.signature(idx).expect("a signature with a wrong type returned earlier");
            let text = self.decl_signature_text(idx, &sig);
            let def = self.fn_decls[idx].span;
            let n = sig.params.len();
            if xs.len() > n || xs.len() < sig.required {
                let takes = if sig.required == n { n.to_string() } else { format!("{} to {n}", sig.required) };
                let d = Diagnostic::error(format!("wrong number of arguments: `{name}` takes {takes} but {} were given", xs.len()), span)
                    .with_secondary(def, "defined here")
                    .with_note(format!("expected: {text}"));
                self.diags.push(d);
                return;
            }
            if let Some((x, p)) = xs.iter().zip(&sig.params).find(|(x, p)| x.ty != **p) {
                let d = Diagnostic::error(format!("type mismatch: argument is `{}` but `{name}` expects `{}`", self.show(&x.ty), self.show(p)), x.span)
                    .with_note(format!("expected: {text}"));
                self.diags.push(d);
            }
            return;
        }
        let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
        let mut sigs = Vec::new();
        for &d in decls {
            if let Some(sig) = self.signature(d) {
                sigs.push(self.decl_signature_text(d, &sig));
            }
        }
        let d = Diagnostic::error(format!("no overload of `{name}` takes ({})", given.join(", ")), span).with_note(format!("the overloads are:\n  {}", sigs.join("\n  ")));
        self.diags.push(d);
    }

    /// `name(a : T; b : U = ...)`, from a declaration and its signature.
    pub(super) fn decl_signature_text(&self, idx: usize, sig: &Signature) -> String {
        let decl = self.fn_decls[idx];
        let ps: Vec<String> = decl
            .params
            .iter()
            .zip(&sig.params)
            .map(|(p, t)| {
                let (var, r, def) = (if p.mutable { "var " } else { "" }, if p.by_ref { "&" } else { "" }, if p.default.is_some() { " = ..." } else { "" });
                format!("{var}{} : {}{r}{def}", p.name.name, self.show(t))
            })
            .collect();
        format!("{}({})", decl.name.name, ps.join("; "))
    }

    /// `f([a = x, b = y])`: daslang's call by parameter name. Each value
    /// goes to the parameter of its name, in any order; the parameters
    /// left out take their default values, wherever they are. Of several
    /// overloads, the one whose parameter names and types the values fit.
    pub(super) fn check_call_by_name(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, items: &'a [ast::Expr], span: Span) -> Expr {
        let name = callee.name.as_str();
        let Some(decls) = self.funcs.get(name).cloned() else {
            let what = if self.structs.contains_key(name) {
                format!("`{name}` is a struct: construct it as `{name}(field = value, ...)`")
            } else if builtins::is_builtin(name) || Ty::from_builtin_name(name).is_some() {
                format!("`{name}` is a builtin, which takes its arguments by position")
            } else {
                format!("`{name}` is not a function of this program")
            };
            self.diags.push(Diagnostic::error(format!("arguments by name (`{name}([a = ...])`) call a function; {what}"), callee.span));
            return err_expr(span);
        };
        // The values, each checked once, with their names.
        let mut given: Vec<(&'a ast::Ident, Expr)> = Vec::with_capacity(items.len());
        for a in items {
            let ast::ExprKind::Named(pname, value) = &a.kind else { unreachable!("checked by the caller") };
            if let Some((_, prev)) = given.iter().find(|(n, _)| n.name == pname.name) {
                let d = Diagnostic::error(format!("argument `{}` is given twice", pname.name), pname.span).with_secondary(prev.span, "first given here");
                self.diags.push(d);
                return err_expr(span);
            }
            let x = self.check_expr(cx, value);
            if x.ty.is_error() {
                return err_expr(span);
            }
            given.push((pname, x));
        }
        // The overloads the names and types fit: each name a parameter of
        // the value's type, each parameter left out one with a default.
        let mut fitting = Vec::new();
        for &d in &decls {
            let Some(sig) = self.signature(d) else { return err_expr(span) };
            let params = &self.fn_decls[d].params;
            let names_fit = given.iter().all(|(n, x)| params.iter().zip(&sig.params).any(|(p, t)| p.name.name == n.name && *t == x.ty));
            let rest_default = params.iter().all(|p| p.default.is_some() || given.iter().any(|(n, _)| n.name == p.name.name));
            if names_fit && rest_default {
                fitting.push(d);
            }
        }
        let d = match fitting.as_slice() {
            [one] => *one,
            [] if decls.len() == 1 => {
                let d = decls[0];
                let params = &self.fn_decls[d].params;
                let sig = self.signature(d).expect("checked above");
                // What does not fit: an unknown name, a type, a parameter left out.
                for (n, x) in &given {
                    match params.iter().position(|p| p.name.name == n.name) {
                        None => {
                            let names: Vec<&str> = params.iter().map(|p| p.name.name.as_str()).collect();
                            let mut e = Diagnostic::error(format!("`{name}` has no parameter `{}`", n.name), n.span);
                            e = match suggest(&n.name, names.iter().copied()) {
                                Some(s) => e.with_note(format!("help: did you mean `{s}`?")),
                                None => e.with_note(format!("its parameters are: {}", names.join(", "))),
                            };
                            self.diags.push(e.with_secondary(self.fn_decls[d].name.span, "defined here"));
                            return err_expr(span);
                        }
                        Some(i) if sig.params[i] != x.ty => {
                            let e = Diagnostic::error(format!("type mismatch: parameter `{}` of `{name}` is `{}`, given `{}`", n.name, self.show(&sig.params[i]), self.show(&x.ty)), x.span);
                            self.diags.push(e.with_secondary(params[i].span, "declared here"));
                            return err_expr(span);
                        }
                        Some(_) => {}
                    }
                }
                let missing: Vec<String> = params.iter().filter(|p| p.default.is_none() && !given.iter().any(|(n, _)| n.name == p.name.name)).map(|p| format!("`{}`", p.name.name)).collect();
                let e = Diagnostic::error(format!("this call of `{name}` leaves out {}, which has no default value", missing.join(", ")), span)
                    .with_note("help: give every parameter without a default value by name")
                    .with_secondary(self.fn_decls[d].name.span, "defined here");
                self.diags.push(e);
                return err_expr(span);
            }
            [] => {
                let shown: Vec<String> = given.iter().map(|(n, x)| format!("{} : {}", n.name, self.show(&x.ty))).collect();
                let mut e = Diagnostic::error(format!("no overload of `{name}` takes the arguments [{}] by name", shown.join("; ")), span);
                for &k in &decls {
                    e = e.with_secondary(self.fn_decls[k].name.span, "an overload");
                }
                self.diags.push(e.with_note("an overload fits when each name is one of its parameters, of the value's type, and the parameters left out have default values"));
                return err_expr(span);
            }
            several => {
                let mut e = Diagnostic::error(format!("ambiguous call: {} overloads of `{name}` take these arguments by name", several.len()), span);
                for &k in several {
                    e = e.with_secondary(self.fn_decls[k].name.span, "this one");
                }
                self.diags.push(e.with_note("help: name more of the arguments, or remove an overload"));
                return err_expr(span);
            }
        };
        // In parameter order: the values given, the defaults elsewhere.
        let sig = self.signature(d).expect("checked above");
        let decl = self.fn_decls[d];
        let mut xs = Vec::with_capacity(decl.params.len());
        for (p, ty) in decl.params.iter().zip(&sig.params) {
            match given.iter().position(|(n, _)| n.name == p.name.name) {
                Some(k) => xs.push(given.swap_remove(k).1),
                None => {
                    let default = p.default.as_ref().expect("the overload fits: the parameters left out have defaults");
                    match self.default_argument(default, ty, span) {
                        Some(v) => xs.push(v),
                        None => return err_expr(span),
                    }
                }
            }
        }
        // Not a struct's construction: `Err` is never returned.
        self.check_helper_call(cx, callee, xs, span, false).unwrap_or_else(|_| err_expr(span))
    }

    /// `S(a = x, b = y)`: the fields named take the values given, the others
    /// their initial values (`a : float = 1.0` in the struct), or zero.
    /// `S()` gives every field its initial value.
    pub(super) fn check_named_construction(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, args: &'a [ast::Expr], span: Span) -> Expr {
        let name = callee.name.as_str();
        let Some(&sid) = self.structs.get(name) else {
            let (helper, builtin) = (self.funcs.contains_key(name), builtins::is_builtin(name));
            let what = if helper || builtin { "a function" } else { "not a struct" };
            let help = match helper && !builtin {
                true => format!("help: pass a function's arguments by position, or by name in brackets: `{name}([a = ..., b = ...])`"),
                false => "help: pass a function's arguments by position, in the order of its parameters".to_string(),
            };
            let d = Diagnostic::error(format!("`name = value` arguments construct a struct, and `{name}` is {what}"), callee.span).with_note(help);
            self.diags.push(d);
            return err_expr(span);
        };
        let n = self.out.structs[sid].fields.len();
        let mut given: Vec<Option<Expr>> = vec![None; n];
        let mut ok = true;
        for a in args {
            let ast::ExprKind::Named(fname, value) = &a.kind else {
                let d = Diagnostic::error(format!("a construction of `{name}` names all of its values or none"), a.span)
                    .with_label("no field name")
                    .with_note(format!("help: write `field = value` for this one too (the fields of `{name}`: {})", self.field_list(sid)));
                self.diags.push(d);
                ok = false;
                continue;
            };
            let x = self.check_expr(cx, value);
            let fields = &self.out.structs[sid].fields;
            let Some(i) = fields.iter().position(|(f, _, _)| *f == *fname.name) else {
                let names: Vec<&str> = fields.iter().map(|(f, _, _)| f.as_str()).collect();
                let mut d = Diagnostic::error(format!("struct `{name}` has no field `{}`", fname.name), fname.span);
                d = match suggest(&fname.name, names.iter().copied()) {
                    Some(s) => d.with_note(format!("help: did you mean `{s}`?")),
                    None => d.with_note(format!("its fields are: {}", names.join(", "))),
                };
                self.diags.push(d);
                ok = false;
                continue;
            };
            if let Some(prev) = &given[i] {
                let d = Diagnostic::error(format!("field `{}` is given twice", fname.name), fname.span).with_secondary(prev.span, "first given here");
                self.diags.push(d);
                ok = false;
                continue;
            }
            let fty = fields[i].1.clone();
            if !x.ty.is_error() && !fty.is_error() && x.ty != fty {
                let d = Diagnostic::error(format!("type mismatch: field `{}` of `{name}` is `{}`, given `{}`", fname.name, self.show(&fty), self.show(&x.ty)), x.span);
                self.diags.push(d);
                ok = false;
            }
            ok &= !x.ty.is_error();
            given[i] = Some(x);
        }
        if !ok {
            return err_expr(span);
        }
        let mut xs = Vec::with_capacity(n);
        for (i, g) in given.into_iter().enumerate() {
            match g {
                Some(x) => xs.push(x),
                None => match self.field_inits[sid].get(i).copied().flatten() {
                    Some(init) => match self.field_init_value(sid, i, init, span) {
                        Some(v) => xs.push(Expr { span, ..v }),
                        None => return err_expr(span),
                    },
                    None => xs.push(Expr { kind: ExprKind::Zero, ty: self.out.structs[sid].fields[i].1.clone(), span }),
                },
            }
        }
        Expr { kind: ExprKind::Construct(xs), ty: Ty::Struct(sid), span }
    }

    /// The initial value `init` of field `i` of struct `sid`, checked as a
    /// constant; one that needs itself (`struct S { a = S() }`) is an error.
    pub(super) fn field_init_value(&mut self, sid: StructId, i: usize, init: &'a ast::Expr, at: Span) -> Option<Expr> {
        if self.failed_inits.contains(&(sid, i)) {
            return None;
        }
        let (sname, fname) = (self.out.structs[sid].name.clone(), self.out.structs[sid].fields[i].0.clone());
        if self.inits_in_progress.contains(&(sid, i)) {
            let mut d = Diagnostic::error(format!("the initial value of `{sname}.{fname}` needs itself"), at)
                .with_note("help: give the field a value that does not construct its own struct");
            if at != init.span {
                d = d.with_secondary(init.span, "this initial value");
            }
            self.diags.push(d);
            self.failed_inits.insert((sid, i));
            return None;
        }
        self.inits_in_progress.push((sid, i));
        let v = self.constant_value(init, None, &format!("the initial value of `{sname}.{fname}`"));
        self.inits_in_progress.pop();
        if v.is_none() {
            self.failed_inits.insert((sid, i));
        }
        v
    }

    fn field_list(&self, sid: StructId) -> String {
        self.out.structs[sid].fields.iter().map(|(f, _, _)| f.as_str()).collect::<Vec<_>>().join(", ")
    }

    /// Whether a value of `ty` has fields with initial values, which a
    /// `var x : T` without a value would skip (daslang refuses it).
    pub(super) fn has_field_inits(&self, ty: &Ty) -> bool {
        match ty {
            Ty::Struct(sid) => {
                self.field_inits.get(*sid).is_some_and(|fs| fs.iter().any(|f| f.is_some())) || self.out.structs[*sid].fields.iter().any(|f| self.has_field_inits(&f.1))
            }
            Ty::Array(elem, _) => self.has_field_inits(elem),
            _ => false,
        }
    }
}
