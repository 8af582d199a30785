//! Build script: exports the GLSL include directory to dependents and, with the `validate` feature,
//! parses and validates every shader module with naga so that a broken module fails `cargo build`
//! with naga's message pointing at the file and line.

use std::path::{Path, PathBuf};

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let glsl_dir = root.join("shaders").join("glsl");
    println!("cargo:rerun-if-changed=shaders");
    // Seen by dependents' build scripts as DEP_RAY_FOOTPRINT_GLSL_INCLUDE.
    println!("cargo:glsl_include={}", glsl_dir.display());
    #[cfg(feature = "validate")]
    validate::all(&root.join("shaders"));
}

/// The shader modules of one language, sorted by file name.
#[cfg_attr(not(feature = "validate"), allow(dead_code))]
fn modules(dir: &Path, extension: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("readable directory entry").path())
        .filter(|path| path.extension().is_some_and(|ext| ext == extension))
        .collect();
    files.sort();
    files
}

#[cfg(feature = "validate")]
mod validate {
    use super::modules;
    use std::path::Path;

    /// Line prepended to a GLSL module to make it a complete shader (modules carry no `#version`).
    const GLSL_PREFIX: &str = "#version 460\n";
    /// Entry point appended to a GLSL module: naga's GLSL front end needs one.
    const GLSL_SUFFIX: &str = "\nlayout(local_size_x = 1) in;\nvoid main() {}\n";

    pub fn all(shaders: &Path) {
        let mut failures = Vec::new();
        for path in modules(&shaders.join("wgsl"), "wgsl") {
            failures.extend(wgsl(&path).err());
        }
        for path in modules(&shaders.join("glsl"), "glsl") {
            failures.extend(glsl(&path).err());
        }
        if !failures.is_empty() {
            panic!("shader validation failed:\n\n{}", failures.join("\n"));
        }
    }

    fn read(path: &Path) -> String {
        std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
    }

    /// naga's default capabilities plus `pack2x16float`/`unpack2x16float` (wgpu's downlevel flag
    /// `SHADER_F16_IN_F32`, present on every Vulkan, Metal and DX12 device), used by the packed ray
    /// cone; `f64` only for modules whose stem ends in `_f64`, so no other module can use it.
    fn validator(path: &Path) -> naga::valid::Validator {
        let mut capabilities =
            naga::valid::Capabilities::default() | naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32;
        if path
            .file_stem()
            .is_some_and(|stem| stem.to_string_lossy().ends_with("_f64"))
        {
            capabilities |= naga::valid::Capabilities::FLOAT64;
        }
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
    }

    fn wgsl(path: &Path) -> Result<(), String> {
        let source = read(path);
        let name = path.display().to_string();
        let module =
            naga::front::wgsl::parse_str(&source).map_err(|e| e.emit_to_string_with_path(&source, &name))?;
        validator(path)
            .validate(&module)
            .map_err(|e| e.emit_to_string_with_path(&source, &name))?;
        Ok(())
    }

    fn glsl(path: &Path) -> Result<(), String> {
        let module_source = read(path);
        let source = format!("{GLSL_PREFIX}{module_source}{GLSL_SUFFIX}");
        let name = path.display().to_string();
        let options = naga::front::glsl::Options::from(naga::ShaderStage::Compute);
        let module = naga::front::glsl::Frontend::default()
            .parse(&options, &source)
            .map_err(|errors| {
                let lines: Vec<String> = errors
                    .errors
                    .iter()
                    .map(|error| at(&name, &source, error.meta, &error.kind.to_string()))
                    .collect();
                lines.join("\n")
            })?;
        validator(path).validate(&module).map_err(|error| {
            let span = error.spans().next().map(|(span, _)| *span).unwrap_or_default();
            at(&name, &source, span, &format!("{:?}", error.as_inner()))
        })?;
        Ok(())
    }

    /// `file:line:column: message`, with the line counted in the module file (not the wrapped source).
    fn at(name: &str, wrapped: &str, span: naga::Span, message: &str) -> String {
        let location = span.location(wrapped);
        let prefix_lines = GLSL_PREFIX.lines().count() as u32;
        format!(
            "{name}:{}:{}: {message}",
            location.line_number.saturating_sub(prefix_lines),
            location.line_position
        )
    }
}
