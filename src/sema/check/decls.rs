//! Declarations: structs, shader globals (locations, texture units, uniform
//! layouts), type expressions and `let` constants.

use super::*;

/// Size and alignment of a type in a WGSL uniform block (natural layout) and
/// under GLSL std140.
pub(super) struct UniformLayout {
    size: u32,
    align: u32,
    std_size: u32,
    std_align: u32,
}

impl<'a, 'd> Checker<'a, 'd> {
    // ---------------------------------------------------------------- declarations

    pub(super) fn declare(&mut self) {
        let items = &self.ast.items;
        // Sized once: these tables are filled in one go.
        let mut counts = [0usize; 4];
        for item in items {
            match item {
                ast::Item::Struct(_) => counts[0] += 1,
                ast::Item::Global(_) => counts[1] += 1,
                ast::Item::Const(_) => counts[2] += 1,
                ast::Item::Function(_) => counts[3] += 1,
                ast::Item::Enum(_) => {}
            }
        }
        self.structs.reserve(counts[0]);
        self.globals.reserve(counts[1]);
        self.const_decls.reserve(counts[2]);
        self.consts.reserve(counts[2]);
        self.funcs.reserve(counts[3]);
        // The checked program's tables too, each pushed to one at a time.
        // Globals leave room for the `gl_*` builtins a program uses.
        self.out.structs.reserve(counts[0]);
        self.out.globals.reserve(counts[1] + 2);
        self.out.consts.reserve(counts[2]);
        self.out.functions.reserve(counts[3]);
        let mut seen: FxHashMap<&'a str, Span> = FxHashMap::with_capacity_and_hasher(items.len(), Default::default());
        // Struct and enumeration names first, so fields and globals can use any.
        for item in items {
            if let ast::Item::Struct(s) = item {
                self.check_unique(&mut seen, &s.name);
                // A second struct of one name is reported; uses mean the first.
                self.structs.entry(&s.name.name).or_insert(self.out.structs.len());
                self.out.structs.push(StructDef { name: s.name.name.as_str().to_string(), fields: Vec::new(), span: s.span });
            }
        }
        self.declare_enums(&mut seen);
        self.field_inits = vec![Vec::new(); self.out.structs.len()];
        // The n-th struct item is struct n (pushed in that order above);
        // not looked up by name, which a duplicate name maps to the other.
        let mut next_struct = 0;
        for item in items {
            match item {
                ast::Item::Struct(s) => {
                    let id = next_struct;
                    next_struct += 1;
                    let mut fields: Vec<(String, Ty, Span)> = Vec::with_capacity(s.fields.len());
                    // Name -> index, for the duplicate check here and field
                    // lookups later: one hash lookup each, whatever the size.
                    let mut index: FxHashMap<&'a str, u32> = FxHashMap::with_capacity_and_hasher(s.fields.len(), Default::default());
                    // Initial values are rare: a table only where there are some.
                    let inits = s.fields.iter().any(|f| f.init.is_some());
                    for f in &s.fields {
                        // A field without a type takes its initial value's,
                        // once constants are known (below).
                        let ty = f.ty.as_ref().map_or(Ty::Error, |t| self.resolve_type(t));
                        if let Some(&prev) = index.get(f.name.name.as_str()) {
                            let d = Diagnostic::error(format!("field `{}` is declared twice", f.name.name), f.name.span)
                                .with_secondary(fields[prev as usize].2, "first declared here");
                            self.diags.push(d);
                        } else {
                            index.insert(&f.name.name, fields.len() as u32);
                        }
                        // `T[]` only as the last field (of a struct an `@ssbo` holds).
                        let last_unsized = fields.len() + 1 == s.fields.len() && matches!(&ty, Ty::RuntimeArray(e) if e.is_value() && !self.is_unsized(e));
                        if !ty.is_value() && !ty.is_error() && !last_unsized {
                            let what = if matches!(ty, Ty::RuntimeArray(_)) { "a run-time-sized array must be the last field of a struct, of plain values" } else { "a struct field cannot have type" };
                            let d = Diagnostic::error(format!("{what} `{}`", self.show(&ty)), f.ty.as_ref().map_or(f.span, |t| t.span));
                            self.diags.push(d);
                        }
                        fields.push((f.name.name.as_str().to_string(), ty, f.name.span));
                        if inits {
                            self.field_inits[id].push(f.init.as_ref());
                        }
                    }
                    if fields.is_empty() {
                        let d = Diagnostic::error(format!("struct `{}` has no fields", s.name.name), s.name.span);
                        self.diags.push(d);
                    }
                    self.out.structs[id].fields = fields;
                    self.field_index.resize_with(self.out.structs.len(), FxHashMap::default);
                    self.field_index[id] = index;
                }
                ast::Item::Const(k) => {
                    self.check_unique(&mut seen, &k.name);
                    self.const_decls.insert(&k.name.name, k);
                }
                ast::Item::Function(f) => {
                    // Overloads share a name, and a function may be named
                    // like a struct (its initializer).
                    let name: &'a str = &f.name.name;
                    if is_entry(f).is_some() || !(self.funcs.contains_key(name) || self.structs.contains_key(name)) {
                        self.check_unique(&mut seen, &f.name);
                    }
                    if let Some((a, ast::StageAnnotation { stage: None, .. })) = f.stage_annotation() {
                        self.uncompiled_stage(a);
                        continue;
                    }
                    match is_entry(f) {
                        Some(stage) => {
                            let returns = f.ret.as_ref().is_some_and(|t| !matches!(&t.kind, ast::TypeExprKind::Named(id) if id.name == "void"));
                            if !f.params.is_empty() || returns {
                                let d = Diagnostic::error(format!("entry point `{}` cannot take parameters or return a value", f.name.name), f.name.span)
                                    .with_note("entry points read `@in`/`@inout` globals and write `@out`/`@inout` globals and `gl_Position`");
                                self.diags.push(d);
                            }
                            self.entry_decls.push((f, stage));
                        }
                        None => {
                            self.funcs.entry(name).or_default().push(self.fn_decls.len());
                            self.fn_decls.push(f);
                            self.fn_states.push(FuncState::Unchecked);
                            self.fn_sigs.push(None);
                        }
                    }
                }
                ast::Item::Global(_) | ast::Item::Enum(_) => {}
            }
        }
        self.enum_values();
        self.check_field_inits();
        self.check_overloads();
        self.check_struct_recursion();
        self.declare_globals(&mut seen);
    }

