//! Texts that stand for files on disk while a compilation runs: an
//! editor's unsaved documents (`crate::workspace`). Every read of a source
//! file (the root, `#include`s, `require`d modules) goes through
//! [`super::read_bounded`], which asks here first.
//!
//! The overlay is per thread, so that compilations on other threads (tests,
//! a build's workers) never see it; [`with`] installs it around one
//! compilation, which runs on the calling thread.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// Texts by normalized absolute path ([`normalize`]).
pub type Texts = Arc<HashMap<PathBuf, String>>;

thread_local! {
    static CURRENT: RefCell<Option<Texts>> = const { RefCell::new(None) };
}

/// Runs `f` with `texts` standing for the files they name, on this thread.
pub fn with<T>(texts: Texts, f: impl FnOnce() -> T) -> T {
    struct Reset(Option<Texts>);
    impl Drop for Reset {
        fn drop(&mut self) {
            CURRENT.with(|c| *c.borrow_mut() = self.0.take());
        }
    }
    let _reset = Reset(CURRENT.with(|c| c.borrow_mut().replace(texts)));
    f()
}

/// The text standing for `path`, if any.
pub(crate) fn text_of(path: &Path) -> Option<String> {
    CURRENT.with(|c| {
        let c = c.borrow();
        let texts = c.as_ref()?;
        texts.get(&normalize(path)).cloned()
    })
}

/// The texts installed on this thread, for a thread that runs a
/// compilation on its behalf ([`crate::compile_source`] in an unoptimised
/// build) to install in turn.
pub(crate) fn current() -> Option<Texts> {
    CURRENT.with(|c| c.borrow().clone())
}

/// Whether a text stands for `path` (a file that may exist nowhere else:
/// the playground's includes, which has no file system).
pub(crate) fn holds(path: &Path) -> bool {
    CURRENT.with(|c| c.borrow().as_ref().is_some_and(|t| t.contains_key(&normalize(path))))
}

/// `path` made absolute (against the working directory) with `.` and `..`
/// resolved lexically: an include found as `dir/../inc/a.das` is the open
/// document `inc/a.das`. Symbolic links are not followed (the file may not
/// exist on disk).
pub fn normalize(path: &Path) -> PathBuf {
    let abs = if path.is_absolute() { path.to_path_buf() } else { std::env::current_dir().unwrap_or_default().join(path) };
    let mut out = PathBuf::new();
    for c in abs.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalizes_dots_and_restores_the_previous_overlay() {
        assert_eq!(normalize(Path::new("/a/./b/../c.das")), PathBuf::from("/a/c.das"));
        let texts: Texts = Arc::new([(PathBuf::from("/x/y.das"), "hi".to_string())].into_iter().collect());
        with(texts, || {
            assert_eq!(text_of(Path::new("/x/z/../y.das")).as_deref(), Some("hi"));
            with(Arc::default(), || assert_eq!(text_of(Path::new("/x/y.das")), None));
            assert_eq!(text_of(Path::new("/x/y.das")).as_deref(), Some("hi"));
        });
        assert_eq!(text_of(Path::new("/x/y.das")), None);
    }

    #[test]
    fn an_include_may_exist_only_as_a_text() {
        // The playground has no file system: its includes are texts alone,
        // seen on the thread an unoptimised build compiles on too.
        let main = "#include \"inc/colour.das\"\nvar @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = COLOUR\n}\n";
        let texts: Texts = Arc::new([(normalize(Path::new("nowhere/inc/colour.das")), "#define COLOUR float4(1.0)\n".to_string())].into_iter().collect());
        let opts = crate::Options { allow_outside_includes: true, ..Default::default() };
        let c = with(texts, || crate::compile_source("nowhere/main.das", main, &opts));
        assert!(!c.has_errors(), "{}", c.render_diagnostics());
    }

    #[test]
    fn a_required_module_may_exist_only_as_a_text() {
        // The playground's `require`d modules, as its includes.
        let main = "options gen2\nrequire lib/tint\nvar @out f_color : float4\n[fragment_program]\ndef main_fs {\n    f_color = float4(tint(), 1.0)\n}\n";
        let tint = "options gen2\nmodule tint public\ndef tint() : float3 {\n    return float3(0.25, 0.5, 0.75)\n}\n";
        let texts: Texts = Arc::new([(normalize(Path::new("nowhere/lib/tint.das")), tint.to_string())].into_iter().collect());
        let opts = crate::Options { allow_outside_includes: true, ..Default::default() };
        let c = with(texts, || crate::compile_source("nowhere/main.das", main, &opts));
        assert!(!c.has_errors(), "{}", c.render_diagnostics());
    }
}
