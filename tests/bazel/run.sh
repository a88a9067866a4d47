#!/usr/bin/env bash
# umbrac as a Bazel action with a shared remote cache (issue 41;
# docs/scale.md, "Beyond one machine"):
#
# 1. BuildGrid serves a CAS and an action cache on loopback.
# 2. Workspace A (a copy of shaders/ and bazel/ at one path, its own output
#    base) builds bazel/example's //:all sandboxed, cold, into the cache.
# 3. Workspace B (another path, another output base) builds the same
#    targets: every umbrac action must be a remote cache hit, and every
#    output byte-identical to A's.
# 4. The same with --disk_cache (workspaces C and D).
# 5. A target that leaves out a declared include fails in the sandbox.
# 6. umbrac's own --cache on the same programs, cold and warm, for the
#    side-by-side figures.
#
# Needs bazel (Debian: bazel-bootstrap) and BuildGrid's `bgd` (PyPI:
# buildgrid; $BGD, else `bgd` on PATH, else target/bgvenv/bin/bgd). Missing:
# skipped, or failed with CI=true. The umbrac binary is $UMBRAC, else
# target/debug/umbrac (built if missing).
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$PWD

missing() {
    if [ "${CI:-}" = true ]; then echo "FAIL: $1" >&2; exit 1; fi
    echo "skipped: $1" >&2; exit 0
}
command -v bazel >/dev/null 2>&1 || missing "bazel is not installed (apt-get install bazel-bootstrap)"
bgd="${BGD:-$(command -v bgd || echo "$repo/target/bgvenv/bin/bgd")}"
[ -x "$bgd" ] || missing "BuildGrid's bgd is not installed (pip install buildgrid)"
umbrac="${UMBRAC:-$repo/target/debug/umbrac}"
[ -x "$umbrac" ] || cargo build --quiet --bin umbrac

