//! Functions and data as daslang writes them (issue 17): how the parser
//! shapes pipes, postfix `if`, `=>` bodies and parameters, and what the
//! checker makes of them, on the public API. The computed values are
//! checked on the device in tests/gpu/language_f.rs; refusals are in the
//! bad-input corpus.

use umbrac::diag::Diagnostics;
use umbrac::source::SourceMap;
use umbrac::syntax::{self, ast, ParseOptions};
use umbrac::Target;

fn parse(text: &str) -> (ast::Program, Diagnostics) {
    let mut map = SourceMap::new();
    let root = map.add("test.das", None, text.to_string(), None);
    let mut diags = Diagnostics::new();
    let program = syntax::parse(&mut map, root, &ParseOptions::default(), &mut diags);
    (program, diags)
}

fn function<'p>(p: &'p ast::Program, name: &str) -> &'p ast::FunctionDecl {
    p.items
        .iter()
        .find_map(|i| match i {
            ast::Item::Function(f) if f.name.name == name => Some(f),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no function {name}"))
}

/// The expression `let v = ...` starts `main_fs` with.
fn first_value(src: &str) -> ast::Expr {
    let text = format!("var @out col : float4\n[fragment_program]\ndef main_fs {{\n    let v = {src}\n    col = float4(1.0)\n}}\n");
    let (p, d) = parse(&text);
    assert!(!d.has_errors(), "{src}");
    match &function(&p, "main_fs").body.stmts[0].kind {
        ast::StmtKind::Local { init: Some(e), .. } => e.clone(),
        other => panic!("{other:?}"),
    }
}

fn glsl(src: &str, entry: &str) -> String {
    let opts = umbrac::Options { targets: vec![Target::Glsl330], ..Default::default() };
    let c = umbrac::compile_source("test.das", src, &opts);
    let Some(compiled) = &c.result else { panic!("does not compile:\n{}", c.render_diagnostics()) };
    compiled.artifacts.iter().find(|a| a.entry.as_deref() == Some(entry)).expect("the entry point's GLSL").text().into_owned()
}

/// The reported bug: a function with no declared result that returns a
/// value was "a function that returns nothing" (`return` takes no value).
#[test]
fn a_function_without_a_result_type_returns_what_return_gives() {
    let src = "def h() {\n    return 1.0\n}\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    var a = 1.0\n    h()\n    a = h() * a\n    f_color = float4(a)\n}\n";
    let text = glsl(src, "fs");
    assert!(text.contains("float h()"), "{text}");
}

#[test]
fn pipes_bind_tighter_than_operators_and_chain_left_to_right() {
    // `2.0 + x |> f(y)` is `2.0 + f(x, y)`.
    let e = first_value("2.0 + 1.0 |> max(0.5)");
    let ast::ExprKind::Binary(ast::BinaryOp::Add, lr) = &e.kind else { panic!("{e:?}") };
    let ast::ExprKind::Call { callee, args } = &lr.1.kind else { panic!("{e:?}") };
    assert_eq!((callee.name.as_str(), args.len()), ("max", 2));
    assert!(matches!(args[0].kind, ast::ExprKind::Float(f) if f == 1.0));
    // `x |> f() |> g(y)` is `g(f(x), y)`; `f(y) <| x` is `f(y, x)`.
    let e = first_value("1.0 |> abs() |> min(2.0)");
    let ast::ExprKind::Call { callee, args } = &e.kind else { panic!("{e:?}") };
    assert_eq!(callee.name.as_str(), "min");
    assert!(matches!(&args[0].kind, ast::ExprKind::Call { callee, .. } if callee.name == "abs"));
    let e = first_value("min(2.0) <| 1.0");
    let ast::ExprKind::Call { args, .. } = &e.kind else { panic!("{e:?}") };
    assert!(matches!(args[1].kind, ast::ExprKind::Float(f) if f == 1.0));
}

#[test]
fn headers_keep_parameter_kinds_defaults_and_arrow_bodies() {
    let (p, d) = parse("def private f(var a : float&; b : float3 const; var c : int; d : float = 0.5) -> float => a\n[fragment_program]\ndef fs {\n    f()\n}\n");
    assert!(!d.has_errors());
    let f = function(&p, "f");
    let kinds: Vec<(bool, bool, bool, bool)> = f.params.iter().map(|p| (p.mutable, p.by_ref, p.constant.is_some(), p.default.is_some())).collect();
    assert_eq!(kinds, [(true, true, false, false), (false, false, true, false), (true, false, false, false), (false, false, false, true)]);
    assert!(f.ret.is_some());
    assert!(matches!(f.body.stmts.as_slice(), [ast::Stmt { kind: ast::StmtKind::Return(Some(_)), .. }]));
}

#[test]
fn a_postfix_if_is_an_if_around_its_statement() {
    let (p, d) = parse("def f(x : float) : float {\n    return 0.0 if (x < 0.0) else return 1.0\n}\n[fragment_program]\ndef fs {\n    f()\n}\n");
    assert!(!d.has_errors());
    let ast::StmtKind::If { then, otherwise: Some(otherwise), elifs, .. } = &function(&p, "f").body.stmts[0].kind else { panic!() };
    assert!(elifs.is_empty());
    assert!(matches!(then.stmts[0].kind, ast::StmtKind::Return(Some(_))));
    assert!(matches!(otherwise.stmts[0].kind, ast::StmtKind::Return(Some(_))));
}

#[test]
fn only_the_overloads_an_entry_point_reaches_are_in_its_file() {
    let src = "def luma(c : float3) => c.g\ndef luma(c : float4) => c.a\nvar @inout v : float4\nvar @out f_color : float4\n\
               [vertex_program]\ndef vs {\n    v = float4(luma(float3(1.0)))\n    gl_Position = v\n}\n\
               [fragment_program]\ndef fs {\n    f_color = float4(luma(v))\n}\n";
    let (vs, fs) = (glsl(src, "vs"), glsl(src, "fs"));
    assert!(vs.contains("luma_float3_") && !vs.contains("luma_float4_"), "{vs}");
    assert!(fs.contains("luma_float4_") && !fs.contains("luma_float3_"), "{fs}");
}

#[test]
fn independent_errors_in_the_new_constructs_are_reported_together() {
    let src = "enum Mode {\n    a\n}\nstruct S {\n    x : float = 1.0\n}\ndef f(x : float; k : float = 2) => x * k\n\
               var @out f_color : float4\n[fragment_program]\ndef fs {\n    let s = S(y = 1.0)\n    let m = Mode.b\n    f_color = float4(f(1.0))\n}\n";
    let c = umbrac::compile_source("test.das", src, &Default::default());
    let errors: Vec<&str> = c.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.message.as_str()).collect();
    assert_eq!(errors.len(), 3, "{errors:?}");
    assert!(errors.iter().any(|m| m.contains("default value of `k`")), "{errors:?}");
    assert!(errors.iter().any(|m| m.contains("no field `y`")), "{errors:?}");
    assert!(errors.iter().any(|m| m.contains("no value `b`")), "{errors:?}");
}
