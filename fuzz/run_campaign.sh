#!/bin/sh
# Time-bounded fuzz campaign over the three targets, one after another.
# Usage: fuzz/run_campaign.sh [SECONDS_PER_TARGET]   (default 300)
# Needs: rustup toolchain nightly, cargo install cargo-fuzz.
set -u
cd "$(dirname "$0")"
secs=${1:-300}
./seed.sh >/dev/null
for t in compile parse preprocess; do
    echo "=== $t: $secs s"
    cargo +nightly fuzz run -O "$t" -- \
        -max_total_time="$secs" -timeout=10 -max_len=8192 -rss_limit_mb=4096 \
        -dict=daslang.dict -print_final_stats=1 \
        -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 2>&1 | tail -n 40
    echo "=== $t: artifacts"
    ls artifacts/"$t" 2>/dev/null || true
done
