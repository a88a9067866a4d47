//! Function bodies: entry points and their stage rules, helper functions
//! checked on first use, statements, and assignable places.

use super::*;

impl<'a, 'd> Checker<'a, 'd> {
    // ---------------------------------------------------------------- functions

    pub(super) fn check_entry_points(&mut self) {
        let entries = self.entry_decls.clone();
        let mut names: FxHashMap<String, Span> = FxHashMap::with_capacity_and_hasher(entries.len(), Default::default());
        self.out.entry_points.reserve(entries.len());
        for (decl, stage) in entries {
            let name = entry_name(decl);
            if let Some(why) = entry_name_problem(&name) {
                let at = decl.annotations.iter().flat_map(|a| &a.args).find(|a| a.name.name == "name").and_then(|a| a.value.as_ref()).map_or(decl.name.span, |v| v.span);
                let shown: String = if name.len() > 64 { format!("{}...", name.chars().take(32).collect::<String>()) } else { name.clone() };
                self.diags.push(Diagnostic::error(format!("entry point name {shown:?} {why}"), at).with_note("it names the entry point in every output and the output files"));
                continue;
            }
            if let Some(prev) = names.insert(name.clone(), decl.name.span) {
                let d = Diagnostic::error(format!("two entry points are named `{name}`"), decl.name.span).with_secondary(prev, "first one here");
                self.diags.push(d);
                continue;
            }
            let workgroup_size = match stage {
                naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task => self.workgroup_size(decl),
                _ => [0; 3],
            };
            let mesh = (stage == naga::ShaderStage::Mesh).then(|| self.mesh_output(decl));
            if matches!(stage, naga::ShaderStage::Mesh | naga::ShaderStage::Task) {
                let at = decl.stage_annotation().map_or(decl.name.span, |(a, _)| a.span);
                self.mesh_stage_used(stage, decl.stage_annotation().map_or("", |(a, _)| a.name.name.as_str()), at);
            }
            self.entry_workgroup_size = workgroup_size;
            self.entry_stage = Some(stage);
            let Some(func) = self.check_function(decl, Some(stage), None) else { continue };
            self.check_stage_rules(&name, stage, &func);
            self.check_compute_rules(decl, &name, stage, &func);
            let (annotation, dialect) = decl.stage_annotation().map_or((decl.name.span, ast::Dialect::Gl), |(a, s)| (a.span, s.dialect));
            if dialect == ast::Dialect::Vulkan {
                self.check_vulkan_locations(&name, &func);
                self.check_vulkan_stage_args(decl, stage);
            }
            self.out.entry_points.push(EntryPoint { name, stage, func, locations: Vec::new(), workgroup_size, annotation, dialect, mesh });
        }
    }

    /// The Vulkan dialect matches stage I/O by location, so (as dasSpirv)
    /// every `@in`/`@out` a Vulkan-dialect entry point uses gives one.
    fn check_vulkan_locations(&mut self, name: &str, func: &Function) {
        let mut unlocated: Vec<(GlobalId, Span)> = func.uses.iter().map(|(&g, &s)| (g, s)).filter(|&(g, _)| matches!(self.out.globals[g].kind, GlobalKind::Io { location: None, .. })).collect();
        unlocated.sort_unstable();
        for (g, _) in unlocated {
            let global = &self.out.globals[g];
            let d = Diagnostic::error(format!("`{}` needs `@location = N`: Vulkan-dialect entry point `{name}` uses it", global.name), global.span)
                .with_note("in the Vulkan dialect stage inputs and outputs are matched by location, as dasSpirv requires");
            self.diags.push(d);
        }
    }

    /// The arguments of a Vulkan-dialect vertex or fragment annotation (a
    /// compute one's are read with its workgroup size): `name`; what
    /// dasSpirv has beyond it is refused by name, never ignored.
    fn check_vulkan_stage_args(&mut self, decl: &ast::FunctionDecl, stage: naga::ShaderStage) {
        let workgroups = matches!(stage, naga::ShaderStage::Compute | naga::ShaderStage::Mesh | naga::ShaderStage::Task);
        let Some((a, _)) = decl.stage_annotation().filter(|_| !workgroups) else { return };
        for arg in a.args.iter().filter(|arg| arg.name.name != "name") {
            let arg_name = arg.name.name.as_str();
            let d = if arg_name == "early_fragment_tests" {
                let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
                Diagnostic::error(format!("`early_fragment_tests` is not supported by umbrac on {}", targets.join(", ")), arg.name.span)
                    .with_note("GLSL 3.30 and ES 3.00 have no early fragment tests, and umbrac does not write them elsewhere")
            } else {
                let mut d = Diagnostic::error(format!("unknown `{}` argument `{arg_name}`", a.name.name), arg.name.span).with_note(format!("`[{}(name = \"...\")]`", a.name.name));
                if let Some(s) = suggest(arg_name, ["name", "early_fragment_tests"]) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                d
            };
            self.diags.push(d);
        }
    }

