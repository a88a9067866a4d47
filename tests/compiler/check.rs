//! `umbrac compile --check`, `umbrac bindgen` and `umbrac reflect` from the
//! command line.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::support::{repo, umbrac};

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).map(|p| (p.clone(), std::fs::read(&p).unwrap())).collect()
}

#[test]
fn check_passes_on_untouched_outputs_and_reports_a_one_character_change() {
    let d = tempfile::tempdir().unwrap();
    let shader = repo().join("shaders/shadow.das");
    let shader = shader.to_str().unwrap();
    let out = d.path().join("out");
    let o = umbrac(&["compile", shader, "-o", out.to_str().unwrap()], d.path());
    assert!(o.status.success(), "{}", text(&o.stderr));

    // Untouched: exit 0, silent, nothing written.
    let before = snapshot(&out);
    let o = umbrac(&["compile", "--check", shader, "-o", out.to_str().unwrap()], d.path());
    assert_eq!(o.status.code(), Some(0), "{}{}", text(&o.stdout), text(&o.stderr));
    assert!(o.stdout.is_empty(), "{}", text(&o.stdout));
    assert_eq!(snapshot(&out), before);

    // One character changed in one emitted file: a unified diff of that line.
    let wgsl = out.join("shadow.wgsl");
    let original = std::fs::read_to_string(&wgsl).unwrap();
    let changed = original.replacen("0.5", "0.6", 1);
    assert_ne!(changed, original);
    std::fs::write(&wgsl, &changed).unwrap();
    // Also a missing and a stale output.
    std::fs::remove_file(out.join("main_fs.300es.frag")).unwrap();
    std::fs::write(out.join("old_vs.330.vert"), "void main() {}\n").unwrap();
    let before = snapshot(&out);
    let o = umbrac(&["compile", "--check", shader, "-o", out.to_str().unwrap()], d.path());
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}{}", text(&o.stderr));
    assert!(stdout.contains("shadow.wgsl"), "{stdout}");
    assert!(stdout.contains("@@"), "a unified diff hunk:\n{stdout}");
    let minus: Vec<&str> = stdout.lines().filter(|l| l.starts_with('-') && !l.starts_with("---")).collect();
    let plus: Vec<&str> = stdout.lines().filter(|l| l.starts_with('+') && !l.starts_with("+++")).collect();
    assert_eq!((minus.len(), plus.len()), (1, 1), "exactly the changed line:\n{stdout}");
    assert!(minus[0].contains("0.6") && plus[0].contains("0.5"), "checked-in line removed, compiler's line added:\n{stdout}");
    assert!(stdout.contains("missing:") && stdout.contains("main_fs.300es.frag"), "{stdout}");
    assert!(stdout.contains("stale:") && stdout.contains("old_vs.330.vert"), "{stdout}");
    assert!(text(&o.stderr).contains("3 file(s)"), "{}", text(&o.stderr));
    assert_eq!(snapshot(&out), before, "--check writes nothing");

    // --check with -o - is a usage error.
    let o = umbrac(&["compile", "--check", shader, "-o", "-"], d.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn check_of_a_shader_with_errors_exits_1_with_the_diagnostic() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("bad.das"), "[vertex_program]\ndef vs {\n    gl_Position = float4(1.0, 2.0\n}\n").unwrap();
    let o = umbrac(&["compile", "--check", "bad.das", "-o", "."], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stderr).contains("bad.das:"), "{}", text(&o.stderr));
}

