//! Front-end tests: item selection on real files, the preprocessor, parser
//! errors and recovery, limits.

use std::path::{Path, PathBuf};

use umbrac::diag::{Diagnostic, Diagnostics};
use umbrac::source::SourceMap;
use umbrac::syntax::ast::{self, ExprKind, Item, QualifierKind, StmtKind};
use umbrac::syntax::{self, ParseOptions};

struct Parsed {
    map: SourceMap,
    program: ast::Program,
    diags: Vec<Diagnostic>,
}

impl Parsed {
    fn names(&self) -> Vec<String> {
        self.program
            .items
            .iter()
            .map(|i| match i {
                Item::Global(g) => g.name.name.to_string(),
                Item::Const(c) => c.name.name.to_string(),
                Item::Function(f) => f.name.name.to_string(),
                Item::Struct(s) => s.name.name.to_string(),
                Item::Enum(e) => e.name.name.to_string(),
            })
            .collect()
    }

    fn errors(&self) -> Vec<&Diagnostic> {
        self.diags.iter().filter(|d| d.is_error()).collect()
    }

    /// `file:line:col: message` of every diagnostic (file name's last component).
    fn locs(&self) -> Vec<String> {
        self.diags.iter().map(|d| self.loc(d)).collect()
    }

    fn loc(&self, d: &Diagnostic) -> String {
        match d.span.and_then(|s| self.map.line_col(s)) {
            Some((file, line, col)) => {
                let name = &self.map.file(file).name;
                let short = Path::new(name).file_name().map(|s| s.to_string_lossy().into_owned()).unwrap_or(name.clone());
                format!("{short}:{line}:{col}: {}", d.message)
            }
            None => format!("?: {}", d.message),
        }
    }

    fn rendered(&self) -> String {
        self.diags.iter().map(|d| d.render(&self.map)).collect()
    }

    fn function(&self, name: &str) -> &ast::FunctionDecl {
        self.program
            .items
            .iter()
            .find_map(|i| match i {
                Item::Function(f) if f.name.name == name => Some(f),
                _ => None,
            })
            .unwrap_or_else(|| panic!("no function {name}"))
    }
}

fn parse_path(path: &Path, opts: &ParseOptions) -> Parsed {
    let text = syntax::read_source(path).expect("readable");
    let mut map = SourceMap::new();
    let root = map.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
    let mut diags = Diagnostics::new();
    let program = syntax::parse(&mut map, root, opts, &mut diags);
    Parsed { map, program, diags: diags.into_vec() }
}

fn parse_str(text: &str) -> Parsed {
    parse_str_opts(text, &ParseOptions::default())
}

fn parse_str_opts(text: &str, opts: &ParseOptions) -> Parsed {
    let mut map = SourceMap::new();
    let root = map.add("test.das", None, text.to_string(), None);
    let mut diags = Diagnostics::new();
    let program = syntax::parse(&mut map, root, opts, &mut diags);
    Parsed { map, program, diags: diags.into_vec() }
}

/// A shader program around a fragment shader body.
fn fs(body: &str) -> String {
    format!("var @out col : float4\n[fragment_program]\ndef main_fs {{\n{body}\n}}\n")
}

fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

// ---------------------------------------------------------------- real files

