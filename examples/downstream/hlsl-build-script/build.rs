//! Compiles `shaders/eye_rays.hlsl` to SPIR-V with glslang's HLSL front end, finding
//! ray-footprint's HLSL modules through the include directory the crate exports to its dependents
//! (`DEP_RAY_FOOTPRINT_HLSL_INCLUDE`). With DXC the same shader compiles with
//! `dxc -spirv -T cs_6_0 -E main -HV 2021 -fspv-target-env=vulkan1.1 -I <that directory>`.

use std::path::PathBuf;
use std::process::Command;

fn main() {
    let include = std::env::var("DEP_RAY_FOOTPRINT_HLSL_INCLUDE")
        .expect("ray-footprint exports its HLSL include directory");
    let output = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("eye_rays.spv");
    println!("cargo:rerun-if-changed=shaders/eye_rays.hlsl");
    // For main to compare with the crate's own HLSL_INCLUDE_DIR.
    println!("cargo:rustc-env=RAY_FOOTPRINT_HLSL_INCLUDE={include}");
    let result = Command::new("glslangValidator")
        .args([
            "-D",
            "-V",
            "--target-env",
            "vulkan1.1",
            "-S",
            "comp",
            "-e",
            "main",
        ])
        .arg(format!("-I{include}"))
        .arg("-o")
        .arg(&output)
        .arg("shaders/eye_rays.hlsl")
        .output()
        .expect("glslangValidator runs (scripts/setup.sh installs it)");
    let log = String::from_utf8_lossy(&result.stdout);
    // glslang reports some HLSL it cannot translate ("Missing functionality: ...") and succeeds.
    assert!(
        result.status.success() && !log.contains("Missing functionality"),
        "glslang:\n{log}"
    );
}
