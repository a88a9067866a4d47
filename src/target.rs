//! What a compilation produces: the output languages ([`Target`]) and the
//! files made for them ([`Artifact`]). Defined below `emit`, which makes
//! them, so that `emit`, `output` and `golden` need nothing of the driver.

/// An output language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    Glsl330,
    Gles300,
    Wgsl,
    Spirv,
}

impl Target {
    pub const ALL: [Target; 4] = [Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Spirv];

    /// The name used on the command line and in the reflection manifest.
    pub fn name(self) -> &'static str {
        match self {
            Target::Glsl330 => "glsl330",
            Target::Gles300 => "gles300",
            Target::Wgsl => "wgsl",
            Target::Spirv => "spirv",
        }
    }

    pub fn from_name(s: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == s)
    }
}

/// One output file's name and bytes.
#[derive(Clone, Debug)]
pub struct Artifact {
    /// File name without directory: `main_vs.330.vert`, `shadow.wgsl`, ...
    pub file_name: String,
    /// `None` for the reflection manifest.
    pub target: Option<Target>,
    /// The entry point, for per-entry-point outputs (the GLSL files).
    pub entry: Option<String>,
    pub contents: Vec<u8>,
}

impl Artifact {
    /// The contents as text (SPIR-V is binary; this is lossy for it).
    pub fn text(&self) -> std::borrow::Cow<'_, str> {
        String::from_utf8_lossy(&self.contents)
    }
}