#[test]
fn tutorial_selects_exactly_the_shader_part() {
    let path = manifest().join("../shared/reference/08_shadow.das");
    if !path.exists() {
        eprintln!("skipped: {} is missing", path.display());
        return;
    }
    let p = parse_path(&path, &ParseOptions::default());
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let names = p.names();
    let globals: Vec<&str> = p
        .program
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Global(g) => Some(g.name.name.as_str()),
            _ => None,
        })
        .collect();
    // Every `var` with a shader qualifier: 14 declarations in the file.
    assert_eq!(globals.len(), 14, "{globals:?}");
    let expected = [
        "u_light_vp",
        "u_model",
        "u_view",
        "u_proj",
        "u_light_dir",
        "u_cam_pos",
        "u_is_floor",
        "shadow_map",
        "a_pos",
        "a_normal",
        "v_world_pos",
        "v_world_normal",
        "v_light_space",
        "f_FragColor",
        "shadow_vs",
        "shadow_fs",
        "main_vs",
        "SHADOW_DIM_F",
        "pcf_shadow",
        "main_fs",
    ];
    assert_eq!(names, expected);
    for host in ["identity_m4", "cube_model", "SHADOW_DIM", "SceneVertex", "cube_verts"] {
        assert!(!names.iter().any(|n| n == host), "{host} selected");
    }
    // Spot checks of the parse.
    let pcf = p.function("pcf_shadow");
    assert_eq!(pcf.params.len(), 2);
    assert!(pcf.ret.is_some());
    assert!(matches!(pcf.body.stmts[2].kind, StmtKind::For { .. }));
    let a_pos = p.program.items.iter().find_map(|i| match i {
        Item::Global(g) if g.name.name == "a_pos" => Some(g),
        _ => None,
    });
    let kinds: Vec<_> = a_pos.unwrap().qualifiers.iter().map(|q| q.kind.clone()).collect();
    assert_eq!(kinds, [QualifierKind::In, QualifierKind::Location(Some(0))]);
    let main_fs = p.function("main_fs");
    assert!(main_fs.annotations.iter().any(|a| a.name.name == "fragment_program"));
}

#[test]
fn project_shadow_program_parses() {
    let p = parse_path(&manifest().join("shaders/shadow.das"), &ParseOptions::default());
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let names = p.names();
    for n in ["shadow_vs", "shadow_fs", "main_vs", "main_fs", "sun_visibility", "floor_albedo", "SHADOW_MAP_SIZE", "PCF_RADIUS"] {
        assert!(names.iter().any(|x| x == n), "{n} missing from {names:?}");
    }
    let sm = p.program.items.iter().find_map(|i| match i {
        Item::Global(g) if g.name.name == "shadow_map" => Some(g),
        _ => None,
    });
    assert!(sm.unwrap().qualifiers.iter().any(|q| q.kind == QualifierKind::Stage(Some(0))));
}

/// A visibility word before a shader qualifier or a block
/// (`var private @uniform`, `let private { ... }`) once made the item
/// host code: a shader global dropped without a word, its uses "unknown".
#[test]
fn visibility_words_keep_shader_globals_and_blocks() {
    let src = "var private @uniform u_unused : float\nvar public @in a_pos : float2\nvar shared @uniform u_k : float\nlet private {\n    A = 0.5\n}\nvar shared = 2.0\n";
    let p = parse_str(&format!("{src}{}", fs("    col = float4(a_pos * A * u_k * shared, 0.0, 1.0)")));
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let names = p.names();
    for n in ["u_unused", "a_pos", "u_k", "A", "shared", "col", "main_fs"] {
        assert!(names.iter().any(|x| x == n), "`{n}` missing from {names:?}");
    }
}

/// A body given by indentation alone (daslang's older syntax, as in
/// daslang's own `sdfi.das` and toy path tracer) is named, with the way
/// daslang converts such a file.
#[test]
fn indented_bodies_name_the_older_syntax_and_its_converter() {
    let p = parse_str("var @out c : float4\n[fragment_program]\ndef main_fs\n    c = float4(1.0)\n");
    let d = p.errors()[0];
    assert_eq!(d.message, "expected '{', found the end of the line");
    assert!(d.notes.iter().any(|n| n.contains("older syntax") && n.contains("options gen2")), "{:?}", d.notes);
    assert!(d.notes.iter().any(|n| n.contains("gen1-to-gen2")), "{:?}", d.notes);
}

#[test]
fn entry_filter_and_unknown_entry() {
    let src = "var @out c : float4\n[vertex_program]\ndef a_vs {\n}\n[fragment_program(name = \"frag\")]\ndef b_fs {\nc = f()\n}\ndef f : float4 {\nreturn float4(1.0)\n}\n";
    let opts = ParseOptions { entries: vec!["a_vs".into()], ..Default::default() };
    let p = parse_str_opts(src, &opts);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert_eq!(p.names(), ["c", "a_vs"]);
    let opts = ParseOptions { entries: vec!["frag".into()], ..Default::default() };
    let p = parse_str_opts(src, &opts);
    assert_eq!(p.names(), ["c", "b_fs", "f"]);
    let ann = &p.function("b_fs").annotations[0];
    assert!(matches!(&ann.args[0].value, Some(ast::Expr { kind: ExprKind::Str(s), .. }) if s == "frag"));
    let opts = ParseOptions { entries: vec!["a_v".into()], ..Default::default() };
    let p = parse_str_opts(src, &opts);
    assert_eq!(p.errors().len(), 1);
    let d = p.errors()[0];
    assert_eq!(d.message, "unknown entry point `a_v`");
    assert!(d.notes.iter().any(|n| n.contains("a_vs, b_fs")), "{:?}", d.notes);
}

