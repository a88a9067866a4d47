//! The program the runner draws: a `.das` file compiled in process (or the
//! project's scene program), or a ready `.wgsl` / `.spv` file.

use std::path::Path;

use crate::render::consumer::Consumer;
use crate::render::hand;
use crate::render::program::{ShaderCode, ShaderSet};
use crate::Target;

/// The project's own scene program, used when FILE is not given and
/// `shaders/shadow.das` is not on disk.
const BUILTIN_PROGRAM: &str = include_str!("../../../shaders/shadow.das");
pub(crate) const DEFAULT_PROGRAM: &str = "shaders/shadow.das";

/// Loads the program named on the command line, in the form `consumer` runs.
pub fn load_program(file: Option<&Path>, reflection: Option<&Path>, consumer: Consumer) -> Result<ShaderSet, String> {
    load_program_with(file, reflection, consumer, crate::Options::default())
}

/// [`load_program`] with the options of a .das program's compile (`-D`
/// definitions, `--daslang-root`; its targets are the consumer's).
pub fn load_program_with(file: Option<&Path>, reflection: Option<&Path>, consumer: Consumer, base: crate::Options) -> Result<ShaderSet, String> {
    let target = consumer.target().ok_or_else(|| format!("{} runs no compiled program", consumer.name()))?;
    let ext = file.and_then(|p| p.extension()).and_then(|e| e.to_str());
    if let (Some(path), Some(ext @ ("wgsl" | "spv"))) = (file, ext) {
        if !matches!(target, Target::Wgsl | Target::Spirv) {
            return Err(format!("the GL consumers run the compiler's GLSL: give a .das program, not a .{ext} file"));
        }
        let code = if ext == "wgsl" {
            if target != Target::Wgsl {
                return Err(format!("{} is WGSL; --via spirv needs a .das or .spv program", path.display()));
            }
            ShaderCode::Wgsl(std::fs::read_to_string(path).map_err(|e| format!("reading {}: {e}", path.display()))?)
        } else {
            let bytes = std::fs::read(path).map_err(|e| format!("reading {}: {e}", path.display()))?;
            ShaderCode::spirv_from_bytes(&bytes).map_err(|e| format!("{}: {e}", path.display()))?
        };
        let refl = match reflection {
            Some(r) => {
                let json = std::fs::read_to_string(r).map_err(|e| format!("reading {}: {e}", r.display()))?;
                serde_json::from_str(&json).map_err(|e| format!("{}: not a reflection manifest: {e}", r.display()))?
            }
            None => hand::reflection(),
        };
        return Ok(ShaderSet::single(path.display().to_string(), code, refl));
    }
    let opts = crate::Options { targets: vec![target], ..base };
    match compile_program(file, &opts) {
        (name, Some(compiled)) => ShaderSet::from_compiled(name, &compiled, target),
        (name, None) => Err(format!(
            "{name} did not compile (the hand-written port renders with `umbrac render {}`)",
            hand::FILE_NAME
        )),
    }
}

/// Compiles the program the runner draws: `file`, else `shaders/shadow.das`
/// when run from a checkout, else the copy built into the binary. Its
/// diagnostics go to stderr; the result comes back only when it has no
/// errors, with the name the diagnostics use.
pub fn compile_program(file: Option<&Path>, opts: &crate::Options) -> (String, Option<crate::Compiled>) {
    let compilation = match file {
        Some(path) => crate::compile_file(path, opts),
        None if Path::new(DEFAULT_PROGRAM).is_file() => crate::compile_file(Path::new(DEFAULT_PROGRAM), opts),
        None => crate::compile_source(DEFAULT_PROGRAM, BUILTIN_PROGRAM, opts),
    };
    let name = file.map_or(DEFAULT_PROGRAM.to_string(), |p| p.display().to_string());
    let diagnostics = compilation.render_diagnostics();
    if !diagnostics.is_empty() {
        eprint!("{diagnostics}");
    }
    let ok = !compilation.has_errors();
    (name, compilation.result.filter(|_| ok))
}