    /// Reports uses that the entry point's stage does not allow.
    pub(super) fn check_stage_rules(&mut self, name: &str, stage: naga::ShaderStage, func: &Function) {
        for (&gid, &span) in &func.uses {
            let g = &self.out.globals[gid];
            if let GlobalKind::Builtin(b) = g.kind {
                if !b.available_in(stage) {
                    let d = Diagnostic::error(format!("`{}` is not available in {} entry point `{name}`", b.name(), stage_name(stage)), span)
                        .with_note(match b.available_in(naga::ShaderStage::Fragment) && b.available_in(naga::ShaderStage::Compute) {
                            true => format!("`{}` belongs to the compute and fragment stages", b.name()),
                            false => format!("`{}` belongs to the {} stage", b.name(), stage_name(b.stage())),
                        });
                    self.diags.push(d);
                }
            }
        }
        if let (naga::ShaderStage::Vertex, Some(span)) = (stage, func.subgroup_op) {
            let d = Diagnostic::error(format!("subgroup operations are not available in vertex entry point `{name}`"), span)
                .with_note("WebGPU and Vulkan 1.1's guaranteed subgroup stages are compute and fragment");
            self.diags.push(d);
        }
        if let (false, Some((span, what))) = (stage == naga::ShaderStage::Fragment, func.fragment_only) {
            let d = Diagnostic::error(format!("{what} is only available in fragment entry points, and `{name}` is a {} entry point", stage_name(stage)), span);
            self.diags.push(d);
        }
    }

    /// The checked function of helper declaration `idx`, checked on first
    /// use (callees land before their callers, and recursion is found).
    pub(super) fn function_id(&mut self, idx: usize, call_span: Span) -> Option<FuncId> {
        let decl = self.fn_decls[idx];
        match self.fn_states[idx] {
            FuncState::Done(id) => Some(id),
            FuncState::Failed => None,
            FuncState::InProgress(def) => {
                let d = Diagnostic::error(format!("`{}` calls itself; shaders cannot recurse", decl.name.name), call_span).with_secondary(def, "function defined here");
                self.diags.push(d);
                None
            }
            FuncState::Unchecked => {
                if self.call_depth > MAX_DEPTH {
                    let d = Diagnostic::error(format!("calls nest too deeply (limit {MAX_DEPTH} levels of nested calls, expressions and blocks)"), call_span)
                        .with_secondary(decl.name.span, "this function is called at the limit");
                    self.diags.push(d);
                    self.fn_states[idx] = FuncState::Failed;
                    return None;
                }
                self.fn_states[idx] = FuncState::InProgress(decl.name.span);
                let sig = self.signature(idx);
                let checked = sig.and_then(|sig| self.check_function(decl, None, Some(&sig.params)));
                match checked {
                    Some(mut f) => {
                        if let Some(name) = self.overload_name(idx, &f) {
                            f.name = name;
                        }
                        let id = self.out.functions.len();
                        self.out.functions.push(f);
                        self.fn_states[idx] = FuncState::Done(id);
                        Some(id)
                    }
                    None => {
                        self.fn_states[idx] = FuncState::Failed;
                        None
                    }
                }
            }
        }
    }

    /// The parameter types of helper declaration `idx`, resolved once (a
    /// wrong type is reported once, and the function is then `None`).
    pub(super) fn signature(&mut self, idx: usize) -> Option<std::rc::Rc<Signature>> {
        if let Some(sig) = &self.fn_sigs[idx] {
            return sig.clone();
        }
        let decl = self.fn_decls[idx];
        let errors = self.diags.error_count();
        let params: Vec<Ty> = decl.params.iter().map(|p| self.resolve_type(&p.ty)).collect();
        for (p, ty) in decl.params.iter().zip(&params) {
            if matches!(ty, Ty::Image(_) | Ty::RuntimeArray(_)) {
                let what = if matches!(ty, Ty::Image(_)) { "a storage image" } else { "a run-time-sized array" };
                let d = Diagnostic::error(format!("parameter `{}` cannot be {what} (`{}`)", p.name.name, self.show(ty)), p.ty.span)
                    .with_note("help: use the global by its name in the function");
                self.diags.push(d);
            }
        }
        let required = decl.params.iter().rposition(|p| p.default.is_none()).map_or(0, |k| k + 1);
        let sig = (self.diags.error_count() == errors).then(|| std::rc::Rc::new(Signature { params, required }));
        self.fn_sigs[idx] = Some(sig.clone());
        sig
    }