#[test]
fn no_entry_points_is_an_error() {
    let p = parse_str("var @uniform x : float\ndef f {\n}\n");
    assert_eq!(p.errors().len(), 1);
    assert!(p.errors()[0].message.starts_with("no entry points"));
}

// ---------------------------------------------------------------- host code

#[test]
fn errors_in_host_code_are_not_reported() {
    let src = "options gen2\nrequire daslib/glfw_boost\n\
        def host {\nlet x = 1 +* § \"unterminated\nvar p : int? = null ?? q?.r\n}\n\
        struct Host {\nx : array<table<string; int>>\n}\n\
        var window : GLFWwindow?\nlet table = { \"a\" => 1 }\n\
        [export]\ndef main {\nwhile (update()) {\n}\n}\n\
        enum Color {\nRed\nGreen\n}\n\
        var @out col : float4\n[fragment_program]\ndef main_fs {\ncol = float4(1.0)\n}\n";
    let p = parse_str(src);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert_eq!(p.names(), ["col", "main_fs"]);
}

#[test]
fn lexing_error_in_a_shader_is_reported() {
    let p = parse_str(&fs("let x = 1.0 § 2.0"));
    assert_eq!(p.locs(), ["test.das:4:13: unexpected character `§`"]);
}

#[test]
fn crlf_bom_tabs_and_nul() {
    let src = "\u{feff}var @out col : float4\r\n[fragment_program]\r\ndef main_fs {\r\n\tcol = float4(1.0)\r\n}\r\n// \0 in a comment\r\n";
    let p = parse_str(src);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let p = parse_str(&fs("\tlet a = 1\0"));
    assert_eq!(p.locs(), ["test.das:4:11: unexpected character `\\0`"]);
}

// ---------------------------------------------------------------- parser

/// daslang's gen2 one-line bodies: one expression, assignment, `return`,
/// `break` or `continue` on the line of `if (...)`, `elif (...)`, `else`,
/// `while (...)` and `for (...)`; an `else` on the next line belongs to
/// the one-line `if`.
#[test]
fn one_line_bodies() {
    let body = "if (a) return\nif (b) x = 1\nelif (c) x += 2\nelse x = 3\nwhile (x < 4) x++\nfor (i in range(4)) s += i\nif (d) f(x) else return";
    let p = parse_str(&fs(body));
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let f = p.function("main_fs");
    assert_eq!(f.body.stmts.len(), 5);
    let StmtKind::If { then, elifs, otherwise: Some(otherwise), .. } = &f.body.stmts[1].kind else { panic!("{:?}", f.body.stmts[1].kind) };
    assert!(matches!(then.stmts[..], [ast::Stmt { kind: StmtKind::Assign { .. }, .. }]));
    assert_eq!(elifs.len(), 1);
    assert!(matches!(otherwise.stmts[..], [ast::Stmt { kind: StmtKind::Assign { .. }, .. }]));
    assert!(matches!(&f.body.stmts[2].kind, StmtKind::While { body, .. } if body.stmts.len() == 1));
    assert!(matches!(&f.body.stmts[3].kind, StmtKind::For { body, .. } if body.stmts.len() == 1));
    // A declaration or a compound statement needs braces; so does a body on the next line.
    assert_eq!(parse_str(&fs("if (a) let y = 1")).locs(), ["test.das:4:8: keyword 'let' cannot stand alone as a one-line body"]);
    assert_eq!(parse_str(&fs("while (a) if (b) break")).locs(), ["test.das:4:11: keyword 'if' cannot stand alone as a one-line body"]);
    assert!(parse_str(&fs("if (a)\n    return")).locs()[0].starts_with("test.das:5:5: expected '{'"));
}

