#!/usr/bin/env bash
# Compile speed of this checkout against an older commit, in one run
# (docs/performance.md, "Ninth sitting"):
#
#   bash benches/regression.sh [BASE_REV [PROGRAM]]   # default 8dfc985 (before issue 17),
#                                                    # shaders/shadow.das
#
# Builds benches/regression/harness.rs twice in release, against this
# checkout and against BASE_REV (exported with `git archive` under
# target/regression/, no worktree registered), then for each stage prefix
# (syntax, check, front, all: see the harness) reports
#
# - instructions per compile under callgrind, (N = 11 minus N = 1) / 10,
#   which the machine's load does not change (needs valgrind);
# - CPU time per compile, the two binaries alternating ROUNDS times
#   (default 7), medians and the median of the rounds' ratios.
#
# Environment: ROUNDS, MODES (default "syntax check front all"), SKIP_TIME=1
# (instructions only), SKIP_INSTR=1 (time only).
set -euo pipefail
cd "$(dirname "$0")/.."
base_rev="${1:-8dfc985}"
program="$(realpath "${2:-shaders/shadow.das}")"
head="$(pwd)"
dir="$head/target/regression"
rounds="${ROUNDS:-7}"
base_id="$(git rev-parse --short "$base_rev^{commit}")"
base_src="$dir/src-$base_id"
mkdir -p "$dir"
if [ ! -f "$base_src/Cargo.toml" ]; then
    rm -rf "$base_src.tmp" && mkdir -p "$base_src.tmp"
    git archive --format=tar "$base_id" | tar -x -C "$base_src.tmp"
    mv "$base_src.tmp" "$base_src"
fi

# One harness crate per side; one target directory, so naga and the other
# dependencies are built once.
for side in base head; do
    src=$([ "$side" = base ] && echo "$base_src" || echo "$head")
    crate="$dir/harness-$side"
    mkdir -p "$crate/src"
    cp benches/regression/harness.rs "$crate/src/main.rs"
    cp "$src/Cargo.lock" "$crate/Cargo.lock"
    cat > "$crate/Cargo.toml" <<TOML
[package]
name = "harness-$side"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
umbrac = { path = "$src", default-features = false }
libc = "0.2"

[workspace]
TOML
    echo "building the $side harness ($([ "$side" = base ] && echo "$base_id" || git rev-parse --short HEAD)$([ "$side" = head ] && ! git diff --quiet HEAD -- src Cargo.toml && echo ", with uncommitted changes" || true))" >&2
    CARGO_TARGET_DIR="$dir/target" cargo build --quiet --release --manifest-path "$crate/Cargo.toml"
done
bin_base="$dir/target/release/harness-base"
bin_head="$dir/target/release/harness-head"
modes="${MODES:-syntax check front all}"

echo "program: ${program#$head/}, base $base_id, head $(git rev-parse --short HEAD)"
if [ -z "${SKIP_INSTR:-}" ]; then
    command -v valgrind >/dev/null || { echo "valgrind is not installed: apt-get install valgrind" >&2; exit 1; }
    instr() { # BIN MODE N -> instructions of the whole run
        valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" "$2" "$3" "$program" 2>&1 >/dev/null |
            sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
    }
    echo
    echo "| instructions per compile | $base_id | head | head / base |"
    echo "|---|---|---|---|"
    for m in $modes; do
        b=$(( ($(instr "$bin_base" $m 11) - $(instr "$bin_base" $m 1)) / 10 ))
        h=$(( ($(instr "$bin_head" $m 11) - $(instr "$bin_head" $m 1)) / 10 ))
        awk -v m="$m" -v b="$b" -v h="$h" 'BEGIN { printf "| %s | %.3f M | %.3f M | %.3fx |\n", m, b / 1e6, h / 1e6, h / b }'
    done
fi
if [ -z "${SKIP_TIME:-}" ]; then
    echo
    echo "| CPU time per compile ($rounds rounds, alternating) | $base_id median | head median | ratio of medians | median of the rounds' ratios |"
    echo "|---|---|---|---|---|"
    for m in $modes; do
        case $m in syntax|check) n=3000 ;; front) n=1500 ;; all) n=500 ;; esac
        for _ in $(seq "$rounds"); do
            b=$("$bin_base" $m $n "$program")
            h=$("$bin_head" $m $n "$program")
            echo "$b $h"
        done | python3 -c '
import statistics, sys
rows = [tuple(map(float, l.split())) for l in sys.stdin]
b = statistics.median(r[0] for r in rows)
h = statistics.median(r[1] for r in rows)
q = statistics.median(r[1] / r[0] for r in rows)
print(f"| {sys.argv[1]} | {b:.1f} us | {h:.1f} us | {h / b:.3f}x | {q:.3f}x |")' "$m"
    done
    echo
    echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
fi