#[test]
fn bindgen_writes_the_module_and_reflect_prints_the_manifest() {
    let d = tempfile::tempdir().unwrap();
    let shader = repo().join("shaders/shadow.das");
    let o = umbrac(&["bindgen", shader.to_str().unwrap(), "-o", "bindings.rs"], d.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let rs = std::fs::read_to_string(d.path().join("bindings.rs")).unwrap();
    for needle in [
        "pub mod shadow {",
        "pub struct Uniforms {",
        "pub u_light_dir: [f32; 3],",
        "pub _pad0: [u8; 4],",
        "pub type Block = super::super::Uniforms;",
        "pub const WGSL: &str",
        "pub const SPIRV: &[u32] = &[",
        "0x07230203,",
        "pub const GLSL_BLOCK: Option<&str> = None;",
        "pub const GLSL_NAME: Option<&str> = Some(\"u_light_dir\");",
        "pub const GLSL_TYPE: &str = \"vec3\";",
        "pub const TEXTURE_UNIT: u32 = 0;",
        "pub const VERTEX_BUFFER_LAYOUT: wgpu::VertexBufferLayout<'static>",
        "#[cfg(feature = \"wgpu\")]",
        "const _: () = assert!(core::mem::size_of::<Uniforms>() == 288);",
    ] {
        assert!(rs.contains(needle), "`{needle}` missing from the bindings:\n{rs}");
    }
    let o = umbrac(&["bindgen", shader.to_str().unwrap(), "--module", "scene", "--no-bytemuck"], d.path());
    assert!(o.status.success());
    let rs = text(&o.stdout);
    assert!(rs.contains("pub mod scene {") && !rs.contains("bytemuck"), "{rs}");

    let o = umbrac(&["reflect", shader.to_str().unwrap()], &repo());
    assert!(o.status.success());
    let printed: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(printed["uniform_buffers"][0]["name"], "uniforms");
    assert_eq!(printed["uniforms"][0]["name"], "u_light_vp");
    assert_eq!(printed["samplers"][0]["glsl_name"], "shadow_map");
}

/// A file named as daslang's tutorials are (`08_shadow.das`) gets a valid
/// module name (`_08_shadow`); a module name given explicitly must be one.
#[test]
fn bindgen_makes_a_module_name_from_any_file_name() {
    let d = tempfile::tempdir().unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), d.path().join("08_shadow.das")).unwrap();
    std::fs::copy(repo().join("shaders/shadow.das"), d.path().join("my-shader.das")).unwrap();
    let o = umbrac(&["bindgen", "08_shadow.das", "-o", "b.rs"], d.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let rs = std::fs::read_to_string(d.path().join("b.rs")).unwrap();
    assert!(rs.contains("pub mod _08_shadow {"), "{}", &rs[..400]);
    let o = umbrac(&["bindgen", "my-shader.das"], d.path());
    assert!(o.status.success() && text(&o.stdout).contains("pub mod my_shader {"), "{}", text(&o.stderr));
    let o = umbrac(&["bindgen", "08_shadow.das", "--module", "08x"], d.path());
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    assert!(text(&o.stderr).contains("not a Rust identifier"), "{}", text(&o.stderr));
}

