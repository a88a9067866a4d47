#!/usr/bin/env bash
# What umbrac costs as a build dependency, compared with naga alone
# (docs/build.md, "Cost as a build dependency").
#
#   bash benches/build_cost.sh [ROUNDS [OTHER_CHECKOUT...]]    # default 3 rounds
#
# Two tiny crates are made in a temporary directory (BUILD_COST_DIR to pick
# one; it is kept then), each with a one-line build.rs and one build
# dependency:
#   m-naga:   naga = { version = "30.0.1", features = ["glsl-out", "wgsl-out", "spv-out"] }
#   m-umbrac: umbrac = { path = <this repo>, default-features = false }
# plus one m-umbrac-N per OTHER_CHECKOUT (another umbrac source tree, e.g.
# an older commit from `git worktree add`), to compare versions under the
# same load. Every crate gets this repo's Cargo.lock, so they resolve to
# the same versions (where a crate is in both). Each round builds every
# crate cold (`rm -rf` of the crate's own target dir, then `cargo build`,
# default dev profile), one after the other, so that changes in the
# machine's load hit all of them alike. Prints each round's wall-clock
# seconds and CPU seconds (user + system: what the build costs the machine,
# and much less sensitive than wall time to other processes' load), the
# medians and the ratios to naga (of the medians, and the median of the
# rounds' ratios), with the load average.
# Timing is done by hyperfine when it is installed (one run per build, so
# the rounds stay interleaved), by bash's `time` otherwise.
#
# Environment: JOBS (cargo -j, default: cargo's own), TIMINGS=1 (after the
# rounds, one `cargo build --timings` of each crate; prints where the HTML
# reports are, and keeps the temporary directory).
set -euo pipefail

ROUNDS=${1:-3}
shift || true
REPO=$(cd "$(dirname "$0")/.." && pwd)
if [ -n "${BUILD_COST_DIR:-}" ]; then
    WORK=$BUILD_COST_DIR
    mkdir -p "$WORK"
else
    WORK=$(mktemp -d)
    [ "${TIMINGS:-0}" = 1 ] || trap 'rm -rf "$WORK"' EXIT
fi

make_crate() { # name, dependency line, build.rs
    local dir=$WORK/$1
    mkdir -p "$dir/src"
    cat >"$dir/Cargo.toml" <<EOF
[package]
name = "$1"
version = "0.1.0"
edition = "2021"
publish = false

[build-dependencies]
$2

[workspace]
EOF
    echo "$3" >"$dir/build.rs"
    echo 'fn main() {}' >"$dir/src/main.rs"
    cp "$REPO/Cargo.lock" "$dir/Cargo.lock"
}

describe() { # a checkout: its path and commit
    local rev
    if rev=$(git -C "$1" rev-parse --short HEAD 2>/dev/null); then
        git -C "$1" diff --quiet HEAD 2>/dev/null || rev="$rev, modified"
    else
        rev="not a git checkout"
    fi
    echo "$1 ($rev)"
}

# Each build script uses its dependency the way a real one would, so that
# it is linked as well as compiled: naga validates a module and writes
# WGSL; umbrac runs `umbrac::build` (which finds no shader files at run
# time; `compile` returns that error instead of failing the build).
UMBRAC_BUILD_RS='fn main() { let _ = umbrac::build::Build::new().compile(); }'
make_crate m-naga 'naga = { version = "30.0.1", features = ["glsl-out", "wgsl-out", "spv-out"] }' \
    'fn main() { let m = naga::Module::default(); let i = naga::valid::Validator::new(Default::default(), Default::default()).validate(&m).unwrap(); let _ = naga::back::wgsl::write_string(&m, &i, naga::back::wgsl::WriterFlags::empty()); }'
CRATES=(m-naga m-umbrac)
make_crate m-umbrac "umbrac = { path = \"$REPO\", default-features = false }" "$UMBRAC_BUILD_RS"
echo "m-umbrac:   $(describe "$REPO")"
n=2
for other in "$@"; do
    other=$(cd "$other" && pwd)
    make_crate "m-umbrac-$n" "umbrac = { path = \"$other\", default-features = false }" "$UMBRAC_BUILD_RS"
    echo "m-umbrac-$n: $(describe "$other")"
    CRATES+=("m-umbrac-$n")
    n=$((n + 1))
done

CARGO_FLAGS=()
[ -n "${JOBS:-}" ] && CARGO_FLAGS+=(-j "$JOBS")
# Offline when every crate is already in the local registry cache.
offline=1
for c in "${CRATES[@]}"; do
    (cd "$WORK/$c" && cargo fetch --offline -q 2>/dev/null) || offline=0
