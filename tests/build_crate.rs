//! `umbrac::build` from real cargo builds of user crates (cargo in cargo).
//!
//! Slow: the first build compiles umbrac (no default features) and naga for
//! the build scripts. Every crate here shares one target directory,
//! `target/build-tests`, which survives between runs, and the crates are
//! tiny (no wgpu) except the shadow example.
//!
//! - `user_crate`: one small crate through a sequence of edits: a clean
//!   build; no rerun after touching unrelated files; a rerun after touching
//!   an `#include`d file; stale host code failing to compile after the
//!   shader's layout or member names change; a shader error failing
//!   `cargo build` with the shader's file:line:col.
//! - `shadow_example`: builds examples/shadow-build and runs it (the run is
//!   skipped without a Vulkan adapter unless CI=true).

// Only the CI policy of tests/support: the rest would link umbrac, naga
// and wgpu into this binary, which needs none of them.
#[path = "support/ci.rs"]
#[allow(dead_code)]
mod ci;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::SystemTime;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn target_dir() -> PathBuf {
    repo().join("target").join("build-tests")
}

/// `cargo ARGS` in `dir`, with the shared target directory.
fn cargo(dir: &Path, args: &[&str]) -> Output {
    let mut c = Command::new(env!("CARGO"));
    c.args(args).current_dir(dir).env("CARGO_TARGET_DIR", target_dir()).env("CARGO_TERM_COLOR", "never");
    // Line tables only, as umbrac's own dev profile gives its dependencies:
    // with full debug info the example's binary alone is ~100 MB to link.
    c.env("CARGO_PROFILE_DEV_DEBUG", "line-tables-only");
    for var in ["CARGO_BUILD_TARGET_DIR", "RUSTC_WORKSPACE_WRAPPER", "CARGO_MAKEFLAGS", "MAKEFLAGS", "MFLAGS"] {
        c.env_remove(var);
    }
    c.output().expect("run cargo")
}

fn all_output(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

fn write(path: &Path, text: &str) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
}

fn touch(path: &Path) {
    std::fs::File::options().append(true).open(path).unwrap().set_modified(SystemTime::now()).unwrap();
}

const COMMON: &str = "// included by main.das\nstruct Light {\n    dir : float3\n    intensity : float\n    color : float4\n}\n";

const MAIN: &str = r#"#include "inc/common.das"

var @uniform light : Light
var @uniform u_mvp : float4x4
var @in @location = 0 a_pos : float3
var @out f_color : float4

[vertex_program]
def vs {
    gl_Position = u_mvp * float4(a_pos, 1.0)
}

[fragment_program]
def fs {
    f_color = light.color * light.intensity
}
"#;

/// Nested structs, arrays, padded matrices, integer vectors and samplers:
/// the generated asserts hold these layouts to rustc's.
const LAYOUT: &str = r#"struct Inner {
    a : float3
    b : float
}
struct Big {
    m3 : float3x3
    v3 : float3
    s : float
    arr : float4[3]
    inner : Inner
    inners : Inner[2]
    i2 : int2
    u : uint
    m43 : float4x3
}
var @uniform big : Big
var @uniform u_type : float3x3 = float3x3(float3(1.0, 0.0, 0.0), float3(0.0, 2.0, 0.0), float3(0.0, 0.0, 3.0))
var @uniform u_inner : Inner = Inner(float3(1.0, 2.0, 3.0), 4.0)
var @uniform @stage = 2 tex : sampler2D
var @uniform itex : isampler2D
var @in @location = 0 a_pos : float3
var @in @location = 3 a_id : int
var @out f_color : float4

[vertex_program]
def vs {
    gl_Position = float4(a_pos * u_inner.a * u_inner.b + big.v3 * big.s + float3(big.i2.x) + float3(float(a_id)), 1.0) + float4(big.m3 * u_type * big.arr[1].xyz, 0.0) + float4(big.inner.a + big.inners[1].a, float(big.u)) + float4(big.m43 * float4(1.0), 0.0)
}

[fragment_program]
def fs {
    f_color = texture(tex, float2(0.5)) + float4(texelFetch(itex, int2(0), 0))
}
"#;

/// Host code written against the shader as it is at the start.
const HOST: &str = r#"#![deny(warnings)]
include!(concat!(env!("OUT_DIR"), "/umbrac/shaders.rs"));

// Stale host code must not compile: the layout is asserted here too.
const _: () = assert!(core::mem::size_of::<main::Light>() == 32);

fn main() {
    let l = main::Light::new([0.0, -1.0, 0.0], 2.0, [1.0; 4]);
    println!("intensity {} binding {} block {}", l.intensity, main::uniforms::light::BINDING, main::uniforms::light::GLSL_BLOCK);
    println!("{} {} {}", main::WGSL.len(), main::SPIRV[0], main::vs::GLSL330.len());
    println!("{} {}", layout::Big::SIZE, layout::samplers::tex::TEXTURE_UNIT);
    // Uniform defaults (`var @uniform x : T = value`) as typed constants.
    let inner = layout::uniforms::u_inner::DEFAULT;
    assert_eq!((inner.a, inner.b), ([1.0, 2.0, 3.0], 4.0));
    assert_eq!(layout::uniforms::u_type::DEFAULT.u_type[1], [0.0, 2.0, 0.0, 0.0]);
    println!("{} {}", shadow::ULightDir::SIZE, structs::WGSL.len() + textures::WGSL.len() + preprocessor::WGSL.len());
}
"#;

