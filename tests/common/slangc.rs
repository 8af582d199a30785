//! Runs `slangc`, the Slang compiler `scripts/setup.sh` installs, and `spirv-val` on its output.
//!
//! Kernels are compiled the way the crate's Slang users compile: the modules' directory on the
//! search path (`-I`), scalar block layout, every warning an error. `-O0` because the slangc of the
//! `slangtorch` wheel ships without Slang's `spirv-opt` library; Slang then writes its SPIR-V
//! directly, with no optimizer pass.

use ray_footprint::shaders::SLANG_INCLUDE_DIR;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The Slang compiler, found on the `PATH`.
pub const SLANGC: &str = "slangc";

/// `OpSource`, and the `SourceLanguage` operand value Slang writes in it.
const OP_SOURCE: u32 = 3;
const SOURCE_LANGUAGE_SLANG: u32 = 11;

/// A fresh path in the temporary directory ending in `.extension`.
pub fn temp_path(extension: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    std::env::temp_dir().join(format!(
        "ray-footprint-slang-{}-{}.{extension}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ))
}

/// Runs `program` with `args`; `Err` carries its output when it fails, or says how to install it
/// when it cannot be started.
pub fn run(program: &str, args: &[&str]) -> Result<Output, String> {
    let output = Command::new(program).args(args).output().map_err(|error| {
        format!("cannot run {program} ({error}); scripts/setup.sh installs it on Debian 12")
    })?;
    if output.status.success() {
        Ok(output)
    } else {
        Err(format!(
            "{program} {} failed:\n{}{}",
            args.join(" "),
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        ))
    }
}

/// Compiles Slang `source` (entry point `main` for `stage`, SPIR-V version `profile` such as
/// `spirv_1_3`) to SPIR-V words. Errors carry slangc's messages followed by the source.
pub fn compile(source: &str, stage: &str, profile: &str) -> Result<Vec<u32>, String> {
    let (input, output) = (temp_path("slang"), temp_path("spv"));
    std::fs::write(&input, source).map_err(|e| format!("writing {}: {e}", input.display()))?;
    let args = [
        path_str(&input),
        "-target",
        "spirv",
        "-profile",
        profile,
        "-entry",
        "main",
        "-stage",
        stage,
        "-O0",
        "-fvk-use-scalar-layout",
        "-warnings-as-errors",
        "all",
        "-I",
        SLANG_INCLUDE_DIR,
        "-o",
        path_str(&output),
    ];
    let result = run(SLANGC, &args);
    let bytes = std::fs::read(&output);
    let _ = std::fs::remove_file(&input);
    let _ = std::fs::remove_file(&output);
    result.map_err(|log| format!("{log}\n--- source ---\n{source}"))?;
    let bytes = bytes.map_err(|e| format!("reading slangc's output: {e}"))?;
    let mut words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    without_slang_source_language(&mut words);
    Ok(words)
}

/// Replaces the source language `Slang` of the `OpSource` debug instruction by `Unknown`: SPIRV-Tools
/// 2023.1 (Debian 12's spirv-val) and the validation layer 1.3.239 predate that enumerant and reject
/// the whole module for it. Nothing else is touched.
fn without_slang_source_language(words: &mut [u32]) {
    let mut at = 5; // after the header
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if words[at] & 0xffff == OP_SOURCE && words.get(at + 1) == Some(&SOURCE_LANGUAGE_SLANG) {
            words[at + 1] = 0;
        }
        at += count.max(1);
    }
}

/// Runs `spirv-val` on `words` for `target_env` (`vulkan1.1`, `vulkan1.2`), allowing scalar block
/// layout as the kernels use it.
pub fn validate(words: &[u32], target_env: &str) -> Result<(), String> {
    let path = temp_path("spv");
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    std::fs::write(&path, bytes).map_err(|e| format!("writing {}: {e}", path.display()))?;
    let result = run(
        "spirv-val",
        &[
            "--target-env",
            target_env,
            "--scalar-block-layout",
            path_str(&path),
        ],
    );
    let _ = std::fs::remove_file(&path);
    result.map(|_| ())
}

/// A path as the `&str` slangc and spirv-val take on their command line.
pub fn path_str(path: &Path) -> &str {
    path.to_str().expect("the temporary directory and the crate's paths are UTF-8")
}
