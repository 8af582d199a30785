//! The inclusion paths, proven by downstream crates in `examples/downstream/`: each is built and run
//! as a user would (`cargo run`), with a path dependency on this crate, and checks its own results.

use std::process::Command;

/// Builds and runs the downstream crate `name` with `cargo run`; it must succeed and print
/// `expected`.
fn run_downstream(name: &str, expected: &str) {
    cargo_downstream("run", name, expected);
}

/// Runs `cargo <command>` (`run` or `test`) on the downstream crate `name`; it must succeed and
/// print `expected`.
fn cargo_downstream(command: &str, name: &str, expected: &str) {
    let root = env!("CARGO_MANIFEST_DIR");
    let manifest = format!("{root}/examples/downstream/{name}/Cargo.toml");
    let output = Command::new(env!("CARGO"))
        .args([
            command,
            "--release",
            "--quiet",
            "--manifest-path",
            &manifest,
            "--target-dir",
        ])
        .arg(format!("{root}/target/downstream"))
        .output()
        .unwrap_or_else(|error| panic!("{name}: cannot run cargo: {error}"));
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{name}:\n{stdout}");
    assert!(output.status.success(), "{name} failed:\n{stdout}\n{stderr}");
    assert!(
        stdout.contains(expected),
        "{name} did not print {expected:?}:\n{stdout}"
    );
}

/// A wgpu user: the WGSL prelude in a compute shader, validated by wgpu and run through its Vulkan
/// backend on lavapipe, compared with the Rust mirror.
#[test]
fn wgpu_compute_shader_agrees_with_the_mirror() {
    run_downstream("wgpu-compute", "LODs computed by wgpu");
}

/// A Bevy user: `#import ray_footprint::ray_cone::...` through naga_oil, validated by naga.
#[test]
fn naga_oil_composes_the_modules() {
    run_downstream("naga-oil", "composed with naga_oil, validated by naga");
}

/// A Vulkan user: a closest-hit shader `#include`s the GLSL modules through the include directory
/// the crate exports to dependents' build scripts, compiled by glslang, accepted by spirv-val.
#[test]
fn glsl_build_script_compiles_a_closest_hit_shader() {
    run_downstream("glsl-build-script", "accepted by spirv-val");
}

/// A Vulkan user writing Slang: a compute shader `import`s the Slang ray-cone module through the
/// directory the crate exports to dependents' build scripts, compiled by slangc, run on lavapipe
/// with the validation layer on and checked against the mirror.
#[test]
fn slang_build_script_compiles_a_compute_shader() {
    run_downstream("slang-build-script", "cases agree with the mirror");
}

/// A Vulkan user writing HLSL: a compute shader `#include`s the HLSL ray-differential module
/// through the directory the crate exports to dependents' build scripts, compiled by glslang's HLSL
/// front end, run on lavapipe with the validation layer on, its eye rays (from glam's matrices in
/// HLSL float4x4s) checked against the mirror.
#[test]
fn hlsl_build_script_compiles_a_compute_shader() {
    run_downstream("hlsl-build-script", "eye rays agree with the mirror");
}

/// A CPU path tracer: the Rust mirror alone, default features, no Vulkan.
#[test]
fn cpu_path_tracer_uses_the_mirror_alone() {
    run_downstream("cpu-path-tracer", "ground rows");
}

/// A user of the harness: their own WGSL, GLSL and Slang functions checked against their own Rust
/// functions with shader-proptest, as an outside crate's tests, on lavapipe.
#[test]
fn shader_proptest_checks_a_users_functions() {
    cargo_downstream("test", "shader-proptest-user", "test result: ok. 3 passed");
}
