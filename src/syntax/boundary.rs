//! Which directories an `#include` or `require` may read from. A file is
//! inside when its real path is under a directory's real path, or when the
//! path it was found by is, as written, under the directory as the user
//! named it. The second rule is for sandboxes made of symlinks (Bazel
//! stages every input as a link into the source tree): there the directory
//! the user named is the boundary, not where its files' links point. A
//! file the sandbox does not hold is still not found.

use std::path::{Component, Path, PathBuf};

pub(crate) struct Boundary {
    /// The directories' real paths.
    real: Vec<PathBuf>,
    /// The directories as named, made absolute, `.` and `..` removed
    /// by their text.
    named: Vec<PathBuf>,
}

impl Boundary {
    pub(crate) fn new<'a>(dirs: impl IntoIterator<Item = &'a PathBuf>) -> Boundary {
        let mut b = Boundary { real: Vec::new(), named: Vec::new() };
        for d in dirs {
            // A directory that does not exist holds nothing to allow.
            if let Ok(c) = std::fs::canonicalize(d) {
                b.real.push(c);
                b.named.extend(lexical(d));
            }
        }
        b
    }

    /// The real directories, for the notes of a refusal.
    pub(crate) fn dirs(&self) -> &[PathBuf] {
        &self.real
    }

    /// Whether `found` (the path a file was found by, `canon` its real
    /// path) is inside. By name only when the name, `..` taken by its
    /// text, reaches the same file: `inc/link/../x` with `link` a symlink
    /// elsewhere is judged by where it really leads.
    pub(crate) fn contains(&self, found: &Path, canon: &Path) -> bool {
        if self.real.iter().any(|a| canon.starts_with(a)) {
            return true;
        }
        let Some(named) = lexical(found) else { return false };
        self.named.iter().any(|a| named.starts_with(a)) && std::fs::canonicalize(&named).is_ok_and(|c| c == canon)
    }
}

/// `p` made absolute against the working directory, with `.` and `..`
/// taken by their text (a `..` above the root stays at the root).
pub(crate) fn lexical(p: &Path) -> Option<PathBuf> {
    let abs = if p.is_absolute() { p.to_path_buf() } else { std::env::current_dir().ok()?.join(p) };
    Some(normalize(&abs))
}

/// `.` and `..` components removed by their text: `a/./b/../c` is `a/c`;
/// a relative path keeps its leading `..`s.
pub fn normalize(p: &Path) -> PathBuf {
    let mut out: Vec<Component> = Vec::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => match out.last() {
                Some(Component::Normal(_)) => {
                    out.pop();
                }
                Some(Component::RootDir | Component::Prefix(_)) => {}
                _ => out.push(c),
            },
            _ => out.push(c),
        }
    }
    if out.is_empty() {
        return PathBuf::from(".");
    }
    out.iter().collect()
}

#[cfg(test)]
mod tests {
    use super::normalize;
    use std::path::Path;

    #[test]
    fn dots_are_taken_by_their_text() {
        assert_eq!(normalize(Path::new("inc/lib/../palette.das")), Path::new("inc/palette.das"));
        assert_eq!(normalize(Path::new("./a/./b")), Path::new("a/b"));
        assert_eq!(normalize(Path::new("../../x/../y")), Path::new("../../y"));
        assert_eq!(normalize(Path::new("/../a/..")), Path::new("/"));
        assert_eq!(normalize(Path::new("a/..")), Path::new("."));
    }
}
