//! Compiles `shaders/footprint.slang` with slangc, finding ray-footprint's Slang modules through the
//! directory the crate exports to its dependents (`DEP_RAY_FOOTPRINT_SLANG_INCLUDE`).

use std::path::PathBuf;
use std::process::Command;

fn main() {
    let include = std::env::var("DEP_RAY_FOOTPRINT_SLANG_INCLUDE")
        .expect("ray-footprint exports its Slang module directory");
    let output = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("footprint.spv");
    println!("cargo:rerun-if-changed=shaders/footprint.slang");
    // For main to compare with the crate's own SLANG_INCLUDE_DIR.
    println!("cargo:rustc-env=RAY_FOOTPRINT_SLANG_INCLUDE={include}");
    // -O0: the slangc of the PyPI wheel that scripts/setup.sh installs has no SPIR-V optimizer.
    // -fvk-use-scalar-layout: scalar buffer layout, as nvpro's samples use; the crate's structs
    // have the same layout under it as under Slang's default std430.
    let result = Command::new("slangc")
        .arg("shaders/footprint.slang")
        .args([
            "-target",
            "spirv",
            "-profile",
            "spirv_1_3",
            "-entry",
            "main",
            "-stage",
            "compute",
        ])
        .args([
            "-O0",
            "-fvk-use-scalar-layout",
            "-warnings-as-errors",
            "all",
            "-I",
        ])
        .arg(&include)
        .arg("-o")
        .arg(&output)
        .output()
        .expect("slangc runs (scripts/setup.sh installs it)");
    assert!(
        result.status.success(),
        "slangc:\n{}{}",
        String::from_utf8_lossy(&result.stdout),
        String::from_utf8_lossy(&result.stderr)
    );
}
