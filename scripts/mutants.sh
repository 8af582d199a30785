#!/usr/bin/env bash
# Mutation score of the Rust mirror: cargo-mutants changes src/ray_cone.rs, src/ray_diff.rs,
# src/ray_diff_f64.rs and src/wireframe.rs one mutant at a time (an operator swapped, a body
# replaced by a default value, a condition negated...) and runs the CPU tests that pin the mirror
# down: the root crate's unit tests and its math and bad-input tests, and ray-footprint-cases'
# records and independent references. No GPU test runs, so the score measures what the references
# and the CPU tests catch, not what agreement with the shaders would. The tests build with the
# `mutants` profile (Cargo.toml: optimised, no debug information).
#
# Usage: scripts/mutants.sh [OUT_DIR] [cargo-mutants arguments...]
#   scripts/mutants.sh target/mutants-report -j 8                      every mutant, 8 at a time
#   scripts/mutants.sh target/mutants-report --shard 0/12 --sharding round-robin
#                                                               every 12th mutant, a sample
#
# cargo-mutants (the version below) is installed with `cargo install` when missing. Writes
# OUT_DIR/mutants.out (default target/mutants-report) and prints the counts, the score (caught over
# viable mutants: caught, missed and timed out) and every surviving mutant.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
version=27.1.0
out=${1:-$root/target/mutants-report}
shift || true
if ! cargo mutants --version 2>/dev/null | grep -q "$version"; then
    cargo install --locked --version "$version" cargo-mutants
fi
cd "$root"
# Each copy of the tree builds into its own target directory.
unset CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR
tests=(--lib --test bad_input --test ray_cone_math
    --test ray_diff_cone_math --test ray_diff_math --test wireframe_math
    --test records --test references)
test_args=()
for arg in "${tests[@]}"; do
    test_args+=(--cargo-test-arg="$arg")
done
# The unmutated tree must pass these tests first. cargo-mutants' own baseline would run only the
# mutated package's tests, where the cases crate's test names do not exist.
cargo test --profile mutants -p ray-footprint -p ray-footprint-cases "${tests[@]}"
mkdir -p "$out"
status=0
cargo mutants --package ray-footprint \
    -f src/ray_cone.rs -f src/ray_diff.rs -f src/ray_diff_f64.rs -f src/wireframe.rs \
    --test-package ray-footprint,ray-footprint-cases "${test_args[@]}" \
    --profile mutants --baseline skip --build-timeout 1800 --timeout 300 \
    --output "$out" "$@" || status=$?
# cargo-mutants exits 2 when a mutant survives and 3 when one times out; both still give a score.
case $status in 0 | 2 | 3) ;; *) exit "$status" ;; esac
results=$out/mutants.out
count() {
    if [ -f "$results/$1.txt" ]; then awk 'NF { n++ } END { print n + 0 }' "$results/$1.txt"; else echo 0; fi
}
caught=$(count caught)
missed=$(count missed)
timeout=$(count timeout)
unviable=$(count unviable)
viable=$((caught + missed + timeout))
echo "mutants: $caught caught, $missed missed, $timeout timed out, $unviable unviable"
if [ "$viable" -gt 0 ]; then
    awk -v caught="$caught" -v viable="$viable" \
        'BEGIN { printf "score: %d of %d viable mutants caught = %.1f%%\n", caught, viable, 100 * caught / viable }'
fi
if [ "$missed" -gt 0 ]; then
    echo "survivors:"
    sed 's/^/  /' "$results/missed.txt"
fi