/// Calls with daslang's block argument (`f() $ { }`, `f() <| $ { }`,
/// `f($ { })`): parsed for every name; the checker takes only `unroll`.
#[test]
fn calls_with_a_block() {
    let body = "unroll() $ {\nfor (i in range(4)) {\ns += i\n}\n}\nunroll() <| $ {\nfor (i in range(2)) {\n}\n}\nunroll($ {\nlet k = 1\n})\nother(1, 2) $ {\n}";
    let p = parse_str(&fs(body));
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let f = p.function("main_fs");
    let calls: Vec<(&str, usize, usize)> = f
        .body
        .stmts
        .iter()
        .map(|s| match &s.kind {
            StmtKind::CallBlock { callee, args, body } => (callee.name.as_str(), args.len(), body.stmts.len()),
            k => panic!("{k:?}"),
        })
        .collect();
    assert_eq!(calls, [("unroll", 0, 1), ("unroll", 0, 1), ("unroll", 0, 1), ("other", 2, 0)]);
    assert_eq!(parse_str(&fs("x $ {\n}")).locs(), ["test.das:4:3: a block argument follows a call: `f() $ { ... }`"]);
    // `unsafe { ... }` is its statements.
    let p = parse_str(&fs("unsafe {\nlet b = reinterpret<uint>(1.0)\n}"));
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert!(matches!(&p.function("main_fs").body.stmts[0].kind, StmtKind::Block(b) if b.stmts.len() == 1));
}

#[test]
fn statements_and_expressions() {
    let body = "var a, b : float3\nlet c : float = 1.0; let d = 2\nvar e = fixed_array<float>(1.0, 2.0)\nvar f = [1, 2,\n3]\n\
        a += b * c\nif (c > 0.0) {\nreturn\n} elif d == 2 {\nd++\n}\nelse {\n--d\n}\n\
        while (c < 1.0 &&\n d != 3) {\nbreak\n}\nfor (i in range(0, 4)) {\ncontinue\n}\n\
        {\nlet g = c > 1.0 ? a.xyz : b[0] << 1u\n}\ncol = float4(0x1Fu, .5, 1e-3, 2.5e+2f)\ndiscard()";
    let p = parse_str(&fs(body));
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let f = p.function("main_fs");
    let kinds: Vec<&str> = f
        .body
        .stmts
        .iter()
        .map(|s| match &s.kind {
            StmtKind::Local { .. } => "local",
            StmtKind::Assign { .. } => "assign",
            StmtKind::Expr(_) => "expr",
            StmtKind::If { .. } => "if",
            StmtKind::While { .. } => "while",
            StmtKind::For { .. } => "for",
            StmtKind::Return(_) => "return",
            StmtKind::Break => "break",
            StmtKind::Continue => "continue",
            StmtKind::Block(_) => "block",
            StmtKind::With { .. } => "with",
            StmtKind::CallBlock { .. } => "call-block",
        })
        .collect();
    assert_eq!(kinds, ["local", "local", "local", "local", "local", "assign", "if", "while", "for", "block", "assign", "expr"]);
    let StmtKind::If { elifs, otherwise, .. } = &f.body.stmts[6].kind else { panic!() };
    assert_eq!(elifs.len(), 1);
    assert!(otherwise.is_some());
    // Precedence: `a + b * c` is `a + (b * c)`; `x || y && z` is `x || (y && z)`.
    let p = parse_str(&fs("let x = 1 + 2 * 3\nlet y = a || b && c ^^ d"));
    let f = p.function("main_fs");
    let StmtKind::Local { init: Some(e), .. } = &f.body.stmts[0].kind else { panic!() };
    assert!(matches!(&e.kind, ExprKind::Binary(ast::BinaryOp::Add, lr) if matches!(lr.1.kind, ExprKind::Binary(ast::BinaryOp::Mul, _))));
    let StmtKind::Local { init: Some(e), .. } = &f.body.stmts[1].kind else { panic!() };
    assert!(matches!(&e.kind, ExprKind::Binary(ast::BinaryOp::Or, lr) if matches!(lr.1.kind, ExprKind::Binary(ast::BinaryOp::Xor, _))));
}

