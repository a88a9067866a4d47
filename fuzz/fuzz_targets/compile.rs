//! The whole compile, every target and the reflection manifest: anything
//! the front end accepts must lower, validate in naga and emit, and what
//! it emits must be accepted by a consumer. A finding is an internal
//! compiler error (naga rejecting umbrac's IR, a backend failure or a
//! caught panic), a failure without an error, or WGSL text that naga's
//! WGSL front end (what wgpu runs) refuses to parse or validate: WGSL
//! evaluates constant expressions when it reads a shader, so IR that
//! validates can still be text a consumer rejects. It is also a finding
//! when the WGSL, converted by naga to SPIR-V, disagrees with umbrac's own
//! SPIR-V or the manifest on the interface (interface.rs). The outputs of
//! the corpus and of a sample of the compiled mutants are checked by
//! glslangValidator, spirv-val and tint in `fuzz/run_campaign.sh`
//! (processes are too slow to start per input): see `keep_mutant`.
#![no_main]

use libfuzzer_sys::fuzz_target;

include!("common.rs");
mod interface;

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
            let wgsl = r.artifacts.iter().find(|a| a.target == Some(umbrac::Target::Wgsl)).expect("a WGSL output");
            let (module, info) = check_wgsl(&wgsl.text());
            differential(&module, &info, &r.artifacts);
            keep_outputs(data, &r.artifacts);
            keep_mutant(data);
        }
        None => assert!(c.diagnostics.iter().any(|d| d.is_error()), "a failed compile says why"),
    }
});

/// naga's WGSL front end, as wgpu runs it: parse, then validate with every
/// check on and the capabilities wgpu grants: f16 packing in f32 on every
/// WebGPU device (`pack2x16float`), f16 itself where the device has the
/// `shader-f16` feature a WGSL file with `enable f16;` asks for.
fn check_wgsl(wgsl: &str) -> (naga::Module, naga::valid::ModuleInfo) {
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
    match naga::valid::Validator::new(flags, caps).validate(&module) {
        Ok(info) => (module, info),
        Err(e) => panic!("the emitted WGSL does not validate after naga reads it back:\n{}\n{wgsl}", e.emit_to_string(wgsl)),
    }
}

/// The WGSL's interface, as naga reads it and as naga's SPIR-V of it reads
/// back, against umbrac's SPIR-V and the manifest. naga's SPIR-V front end
/// does not take every valid module (its own output included: some
/// capabilities and constructs are missing); where it refuses one, the
/// SPIR-V side of the comparison is left out and the WGSL is still held
/// to the manifest.
fn differential(module: &naga::Module, info: &naga::valid::ModuleInfo, artifacts: &[umbrac::Artifact]) {
    let wgsl = interface::of_module(module);
    let manifest = artifacts.iter().find(|a| a.target.is_none()).expect("a manifest");
    let manifest = interface::of_manifest(&manifest.contents).unwrap_or_else(|e| panic!("{e}"));
    if let Some(d) = interface::differences(&wgsl, "the WGSL", &manifest, "the manifest") {
        panic!("the WGSL and the manifest disagree on the interface:\n{d}");
    }
    let spv = artifacts.iter().find(|a| a.target == Some(umbrac::Target::Spirv)).expect("a SPIR-V output");
    if let (Ok(ours), Ok(theirs)) = (interface::spirv(&spv.contents), interface::wgsl_as_spirv(module, info)) {
        if let Some(d) = interface::differences(&theirs, "naga's SPIR-V of the WGSL", &ours, "umbrac's SPIR-V") {
            panic!("naga's SPIR-V of the WGSL and umbrac's SPIR-V disagree on the interface:\n{d}");
        }
    }
}

/// With `UMBRAC_FUZZ_OUT=DIR`, the outputs of each input that compiles are
/// written to `DIR/<hash of the input>/`, for `fuzz/run_campaign.sh` to run
/// glslangValidator, spirv-val and tint over (`compile -runs=0 CORPUS`).
fn keep_outputs(data: &[u8], artifacts: &[umbrac::Artifact]) {
    static OUT: std::sync::OnceLock<Option<std::path::PathBuf>> = std::sync::OnceLock::new();
    let Some(out) = OUT.get_or_init(|| std::env::var_os("UMBRAC_FUZZ_OUT").map(Into::into)) else { return };
    let dir = out.join(format!("{:016x}", fnv1a(data)));
    std::fs::create_dir_all(&dir).expect("create the output directory");
    // The input beside its outputs: a rejected output's reproducer.
    std::fs::write(dir.join("input.das.txt"), data).expect("write the input");
    for a in artifacts {
        std::fs::write(dir.join(&a.file_name), &a.contents).expect("write an output");
    }
    // The vertex/fragment pairs the manifest links, one `VS FS` a line, for
    // the script to link with glslangValidator without a JSON reader.
    let manifest = artifacts.iter().find(|a| a.target.is_none()).expect("a manifest");
    let v: serde_json::Value = serde_json::from_slice(&manifest.contents).expect("the manifest is JSON");
    let mut pairs = String::new();
    for p in v["programs"].as_array().into_iter().flatten() {
        if let (Some(vs), Some(fs)) = (p["vertex"].as_str(), p["fragment"].as_str()) {
            pairs += &format!("{vs} {fs}\n");
        }
    }
    std::fs::write(dir.join("programs.txt"), pairs).expect("write the program list");
}

/// With `UMBRAC_FUZZ_KEEP=DIR`, one compiled input in `UMBRAC_FUZZ_KEEP_EVERY`
/// (default 4, chosen by its hash, so a mutant is kept or not whatever
/// the process) is copied to `DIR/<hash>.das`: the sample of accepted
/// mutants whose outputs `fuzz/run_campaign.sh` runs through every
/// validator after the run (processes are too slow to start per input).
fn keep_mutant(data: &[u8]) {
    static KEEP: std::sync::OnceLock<Option<(std::path::PathBuf, u64)>> = std::sync::OnceLock::new();
    let Some((dir, every)) = KEEP.get_or_init(|| {
        let dir = std::env::var_os("UMBRAC_FUZZ_KEEP")?;
        let every = std::env::var("UMBRAC_FUZZ_KEEP_EVERY").ok().and_then(|v| v.parse().ok()).unwrap_or(4u64);
        Some((dir.into(), every.max(1)))
    }) else {
        return;
    };
    let hash = fnv1a(data);
    if hash % every == 0 {
        std::fs::create_dir_all(dir).expect("create the mutant directory");
        std::fs::write(dir.join(format!("{hash:016x}.das")), data).expect("keep a mutant");
    }
}

/// FNV-1a: a stable name per input, no dependency.
fn fnv1a(data: &[u8]) -> u64 {
    data.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3))
}
