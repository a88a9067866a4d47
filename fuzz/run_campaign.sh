#!/bin/bash
# A time-bounded fuzz campaign over the three targets, one after another,
# whose findings are: a crash (a panic, an internal compiler error, WGSL
# that naga's front end rejects, WGSL whose interface disagrees with the
# SPIR-V or the manifest: see fuzz_targets/compile.rs), an input that runs
# longer than 10 s (a hang), one that needs more than 2 GiB, and any
# output of the final corpus or of a kept mutant that glslangValidator
# (pairs linked), spirv-val or tint rejects. Exits 1 if there is any.
#
# Usage: fuzz/run_campaign.sh [SECONDS_PER_TARGET] [--seed N] [--jobs N] [--keep-every N]
#   default 300 s per target. --seed N: one process, libFuzzer's seed N,
#   stopping at the first finding (what .ci/run does). Without it, fork
#   mode: a finding is recorded under fuzz/artifacts/ and the run goes on.
#   --keep-every N (default 4): one compiled mutant in N is kept under
#   fuzz/mutants/ and its outputs validated after the run. --targets
#   "LIST" (default "compile parse preprocess"): the targets to run.
#   UMBRAC_FUZZ_BIN=DIR: use the targets already built there (build.sh's
#   last line) instead of building.
# Needs: a Rust toolchain (stable is enough: fuzz/build.sh), a C++
# compiler, glslangValidator, spirv-val and tint. docs/robustness.md has
# the campaign on record.
set -uo pipefail
cd "$(dirname "$0")"
secs=300
seed=""
jobs=1
keep=4
targets="compile parse preprocess"
while [ $# -gt 0 ]; do
    case "$1" in
        --seed) seed="$2"; shift 2 ;;
        --jobs) jobs="$2"; shift 2 ;;
        --keep-every) keep="$2"; shift 2 ;;
        --targets) targets="$2"; shift 2 ;;
        *) secs="$1"; shift ;;
    esac
done
for tool in glslangValidator spirv-val tint; do
    command -v "$tool" >/dev/null || { echo "fuzz: $tool is missing (glslang-tools, spirv-tools; tint: docs/build.md)" >&2; exit 1; }
done
start=$(date +%s)
bin=${UMBRAC_FUZZ_BIN:-}
[ -n "$bin" ] || bin=$(./build.sh $targets | tail -n 1) || { echo "fuzz: the build failed" >&2; exit 1; }
echo "fuzz: built in $(( $(date +%s) - start )) s"
./seed.sh >/dev/null
rm -rf mutants && mkdir mutants
findings=0
ntargets=0
for t in $targets; do
    ntargets=$((ntargets + 1))
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
    UMBRAC_FUZZ_KEEP="$(pwd)/mutants" UMBRAC_FUZZ_KEEP_EVERY="$keep" "$bin/$t" "${opts[@]}" "corpus/$t" >"$log" 2>&1
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
# The outputs of every corpus input and of every kept mutant (one compiled
# mutant in --keep-every, see keep_mutant in fuzz_targets/compile.rs) that
# compile, through glslangValidator (each file, and each vertex/fragment
# pair the manifest links, per profile), spirv-val and tint. naga's WGSL
# front end and the differential check ran in the target on every input.
out=$(mktemp -d)
UMBRAC_FUZZ_OUT="$out" "$bin/compile" -runs=0 corpus/compile mutants >logs/outputs.log 2>&1 || {
    echo "fuzz: replaying the corpus failed"; tail -n 40 logs/outputs.log; findings=$((findings + 1)); }
runs=0
rejected=0
reject() { # DIR TOOL OUTPUT
    rejected=$((rejected + 1))
    mkdir -p artifacts/rejected
    cp -r "$1" artifacts/rejected/
    echo "fuzz: $2 rejects an output of $(basename "$1") (artifacts/rejected/$(basename "$1")/input.das.txt)"
    echo "$3" | head -n 8
}
for d in "$out"/*/; do
    d=${d%/}
    for f in "$d"/*; do
        case "$f" in
            *.vert|*.frag|*.comp) tool=glslangValidator; result=$(glslangValidator "$f" 2>&1) ;;
            *.spv) tool=spirv-val; result=$(spirv-val --target-env vulkan1.0 "$f" 2>&1) ;;
            *.wgsl) tool=tint; result=$(tint --format wgsl -o /dev/null "$f" 2>&1) ;;
            *) continue ;;
        esac
        [ $? -eq 0 ] || reject "$d" "$tool" "$result"
        runs=$((runs + 1))
    done
    while read -r vs fs; do
        for p in 330 300es 430 310es; do
            [ -f "$d/$vs.$p.vert" ] && [ -f "$d/$fs.$p.frag" ] || continue
            result=$(glslangValidator -l "$d/$vs.$p.vert" "$d/$fs.$p.frag" 2>&1) || reject "$d" "glslangValidator -l" "$result"
            runs=$((runs + 1))
        done
    done <"$d/programs.txt"
done
echo "fuzz: validators: $(ls "$out" | wc -l) compiled inputs ($(ls corpus/compile | wc -l) corpus, $(ls mutants | wc -l) kept mutants), $runs validator runs, $rejected rejected"
rm -rf "$out"
[ $rejected -eq 0 ] || findings=$((findings + 1))
echo "fuzz: $(( $(date +%s) - start )) s in all, $findings targets or checks with findings"
# Each target and the validators: one check each.
echo "fuzz: $((ntargets + 1 - findings)) passed, $findings failed"
[ $findings -eq 0 ]
