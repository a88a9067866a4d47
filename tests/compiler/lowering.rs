//! Properties of the naga modules the lowering builds, over every program
//! under `shaders/` that compiles on its own.

use std::path::Path;

/// The lowered modules of `path`, or `None` when it does not compile with
/// default options (one that needs defines, say).
fn lower(path: &Path) -> Option<umbrac::Lowered> {
    let mut sources = umbrac::SourceMap::new();
    let text = std::fs::read_to_string(path).unwrap();
    let root = sources.add(path.display().to_string(), Some(path.to_path_buf()), text, None);
    let mut diags = umbrac::Diagnostics::new();
    let ast = umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
    if diags.has_errors() {
        return None;
    }
    let checked = umbrac::sema::check(&ast, &mut diags)?;
    if diags.has_errors() {
        return None;
    }
    umbrac::lower::lower(&checked, umbrac::Conventions::default()).ok()
}

/// naga never emits literals, constants, variables' pointers and zero
/// values, and lets a function use each anywhere in it: a function holds
/// one of each, not one per use (every extra one was an expression to
/// validate and write, and a split of the running emit range).
#[test]
fn a_function_holds_each_unemitted_expression_once() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let mut checked = 0;
    for found in umbrac::batch::programs_under(&root).expect("shaders/ is readable") {
        let path = &found.path;
        let Some(lowered) = lower(path) else { continue };
        let modules = std::iter::once(&lowered.gpu).chain(lowered.gl.iter().map(|g| &g.module));
        for module in modules {
            let functions = module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
            for f in functions {
                let mut seen = std::collections::HashSet::new();
                for (h, e) in f.expressions.iter() {
                    use naga::Expression as E;
                    // Literals by their Debug text: -0.0 and 0.0 differ.
                    let key = match e {
                        E::Literal(_) | E::Constant(_) | E::GlobalVariable(_) | E::LocalVariable(_) | E::ZeroValue(_) => format!("{e:?}"),
                        _ => continue,
                    };
                    assert!(seen.insert(key.clone()), "{}: function `{}` has a second {key} at {h:?}", path.display(), f.name.as_deref().unwrap_or("?"));
                }
            }
        }
        checked += 1;
    }
    assert!(checked >= 40, "only {checked} programs under shaders/ compiled on their own");
}
