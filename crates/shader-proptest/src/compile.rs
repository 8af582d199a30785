//! The shader compilers: naga (WGSL), glslang (`glslangValidator`, the compiler Vulkan's GLSL users
//! use, and its HLSL front end) and slangc (the Slang compiler, also for HLSL input), each to
//! SPIR-V words. One function per compiler and input language; the back ends ([`crate::Language`]) choose
//! one for their kernels and layout probes, and any other shader a user builds with this crate goes
//! through them too. glslang runs as a process per shader; slangc's compiler runs in this process,
//! as the library `slangc` loads, with slangc's options (`compile/slang_library.rs`), because
//! starting slangc is most of what it takes to compile a small shader; the Slang modules a shader
//! imports are compiled once per process to binary modules (`compile/slang_modules.rs`).

mod cache;
mod slang_library;
mod slang_modules;

pub use crate::tool::{CompileError, Target};
pub use cache::SPIRV_CACHE_ENV;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Forgets every compile this process kept in memory (the SPIR-V of each shader, and the Slang
/// modules compiled for the shaders that import them): the next compile of each shader runs the compiler
/// (or reads the disk cache) again, as in a new process. For measuring a cold start.
pub fn forget_compiles() {
    cache::forget();
    slang_modules::forget();
}

/// A shader stage: for GLSL named by the file extension glslang reads it from, for Slang by
/// slangc's `-stage`.
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

    /// slangc's name of the stage.
    pub fn slang_name(self) -> &'static str {
        match self {
            Stage::Compute => "compute",
            Stage::RayGeneration => "raygeneration",
            Stage::Miss => "miss",
            Stage::ClosestHit => "closesthit",
        }
    }
}

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
    glslang(source, stage, target, include_dirs, &[])
}

/// [`compile_glsl`] with more of glslang's options, such as `--keep-uncalled` (functions no entry
/// point calls stay in the SPIR-V, as a signature probe needs them).
pub(crate) fn glslang(
    source: &str,
    stage: Stage,
    target: Target,
    include_dirs: &[&Path],
    options: &[&str],
) -> Result<Vec<u32>, CompileError> {
    let mut command = Command::new("glslangValidator");
    command.args(["--target-env", target.glslang_env()]).args(options);
    for dir in include_dirs {
        command.arg(format!("-I{}", dir.display()));
    }
    run_compiler(
        command,
        (source, stage.extension()),
        include_dirs,
        |command, input, output| {
            command.arg("-o").arg(output).arg(input);
        },
    )
}

/// Compiles HLSL (a whole shader with the entry point `main`) as `stage` for `target` with
/// glslang's HLSL front end (`glslangValidator -D`), with `include_dirs` on the include path.
/// Needs `glslangValidator` on the `PATH`. A compile after which glslang printed
/// `Missing functionality` fails (glslang exits with 0 after it).
pub fn compile_hlsl_with_glslang(
    source: &str,
    stage: Stage,
    target: Target,
    include_dirs: &[&Path],
) -> Result<Vec<u32>, CompileError> {
    let mut command = Command::new("glslangValidator");
    command.args(["-D", "-V", "--target-env", target.glslang_env()]);
    command.args(["-S", stage.extension(), "-e", "main"]);
    for dir in include_dirs {
        command.arg(format!("-I{}", dir.display()));
    }
    run_compiler(
        command,
        (source, "hlsl"),
        include_dirs,
        |command, input, output| {
            command.arg("-o").arg(output).arg(input);
        },
    )
}

