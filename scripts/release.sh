#!/usr/bin/env bash
# A reproducible release build of the `umbrac` compiler (no renderer: what
# a build system runs as a tool): the same commit and toolchain give the
# same bytes at any checkout path and on any machine (docs/scale.md,
# "Beyond one machine"). Cargo names umbrac's own sources by relative
# paths; a dependency's are under $CARGO_HOME/registry/src, which differs
# between machines: it is written as /cargo instead. The flag does not name
# the checkout, so two checkouts sharing one target directory share every
# dependency's build. Prints the binary's path.
#
#     bash scripts/release.sh [EXTRA CARGO ARGS]
set -euo pipefail
cd "$(dirname "$0")/.."
cargo_home="${CARGO_HOME:-$HOME/.cargo}"
export RUSTFLAGS="${RUSTFLAGS:-} --remap-path-prefix=$cargo_home=/cargo"
export CARGO_INCREMENTAL=0
cargo build --release --locked --quiet --no-default-features --features cli --bin umbrac "$@"
echo "${CARGO_TARGET_DIR:-target}/release/umbrac"
