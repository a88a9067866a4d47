//! The whole compile, every target and the reflection manifest: anything
//! the front end accepts must lower, validate in naga and emit, and what
//! it emits must be accepted by a consumer. A finding is an internal
//! compiler error (naga rejecting umbrac's IR, a backend failure or a
//! caught panic), a failure without an error, or WGSL text that naga's
//! WGSL front end (what wgpu runs) refuses to parse or validate: WGSL
//! evaluates constant expressions when it reads a shader, so IR that
//! validates can still be text a consumer rejects. The GLSL and SPIR-V
//! outputs of the corpus are checked by glslangValidator and spirv-val in
//! `fuzz/run_campaign.sh` (processes are too slow to start per input).
#![no_main]

use libfuzzer_sys::fuzz_target;

include!("common.rs");

fuzz_target!(|data: &[u8]| {
    let text = source_of(data);
    let opts = umbrac::Options { defines: parse_options().defines, ..Default::default() };
    let c = umbrac::compile_source(ROOT, &text, &opts);
    render_all(&c.diagnostics, &c.sources);
    if let Some(bug) = c.diagnostics.iter().find(|d| d.severity == umbrac::Severity::Bug) {
        panic!("internal compiler error:\n{}", bug.render(&c.sources));
    }
    match &c.result {
        Some(r) => {
            assert!(!c.has_errors());
            assert!(r.artifacts.len() >= 4, "every target was emitted");
            for a in r.artifacts.iter().filter(|a| a.target == Some(umbrac::Target::Wgsl)) {
                check_wgsl(&a.text());
            }
            keep_outputs(data, &r.artifacts);
        }
        None => assert!(c.diagnostics.iter().any(|d| d.is_error()), "a failed compile says why"),
    }
});

/// naga's WGSL front end, as wgpu runs it: parse, then validate with every
/// check on and the capabilities wgpu grants: f16 packing in f32 on every
/// WebGPU device (`pack2x16float`), f16 itself where the device has the
/// `shader-f16` feature a WGSL file with `enable f16;` asks for.
fn check_wgsl(wgsl: &str) {
    use naga::valid::Capabilities;
    let mut caps = Capabilities::default() | Capabilities::SHADER_FLOAT16_IN_FLOAT32;
    if wgsl.contains("enable f16;") {
        caps |= Capabilities::SHADER_FLOAT16;
    }
    let module = match naga::front::wgsl::parse_str(wgsl) {
        Ok(m) => m,
        Err(e) => panic!("naga's WGSL front end rejects the emitted WGSL:\n{}\n{wgsl}", e.emit_to_string(wgsl)),
    };
    let flags = naga::valid::ValidationFlags::all();
    if let Err(e) = naga::valid::Validator::new(flags, caps).validate(&module) {
        panic!("the emitted WGSL does not validate after naga reads it back:\n{}\n{wgsl}", e.emit_to_string(wgsl));
    }
}

/// With `UMBRAC_FUZZ_OUT=DIR`, the outputs of each input that compiles are
/// written to `DIR/<hash of the input>/`, for `fuzz/run_campaign.sh` to run
/// glslangValidator and spirv-val over (`compile -runs=0 CORPUS`).
fn keep_outputs(data: &[u8], artifacts: &[umbrac::Artifact]) {
    static OUT: std::sync::OnceLock<Option<std::path::PathBuf>> = std::sync::OnceLock::new();
    let Some(out) = OUT.get_or_init(|| std::env::var_os("UMBRAC_FUZZ_OUT").map(Into::into)) else { return };
    // FNV-1a: a stable name per input, no dependency.
    let hash = data.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3));
    let dir = out.join(format!("{hash:016x}"));
    std::fs::create_dir_all(&dir).expect("create the output directory");
    for a in artifacts {
        std::fs::write(dir.join(&a.file_name), &a.contents).expect("write an output");
    }
}