fn build_rs() -> String {
    let features = repo().join("shaders/features");
    let programs = repo().join("shaders/programs");
    let shadow = repo().join("shaders/shadow.das");
    format!(
        r#"fn main() {{
    // Counts the runs of this script.
    let runs = std::fs::read_to_string("runs.txt").unwrap_or_default();
    std::fs::write("runs.txt", format!("{{runs}}run\n")).unwrap();
    umbrac::build::Build::new()
        .file("shaders/main.das")
        .file("shaders/layout.das")
        .file({shadow:?})
        .dir({features:?})
        .dir({programs:?})
        .bytemuck(false)
        .run();
}}
"#
    )
}

fn runs(dir: &Path) -> usize {
    std::fs::read_to_string(dir.join("runs.txt")).unwrap_or_default().lines().count()
}

/// A user crate: umbrac as a build dependency with default features off.
fn make_user_crate(dir: &Path) {
    let manifest = format!(
        r#"[package]
name = "mini"
version = "0.1.0"
edition = "2021"
publish = false

[workspace]

[build-dependencies]
umbrac = {{ path = {:?}, default-features = false }}
"#,
        repo().display().to_string()
    );
    write(&dir.join("Cargo.toml"), &manifest);
    // The same versions as umbrac's own lock, without asking the registry.
    std::fs::copy(repo().join("Cargo.lock"), dir.join("Cargo.lock")).unwrap();
    write(&dir.join("build.rs"), &build_rs());
    write(&dir.join("src/main.rs"), HOST);
    write(&dir.join("shaders/main.das"), MAIN);
    write(&dir.join("shaders/inc/common.das"), COMMON);
    write(&dir.join("shaders/layout.das"), LAYOUT);
    write(&dir.join("shaders/unrelated.das"), "// not compiled, not included\n");
    write(&dir.join("notes.txt"), "unrelated\n");
}

#[test]
fn user_crate() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    make_user_crate(dir);

    // 1. Builds and runs, warning-free under #![deny(warnings)].
    let o = cargo(dir, &["run", "-q"]);
    assert!(o.status.success(), "first build:\n{}", all_output(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("intensity 2 binding 0 block light_block"), "{}", all_output(&o));
    assert_eq!(runs(dir), 1);

    // 2. Touching unrelated files (a shader nobody includes, a text file)
    //    neither reruns the build script nor rebuilds the crate.
    touch(&dir.join("shaders/unrelated.das"));
    touch(&dir.join("notes.txt"));
    let o = cargo(dir, &["build", "-v"]);
    assert!(o.status.success(), "{}", all_output(&o));
    assert_eq!(runs(dir), 1, "the build script reran for an unrelated file:\n{}", all_output(&o));
    assert!(all_output(&o).contains("Fresh mini"), "{}", all_output(&o));

    // 3. Touching the included file reruns it.
    touch(&dir.join("shaders/inc/common.das"));
    let o = cargo(dir, &["build", "-v"]);
    assert!(o.status.success(), "{}", all_output(&o));
    assert_eq!(runs(dir), 2, "touching an #include did not rerun the build script:\n{}", all_output(&o));

    // 4. The shader's layout changes under stale host code: the user's crate
    //    does not compile.
    write(&dir.join("shaders/inc/common.das"), &COMMON.replace("dir : float3", "dir : float4"));
    let o = cargo(dir, &["build"]);
    let out = all_output(&o);
    assert!(!o.status.success(), "a changed layout compiled against stale host code:\n{out}");
    assert!(out.contains("size_of::<main::Light>() == 32"), "{out}");

    // 5. A member renamed: the stale field access does not compile.
    write(&dir.join("shaders/inc/common.das"), &COMMON.replace("intensity", "power"));
    write(&dir.join("shaders/main.das"), &MAIN.replace("light.intensity", "light.power"));
    let o = cargo(dir, &["build"]);
    let out = all_output(&o);
    assert!(!o.status.success(), "a renamed member compiled against stale host code:\n{out}");
    assert!(out.contains("no field `intensity`"), "{out}");

    // 6. A shader error fails `cargo build` with the shader's file:line:col.
    write(&dir.join("shaders/main.das"), &MAIN.replace("light.color * light.intensity", "light.color * undefined_thing"));
    let o = cargo(dir, &["build"]);
    let out = all_output(&o);
    assert!(!o.status.success(), "{out}");
    assert!(out.contains("shaders/main.das:15:"), "no file:line:col for the shader error:\n{out}");
    assert!(out.contains("undefined_thing"), "{out}");
    assert!(out.contains("failed to compile"), "{out}");
}

#[test]
fn shadow_example() {
    let dir = repo().join("examples/shadow-build");
    let o = cargo(&dir, &["build"]);
    assert!(o.status.success(), "examples/shadow-build does not build:\n{}", all_output(&o));
    let png = tempfile::tempdir().unwrap();
    let path = png.path().join("shadow.png");
    let o = Command::new(target_dir().join("debug/shadow-build")).arg(&path).output().expect("run the example");
    if o.status.code() == Some(2) {
        // The example's exit status when it finds no Vulkan adapter.
        ci::skip(format!("the example's render: {}", all_output(&o)));
        return;
    }
    assert!(o.status.success(), "the example failed:\n{}", all_output(&o));
    let bytes = std::fs::read(&path).unwrap();
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n") && bytes.len() > 10_000, "{} bytes", bytes.len());
    // The scene is mostly lit floor on a dark background: neither blank nor white.
    let out = String::from_utf8_lossy(&o.stdout);
    let mean: u32 = out.split("mean level ").nth(1).and_then(|s| s.split(',').next()).and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("{out}"));
    assert!((30..200).contains(&mean), "mean level {mean}: {out}");
}
