//! Runs `glslangValidator`, the GLSL compiler Vulkan users use, on GLSL source text.

use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Why glslang produced no SPIR-V.
#[derive(Debug)]
pub(crate) enum GlslangError {
    /// glslangValidator could not be run, or its files could not be written or read.
    NotRun(String),
    /// The source does not compile: glslang's log, whose errors are prefixed `source_path:line:`.
    Failed { log: String, source_path: String },
}

/// Compiles `source` as the stage named by `stage` (the file extension glslang reads it from:
/// `comp`, `rgen`, `rchit`, `rmiss`) for `target_env` (`vulkan1.1`, `vulkan1.2`) with `include_dirs`
/// on the include path, and returns the SPIR-V words.
pub(crate) fn compile(
    source: &str,
    stage: &str,
    target_env: &str,
    include_dirs: &[&Path],
) -> Result<Vec<u32>, GlslangError> {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let stem = std::env::temp_dir().join(format!(
        "ray-footprint-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let (input, output) = (stem.with_extension(stage), stem.with_extension("spv"));
    std::fs::write(&input, source)
        .map_err(|e| GlslangError::NotRun(format!("writing {}: {e}", input.display())))?;
    let mut command = Command::new("glslangValidator");
    command.args(["--target-env", target_env]);
    for dir in include_dirs {
        command.arg(format!("-I{}", dir.display()));
    }
    let result = command.arg("-o").arg(&output).arg(&input).output();
    let bytes = std::fs::read(&output);
    let _ = std::fs::remove_file(&input);
    let _ = std::fs::remove_file(&output);
    let result = result.map_err(|e| GlslangError::NotRun(format!("cannot run glslangValidator: {e}")))?;
    if !result.status.success() {
        return Err(GlslangError::Failed {
            log: format!(
                "{}{}",
                String::from_utf8_lossy(&result.stdout),
                String::from_utf8_lossy(&result.stderr)
            ),
            source_path: input.display().to_string(),
        });
    }
    let bytes = bytes.map_err(|e| GlslangError::NotRun(format!("reading glslang output: {e}")))?;
    Ok(bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect())
}