#[test]
fn parser_error_messages_and_locations() {
    let cases: &[(&str, &str)] = &[
        ("let a = foo(1, 2", "test.das:5:1: expected ',' or ')', found '}'"),
        ("let a = (1 + 2\nlet b = 1", "test.das:5:1: expected ')', found keyword 'let'"),
        ("let a = 1 +", "test.das:5:1: expected an expression, found '}'"),
        ("let a = 1\n* 2", "test.das:5:1: unexpected '*'"),
        ("let x = 1.0d", "test.das:4:9: double-precision literal `1.0d` is not supported in shader code"),
        ("if (true)\n    return", "test.das:5:5: expected '{', found keyword 'return'"),
        ("let a = 1 2", "test.das:4:11: expected newline or ';' after the statement, found number '2'"),
        ("let a = b)", "test.das:4:10: expected newline or ';' after the statement, found ')'"),
        ("let a = [1, 2", "test.das:5:1: expected ',' or ']', found '}'"),
        ("let = 1", "test.das:4:5: expected a variable name, found '='"),
        ("x := 1", "test.das:4:3: ':=' is not supported in shader code"),
        ("for (i range(3)) {\n}", "test.das:4:8: expected 'in', found identifier 'range'"),
        ("let s = \"str\"", "test.das:4:9: string literals are not supported in shader code"),
        ("else {\n}", "test.das:4:1: `else` without a preceding `if`"),
    ];
    for (body, want) in cases {
        let p = parse_str(&fs(body));
        let locs = p.locs();
        assert!(locs.first().map(String::as_str) == Some(*want), "for {body:?}: {locs:?}");
    }
}

#[test]
fn recovery_reports_each_independent_error_once() {
    let body = "let a = 1 +\nlet b = (2\nlet ok = 3\nfoo(1 2,\n 3, 4)\nlet c = ]\nif (a) {\nlet d = * 2\n}\nlet fine = 1";
    let p = parse_str(&fs(body));
    assert_eq!(
        p.locs(),
        [
            "test.das:5:1: expected an expression, found keyword 'let'",
            "test.das:6:1: expected ')', found keyword 'let'",
            "test.das:7:7: expected ',' or ')', found number '2'",
            "test.das:9:9: unexpected ']'",
            "test.das:11:9: unexpected '*'",
        ]
    );
    // Errors in separate items are all reported too.
    let src = "var @uniform u : float[\nvar @out c : float4\n[fragment_program]\ndef fs {\nc = (1\n}\n[vertex_program]\ndef vs(a : ) {\nlet x = = 1\n}\n";
    let p = parse_str(src);
    assert_eq!(p.errors().len(), 4, "{:?}", p.locs());
}

#[test]
fn global_declarations() {
    let src = "var @uniform @stage = 2 tex : sampler2D\nvar @out @location = 1 a, b : float4\nvar @in @location v : float3[4]\n\
        var @uniform @foo = 3 u : float\n[vertex_program]\ndef vs {\n}\n";
    let p = parse_str(src);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert_eq!(p.names(), ["tex", "a", "b", "v", "u", "vs"]);
    let Item::Global(v) = &p.program.items[3] else { panic!() };
    assert_eq!(v.qualifiers[1].kind, QualifierKind::Location(None));
    assert!(matches!(v.ty.as_ref().unwrap().kind, ast::TypeExprKind::Array(..)));
    let Item::Global(u) = &p.program.items[4] else { panic!() };
    assert_eq!(u.qualifiers[1].kind, QualifierKind::Other("foo".into()));
    let p = parse_str("var @uniform x = 1.0\n[vertex_program]\ndef vs {\n}\n");
    assert_eq!(p.locs(), ["test.das:1:16: expected ':' and a type for shader global `x`, found '='"]);
}

#[test]
fn reachability_pulls_structs_constants_and_helpers() {
    let src = "struct Light {\npos : float3\ncolor, dir : float3\n}\nstruct Unused {\nx : float\n}\n\
        let N = 4\nlet UNUSED = 5\nvar @uniform lights : Light[N]\n\
        def helper(l : Light) : float3 {\nreturn l.color\n}\ndef pos : float {\nreturn 1.0\n}\n\
        [fragment_program]\ndef fs {\nlet pos = helper(lights[0])\n}\n";
    let p = parse_str(src);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    // `pos` the function is not pulled in: `pos` in fs is a local and `.pos` a field.
    assert_eq!(p.names(), ["Light", "N", "lights", "helper", "fs"]);
    let Item::Struct(s) = &p.program.items[0] else { panic!() };
    assert_eq!(s.fields.len(), 3);
}

