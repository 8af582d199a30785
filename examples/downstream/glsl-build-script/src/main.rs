//! Checks the closest-hit shader the build script compiled: SPIR-V that `spirv-val` accepts for
//! Vulkan 1.2. Also shows the include resolver a shaderc include callback can use.

use std::process::{Command, ExitCode};

const CLOSEST_HIT: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/closest_hit.spv"));

fn main() -> ExitCode {
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
