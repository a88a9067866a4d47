//! Expressions: names, fields and swizzles, calls of functions, builtins,
//! constructors and texture functions, and operator typing.

use super::*;

impl<'a, 'd> Checker<'a, 'd> {
    // ---------------------------------------------------------------- expressions

    pub(super) fn check_expr(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        cx.depth += 1;
        let r = if cx.depth > MAX_DEPTH {
            self.diags.push(Diagnostic::error(format!("expression nests deeper than the limit of {MAX_DEPTH}"), e.span));
            err_expr(e.span)
        } else {
            self.check_expr_inner(cx, e)
        };
        cx.depth -= 1;
        r
    }

    pub(super) fn check_expr_inner(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let span = e.span;
        let mk = |kind, ty| Expr { kind, ty, span };
        match &e.kind {
            ast::ExprKind::Int(v, suffix) => match suffix {
                ast::IntSuffix::None => match i32::try_from(*v) {
                    Ok(v) => mk(ExprKind::Int(v as i64), INT),
                    // 2147483648 is fine as the operand of unary minus; see Unary below.
                    Err(_) => {
                        self.diags.push(Diagnostic::error(format!("integer literal {v} does not fit in `int`"), span).with_note("help: add a `u` suffix for `uint`"));
                        err_expr(span)
                    }
                },
                ast::IntSuffix::Unsigned => match u32::try_from(*v) {
                    Ok(v) => mk(ExprKind::Uint(v as u64), UINT),
                    Err(_) => {
                        self.diags.push(Diagnostic::error(format!("integer literal {v} does not fit in `uint`"), span));
                        err_expr(span)
                    }
                },
            },
            ast::ExprKind::Float(v) => {
                if v.is_finite() && (*v == 0.0 || v.abs() <= f32::MAX as f64) {
                    mk(ExprKind::Float(*v), FLOAT)
                } else {
                    self.diags.push(Diagnostic::error("float literal is out of range for `float`", span));
                    err_expr(span)
                }
            }
            ast::ExprKind::Bool(b) => mk(ExprKind::Bool(*b), BOOL),
            ast::ExprKind::Half(v) => {
                self.half_used(span);
                mk(ExprKind::Float(*v), HALF)
            }
            ast::ExprKind::Str(_) => {
                self.diags.push(Diagnostic::error("strings are not shader values", span));
                err_expr(span)
            }
            ast::ExprKind::Named(name, _) => {
                let d = Diagnostic::error(format!("`{} = ...` names a field, which only a struct construction takes", name.name), span)
                    .with_note("help: construct a struct as `S(field = value, ...)`; compare with `==`");
                self.diags.push(d);
                err_expr(span)
            }
            ast::ExprKind::Paren(inner) => {
                let mut x = self.check_expr(cx, inner);
                x.span = span;
                x
            }
            ast::ExprKind::Name(id) => self.check_name(cx, id),
            ast::ExprKind::Unary(op, inner) => {
                if let (UnaryOp::Neg, ast::ExprKind::Int(2147483648, ast::IntSuffix::None)) = (op, &inner.kind) {
                    return mk(ExprKind::Int(i32::MIN as i64), INT);
                }
                let x = self.check_expr(cx, inner);
                if x.ty.is_error() {
                    return err_expr(span);
                }
                let ok = match op {
                    // `-m` of a matrix is daslang's too (its math module).
                    UnaryOp::Neg | UnaryOp::Plus => matches!(x.ty.scalar(), Some(Scalar::Float | Scalar::Half | Scalar::Int)),
                    UnaryOp::Not => x.ty == BOOL,
                    UnaryOp::BitNot => matches!(x.ty.scalar(), Some(Scalar::Int | Scalar::Uint)),
                    _ => {
                        self.diags.push(Diagnostic::error("`++` and `--` can only be used as statements", span));
                        return err_expr(span);
                    }
                };
                if !ok {
                    let d = Diagnostic::error(format!("type mismatch: `{}` cannot be applied to `{}`", unary_text(*op), self.show(&x.ty)), span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                if *op == UnaryOp::Plus {
                    return Expr { span, ..x };
                }
                let ty = x.ty.clone();
                mk(ExprKind::Unary(*op, Box::new(x)), ty)
            }
            ast::ExprKind::Binary(op, lr) => {
                let l = self.check_expr(cx, &lr.0);
                let r = self.check_expr(cx, &lr.1);
                if l.ty.is_error() || r.ty.is_error() {
                    return err_expr(span);
                }
                match self.binary_type(*op, &l.ty, &r.ty, span) {
                    Some(ty) => {
                        // Constant operands make a constant expression in the
                        // WGSL output, which WGSL evaluates at shader creation
                        // and rejects on overflow, division by zero or a
                        // non-finite result: report those here.
                        if let (Some(a), Some(b)) = (self.literal_value(&l), self.literal_value(&r)) {
                            if let Err(msg) = crate::sema::consts::binary(*op, &a, &l.ty, &b, &r.ty) {
                                if !msg.contains("not supported") && !msg.contains("mismatch") {
                                    self.diags.push(Diagnostic::error(msg, span).with_note("both operands are constants, so this is evaluated at compile time"));
                                    return err_expr(span);
                                }
                            }
                        }
                        mk(ExprKind::Binary(*op, Box::new((l, r))), ty)
                    }
                    None => err_expr(span),
                }
            }
            ast::ExprKind::Ternary(c, a, b) => {
                let c = self.check_expr(cx, c);
                let a = self.check_expr(cx, a);
                let b = self.check_expr(cx, b);
                if c.ty.is_error() || a.ty.is_error() || b.ty.is_error() {
                    return err_expr(span);
                }
                let cond_ok = c.ty == BOOL || matches!((&c.ty, &a.ty), (Ty::Vector(Scalar::Bool, n), Ty::Vector(_, m)) if n == m);
                if !cond_ok {
                    let d = Diagnostic::error(format!("type mismatch: the condition of `?:` must be `bool` (or a bool vector as wide as the values), found `{}`", self.show(&c.ty)), c.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                if a.ty != b.ty {
                    let d = Diagnostic::error(format!("type mismatch: the branches of `?:` are `{}` and `{}`", self.show(&a.ty), self.show(&b.ty)), span)
                        .with_secondary(a.span, format!("`{}`", self.show(&a.ty)))
                        .with_secondary(b.span, format!("`{}`", self.show(&b.ty)));
                    self.diags.push(d);
                    return err_expr(span);
                }
                if !a.ty.is_value() || matches!(a.ty, Ty::Array(..) | Ty::Struct(_)) {
                    let d = Diagnostic::error(format!("`?:` cannot choose between `{}` values", self.show(&a.ty)), span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                let ty = a.ty.clone();
                mk(ExprKind::Select { cond: Box::new(c), accept: Box::new(a), reject: Box::new(b) }, ty)
            }
            // `unsafe(x)`: daslang's permission for `reinterpret`; x itself.
            ast::ExprKind::Call { callee, args } if callee.name == "unsafe" && args.len() == 1 && !self.funcs.contains_key("unsafe") => {
                let mut x = self.check_expr(cx, &args[0]);
                x.span = span;
                x
            }
            ast::ExprKind::Reinterpret(to, value) => self.check_reinterpret(cx, to, value, span),
            ast::ExprKind::Call { callee, args } => self.check_call(cx, callee, args, span),
            ast::ExprKind::Field(base, name) => {
                if let ast::ExprKind::Name(ty) = &base.kind {
                    if let Some(v) = self.enum_value_expr(cx, ty, name, span) {
                        return v;
                    }
                }
                let b = self.check_expr(cx, base);
                self.check_field(b, name, span)
            }
            ast::ExprKind::Index(base, index) => {
                let b = self.check_expr(cx, base);
                let i = self.check_expr(cx, index);
                if b.ty.is_error() || i.ty.is_error() {
                    return err_expr(span);
                }
                if i.ty != INT && i.ty != UINT && !matches!(i.ty, Ty::Enum(_)) {
                    let d = Diagnostic::error(format!("type mismatch: an index must be `int`, `uint` or an enumeration value, found `{}`", self.show(&i.ty)), i.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
                let (elem, len) = match &b.ty {
                    Ty::Vector(s, n) => (Ty::Scalar(*s), *n as u32),
                    Ty::Matrix(c, r) => (Ty::Vector(Scalar::Float, *r), *c as u32),
                    Ty::Array(elem, n) => ((**elem).clone(), *n),
                    // Bounds come from the buffer bound; every target
                    // clamps. A constant index must still be an `int`
                    // (GLSL indexes with one; naga writes it as WGSL's
                    // `i32`): at most 2^31 - 1.
                    Ty::RuntimeArray(elem) => ((**elem).clone(), MAX_RUNTIME_INDEX + 1),
                    other => {
                        let d = Diagnostic::error(format!("`{}` cannot be indexed", self.show(other)), b.span);
                        self.diags.push(d);
                        return err_expr(span);
                    }
                };
                // A literal or a named constant index is checked here; naga
                // would otherwise reject the IR (an internal error).
                let constant_index = match &i.kind {
                    ExprKind::Int(k) => Some(*k),
                    ExprKind::Uint(k) => Some(*k as i64),
                    ExprKind::Unary(UnaryOp::Neg, x) => match x.kind {
                        ExprKind::Int(k) => Some(-k),
                        _ => None,
                    },
                    ExprKind::Const(c) => match self.out.consts[*c].value {
                        ConstValue::Int(k) => Some(k),
                        ConstValue::Uint(k) => Some(k as i64),
                        _ => None,
                    },
                    _ => None,
                };
                if let Some(k) = constant_index {
                    if k < 0 || k as u64 >= len as u64 {
                        let d = if matches!(b.ty, Ty::RuntimeArray(_)) {
                            Diagnostic::error(format!("constant index {k} into run-time-sized `{}` is not in 0 to {MAX_RUNTIME_INDEX}", self.show(&b.ty)), i.span)
                                .with_note("GLSL indexes arrays with an `int`, and WGSL (as written) with an `i32`")
                        } else {
                            Diagnostic::error(format!("index {k} is out of bounds for `{}` (length {len})", self.show(&b.ty)), i.span)
                        };
                        self.diags.push(d);
                        return err_expr(span);
                    }
                }
                mk(ExprKind::Index(Box::new(b), Box::new(i)), elem)
            }
            ast::ExprKind::Array { elem, items } => {
                let declared = elem.as_ref().map(|t| self.resolve_type(t));
                let xs: Vec<Expr> = items.iter().map(|i| self.check_expr(cx, i)).collect();
                if xs.iter().any(|x| x.ty.is_error()) || declared.as_ref().is_some_and(|d| d.is_error()) {
                    return err_expr(span);
                }
                let Some(elem_ty) = declared.or_else(|| xs.first().map(|x| x.ty.clone())) else {
                    self.diags.push(Diagnostic::error("an empty array has no type", span));
                    return err_expr(span);
                };
                for x in &xs {
                    if x.ty != elem_ty {
                        let d = Diagnostic::error(format!("type mismatch: array element is `{}`, expected `{}`", self.show(&x.ty), self.show(&elem_ty)), x.span);
                        self.diags.push(d);
                        return err_expr(span);
                    }
                }
                if xs.is_empty() || xs.len() as u64 > MAX_ARRAY_LEN {
                    self.diags.push(Diagnostic::error(format!("an array needs 1 to {MAX_ARRAY_LEN} elements"), span));
                    return err_expr(span);
                }
                if matches!(elem_ty, Ty::Array(..)) {
                    self.diags.push(super::decls::array_of_arrays(span));
                    return err_expr(span);
                }
                let ty = Ty::Array(Box::new(elem_ty), xs.len() as u32);
                mk(ExprKind::Construct(xs), ty)
            }
        }
    }

    /// The value of a literal or named scalar constant.
    pub(super) fn literal_value(&self, e: &Expr) -> Option<ConstValue> {
        if matches!(e.ty, Ty::Enum(_)) {
            return None;
        }
        match &e.kind {
            ExprKind::Int(v) => Some(ConstValue::Int(*v)),
            ExprKind::Uint(v) => Some(ConstValue::Uint(*v)),
            ExprKind::Float(v) => Some(ConstValue::Float(*v as f32 as f64)),
            ExprKind::Const(c) if matches!(self.out.consts[*c].ty, Ty::Scalar(_)) => Some(self.out.consts[*c].value.clone()),
            ExprKind::Unary(UnaryOp::Neg, x) => match self.literal_value(x)? {
                ConstValue::Float(v) => Some(ConstValue::Float(-v)),
                ConstValue::Int(v) => (v as i32).checked_neg().map(|v| ConstValue::Int(v as i64)),
                _ => None,
            },
            _ => None,
        }
    }

    pub(super) fn check_name(&mut self, cx: &mut FnCtx<'a>, id: &'a ast::Ident) -> Expr {
        let span = id.span;
        if !cx.withs.is_empty() {
            if let Some(f) = self.with_field(cx, &id.name, span) {
                return f;
            }
        }
        if let Some(l) = cx.lookup(&id.name) {
            if let Some(a) = (!cx.aliases.is_empty()).then(|| cx.aliases.get(&l)).flatten() {
                // An element of an iterated array: the element itself.
                return Expr { span, ..a.clone() };
            }
            return Expr { kind: ExprKind::Local(l), ty: cx.locals[l].ty.clone(), span };
        }
        if let Some(&g) = self.globals.get(id.name.as_str()) {
            cx.uses.entry(g).or_insert(span);
            return Expr { kind: ExprKind::Global(g), ty: self.out.globals[g].ty.clone(), span };
        }
        if self.const_decls.contains_key(id.name.as_str()) || self.consts.contains_key(id.name.as_str()) {
            return match self.const_id(&id.name, span) {
                Some(c) => Expr { kind: ExprKind::Const(c), ty: self.out.consts[c].ty.clone(), span },
                None => err_expr(span),
            };
        }
        if let Some(b) = BuiltinVar::from_name(&id.name) {
            if b == BuiltinVar::WorkGroupSize {
                return self.workgroup_size_value(cx, span);
            }
            let g = match self.builtin_vars.get(&b) {
                Some(&g) => g,
                None => {
                    let ty = self.mesh_output_ty(b, span).unwrap_or_else(|| b.ty());
                    self.out.globals.push(Global { name: b.name().to_string(), ty, kind: GlobalKind::Builtin(b), span, bind: None });
                    self.builtin_vars.insert(b, self.out.globals.len() - 1);
                    self.out.globals.len() - 1
                }
            };
            cx.uses.entry(g).or_insert(span);
            self.builtin_var_used(b, span);
            return Expr { kind: ExprKind::Global(g), ty: self.out.globals[g].ty.clone(), span };
        }
        if self.funcs.contains_key(id.name.as_str()) || builtins::is_builtin(&id.name) {
            self.diags.push(Diagnostic::error(format!("`{}` is a function; call it with `{}(...)`", id.name, id.name), span));
            return err_expr(span);
        }
        if let Some(&e) = self.enums.get(id.name.as_str()) {
            let first = self.out.enums[e as usize].values.first().map_or("value", |v| v.0.as_str());
            let d = Diagnostic::error(format!("`{}` is an enumeration, not a value", id.name), span).with_note(format!("help: name one of its values: `{}.{first}`", id.name));
            self.diags.push(d);
            return err_expr(span);
        }
        // A global not declared yet: only a constant (field initial value)
        // is checked before the globals are.
        if self.globals.is_empty() && self.ast.items.iter().any(|i| matches!(i, ast::Item::Global(g) if g.name.name == id.name)) {
            let d = Diagnostic::error(format!("`{}` is a shader global, which a constant cannot read", id.name), span)
                .with_note("help: give literals, top-level `let` constants, enumeration values, constructors and math of those");
            self.diags.push(d);
            return err_expr(span);
        }
        if let Some(e) = self.builtin_constant(id) {
            return e;
        }
        if let Some(d) = self.unsupported_daslang_builtin(&id.name, span) {
            self.diags.push(d);
            return err_expr(span);
        }
        let mut d = Diagnostic::error(format!("unknown name `{}`", id.name), span).with_label("not found in this scope");
        let mut candidates: Vec<&str> = cx.scopes.visible.keys().copied().collect();
        candidates.extend(self.globals.keys().copied());
        candidates.extend(self.const_decls.keys().copied());
        candidates.extend(BuiltinVar::NAMES);
        if let Some(s) = suggest(&id.name, candidates.iter().copied()) {
            d = d.with_note(format!("help: did you mean `{s}`?"));
        }
        let d = self.with_missing_modules(d);
        self.diags.push(d);
        err_expr(span)
    }

    pub(super) fn check_field(&mut self, b: Expr, name: &ast::Ident, span: Span) -> Expr {
        match &b.ty {
            Ty::Error => err_expr(span),
            Ty::Struct(sid) => {
                let fields = &self.out.structs[*sid].fields;
                match self.field_index.get(*sid).and_then(|ix| ix.get(name.name.as_str())).map(|&i| i as usize) {
                    Some(i) => {
                        let ty = fields[i].1.clone();
                        Expr { kind: ExprKind::Field(Box::new(b), i as u32), ty, span }
                    }
                    None => {
                        let names: Vec<&str> = fields.iter().map(|(n, _, _)| n.as_str()).collect();
                        let mut d = Diagnostic::error(format!("struct `{}` has no field `{}`", self.out.structs[*sid].name, name.name), name.span);
                        if let Some(s) = suggest(&name.name, names.iter().copied()) {
                            d = d.with_note(format!("help: did you mean `{s}`?"));
                        } else {
                            d = d.with_note(format!("its fields are: {}", names.join(", ")));
                        }
                        self.diags.push(d);
                        err_expr(span)
                    }
                }
            }
            Ty::Vector(s, n) => {
                let s = *s;
                let n = *n;
                match parse_swizzle(&name.name, n) {
                    Ok(comps) => {
                        let ty = Ty::vec(s, comps.len() as u8);
                        Expr { kind: ExprKind::Swizzle(Box::new(b), comps), ty, span }
                    }
                    Err(msg) => {
                        let d = Diagnostic::error(format!("invalid swizzle `.{}` on `{}`: {msg}", name.name, self.show(&b.ty)), name.span);
                        self.diags.push(d);
                        err_expr(span)
                    }
                }
            }
            other => {
                let d = Diagnostic::error(format!("`{}` has no fields (`.{}`)", self.show(other), name.name), name.span);
                self.diags.push(d);
                err_expr(span)
            }
        }
    }

    // ---------------------------------------------------------------- calls

    pub(super) fn check_call(&mut self, cx: &mut FnCtx<'a>, callee: &'a ast::Ident, args: &'a [ast::Expr], span: Span) -> Expr {
        let name = callee.name.as_str();
        // Arguments by parameter name: `f([a = 1.0, b = v])`.
        let by_name = |a: &'a ast::Expr| match &a.kind {
            ast::ExprKind::Array { elem: None, items } if !items.is_empty() && items.iter().all(|a| matches!(a.kind, ast::ExprKind::Named(..))) => Some(items),
            _ => None,
        };
        if let [one] = args {
            if let Some(items) = by_name(one) {
                return self.check_call_by_name(cx, callee, items, span);
            }
        } else if let Some(list) = args.iter().find(|a| by_name(a).is_some()) {
            // `x |> f([b = 1.0])`, `f(x, [b = 1.0])`.
            let d = Diagnostic::error(format!("a call of `{name}` by parameter name gives all its arguments in the one list"), list.span)
                .with_label("arguments by name")
                .with_note("help: name the others too (a pipe passes its value by position): `f([a = x, b = 1.0])`");
            self.diags.push(d);
            return err_expr(span);
        }
        // Fields by name: a struct construction (`Light(k = 1.0)`).
        if args.iter().any(|a| matches!(a.kind, ast::ExprKind::Named(..))) {
            return self.check_named_construction(cx, callee, args, span);
        }
        // Constructors and casts.
        // `half` is no daslang type: a program's own function of that name wins.
        let ctor_ty = Ty::from_builtin_name(name)
            .filter(|t| !matches!(t, Ty::Sampler(_) | Ty::Image(_)) && (!t.has_half(&[]) || !self.funcs.contains_key(name)))
            .or_else(|| self.structs.get(name).map(|&s| Ty::Struct(s)));
        let mut xs: Vec<Expr> = args.iter().map(|a| self.check_expr(cx, a)).collect();
        if xs.iter().any(|x| x.ty.is_error()) {
            return err_expr(span);
        }
        // A helper (or a struct's initializer, a function named like it).
        if self.funcs.contains_key(name) {
            match self.check_helper_call(cx, callee, xs, span, matches!(ctor_ty, Some(Ty::Struct(_)))) {
                Ok(e) => return e,
                Err(back) => xs = back,
            }
        }
        if let Some(ty) = ctor_ty {
            // `S()`: every field takes its initial value.
            if matches!(ty, Ty::Struct(_)) && xs.is_empty() {
                return self.check_named_construction(cx, callee, args, span);
            }
            // `int(e)` / `uint(e)`: an enumeration value's number.
            if let ([x], Ty::Scalar(Scalar::Int | Scalar::Uint)) = (xs.as_slice(), &ty) {
                if matches!(x.ty, Ty::Enum(_)) {
                    return Expr { kind: ExprKind::Construct(xs), ty, span };
                }
            }
            if ty.has_half(&[]) {
                self.half_used(callee.span);
            }
            return self.check_constructor(ty, xs, span);
        }
        if name == "range" {
            self.diags.push(Diagnostic::error("`range` can only be used as the iterator of a `for` loop", span));
            return err_expr(span);
        }
        if name == "discard" {
            self.diags.push(Diagnostic::error("`discard()` is a statement and has no value", span));
            return err_expr(span);
        }
        if name == "sincos" && !self.funcs.contains_key(name) {
            let d = Diagnostic::error("`sincos(x, s, c)` is a statement and has no value", span)
                .with_note("help: it sets `s = sin(x)` and `c = cos(x)`; call it on a line of its own");
            self.diags.push(d);
            return err_expr(span);
        }
        if let Some((_, b)) = builtins::TEXTURE_FUNCTIONS.iter().find(|(n, _)| *n == name) {
            return self.check_texture_call(cx, *b, name, xs, span);
        }
        if name == "length" && !self.funcs.contains_key(name) {
            if let Some(e) = self.array_length_call(&xs, span) {
                return e;
            }
        }
        if let Some(b) = super::compute::compute_builtin(name) {
            return self.check_compute_call(cx, b, name, xs, span);
        }
        if let Some(b) = super::subgroup::subgroup_builtin(name) {
            return self.check_subgroup_call(cx, b, name, xs, span);
        }
        if let Some((_, why)) = super::subgroup::UNSUPPORTED_SUBGROUP.iter().find(|(n, _)| *n == name) {
            let d = Diagnostic::error(format!("`{name}` is not supported by umbrac on any target"), span).with_note(why.to_string());
            self.diags.push(d);
            return err_expr(span);
        }
        match builtins::resolve(name, xs.iter().map(|x| &x.ty)) {
            Ok(Some((b, ret))) => {
                if matches!(b, Builtin::Derivative(..)) {
                    cx.fragment_only.get_or_insert((span, "a derivative"));
                }
                if matches!(b, Builtin::Math(naga::MathFunction::Determinant) | Builtin::Inverse) && !matches!(xs[0].ty, Ty::Matrix(c, r) if c == r) {
                    self.diags.push(Diagnostic::error(format!("`{name}` needs a square matrix"), span));
                    return err_expr(span);
                }
                // With constant arguments, the WGSL output is a constant
                // expression, which WGSL evaluates at shader creation and
                // rejects when undefined or not finite: report it here.
                if !xs.is_empty() && !matches!(b, Builtin::Derivative(..)) {
                    if let Some(consts) = xs.iter().map(|x| self.literal_value(x).map(|v| (v, x.ty.clone()))).collect::<Option<Vec<_>>>() {
                        if let Some(Err(msg)) = crate::sema::fold::call(name, &consts) {
                            self.diags.push(Diagnostic::error(msg, span).with_note("its arguments are constants, so this call is evaluated at compile time"));
                            return err_expr(span);
                        }
                    }
                }
                Expr { kind: ExprKind::Builtin(b, xs), ty: ret, span }
            }
            Ok(None) if builtins::LEGACY_TEXTURE_FUNCTIONS.iter().any(|(n, ..)| *n == name) => {
                let &(_, b, kind, now) = builtins::LEGACY_TEXTURE_FUNCTIONS.iter().find(|(n, ..)| *n == name).expect("matched");
                self.check_legacy_texture_call(cx, callee, (b, kind, now), xs, span)
            }
            Ok(None) if crate::sema::types::unsupported_type(name).is_some() => {
                let (msg, help) = crate::sema::types::unsupported_type(name).expect("matched");
                self.diags.push(Diagnostic::error(msg, callee.span).with_label("a type no target has").with_note(format!("help: {help}")));
                err_expr(span)
            }
            Ok(None) if builtins::UNSUPPORTED.iter().any(|(n, _)| *n == name) => {
                let why = builtins::UNSUPPORTED.iter().find(|(n, _)| *n == name).map(|(_, w)| *w).unwrap_or_default();
                let d = Diagnostic::error(format!("`{name}` is not available in umbrac shaders"), callee.span).with_note(format!("help: {why}"));
                self.diags.push(d);
                err_expr(span)
            }
            Ok(None) if self.ast.daslang_builtins.iter().any(|b| b.name == name) => {
                let d = self.unsupported_daslang_builtin(name, callee.span).expect("matched");
                self.diags.push(d);
                err_expr(span)
            }
            Ok(None) => {
                let mut d = Diagnostic::error(format!("unknown function `{name}`"), callee.span).with_label("not a function, builtin or type");
                let mut candidates: Vec<&str> = builtins::all_names().collect();
                candidates.extend(self.funcs.keys().copied());
                candidates.extend(self.structs.keys().copied());
                candidates.extend(TYPE_NAMES.iter().copied());
                if let Some(s) = suggest(name, candidates) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                let d = self.with_missing_modules(d);
                self.diags.push(d);
                err_expr(span)
            }
            Err(sigs) => {
                let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
                let what = if sigs.iter().all(|s| s.matches(", ").count() + 1 != xs.len()) { "wrong number of arguments" } else { "type mismatch" };
                let mut d = Diagnostic::error(format!("{what}: no overload of `{name}` takes ({})", given.join(", ")), span);
                d = d.with_note(format!("expected one of:\n  {}", sigs.join("\n  ")));
                self.diags.push(d);
                err_expr(span)
            }
        }
    }

    /// `reinterpret<T>(x)`: the bits of a 32-bit scalar or vector as
    /// another of the same width (naga's bit cast); nothing else.
    fn check_reinterpret(&mut self, cx: &mut FnCtx<'a>, to: &'a ast::Ident, value: &'a ast::Expr, span: Span) -> Expr {
        let x = self.check_expr(cx, value);
        let target = Ty::from_builtin_name(&to.name);
        if target.is_none() {
            if let Some((msg, help)) = crate::sema::types::unsupported_type(&to.name) {
                self.diags.push(Diagnostic::error(msg, to.span).with_label("a type no target has").with_note(format!("help: {help}")));
                return err_expr(span);
            }
        }
        let target = target.unwrap_or(Ty::Void);
        if x.ty.is_error() {
            return err_expr(span);
        }
        let bits32 = |t: &Ty| match t {
            Ty::Scalar(s @ (Scalar::Float | Scalar::Int | Scalar::Uint)) => Some((*s, 1)),
            Ty::Vector(s @ (Scalar::Float | Scalar::Int | Scalar::Uint), n) => Some((*s, *n)),
            _ => None,
        };
        match (bits32(&target), bits32(&x.ty)) {
            (Some((s, n)), Some((_, m))) if n == m => {
                if x.ty == target {
                    return Expr { span, ..x };
                }
                Expr { kind: ExprKind::Builtin(Builtin::Bitcast(s), vec![x]), ty: target, span }
            }
            _ => {
                let d = Diagnostic::error(format!("`reinterpret<{}>` of `{}`: a bit cast is only between 32-bit scalars or vectors of as many components (`int`, `uint`, `float`, `int2`, ...)", to.name, self.show(&x.ty)), span)
                    .with_label("not a bit cast every target has")
                    .with_note("naga, WGSL and GLSL reinterpret only same-size 32-bit numbers (`bitcast`, `floatBitsToUint`)");
                self.diags.push(d);
                err_expr(span)
            }
        }
    }

    pub(super) fn check_constructor(&mut self, ty: Ty, xs: Vec<Expr>, span: Span) -> Expr {
        // The type's name is formatted only for a message.
        let fail = |this: &mut Self, msg: String| {
            this.diags.push(Diagnostic::error(msg, span));
            err_expr(span)
        };
        match &ty {
            Ty::Scalar(_) => {
                if xs.len() != 1 || !matches!(xs[0].ty, Ty::Scalar(_)) {
                    let given: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
                    let name = self.show(&ty);
                    return fail(self, format!("wrong arguments: `{name}(...)` converts one scalar, given ({})", given.join(", ")));
                }
            }
            Ty::Vector(_, n) => {
                let n = *n as usize;
                let single_ok = xs.len() == 1 && (matches!(xs[0].ty, Ty::Scalar(_)) || matches!(xs[0].ty, Ty::Vector(_, m) if m as usize >= n));
                if !single_ok {
                    let mut count = 0;
                    for x in &xs {
                        match x.ty {
                            Ty::Scalar(_) => count += 1,
                            Ty::Vector(_, m) => count += m as usize,
                            _ => {
                                let name = self.show(&ty);
                                return fail(self, format!("type mismatch: `{name}(...)` takes scalars and vectors, not `{}`", self.show(&x.ty)));
                            }
                        }
                    }
                    if count != n {
                        let name = self.show(&ty);
                        return fail(self, format!("wrong number of components: `{name}` needs {n}, the arguments give {count}"));
                    }
                }
            }
            Ty::Matrix(c, r) => {
                let (c, r) = (*c as usize, *r as usize);
                let cols_ok = xs.len() == c && xs.iter().all(|x| x.ty == Ty::Vector(Scalar::Float, r as u8));
                let scalars_ok = xs.len() == c * r && xs.iter().all(|x| x.ty == FLOAT);
                let diag_ok = xs.len() == 1 && xs[0].ty == FLOAT;
                // Another matrix, any size: its upper-left part, the rest of
                // the identity (GLSL's rule; `float3x3(m4)`).
                let matrix_ok = xs.len() == 1 && matches!(xs[0].ty, Ty::Matrix(..));
                if !(cols_ok || scalars_ok || diag_ok || matrix_ok) {
                    let name = self.show(&ty);
                    return fail(self, format!("wrong arguments: `{name}` is built from {c} float{r} columns, {} floats, one float (a diagonal) or another matrix", c * r));
                }
            }
            Ty::Struct(sid) => {
                let fields = &self.out.structs[*sid].fields;
                if fields.len() != xs.len() {
                    let (name, n) = (self.show(&ty), fields.len());
                    return fail(self, format!("wrong number of arguments: `{name}` has {n} fields but {} values were given", xs.len()));
                }
                if let Some(((fname, fty, _), x)) = fields.iter().zip(&xs).find(|((_, fty, _), x)| *fty != x.ty) {
                    let name = self.show(&ty);
                    let d = Diagnostic::error(format!("type mismatch: field `{fname}` of `{name}` is `{}`, given `{}`", self.show(fty), self.show(&x.ty)), x.span);
                    self.diags.push(d);
                    return err_expr(span);
                }
            }
            _ => {
                let name = self.show(&ty);
                return fail(self, format!("`{name}` cannot be constructed"));
            }
        }
        if xs.iter().any(|x| !x.ty.is_value() || matches!(x.ty, Ty::Array(..)) && !matches!(ty, Ty::Struct(_))) {
            let name = self.show(&ty);
            return fail(self, format!("invalid argument for `{name}(...)`"));
        }
        Expr { kind: ExprKind::Construct(xs), ty, span }
    }

    pub(super) fn check_texture_call(&mut self, cx: &mut FnCtx<'a>, called: Builtin, name: &str, xs: Vec<Expr>, span: Span) -> Expr {
        // An `...Offset` call is checked as the call it offsets, its
        // offset argument aside.
        let (b, offset_at) = called.split_offset();
        let Some(first) = xs.first() else {
            self.diags.push(Diagnostic::error(format!("wrong number of arguments: `{name}` takes a sampler first"), span));
            return err_expr(span);
        };
        let kind = match (&first.ty, &first.kind) {
            (Ty::Sampler(k), ExprKind::Global(_)) => *k,
            (Ty::Sampler(k), ExprKind::Index(base, _)) if matches!(base.kind, ExprKind::Global(_)) => *k,
            // A sampler parameter.
            (Ty::Sampler(k), ExprKind::Local(_)) => *k,
            _ => {
                let d = Diagnostic::error(format!("type mismatch: the first argument of `{name}` must be a sampler, found `{}`", self.show(&first.ty)), first.span);
                self.diags.push(d);
                return err_expr(span);
            }
        };
        let f2 = Ty::Vector(Scalar::Float, 2);
        let f3 = Ty::Vector(Scalar::Float, 3);
        let f4 = Ty::Vector(Scalar::Float, 4);
        let coord = match kind {
            SamplerKind::Sampler2D | SamplerKind::Sampler2DShadow | SamplerKind::ISampler2D | SamplerKind::USampler2D => f2.clone(),
            _ => f3.clone(),
        };
        let texel = match kind {
            SamplerKind::ISampler2D => Ty::Vector(Scalar::Int, 4),
            SamplerKind::USampler2D => Ty::Vector(Scalar::Uint, 4),
            _ => f4.clone(),
        };
        let shadow = kind.is_shadow();
        let icoord = match kind {
            SamplerKind::Sampler3D | SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow => Ty::Vector(Scalar::Int, 3),
            _ => Ty::Vector(Scalar::Int, 2),
        };
        let (sigs, ret): (Vec<Vec<Ty>>, Ty) = match b {
            Builtin::Texture | Builtin::TextureLod | Builtin::TextureGrad if shadow => {
                let d = Diagnostic::error(format!("`{name}` on shadow sampler `{}` is not supported", kind.name()), span)
                    .with_note("help: use textureCompare(sampler, uv, reference_depth) for a depth comparison");
                self.diags.push(d);
                return err_expr(span);
            }
            Builtin::Texture => (vec![vec![coord.clone()], vec![coord.clone(), FLOAT]], texel),
            Builtin::TextureLod => (vec![vec![coord.clone(), FLOAT]], texel),
            Builtin::TextureGrad => {
                let grad = match kind.dim() {
                    naga::ImageDimension::D2 => f2.clone(),
                    _ => f3.clone(),
                };
                (vec![vec![coord.clone(), grad.clone(), grad]], texel)
            }
            Builtin::TextureCompare => {
                if !shadow {
                    let d = Diagnostic::error(format!("`textureCompare` needs a shadow sampler, but `{}` is a `{}`", self.sampler_name(cx, first), kind.name()), first.span)
                        .with_label(format!("this is a `{}`", kind.name()))
                        .with_note("help: declare it as sampler2DShadow, sampler2DArrayShadow or samplerCubeShadow, or read it with texture()");
                    self.diags.push(d);
                    return err_expr(span);
                }
                (vec![vec![coord.clone(), FLOAT]], FLOAT)
            }
            Builtin::TextureProj => match kind {
                SamplerKind::Sampler2D => (vec![vec![f3.clone()], vec![f4.clone()]], texel),
                SamplerKind::Sampler2DShadow => (vec![vec![f4.clone()]], FLOAT),
                _ => {
                    self.diags.push(Diagnostic::error(format!("`textureProj` supports sampler2D and sampler2DShadow, not `{}`", kind.name()), span));
                    return err_expr(span);
                }
            },
            Builtin::TexelFetch => {
                if shadow || kind.dim() == naga::ImageDimension::Cube {
                    self.diags.push(Diagnostic::error(format!("`texelFetch` does not support `{}`", kind.name()), span));
                    return err_expr(span);
                }
                (vec![vec![icoord.clone(), INT]], texel)
            }
            Builtin::TextureSize => {
                let size = match kind {
                    SamplerKind::Sampler3D | SamplerKind::Sampler2DArray | SamplerKind::Sampler2DArrayShadow => Ty::Vector(Scalar::Int, 3),
                    _ => Ty::Vector(Scalar::Int, 2),
                };
                (vec![vec![INT]], size)
            }
            _ => unreachable!("only texture builtins reach check_texture_call"),
        };
        let offset_ty = Ty::Vector(Scalar::Int, if kind.dim() == naga::ImageDimension::D3 { 3 } else { 2 });
        if offset_at.is_some() {
            if let Some(why) = match kind {
                SamplerKind::SamplerCube | SamplerKind::SamplerCubeShadow => Some("cube maps have no texel offsets"),
                // naga's GLSL 330 writer cannot write it.
                SamplerKind::Sampler2DArrayShadow => Some("GLSL 330 has no offset compare on shadow array samplers"),
                _ => None,
            } {
                self.diags.push(Diagnostic::error(format!("`{name}` does not support `{}`: {why}", kind.name()), span));
                return err_expr(span);
            }
        }
        let given: Vec<Ty> = xs.iter().enumerate().skip(1).filter(|(i, _)| Some(*i) != offset_at).map(|(_, x)| x.ty.clone()).collect();
        let offset_missing = offset_at.is_some_and(|at| xs.len() <= at);
        if !sigs.contains(&given) || offset_missing {
            let show_sig = |s: &Vec<Ty>| {
                let mut parts = vec![kind.name().to_string()];
                parts.extend(s.iter().map(|t| self.show(t)));
                if let Some(at) = offset_at {
                    parts.insert(at, self.show(&offset_ty));
                }
                format!("{name}({})", parts.join(", "))
            };
            let expected: Vec<String> = sigs.iter().map(show_sig).collect();
            let given_s: Vec<String> = xs.iter().map(|x| self.show(&x.ty)).collect();
            let what = if offset_missing || sigs.iter().all(|s| s.len() != given.len()) { "wrong number of arguments" } else { "type mismatch" };
            let d = Diagnostic::error(format!("{what}: `{name}` cannot take ({})", given_s.join(", ")), span).with_note(format!("expected one of:\n  {}", expected.join("\n  ")));
            self.diags.push(d);
            return err_expr(span);
        }
        if let Some(at) = offset_at {
            let off = &xs[at];
            if off.ty != offset_ty {
                let d = Diagnostic::error(format!("type mismatch: the offset of `{name}` on a `{}` is an `{}`, found `{}`", kind.name(), self.show(&offset_ty), self.show(&off.ty)), off.span);
                self.diags.push(d);
                return err_expr(span);
            }
            match off.const_ints(&self.out.consts) {
                None => {
                    let d = Diagnostic::error(format!("the offset of `{name}` must be known when compiling"), off.span)
                        .with_label("not a constant")
                        .with_note("help: write it as `int2(1, -1)` or a top-level `let`; add a varying offset to the coordinate instead");
                    self.diags.push(d);
                    return err_expr(span);
                }
                Some(ks) if ks.iter().any(|k| !builtins::TEXEL_OFFSET_RANGE.contains(k)) => {
                    let d = Diagnostic::error(format!("texel offset {:?} is out of range", ks.as_slice()), off.span)
                        .with_note("every target guarantees offsets from -8 to 7 in each component");
                    self.diags.push(d);
                    return err_expr(span);
                }
                Some(_) => {}
            }
        }
        if matches!(b, Builtin::Texture | Builtin::TextureProj | Builtin::TextureCompare) {
            // Allowed in vertex entry points too: lowered with level 0 there.
            cx.implicit_lod = true;
        }
        Expr { kind: ExprKind::Builtin(called, xs), ty: ret, span }
    }

    pub(super) fn sampler_name(&self, cx: &FnCtx<'a>, e: &Expr) -> String {
        match &e.kind {
            ExprKind::Global(g) => self.out.globals[*g].name.clone(),
            ExprKind::Index(b, _) => format!("{}[...]", self.sampler_name(cx, b)),
            ExprKind::Local(l) => cx.locals[*l].name.as_str().to_owned(),
            _ => "the sampler".into(),
        }
    }

    // ---------------------------------------------------------------- operators

    /// The result type of `l op r`, or reports why there is none.
    pub(super) fn binary_type(&mut self, op: BinaryOp, l: &Ty, r: &Ty, span: Span) -> Option<Ty> {
        use BinaryOp::*;
        if matches!(l, Ty::Enum(_)) || matches!(r, Ty::Enum(_)) {
            return self.enum_binary(op, l, r, span);
        }
        let res = match op {
            Add | Sub | Mul | Div | Mod => arith_type(op, l, r),
            Lt | Le | Gt | Ge => match (l, r) {
                (Ty::Scalar(a), Ty::Scalar(b)) if a == b && a.is_numeric() => Ok(BOOL),
                (Ty::Vector(..), _) | (_, Ty::Vector(..)) => Err("compare vectors component-wise with lessThan(), greaterThan(), ...".to_string()),
                _ => Err(String::new()),
            },
            Eq | Ne => match (l, r) {
                (a, b) if a == b && matches!(a, Ty::Scalar(_) | Ty::Vector(..)) => Ok(BOOL),
                _ => Err(String::new()),
            },
            And | Or | Xor => {
                if *l == BOOL && *r == BOOL {
                    Ok(BOOL)
                } else {
                    Err(format!("`{}` needs bool operands", op_text(op)))
                }
            }
            BitAnd | BitOr | BitXor | Shl | Shr => match (l.scalar(), r.scalar()) {
                (Some(a), Some(b)) if a.is_integer() && b.is_integer() && !matches!(l, Ty::Matrix(..)) => {
                    let shift = matches!(op, Shl | Shr);
                    // A shift amount is one per component or one for all (`v << 2`).
                    if (shift && (l.width() == r.width() || r.width() == Some(1))) || (!shift && (l == r || (a == b && (l.width() == Some(1) || r.width() == Some(1))))) {
                        Ok(if l.width() == Some(1) && !shift { r.clone() } else { l.clone() })
                    } else {
                        Err(String::new())
                    }
                }
                _ => Err(format!("`{}` needs int or uint operands", op_text(op))),
            },
        };
        match res {
            Ok(t) => Some(t),
            Err(hint) => {
                let mut d = Diagnostic::error(format!("type mismatch: `{}` cannot be applied to `{}` and `{}`", op_text(op), self.show(l), self.show(r)), span);
                if !hint.is_empty() {
                    d = d.with_note(format!("help: {hint}"));
                } else if l.scalar().is_some() && r.scalar().is_some() && l.scalar() != r.scalar() {
                    d = d.with_note(format!("help: there are no implicit conversions; convert one side, e.g. `{}(...)`", l.scalar().map(|s| s.name()).unwrap_or("float")));
                }
                self.diags.push(d);
                None
            }
        }
    }
}

/// Arithmetic result types, GLSL rules: same-shape operands, scalar with
/// vector (or matrix for `*`), and the linear-algebra products.
pub(super) fn arith_type(op: BinaryOp, l: &Ty, r: &Ty) -> Result<Ty, String> {
    let num = |t: &Ty| t.scalar().is_some_and(|s| s.is_numeric());
    if !num(l) || !num(r) {
        return Err("arithmetic needs numeric operands".into());
    }
    if l.scalar() != r.scalar() {
        return Err(String::new());
    }
    match (l, r) {
        (Ty::Matrix(c1, r1), Ty::Matrix(c2, r2)) => match op {
            BinaryOp::Mul if c1 == r2 => Ok(Ty::Matrix(*c2, *r1)),
            BinaryOp::Add | BinaryOp::Sub if c1 == c2 && r1 == r2 => Ok(l.clone()),
            _ => Err("matrix dimensions do not fit".into()),
        },
        (Ty::Matrix(c, rows), Ty::Vector(_, n)) if op == BinaryOp::Mul => {
            if c == n {
                Ok(Ty::Vector(Scalar::Float, *rows))
            } else {
                Err(format!("a matrix with {c} columns multiplies a float{c}"))
            }
        }
        (Ty::Vector(_, n), Ty::Matrix(c, rows)) if op == BinaryOp::Mul => {
            if rows == n {
                Ok(Ty::Vector(Scalar::Float, *c))
            } else {
                Err(format!("a float{n} multiplies a matrix with {n} rows"))
            }
        }
        (Ty::Matrix(..), Ty::Scalar(_)) | (Ty::Scalar(_), Ty::Matrix(..)) if op == BinaryOp::Mul => Ok(if matches!(l, Ty::Matrix(..)) { l.clone() } else { r.clone() }),
        (Ty::Matrix(..), _) | (_, Ty::Matrix(..)) => Err("this operator does not apply to matrices".into()),
        (a, b) if a == b => Ok(a.clone()),
        (Ty::Vector(..), Ty::Scalar(_)) => Ok(l.clone()),
        (Ty::Scalar(_), Ty::Vector(..)) => Ok(r.clone()),
        _ => Err("vector sizes differ".into()),
    }
}

pub(super) fn unary_text(op: UnaryOp) -> &'static str {
    match op {
        UnaryOp::Neg => "-",
        UnaryOp::Plus => "+",
        UnaryOp::Not => "!",
        UnaryOp::BitNot => "~",
        UnaryOp::PreInc | UnaryOp::PostInc => "++",
        UnaryOp::PreDec | UnaryOp::PostDec => "--",
    }
}

/// Component indices of a swizzle (`xyzw` or `rgba`, not mixed).
pub(super) fn parse_swizzle(s: &str, width: u8) -> Result<Components, String> {
    if s.is_empty() || s.len() > 4 {
        return Err("a swizzle has 1 to 4 components".into());
    }
    // Bytes: a string all of whose bytes are in a set is ASCII.
    let sets: [&[u8; 4]; 3] = [b"xyzw", b"rgba", b"stpq"];
    let set = sets.iter().find(|set| s.bytes().all(|c| set.contains(&c))).ok_or_else(|| "use components from one of xyzw, rgba or stpq".to_string())?;
    let mut comps = Components::new();
    for c in s.bytes() {
        let i = set.iter().position(|&x| x == c).expect("checked above") as u8;
        if i >= width {
            return Err(format!("component `{}` does not exist on a {width}-component vector", c as char));
        }
        comps.push(i);
    }
    Ok(comps)
}

/// The largest constant index into a run-time-sized array: `int`'s.
pub(super) const MAX_RUNTIME_INDEX: u32 = i32::MAX as u32;
