//! The compile loop that `benches/regression.sh` builds twice, once against
//! this checkout and once against an older one, to compare them in one run
//! (docs/performance.md, "Ninth sitting").
//!
//!     harness MODE N PROGRAM
//!
//! compiles PROGRAM (read once) N times and
//! prints the process CPU time per compile in microseconds. Modes, each a
//! prefix of the next:
//!
//! - `syntax`: preprocess and parse (`syntax::parse`);
//! - `check`: and check (`sema::check`);
//! - `front`: and lower and validate the GPU module (`lower::lower_gpu`):
//!   what `benches/compile.rs` times as `front_end`;
//! - `all`: `compile_source` to every output: `all_targets`.
//!
//! Only API that both sides of a comparison have is used: the stage
//! functions have had these signatures since before issue 17.

use std::hint::black_box;

fn parse(text: &str) -> umbrac::syntax::ast::Program {
    let mut sources = umbrac::SourceMap::new();
    let root = sources.add("program.das", None, text.to_string(), None);
    let mut diags = umbrac::Diagnostics::new();
    let program = umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
    assert!(!diags.has_errors(), "the program does not parse");
    program
}

fn check(text: &str) -> umbrac::sema::Program {
    let program = parse(text);
    let mut diags = umbrac::Diagnostics::new();
    let checked = umbrac::sema::check(&program, &mut diags);
    assert!(!diags.has_errors(), "the program does not check");
    checked.expect("checks")
}

/// CPU time of the whole process so far (every thread), in microseconds.
fn cpu_us() -> f64 {
    let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `t` is a valid timespec to write to.
    let r = unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    assert_eq!(r, 0);
    t.tv_sec as f64 * 1e6 + t.tv_nsec as f64 / 1e3
}

fn main() {
    let mut args = std::env::args().skip(1);
    let usage = "usage: harness syntax|check|front|all N PROGRAM";
    let mode = args.next().expect(usage);
    let n: u32 = args.next().expect(usage).parse().expect(usage);
    let path = args.next().expect(usage);
    let text = std::fs::read_to_string(&path).expect("reads the program");
    let one: Box<dyn Fn()> = match mode.as_str() {
        "syntax" => Box::new(|| drop(black_box(parse(black_box(&text))))),
        "check" => Box::new(|| drop(black_box(check(black_box(&text))))),
        "front" => Box::new(|| {
            let lowered = umbrac::lower::lower_gpu(&check(black_box(&text)), umbrac::Conventions::Portable);
            drop(black_box(lowered.expect("lowers")));
        }),
        "all" => Box::new(|| {
            let c = umbrac::compile_source("program.das", black_box(&text), &Default::default());
            assert!(!c.has_errors());
            drop(black_box(c));
        }),
        _ => panic!("{usage}"),
    };
    let start = cpu_us();
    for _ in 0..n {
        one();
    }
    println!("{:.2}", (cpu_us() - start) / n.max(1) as f64);
}