// ---------------------------------------------------------------- limits

fn nested_parens(n: usize) -> String {
    fs(&format!("let x = {}1{}", "(".repeat(n), ")".repeat(n)))
}

#[test]
fn deep_nesting_is_a_diagnostic_not_a_crash() {
    // Runs on the test harness's 2 MiB thread.
    for src in [
        nested_parens(100_000),
        fs(&format!("let x = {}", "(".repeat(100_000))),
        fs(&format!("let x = {}1", "-".repeat(100_000))),
        fs(&format!("{}{}", "{\n".repeat(100_000), "}\n".repeat(100_000))),
        fs(&format!("let x = {}1", "a ? ".repeat(50_000))),
    ] {
        let p = parse_str(&src);
        let errs = p.errors();
        assert_eq!(errs.len(), 1, "{:?}", p.locs().iter().take(3).collect::<Vec<_>>());
        assert!(errs[0].message.contains("limit 128"), "{}", errs[0].message);
    }
    // Within the limit is fine.
    let p = parse_str(&nested_parens(120));
    assert!(p.diags.is_empty(), "{}", p.rendered());
}

#[test]
fn garbage_never_panics() {
    let mut inputs: Vec<String> = vec![
        "".into(),
        "\0\0\0".into(),
        "[".into(),
        "[vertex_program".into(),
        "[vertex_program]\ndef".into(),
        "[vertex_program]\ndef f(".into(),
        "[vertex_program]\ndef f {".into(),
        "[vertex_program]\ndef f { let x = \"\u{1F600}".into(),
        "[vertex_program]\ndef f { /* ".into(),
        "#ifdef".into(),
        "#include".into(),
        "#define".into(),
        "var @".into(),
        "var @uniform".into(),
        "var @uniform x :".into(),
        "}}}}]]]))))".into(),
    ];
    let base = fs("let a = float4(1.0, 2.0).xyz * b[c] + (d ? e : f)\nif (x) {\n}");
    for cut in 0..base.len() {
        inputs.push(base[..cut].to_string());
    }
    for s in inputs {
        let _ = parse_str(&s);
    }
}

#[test]
fn token_soup_never_panics() {
    // A deterministic pseudo-random mix of daslang fragments.
    let parts = [
        "var", "let", "def", "struct", "[vertex_program]", "[fragment_program]", "@uniform", "@in", "@location", "=", "==", "(",
        ")", "[", "]", "{", "}", "\n", ";", ",", ":", "?", "x", "float4", "1", "1.5", "0x", "1e", ".", "+", "-", "*", "++",
        "if", "elif", "else", "for", "in", "while", "return", "\"", "'", "/*", "*/", "//", "#ifdef A", "#endif", "#define A (",
        "§", "\0", "fixed_array<", ">", "<-", ":=", "@@", "$", "1.0d", "9999999999999999999999",
    ];
    let mut state = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..3000 {
        let mut s = String::new();
        for _ in 0..(state % 60) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            s.push_str(parts[(state % parts.len() as u64) as usize]);
            s.push(if state & 0x100 != 0 { ' ' } else { '\n' });
        }
        let _ = parse_str(&s);
        let _ = parse_str(&fs(&s));
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    }
}

// ---------------------------------------------------------------- preprocessor

struct Dir {
    dir: tempfile::TempDir,
}

impl Dir {
    fn new() -> Dir {
        Dir { dir: tempfile::tempdir().unwrap() }
    }

    fn write(&self, name: &str, text: impl AsRef<str>) -> PathBuf {
        let p = self.dir.path().join(name);
        if let Some(parent) = p.parent() {
            std::fs::create_dir_all(parent).unwrap();
        }
        std::fs::write(&p, text.as_ref()).unwrap();
        p
    }

    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }
}

const MAIN_FS: &str = "[fragment_program]\ndef main_fs {\ncol = COLOR\n}\n";

