#!/usr/bin/env bash
# Whole-process figures for `umbrac compile` on the tutorial program
# (docs/performance.md): wall time with hyperfine, instructions with
# callgrind. Needs `apt-get install hyperfine valgrind` and a release build
# (`cargo build --release`). Run from the repository root.
set -euo pipefail
input="${1:-../shared/reference/08_shadow.das}"
bin=target/release/umbrac
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
[ -x "$bin" ] || cargo build --release --bin umbrac
echo "## hyperfine: $bin compile $input -o $out"
hyperfine --warmup 5 --runs 40 -N --export-markdown "$out/hf.md" --export-json "$out/hf.json" "$bin compile $input -o $out/o" >/dev/null
cat "$out/hf.md"
# CPU time of the process itself (user + system), which the load on the
# shared cores does not inflate the way it inflates wall time.
python3 -c "import json,sys; r=json.load(open(sys.argv[1]))['results'][0]; print('user %.2f ms, system %.2f ms (means); wall min %.1f ms, median %.1f ms' % (r['user']*1e3, r['system']*1e3, r['min']*1e3, r['median']*1e3))" "$out/hf.json"
echo
echo "## callgrind: instructions"
valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" "$bin" compile "$input" -o "$out/o" 2>"$out/cg.log"
grep -E "Collected|refs" "$out/cg.log" | sed 's/^==[0-9]*== //'
callgrind_annotate "$out/cg.out" 2>/dev/null | sed -n '1,40p' | grep -E "PROGRAM TOTALS|Ir" | head -3
echo
echo "## top functions (inclusive)"
callgrind_annotate --inclusive=yes "$out/cg.out" 2>/dev/null | grep -E "^ *[0-9,]+ \(" | head -25
