#!/usr/bin/env bash
# Installs what ray-footprint's GPU tests and main job need on Debian 12 (bookworm): the Vulkan
# loader, Mesa's lavapipe >= 24.1 from bookworm-backports (bookworm's own 22.3 lacks ray tracing),
# the Khronos validation layer, glslang and SPIRV-Tools, g++ (the quality lab's nv-flip builds
# NVIDIA's FLIP from C++), Chromium (the browser tests run WGSL in its WebGPU), and the Slang
# compiler slangc. Debian has no Slang package; slangc comes
# from the PyPI wheel slangtorch, which ships slangc and libslang-compiler (and nothing else is taken
# from it: no Python import, no PyTorch). Idempotent: installs only what is missing. Elsewhere it
# prints what to install and exits non-zero.
set -euo pipefail

MIN_MESA=24.1
PACKAGES=(libvulkan1 mesa-vulkan-drivers vulkan-validationlayers glslang-tools spirv-tools g++ python3-pip chromium)
# slangc: the wheel's version, the compiler version it ships, and where it goes.
SLANGTORCH_VERSION=1.3.22
SLANGC_VERSION=2026.14.1
SLANG_DIR=/opt/ray-footprint/slangtorch-$SLANGTORCH_VERSION
SLANGC_LINK=/usr/local/bin/slangc

say() { printf 'setup: %s\n' "$*"; }

other_system() {
    say "this script installs packages on Debian 12 (bookworm) only."
    say "elsewhere, install: the Vulkan loader, Mesa lavapipe >= $MIN_MESA (VK_KHR_ray_tracing_pipeline),"
    say "the Khronos validation layer (VK_LAYER_KHRONOS_validation), glslangValidator, SPIRV-Tools, a C++ compiler,"
    say "Chromium or Chrome (for the browser tests; SHADER_PROPTEST_CHROMIUM names its executable if not on the PATH),"
    say "slangc $SLANGC_VERSION or newer on the PATH (the Vulkan SDK has it; so does the PyPI wheel"
    say "slangtorch==$SLANGTORCH_VERSION as slangtorch/bin/slangc: pip install --no-deps --target DIR),"
    say "and a Rust toolchain (1.87 or newer)."
    exit 1
}

[ -r /etc/os-release ] || other_system
. /etc/os-release
[ "${ID:-}" = debian ] && [ "${VERSION_CODENAME:-}" = bookworm ] || other_system

if [ "$(id -u)" -eq 0 ]; then SUDO=(); elif command -v sudo >/dev/null; then SUDO=(sudo); else
    say "need root (or sudo) to install packages"; exit 1
fi

mesa_version() { dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true; }

install_packages() {
    local missing=() package mesa
    for package in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
    done
    mesa=$(mesa_version)
    if [ -n "$mesa" ] && dpkg --compare-versions "$mesa" lt "$MIN_MESA"; then
        say "mesa-vulkan-drivers $mesa is older than $MIN_MESA"
        missing+=(mesa-vulkan-drivers)
    fi

    if [ ${#missing[@]} -eq 0 ]; then
        say "every package is installed (mesa-vulkan-drivers $mesa)"
        return
    fi

    if ! grep -rqs '^[^#]*bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
        say "adding bookworm-backports"
        echo 'deb http://deb.debian.org/debian bookworm-backports main' |
            "${SUDO[@]}" tee /etc/apt/sources.list.d/bookworm-backports.list >/dev/null
    fi
    say "installing: ${missing[*]}"
    "${SUDO[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq -t bookworm-backports "${PACKAGES[@]}" >/dev/null
    mesa=$(mesa_version)
    if dpkg --compare-versions "$mesa" lt "$MIN_MESA"; then
        say "mesa-vulkan-drivers $mesa is still older than $MIN_MESA"; exit 1
    fi
    say "installed; mesa-vulkan-drivers $mesa"
}

slangc_version() { "$SLANGC_LINK" -v 2>&1 || true; }

# The wheel's declared dependencies (PyTorch and friends) are for its Python API, which nothing
# here uses: --no-deps keeps them out. --target puts the files in SLANG_DIR, outside every Python
# environment, so the system Python is not touched.
install_slangc() {
    if [ "$(slangc_version)" = "$SLANGC_VERSION" ]; then
        say "slangc $SLANGC_VERSION is installed"
        return
    fi
    say "installing slangc $SLANGC_VERSION from the PyPI wheel slangtorch==$SLANGTORCH_VERSION into $SLANG_DIR"
    "${SUDO[@]}" /usr/bin/python3 -m pip install --quiet --no-deps --no-compile --upgrade \
        --root-user-action=ignore --target "$SLANG_DIR" "slangtorch==$SLANGTORCH_VERSION"
    "${SUDO[@]}" ln -sf "$SLANG_DIR/slangtorch/bin/slangc" "$SLANGC_LINK"
    if [ "$(slangc_version)" != "$SLANGC_VERSION" ]; then
        say "$SLANGC_LINK does not report version $SLANGC_VERSION: $(slangc_version)"; exit 1
    fi
    say "installed; $SLANGC_LINK -> $SLANG_DIR/slangtorch/bin/slangc"
}

install_packages
install_slangc
