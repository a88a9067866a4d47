//! Compile-speed benchmarks (criterion): `cargo bench --bench compile`.
//!
//! - `front_end`: umbrac's front end (shaders/shadow.das -> one validated
//!   naga module, the whole program's) beside naga's WGSL front end (parse +
//!   validate) on the equivalent WGSL program, benches/shadow_equivalent.wgsl,
//!   in the same run; and umbrac to every module it emits from (the GPU
//!   module and one GL module per entry point);
//! - `all_targets`: shaders/shadow.das to every output (GLSL 330 and ES 3.00
//!   per entry point, WGSL, SPIR-V, reflection), beside naga's parse +
//!   validate again;
//! - `all_targets_wall`: the same two in wall-clock time;
//! - `stages`: each stage of umbrac alone, to see where the time goes.
//!
//! Times are CPU time of the whole process (every thread summed: a
//! compilation runs on its own large-stack thread), except in
//! `all_targets_wall`: on a shared machine, wall time counts other
//! processes' turns on the cores too.
//!
//! docs/performance.md has the results and the ratios.

#[path = "support/mod.rs"]
mod support;

use criterion::{criterion_group, criterion_main, Criterion};

type C = Criterion<CpuTime>;
use std::hint::black_box;
use support::*;

fn front_end(c: &mut C) {
    let mut g = c.benchmark_group("front_end");
    g.bench_function("umbrac_das_to_validated_module", |b| b.iter(|| umbrac_front_end(black_box(SHADOW_DAS))));
    g.bench_function("naga_wgsl_parse_validate", |b| b.iter(|| naga_front_end(black_box(SHADOW_WGSL))));
    g.bench_function("umbrac_das_to_all_modules", |b| b.iter(|| umbrac_all_modules(black_box(SHADOW_DAS))));
    g.finish();
}

fn all_targets(c: &mut C) {
    let mut g = c.benchmark_group("all_targets");
    g.bench_function("umbrac_shadow_all_outputs", |b| b.iter(|| umbrac_all_targets(black_box(SHADOW_DAS))));
    g.bench_function("naga_wgsl_parse_validate", |b| b.iter(|| naga_front_end(black_box(SHADOW_WGSL))));
    g.finish();
}

fn all_targets_wall(c: &mut Criterion) {
    let mut g = c.benchmark_group("all_targets_wall");
    g.bench_function("umbrac_shadow_all_outputs", |b| b.iter(|| umbrac_all_targets(black_box(SHADOW_DAS))));
    g.bench_function("naga_wgsl_parse_validate", |b| b.iter(|| naga_front_end(black_box(SHADOW_WGSL))));
    g.finish();
}

fn stages(c: &mut C) {
    let mut g = c.benchmark_group("stages");
    g.bench_function("syntax", |b| {
        b.iter(|| {
            let mut sources = umbrac::SourceMap::new();
            let root = sources.add("shadow.das", None, SHADOW_DAS.to_string(), None);
            let mut diags = umbrac::Diagnostics::new();
            umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags)
        })
    });
    let mut sources = umbrac::SourceMap::new();
    let root = sources.add("shadow.das", None, SHADOW_DAS.to_string(), None);
    let mut diags = umbrac::Diagnostics::new();
    let program = umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
    g.bench_function("sema", |b| b.iter(|| umbrac::sema::check(black_box(&program), &mut umbrac::Diagnostics::new())));
    let checked = umbrac::sema::check(&program, &mut diags).unwrap();
    g.bench_function("lower_gpu_and_validate", |b| {
        b.iter(|| umbrac::lower::lower_gpu(black_box(&checked), umbrac::Conventions::Portable).unwrap())
    });
    g.bench_function("lower_and_validate", |b| {
        b.iter(|| umbrac::lower::lower(black_box(&checked), umbrac::Conventions::Portable).unwrap())
    });
    let lowered = umbrac::lower::lower(&checked, umbrac::Conventions::Portable).unwrap();
    g.bench_function("emit_all", |b| b.iter(|| umbrac::emit::emit(black_box(&lowered), "shadow", "shadow.das", &[]).unwrap()));
    let validator = || naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default());
    g.bench_function("validate_umbrac_gpu_module", |b| b.iter(|| validator().validate(black_box(&lowered.gpu)).unwrap()));
    g.bench_function("naga_wgsl_parse_only", |b| b.iter(|| naga::front::wgsl::parse_str(black_box(SHADOW_WGSL)).unwrap()));
    let wgsl_module = naga::front::wgsl::parse_str(SHADOW_WGSL).unwrap();
    g.bench_function("naga_validate_only", |b| b.iter(|| validator().validate(black_box(&wgsl_module)).unwrap()));
    g.finish();
}

criterion_group! {
    name = benches;
    // Process CPU time, not wall time: the machine's cores are shared.
    config = Criterion::default().with_measurement(CpuTime::PROCESS)
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(3))
        .sample_size(50);
    targets = front_end, all_targets, stages
}
criterion_group! {
    name = wall;
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(3))
        .sample_size(50);
    targets = all_targets_wall
}
criterion_main!(benches, wall);
