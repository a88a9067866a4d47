#!/usr/bin/env bash
# Builds the playground (docs/preview.md, "Playground") into a folder of
# static files, target/playground/ by default:
#
#   bash scripts/build-playground.sh [OUT_DIR]
#
# 1. umbrac's library for wasm32-unknown-unknown (web/playground/wasm, its
#    release profile), 2. wasm-bindgen's JavaScript glue (wasm-bindgen-cli,
#    installed into target/tools at the crate's version when missing),
#    3. the page and its worker bundled by esbuild (npm, web/playground),
#    4. the examples: shaders/ and, when ../shared/reference is there,
#    daslang's GL tutorials.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out="${1:-$root/target/playground}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# The wasm-bindgen crate's version in the lock file; the CLI must match it.
bindgen_version="$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' web/playground/wasm/Cargo.lock)"
bindgen="$root/target/tools/bin/wasm-bindgen"
# Unoptimised and without its default TLS stack (only its test runner
# downloads): about 110 s of CPU to build instead of several minutes, and
# it binds this module in 1.5 s instead of 0.3, to the same bytes.
if ! "$bindgen" --version 2>/dev/null | grep -qF "$bindgen_version"; then
    echo "installing wasm-bindgen-cli $bindgen_version into target/tools"
    cargo install --quiet --debug wasm-bindgen-cli --version "$bindgen_version" --no-default-features --root "$root/target/tools"
fi

echo "building the compiler for wasm32-unknown-unknown"
(cd web/playground/wasm && cargo build --quiet --release --target wasm32-unknown-unknown --target-dir "$root/target")
wasm="$root/target/wasm32-unknown-unknown/release/umbrac_web.wasm"

# Built into a fresh folder, then swapped in, so a failed build never
# leaves a half-written page.
stage="$(mktemp -d "$out.tmp.XXXXXX")"
chmod 755 "$stage"
trap 'rm -rf "$stage"' EXIT
"$bindgen" --target web --no-typescript --out-dir "$stage/pkg" "$wasm"

if [ ! -x web/playground/node_modules/.bin/esbuild ]; then
    npm ci --prefix web/playground --no-audit --no-fund >/dev/null
fi
esbuild=web/playground/node_modules/.bin/esbuild
"$esbuild" web/playground/main.js --bundle --format=esm --minify --log-level=warning --outfile="$stage/main.js"
# The worker imports the glue as ./pkg/umbrac_web.js: bundled from beside it.
cp web/playground/worker.js "$stage/worker.src.js"
"$esbuild" "$stage/worker.src.js" --bundle --format=esm --minify --log-level=warning --outfile="$stage/worker.js"
rm "$stage/worker.src.js"
# The worker bundle carries the glue; the wasm file sits beside it. The
# glue is kept too, for scripts that load the compiler in node
# (web/playground/bench.mjs).
mv "$stage/pkg/umbrac_web_bg.wasm" "$stage/pkg/umbrac_web.js" "$stage/"
rm -rf "$stage/pkg"
cp web/playground/index.html web/playground/style.css "$stage/"
node web/playground/examples.mjs "$root" "$stage/examples.json"

rm -rf "$out.old"
mv "$out" "$out.old"
mv "$stage" "$out"
rm -rf "$out.old"
trap - EXIT
echo "the playground is in $out (serve it as static files)"
