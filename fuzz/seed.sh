#!/bin/sh
# Seeds fuzz/corpus/<target>/ from the project's programs, the test inputs
# (the bad-input corpus included) and daslang's tutorials in
# ../shared/reference (when present).
set -eu
cd "$(dirname "$0")/.."
for t in preprocess parse compile; do
    mkdir -p "fuzz/corpus/$t"
    find shaders tests -name '*.das' | while read -r f; do
        cp "$f" "fuzz/corpus/$t/seed-$(echo "$f" | tr '/' '_')"
    done
    for f in ../shared/reference/*.das ../shared/reference/daslang-tutorials/*.das; do
        [ -f "$f" ] && cp "$f" "fuzz/corpus/$t/seed-ref-$(basename "$f")"
    done
done
ls fuzz/corpus/compile | wc -l
