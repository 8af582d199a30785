#!/usr/bin/env bash
# Times the README's test command as a fresh machine runs it: a clean clone of REF (default HEAD)
# in a temporary directory with its own empty target directory, then `scripts/setup.sh` and
# `cargo test --release --workspace --all-features` there. Prints each phase as it ends: the setup,
# the build (until cargo starts the first test binary), every test binary and doc-test run, and the
# total. Each phase shows its wall time and the CPU time of the processes it ran (cargo's and its
# children's), which other work on a shared machine inflates far less than the wall time; the
# load average before and after says how busy the machine was.
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

uptime_load() { uptime | sed 's/.*load/load/'; }
printf 'test-time: %s on %s cores, %s\n' "$(git log -1 --format='%h %s')" "$(nproc)" "$(uptime_load)"
printf '%10s %10s  %s\n' wall cpu phase

cargo_pid=
ticks=$(getconf CLK_TCK)
# CPU seconds used so far by the running cargo and the children it has waited for (every
# finished compiler and test binary, with their own children); 0 before it starts.
cargo_cpu() {
    if [ -n "$cargo_pid" ] && [ -r "/proc/$cargo_pid/stat" ]; then
        awk -v ticks="$ticks" '{ print ($14 + $15 + $16 + $17) / ticks }' "/proc/$cargo_pid/stat"
    else
        echo 0
    fi
}
# CPU seconds of this shell's finished children, from `times` (run in this shell, not in a
# subshell, whose children are its own), into REPLY.
children_cpu() {
    times >"$work/times"
    REPLY=$(awk 'NR == 2 { split($1, u, "m"); split($2, s, "m");
        print u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$work/times")
}
phase_start=$EPOCHREALTIME
phase_cpu=0
total_start=$phase_start
# Prints the wall time since the last phase ended and the CPU time `cpu` (cargo's so far, by
# default) used since then, and starts the next phase.
end_phase() {
    local now=$EPOCHREALTIME cpu=${2:-$(cargo_cpu)}
    awk -v a="$phase_start" -v b="$now" -v c="$phase_cpu" -v d="$cpu" -v name="$1" \
        'BEGIN { printf "%8.1f s %8.1f s  %s\n", b - a, d - c, name }'
    phase_start=$now
    phase_cpu=$cpu
}

children_cpu
start_cpu=$REPLY
scripts/setup.sh >"$work/setup.log" 2>&1 || { cat "$work/setup.log"; exit 1; }
children_cpu
setup_cpu=$REPLY
end_phase setup "$(awk -v a="$setup_cpu" -v b="$start_cpu" 'BEGIN { print a - b }')"
phase_cpu=0

# Each "Running <source> (<binary>)" or "Doc-tests <crate>" line of cargo ends the phase before it.
mkfifo "$work/output"
cargo test --release --workspace --all-features "${timings[@]}" >"$work/output" 2>&1 &
cargo_pid=$!
phase=build
while IFS= read -r line; do
    printf '%s\n' "$line" >>"$log.log"
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
done <"$work/output"
status=0
wait "$cargo_pid" || status=$?
children_cpu
end_phase "$phase" "$(awk -v a="$REPLY" -v b="$setup_cpu" 'BEGIN { print a - b }')"
awk -v a="$total_start" -v b="$EPOCHREALTIME" -v c="$REPLY" -v d="$start_cpu" \
    'BEGIN { printf "%8.1f s %8.1f s  total\n", b - a, c - d }'
printf 'test-time: after, %s; output in %s.log\n' "$(uptime_load)" "$log"
[ ${#timings[@]} -eq 0 ] || cp target/cargo-timings/cargo-timing.html "$log.html"
if [ "$status" -ne 0 ]; then
    echo "test-time: the test command failed; the end of its output:"
    tail -n 60 "$log.log"
    exit 1
fi
