//! What a compilation produces: the output languages ([`Target`]) and the
//! files made for them ([`Artifact`]). Defined below `emit`, which makes
//! them, so that `emit`, `output` and `golden` need nothing of the driver.

/// An output language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Target {
    Glsl330,
    Gles300,
    /// GLSL 430 core: compute, storage buffers and images (GL 4.3).
    Glsl430,
    /// GLSL ES 3.10: compute, storage buffers and images (GLES 3.1).
    Gles310,
    Wgsl,
    Spirv,
}

impl Target {
    pub const ALL: [Target; 6] = [Target::Glsl330, Target::Gles300, Target::Glsl430, Target::Gles310, Target::Wgsl, Target::Spirv];

    /// The targets a program gets when none are requested (`--target all`,
    /// or no `--target`): every target that can run it. GL 3.3 and GLES 3.0
    /// have no compute, storage buffers or images, so a program that uses
    /// them gets GLSL 430 and GLSL ES 3.10 instead; any other gets GLSL 330
    /// and GLSL ES 3.00 (which GL 4.3 and GLES 3.1 drivers run too).
    pub fn defaults(needs_compute: bool) -> [Target; 4] {
        match needs_compute {
            false => [Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Spirv],
            true => [Target::Glsl430, Target::Gles310, Target::Wgsl, Target::Spirv],
        }
    }

    /// The name used on the command line and in the reflection manifest.
    pub fn name(self) -> &'static str {
        match self {
            Target::Glsl330 => "glsl330",
            Target::Gles300 => "gles300",
            Target::Glsl430 => "glsl430",
            Target::Gles310 => "gles310",
            Target::Wgsl => "wgsl",
            Target::Spirv => "spirv",
        }
    }

    /// A GLSL target (one file per entry point).
    pub fn is_glsl(self) -> bool {
        matches!(self, Target::Glsl330 | Target::Gles300 | Target::Glsl430 | Target::Gles310)
    }

    /// A GLSL target without compute, storage buffers or images.
    pub fn is_classic_glsl(self) -> bool {
        matches!(self, Target::Glsl330 | Target::Gles300)
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
