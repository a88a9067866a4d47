#!/usr/bin/env bash
# Two umbrac binaries side by side on the 256 variants of docs/scale.md
# (`shaders/programs/shadow_variants.das` and its spec): the cold run, the
# first rerun, later reruns, and a warm run into an empty directory.
# Instructions (callgrind, whole process, every thread) and CPU time (user +
# system, median of interleaved rounds). Keep a copy of the binary before a
# change to compare with (`cp target/release/umbrac /tmp/umbrac-before`).
#
#     benches/variants_ab.sh OLD_BINARY [NEW_BINARY] [ROUNDS]
set -euo pipefail
old="$1"
new="${2:-target/release/umbrac}"
rounds="${3:-5}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$old" "$new" "$rounds" "$work" <<'PY'
import os, re, resource, statistics, subprocess, sys, time

old, new, rounds, work = sys.argv[1:]
rounds = int(rounds)
binaries = {"old": os.path.abspath(old), "new": os.path.abspath(new)}
src, spec = "shaders/programs/shadow_variants.das", "shaders/programs/shadow_variants.toml"
serial = [0]

def fresh(name):
    serial[0] += 1
    return os.path.join(work, f"{name}-{serial[0]}")

def cmd(binary, out, cache, jobs):
    return [binary, "compile", src, "--variants", spec, "-o", out, "--cache", cache, "--jobs", str(jobs)]

def run(c):
    subprocess.run(c, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

# Each case prepares its state and returns the command to measure.
def cold(b, jobs):
    return cmd(b, fresh("out"), fresh("cache"), jobs)

def first_rerun(b, jobs):
    c = cmd(b, fresh("out"), fresh("cache"), jobs)
    run(c)
    time.sleep(0.05)
    return c

def later_rerun(b, jobs):
    c = first_rerun(b, jobs)
    run(c)
    time.sleep(0.05)
    return c

def warm_empty(b, jobs):
    cache = fresh("cache")
    run(cmd(b, fresh("out"), cache, jobs))
    return cmd(b, fresh("out"), cache, jobs)

cases = [("cold", cold), ("first rerun", first_rerun), ("later rerun", later_rerun), ("warm, into an empty directory", warm_empty)]

def instructions(c):
    log = fresh("cg.log")
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={fresh('cg.out')}", f"--log-file={log}", *c],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return int(re.search(r"Collected : (\d+)", open(log).read()).group(1))

print("| case (`--jobs 1`) | old: instructions | new: instructions | new / old |")
print("|---|---|---|---|")
for name, prepare in cases:
    ir = {k: instructions(prepare(b, 1)) for k, b in binaries.items()}
    print(f"| {name} | {ir['old'] / 1e6:.1f} M | {ir['new'] / 1e6:.1f} M | {ir['new'] / ir['old']:.3f}x |")
sys.stdout.flush()

for jobs in (1, 2):
    cpu = {(name, k): [] for name, _ in cases for k in binaries}
    wall = {key: [] for key in cpu}
    for _ in range(rounds):
        for name, prepare in cases:
            for k, b in binaries.items():
                c = prepare(b, jobs)
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                t0 = time.perf_counter()
                run(c)
                t1 = time.perf_counter()
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                wall[(name, k)].append((t1 - t0) * 1e3)
                cpu[(name, k)].append((after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime) * 1e3)
    print()
    print(f"`--jobs {jobs}`, {rounds} interleaved rounds, median (min) ms:")
    print()
    print("| case | old: wall, CPU | new: wall, CPU | new / old (CPU medians) |")
    print("|---|---|---|---|")
    for name, _ in cases:
        o, n = (name, "old"), (name, "new")
        co, cn = statistics.median(cpu[o]), statistics.median(cpu[n])
        fmt = lambda k: f"{statistics.median(wall[k]):.1f} ({min(wall[k]):.1f}), {statistics.median(cpu[k]):.1f} ({min(cpu[k]):.1f})"
        print(f"| {name} | {fmt(o)} | {fmt(n)} | {cn / co:.3f}x |")
PY