/// `--gl-uniforms blocks` and `--limit NAME=N` reach the compiler; a bad
/// `--limit` is a usage error that lists the names.
#[test]
fn gl_uniform_form_and_limits_on_the_command_line() {
    let d = tempfile::tempdir().unwrap();
    let shader = repo().join("shaders/shadow.das");
    let o = umbrac(&["compile", shader.to_str().unwrap(), "-o", "blocks", "--gl-uniforms", "blocks", "--target", "glsl330"], d.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let vs = std::fs::read_to_string(d.path().join("blocks/main_vs.330.vert")).unwrap();
    assert!(vs.contains("layout(std140) uniform uniforms_ubo {\n    mat4x4 u_light_vp;\n") && vs.contains("} uniforms;") && !vs.contains("uniform mat4x4 u_model;"), "{vs}");
    let manifest: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(d.path().join("blocks/shadow.reflect.json")).unwrap()).unwrap();
    assert_eq!(manifest["gl_uniforms"], "blocks");
    assert_eq!(manifest["uniform_buffers"][0]["glsl_block"], "uniforms_ubo");
    assert_eq!(manifest["uniform_buffers"][0]["glsl_binding"], 0);
    assert_eq!(manifest["uniform_buffers"][0]["members"][0]["glsl_name"], "uniforms_ubo.u_light_vp");

    let o = umbrac(&["compile", shader.to_str().unwrap(), "-o", "x", "--limit", "uniform-blocks=16", "--limit", "texture-units=32"], d.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let o = umbrac(&["compile", shader.to_str().unwrap(), "-o", "y", "--limit", "uniform-blobs=3"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("no limit is named `uniform-blobs`") && text(&o.stderr).contains("uniform-buffers"), "{}", text(&o.stderr));
    assert!(!d.path().join("y").exists());
}

/// The bindings of compute programs: the workgroup size, each storage
/// buffer's std430 offsets, fixed size and run-time stride, each storage
/// image's format and access, wgpu layout entries; and they compile.
#[test]
fn bindgen_describes_compute_programs() {
    let d = tempfile::tempdir().unwrap();
    for (name, needles) in [
        (
            "histogram",
            &[
                "pub const WORKGROUP_SIZE: [u32; 3] = [64, 1, 1];",
                "pub const STORAGE_BUFFERS: &[&str] = &[\"samples\", \"histogram\"];",
                "pub const RUNTIME_STRIDE: Option<u64> = Some(4);",
                "pub const OFFSET_BINS: u64 = 8;",
                "pub const SIZE: u64 = 264;",
                "pub const GLSL_BLOCK: &str = \"histogram_ssbo\";",
                "wgpu::BufferBindingType::Storage { read_only: true }",
                "pub const GLSL430: &str",
            ][..],
        ),
        (
            "image_fill",
            &[
                "pub const FORMAT: &str = \"rgba8\";",
                "pub const ACCESS: &str = \"write\";",
                "pub const IMAGE_UNIT: u32 = 0;",
                "pub const BINDING: u32 = 1;",
                "access: wgpu::StorageTextureAccess::WriteOnly, format: wgpu::TextureFormat::Rgba8Unorm",
                "visibility: wgpu::ShaderStages::COMPUTE,",
            ][..],
        ),
    ] {
        let shader = repo().join(format!("shaders/compute/{name}.das"));
        let out = d.path().join(format!("{name}.rs"));
        let o = umbrac(&["bindgen", shader.to_str().unwrap(), "--no-bytemuck", "-o", out.to_str().unwrap()], d.path());
        assert!(o.status.success(), "{}", text(&o.stderr));
        let rs = std::fs::read_to_string(&out).unwrap();
        for needle in needles {
            assert!(rs.contains(needle), "`{needle}` missing from the bindings of {name}:\n{rs}");
        }
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        let o = std::process::Command::new(rustc).args(["--edition", "2021", "--crate-type", "lib", "--emit=metadata", "-o"]).arg(d.path().join(format!("{name}.rmeta"))).arg(&out).output().expect("rustc");
        assert!(o.status.success(), "the bindings of {name} do not compile:\n{}", text(&o.stderr));
    }
}

/// daslang code says `require daslib/unroll` before `unroll() $ { ... }`:
/// with daslang's own daslib, the module's `unroll` (a function taking a
/// block) does not stand in the way of the loop.
#[test]
fn unroll_with_daslang_own_daslib() {
    let daslib = crate::support::repo().join("../shared/reference/daslang/daslib");
    if !daslib.join("unroll.das").is_file() {
        crate::support::skip(format!("{} is not here", daslib.display()));
        return;
    }
    let src = std::fs::read_to_string(crate::support::repo().join("shaders/compute/dialect_taps.das")).unwrap().replace("options gen2\n", "options gen2\nrequire daslib/unroll\n");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("taps.das");
    std::fs::write(&path, src).unwrap();
    let opts = umbrac::Options { daslib: Some(daslib), ..Default::default() };
    let c = umbrac::compile_file(&path, &opts);
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    assert!(c.files_read().iter().any(|p| p.ends_with("unroll.das")), "daslib/unroll was read");
}