#[test]
fn include_relative_and_include_dirs() {
    let d = Dir::new();
    d.write("inc/common.das", "var @out col : float4\n#include \"more.das\"\n");
    d.write("inc/more.das", "let SCALE = 2.0\n");
    d.write("lib/colors.das", "#define COLOR float4(SCALE)\n");
    let root = d.write("main.das", "#include \"inc/common.das\"\n#include \"colors.das\"\n#include \"colors.das\"\n" .to_owned() + MAIN_FS);
    let opts = ParseOptions { include_dirs: vec![d.path("lib")], ..Default::default() };
    let p = parse_path(&root, &opts);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert_eq!(p.names(), ["col", "SCALE", "main_fs"]);
    // The substituted tokens keep the spans of the #define's text.
    let f = p.function("main_fs");
    let StmtKind::Assign { value, .. } = &f.body.stmts[0].kind else { panic!() };
    let (file, line, col) = p.map.line_col(value.span).unwrap();
    assert!(p.map.file(file).name.ends_with("colors.das"));
    assert_eq!((line, col), (1, 15));
}

#[test]
fn conditionals_defines_and_guards() {
    let d = Dir::new();
    d.write("guard.das", "#ifndef GUARD\n#define GUARD\nvar @out col : float4\n#endif\n");
    let src = "#include \"guard.das\"\n#include \"guard.das\"\n\
        #ifdef FAST\n#ifdef NEVER\nlet NO = 1\n#else\nlet MODE = 1\n#endif\n#else\n#ifndef NEVER\nlet MODE = 2\n#endif\n#endif\n\
        #define NEVER\n#undef NEVER\n#ifdef NEVER\n#bogus directive in dead code\n#endif\n\
        [fragment_program]\ndef main_fs {\ncol = float4(MODE + SCALE)\n}\n";
    let root = d.write("main.das", src);
    let opts = ParseOptions { defines: vec![("FAST".into(), None), ("SCALE".into(), Some("3 * 2".into()))], ..Default::default() };
    let p = parse_path(&root, &opts);
    assert!(p.diags.is_empty(), "{}", p.rendered());
    assert_eq!(p.names(), ["col", "MODE", "main_fs"]);
    let Item::Const(c) = &p.program.items[1] else { panic!() };
    assert_eq!(p.map.line_col(c.span).unwrap().1, 7);
    // -D values have spans in the <command-line> virtual file.
    let f = p.function("main_fs");
    let StmtKind::Assign { value, .. } = &f.body.stmts[0].kind else { panic!() };
    let ExprKind::Call { args, .. } = &value.kind else { panic!() };
    let ExprKind::Binary(_, lr) = &args[0].kind else { panic!() };
    let rhs = &lr.1;
    let (file, line, _) = p.map.line_col(rhs.span).unwrap();
    assert_eq!(p.map.file(file).name, "<command-line>");
    assert_eq!(line, 2);
    // Without FAST, the other branch.
    let p = parse_path(&root, &ParseOptions { defines: vec![("SCALE".into(), Some("1".into()))], ..Default::default() });
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let Item::Const(c) = &p.program.items[1] else { panic!() };
    assert_eq!(p.map.line_col(c.span).unwrap().1, 11);
}

#[test]
fn recursive_define_terminates() {
    let p = parse_str("#define A B + 1\n#define B A\nvar @out col : float4\n[fragment_program]\ndef main_fs {\nlet x = A\n}\n");
    assert!(p.diags.is_empty(), "{}", p.rendered());
}

#[test]
fn include_cycle_shows_the_chain() {
    let d = Dir::new();
    d.write("a.das", "#include \"b.das\"\n");
    d.write("b.das", "\n#include \"a.das\"\n");
    let root = d.write("main.das", "#include \"a.das\"\n".to_owned() + "var @out col : float4\n" + MAIN_FS);
    let p = parse_path(&root, &ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() });
    let locs = p.locs();
    assert_eq!(locs.len(), 1);
    assert!(locs[0].starts_with("b.das:2:10: include cycle: `") && locs[0].ends_with("a.das` includes itself"), "{locs:?}");
    let r = p.rendered();
    assert!(r.contains("a.das -> ") && r.contains("b.das -> "), "{r}");
    assert!(r.contains("included from") && r.contains("main.das:1:1"), "{r}");
}

