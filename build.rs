//! umbrac's own build script: a build id for the compile cache
//! (src/cache.rs). A cached output is only as good as the compiler that
//! made it, and the crate version does not change while the compiler is
//! being worked on, so the id is a hash of the compiler's sources and of
//! the naga release it is built with. std only: this runs in every build
//! that depends on umbrac.

use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};

fn main() {
    let root = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    collect(&root.join("src"), &mut files);
    files.sort();
    // SipHash with fixed keys: the same sources give the same id on every
    // machine built with the same toolchain.
    let mut h = std::collections::hash_map::DefaultHasher::new();
    std::env::var("CARGO_PKG_VERSION").unwrap_or_default().hash(&mut h);
    for f in &files {
        f.strip_prefix(&root).unwrap_or(f).to_string_lossy().replace('\\', "/").hash(&mut h);
        std::fs::read(f).unwrap_or_default().hash(&mut h);
    }
    naga_lock_entries().hash(&mut h);
    println!("cargo:rustc-env=UMBRAC_BUILD_ID={:016x}", h.finish());
    // The `umbrac` executable is linked at a fixed address on x86-64 GNU/Linux
    // (`-no-pie`): a position-independent one had 18,000 relocations for
    // the dynamic loader to apply at every start, a sixth of a cache hit's
    // instructions (docs/performance.md, "Whole process"). Only this
    // package's binaries: a crate that builds with umbrac links as it did.
    let var = |n: &str| std::env::var(n).unwrap_or_default();
    if var("CARGO_CFG_TARGET_ARCH") == "x86_64" && var("CARGO_CFG_TARGET_OS") == "linux" && var("CARGO_CFG_TARGET_ENV") == "gnu" {
        println!("cargo:rustc-link-arg-bins=-no-pie");
    }
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=Cargo.toml");
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The `naga` packages of the Cargo.lock of the build (found above OUT_DIR
/// or the manifest), so that a naga update changes the id. Empty when no
/// lock file is found: the id then follows umbrac's sources alone.
fn naga_lock_entries() -> String {
    let starts = ["OUT_DIR", "CARGO_MANIFEST_DIR"].map(|v| std::env::var_os(v).map(PathBuf::from));
    for start in starts.into_iter().flatten() {
        for dir in start.ancestors() {
            let lock = dir.join("Cargo.lock");
            if let Ok(text) = std::fs::read_to_string(&lock) {
                println!("cargo:rerun-if-changed={}", lock.display());
                return text.split("[[package]]").filter(|p| p.contains("name = \"naga\"")).collect();
            }
        }
    }
    String::new()
}