    /// Fields' initial values: constants of the field's type (or giving the
    /// type of a field declared without one).
    fn check_field_inits(&mut self) {
        let structs = self.ast.items.iter().filter_map(|item| match item {
            ast::Item::Struct(s) => Some(s),
            _ => None,
        });
        for (id, s) in structs.enumerate() {
            for (i, f) in s.fields.iter().enumerate() {
                let Some(init) = &f.init else { continue };
                let declared = self.out.structs[id].fields[i].1.clone();
                let Some(v) = self.field_init_value(id, i, init, init.span) else { continue };
                match &f.ty {
                    // A field without a type has its value's.
                    None => self.out.structs[id].fields[i].1 = v.ty,
                    Some(_) if !declared.is_error() && v.ty != declared => {
                        let d = Diagnostic::error(
                            format!("type mismatch: the initial value of `{}.{}` is `{}`, but its type is `{}`", s.name.name, f.name.name, self.show(&v.ty), self.show(&declared)),
                            v.span,
                        )
                        .with_label(format!("this is `{}`", self.show(&v.ty)));
                        self.diags.push(d);
                    }
                    Some(_) => {}
                }
            }
        }
    }

    /// Overloads of one name must differ in their parameter types.
    fn check_overloads(&mut self) {
        let groups: Vec<Vec<usize>> = self.funcs.values().filter(|ds| ds.len() > 1).cloned().collect();
        for ds in groups {
            let sigs: Vec<Option<std::rc::Rc<Signature>>> = ds.iter().map(|&d| self.signature(d)).collect();
            for (k, &d) in ds.iter().enumerate() {
                let Some(sig) = &sigs[k] else { continue };
                let earlier = (0..k).find(|&j| sigs[j].as_ref().is_some_and(|s| s.params == sig.params));
                if let Some(j) = earlier {
                    let f = self.fn_decls[d];
                    let e = Diagnostic::error(format!("`{}` is defined twice with the same parameter types", f.name.name), f.name.span)
                        .with_secondary(self.fn_decls[ds[j]].name.span, "first defined here")
                        .with_note("overloads of one name differ in their parameter types");
                    self.diags.push(e);
                }
            }
        }
    }

    /// Finds structs that contain themselves and structs nested deeper than
    /// [`MAX_TYPE_DEPTH`], reporting each and clearing its fields so later
    /// passes (which recurse through types) stay finite and shallow.
    pub(super) fn check_struct_recursion(&mut self) {
        // Struct ids a type mentions, looking through arrays, with the array
        // levels on the way.
        fn edges(ty: &Ty, arrays: usize, out: &mut Vec<(StructId, usize)>) -> usize {
            match ty {
                Ty::Struct(id) => {
                    out.push((*id, arrays));
                    0
                }
                Ty::Array(elem, _) => edges(elem, arrays + 1, out),
                _ => arrays,
            }
        }
        #[derive(Clone, Copy, PartialEq)]
        enum State {
            New,
            Open,
            Done(usize),
        }
        let n = self.out.structs.len();
        let mut state = vec![State::New; n];
        let mut bad: Vec<(StructId, bool)> = Vec::new();
        // Iterative depth-first search: (struct, index of the next field edge).
        for root in 0..n {
            if state[root] != State::New {
                continue;
            }
            let mut stack: Vec<(StructId, Vec<(StructId, usize)>, usize, usize)> = Vec::new();
            let push = |id: StructId, structs: &[StructDef], state: &mut [State]| {
                let mut es = Vec::new();
                let mut depth = 1;
                for (_, t, _) in &structs[id].fields {
                    depth = depth.max(1 + edges(t, 0, &mut es));
                }
                state[id] = State::Open;
                (id, es, 0, depth)
            };
            stack.push(push(root, &self.out.structs, &mut state));
            while let Some(top) = stack.last_mut() {
                let (id, es, next, depth) = top;
                if let Some(&(child, arrays)) = es.get(*next) {
                    *next += 1;
                    match state[child] {
                        State::Done(d) => *depth = (*depth).max(1 + arrays + d),
                        State::Open => {
                            if !bad.iter().any(|(b, _)| *b == child) {
                                bad.push((child, true));
                            }
                        }
                        State::New => {
                            let frame = push(child, &self.out.structs, &mut state);
                            stack.push(frame);
                        }
                    }
                    continue;
                }
                let (id, d) = (*id, *depth);
                state[id] = State::Done(d);
                stack.pop();
                if d > MAX_TYPE_DEPTH && !bad.iter().any(|(b, _)| *b == id) {
                    bad.push((id, false));
                }
                if let Some(parent) = stack.last_mut() {
                    let arrays = parent.1[parent.2 - 1].1;
                    parent.3 = parent.3.max(1 + arrays + d);
                }
            }
        }
        bad.sort();
        for (id, cycle) in bad {
            let s = &self.out.structs[id];
            let d = if cycle {
                Diagnostic::error(format!("struct `{}` contains itself", s.name), s.span)
            } else {
                Diagnostic::error(format!("struct `{}` nests struct and array types deeper than the limit of {MAX_TYPE_DEPTH}", s.name), s.span)
            };
            self.diags.push(d);
            for f in &mut self.out.structs[id].fields {
                f.1 = Ty::Error;
            }
        }
    }