/// Compiles Slang (a whole shader with the entry point `main`) as `stage` for `target` with slangc,
/// with `search_dirs` on the search path of `import` and `#include`. Every warning is an error.
/// Needs `slangc` on the `PATH` and the Slang library installed with it (`libslang-compiler`, or
/// `libslang` before 2025, beside it or in its `../lib`), which compiles in this process with
/// slangc's options and gives slangc's SPIR-V, byte for byte.
///
/// Two things are particular to the slangc of the `slangtorch` wheel that `scripts/setup.sh`
/// installs on Debian 12, and harmless with any other:
///
/// - `-O0`: that slangc ships without Slang's SPIR-V optimizer library (`spirv-opt`) and refuses
///   to optimize; at `-O0` it writes its SPIR-V directly. The driver optimizes the code anyway.
/// - The source language in the `OpSource` debug instruction is rewritten from Slang (11) to
///   Unknown (0): SPIR-V headers older than Slang's enumerant, such as those of Debian 12's
///   SPIRV-Tools 2023.1 and Vulkan validation layer 1.3.239, reject the whole module for it.
///   Nothing else in the module is changed.
///
/// No layout option is passed: a buffer without a layout in its type gets Slang's default for
/// Vulkan (`std430` for structured buffers and push constants, `std140` for constant buffers),
/// and `StructuredBuffer<T, ScalarDataLayout>` (or `Std430DataLayout`) chooses one per buffer.
pub fn compile_slang(
    source: &str,
    stage: Stage,
    target: Target,
    search_dirs: &[&Path],
) -> Result<Vec<u32>, CompileError> {
    run_slangc(source, "slang", stage, target, search_dirs)
}

/// Compiles HLSL (a whole shader with the entry point `main`) as `stage` for `target` with slangc,
/// which reads a `.hlsl` file as HLSL; otherwise as [`compile_slang`] (the same options, the same
/// `OpSource` rewrite). Needs `slangc` on the `PATH`.
pub fn compile_hlsl_with_slangc(
    source: &str,
    stage: Stage,
    target: Target,
    search_dirs: &[&Path],
) -> Result<Vec<u32>, CompileError> {
    run_slangc(source, "hlsl", stage, target, search_dirs)
}

/// slangc's options for `stage`, `target` and `search_dirs`, run by the Slang library in this
/// process (`compile/slang_library.rs`) on `source` written to a file with `extension`, which
/// names its language.
fn run_slangc(
    source: &str,
    extension: &str,
    stage: Stage,
    target: Target,
    search_dirs: &[&Path],
) -> Result<Vec<u32>, CompileError> {
    let mut options: Vec<OsString> = [
        "-target",
        "spirv",
        "-profile",
        target.slang_profile(),
        "-entry",
        "main",
    ]
    .into_iter()
    .chain(["-stage", stage.slang_name(), "-O0", "-warnings-as-errors", "all"])
    .map(OsString::from)
    .collect();
    for dir in search_dirs {
        options.extend(["-I".into(), dir.as_os_str().to_os_string()]);
    }
    let mut command = Command::new("slangc");
    command.args(&options);
    let key = cache_key(&command, (source, extension), search_dirs);
    let mut words = cached(key, || {
        let modules = if extension == "slang" {
            slang_modules::imported_modules(source, search_dirs)
        } else {
            Vec::new()
        };
        in_temporary_directory(source, extension, |input, output| {
            let dir = output.parent().unwrap_or(Path::new("."));
            for (name, bytes) in modules.iter() {
                std::fs::write(dir.join(name), bytes.as_slice())
                    .map_err(|e| CompileError::NotRun(format!("writing {name}: {e}")))?;
            }
            let arguments: Vec<OsString> = ["-I".into(), dir.as_os_str().into()]
                .into_iter()
                .chain(options.iter().cloned())
                .chain([input.as_os_str().into()])
                .collect();
            let bytes = slang_library::compile(&arguments, input)?;
            crate::spirv::from_bytes(&bytes)
                .map_err(|e| CompileError::NotRun(format!("slangc's output: {e}")))
        })
    })?;
    crate::spirv::without_slang_source_language(&mut words);
    Ok(words)
}

/// What glslang prints, exiting with success, where it translated part of a shader into nothing
/// (in its HLSL front end, a matrix swizzle such as `m._m00_m10_m20`).
const GLSLANG_MISSING: &str = "Missing functionality";

