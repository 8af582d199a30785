//! The same checks through wgpu (feature `wgpu`), here on lavapipe through wgpu's Vulkan backend:
//! a right WGSL function passes, a wrong one fails and shrinks as on the Vulkan path, and a GLSL
//! shader is refused.

use shader_proptest::{Error, FunctionCheck, Outcome, RunConfig, Shader, Tolerance, WgpuDevice};

const FALLOFF: &str = "fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }";

/// The falloff of the WGSL above, with `smoothstep`'s formula.
fn falloff((d, r0, r1): (f32, f32, f32)) -> f32 {
    let t = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

/// The falloff check on d in 0..10, r0 in 0..1, r1 in 1.5..5. Vulkan lets `smoothstep` be
/// computed with its own roundings: a handful of ULP of 1 is an absolute 1e-6.
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

#[test]
fn a_wgsl_check_runs_through_wgpu() {
    let device = WgpuDevice::new().unwrap_or_else(|error| panic!("{error}"));
    let report = check()
        .run_wgpu(&device, &Shader::wgsl(FALLOFF), &config())
        .unwrap_or_else(|error| panic!("{error}"));
    println!("{report}");
    assert!(report.device.contains("wgpu"), "{}", report.device);
    assert_eq!(report.cases, 20_000);
    report.assert_passed();
}

#[test]
fn a_wrong_function_fails_and_shrinks_through_wgpu() {
    let device = WgpuDevice::new().unwrap_or_else(|error| panic!("{error}"));
    let broken = Shader::wgsl(FALLOFF.replace("r1, d)", "r1 + 1.0, d)"));
    let report = check()
        .run_wgpu(&device, &broken, &config())
        .unwrap_or_else(|error| panic!("{error}"));
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("the broken falloff passed: {report}")
    };
    println!("{report}");
    assert!(failure.input.ends_with(", 0.0, 1.5)"), "{}", failure.input);
}

#[test]
fn glsl_is_refused() {
    let device = WgpuDevice::new().unwrap_or_else(|error| panic!("{error}"));
    let glsl =
        Shader::glsl("float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }");
    match check().run_wgpu(&device, &glsl, &config()) {
        Err(Error::Setup(message)) => assert!(message.contains("wgpu takes WGSL"), "{message}"),
        Err(other) => panic!("expected a setup error, got {other}"),
        Ok(report) => panic!("expected a refusal, got {report}"),
    }
}
