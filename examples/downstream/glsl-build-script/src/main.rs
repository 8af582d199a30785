//! Checks the closest-hit shader the build script compiled: SPIR-V that `spirv-val` accepts for
//! Vulkan 1.2, and the include directory it was compiled with. Also shows the include resolver a
//! shaderc include callback can use.

use ray_footprint::shaders::{Module, GLSL_INCLUDE_DIR};
use std::path::Path;
use std::process::{Command, ExitCode};

const CLOSEST_HIT: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/closest_hit.spv"));

/// The include directory the build script was given (`DEP_RAY_FOOTPRINT_GLSL_INCLUDE`): the
/// crate's `GLSL_INCLUDE_DIR`, holding every module as the crate embeds it.
fn include_directory() -> Result<&'static str, String> {
    let exported = env!("RAY_FOOTPRINT_GLSL_INCLUDE");
    if exported != GLSL_INCLUDE_DIR {
        return Err(format!(
            "the build script got {exported}, the crate names {GLSL_INCLUDE_DIR}"
        ));
    }
    for module in Module::ALL {
        let path = Path::new(exported).join(format!("{}.glsl", module.stem()));
        let text = std::fs::read_to_string(&path).map_err(|error| format!("{}: {error}", path.display()))?;
        if text != module.glsl() {
            return Err(format!("{} differs from the embedded module", path.display()));
        }
    }
    Ok(exported)
}

fn main() -> ExitCode {
    match include_directory() {
        Ok(directory) => println!("GLSL modules in {directory}, as embedded"),
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    }
    let magic = CLOSEST_HIT
        .get(..4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    if magic != Some(0x0723_0203) {
        eprintln!("error: the build script's output is not SPIR-V");
        return ExitCode::FAILURE;
    }
    let path = std::env::temp_dir().join(format!("closest_hit-{}.spv", std::process::id()));
    let validated = std::fs::write(&path, CLOSEST_HIT).and_then(|()| {
        Command::new("spirv-val")
            .args(["--target-env", "vulkan1.2"])
            .arg(&path)
            .output()
    });
    let _ = std::fs::remove_file(&path);
    match validated {
        Ok(output) if output.status.success() => {}
        Ok(output) => {
            eprintln!("error: spirv-val: {}", String::from_utf8_lossy(&output.stderr));
            return ExitCode::FAILURE;
        }
        Err(error) => {
            eprintln!("error: cannot run spirv-val: {error}");
            return ExitCode::FAILURE;
        }
    }
    println!(
        "closest-hit shader: {} bytes of SPIR-V, accepted by spirv-val (vulkan1.2)",
        CLOSEST_HIT.len()
    );
    // A shaderc include callback would answer `#include "wireframe.glsl"` like this:
    match ray_footprint::shaders::resolve_glsl_include("wireframe.glsl") {
        Ok((name, source)) => println!("resolver: wireframe.glsl -> {name} ({} bytes)", source.len()),
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}
