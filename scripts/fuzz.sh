#!/usr/bin/env bash
# Runs every cargo-fuzz target, starting from its committed seed corpus (fuzz/corpus/<target>/; the
# inputs the fuzzer finds go to a scratch directory). Prints one line per target with the executions,
# the time, the rate and the crashes found. A crashing input is copied into fuzz/corpus/<target>/,
# where crates/ray-footprint-cases/tests/fuzz_corpus.rs replays it on stable Rust: commit it with the fix. Exits non-zero when
# any target crashes. Needs a nightly toolchain and cargo-fuzz.
#
# Usage:
#   scripts/fuzz.sh [SECONDS]           each target for SECONDS (default 60) in one process (CI)
#   scripts/fuzz.sh --runs N [WORKERS [TARGET...]]
#                                       each target (default: all) until it has run N inputs, shared
#                                       by WORKERS processes (default 2) that share one corpus
#                                       (libFuzzer -jobs); the long run is
#                                       `scripts/fuzz.sh --runs 1000000`
#
# FUZZ_BINARIES=DIR runs the target binaries in DIR instead of building them (a machine without
# the nightly toolchain, given the binaries `cargo +nightly fuzz build` made elsewhere).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
if [[ "${1:-}" == "--runs" ]]; then
    runs="${2:?--runs needs a number of inputs}"
    workers="${3:-2}"
    # Each job writes its output to fuzz-<job>.log in the working directory.
    budget=(-runs="$(((runs + workers - 1) / workers))" -jobs="$workers" -workers="$workers")
else
    seconds="${1:-60}"
    budget=(-max_total_time="$seconds")
fi
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
targets=(abi_bytes cpu_mirror compose include)
if [[ "${1:-}" == "--runs" && $# -gt 3 ]]; then
    targets=("${@:4}")
fi

# The WGSL tokens, and every name the library's modules declare, for `compose`.
dict="$scratch/wgsl.dict"
cp fuzz/dict/wgsl.dict "$dict"
grep -ohE '^(fn|struct|const) [A-Za-z_][A-Za-z0-9_]*' shaders/wgsl/*.wgsl |
    awk '{ printf "\"%s\"\n", $2 }' >>"$dict"

# Options of one target beyond the budget.
options() {
    case "$1" in
        compose) echo "-dict=$dict" ;;
    esac
}

if [[ -n "${FUZZ_BINARIES:-}" ]]; then
    binaries="$(cd "$FUZZ_BINARIES" && pwd)"
else
    cargo +nightly fuzz build
    binaries="$root/fuzz/target/$(rustc +nightly -vV | sed -n 's/^host: //p')/release"
fi
status=0
for target in "${targets[@]}"; do
    run="$scratch/$target-run"
    mkdir -p "$scratch/$target" "$scratch/$target-artifacts" "$run"
    start="$(date +%s)"
    # shellcheck disable=SC2046 # options are words without spaces
    if (cd "$run" && "$binaries/$target" "$scratch/$target" "$root/fuzz/corpus/$target" \
        "${budget[@]}" $(options "$target") -print_final_stats=1 \
        -artifact_prefix="$scratch/$target-artifacts/" >"$run/main.log" 2>&1); then
        crashed=0
    else
        crashed=1
        status=1
        tail -n 40 "$run/main.log"
    fi
    elapsed=$(($(date +%s) - start))
    # The final stats of the process, or of each job (whose logs the parent prints when it ends).
    executions="$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$run/main.log" |
        awk '{ sum += $2 } END { print sum + 0 }')"
    crashes=0
    for artifact in "$scratch/$target-artifacts"/*; do
        [[ -f "$artifact" ]] || continue
        # An input that only took long (on a loaded machine, say) is no failure.
        [[ "$(basename "$artifact")" == slow-unit-* ]] && continue
        cp "$artifact" "fuzz/corpus/$target/"
        echo "fuzz $target: kept fuzz/corpus/$target/$(basename "$artifact")"
        crashes=$((crashes + 1))
    done
    if [[ "$crashed" == 1 && "$crashes" == 0 ]]; then
        crashes="1 (no input saved, see the log above)"
    fi
    echo "fuzz $target: $executions executions in ${elapsed}s ($((executions / (elapsed > 0 ? elapsed : 1)))/s)," \
        "$crashes crash(es)"
done
exit "$status"
