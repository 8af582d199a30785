#!/usr/bin/env bash
# Runs the checks, tests, gallery and benchmarks of ray-footprint on a machine with a real GPU
# from binaries built elsewhere (no Rust toolchain, no network there), and writes a few small logs.
#
# 1. Here, on the build machine (Debian 12, scripts/setup.sh done), from the repository root:
#
#        [RAY_FOOTPRINT_PEERS=DIR] scripts/nvidia-run.sh pack
#
#    builds the release binaries and puts into .nvidia/ (ignored by git):
#      bin/      verify, gallery, quality, cost_quality, gpu-tests (tests/gpu), mode_costs,
#                function_costs, verification_speed, stripped
#      debs/     the Vulkan loader and the GL/X libraries the NVIDIA driver's ICD loads
#                (libvulkan1, libglvnd0, libegl1, libgl1, libglx0, libgles2, libx11-6 and what it
#                needs), vulkan-validationlayers, glslang-tools, spirv-tools (amd64)
#      slang/    slangc and its libraries, copied from the slangc on the PATH (scripts/setup.sh
#                installs it), for the Slang checks and the Slang closest hit
#      peers/    with RAY_FOOTPRINT_PEERS, the peers' files function_costs times beside the
#                library's functions, copied from under DIR (a Falcor checkout, the
#                vk_raytracing_tutorial_KHR, nvpro_core2): TexLODHelpers.slang, wireframe.h.slang or
#                wireframe_helpers.h.slang, rtraydifferentials.slang; never part of the repository
#      build-root  the directory the binaries were built in (they read shaders from there)
#
# 2. There, from a copy of the repository at the same commit with .nvidia/ beside the sources
#    (the only path to carry), as root:
#
#        SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh run OUT_DIR
#        SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh costs OUT_DIR
#        SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh seeds OUT_DIR SEED...
#        SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh speed OUT_DIR [--batch N]
#        SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh quality OUT_DIR 240x160 360x240
#
#    Both unpack the Vulkan loader and its GL/X libraries into / where the system has no loader,
#    and the validation layer, glslangValidator and spirv-opt under /opt/gl (nothing else under
#    /), put .nvidia/slang on the PATH, link the build directory to the repository copy if the
#    paths differ, and run with the validation layer on (any message fails the run) on the
#    device SHADER_PROPTEST_DEVICE names (lavapipe without it). `run` writes seven files:
#      verify (every check, 100,000 cases per function and language)   -> verify.log
#      the GPU tests (agreement, abi, degenerate, rt); the WGSL ray-query test
#        apart: "not run" with the reason where the device has no ray queries -> gpu-tests.log
#      the gallery at its default size                                   -> gallery.log, ground_modes.png
#      the quality lab at its default settings                           -> quality.log
#      bench verification_speed                                          -> verification_speed.log
#      summary.txt (also printed last)
#    `costs` writes seven:
#      bench mode_costs (3840 x 2160, 2 x 2 samples, every lab scene and mode, 8 rounds)
#                                                                        -> mode_costs.log, mode_costs.csv
#      bench function_costs (every function in 5 languages, each beside its empty kernel,
#        and the peers' originals from .nvidia/peers where packed)       -> function_costs.log
#      the quality lab at its default settings, then cost_quality: the quality gained over mip 0
#        against the time added                                          -> quality.log,
#                                                                           cost_quality.log, cost_quality.png
#      costs-summary.txt (also printed last)
#    `seeds` runs the GPU test binary once per seed     -> gpu-tests-seed-SEED.log, seeds-summary.txt
#    `speed` runs bench verification_speed on every processor with a SPIR-V cache
#      (SHADER_PROPTEST_SPIRV_CACHE): one pass that fills a cache and warms the machine, then two
#      rounds of a pass with an empty cache (cold) and one with the filled cache (warm); flags
#      after OUT_DIR go to verification_speed. With SPEED_BASELINE naming a verification_speed
#      built from another commit (in the same build root), each round runs it warm just before
#      the warm pass, for a comparison on the same machine at the same clocks
#                                            -> speed-ROUND-cold.log, speed-ROUND-warm.log,
#                                               speed-ROUND-baseline.log, speed-summary.txt
#    `quality` runs the quality lab (every scene and method) once per image size WIDTHxHEIGHT:
#      a goal must hold at every size        -> quality-WxH.log, quality-WxH/table.md, quality-summary.txt
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
PACK="$ROOT/.nvidia"
BIN="$PACK/bin"
# Installed into / where the system has no Vulkan loader (the driver's ICD loads them from there).
LOADER_DEBS=(libvulkan1 libglvnd0 libegl1 libgl1 libglx0 libgles2 libx11-6 libxcb1 libxau6 libxdmcp6
    libbsd0 libmd0 libffi8 libwayland-client0)