    /// The name an overloaded helper has in the output: its own with its
    /// parameter types (`luma_float3`, `luma_float4`), so
    /// every target spells each overload the same way.
    fn overload_name(&self, idx: usize, f: &Function) -> Option<String> {
        let decl = self.fn_decls[idx];
        let name = decl.name.name.as_str();
        if self.funcs.get(name).is_none_or(|ds| ds.len() < 2) {
            return None;
        }
        let mut out = name.to_string();
        for l in &f.locals[..f.params] {
            out.push('_');
            let t = self.show(&l.ty);
            out.extend(t.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }));
        }
        if f.params == 0 {
            out.push_str("_void");
        }
        while out.ends_with('_') {
            out.pop();
        }
        Some(out)
    }

    /// Checks a function's body. `params`: the helper's parameter types,
    /// already resolved (entry points: `None`, resolved here).
    pub(super) fn check_function(&mut self, decl: &'a ast::FunctionDecl, entry: Option<naga::ShaderStage>, params: Option<&[Ty]>) -> Option<Function> {
        let errors_before = self.diags.error_count();
        // `: void` says what no result type says, without inferring.
        let is_void = |t: &ast::TypeExpr| matches!(&t.kind, ast::TypeExprKind::Named(id) if id.name == "void");
        let ret = match &decl.ret {
            Some(t) if entry.is_none() && !is_void(t) => self.resolve_type(t),
            _ => Ty::Void,
        };
        if ret.is_sampler_like() {
            self.diags.push(Diagnostic::error("functions cannot return samplers", decl.ret.as_ref().map(|t| t.span).unwrap_or(decl.name.span)));
        }
        // Scope tables are reused from function to function (a callee is
        // checked in the middle of its first caller, hence a pool).
        let scopes = self.spare_scopes.pop().unwrap_or_else(|| Scopes {
            visible: FxHashMap::with_capacity_and_hasher(16, Default::default()),
            shadowed: Vec::with_capacity(16),
            open: Vec::with_capacity(8),
        });
        let depth = if entry.is_some() { 0 } else { self.call_depth };
        let mut cx = FnCtx::new(scopes, ret, depth, decl.params.len() + count_locals(&decl.body.stmts));
        // No declared result: the first `return` says what it is.
        cx.infer_ret = entry.is_none() && decl.ret.is_none();
        cx.entry = entry.is_some();
        // Samplers are not parameters in the outputs (each helper is copied
        // per sampler); WGSL and SPIR-V take at most 255 of the others.
        let mut passed = 0;
        for (i, p) in decl.params.iter().enumerate() {
            let ty = match params {
                Some(ps) => ps[i].clone(),
                None => self.resolve_type(&p.ty),
            };
            self.check_param(p, &ty);
            passed += usize::from(!ty.is_sampler_like());
            if passed == MAX_PARAMETERS + 1 {
                let d = Diagnostic::error(format!("function `{}` has more than {MAX_PARAMETERS} parameters", decl.name.name), p.span)
                    .with_note("WGSL and SPIR-V allow at most 255 parameters per function (samplers aside); pass a struct or an array");
                self.diags.push(d);
            }
            // daslang passes structs and arrays by reference: a `var` one is
            // the caller's variable, as `var p : T&` is.
            let by_ref = p.mutable && (p.by_ref || matches!(ty, Ty::Struct(_) | Ty::Array(..)));
            let lid = self.declare_local(&mut cx, &p.name, ty, p.mutable);
            cx.locals[lid].by_ref = by_ref;
        }
        let params = cx.locals.len();
        cx.params = params;
        let body = self.check_block(&mut cx, &decl.body.stmts);
        let mut scopes = std::mem::take(&mut cx.scopes);
        scopes.visible.clear();
        scopes.shadowed.clear();
        scopes.open.clear();
        self.spare_scopes.push(scopes);
        let ret = cx.ret.clone();
        if !ret.is_error() && ret != Ty::Void && !always_returns(&body) {
            let mut d = Diagnostic::error(format!("function `{}` can reach its end without returning a `{}`", decl.name.name, self.show(&ret)), decl.body.span)
                .with_label("the last statement here does not return");
            if let (true, Some(first)) = (cx.infer_ret, cx.ret_from) {
                d = d.with_secondary(first, format!("the result type `{}` comes from this `return`", self.show(&ret)));
            }
            self.diags.push(d);
        }
        if self.diags.error_count() > errors_before {
            return None;
        }
        Some(Function {
            name: decl.name.name.as_str().to_string(),
            params,
            locals: cx.locals,
            ret,
            body,
            span: decl.span,
            uses: cx.uses,
            fragment_only: cx.fragment_only,
            subgroup_op: cx.subgroup_op,
            implicit_lod: cx.implicit_lod,
            callees: cx.callees,
            ref_writes: cx.ref_writes,
        })
    }

    /// The rules of one parameter: what its type may be with `var`, `&`
    /// and `const`, and its default value.
    fn check_param(&mut self, p: &'a ast::Param, ty: &Ty) {
        // One sampler is a parameter (each call site picks the global:
        // lowering specialises the function per sampler); an array of
        // them is not.
        if matches!(ty, Ty::Array(..)) && ty.is_sampler_like() {
            let d = Diagnostic::error("an array of samplers cannot be a parameter", p.ty.span)
                .with_note("help: pass one element (`s[k]` with a constant `k`) to a parameter of the element's type, or use the array global directly");
            self.diags.push(d);
        }
        if let (true, Some(c)) = (p.mutable, p.constant) {
            let d = Diagnostic::error(format!("parameter `{}` is both `var` and `const`", p.name.name), c)
                .with_note("help: `var` makes a parameter the function may change; drop one of the two");
            self.diags.push(d);
        }
        if ty.is_sampler_like() && (p.mutable || p.by_ref) {
            let what = if p.mutable { "`var`" } else { "a reference (`&`)" };
            let d = Diagnostic::error(format!("sampler parameter `{}` cannot be {what}", p.name.name), p.span)
                .with_note("a sampler parameter names the sampler the call passes; declare it as `name : sampler2D`");
            self.diags.push(d);
        }
        if let Some(v) = &p.default {
            if ty.is_sampler_like() {
                self.diags.push(Diagnostic::error("a sampler parameter cannot have a default value", v.span));
            } else if !ty.is_error() {
                self.constant_value(v, Some(ty), &format!("the default value of `{}`", p.name.name));
            }
        }
    }

    pub(super) fn declare_local(&mut self, cx: &mut FnCtx<'a>, id: &'a ast::Ident, ty: Ty, mutable: bool) -> LocalId {
        if self.globals.contains_key(id.name.as_str()) {
            let gspan = self.out.globals[self.globals[id.name.as_str()]].span;
            let d = Diagnostic::error(format!("`{}` shadows the shader global of the same name", id.name), id.span).with_secondary(gspan, "global declared here");
            self.diags.push(d);
        } else if let Some(prev) = cx.in_innermost_scope(&id.name) {
            let d = Diagnostic::error(format!("`{}` is already declared in this block", id.name), id.span).with_secondary(cx.locals[prev].span, "first declared here");
            self.diags.push(d);
        }
        let lid = cx.locals.len();
        cx.locals.push(Local { name: id.name.clone(), ty, mutable, by_ref: false, span: id.span });
        cx.declare(&id.name, lid);
        lid
    }

    // ---------------------------------------------------------------- statements

    pub(super) fn check_block(&mut self, cx: &mut FnCtx<'a>, stmts: &'a [ast::Stmt]) -> Vec<Stmt> {
        cx.depth += 1;
        if cx.depth > MAX_DEPTH {
            cx.depth -= 1;
            if let Some(s) = stmts.first() {
                self.diags.push(Diagnostic::error(format!("blocks nest deeper than the limit of {MAX_DEPTH}"), s.span));
            }
            return Vec::new();
        }
        cx.open_scope();
        // Usually one checked statement per statement.
        let mut out = Vec::with_capacity(stmts.len());
        for s in stmts {
            self.check_stmt(cx, s, &mut out);
        }
        cx.close_scope();
        cx.depth -= 1;
        out
    }

    pub(super) fn check_stmt(&mut self, cx: &mut FnCtx<'a>, s: &'a ast::Stmt, out: &mut Vec<Stmt>) {
        match &s.kind {
            ast::StmtKind::Local { mutable, names, ty, init } => {
                let declared = ty.as_ref().map(|t| self.resolve_type(t));
                let init_expr = init.as_ref().map(|e| self.check_expr(cx, e));
                let ty = match (&declared, &init_expr) {
                    (Some(d), Some(e)) => {
                        if !d.is_error() && !e.ty.is_error() && *d != e.ty {
                            let d = Diagnostic::error(format!("type mismatch: `{}` is declared `{}` but initialised with `{}`", names.first.name, self.show(d), self.show(&e.ty)), e.span)
                                .with_label(format!("this is `{}`", self.show(&e.ty)));
                            self.diags.push(d);
                        }
                        d.clone()
                    }
                    (Some(d), None) => {
                        if !*mutable {
                            self.diags.push(Diagnostic::error(format!("`let {}` needs a value", names.first.name), s.span));
                        } else if self.has_field_inits(d) {
                            let t = self.show(d);
                            let help = match d {
                                Ty::Array(elem, _) => format!("help: give it a value: `var {} = fixed_array({}(), ...)`, one per element", names.first.name, self.show(elem)),
                                _ => format!("help: initialise it: `var {} = {t}()` (the initial values) or with the fields you want", names.first.name),
                            };
                            let d = Diagnostic::error(format!("`var {}` would start as zeros, but `{t}` gives fields initial values", names.first.name), s.span).with_note(help);
                            self.diags.push(d);
                        }
                        d.clone()
                    }
                    (None, Some(e)) => e.ty.clone(),
                    (None, None) => {
                        self.diags.push(Diagnostic::error(format!("`{}` needs a type or an initial value", names.first.name), s.span));
                        Ty::Error
                    }
                };
                if !ty.is_value() && !ty.is_error() {
                    let msg = match ty {
                        Ty::Void => "this expression has no value".to_string(),
                        _ => format!("a local variable cannot hold a `{}`", self.show(&ty)),
                    };
                    self.diags.push(Diagnostic::error(msg, init_expr.as_ref().map(|e| e.span).unwrap_or(s.span)));
                }
                // `var a, b = x`: every name gets its own copy of the value.
                let mut init_expr = init_expr;
                for (i, n) in names.iter().enumerate() {
                    let init = if i + 1 == names.count() {
                        init_expr.take()
                    } else {
                        init.as_ref().map(|e| self.check_expr(cx, e))
                    };
                    let local = self.declare_local(cx, n, ty.clone(), *mutable);
                    out.push(Stmt::Local { local, init, span: s.span });
                }
            }
            ast::StmtKind::Assign { target, op, value } => {
                let t = self.check_place(cx, target);
                let v = self.check_expr(cx, value);
                let bin = assign_binop(*op);
                if !t.ty.is_error() && !v.ty.is_error() {
                    match bin {
                        None if t.ty != v.ty => {
                            let d = Diagnostic::error(format!("type mismatch: cannot assign `{}` to `{}`", self.show(&v.ty), self.show(&t.ty)), v.span)
                                .with_label(format!("this is `{}`", self.show(&v.ty)))
                                .with_secondary(t.span, format!("this is `{}`", self.show(&t.ty)));
                            self.diags.push(d);
                        }
                        Some(op) => {
                            if let Some(rt) = self.binary_type(op, &t.ty, &v.ty, s.span) {
                                if rt != t.ty {
                                    let d = Diagnostic::error(
                                        format!("`{}` of `{}` and `{}` gives `{}`, which cannot be stored back into `{}`", op_text(op), self.show(&t.ty), self.show(&v.ty), self.show(&rt), self.show(&t.ty)),
                                        s.span,
                                    );
                                    self.diags.push(d);
                                }
                            }
                        }
                        None => {}
                    }
                }
                out.push(Stmt::Assign { target: t, op: bin, value: v, span: s.span });
            }
            ast::StmtKind::Expr(e) => self.check_expr_stmt(cx, e, s.span, out),
            ast::StmtKind::If { cond, then, elifs, otherwise } => {
                let c = self.check_cond(cx, cond);
                let then = self.check_block(cx, &then.stmts);
                // elif chains become nested ifs.
                let mut tail = otherwise.as_ref().map(|b| self.check_block(cx, &b.stmts)).unwrap_or_default();
                for (ec, eb) in elifs.iter().rev() {
                    let ec2 = self.check_cond(cx, ec);
                    let body = self.check_block(cx, &eb.stmts);
                    tail = vec![Stmt::If { cond: ec2, then: body, otherwise: tail, span: ec.span.to(eb.span) }];
                }
                out.push(Stmt::If { cond: c, then, otherwise: tail, span: s.span });
            }
            ast::StmtKind::While { cond, body } => {
                let c = self.check_cond(cx, cond);
                cx.loop_depth += 1;
                let body = self.check_block(cx, &body.stmts);
                cx.loop_depth -= 1;
                out.push(Stmt::While { cond: c, body, span: s.span });
            }
            ast::StmtKind::For { vars, iters, body } => self.check_for(cx, vars, iters, body, s.span, out),
            ast::StmtKind::CallBlock { callee, args, body } => self.check_call_block(cx, callee, args, body, s.span, out),
            ast::StmtKind::With { subject, body } => self.check_with(cx, subject, body, s.span, out),
            ast::StmtKind::Return(value) => {
                let v = value.as_ref().map(|e| self.check_expr(cx, e));
                // Its outputs are handed over after a workgroup barrier
                // every invocation must reach (`lower::mesh`).
                if cx.entry && self.entry_stage == Some(naga::ShaderStage::Mesh) {
                    let d = Diagnostic::error("a mesh entry point cannot `return`", s.span)
                        .with_note("its outputs are handed over at its end, after a workgroup barrier every invocation must reach: put the rest under an `if` instead");
                    self.diags.push(d);
                }
                self.check_return(cx, v.as_ref(), s.span);
                out.push(Stmt::Return(v, s.span));
            }
            ast::StmtKind::Break | ast::StmtKind::Continue => {
                let is_break = matches!(s.kind, ast::StmtKind::Break);
                if cx.loop_depth == 0 {
                    let d = Diagnostic::error(format!("`{}` outside of a loop", if is_break { "break" } else { "continue" }), s.span);
                    self.diags.push(d);
                }
                out.push(if is_break { Stmt::Break(s.span) } else { Stmt::Continue(s.span) });
            }
            ast::StmtKind::Block(b) => {
                let inner = self.check_block(cx, &b.stmts);
                // A nested block only scopes names; its statements run in order.
                out.push(Stmt::If { cond: Expr { kind: ExprKind::Bool(true), ty: BOOL, span: b.span }, then: inner, otherwise: Vec::new(), span: b.span });
            }
        }
    }

    /// `return [value]`: the value against the declared result, or (none
    /// declared) against the first `return`, which decides it.
    pub(super) fn check_return(&mut self, cx: &mut FnCtx<'a>, v: Option<&Expr>, span: Span) {
        if cx.infer_ret && cx.ret_from.is_none() {
            cx.ret_from = Some(span);
            cx.ret = match v {
                None => Ty::Void,
                Some(e) if e.ty.is_sampler_like() => {
                    self.diags.push(Diagnostic::error("functions cannot return samplers", e.span));
                    Ty::Error
                }
                Some(e) if e.ty == Ty::Void => {
                    self.diags.push(Diagnostic::error("this expression has no value to return", e.span));
                    Ty::Error
                }
                Some(e) => e.ty.clone(),
            };
            return;
        }
        let inferred = cx.infer_ret.then_some(cx.ret_from).flatten();
        match (v, &cx.ret) {
            (None, Ty::Void) => {}
            (Some(e), Ty::Void) => {
                let d = match inferred {
                    Some(first) => Diagnostic::error("this `return` gives a value, but the function's first `return` gives none", e.span)
                        .with_secondary(first, "the first `return`, which makes the result `void`")
                        .with_note("help: every `return` of a function gives a value of one type, or none gives a value"),
                    None if !cx.entry => Diagnostic::error("this function is declared `: void`, so `return` takes no value", e.span),
                    None => Diagnostic::error("an entry point returns nothing, so `return` takes no value", e.span)
                        .with_note("entry points write their results to `@out`/`@inout` globals and `gl_Position`"),
                };
                self.diags.push(d);
            }
            (None, r) if !r.is_error() => {
                let mut d = Diagnostic::error(format!("`return` needs a `{}` value here", self.show(r)), span);
                if let Some(first) = inferred {
                    d = d.with_secondary(first, format!("the first `return` gives a `{}`", self.show(r)));
                }
                self.diags.push(d);
            }
            (Some(e), r) if !r.is_error() && !e.ty.is_error() && e.ty != *r => {
                let d = match inferred {
                    Some(first) => Diagnostic::error(format!("type mismatch: this `return` gives `{}`, but the first `return` gives `{}`", self.show(&e.ty), self.show(r)), e.span)
                        .with_secondary(first, format!("the result type `{}` comes from here", self.show(r)))
                        .with_note("help: convert the value, or declare the result type (`def f(...) : T`)"),
                    None => Diagnostic::error(format!("type mismatch: returning `{}` from a function declared to return `{}`", self.show(&e.ty), self.show(r)), e.span),
                };
                self.diags.push(d);
            }
            _ => {}
        }
    }

    pub(super) fn check_expr_stmt(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr, span: Span, out: &mut Vec<Stmt>) {
        match &e.kind {
            ast::ExprKind::Unary(op @ (UnaryOp::PreInc | UnaryOp::PreDec | UnaryOp::PostInc | UnaryOp::PostDec), inner) => {
                let t = self.check_place(cx, inner);
                let one = match t.ty {
                    Ty::Scalar(Scalar::Int) => Some(ExprKind::Int(1)),
                    Ty::Scalar(Scalar::Uint) => Some(ExprKind::Uint(1)),
                    Ty::Scalar(Scalar::Float) => Some(ExprKind::Float(1.0)),
                    Ty::Error => None,
                    _ => {
                        let d = Diagnostic::error(format!("`++`/`--` need an int, uint or float, not `{}`", self.show(&t.ty)), t.span);
                        self.diags.push(d);
                        None
                    }
                };
                if let Some(one) = one {
                    let bop = if matches!(op, UnaryOp::PreInc | UnaryOp::PostInc) { BinaryOp::Add } else { BinaryOp::Sub };
                    let value = Expr { kind: one, ty: t.ty.clone(), span: e.span };
                    out.push(Stmt::Assign { target: t, op: Some(bop), value, span });
                }
            }
            ast::ExprKind::Call { callee, args } if callee.name == "discard" => {
                if !args.is_empty() {
                    self.diags.push(Diagnostic::error("`discard()` takes no arguments", e.span));
                }
                cx.fragment_only.get_or_insert((e.span, "`discard()`"));
                out.push(Stmt::Discard(span));
            }
            ast::ExprKind::Call { callee, args } if callee.name == "sincos" && !self.funcs.contains_key("sincos") => self.check_sincos(cx, args, e.span, out),
            ast::ExprKind::Call { .. } => {
                let x = self.check_expr(cx, e);
                out.push(Stmt::Expr(x));
            }
            ast::ExprKind::Paren(inner) => self.check_expr_stmt(cx, inner, span, out),
            _ => {
                let x = self.check_expr(cx, e);
                if !x.ty.is_error() {
                    let d = Diagnostic::error("this expression's value is not used", e.span).with_note("only calls, assignments and `++`/`--` can stand alone as statements");
                    self.diags.push(d);
                }
            }
        }
    }

    pub(super) fn check_cond(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let c = self.check_expr(cx, e);
        if !c.ty.is_error() && c.ty != BOOL {
            let d = Diagnostic::error(format!("type mismatch: a condition must be `bool`, found `{}`", self.show(&c.ty)), c.span);
            self.diags.push(d);
        }
        c
    }

    /// `range(n)` or `range(a, b)`.
    pub(super) fn check_range(&mut self, cx: &mut FnCtx<'a>, iter: &'a ast::Expr) -> (Expr, Expr) {
        let bad = |span| Expr { kind: ExprKind::Int(0), ty: Ty::Error, span };
        let ast::ExprKind::Call { callee, args } = &iter.kind else {
            self.diags.push(Diagnostic::error("`for` loops iterate over `range(n)` or `range(a, b)`", iter.span));
            return (bad(iter.span), bad(iter.span));
        };
        if callee.name != "range" || args.is_empty() || args.len() > 2 {
            let msg = if callee.name == "range" { "`range` takes one or two arguments: range(n) or range(a, b)" } else { "`for` loops iterate over `range(n)` or `range(a, b)`" };
            self.diags.push(Diagnostic::error(msg, iter.span));
            return (bad(iter.span), bad(iter.span));
        }
        let mut xs: Vec<Expr> = args.iter().map(|a| self.check_expr(cx, a)).collect();
        for x in &xs {
            if !x.ty.is_error() && x.ty != INT && x.ty != UINT {
                let d = Diagnostic::error(format!("type mismatch: `range` bounds must be `int` or `uint`, found `{}`", self.show(&x.ty)), x.span);
                self.diags.push(d);
            }
        }
        if xs.len() == 2 && xs[0].ty != xs[1].ty && !xs[0].ty.is_error() && !xs[1].ty.is_error() {
            let d = Diagnostic::error(format!("type mismatch: `range` bounds are `{}` and `{}`", self.show(&xs[0].ty), self.show(&xs[1].ty)), iter.span);
            self.diags.push(d);
        }
        if xs.len() == 1 {
            let end = xs.pop().expect("one argument");
            let zero = if end.ty == UINT { ExprKind::Uint(0) } else { ExprKind::Int(0) };
            let ty = if end.ty == UINT { UINT } else { INT };
            (Expr { kind: zero, ty, span: iter.span }, end)
        } else {
            let end = xs.pop().expect("two arguments");
            let start = xs.pop().expect("two arguments");
            (start, end)
        }
    }

    // ---------------------------------------------------------------- places

    /// An assignable expression: a `var` local, an output global, or a
    /// field, swizzle or element of one.
    pub(super) fn check_place(&mut self, cx: &mut FnCtx<'a>, e: &'a ast::Expr) -> Expr {
        let x = self.check_expr(cx, e);
        if let Err(d) = self.place_ok(cx, &x) {
            self.diags.push(d);
        }
        x
    }

    pub(super) fn place_ok(&self, cx: &FnCtx<'a>, x: &Expr) -> Result<(), Diagnostic> {
        match &x.kind {
            ExprKind::Local(id) => {
                let l = &cx.locals[*id];
                if l.mutable {
                    Ok(())
                } else {
                    Err(Diagnostic::error(format!("cannot assign to `{}`: it is declared with `let`", l.name), x.span)
                        .with_label("cannot assign")
                        .with_secondary(l.span, "declared here")
                        .with_note(format!("help: declare it with `var {}` to make it mutable", l.name)))
                }
            }
            ExprKind::Global(id) => {
                let g = &self.out.globals[*id];
                let why = match g.kind {
                    GlobalKind::Uniform { .. } | GlobalKind::Sampler { .. } => Some("it is a uniform, set by the host"),
                    GlobalKind::Storage { access: crate::sema::types::Access::Read, .. } => Some("it is a `@readonly` storage buffer"),
                    GlobalKind::Image { .. } => Some("a storage image is written with `imageStore(image, coord, value)`"),
                    GlobalKind::Io { kind: IoKind::In, .. } => Some("it is an `@in` input"),
                    GlobalKind::Builtin(b) if !b.is_output() => Some("it is a builtin input"),
                    GlobalKind::SpecConstant { .. } => Some("it is a specialization constant, set by the host when it creates the pipeline"),
                    // naga (and SPIR-V) let only the task stage write it.
                    GlobalKind::TaskPayload if !(cx.entry && self.entry_stage == Some(naga::ShaderStage::Task)) => {
                        Some("it is a `@task_payload`, written only in the body of the task entry point (mesh entry points read it)")
                    }
                    _ => None,
                };
                match why {
                    None => Ok(()),
                    Some(why) => Err(Diagnostic::error(format!("cannot assign to `{}`: {why}", g.name), x.span).with_secondary(g.span, "declared here")),
                }
            }
            ExprKind::Const(_) => Err(Diagnostic::error("cannot assign to a constant", x.span)),
            ExprKind::Field(base, _) | ExprKind::Index(base, _) => self.place_ok(cx, base),
            ExprKind::Swizzle(base, comps) => {
                let mut seen = [false; 4];
                for &c in comps {
                    if std::mem::replace(&mut seen[c as usize], true) {
                        return Err(Diagnostic::error("cannot assign to a swizzle that repeats a component", x.span));
                    }
                }
                self.place_ok(cx, base)
            }
            _ if x.ty.is_error() => Ok(()),
            _ => Err(Diagnostic::error("cannot assign to this expression", x.span).with_label("not a variable")),
        }
    }

}

