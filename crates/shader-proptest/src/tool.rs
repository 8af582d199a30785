//! What the shader compilers and the SPIR-V tools share: the Vulkan version a shader targets, the
//! error of a compile or a tool run that gave no module, and whether a command-line tool's run
//! succeeded.

use std::fmt;
use std::path::Path;
use std::process::Output;

/// The Vulkan version a shader targets, which fixes its SPIR-V version.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// Vulkan 1.1: SPIR-V 1.3 (compute kernels).
    Vulkan1_1,
    /// Vulkan 1.2: SPIR-V 1.5 (ray tracing).
    Vulkan1_2,
}

impl Target {
    /// The `--target-env` that glslang and SPIRV-Tools take for this target.
    pub(crate) fn glslang_env(self) -> &'static str {
        match self {
            Target::Vulkan1_1 => "vulkan1.1",
            Target::Vulkan1_2 => "vulkan1.2",
        }
    }

    /// The SPIR-V version (major, minor) a module for this target has.
    pub(crate) fn spirv_version(self) -> (u8, u8) {
        match self {
            Target::Vulkan1_1 => (1, 3),
            Target::Vulkan1_2 => (1, 5),
        }
    }

    /// slangc's `-profile` for the SPIR-V version.
    pub(crate) fn slang_profile(self) -> &'static str {
        match self {
            Target::Vulkan1_1 => "spirv_1_3",
            Target::Vulkan1_2 => "spirv_1_5",
        }
    }
}

/// Why a shader produced no SPIR-V.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CompileError {
    /// The compiler could not be run (glslangValidator or slangc missing, a temporary file not
    /// writable).
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

/// `Failed`, with the tool's output after `log_prefix`, where the tool `run` on `input` failed.
pub(crate) fn tool_succeeded(run: &Output, log_prefix: &str, input: &Path) -> Result<(), CompileError> {
    if run.status.success() {
        return Ok(());
    }
    Err(CompileError::Failed {
        log: format!(
            "{log_prefix}{}{}",
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr)
        ),
        source_path: input.display().to_string(),
    })
}
