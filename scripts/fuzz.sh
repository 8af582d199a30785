#!/usr/bin/env bash
# Runs every cargo-fuzz target for a bounded time (issue 7), starting from its committed seed corpus
# (fuzz/corpus/<target>/, never modified: new inputs go to a scratch directory). Prints one line per
# target with the executions run and the crashes found; exits non-zero when any target crashes.
# Needs a nightly toolchain and cargo-fuzz. Usage: scripts/fuzz.sh [seconds per target, default 60]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
targets=(abi_bytes cpu_mirror compose include)

cargo +nightly fuzz build
status=0
for target in "${targets[@]}"; do
    mkdir -p "$scratch/$target"
    log="$scratch/$target.log"
    if cargo +nightly fuzz run "$target" "$scratch/$target" "fuzz/corpus/$target" -- \
        -max_total_time="$seconds" -print_final_stats=1 >"$log" 2>&1; then
        crashes=0
    else
        crashes=1
        status=1
        tail -n 40 "$log"
    fi
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')"
    echo "fuzz $target: $runs executions in ${seconds}s, $crashes crash(es)"
done
exit "$status"