tmp=$(mktemp -d)
bgd_pid=
cleanup() {
    # What went wrong stays readable: Bazel's warnings, and the actions that
    # ran rather than came from a cache.
    if [ -n "${failed:-}" ]; then
        grep -h 'WARNING' "$tmp"/*.log >&2 || true
        for f in "$tmp"/b.exec.json "$tmp"/d.exec.json; do
            [ -f "$f" ] && python3 - "$f" >&2 <<'PY' || true
import json, sys
text = open(sys.argv[1]).read()
dec, i = json.JSONDecoder(), 0
while i < len(text):
    while i < len(text) and text[i].isspace():
        i += 1
    if i >= len(text):
        break
    o, i = dec.raw_decode(text, i)
    if not o.get("remoteCacheHit") and o.get("mnemonic", "").startswith("Umbrac"):
        print(sys.argv[1], "ran:", o.get("progressMessage"), o.get("actualOutputs", [{}])[0].get("path"))
PY
        done
    fi
    [ -n "$bgd_pid" ] && kill "$bgd_pid" 2>/dev/null || true
    for ws in "$tmp"/ws-*; do
        [ -d "$ws/bazel/example" ] && (cd "$ws/bazel/example" && bazel --output_user_root="$tmp/root-${ws##*-}" shutdown) >/dev/null 2>&1 || true
    done
    rm -rf "$tmp"
}
failed=1
trap cleanup EXIT

# A free loopback port, then BuildGrid on it.
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
sed "s/PORT/$port/" tests/bazel/buildgrid.yml > "$tmp/buildgrid.yml"
"$bgd" server start "$tmp/buildgrid.yml" > "$tmp/bgd.log" 2>&1 &
bgd_pid=$!
for _ in $(seq 100); do
    python3 -c "import socket; socket.create_connection(('127.0.0.1', $port), 1)" 2>/dev/null && break
    kill -0 "$bgd_pid" 2>/dev/null || { cat "$tmp/bgd.log" >&2; echo "FAIL: bgd did not start" >&2; exit 1; }
    sleep 0.2
done

# A workspace: the repository's shaders/ and bazel/ copied under a path
# of its own, the same umbrac binary as its tool.
workspace() {
    local ws="$tmp/ws-$1"
    mkdir -p "$ws"
    cp -r shaders bazel "$ws/"
    mkdir -p "$ws/bazel/example/tool"
    cp "$umbrac" "$ws/bazel/example/tool/umbrac"
    echo "$ws/bazel/example"
}

# Builds //:all in workspace $1 with flags; prints the seconds taken and
# leaves Bazel's summary in $tmp/$1.log.
build() {
    local name=$1; shift
    local dir; dir=$(workspace "$name")
    local start end
    start=$(date +%s.%N)
    (cd "$dir" && bazel --output_user_root="$tmp/root-$name" build //:shaders --execution_log_json_file="$tmp/$name.exec.json" "$@") > "$tmp/$name.log" 2>&1 || { cat "$tmp/$name.log" >&2; echo "FAIL: build $name" >&2; exit 1; }
    end=$(date +%s.%N)
    python3 -c "print(f'{$end - $start:.2f}')"
}

# The processes line: "INFO: 70 processes: 2 internal, 68 linux-sandbox."
processes() { grep -o 'INFO: [0-9]* processes: .*' "$tmp/$1.log" | tail -1; }
count() { processes "$1" | grep -o "[0-9]* $2" | grep -o '^[0-9]*' || echo 0; }

# Every output of a workspace, as "hash  path" under bazel-bin.
outputs() {
    local dir="$tmp/ws-$1/bazel/example"
    local bin; bin=$(cd "$dir" && bazel --output_user_root="$tmp/root-$1" info bazel-bin 2>/dev/null)
    (cd "$bin/external/umbrac_src" && find . -type f | sort | xargs sha256sum)
}

remote=(--remote_cache="grpc://127.0.0.1:$port" --remote_max_connections=64)
t_cold=$(build a "${remote[@]}")
if grep -q 'WARNING: Writing to Remote Cache' "$tmp/a.log"; then grep -A3 'WARNING: Writing to Remote Cache' "$tmp/a.log" >&2; echo "FAIL: workspace A could not upload" >&2; exit 1; fi
sandboxed=$(count a linux-sandbox)
[ "$sandboxed" -gt 60 ] || { processes a >&2; echo "FAIL: workspace A ran $sandboxed sandboxed actions" >&2; exit 1; }
t_warm=$(build b "${remote[@]}")
hits=$(count b "remote cache hit")
[ "$hits" = "$sandboxed" ] && [ "$(count b linux-sandbox)" = 0 ] || { processes b >&2; echo "FAIL: workspace B: $hits remote cache hits of $sandboxed actions" >&2; exit 1; }
diff <(outputs a) <(outputs b) || { echo "FAIL: the outputs of A and B differ" >&2; exit 1; }
files=$(outputs a | wc -l)

disk=(--disk_cache="$tmp/disk")
t_disk_cold=$(build c "${disk[@]}")
t_disk_warm=$(build d "${disk[@]}")
# Bazel 4.2 counts a --disk_cache hit as a "remote cache hit".
[ "$(count d "remote cache hit")" = "$sandboxed" ] && [ "$(count d linux-sandbox)" = 0 ] || { processes d >&2; echo "FAIL: workspace D: not every action a disk cache hit" >&2; exit 1; }
diff <(outputs a) <(outputs d) || { echo "FAIL: the outputs of A and D differ" >&2; exit 1; }

# An undeclared include: not in the sandbox, not found.
dir="$tmp/ws-a/bazel/example"
if (cd "$dir" && bazel --output_user_root="$tmp/root-a" build @umbrac_src//:cascades_undeclared) > "$tmp/undeclared.log" 2>&1; then
    echo "FAIL: a target without its includes built" >&2; exit 1
fi
grep -q 'cannot find include file `include/common.das`' "$tmp/undeclared.log" || { cat "$tmp/undeclared.log" >&2; echo "FAIL: the undeclared include is not what failed" >&2; exit 1; }

# umbrac's own cache on the same programs and targets (shaders/spirv/ is
# SPIR-V only: compiled on its own), cold then warm.
own() {
    local start end
    start=$(date +%s.%N)
    "$umbrac" compile shaders/compute shaders/features shaders/programs shaders/techniques shaders/wgsl_spirv shaders/shadow.das \
        --target wgsl --target spirv -o "$tmp/own-$1" --cache "$tmp/own-cache" >/dev/null 2>"$tmp/own.log"
    "$umbrac" compile shaders/spirv --target spirv -o "$tmp/own-$1/spirv" --cache "$tmp/own-cache" >/dev/null 2>>"$tmp/own.log"
    end=$(date +%s.%N)
    python3 -c "print(f'{$end - $start:.2f}')"
}
t_own_cold=$(own cold)
t_own_warm=$(own warm)

echo "ok: $sandboxed umbrac actions ($files files): remote cache cold ${t_cold}s, workspace B from the remote cache ${t_warm}s ($hits hits, byte-identical);"
echo "    disk cache cold ${t_disk_cold}s, warm ${t_disk_warm}s; umbrac --cache alone on the same programs: cold ${t_own_cold}s, warm ${t_own_warm}s"
failed=
