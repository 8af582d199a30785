#!/usr/bin/env bash
# Times the README's test command as a fresh machine runs it: a clean clone of REF (default HEAD)
# in a temporary directory with its own empty target directory, then `scripts/setup.sh` and
# `cargo test --release --workspace --all-features` there. Prints each phase as it ends: the setup,
# the build (until cargo starts the first test binary), every test binary and doc-test run, and the
# total, with the load average before and after (other builds on the machine slow every phase).
#
# Usage: scripts/test-time.sh [REF]
#
# The full output goes to target/test-time/<commit>-<time>.log; with TEST_TIME_TIMINGS=1 cargo
# also writes its --timings report (the time of every compiled unit) next to it. Crates come
# from the local cargo registry cache: download time is not measured.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
commit=$(git -C "$root" rev-parse --verify "${1:-HEAD}^{commit}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
logs="$root/target/test-time"
mkdir -p "$logs"
log="$logs/${commit:0:7}-$(date +%Y%m%d-%H%M%S)"
timings=()
[ "${TEST_TIME_TIMINGS:-0}" = 1 ] && timings=(--timings)
git clone --quiet "$(git -C "$root" rev-parse --path-format=absolute --git-common-dir)" "$work/clone"
git -C "$work/clone" checkout --quiet --detach "$commit"
cd "$work/clone"
# The clone's own ./target, as on a fresh machine.
unset CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR
export CARGO_TERM_COLOR=never

printf 'test-time: %s on %s cores, %s\n' "$(git log -1 --format='%h %s')" "$(nproc)" "$(uptime | sed 's/.*load/load/')"

phase_start=$EPOCHREALTIME
total_start=$phase_start
# Prints the time since the last phase ended and starts the next phase.
end_phase() {
    local now=$EPOCHREALTIME
    awk -v a="$phase_start" -v b="$now" -v name="$1" 'BEGIN { printf "%8.1f s  %s\n", b - a, name }'
    phase_start=$now
}

scripts/setup.sh >"$work/setup.log" 2>&1 || { cat "$work/setup.log"; exit 1; }
end_phase setup

# Each "Running <source> (<binary>)" or "Doc-tests <crate>" line of cargo ends the phase before it.
phase=build
status=0
cargo test --release --workspace --all-features "${timings[@]}" 2>&1 | tee "$log.log" | {
    while IFS= read -r line; do
        case "$line" in
        "     Running "*" ("*")")
            end_phase "$phase"
            source=${line#*Running }
            binary=${source##*/}
            phase="${source%% (*} (${binary%-*})"
            ;;
        "   Doc-tests "*)
            end_phase "$phase"
            phase="doc-tests ${line#*Doc-tests }"
            ;;
        esac
    done
    end_phase "$phase"
} || status=$?
awk -v a="$total_start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%8.1f s  total\n", b - a }'
printf 'test-time: after, %s; output in %s.log\n' "$(uptime | sed 's/.*load/load/')" "$log"
[ ${#timings[@]} -eq 0 ] || cp target/cargo-timings/cargo-timing.html "$log.html"
if [ "$status" -ne 0 ]; then
    echo "test-time: the test command failed; the end of its output:"
    tail -n 60 "$log.log"
    exit 1
fi
