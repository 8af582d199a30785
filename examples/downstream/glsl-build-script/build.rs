//! Compiles `shaders/closest_hit.rchit` with glslang, finding ray-footprint's GLSL modules through
//! the include directory the crate exports to its dependents (`DEP_RAY_FOOTPRINT_GLSL_INCLUDE`).

use std::path::PathBuf;
use std::process::Command;

fn main() {
    let include = std::env::var("DEP_RAY_FOOTPRINT_GLSL_INCLUDE")
        .expect("ray-footprint exports its GLSL include directory");
    let output = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("closest_hit.spv");
    println!("cargo:rerun-if-changed=shaders/closest_hit.rchit");
    // For main to compare with the crate's own GLSL_INCLUDE_DIR.
    println!("cargo:rustc-env=RAY_FOOTPRINT_GLSL_INCLUDE={include}");
    let result = Command::new("glslangValidator")
        .args(["--target-env", "vulkan1.2"])
        .arg(format!("-I{include}"))
        .arg("-o")
        .arg(&output)
        .arg("shaders/closest_hit.rchit")
        .output()
        .expect("glslangValidator runs (scripts/setup.sh installs it)");
    assert!(
        result.status.success(),
        "glslang:\n{}",
        String::from_utf8_lossy(&result.stdout)
    );
}
