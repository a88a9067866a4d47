#!/bin/sh
# Seeds fuzz/corpus/<target>/ from the project's shaders and the test inputs.
set -eu
cd "$(dirname "$0")/.."
for t in preprocess parse compile; do
    mkdir -p "fuzz/corpus/$t"
    find shaders tests -name '*.das' | while read -r f; do
        cp "$f" "fuzz/corpus/$t/seed-$(echo "$f" | tr '/' '_')"
    done
    if [ -f ../shared/reference/08_shadow.das ]; then
        cp ../shared/reference/08_shadow.das "fuzz/corpus/$t/seed-08_shadow.das"
    fi
done
ls fuzz/corpus/compile | wc -l