/// Runs a command-line compiler on `source`, written to a file with `extension` in a fresh
/// temporary directory, `include_dirs` on its include path; `arguments` adds the input and output
/// paths to `command`. Returns the output's SPIR-V words, or the compiler's log naming the input
/// file; a run that printed [`GLSLANG_MISSING`] counts as failed. Cached as [`cached`] says.
fn run_compiler(
    mut command: Command,
    (source, extension): (&str, &str),
    include_dirs: &[&Path],
    arguments: impl FnOnce(&mut Command, &Path, &Path),
) -> Result<Vec<u32>, CompileError> {
    let key = cache_key(&command, (source, extension), include_dirs);
    cached(key, || {
        in_temporary_directory(source, extension, |input, output| {
            let program = command.get_program().to_string_lossy().into_owned();
            arguments(&mut command, input, output);
            let run = command
                .output()
                .map_err(|e| CompileError::NotRun(format!("cannot run {program}: {e}")))?;
            if String::from_utf8_lossy(&run.stdout).contains(GLSLANG_MISSING) {
                return Err(CompileError::Failed {
                    log: String::from_utf8_lossy(&run.stdout).into_owned(),
                    source_path: input.display().to_string(),
                });
            }
            crate::spirv::tool_output(&program, &run, std::fs::read(output), "", input)
        })
    })
}

/// The cache's key for compiling `source` with `command` (the compiler and its options, before
/// the input and output paths), and the disk cache's directory, where [`SPIRV_CACHE_ENV`] is
/// set; `None` where the key cannot be made (the compiler's version or an include directory
/// cannot be read).
fn cache_key(
    command: &Command,
    (source, extension): (&str, &str),
    include_dirs: &[&Path],
) -> Option<(Vec<u8>, Option<PathBuf>)> {
    Some((
        cache::key(command, extension, source, include_dirs)?,
        cache::directory(),
    ))
}

/// `compile`'s words; with a `key` (from [`cache_key`]), the words of an earlier compile of the
/// same input by the same compiler come from this process's memory or from the disk cache
/// (`compile/cache.rs`), and a new compile's words go into both.
fn cached(
    key: Option<(Vec<u8>, Option<PathBuf>)>,
    compile: impl FnOnce() -> Result<Vec<u32>, CompileError>,
) -> Result<Vec<u32>, CompileError> {
    let Some((key, dir)) = key else {
        return compile();
    };
    if let Some(words) = cache::remembered(&key) {
        return Ok(words);
    }
    let words = match dir.as_deref().and_then(|dir| cache::lookup(dir, &key)) {
        Some(words) => words,
        None => {
            let words = compile()?;
            if let Some(dir) = &dir {
                cache::store(dir, &key, &words);
            }
            words
        }
    };
    cache::remember(&key, &words);
    Ok(words)
}

/// `compile(input, output)` with `source` written to `input`, a file with `extension` in a fresh
/// temporary directory, and `output` a path beside it; the directory is removed afterwards.
fn in_temporary_directory(
    source: &str,
    extension: &str,
    compile: impl FnOnce(&Path, &Path) -> Result<Vec<u32>, CompileError>,
) -> Result<Vec<u32>, CompileError> {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "shader-proptest-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir)
        .map_err(|e| CompileError::NotRun(format!("creating {}: {e}", dir.display())))?;
    let (input, output) = (dir.join(format!("shader.{extension}")), dir.join("shader.spv"));
    let result = std::fs::write(&input, source)
        .map_err(|e| CompileError::NotRun(format!("writing {}: {e}", input.display())))
        .and_then(|()| compile(&input, &output));
    let _ = std::fs::remove_dir_all(&dir);
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// A second compile of the same input in one process comes from memory; after
    /// `forget_compiles` the compiler runs again.
    #[test]
    fn the_same_input_is_compiled_once_per_process() {
        let command = Command::new("glslangValidator");
        let source = "// the_same_input_is_compiled_once_per_process\nvoid main() {}";
        let key = || {
            let key = cache::key(&command, "comp", source, &[])
                .expect("glslangValidator answers --version (scripts/setup.sh installs it)");
            Some((key, None))
        };
        let runs = Cell::new(0);
        let compile = || {
            runs.set(runs.get() + 1);
            Ok(vec![crate::spirv::MAGIC, 0x0001_0300, 7, 9, 0])
        };
        let first = cached(key(), compile).expect("words");
        let second = cached(key(), compile).expect("words");
        assert_eq!((runs.get(), &first), (1, &second));
        forget_compiles();
        cached(key(), compile).expect("words");
        assert_eq!(runs.get(), 2);
    }
}
