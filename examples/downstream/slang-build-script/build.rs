//! Compiles `shaders/footprint.slang` with slangc, finding ray-footprint's Slang modules through the
//! directory the crate exports to its dependents (`DEP_RAY_FOOTPRINT_SLANG_INCLUDE`).

use std::path::PathBuf;
use std::process::Command;

/// `OpSource`, and the source-language values Slang writes in it and the one written instead.
const OP_SOURCE: u32 = 3;
const SOURCE_LANGUAGE_SLANG: u32 = 11;
const SOURCE_LANGUAGE_UNKNOWN: u32 = 0;

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
    let spirv = std::fs::read(&output).expect("slangc wrote its output");
    std::fs::write(&output, without_slang_source_language(&spirv)).expect("rewriting the SPIR-V");
}

/// The SPIR-V with the source language of `OpSource` changed from Slang to Unknown. SPIR-V tools
/// older than Slang's enumerant, such as Debian 12's SPIRV-Tools 2023.1 and Vulkan validation
/// layer 1.3.239, reject a module that names it; newer ones need no such change.
fn without_slang_source_language(bytes: &[u8]) -> Vec<u8> {
    let mut words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    let mut at = 5; // after the header
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if words[at] & 0xffff == OP_SOURCE && words.get(at + 1) == Some(&SOURCE_LANGUAGE_SLANG) {
            words[at + 1] = SOURCE_LANGUAGE_UNKNOWN;
        }
        at += count.max(1);
    }
    words.iter().flat_map(|word| word.to_le_bytes()).collect()
}
