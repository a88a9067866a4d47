//! Composes the 256 variants of benches/shadow_variants_equivalent.wgsl
//! with naga_oil (shader defs), validates each module and writes WGSL and
//! SPIR-V, in process; prints the best of N rounds as JSON:
//! `{"variants":256,"rounds":N,"best_ms":...,"median_ms":...}`.
//! Usage: naga-oil-variants WGSL [ROUNDS]

use std::collections::HashMap;
use std::time::Instant;

use naga_oil::compose::{Composer, NagaModuleDescriptor, ShaderDefValue, ShaderType};

const AXES: [&str; 8] = ["PCF", "SLOPE_BIAS", "BORDER_FADE", "SPECULAR", "RIM", "FOG", "TONEMAP", "GAMMA"];

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("usage: naga-oil-variants WGSL [ROUNDS]");
    let rounds: usize = args.next().map_or(5, |r| r.parse().expect("ROUNDS"));
    let source = std::fs::read_to_string(&path).expect("read the WGSL");
    let mut times = Vec::new();
    let mut bytes = 0usize;
    for _ in 0..rounds {
        let start = Instant::now();
        bytes = 0;
        for bits in 0..256u32 {
            let shader_defs: HashMap<String, ShaderDefValue> =
                AXES.iter().enumerate().filter(|(i, _)| bits & (1 << i) != 0).map(|(_, a)| (a.to_string(), ShaderDefValue::Bool(true))).collect();
            let mut composer = Composer::default();
            let module = composer
                .make_naga_module(NagaModuleDescriptor { source: &source, file_path: &path, shader_type: ShaderType::Wgsl, shader_defs, additional_imports: &[] })
                .unwrap_or_else(|e| panic!("variant {bits:08b}: {}", e.emit_to_string(&composer)));
            let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default()).validate(&module).expect("valid");
            let wgsl = naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty()).expect("wgsl");
            let spv = naga::back::spv::write_vec(&module, &info, &naga::back::spv::Options::default(), None).expect("spv");
            bytes += wgsl.len() + spv.len() * 4;
        }
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let best = times.iter().cloned().fold(f64::INFINITY, f64::min);
    times.sort_by(f64::total_cmp);
    println!("{{\"variants\":256,\"rounds\":{rounds},\"best_ms\":{best:.2},\"median_ms\":{:.2},\"output_bytes\":{bytes}}}", times[times.len() / 2]);
}
