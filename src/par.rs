//! Running a compilation's independent jobs side by side.
//!
//! After checking, the work splits into independent pieces: the GPU module
//! and one GL module per entry point (lowering), then one job per output
//! (emission). [`map`] runs such a list on the calling thread plus up to
//! [`threads`]` - 1` scoped helpers that take the next job as they finish
//! one, and returns the results in job order, so the outputs do not depend
//! on scheduling.
//!
//! `UMBRAC_THREADS=1` runs everything on the calling thread (the default is
//! the machine's parallelism, at most 4: a shader has few pieces).

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// How many threads a compilation may use, the calling one included.
pub fn threads() -> usize {
    let from_env = std::env::var("UMBRAC_THREADS").ok().and_then(|v| v.trim().parse::<usize>().ok());
    match from_env {
        Some(n) => n.max(1),
        None => std::thread::available_parallelism().map_or(1, |n| n.get()).min(4),
    }
}

/// `job(0)`, ..., `job(n - 1)`, spread over up to [`threads`] threads; the
/// results in index order. Put the largest jobs first: they are taken first.
pub fn map<R: Send>(n: usize, job: impl Fn(usize) -> R + Sync) -> Vec<R> {
    let helpers = threads().min(n).saturating_sub(1);
    if helpers == 0 {
        return (0..n).map(job).collect();
    }
    let next = AtomicUsize::new(0);
    let results: Vec<Mutex<Option<R>>> = (0..n).map(|_| Mutex::new(None)).collect();
    let work = || loop {
        let i = next.fetch_add(1, Ordering::Relaxed);
        if i >= n {
            break;
        }
        let r = job(i);
        *results[i].lock().unwrap_or_else(|e| e.into_inner()) = Some(r);
    };
    std::thread::scope(|s| {
        for _ in 0..helpers {
            // Same stack as the compiler thread: the writers and the
            // lowering recurse on expression depth. A helper that cannot be
            // started leaves its share to the others.
            let _ = std::thread::Builder::new().name("umbrac-job".into()).stack_size(crate::COMPILER_STACK_SIZE).spawn_scoped(s, work);
        }
        work();
    });
    // Every index below `n` was taken by exactly one thread, which stored
    // its result before the scope ended (a panic would have propagated).
    results.into_iter().map(|m| m.into_inner().unwrap_or_else(|e| e.into_inner()).expect("every job ran")).collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn results_come_back_in_job_order() {
        let out = super::map(37, |i| i * i);
        assert_eq!(out, (0..37).map(|i| i * i).collect::<Vec<_>>());
        assert!(super::map(0, |i| i).is_empty());
    }
}