# Installed under /opt/gl.
TOOL_DEBS=(vulkan-validationlayers glslang-tools spirv-tools)
DEBS=("${LOADER_DEBS[@]}" "${TOOL_DEBS[@]}")
OPT=/opt/gl

say() { printf 'nvidia-run: %s\n' "$*"; }

# The executable cargo built for each target `kind:name` in its JSON messages on stdin.
executables() {
    python3 -c '
import json, sys
for line in sys.stdin:
    message = json.loads(line)
    if message.get("reason") == "compiler-artifact" and message.get("executable"):
        target = message["target"]
        print(target["kind"][0] + ":" + target["name"], message["executable"])
'
}

pack() {
    set -e
    cd "$ROOT"
    say "building the release binaries"
    local built
    built=$(cargo build --release -p ray-footprint-lab --all-features --examples --tests --benches \
        --message-format=json | executables)
    rm -rf "$PACK"
    mkdir -p "$BIN" "$PACK/debs"
    local target name
    for target in example:verify example:gallery example:quality example:cost_quality test:gpu \
        bench:mode_costs bench:function_costs bench:verification_speed; do
        name=${target#*:}
        [ "$name" = gpu ] && name=gpu-tests
        local path
        path=$(printf '%s\n' "$built" | awk -v t="$target" '$1 == t { print $2 }' | tail -n 1)
        [ -n "$path" ] || { say "no executable for $target"; exit 1; }
        cp "$path" "$BIN/$name"
        strip "$BIN/$name"
    done
    say "downloading ${DEBS[*]}"
    local lists=/tmp/nvidia-run-apt-lists
    mkdir -p "$lists/partial"
    local options=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$lists")
    apt-get "${options[@]}" update -qq
    (cd "$PACK/debs" && apt-get "${options[@]}" download "${DEBS[@]}")
    local slangc
    slangc=$(readlink -f "$(command -v slangc)") || { say "no slangc on the PATH: run scripts/setup.sh"; exit 1; }
    say "copying $(dirname "$slangc")"
    cp -r "$(dirname "$slangc")" "$PACK/slang"
    pwd >"$PACK/build-root"
    pack_peers
    du -sh "$PACK"
    say "carry .nvidia/ with the repository; there run: SHADER_PROPTEST_DEVICE=nvidia scripts/nvidia-run.sh run OUT_DIR"
}

# The peers' files under $RAY_FOOTPRINT_PEERS, into .nvidia/peers (nothing when it is unset).
pack_peers() {
    [ -n "${RAY_FOOTPRINT_PEERS:-}" ] || { say "no RAY_FOOTPRINT_PEERS: function_costs will say the peers were not run"; return 0; }
    mkdir -p "$PACK/peers"
    local name path
    for name in TexLODHelpers.slang wireframe.h.slang wireframe_helpers.h.slang rtraydifferentials.slang; do
        path=$(find "$RAY_FOOTPRINT_PEERS" -name "$name" -type f -print -quit)
        [ -n "$path" ] && cp "$path" "$PACK/peers/" && say "peer: $path"
    done
}

# The Vulkan loader (into / where the system has none), the layer and the tools (under /opt/gl).
install_packages() {
    [ -d "$PACK/debs" ] || return 0
    local has_loader=false name
    ldconfig -p | grep -q 'libvulkan.so.1 ' && has_loader=true
    for name in "${LOADER_DEBS[@]}"; do
        $has_loader || dpkg -x "$PACK"/debs/"${name}"_*.deb /
    done
    mkdir -p "$OPT"
    for name in "${TOOL_DEBS[@]}"; do
        dpkg -x "$PACK"/debs/"${name}"_*.deb "$OPT"
    done
    ldconfig
}

setup_environment() {
    if [ -d "$OPT/usr" ]; then
        export PATH="$OPT/usr/bin:$PATH"
        export LD_LIBRARY_PATH="$OPT/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
        export VK_LAYER_PATH="$OPT/usr/share/vulkan/explicit_layer.d"
    fi
    if [ -x "$PACK/slang/slangc" ]; then
        export PATH="$PACK/slang:$PATH"
    fi
    local nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
    if [ -n "${SHADER_PROPTEST_DEVICE:-}" ] && [ -f "$nvidia_icd" ] && ! ls /usr/share/vulkan/icd.d/nvidia* \
        /etc/vulkan/icd.d/nvidia* >/dev/null 2>&1; then
        export VK_DRIVER_FILES="$nvidia_icd"
    fi
    if [ -d "$PACK/peers" ]; then
        export RAY_FOOTPRINT_PEERS="$PACK/peers"
    fi
    # The binaries read the shaders from the directory they were built in.
    local built
    built=$(cat "$PACK/build-root" 2>/dev/null || echo "$ROOT")
    if [ "$built" != "$ROOT" ] && [ ! -e "$built" ]; then
        mkdir -p "$(dirname "$built")"
        ln -s "$ROOT" "$built"
    fi
}

# Runs a step: its name, its log, then the command; records the exit status and the seconds.
STEPS=()
step() {
    local name=$1 log=$2
    shift 2
    say "$name ..."
    local started=$SECONDS
    "$@" >"$log" 2>&1
    local status=$?
    STEPS+=("$(printf '%-22s exit %3d  %4d s' "$name" "$status" $((SECONDS - started)))")
}

# Makes the output directory $1 and prints its absolute path.
output_dir() {
    mkdir -p "$1" && cd "$1" && pwd
}

# Unpacks, sets the environment, and checks that the binaries are there.
prepare() {
    install_packages
    setup_environment
    [ -d "$BIN" ] || { say "no binaries in $BIN: run 'scripts/nvidia-run.sh pack' on the build machine"; exit 2; }
    cd "$ROOT"
}

run() {
    local out
    out=$(output_dir "${1:?usage: nvidia-run.sh run OUT_DIR}")
    prepare
    local wgsl_test=rt::wgsl_ray_query_agrees_with_the_mirror
    local gallery_dir
    gallery_dir=$(mktemp -d)
    step verify "$out/verify.log" "$BIN/verify"
    # One test at a time: on the H100 (driver 580) 16 tests at once, each with its own device and
    # validation layer, had not finished after 200 s; one at a time they take seconds each.
    step "gpu tests" "$out/gpu-tests.log" "$BIN/gpu-tests" --test-threads 1 --skip "$wgsl_test"
    step "wgsl ray-query test" "$out/wgsl.tmp" "$BIN/gpu-tests" "$wgsl_test" --exact --nocapture
    step gallery "$out/gallery.log" "$BIN/gallery" --out "$gallery_dir"
    cp "$gallery_dir/ground_modes.png" "$out/" 2>/dev/null
    step quality "$out/quality.log" "$BIN/quality" --out "$gallery_dir/quality"
    step "verification speed" "$out/verification_speed.log" "$BIN/verification_speed"
    rm -rf "$gallery_dir"
    { printf '\n--- %s ---\n' "$wgsl_test"; cat "$out/wgsl.tmp"; } >>"$out/gpu-tests.log"
    rm -f "$out/wgsl.tmp"
    summary "$out" | tee "$out/summary.txt"
}

costs() {
    local out
    out=$(output_dir "${1:?usage: nvidia-run.sh costs OUT_DIR}")
    prepare
    local quality_dir
    quality_dir=$(mktemp -d)
    step "mode costs" "$out/mode_costs.log" "$BIN/mode_costs" --csv "$out/mode_costs.csv"
    step "function costs" "$out/function_costs.log" "$BIN/function_costs"
    step quality "$out/quality.log" "$BIN/quality" --out "$quality_dir"
    step "cost against quality" "$out/cost_quality.log" "$BIN/cost_quality" --quality "$quality_dir/table.csv" \
        --costs "$out/mode_costs.csv" --out "$out/cost_quality.png"
    rm -rf "$quality_dir"
    costs_summary "$out" | tee "$out/costs-summary.txt"
}

# The GPU test binary once per seed (SHADER_PROPTEST_SEED), one test at a time: a randomized suite
# must pass under every seed. One log per seed, and a line per seed in seeds-summary.txt.
seeds() {
    local out
    out=$(output_dir "${1:?usage: nvidia-run.sh seeds OUT_DIR SEED...}")
    shift
    [ $# -gt 0 ] || { echo "usage: nvidia-run.sh seeds OUT_DIR SEED..." >&2; exit 2; }
    prepare
    local seed
    for seed in "$@"; do
        SHADER_PROPTEST_SEED=$seed step "gpu tests seed $seed" "$out/gpu-tests-seed-$seed.log" \
            "$BIN/gpu-tests" --test-threads 1 --skip rt::wgsl_ray_query_agrees_with_the_mirror
    done
    {
        printf '%s\n' "${STEPS[@]}"
        for seed in "$@"; do
            echo "seed $seed: $(grep -m1 '^test result' "$out/gpu-tests-seed-$seed.log")"
            { grep -A3 '^failures:$' "$out/gpu-tests-seed-$seed.log" || true; } | head -n 8
        done
    } | tee "$out/seeds-summary.txt"
}

# verification_speed on every processor: a pass that fills a SPIR-V cache (and warms the clocks),
# then rounds of an empty cache (cold) and the filled one (warm), interleaved.
speed() {
    local out threads filled round cold
    out=$(output_dir "${1:?usage: nvidia-run.sh speed OUT_DIR [verification_speed flags]}")
    shift
    prepare
    threads=$(nproc)
    filled=$(mktemp -d)
    SHADER_PROPTEST_SPIRV_CACHE=$filled step "speed, filling" "$out/speed-fill.log" \
        "$BIN/verification_speed" --threads "$threads" "$@"
    for round in 1 2; do
        cold=$(mktemp -d)
        SHADER_PROPTEST_SPIRV_CACHE=$cold step "speed $round, cold cache" "$out/speed-$round-cold.log" \
            "$BIN/verification_speed" --threads "$threads" "$@"
        rm -rf "$cold"
        if [ -n "${SPEED_BASELINE:-}" ]; then
            SHADER_PROPTEST_SPIRV_CACHE=$filled step "speed $round, baseline, warm cache" \
                "$out/speed-$round-baseline.log" "$SPEED_BASELINE" --threads "$threads" "$@"
        fi
        SHADER_PROPTEST_SPIRV_CACHE=$filled step "speed $round, warm cache" "$out/speed-$round-warm.log" \
            "$BIN/verification_speed" --threads "$threads" "$@"
    done
    rm -rf "$filled"
    {
        printf '%s\n' "${STEPS[@]}"
        for log in "$out"/speed-[12]-*.log; do
            echo "$(basename "$log" .log): $(grep -A2 '^| threads' "$log" | tail -n 1)"
        done
        sed -n '/^| phase/,$p' "$out/speed-2-warm.log"
    } | tee "$out/speed-summary.txt"
}

# The quality lab once per image size (WIDTHxHEIGHT), each run's table kept beside its log.
quality() {
    local out size
    out=$(output_dir "${1:?usage: nvidia-run.sh quality OUT_DIR WIDTHxHEIGHT...}")
    shift
    [ $# -gt 0 ] || { echo "usage: nvidia-run.sh quality OUT_DIR WIDTHxHEIGHT..." >&2; exit 2; }
    prepare
    for size in "$@"; do
        step "quality $size" "$out/quality-$size.log" "$BIN/quality" --width "${size%x*}" --height "${size#*x}" \
            --out "$out/quality-$size"
        rm -rf "$out/quality-$size/truth" "$out/quality-$size/images" "$out/quality-$size/crops" \
            "$out/quality-$size/flip"
    done
    {
        printf '%s\n' "${STEPS[@]}"
        for size in "$@"; do
            echo "$size: $(grep -m1 '^goals (' "$out/quality-$size.log")"
            grep -F -- '- **MISSED**' "$out/quality-$size.log" || true
        done
    } | tee "$out/quality-summary.txt"
}

# The lines that say how each step went.
summary() {
    local out=$1
    echo "device and driver: $(grep -m1 '^device:' "$out/verify.log")"
    printf '%s\n' "${STEPS[@]}"
    echo "verify: $(tail -n 1 "$out/verify.log")"
    echo "gpu tests: $(grep -m1 '^test result' "$out/gpu-tests.log")"
    local wgsl
    wgsl=$(sed -n '/^--- rt::wgsl/,$p' "$out/gpu-tests.log")
    if grep -q '^test result: ok' <<<"$wgsl"; then
        echo "wgsl ray-query test: passed"
    elif grep -q 'not supported' <<<"$wgsl"; then
        echo "wgsl ray-query test: not run: $(grep -m1 -o 'not supported: .*' <<<"$wgsl")"
    else
        echo "wgsl ray-query test: FAILED (see gpu-tests.log)"
    fi
    echo "gallery: $(grep -m1 '^image size' "$out/gallery.log"); $(grep -m1 '^files written' "$out/gallery.log")"
    echo "quality lab: $(grep -c '' "$out/quality.log") lines (quality.log)"
    echo "verification speed:"
    sed -n '/^| threads/,$p' "$out/verification_speed.log"
    grep -h 'VUID\|Validation\|validation layer' "$out"/*.log | head -n 5
    true
}

# The lines that say how each cost step went, and the tables.
costs_summary() {
    local out=$1
    echo "device and driver: $(grep -m1 '^device:' "$out/mode_costs.log")"
    printf '%s\n' "${STEPS[@]}"
    grep -h '^GPU clocks' "$out/mode_costs.log" "$out/function_costs.log"
    grep -h -A2 '^goal' "$out/mode_costs.log"
    grep -h '^not run\|^error' "$out"/*.log | head -n 5
    echo "function costs against the peers:"
    grep '^| .*: \(met\|MISSED\|not separable\)' "$out/function_costs.log"
    echo "quality gained against time added:"
    grep '^|' "$out/cost_quality.log"
    grep -h 'VUID\|Validation\|validation layer' "$out"/*.log | head -n 5
    # A grep that finds nothing is no failure of the run.
    true
}

case "${1:-}" in
    pack) pack ;;
    run) shift && run "$@" ;;
    costs) shift && costs "$@" ;;
    seeds) shift && seeds "$@" ;;
    speed) shift && speed "$@" ;;
    quality) shift && quality "$@" ;;
    *)
        echo "usage: scripts/nvidia-run.sh pack | run OUT_DIR | costs OUT_DIR | seeds OUT_DIR SEED... | speed OUT_DIR [FLAGS] | quality OUT_DIR WIDTHxHEIGHT..." >&2
        exit 2
        ;;
esac
