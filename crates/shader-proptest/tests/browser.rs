//! The same checks in headless Chromium's WebGPU (feature `browser`): a right WGSL function
//! passes, a wrong one fails and shrinks as on the Vulkan path, a kernel Tint rejects, a shader
//! that needs 64-bit floats, a GLSL shader, a missing Chromium and a page that never answers
//! each end with what happened.

use shader_proptest::{
    BrowserDevice, Chromium, ChromiumOptions, Error, FunctionCheck, LoopbackServer, Outcome, Response,
    RunConfig, Shader, Tolerance,
};
use std::time::{Duration, Instant};

const FALLOFF: &str = "fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }";

/// The falloff of the WGSL above, with `smoothstep`'s formula.
fn falloff((d, r0, r1): (f32, f32, f32)) -> f32 {
    let t = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

/// The falloff check on d in 0..10, r0 in 0..1, r1 in 1.5..5. Vulkan and WebGPU let `smoothstep`
/// be computed with its own roundings: a handful of ULP of 1 is an absolute 1e-6.
fn check() -> FunctionCheck<(f32, f32, f32), f32> {
    FunctionCheck::new("falloff", || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0), falloff)
        .tolerance(Tolerance::Absolute(1.0e-6))
}

fn config() -> RunConfig {
    RunConfig {
        cases: 20_000,
        seed: Some(5),
        ..RunConfig::default()
    }
}

fn device() -> BrowserDevice {
    BrowserDevice::new().unwrap_or_else(|error| panic!("{error}\non Debian 12 run `scripts/setup.sh`"))
}

#[test]
fn a_wgsl_check_runs_in_the_browser() {
    let device = device();
    let report = check()
        .run_browser(&device, &Shader::wgsl(FALLOFF), &config())
        .unwrap_or_else(|error| panic!("{error}"));
    println!("{report}");
    assert!(report.device.contains("through Chromium"), "{}", report.device);
    assert!(report.device.ends_with("WebGPU"), "{}", report.device);
    assert_eq!(report.cases, 20_000);
    report.assert_passed();
}

#[test]
fn a_wrong_function_fails_and_shrinks_in_the_browser() {
    let device = device();
    let broken = Shader::wgsl(FALLOFF.replace("r1, d)", "r1 + 1.0, d)"));
    let report = check()
        .run_browser(&device, &broken, &config())
        .unwrap_or_else(|error| panic!("{error}"));
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("the broken falloff passed: {report}")
    };
    println!("{report}");
    assert!(failure.input.ends_with(", 0.0, 1.5)"), "{}", failure.input);
}
