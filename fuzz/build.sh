#!/bin/sh
# Builds the fuzz targets on a stable toolchain, without cargo-fuzz: the
# flags cargo-fuzz passes for `--sanitizer none` are stable rustc options
# (SanitizerCoverage through LLVM: inline 8-bit counters, PC table,
# comparison tracing), and libfuzzer-sys compiles libFuzzer itself with
# the system C++ compiler. Debug assertions and overflow checks are on, so
# an arithmetic overflow in umbrac is a finding too.
#
# Usage: fuzz/build.sh [TARGET...]     (default: compile parse preprocess)
# Binaries: fuzz/target/<host triple>/release/<target> (its last line of output)
set -eu
cd "$(dirname "$0")"
host=$(rustc -vV | sed -n 's/^host: //p')
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
# An explicit --target keeps RUSTFLAGS off build scripts and proc macros.
bins=""
for t in "$@"; do bins="$bins --bin $t"; done
[ $# -gt 0 ] || bins="--bin compile --bin parse --bin preprocess"
cargo build --release --locked --target "$host" $bins
echo "${CARGO_TARGET_DIR:-$(pwd)/target}/$host/release"
