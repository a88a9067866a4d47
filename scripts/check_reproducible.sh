#!/usr/bin/env bash
# CI's reproducibility check (docs/scale.md, "Beyond one machine"): the
# release umbrac from this checkout (scripts/release.sh) and from a clone of
# the same commit at another path, sharing the target directory, must be
# byte-identical, and neither may hold either checkout's path.
#
# Sharing the target directory keeps it affordable: the remap flag does
# not name the checkout, so only umbrac's own crate (library, build script,
# binary) is built again. What it proves: nothing umbrac's own crate puts
# in the binary depends on where it is checked out. What it does not: that
# dependencies built under another $CARGO_HOME, or on another machine or
# toolchain, give the same bytes (that was measured by hand, two full
# builds; the remap is what makes the registry path drop out).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
target="${CARGO_TARGET_DIR:-$repo/target}"
case "$target" in /*) ;; *) target="$repo/$target" ;; esac

a=$(CARGO_TARGET_DIR="$target" bash scripts/release.sh)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$a" "$tmp/umbrac-a"
git clone --quiet --no-hardlinks "$repo" "$tmp/elsewhere/checkout"
# The working tree's uncommitted state too, so a local run checks what is
# on disk, not only HEAD.
git diff HEAD | (cd "$tmp/elsewhere/checkout" && git apply --allow-empty)
b=$(cd "$tmp/elsewhere/checkout" && CARGO_TARGET_DIR="$target" bash scripts/release.sh)
cp "$b" "$tmp/umbrac-b"
if ! cmp "$tmp/umbrac-a" "$tmp/umbrac-b"; then
    echo "FAIL: the release umbrac differs between $repo and $tmp/elsewhere/checkout" >&2
    exit 1
fi
for p in "$repo" "$tmp/elsewhere" "${CARGO_HOME:-$HOME/.cargo}"; do
    if grep -qaF "$p" "$tmp/umbrac-a"; then
        echo "FAIL: the release umbrac holds the path $p" >&2
        exit 1
    fi
done
echo "ok: the release umbrac is byte-identical from two checkout paths ($(sha256sum < "$tmp/umbrac-a" | cut -c1-16))"
