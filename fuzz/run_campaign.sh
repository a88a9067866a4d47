#!/bin/bash
# A time-bounded fuzz campaign over the three targets, one after another,
# whose findings are: a crash (a panic, an internal compiler error, WGSL
# that naga's front end rejects: see fuzz_targets/compile.rs), an input
# that runs longer than 10 s (a hang), one that needs more than 2 GiB, and
# any GLSL or SPIR-V output of the final corpus that glslangValidator or
# spirv-val rejects. Exits 1 if there is any.
#
# Usage: fuzz/run_campaign.sh [SECONDS_PER_TARGET] [--seed N] [--jobs N]
#   default 300 s per target. --seed N: one process, libFuzzer's seed N,
#   stopping at the first finding (what .ci/run does). Without it, fork
#   mode: a finding is recorded under fuzz/artifacts/ and the run goes on.
# Needs: a Rust toolchain (stable is enough: fuzz/build.sh), a C++
# compiler, glslangValidator and spirv-val. docs/robustness.md has the
# campaign on record.
set -uo pipefail
cd "$(dirname "$0")"
secs=300
seed=""
jobs=1
while [ $# -gt 0 ]; do
    case "$1" in
        --seed) seed="$2"; shift 2 ;;
        --jobs) jobs="$2"; shift 2 ;;
        *) secs="$1"; shift ;;
    esac
done
for tool in glslangValidator spirv-val; do
    command -v "$tool" >/dev/null || { echo "fuzz: $tool is missing (apt-get install glslang-tools spirv-tools)" >&2; exit 1; }
done
start=$(date +%s)
bin=$(./build.sh | tail -n 1) || { echo "fuzz: the build failed" >&2; exit 1; }
echo "fuzz: built in $(( $(date +%s) - start )) s"
./seed.sh >/dev/null
findings=0
for t in compile parse preprocess; do
    mkdir -p "artifacts/$t" logs
    before=$(ls "artifacts/$t" | wc -l)
    log="logs/$t.log"
    opts=(-max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -dict=daslang.dict
          -print_final_stats=1 -artifact_prefix="artifacts/$t/")
    if [ -n "$seed" ]; then
        opts+=(-seed="$seed")
    else
        opts+=(-fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    fi
    seeds=$(ls "corpus/$t" | wc -l)
    "$bin/$t" "${opts[@]}" "corpus/$t" >"$log" 2>&1
    status=$?
    after=$(ls "artifacts/$t" | wc -l)
    # One process prints its final stats; fork mode prints a running total
    # (`#N:`) after each job.
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -n 1)
    [ -n "$execs" ] || execs=$(grep -o '^#[0-9]*:' "$log" | tail -n 1 | tr -d '#:')
    cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -n 1)
    echo "fuzz: $t: $secs s, $execs executions, $cov, corpus $seeds -> $(ls "corpus/$t" | wc -l), exit $status, $((after - before)) new findings"
    if [ $status -ne 0 ] || [ "$after" -gt "$before" ]; then
        findings=$((findings + 1))
        tail -n 60 "$log"
    fi
done
# The GLSL and SPIR-V of every corpus input that compiles, through the
# validators (the compile target checks the WGSL itself).
out=$(mktemp -d)
UMBRAC_FUZZ_OUT="$out" "$bin/compile" -runs=0 corpus/compile >logs/outputs.log 2>&1 || {
    echo "fuzz: replaying the corpus failed"; tail -n 40 logs/outputs.log; findings=$((findings + 1)); }
runs=0
rejected=0
for f in "$out"/*/*; do
    case "$f" in
        *.vert|*.frag) result=$(glslangValidator "$f" 2>&1) ;;
        *.spv) result=$(spirv-val --target-env vulkan1.0 "$f" 2>&1) ;;
        *) continue ;;
    esac
    if [ $? -ne 0 ]; then
        rejected=$((rejected + 1))
        mkdir -p artifacts/rejected
        cp -r "$(dirname "$f")" artifacts/rejected/
        echo "fuzz: rejected: $f"; echo "$result" | head -n 5
    fi
    runs=$((runs + 1))
done
echo "fuzz: validators: $(ls "$out" | wc -l) compiled corpus inputs, $runs validator runs, $rejected rejected"
rm -rf "$out"
[ $rejected -eq 0 ] || findings=$((findings + 1))
echo "fuzz: $(( $(date +%s) - start )) s in all, $findings targets or checks with findings"
# Three targets and the validators: one check each.
echo "fuzz: $((4 - findings)) passed, $findings failed"
[ $findings -eq 0 ]
