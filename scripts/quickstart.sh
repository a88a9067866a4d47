#!/usr/bin/env bash
# The main job on a fresh machine: install the CPU Vulkan driver (lavapipe),
# compile the shipped program to every target into out/, and render the
# shadow scene from the generated shaders to out/frame.png.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
if command -v apt-get >/dev/null 2>&1 && ! ls /usr/share/vulkan/icd.d/lvp_icd*.json >/dev/null 2>&1; then
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends mesa-vulkan-drivers libvulkan1 >/dev/null
fi
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"

cargo build --release
./target/release/umbrac compile shaders/shadow.das -o out
./target/release/umbrac render shaders/shadow.das --size 640x480 --time 2 --out out/frame.png
echo "outputs in out/:"
ls out