    /// Declares the shader globals. Locations and texture units written
    /// in the source are range-checked here; the others are numbered, and
    /// all are checked for clashes, per program once the entry points are
    /// known (`programs.rs`).
    pub(super) fn declare_globals(&mut self, seen: &mut FxHashMap<&'a str, Span>) {
        let items = &self.ast.items;
        for item in items {
            let ast::Item::Global(g) = item else { continue };
            self.check_unique(seen, &g.name);
            if BuiltinVar::from_name(&g.name.name).is_some() || g.name.name.starts_with("gl_") {
                let d = Diagnostic::error(format!("`{}` is reserved for builtin variables", g.name.name), g.name.span);
                self.diags.push(d);
            }
            if g.qualifiers.is_empty() {
                self.declare_module_var(g);
                continue;
            }
            // The parser gives every global with qualifiers a type.
            let Some(gty) = &g.ty else { continue };
            let ty = self.resolve_type(gty);
            let mut class: Option<(&'static str, Span)> = None;
            let mut location: Option<(i64, Span)> = None;
            let mut stage: Option<(Option<i64>, Span)> = None;
            // An annotation already reported: no second error for the global.
            let mut refused = false;
            // `@set = N`, `@binding = N`.
            let mut bind: (Option<(i64, Span)>, Option<(i64, Span)>) = (None, None);
            // `@readonly` / `@writeonly`, `@format = F` (storage buffers and images).
            let mut access: Option<(Access, Span)> = None;
            let mut format: Option<(ImageFormat, Span)> = None;
            let mut constant_id: Option<(i64, Span)> = None;
            let mut flat: Option<Span> = None;
            let push_constant = g.qualifiers.iter().any(|q| matches!(&q.kind, ast::QualifierKind::Other(n) if n == "push_constant"));
            for q in &g.qualifiers {
                let c = match &q.kind {
                    ast::QualifierKind::Uniform => Some("uniform"),
                    ast::QualifierKind::In => Some("in"),
                    ast::QualifierKind::Out => Some("out"),
                    ast::QualifierKind::InOut => Some("inout"),
                    ast::QualifierKind::Location(l) => {
                        if let Some(l) = l {
                            location = Some((*l, q.span));
                        }
                        None
                    }
                    ast::QualifierKind::Stage(s) => {
                        stage = Some((*s, q.span));
                        None
                    }
                    ast::QualifierKind::Set(n) => {
                        bind.0 = Some((*n, q.span));
                        None
                    }
                    ast::QualifierKind::Binding(n) => {
                        bind.1 = Some((*n, q.span));
                        None
                    }
                    // daslang binds `@push_constant` like `@uniform` on GL:
                    // a uniform on every target (docs/language.md).
                    ast::QualifierKind::Other(name) if name == "push_constant" => Some("uniform"),
                    ast::QualifierKind::Other(name) if name == "ssbo" => Some("ssbo"),
                    // dasSpirv's `@flat`: no interpolation (ints are flat anyway).
                    ast::QualifierKind::Other(name) if name == "flat" => {
                        flat = Some(q.span);
                        None
                    }
                    ast::QualifierKind::Other(name) if name == "groupshared" => Some("groupshared"),
                    ast::QualifierKind::Other(name) if name == "task_payload" => Some("task_payload"),
                    ast::QualifierKind::ConstantId(n) => {
                        constant_id = Some((*n, q.span));
                        Some("constant_id")
                    }
                    ast::QualifierKind::Other(name) if name == "readonly" || name == "writeonly" => {
                        let a = if name == "readonly" { Access::Read } else { Access::Write };
                        if let Some((prev, prev_span)) = access.filter(|p| p.0 != a) {
                            let d = Diagnostic::error(format!("`@{name}` conflicts with `@{}`", if prev == Access::Read { "readonly" } else { "writeonly" }), q.span)
                                .with_secondary(prev_span, "already declared here")
                                .with_note("leave both out for read-write access");
                            self.diags.push(d);
                        }
                        access = Some((a, q.span));
                        None
                    }
                    ast::QualifierKind::Format(id) => {
                        match ImageFormat::from_name(&id.name) {
                            Some(f) => format = Some((f, q.span)),
                            None => {
                                let names: Vec<&str> = ImageFormat::ALL.iter().map(|f| f.name()).collect();
                                let mut d = Diagnostic::error(format!("unknown image format `{}`", id.name), id.span).with_label("not a storage image format");
                                if let Some(s) = suggest(&id.name, names.iter().copied()) {
                                    d = d.with_note(format!("help: did you mean `{s}`?"));
                                }
                                self.diags.push(d.with_note(format!("the formats every target with storage images has: {}", names.join(", "))));
                                refused = true;
                            }
                        }
                        None
                    }
                    // dasSpirv's payloads of the stages umbrac does not compile.
                    ast::QualifierKind::Other(name) if matches!(name.as_str(), "ray_payload" | "incoming_ray_payload" | "hit_attribute" | "callable_data" | "incoming_callable_data") => {
                        let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
                        let d = Diagnostic::error(format!("`@{name}` (of ray-tracing shaders) is not supported by umbrac on {}", targets.join(", ")), q.span)
                            .with_note("umbrac compiles the vertex, fragment, compute, mesh and task stages of the Vulkan dialect");
                        self.diags.push(d);
                        refused = true;
                        None
                    }
                    ast::QualifierKind::Other(name) => {
                        let d = Diagnostic::error(format!("unknown annotation `@{name}`"), q.span)
                            .with_note("shader globals take @uniform, @in, @out, @inout, @flat, @push_constant, @ssbo, @groupshared, @readonly, @writeonly, @format = F, @location = N, @stage = N, @set = N and @binding = N");
                        self.diags.push(d);
                        refused = true;
                        None
                    }
                };
                if let Some(c) = c {
                    if let Some((prev, prev_span)) = class {
                        let d = Diagnostic::error(format!("`@{c}` conflicts with `@{prev}`"), q.span).with_secondary(prev_span, "already declared here");
                        self.diags.push(d);
                    } else {
                        class = Some((c, q.span));
                    }
                }
            }
            // A uniform's initial value is the host's default; other
            // shader globals have none.
            if let (Some(init), Some(("uniform" | "constant_id", _))) = (&g.init, class) {
                if ty.is_sampler_like() {
                    let d = Diagnostic::error("samplers cannot have an initial value", init.span).with_note("the host binds a texture to each sampler");
                    self.diags.push(d);
                }
            } else if let Some(init) = &g.init {
                // (and `@constant_id` constants, whose value is their default)
                let d = Diagnostic::error("only `@uniform` values can have an initial value", init.span)
                    .with_note("a uniform's initial value is the default the host sets; inputs and outputs have none");
                self.diags.push(d);
            }
            // A storage image needs no `@uniform` (it is one in GLSL); in the
            // Vulkan dialect a sampler at a `@set`/`@binding` needs none either
            // (dasSpirv reads it as a descriptor).
            let bound = bind.0.is_some() || bind.1.is_some();
            let class = class.or_else(|| (matches!(ty, Ty::Image(_)) || (self.vulkan && bound && ty.is_sampler_like())).then_some(("uniform", g.name.span)));
            if !(matches!(class, Some(("ssbo", _))) || matches!(ty, Ty::Image(_))) {
                if let Some((_, span)) = access {
                    self.diags.push(Diagnostic::error("`@readonly` and `@writeonly` apply only to `@ssbo` buffers and storage images", span));
                }
            }
            if let Some((_, span)) = format.filter(|_| !matches!(ty, Ty::Image(_))) {
                self.diags.push(Diagnostic::error("`@format` applies only to storage images (`image2D`, `uimage3D`, ...)", span));
            }
            let Some((class, class_span)) = class else {
                if refused {
                    // Declared, with no type, so that its uses report nothing more.
                    self.globals.insert(&g.name.name, self.out.globals.len());
                    self.out.globals.push(Global { name: g.name.name.as_str().to_string(), ty: Ty::Error, kind: GlobalKind::Uniform { default: None }, span: g.name.span, bind: None });
                } else {
                    let d = Diagnostic::error(format!("`{}` has no shader qualifier", g.name.name), g.name.span);
                    self.diags.push(d);
                }
                continue;
            };
            let kind = match (class, &ty) {
                ("uniform", Ty::Sampler(_)) | ("uniform", Ty::Array(..)) if ty.is_sampler_like() => {
                    let (kind, count) = match &ty {
                        Ty::Array(elem, n) => match **elem {
                            Ty::Sampler(k) => (k, Some(*n)),
                            _ => (SamplerKind::Sampler2D, Some(*n)),
                        },
                        Ty::Sampler(k) => (*k, None),
                        _ => (SamplerKind::Sampler2D, None),
                    };
                    let n = count.unwrap_or(1);
                    if let (true, Some(_)) = (self.vulkan, count) {
                        self.descriptor_array_used(gty.span);
                    }
                    if let Some((_, span)) = location {
                        self.diags.push(Diagnostic::error("`@location` does not apply to samplers; use `@stage = N` for the texture unit", span));
                    }
                    let unit = match stage {
                        Some((Some(s), span)) if !(0..32).contains(&s) || s + n as i64 > 32 => {
                            let msg = if n > 1 {
                                format!("texture units {s}..{} are out of range (0..=31)", s + n as i64 - 1)
                            } else {
                                format!("texture unit {s} is out of range (0..=31)")
                            };
                            self.diags.push(Diagnostic::error(msg, span));
                            0
                        }
                        Some((Some(s), span)) => {
                            self.unit_spans.insert(self.out.globals.len(), span);
                            s as u32
                        }
                        // Bare `@stage`, or none: numbered per program.
                        _ => 0,
                    };
                    GlobalKind::Sampler { kind, texture_unit: unit, count }
                }
                ("uniform", Ty::Image(k)) => {
                    // dasSpirv's default format is rgba8, as dasGlsl's bare `@format`.
                    let format = format.or_else(|| self.vulkan.then(|| ImageFormat::from_name("rgba8").map(|f| (f, gty.span))).flatten());
                    let unit = self.storage_unit(location.map(|l| l.1), stage, "storage images");
                    self.image_kind(*k, format, access, unit, gty.span)
                }
                ("ssbo", _) => {
                    let unit = self.storage_unit(location.map(|l| l.1), stage, "`@ssbo` buffers");
                    self.storage_kind(&ty, access, unit, gty.span)
                }
                ("constant_id", _) => match self.spec_constant(g, &ty, constant_id, gty.span) {
                    Some(kind) => kind,
                    None => {
                        self.declare_failed(g);
                        continue;
                    }
                },
                ("groupshared", _) => {
                    if let Some(span) = location.map(|l| l.1).or(stage.map(|s| s.1)) {
                        self.diags.push(Diagnostic::error("`@groupshared` variables take no `@location` or `@stage`", span));
                    }
                    if !ty.is_error() && (!ty.is_value() || self.is_unsized(&ty)) {
                        self.diags.push(Diagnostic::error(format!("`@groupshared` variables must be plain values, not `{}`", self.show(&ty)), gty.span));
                    }
                    GlobalKind::Workgroup
                }
                ("task_payload", _) => {
                    if let Some(span) = location.map(|l| l.1).or(stage.map(|s| s.1)) {
                        self.diags.push(Diagnostic::error("`@task_payload` variables take no `@location` or `@stage`", span));
                    }
                    if !ty.is_error() && (!ty.is_value() || self.is_unsized(&ty)) {
                        self.diags.push(Diagnostic::error(format!("`@task_payload` variables must be plain values, not `{}`", self.show(&ty)), gty.span));
                    }
                    GlobalKind::TaskPayload
                }
                ("uniform", _) => {
                    if let Some(span) = location.map(|l| l.1).or(stage.map(|s| s.1)) {
                        self.diags.push(Diagnostic::error("uniform values take no `@location` or `@stage`", span));
                    }
                    if !ty.is_error() {
                        if let Some(msg) = self.uniform_type_problem(&ty) {
                            self.diags.push(Diagnostic::error(msg, gty.span));
                        }
                    }
                    let default = g.init.as_ref().and_then(|e| self.uniform_default(&g.name.name, &ty, e));
                    GlobalKind::Uniform { default }
                }
                (c, _) => {
                    let io = match c {
                        "in" => IoKind::In,
                        "out" => IoKind::Out,
                        _ => IoKind::InOut,
                    };
                    if let Some((_, span)) = stage {
                        self.diags.push(Diagnostic::error("`@stage` applies only to samplers, storage images and `@ssbo` buffers", span));
                    }
                    // `@out array<T>`: a mesh entry point's per-vertex
                    // output (one `T` per vertex, `check_stage_rules`).
                    let io_ty = match (&ty, c) {
                        (Ty::RuntimeArray(elem), "out") => &**elem,
                        _ => &ty,
                    };
                    let ok = matches!(io_ty, Ty::Scalar(s) | Ty::Vector(s, _) if *s != Scalar::Bool) || ty.is_error();
                    if matches!(ty, Ty::Scalar(Scalar::Half) | Ty::Vector(Scalar::Half, _)) {
                        self.diags.push(half_interface_error(&format!("an `@{c}` variable"), gty.span));
                    } else if !ok {
                        let d = Diagnostic::error(format!("`@{c}` variables must be numeric scalars or vectors, not `{}`", self.show(&ty)), gty.span);
                        self.diags.push(d);
                    }
                    let loc = match location {
                        Some((l, span)) if !(0..MAX_LOCATIONS as i64).contains(&l) => {
                            self.diags.push(Diagnostic::error(format!("location {l} is out of range (0..{MAX_LOCATIONS})"), span));
                            None
                        }
                        Some((l, span)) => {
                            self.location_spans.insert(self.out.globals.len(), span);
                            Some(l as u32)
                        }
                        None => None,
                    };
                    let _ = class_span;
                    GlobalKind::Io { kind: io, location: loc }
                }
            };
            if let Some(span) = flat {
                if matches!(kind, GlobalKind::Io { .. }) {
                    self.out.flat.insert(self.out.globals.len());
                } else {
                    self.diags.push(Diagnostic::error("`@flat` applies only to `@in` and `@out` variables", span));
                }
            }
            if push_constant {
                self.out.push_constants.insert(self.out.globals.len());
            }
            self.written_bind(&kind, bind);
            self.globals.insert(&g.name.name, self.out.globals.len());
            self.out.globals.push(Global { name: g.name.name.as_str().to_string(), ty, kind, span: g.name.span, bind: None });
        }
    }

    /// Whether `ty` is or holds a run-time-sized array (only an `@ssbo`
    /// holds one: it is no value to copy).
    pub(super) fn is_unsized(&self, ty: &Ty) -> bool {
        match ty {
            Ty::RuntimeArray(_) => true,
            Ty::Struct(id) => self.out.structs.get(*id).is_some_and(|s| s.fields.last().is_some_and(|f| matches!(f.1, Ty::RuntimeArray(_)))),
            _ => false,
        }
    }

    /// The GL unit of a storage image (image unit) or buffer (binding
    /// point), as dasGlsl reads `@stage = N`: the number written (0 until
    /// numbered when bare or absent, `programs::number_storage_units`).
    fn storage_unit(&mut self, location: Option<Span>, stage: Option<(Option<i64>, Span)>, what: &str) -> u32 {
        if let Some(span) = location {
            self.diags.push(Diagnostic::error(format!("{what} take no `@location`; `@stage = N` is their GL unit"), span));
        }
        match stage {
            Some((Some(s), span)) if !(0..32).contains(&s) => {
                self.diags.push(Diagnostic::error(format!("GL unit {s} is out of range (0..=31)"), span));
                0
            }
            Some((Some(s), span)) => {
                self.unit_spans.insert(self.out.globals.len(), span);
                s as u32
            }
            _ => 0,
        }
    }

    /// A storage image: `@format` given and matching the type's texels.
    /// Read-write unless `@readonly`/`@writeonly`, as in dasGlsl; the
    /// targets that lack read-write access to its format are refused
    /// (`targets::read_write_image_used`).
    fn image_kind(&mut self, k: ImageKind, format: Option<(ImageFormat, Span)>, access: Option<(Access, Span)>, unit: u32, ty_span: Span) -> GlobalKind {
        let access_given = access.map(|a| a.0);
        let Some((format, format_span)) = format else {
            let d = Diagnostic::error(format!("storage image `{}` needs a texel format: `@format = F`", k.name()), ty_span)
                .with_note(format!("help: for example `@format = {}` (a bare `@format` is `rgba8`, as in daslang)", match k.scalar { Scalar::Uint => "r32ui", Scalar::Int => "r32i", _ => "rgba8" }));
            self.diags.push(d);
            return GlobalKind::Image { format: ImageFormat::R32f, access: access_given.unwrap_or(Access::ReadWrite), unit };
        };
        if format.scalar() != k.scalar {
            let want = match format.scalar() { Scalar::Uint => "uimage", Scalar::Int => "iimage", _ => "image" };
            let d = Diagnostic::error(format!("format `{}` holds {} texels, which `{}` does not read", format.name(), format.scalar().name(), k.name()), format_span)
                .with_secondary(ty_span, "the image type")
                .with_note(format!("help: declare it as `{want}...` or pick a format of {} texels", match k.scalar { Scalar::Uint => "uint", Scalar::Int => "int", _ => "float" }));
            self.diags.push(d);
        }
        let access = access_given.unwrap_or(Access::ReadWrite);
        if access == Access::ReadWrite && !format.allows_read_write() {
            self.read_write_image_used(format.name(), format_span);
        }
        GlobalKind::Image { format, access, unit }
    }

    /// A storage buffer: a struct of host-shareable members (std430), read
    /// by every stage, written only where `@readonly` is not given.
    fn storage_kind(&mut self, ty: &Ty, access: Option<(Access, Span)>, unit: u32, ty_span: Span) -> GlobalKind {
        if let Some((Access::Write, span)) = access {
            self.diags.push(Diagnostic::error("`@writeonly` applies only to storage images; a storage buffer is read-write, or `@readonly`", span));
        }
        match ty {
            // dasSpirv's `@ssbo x : array<T>`: the buffer is the array, of
            // plain values of one size.
            Ty::RuntimeArray(e) if !e.is_error() && (!e.is_value() || self.is_unsized(e)) => {
                self.diags.push(Diagnostic::error(format!("the elements of an `@ssbo` array must be plain values of one size, not `{}`", self.show(e)), ty_span));
            }
            Ty::Struct(_) | Ty::RuntimeArray(_) => {
                if let Some(msg) = self.storage_type_problem(ty) {
                    self.diags.push(Diagnostic::error(msg, ty_span));
                }
            }
            Ty::Error => {}
            _ => {
                let d = Diagnostic::error(format!("an `@ssbo` buffer holds a struct, not `{}`", self.show(ty)), ty_span)
                    .with_note("help: declare `struct Buf { data : uint[] }` and `var @ssbo buf : Buf`");
                self.diags.push(d);
            }
        }
        GlobalKind::Storage { access: if matches!(access, Some((Access::Read, _))) { Access::Read } else { Access::ReadWrite }, unit }
    }

    /// Why `ty` cannot be stored in a storage buffer (std430, shared with
    /// the host): booleans, `half`, enumerations, samplers and images.
    fn storage_type_problem(&self, ty: &Ty) -> Option<String> {
        match ty {
            Ty::Scalar(Scalar::Bool) | Ty::Vector(Scalar::Bool, _) => Some("`bool` cannot live in a storage buffer (it has no portable layout); use `int` or `uint`".into()),
            Ty::Scalar(Scalar::Half) | Ty::Vector(Scalar::Half, _) => Some(HALF_INTERFACE.replace("{what}", "a storage buffer")),
            Ty::Enum(_) => Some(format!("an enumeration (`{}`) cannot be in a storage buffer: its storage is not portable; use `int`", self.show(ty))),
            Ty::Array(e, _) | Ty::RuntimeArray(e) => self.storage_type_problem(e),
            Ty::Struct(id) => self.out.structs.get(*id)?.fields.iter().find_map(|f| self.storage_type_problem(&f.1).map(|m| format!("field `{}`: {m}", f.0))),
            _ => None,
        }
    }

    /// Records (range-checked) the `@set`/`@binding` written on the global
    /// about to be declared; only uniforms and samplers take them.
    fn written_bind(&mut self, kind: &GlobalKind, (set, binding): (Option<(i64, Span)>, Option<(i64, Span)>)) {
        let resource = matches!(kind, GlobalKind::Uniform { .. } | GlobalKind::Sampler { .. } | GlobalKind::Storage { .. } | GlobalKind::Image { .. });
        let mut checked = |q: Option<(i64, Span)>, what: &str, limit: i64| -> Option<(u32, Span)> {
            let (n, span) = q?;
            if !resource {
                self.diags.push(Diagnostic::error(format!("`@{what}` applies only to uniforms, samplers, storage buffers and images"), span));
                return None;
            }
            if !(0..limit).contains(&n) {
                self.diags.push(Diagnostic::error(format!("`@{what} = {n}` is out of range (0..{limit})"), span));
                return None;
            }
            Some((n as u32, span))
        };
        // Bounds of the checker's tables; wgpu's default of 4 bind groups
        // is checked per target (`emit::limits`); 1000 bindings per group.
        let set = checked(set, "set", crate::sema::limits::MAX_SETS);
        let binding = checked(binding, "binding", crate::sema::tree::MAX_BINDINGS as i64);
        if let Some((b, _)) = binding {
            self.out.written_bindings.insert(self.out.globals.len(), b);
        }
        if set.is_some() || binding.is_some() {
            self.bind_written.insert(self.out.globals.len(), (set, binding));
        }
    }

    /// Evaluates `value` at compile time, the constants it names first.
    /// `None` when one of those is wrong (reported already).
    /// `own`: the constant being defined, which `value` may not name.
    pub(super) fn fold(&mut self, value: &'a ast::Expr, own: Option<&str>, use_span: Span) -> Option<Result<(ConstValue, Ty), Diagnostic>> {
        let mut names = Vec::new();
        crate::sema::consts::collect_names(value, &mut names);
        let mut deps_ok = true;
        for n in names {
            if Some(n) != own && self.const_decls.contains_key(n) {
                deps_ok &= self.const_id(n, use_span).is_some();
            }
        }
        // A value built from a wrong constant is wrong too, but that was
        // reported already.
        deps_ok.then(|| eval_const(value, &ConstEnvAdapter { c: self }))
    }

    /// A module variable reached by a shader (`var angle = 0.0`): private
    /// to each shader invocation, starting from its initial value (a
    /// compile-time constant; zero without one).
    fn declare_module_var(&mut self, g: &'a ast::GlobalVar) {
        let name: &'a str = &g.name.name;
        let declared = g.ty.as_ref().map(|t| (self.resolve_type(t), t.span));
        let init = match &g.init {
            None => None,
            Some(e) => match self.fold(e, None, e.span) {
                Some(Ok(v)) => Some(v),
                Some(Err(d)) => {
                    self.diags.push(d.with_note(format!("the initial value of module variable `{name}` must be a compile-time constant: every shader invocation starts with it")));
                    return self.declare_failed(g);
                }
                None => return self.declare_failed(g),
            },
        };
        let ty = match (&declared, &init) {
            (Some((t, _)), Some((_, vt))) if !t.is_error() && t != vt => {
                let d = Diagnostic::error(format!("module variable `{name}` is declared `{}` but its value is `{}`", self.show(t), self.show(vt)), g.init.as_ref().map_or(g.name.span, |e| e.span));
                self.diags.push(d);
                return self.declare_failed(g);
            }
            (Some((t, _)), _) => t.clone(),
            (None, Some((_, vt))) => vt.clone(),
            (None, None) => return self.declare_failed(g),
        };
        if ty.is_sampler_like() || ty == Ty::Void {
            let span = declared.as_ref().map_or(g.name.span, |d| d.1);
            let d = Diagnostic::error(format!("module variable `{name}` cannot hold a `{}`", self.show(&ty)), span)
                .with_note("samplers are `@uniform` globals set by the host");
            self.diags.push(d);
            return self.declare_failed(g);
        }
        self.globals.insert(name, self.out.globals.len());
        self.out.globals.push(Global { name: name.to_string(), ty, kind: GlobalKind::Private { init: init.map(|v| v.0) }, span: g.name.span, bind: None });
    }

    /// The default value of uniform `name` of type `ty`: a compile-time
    /// constant of that type (reported otherwise).
    fn uniform_default(&mut self, name: &str, ty: &Ty, init: &'a ast::Expr) -> Option<ConstValue> {
        match self.fold(init, None, init.span)? {
            Ok((v, vt)) if vt == *ty || ty.is_error() => Some(v),
            Ok((_, vt)) => {
                let d = Diagnostic::error(format!("uniform `{name}` is `{}` but its default value is `{}`", self.show(ty), self.show(&vt)), init.span);
                self.diags.push(d);
                None
            }
            Err(d) => {
                self.diags.push(d.with_note(format!("the default value of uniform `{name}` must be a compile-time constant: the host sets it")));
                None
            }
        }
    }

    /// A specialization constant (`var @constant_id = N name : T = default`),
    /// as dasSpirv takes them: a 32-bit scalar with a constant default,
    /// ids unique and (WGSL's `@id`) below 65536.
    fn spec_constant(&mut self, g: &'a ast::GlobalVar, ty: &Ty, id: Option<(i64, Span)>, ty_span: Span) -> Option<GlobalKind> {
        let (id, id_span) = id?;
        if !matches!(ty, Ty::Scalar(Scalar::Bool | Scalar::Int | Scalar::Uint | Scalar::Float)) {
            if !ty.is_error() {
                let d = Diagnostic::error(format!("a specialization constant must be a `bool`, `int`, `uint` or `float`, not `{}`", self.show(ty)), ty_span);
                self.diags.push(d);
            }
            return None;
        }
        if !(0..65536).contains(&id) {
            let d = Diagnostic::error(format!("`@constant_id = {id}` is out of range (0..=65535)"), id_span).with_note("WGSL's `@id` of an `override` is below 65536");
            self.diags.push(d);
            return None;
        }
        let id = id as u32;
        let clash = self.out.globals.iter().find(|o| matches!(o.kind, GlobalKind::SpecConstant { id: other, .. } if other == id));
        if let Some(other) = clash {
            let d = Diagnostic::error(format!("`@constant_id = {id}` is already the id of `{}`", other.name), id_span).with_secondary(other.span, "declared here");
            self.diags.push(d);
            return None;
        }
        let Some(init) = &g.init else {
            let d = Diagnostic::error(format!("specialization constant `{}` needs a default value", g.name.name), g.name.span)
                .with_note(format!("help: `var @constant_id = {id} {} : {} = ...`", g.name.name, self.show(ty)));
            self.diags.push(d);
            return None;
        };
        let default = match self.fold(init, None, init.span)? {
            Ok((v, vt)) if vt == *ty => v,
            // An `int` literal default of a `uint` constant (`= 64`).
            Ok((ConstValue::Int(v), Ty::Scalar(Scalar::Int))) if *ty == UINT && v >= 0 => ConstValue::Uint(v as u64),
            Ok((_, vt)) => {
                let d = Diagnostic::error(format!("specialization constant `{}` is `{}` but its default value is `{}`", g.name.name, self.show(ty), self.show(&vt)), init.span);
                self.diags.push(d);
                return None;
            }
            Err(d) => {
                self.diags.push(d.with_note("the default value of a specialization constant must be a compile-time constant"));
                return None;
            }
        };
        Some(GlobalKind::SpecConstant { id, default })
    }

    /// Declares `g` with no type after an error: its uses report nothing more.
    fn declare_failed(&mut self, g: &'a ast::GlobalVar) {
        self.globals.insert(&g.name.name, self.out.globals.len());
        self.out.globals.push(Global { name: g.name.name.as_str().to_string(), ty: Ty::Error, kind: GlobalKind::Private { init: None }, span: g.name.span, bind: None });
    }

    /// Why a type cannot be a uniform, if it cannot. A struct is a uniform
    /// block of its own, laid out alike on every target; any other type
    /// is a loose uniform, a member of its group's uniform buffer, where
    /// `bool`s, short-element arrays and two-row matrices are stored
    /// padded (see `lower::packed`), so only the structs in it must share
    /// a layout.
    pub(super) fn uniform_type_problem(&self, ty: &Ty) -> Option<String> {
        let layout = match ty {
            // Arrays of what the buffer pads (scalars, vectors, matrices);
            // an array of structs keeps the struct's layout.
            Ty::Array(elem, _) if matches!(**elem, Ty::Scalar(_) | Ty::Vector(..) | Ty::Matrix(..)) => return self.uniform_type_problem(elem),
            Ty::Scalar(Scalar::Bool) | Ty::Vector(Scalar::Bool, _) | Ty::Matrix(..) => return None,
            _ => self.uniform_layout(ty, ""),
        };
        match layout {
            Err(e) => Some(e),
            Ok(l) if l.size.max(l.std_size) > MAX_UNIFORM_BLOCK_SIZE => Some(format!(
                "a uniform of `{}` takes {}; a uniform block holds at most {MAX_UNIFORM_BLOCK_SIZE} bytes (WebGPU's default binding size limit; GLSL 330 and ES 3.00 guarantee only 16384)",
                self.show(ty),
                match l.size.max(l.std_size) {
                    u32::MAX => "more than 4 GiB".to_string(),
                    n => format!("{n} bytes"),
                }
            )),
            Ok(_) => None,
        }
    }

    /// The layout of `ty` in a uniform block, checked to be the same under
    /// GLSL's std140 rules and WGSL's uniform rules (naga writes WGSL
    /// structs without `@align`/`@size`, so the natural WGSL layout is the
    /// one every target must share).
    pub(super) fn uniform_layout(&self, ty: &Ty, path: &str) -> Result<UniformLayout, String> {
        // Saturating: sizes of huge types stop at u32::MAX, which the size
        // limit then refuses (a 65536-element array of 1 MiB structs
        // overflowed a u32).
        let round = |a: u32, x: u32| x.div_ceil(a).saturating_mul(a);
        match ty {
            Ty::Scalar(Scalar::Bool) | Ty::Vector(Scalar::Bool, _) => {
                Err("`bool` cannot live in a uniform block (it has no portable layout); use `int` or `uint`".into())
            }
            Ty::Scalar(Scalar::Half) | Ty::Vector(Scalar::Half, _) => Err(HALF_INTERFACE.replace("{what}", "a uniform block")),
            Ty::Scalar(_) => Ok(UniformLayout { size: 4, align: 4, std_size: 4, std_align: 4 }),
            Ty::Vector(_, n) => {
                let align = if *n == 2 { 8 } else { 16 };
                Ok(UniformLayout { size: 4 * *n as u32, align, std_size: 4 * *n as u32, std_align: align })
            }
            Ty::Matrix(_, 2) => Err(format!(
                "`{}` has different layouts in GLSL std140 and WGSL uniform blocks; use a float4 per column or a wider matrix",
                self.show(ty)
            )),
            Ty::Matrix(c, _) => Ok(UniformLayout { size: 16 * *c as u32, align: 16, std_size: 16 * *c as u32, std_align: 16 }),
            Ty::Array(elem, n) => {
                if matches!(**elem, Ty::Scalar(_) | Ty::Vector(_, 2) | Ty::Vector(_, 3)) {
                    return Err(format!(
                        "arrays of `{}` in a uniform block have a 16-byte element stride in GLSL std140, which WGSL cannot express; use float4 (or int4, uint4) elements and pack several values into each",
                        self.show(elem)
                    ));
                }
                let e = self.uniform_layout(elem, &format!("{path}[]"))?;
                let stride = round(e.align, e.size);
                let std_stride = round(16, e.std_size);
                if stride % 16 != 0 || stride != std_stride {
                    return Err(format!(
                        "elements of `{}` are {stride} bytes apart in WGSL but {std_stride} in GLSL std140; pad `{}` to a multiple of 16 bytes (e.g. with a float4 field)",
                        self.show(ty),
                        self.show(elem)
                    ));
                }
                Ok(UniformLayout { size: stride.saturating_mul(*n), align: e.align, std_size: std_stride.saturating_mul(*n), std_align: 16 })
            }
            Ty::Struct(id) => {
                let def = &self.out.structs[*id];
                let (mut end, mut std_end, mut align, mut std_align) = (0u32, 0u32, 1u32, 16u32);
                let mut prev_struct: Option<(String, u32)> = None;
                for (fname, fty, _) in &def.fields {
                    let fpath = if path.is_empty() { format!("{}.{fname}", def.name) } else { format!("{path}.{fname}") };
                    let m = self.uniform_layout(fty, &fpath).map_err(|e| if path.is_empty() && !e.contains('`') { format!("`{fpath}`: {e}") } else { e })?;
                    // WGSL uniform rule: struct and array members start at multiples of 16.
                    let member_align = if matches!(fty, Ty::Struct(_) | Ty::Array(..)) { round(16, m.align) } else { m.align };
                    let off = round(m.align, end);
                    let std_off = round(m.std_align, std_end);
                    if off != std_off || off % member_align != 0 {
                        return Err(format!(
                            "field `{fname}` of `{}` would be at offset {off} in WGSL but {std_off} in GLSL std140; reorder or pad the fields so that every struct or array field starts at a multiple of 16 and every struct used in a uniform is a multiple of 16 bytes",
                            def.name
                        ));
                    }
                    if let Some((pname, min)) = prev_struct.take() {
                        if off < min {
                            return Err(format!(
                                "field `{fname}` of `{}` follows struct field `{pname}` too closely for a WGSL uniform block; pad `{pname}`'s type to a multiple of 16 bytes",
                                def.name
                            ));
                        }
                    }
                    if matches!(fty, Ty::Struct(_)) {
                        prev_struct = Some((fname.clone(), off.saturating_add(round(16, m.size))));
                    }
                    end = off.saturating_add(m.size);
                    std_end = std_off.saturating_add(m.std_size);
                    align = align.max(m.align);
                    std_align = std_align.max(round(16, m.std_align));
                }
                Ok(UniformLayout { size: round(align, end), align, std_size: round(std_align, std_end), std_align })
            }
            Ty::Enum(_) => Err(format!("an enumeration (`{}`) cannot be in a uniform block: its storage is not portable; use `int` and compare with `int(E.value)`", self.show(ty))),
            // A type already reported as wrong: nothing more to say.
            Ty::Error => Ok(UniformLayout { size: 4, align: 4, std_size: 4, std_align: 4 }),
            _ => Err(format!("`{}` cannot be in a uniform block", self.show(ty))),
        }
    }

    pub(super) fn resolve_type(&mut self, t: &'a ast::TypeExpr) -> Ty {
        match &t.kind {
            ast::TypeExprKind::Named(id) => {
                if let Some(ty) = Ty::from_builtin_name(&id.name) {
                    if ty.has_half(&[]) {
                        self.half_used(id.span);
                    }
                    return ty;
                }
                if let Some((msg, help)) = crate::sema::types::unsupported_type(&id.name) {
                    self.diags.push(Diagnostic::error(msg, id.span).with_label("no target has this type").with_note(format!("help: {help}")));
                    return Ty::Error;
                }
                if let Some(&sid) = self.structs.get(id.name.as_str()) {
                    return Ty::Struct(sid);
                }
                if let Some(&eid) = self.enums.get(id.name.as_str()) {
                    return Ty::Enum(eid);
                }
                if let Some(d) = self.unsupported_daslang_builtin(&id.name, id.span) {
                    self.diags.push(d);
                    return Ty::Error;
                }
                let candidates: Vec<&str> = self.structs.keys().chain(self.enums.keys()).copied().chain(TYPE_NAMES.iter().copied()).collect();
                let mut d = Diagnostic::error(format!("unknown type `{}`", id.name), id.span).with_label("not a type");
                if let Some(s) = suggest(&id.name, candidates.iter().copied()) {
                    d = d.with_note(format!("help: did you mean `{s}`?"));
                }
                let d = self.with_missing_modules(d);
                self.diags.push(d);
                Ty::Error
            }
            ast::TypeExprKind::RuntimeArray(elem) => Ty::RuntimeArray(Box::new(self.resolve_type(elem))),
            ast::TypeExprKind::Array(elem, len) => {
                let elem_ty = self.resolve_type(elem);
                let mut names = Vec::new();
                crate::sema::consts::collect_names(len, &mut names);
                for n in names {
                    if self.const_decls.contains_key(n) {
                        self.const_id(n, len.span);
                    }
                }
                let n = match eval_const(len, &ConstEnvAdapter { c: self }).map(|(v, _)| v) {
                    Ok(ConstValue::Int(n)) if n > 0 && (n as u64) <= MAX_ARRAY_LEN => n as u32,
                    Ok(ConstValue::Uint(n)) if n > 0 && n <= MAX_ARRAY_LEN => n as u32,
                    Ok(_) => {
                        let d = Diagnostic::error(format!("array length must be a positive integer constant of at most {MAX_ARRAY_LEN}"), len.span);
                        self.diags.push(d);
                        return Ty::Error;
                    }
                    Err(d) => {
                        self.diags.push(d);
                        return Ty::Error;
                    }
                };
                if matches!(elem_ty, Ty::Array(..)) && elem_ty.is_sampler_like() {
                    self.diags.push(Diagnostic::error("arrays of arrays of samplers are not supported; use one array of samplers", t.span));
                    return Ty::Error;
                }
                if elem_ty.is_error() {
                    return Ty::Error;
                }
                if matches!(elem_ty, Ty::Array(..)) {
                    self.diags.push(array_of_arrays(t.span));
                    return Ty::Error;
                }
                Ty::Array(Box::new(elem_ty), n)
            }
        }
    }

    // ---------------------------------------------------------------- constants

    /// Looks up (checking on first use) a top-level constant.
    pub(super) fn const_id(&mut self, name: &str, use_span: Span) -> Option<ConstId> {
        if let Some(&id) = self.consts.get(name) {
            return Some(id);
        }
        if self.failed_consts.contains(name) {
            return None;
        }
        let decl: &'a ast::ConstDecl = self.const_decls.get(name)?;
        // Keys borrow the declaration's own name.
        let name: &'a str = &decl.name.name;
        if self.const_in_progress.contains(&name) {
            let d = Diagnostic::error(format!("constant `{name}` depends on itself"), use_span).with_secondary(decl.name.span, "defined here");
            self.diags.push(d);
            return None;
        }
        if self.const_in_progress.len() >= MAX_CONST_CHAIN {
            let d = Diagnostic::error(format!("constants are defined in terms of each other too deeply (limit {MAX_CONST_CHAIN})"), decl.name.span)
                .with_label("the limit is reached at this constant");
            self.diags.push(d);
            self.failed_consts.insert(name);
            return None;
        }
        self.const_in_progress.push(name);
        let value = self.fold(&decl.value, Some(name), use_span);
        self.const_in_progress.pop();
        let (value, ty) = match value {
            Some(Ok(v)) => v,
            Some(Err(d)) => {
                self.diags.push(d);
                self.failed_consts.insert(name);
                return None;
            }
            None => {
                self.failed_consts.insert(name);
                return None;
            }
        };
        if matches!(&ty, Ty::Array(elem, _) if matches!(**elem, Ty::Array(..))) {
            self.diags.push(array_of_arrays(decl.value.span));
            self.failed_consts.insert(name);
            return None;
        }
        if let Some(t) = &decl.ty {
            let declared = self.resolve_type(t);
            if !declared.is_error() && declared != ty {
                let d = Diagnostic::error(
                    format!("constant `{name}` is declared `{}` but its value is `{}`", self.show(&declared), self.show(&ty)),
                    decl.value.span,
                );
                self.diags.push(d);
                self.failed_consts.insert(name);
                return None;
            }
        }
        let id = self.out.consts.len();
        self.out.consts.push(Const { name: name.to_string(), ty, value, span: decl.name.span });
        self.consts.insert(name, id);
        Some(id)
    }

}

/// An array whose elements are arrays: naga writes them only for GLSL 430
/// and GLSL ES 3.10 and later (`ARRAY_OF_ARRAYS`), not for the 330 and
/// ES 3.00 targets.
pub(super) fn array_of_arrays(span: Span) -> Diagnostic {
    Diagnostic::error("arrays of arrays are not supported", span)
        .with_label("an array of arrays")
        .with_note("GLSL 330 and GLSL ES 3.00 have no arrays of arrays")
        .with_note("help: use one array of N * M elements indexed by `i * M + j`, or an array of structs holding an array")
}

/// Lets the constant evaluator look up other constants through the checker.
pub(super) struct ConstEnvAdapter<'c, 'a, 'd> {
    pub(super) c: &'c Checker<'a, 'd>,
}