pub(super) fn stage_name(s: naga::ShaderStage) -> &'static str {
    match s {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Mesh => "mesh",
        naga::ShaderStage::Task => "task",
        _ => "compute",
    }
}

/// Whether every path through `stmts` ends in `return` (or `discard`).
/// Each branch is looked at once: asking twice per `if` was exponential in
/// the nesting depth.
pub(super) fn always_returns(stmts: &[Stmt]) -> bool {
    match stmts.last() {
        Some(Stmt::Return(..)) | Some(Stmt::Discard(_)) => true,
        Some(Stmt::If { then, otherwise, cond, .. }) => {
            always_returns(then) && (matches!(cond.kind, ExprKind::Bool(true)) || always_returns(otherwise))
        }
        _ => false,
    }
}

pub(super) fn assign_binop(op: ast::AssignOp) -> Option<BinaryOp> {
    use ast::AssignOp as A;
    Some(match op {
        A::Set => return None,
        A::Add => BinaryOp::Add,
        A::Sub => BinaryOp::Sub,
        A::Mul => BinaryOp::Mul,
        A::Div => BinaryOp::Div,
        A::Mod => BinaryOp::Mod,
        A::BitAnd => BinaryOp::BitAnd,
        A::BitOr => BinaryOp::BitOr,
        A::BitXor => BinaryOp::BitXor,
        A::Shl => BinaryOp::Shl,
        A::Shr => BinaryOp::Shr,
    })
}