done
if [ $offline = 1 ]; then
    CARGO_FLAGS+=(--offline)
else
    for c in "${CRATES[@]}"; do (cd "$WORK/$c" && cargo fetch -q); done
fi

HYPERFINE=${HYPERFINE-$(command -v hyperfine || true)} # HYPERFINE= to time with bash

# Builds crate $1 cold; prints the wall-clock seconds it took and the CPU
# seconds (user + system, cargo and every rustc) it used.
cold_build() {
    local dir=$WORK/$1 target=$WORK/$1/target
    local cmd="cd '$dir' && CARGO_TARGET_DIR='$target' cargo build -q ${CARGO_FLAGS[*]}"
    if [ -n "$HYPERFINE" ]; then
        local json=$WORK/$1.hyperfine.json
        "$HYPERFINE" --runs 1 --prepare "rm -rf '$target'" --export-json "$json" --style none "$cmd" >/dev/null 2>&1 \
            || { echo "cargo build of $1 failed:" >&2; bash -c "$cmd" >&2; exit 1; }
        python3 -c 'import json,sys; r = json.load(open(sys.argv[1]))["results"][0]; print("%.1f %.1f" % (r["times"][0], r["user"] + r["system"]))' "$json"
    else
        rm -rf "$target"
        local TIMEFORMAT='%R %U %S' t
        t=$( { time bash -c "$cmd" >/dev/null 2>&1; } 2>&1 ) || { echo "cargo build of $1 failed" >&2; bash -c "$cmd" >&2; exit 1; }
        echo "$t" | awk '{ printf "%.1f %.1f\n", $1, $2 + $3 }'
    fi
}

median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.2f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b / a }'; }
load() { uptime | sed 's/.*load average: //'; }

echo "rustc: $(rustc --version), cargo flags: ${CARGO_FLAGS[*]:-(none)}, timer: ${HYPERFINE:-date}, $(nproc) cores"
echo "load before: $(load)"
header=$(printf '%-6s %13s' round "naga (cpu)")
for c in "${CRATES[@]:1}"; do header+=$(printf ' %15s %5s %5s' "${c#m-} (cpu)" ratio cpu); done
echo "$header   load (1, 5, 15 min)"
declare -A wall cpu ratios cpu_ratios
for r in $(seq 1 "$ROUNDS"); do
    line=$(printf '%-6s' "$r")
    for c in "${CRATES[@]}"; do
        read -r w u < <(cold_build "$c")
        wall[$c]+="$w " cpu[$c]+="$u "
        if [ "$c" = m-naga ]; then
            nw=$w nu=$u
            line+=$(printf ' %6ss (%4s)' "$w" "$u")
        else
            ratios[$c]+="$(ratio "$nw" "$w") " cpu_ratios[$c]+="$(ratio "$nu" "$u") "
            line+=$(printf ' %8ss (%4s) %5s %5s' "$w" "$u" "$(ratio "$nw" "$w")" "$(ratio "$nu" "$u")")
        fi
    done
    echo "$line   $(load)"
done
med() { printf '%s\n' $1 | median; }
nw=$(med "${wall[m-naga]}") nu=$(med "${cpu[m-naga]}")
line=$(printf '%-6s %6ss (%4s)' median "$nw" "$nu")
for c in "${CRATES[@]:1}"; do
    w=$(med "${wall[$c]}") u=$(med "${cpu[$c]}")
    line+=$(printf ' %8ss (%4s) %5s %5s' "$w" "$u" "$(ratio "$nw" "$w")" "$(ratio "$nu" "$u")")
done
echo "$line   ratios of the medians"
line=$(printf '%-6s %13s' "" "")
for c in "${CRATES[@]:1}"; do line+=$(printf ' %15s %5s %5s' "" "$(med "${ratios[$c]}")" "$(med "${cpu_ratios[$c]}")"); done
echo "$line   medians of the rounds' ratios"
echo "load after: $(load)"

if [ "${TIMINGS:-0}" = 1 ]; then
    for c in "${CRATES[@]}"; do
        rm -rf "$WORK/$c/target"
        (cd "$WORK/$c" && CARGO_TARGET_DIR="$WORK/$c/target" cargo build -q --timings "${CARGO_FLAGS[@]}")
        echo "timings of $c: $WORK/$c/target/cargo-timings/cargo-timing.html"
    done
fi