impl ConstEnv for ConstEnvAdapter<'_, '_, '_> {
    fn lookup(&self, name: &str) -> Option<(ConstValue, Ty)> {
        let Some(&id) = self.c.consts.get(name) else {
            // A program's own constant hides a builtin one (`PI`).
            return if self.c.const_decls.contains_key(name) { None } else { builtins::constant(name) };
        };
        let k = &self.c.out.consts[id];
        Some((k.value.clone(), k.ty.clone()))
    }

    fn struct_type(&self, name: &str) -> Option<(Ty, Vec<Ty>)> {
        let &sid = self.c.structs.get(name)?;
        Some((Ty::Struct(sid), self.c.out.structs[sid].fields.iter().map(|f| f.1.clone()).collect()))
    }

    fn enum_value(&self, ty: &str, member: &str) -> Option<(ConstValue, Ty)> {
        self.c.enum_const(ty, member)
    }

    fn why_not_const(&self, name: &str) -> Option<String> {
        let spec = self.c.ast.items.iter().any(|i| matches!(i, ast::Item::Global(g) if g.name.name == name && g.qualifiers.iter().any(|q| matches!(q.kind, ast::QualifierKind::ConstantId(_)))));
        spec.then(|| format!("`{name}` is a specialization constant (`@constant_id`), whose value the host sets when it creates the pipeline: WGSL takes an `override` in no array size here and in no `const`, and GLSL holds only its default, so it is refused on every target (use it in the shader's code, or a `let` constant where a constant is needed)"))
    }
}

/// What `half` cannot be, with what to do instead.
const HALF_INTERFACE: &str = "`half` cannot be in {what}: host formats and the GPU interface of the WGSL and SPIR-V targets are 32-bit here; use `float` and convert with `half(x)` inside the shader";

fn half_interface_error(what: &str, span: Span) -> Diagnostic {
    Diagnostic::error(HALF_INTERFACE.replace("{what}", what), span)
}
