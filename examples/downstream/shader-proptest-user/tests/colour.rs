//! The shader twins of `luminance` and `tone_map` agree with the Rust functions, on lavapipe.

use downstream_shader_proptest_user::{luminance, tone_map};
use glam::Vec3;
use shader_proptest::proptest::prelude::*;
use shader_proptest::{Check, FunctionCheck, Gpu, RunConfig, Shader, Tolerance};

/// A linear colour with channels from 0 to 100 (high dynamic range).
fn colour() -> impl Strategy<Value = (Vec3,)> {
    (0.0f32..100.0, 0.0f32..100.0, 0.0f32..100.0).prop_map(|(r, g, b)| (Vec3::new(r, g, b),))
}

/// Runs each of `checks` on `shader` with the default configuration, prints its report and fails
/// the test unless the shader agreed.
fn assert_agrees(shader: &Shader, checks: &[&dyn Check]) {
    let gpu = Gpu::new().unwrap();
    for check in checks {
        let report = check.run(&gpu, shader, &RunConfig::default()).unwrap();
        println!("{report}");
        report.assert_passed();
    }
}

#[test]
fn wgsl_luminance_agrees() {
    let shader = Shader::wgsl(include_str!("../shaders/colour.wgsl"));
    // A dot product of three terms: three roundings, possibly fused.
    let check = FunctionCheck::new("luminance", colour, |(c,)| luminance(c)).tolerance(Tolerance::Ulps(4.0));
    assert_agrees(&shader, &[&check]);
}

#[test]
fn glsl_tone_map_agrees() {
    let shader =
        Shader::glsl("#include \"colour.glsl\"").include_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders"));
    // A correctly rounded sum and a division of 2.5 ULP on the device, 0.5 each in Rust.
    let check = FunctionCheck::new("tone_map", colour, |(c,)| tone_map(c)).tolerance(Tolerance::Ulps(4.0));
    assert_agrees(&shader, &[&check]);
}

#[test]
fn slang_luminance_and_tone_map_agree() {
    let shader = Shader::slang("import colour;").include_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders"));
    // The same operations as in WGSL and GLSL, with the same bounds.
    let luminance_check =
        FunctionCheck::new("luminance", colour, |(c,)| luminance(c)).tolerance(Tolerance::Ulps(4.0));
    let tone_map_check =
        FunctionCheck::new("tone_map", colour, |(c,)| tone_map(c)).tolerance(Tolerance::Ulps(4.0));
    assert_agrees(&shader, &[&luminance_check, &tone_map_check]);
}
