//! `umbrac preview FILE --scene SCENE`: the program drawn with a scene
//! file (docs/runner.md, "Scene files") instead of its inferred scene. The
//! file is read again on every compile (and watched, so saving it redraws),
//! and the image files its textures name are served under `/scene/NAME`:
//! only those, and only inside the scene file's directory.

use std::path::{Component, Path, PathBuf};

use crate::diag::{JsonDiagnostic, Severity};
use crate::scene::Scene;

/// A scene file the preview draws with.
#[derive(Clone, Debug)]
pub struct SceneFile {
    path: PathBuf,
}

impl SceneFile {
    /// Checks that `path` reads and parses now, so that a mistake is
    /// reported before the server starts.
    pub fn open(path: &Path) -> Result<SceneFile, String> {
        let f = SceneFile { path: path.to_path_buf() };
        f.load()?;
        Ok(f)
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The scene as the file says now; the error names the file, line and column.
    pub fn load(&self) -> Result<Scene, String> {
        let text = std::fs::read_to_string(&self.path).map_err(|e| format!("cannot read `{}`: {e}", self.path.display()))?;
        Scene::parse(&self.path.display().to_string(), &text)
    }

    /// A scene file's mistake as a bundle's diagnostic: the page shows it
    /// over the last good picture, as a compile error.
    pub fn diagnostic(message: &str) -> JsonDiagnostic {
        JsonDiagnostic {
            severity: Severity::Error,
            message: message.lines().next().unwrap_or_default().to_string(),
            location: None,
            label: String::new(),
            related: Vec::new(),
            notes: Vec::new(),
            include_chain: Vec::new(),
            rendered: format!("error: {message}\n"),
        }
    }

    /// The image file a texture of the scene names `name` (as the scene
    /// writes it, relative to its directory): its content type and bytes,
    /// or the status and why it is refused.
    pub fn image(&self, name: &str) -> Result<(&'static str, Vec<u8>), (u16, String)> {
        let scene = self.load().map_err(|e| (404, format!("the scene file does not parse: {e}")))?;
        if !scene.textures.iter().any(|t| t.image.as_deref() == Some(name)) {
            return Err((404, format!("`{name}` is no image the scene file names")));
        }
        // A name that leaves the directory is refused even when the scene names it.
        if name.is_empty() || !Path::new(name).components().all(|c| matches!(c, Component::Normal(_))) {
            return Err((403, format!("`{name}` is not inside the scene file's directory")));
        }
        let dir = self.path.parent().unwrap_or(Path::new("."));
        let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
        let file = dir.join(name);
        let inside = match (dir.canonicalize(), file.canonicalize()) {
            (Ok(d), Ok(f)) => f.starts_with(d),
            _ => return Err((404, format!("`{name}`: no such file beside the scene file"))),
        };
        if !inside {
            return Err((403, format!("`{name}` is not inside the scene file's directory (a link leads out)")));
        }
        let kind = match file.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("png") => "image/png",
            Some("jpg" | "jpeg") => "image/jpeg",
            _ => "application/octet-stream",
        };
        std::fs::read(&file).map(|b| (kind, b)).map_err(|e| (404, format!("`{name}`: {e}")))
    }
}
