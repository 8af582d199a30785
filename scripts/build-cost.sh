#!/usr/bin/env bash
# What ray-footprint costs a downstream crate: the clean-build time (debug, as `cargo build`) and
# the number of crates pulled in, for the default features and for each optional feature.
# Usage: scripts/build-cost.sh [FEATURE...]   (default: "" validate naga_oil shader-proptest)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo new -q --lib "$work/consumer"
feature_sets=("$@")
[ ${#feature_sets[@]} -gt 0 ] || feature_sets=("" validate naga_oil shader-proptest)

printf '%-10s %8s %8s %s\n' features crates seconds gpu-crates
for features in "${feature_sets[@]}"; do
    cat > "$work/consumer/Cargo.toml" <<TOML
[package]
name = "consumer"
version = "0.0.0"
edition = "2021"

[dependencies]
ray-footprint = { path = "$root", features = [${features:+\"$features\"}] }
TOML
    (cd "$work/consumer" && cargo generate-lockfile -q --offline 2>/dev/null || cargo generate-lockfile -q)
    rm -rf "$work/consumer/target"
    start=$(date +%s%N)
    (cd "$work/consumer" && cargo build -q)
    tenths=$(( ($(date +%s%N) - start) / 100000000 ))
    crates=$(cd "$work/consumer" && cargo tree -q -e normal,build --prefix none | sed 's/ (.*//; s/ (\*)//' | sort -u | grep -vc '^consumer ')
    gpu=$(cd "$work/consumer" && cargo tree -q -e normal --prefix none | grep -cE '^(ash|wgpu|naga|gpu-alloc|vulkan) ' || true)
    printf '%-10s %8s %6d.%d %s\n' "${features:-default}" "$crates" $((tenths / 10)) $((tenths % 10)) "$gpu"
done