/// How many locals `stmts` declare (`let`/`var` names and loop variables,
/// nested blocks included), to size a function's table of locals once.
fn count_locals(stmts: &[ast::Stmt]) -> usize {
    stmts
        .iter()
        .map(|s| match &s.kind {
            ast::StmtKind::Local { names, .. } => names.count(),
            ast::StmtKind::If { then, elifs, otherwise, .. } => {
                count_locals(&then.stmts)
                    + elifs.iter().map(|(_, b)| count_locals(&b.stmts)).sum::<usize>()
                    + otherwise.as_ref().map_or(0, |b| count_locals(&b.stmts))
            }
            ast::StmtKind::While { body, .. } => count_locals(&body.stmts),
            // The loop variables and up to two hidden locals per source.
            ast::StmtKind::For { body, vars, iters } => vars.len() + 2 * iters.len() + count_locals(&body.stmts),
            ast::StmtKind::With { body, .. } => 2 + count_locals(&body.stmts),
            ast::StmtKind::Block(b) | ast::StmtKind::CallBlock { body: b, .. } => 2 + count_locals(&b.stmts),
            _ => 0,
        })
        .sum()
}

/// The most parameters a helper may pass (the WGSL specification's limit,
/// and the SPIR-V specification's "function parameters per function
/// declaration").
pub const MAX_PARAMETERS: usize = 255;

