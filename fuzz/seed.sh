#!/bin/sh
# Seeds fuzz/corpus/<target>/ from the project's programs, the test inputs
# (the bad-input corpus and fuzz/regressions/ included) and, when
# ../shared/reference is present, real daslang programs of both dialects:
# the GL tutorials, dasVulkan's tutorial shaders and every other daScript
# file that declares a shader stage.
set -eu
cd "$(dirname "$0")/.."
ref=../shared/reference
refs=$(mktemp)
trap 'rm -f "$refs"' EXIT
if [ -d "$ref" ]; then
    {
        ls "$ref"/*.das "$ref"/daslang-tutorials/*.das 2>/dev/null || true
        ls "$ref"/daslang/modules/dasVulkan/tutorials/*/*_shaders.das 2>/dev/null || true
        grep -rlE '\[(vertex|fragment|compute)_(program|shader)|\[vulkan_[a-z_]*_shader' \
            --include='*.das' "$ref/daslang" 2>/dev/null || true
    } | sort -u >"$refs"
fi
for t in preprocess parse compile; do
    mkdir -p "fuzz/corpus/$t"
    find shaders tests fuzz/regressions -name '*.das' 2>/dev/null | while read -r f; do
        cp "$f" "fuzz/corpus/$t/seed-$(echo "$f" | tr '/' '_')"
    done
    while read -r f; do
        cp "$f" "fuzz/corpus/$t/seed-ref-$(echo "${f#"$ref"/}" | tr '/' '_')"
    done <"$refs"
done
echo "fuzz: $(wc -l <"$refs") daslang programs from $ref" >&2
ls fuzz/corpus/compile | wc -l
