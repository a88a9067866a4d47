#!/usr/bin/env bash
# Whole-process cost of `umbrac compile` on the tutorial, as a new user runs
# it, against the naga CLI producing the same ten outputs from the
# equivalent hand-written WGSL (docs/performance.md, "Whole process").
#
# Instructions (callgrind, every instruction of the process, dynamic loading
# included) are the criterion: they repeat on this machine. Wall and CPU
# time (user + system of the process, from its rusage) come after, from
# interleaved rounds: each round runs every case once, naga included.
#
# Needs valgrind, python3, /usr/local/bin/naga (or NAGA=...) and a release
# build (`cargo build --release`). Run from the repository root:
#
#     benches/whole_process.sh [INPUT.das] [ROUNDS]
#
# UMBRAC_BIN=PATH measures another build (an older one, to compare).
# WHOLE_PROCESS_ANNOTATE=1 also prints the top functions (inclusive) of
# each umbrac case, from the same callgrind runs.
set -euo pipefail
input="${1:-../shared/reference/08_shadow.das}"
rounds="${2:-20}"
bin="${UMBRAC_BIN:-target/release/umbrac}"
naga="${NAGA:-naga}"
wgsl=benches/shadow_equivalent.wgsl
[ -x "$bin" ] || cargo build --release --bin umbrac
command -v valgrind >/dev/null || { echo "needs valgrind" >&2; exit 1; }
command -v "$naga" >/dev/null || { echo "needs the naga CLI (NAGA=...)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$bin" "$input" "$naga" "$wgsl" "$work" "$rounds" "${WHOLE_PROCESS_ANNOTATE:-0}" <<'PY'
import os, re, resource, statistics, subprocess, sys, time

binary, source, naga, wgsl, work, rounds, annotate = sys.argv[1:]
rounds, annotate = int(rounds), annotate == "1"
binary = os.path.abspath(binary)
serial = [0]

def fresh(name):
    serial[0] += 1
    return os.path.join(work, f"{name}-{serial[0]}")

def env_with(cache_home):
    env = {k: v for k, v in os.environ.items() if k != "UMBRAC_CACHE_DIR"}
    env["XDG_CACHE_HOME"] = cache_home
    return env

def compile_cmd(out, *extra):
    return [binary, "compile", source, "--target", "all", "-o", out, *extra]

# naga: the WGSL and the SPIR-V from one process, each GLSL file from its
# own (an entry point and a profile per process): nine processes.
def naga_cmds(out):
    cmds = [[naga, wgsl, f"{out}/shadow.wgsl", f"{out}/shadow.spv"]]
    for entry, stage in [("shadow_vs", "vert"), ("shadow_fs", "frag"), ("main_vs", "vert"), ("main_fs", "frag")]:
        for profile, suffix in [("core330", "330"), ("es300", "300es")]:
            cmds.append([naga, "--entry-point", entry, "--profile", profile, wgsl, f"{out}/{entry}.{suffix}.{stage}"])
    return cmds

def run(cmd, env=None):
    subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

# Each case: a name, and a function that prepares the state and returns
# the command lists to measure (with their environment).
def cold():
    return [compile_cmd(fresh("out"))], env_with(fresh("cache"))

def no_cache():
    return [compile_cmd(fresh("out"), "--no-cache")], env_with(fresh("cache"))

def hit():
    env = env_with(fresh("cache"))
    run(compile_cmd(fresh("out")), env)
    return [compile_cmd(fresh("out"))], env

# The first rerun after a compile, as a user's second run: the outputs it
# finds were just written, so no stamp vouches for them yet and it reads
# them back (src/rerun.rs). The pause is a user's; it is above the 20 ms
# a stamp must be taken after a file's last change to be trusted.
def rerun():
    env = env_with(fresh("cache"))
    out = fresh("out")
    run(compile_cmd(out), env)
    time.sleep(0.05)
    return [compile_cmd(out)], env

# Every later rerun: the first one stamped the outputs.
def later_rerun():
    cmds, env = rerun()
    run(cmds[0], env)
    time.sleep(0.05)
    return cmds, env

def version():
    return [[binary, "--version"]], None

def naga_cli():
    out = fresh("naga")
    os.makedirs(out)
    return naga_cmds(out), None

cases = [
    ("first compile, empty cache (`XDG_CACHE_HOME` new)", cold),
    ("the same with `--no-cache`", no_cache),
    ("cache hit into a new output directory", hit),
    ("unchanged rerun into the same directory", rerun),
    ("`umbrac --version` (process start)", version),
]

def instructions(cmds, env, keep=None):
    total = 0
    for i, cmd in enumerate(cmds):
        log = fresh("cg.log")
        out = keep or fresh("cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", f"--log-file={log}", *cmd],
                       env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        m = re.search(r"Collected : (\d+)", open(log).read())
        total += int(m.group(1))
    return total

naga_ir = instructions(*naga_cli())
print(f"naga CLI, {len(naga_cmds('x'))} processes (`{naga} {wgsl} ...`): {naga_ir / 1e6:.2f} M instructions")
print()
print("| run | instructions | ratio to naga CLI |")
print("|---|---|---|")
profiles = []
for name, prepare in cases:
    cmds, env = prepare()
    keep = fresh("cg.keep")
    ir = instructions(cmds, env, keep)
    profiles.append((name, keep))
    print(f"| {name} | {ir / 1e6:.2f} M | {ir / naga_ir:.3f}x |")
later = instructions(*later_rerun())
print()
print(f"Later unchanged reruns (outputs stamped by the first): {later / 1e6:.2f} M, {later / naga_ir:.3f}x.")
sys.stdout.flush()

# Interleaved timing: every round runs each case (prepared outside the
# clock) and then naga's nine processes.
wall = {name: [] for name, _ in cases + [("naga CLI", None)]}
cpu = {name: [] for name in wall}
for _ in range(rounds):
    for name, prepare in cases + [("naga CLI", naga_cli)]:
        cmds, env = prepare()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        for cmd in cmds:
            run(cmd, env)
        t1 = time.perf_counter()
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        wall[name].append((t1 - t0) * 1e3)
        cpu[name].append((after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime) * 1e3)
print()
print(f"Time, {rounds} interleaved rounds, median (min-max) ms; CPU is user + system of the processes:")
print()
print("| run | wall | CPU | wall / naga CLI's |")
print("|---|---|---|---|")
naga_wall = statistics.median(wall["naga CLI"])
for name in wall:
    w, c = wall[name], cpu[name]
    print(f"| {name} | {statistics.median(w):.2f} ({min(w):.2f}-{max(w):.2f}) | {statistics.median(c):.2f} ({min(c):.2f}-{max(c):.2f}) | {statistics.median(w) / naga_wall:.3f}x |")

if annotate:
    for name, keep in profiles:
        print(f"\n## {name}: top functions (inclusive)")
        text = subprocess.run(["callgrind_annotate", "--inclusive=yes", keep], capture_output=True, text=True).stdout
        print("\n".join([l for l in text.splitlines() if re.match(r"^ *[0-9,]+ \(", l)][:25]))
PY
