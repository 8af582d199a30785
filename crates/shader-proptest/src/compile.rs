//! The shader compilers: WGSL through naga, GLSL through glslang (`glslangValidator`, the compiler
//! Vulkan's GLSL users use), each to SPIR-V words. One function per language; kernels, layout
//! probes and any other shader a user builds with this crate go through them.

use std::fmt;
use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A shader language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// WGSL, compiled by naga.
    Wgsl,
    /// GLSL 460, compiled by glslang.
    Glsl,
}

impl Language {
    /// Every language.
    pub const ALL: [Language; 2] = [Language::Wgsl, Language::Glsl];

    /// `"WGSL"` or `"GLSL"`.
    pub fn name(self) -> &'static str {
        match self {
            Language::Wgsl => "WGSL",
            Language::Glsl => "GLSL",
        }
    }
}

impl fmt::Display for Language {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// The Vulkan version a shader targets, which fixes its SPIR-V version.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// Vulkan 1.1: SPIR-V 1.3 (compute kernels).
    Vulkan1_1,
    /// Vulkan 1.2: SPIR-V 1.5 (ray tracing).
    Vulkan1_2,
}

impl Target {
    fn glslang_env(self) -> &'static str {
        match self {
            Target::Vulkan1_1 => "vulkan1.1",
            Target::Vulkan1_2 => "vulkan1.2",
        }
    }

    fn spirv_version(self) -> (u8, u8) {
        match self {
            Target::Vulkan1_1 => (1, 3),
            Target::Vulkan1_2 => (1, 5),
        }
    }
}

/// A GLSL shader stage, named by the file extension glslang reads it from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// `comp`.
    Compute,
    /// `rgen`.
    RayGeneration,
    /// `rmiss`.
    Miss,
    /// `rchit`.
    ClosestHit,
}

impl Stage {
    /// The file extension glslang infers the stage from.
    pub fn extension(self) -> &'static str {
        match self {
            Stage::Compute => "comp",
            Stage::RayGeneration => "rgen",
            Stage::Miss => "rmiss",
            Stage::ClosestHit => "rchit",
        }
    }
}

/// Why a shader produced no SPIR-V.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CompileError {
    /// The compiler could not be run (glslangValidator missing, a temporary file not writable).
    NotRun(String),
    /// The source does not compile: the compiler's message, which names `source_path` and a line.
    Failed {
        /// The compiler's log.
        log: String,
        /// The name the compiler gave the source in its messages.
        source_path: String,
    },
}

impl fmt::Display for CompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompileError::NotRun(message) => write!(f, "{message}"),
            CompileError::Failed { log, .. } => write!(f, "{log}"),
        }
    }
}

impl std::error::Error for CompileError {}

/// The naga capabilities every shader may use: naga's defaults plus `pack2x16float` and
/// `unpack2x16float` (wgpu's downlevel flag `SHADER_F16_IN_F32`, on every Vulkan, Metal and DX12
/// adapter).
pub fn base_capabilities() -> naga::valid::Capabilities {
    naga::valid::Capabilities::default() | naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32
}

/// Parses and validates WGSL with naga, with `capabilities` allowed; errors point into `source`,
/// which messages call `name`.
pub fn validate_wgsl(
    source: &str,
    name: &str,
    capabilities: naga::valid::Capabilities,
) -> Result<(naga::Module, naga::valid::ModuleInfo), CompileError> {
    let failed = |log: String| CompileError::Failed {
        log,
        source_path: name.to_string(),
    };
    let module =
        naga::front::wgsl::parse_str(source).map_err(|e| failed(e.emit_to_string_with_path(source, name)))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| failed(e.emit_to_string_with_path(source, name)))?;
    Ok((module, info))
}

/// Compiles WGSL to SPIR-V for `target` with naga, with `capabilities` allowed (see
/// [`validate_wgsl`]); errors name the source `name`.
pub fn compile_wgsl(
    source: &str,
    name: &str,
    capabilities: naga::valid::Capabilities,
    target: Target,
) -> Result<Vec<u32>, CompileError> {
    let (module, info) = validate_wgsl(source, name, capabilities)?;
    let options = naga::back::spv::Options {
        lang_version: target.spirv_version(),
        ..Default::default()
    };
    naga::back::spv::write_vec(&module, &info, &options, None).map_err(|e| CompileError::Failed {
        log: format!("naga SPIR-V output: {e}"),
        source_path: name.to_string(),
    })
}

/// Compiles GLSL (a whole shader: `#version`, extensions, `main`) as `stage` for `target` with
/// glslang, with `include_dirs` on the include path (`#include` needs
/// `GL_GOOGLE_include_directive`). Needs `glslangValidator` on the `PATH`.
pub fn compile_glsl(
    source: &str,
    stage: Stage,
    target: Target,
    include_dirs: &[&Path],
) -> Result<Vec<u32>, CompileError> {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let stem = std::env::temp_dir().join(format!(
        "shader-proptest-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let (input, output) = (stem.with_extension(stage.extension()), stem.with_extension("spv"));
    std::fs::write(&input, source)
        .map_err(|e| CompileError::NotRun(format!("writing {}: {e}", input.display())))?;
    let mut command = Command::new("glslangValidator");
    command.args(["--target-env", target.glslang_env()]);
    for dir in include_dirs {
        command.arg(format!("-I{}", dir.display()));
    }
    let result = command.arg("-o").arg(&output).arg(&input).output();
    let bytes = std::fs::read(&output);
    let _ = std::fs::remove_file(&input);
    let _ = std::fs::remove_file(&output);
    let result = result.map_err(|e| CompileError::NotRun(format!("cannot run glslangValidator: {e}")))?;
    if !result.status.success() {
        return Err(CompileError::Failed {
            log: format!(
                "{}{}",
                String::from_utf8_lossy(&result.stdout),
                String::from_utf8_lossy(&result.stderr)
            ),
            source_path: input.display().to_string(),
        });
    }
    let bytes = bytes.map_err(|e| CompileError::NotRun(format!("reading glslang's output: {e}")))?;
    Ok(bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect())
}