#[test]
fn missing_include_lists_searched_paths() {
    let d = Dir::new();
    let root = d.write("main.das", "\n  #include \"nope.das\"\nvar @out col : float4\n".to_owned() + MAIN_FS);
    let opts = ParseOptions { include_dirs: vec![d.path("extra")], defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() };
    let p = parse_path(&root, &opts);
    assert_eq!(p.locs(), ["main.das:2:12: cannot find include file `nope.das`"]);
    let notes = &p.diags[0].notes;
    assert_eq!(notes.len(), 2, "{notes:?}");
    assert!(notes[1].contains("extra"), "{notes:?}");
}

#[test]
fn includes_are_confined() {
    let d = Dir::new();
    d.write("outside/evil.das", "let X = 1\n");
    let root = d.write("proj/main.das", "#include \"../outside/evil.das\"\nvar @out col : float4\n".to_owned() + MAIN_FS);
    let opts = ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() };
    let p = parse_path(&root, &opts);
    assert_eq!(p.locs(), ["main.das:1:10: `#include \"../outside/evil.das\"` reaches outside the input's directory and the include directories"]);
    assert!(p.rendered().contains("--allow-outside-includes"));
    let p = parse_path(&root, &ParseOptions { allow_outside_includes: true, ..opts.clone() });
    assert!(p.diags.is_empty(), "{}", p.rendered());
    let p = parse_path(&root, &ParseOptions { include_dirs: vec![d.path("outside")], ..opts });
    assert!(p.diags.is_empty(), "{}", p.rendered());
}

#[cfg(unix)]
#[test]
fn symlink_loop_is_an_error() {
    let d = Dir::new();
    std::os::unix::fs::symlink(d.path("loop1.das"), d.path("loop2.das")).unwrap();
    std::os::unix::fs::symlink(d.path("loop2.das"), d.path("loop1.das")).unwrap();
    let root = d.write("main.das", "#include \"loop1.das\"\nvar @out col : float4\n".to_owned() + MAIN_FS);
    let p = parse_path(&root, &ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() });
    assert_eq!(p.locs(), ["main.das:1:10: cannot find include file `loop1.das`"]);
    assert!(p.diags[0].notes.iter().any(|n| n.contains("symbolic links")), "{:?}", p.diags[0].notes);
}

#[test]
fn include_depth_limit() {
    let d = Dir::new();
    // Distinct files, each including the next: no cycle, just depth.
    for i in 0..70 {
        d.write(&format!("f{i}.das"), format!("#include \"f{}.das\"\n", i + 1));
    }
    d.write("f70.das", "");
    let root = d.write("main.das", "#include \"f0.das\"\nvar @out col : float4\n".to_owned() + MAIN_FS);
    let p = parse_path(&root, &ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() });
    assert_eq!(p.errors().len(), 1, "{:?}", p.locs());
    assert_eq!(p.locs()[0], "f63.das:1:1: `#include` nested too deeply (limit 64)");
}

#[test]
fn unterminated_ifdef_and_stray_directives() {
    let src = "var @out col : float4\n#ifdef X\n#else\n".to_owned() + MAIN_FS;
    let p = parse_str_opts(&src, &ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() });
    assert_eq!(p.locs(), ["test.das:2:1: unterminated `#ifdef`"]);
    let p = parse_str("#endif\n#else\n#pragma once\n#if X\n#endif\n  #include <x>\n".to_owned().as_str());
    assert_eq!(
        p.locs(),
        [
            "test.das:1:1: `#endif` without a matching `#ifdef` or `#ifndef`",
            "test.das:2:1: `#else` without a matching `#ifdef` or `#ifndef`",
            "test.das:3:1: unknown preprocessor directive `#pragma`",
            "test.das:4:1: `#if` is not supported",
            "test.das:6:12: expected a file name in double quotes after `#include`, found `<`",
        ]
    );
}

#[test]
fn non_utf8_include() {
    let d = Dir::new();
    std::fs::write(d.path("bad.das"), b"let X = \xff\xfe\n").unwrap();
    let root = d.write("main.das", "#include \"bad.das\"\nvar @out col : float4\n".to_owned() + MAIN_FS);
    let p = parse_path(&root, &ParseOptions { defines: vec![("COLOR".into(), Some("col".into()))], ..Default::default() });
    assert_eq!(p.locs(), ["main.das:1:10: include file `".to_owned() + &d.path("bad.das").display().to_string() + "` is not UTF-8 text"]);
}
