//! The native side of web/playground/bench.mjs: the same compiles, timed
//! the same way (the median process CPU time of 200 runs after 30 to warm
//! up), in this crate's release profile on the host, so that the ratio of
//! WebAssembly to native is taken on one machine under one load:
//!
//!   cargo run --release --example native_bench --target-dir target -- FILE.das...
//!
//! (from web/playground/wasm; docs/performance.md, "The compiler in WebAssembly").

const WARM: usize = 30;
const RUNS: usize = 200;

fn cpu_us() -> u64 {
    let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: clock_gettime writes the timespec it is given.
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    t.tv_sec as u64 * 1_000_000 + t.tv_nsec as u64 / 1000
}

fn median(mut f: impl FnMut()) -> u64 {
    for _ in 0..WARM {
        f();
    }
    let mut t: Vec<u64> = (0..RUNS)
        .map(|_| {
            let s = cpu_us();
            f();
            cpu_us() - s
        })
        .collect();
    t.sort_unstable();
    t[t.len() / 2]
}

fn main() {
    println!("| file | compile_only (us, CPU) | compile + bundle JSON (us, CPU) |\n|---|---|---|");
    for file in std::env::args().skip(1) {
        let src = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{file}: {e}"));
        let name = std::path::Path::new(&file).file_name().unwrap().to_string_lossy().into_owned();
        assert!(umbrac_web::compile_only(&name, &src), "{file} does not compile");
        let only = median(|| {
            std::hint::black_box(umbrac_web::compile_only(&name, &src));
        });
        let whole = median(|| {
            std::hint::black_box(umbrac_web::compile(&name, &src, "{}"));
        });
        println!("| {file} | {only} | {whole} |");
    }
}