/// The longest entry point name: `NAME.300es.frag` (or `.310es.comp`)
/// must fit the 255 bytes most file systems allow a file name.
pub const MAX_ENTRY_NAME_LEN: usize = 255 - ".300es.frag".len();

/// Why a name given with `[vertex_program(name = "...")]` cannot name an
/// entry point: the outputs, the manifest and the file names all use it
/// as it is, so it must be a plain identifier within the name limit.
fn entry_name_problem(name: &str) -> Option<String> {
    // It names files, `NAME.300es.frag` the longest: file systems take
    // names of at most 255 bytes.
    let limit = MAX_ENTRY_NAME_LEN;
    let mut chars = name.chars();
    if !chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') || !chars.all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Some("is not a name: use letters, digits and `_`, starting with a letter or `_`".into());
    }
    if name.len() > limit {
        return Some(format!("is {} characters long; entry point names are limited to {limit}, as they name the output files (`NAME.300es.frag`, at most 255 bytes)", name.len()));
    }
    // naga's WGSL writer renames what WGSL reserves (`fn` becomes `fn_`),
    // and the manifest would name an entry point the WGSL does not have.
    // naga's own sets of those words: a scan of its ~400 words was 3,000
    // instructions a name, and a set of our own cost building (50,000)
    // besides the ones naga's WGSL writer builds anyway.
    let wgsl = |n: &str| naga::keywords::wgsl::RESERVED_SET.contains(n) || naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET.contains(n);
    if wgsl(name) || name.starts_with("__") || name == "_" {
        return Some("is reserved in WGSL; choose another".into());
    }
    None
}
