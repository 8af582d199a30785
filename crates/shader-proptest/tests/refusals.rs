//! A check the harness cannot run as written is refused before anything runs, saying why.
//!
//! - Rust types that are not the shader function's: with both signatures, where the kernel does
//!   not compile (every language) and where it compiles because the language converts the
//!   argument on the way (GLSL's `int` to `float`, Slang's `float` to `float3`), which would
//!   otherwise give wrong results.
//! - A `pod` struct whose Rust layout is not the shader's: with the table of both.

use glam::Vec3;
use shader_proptest::proptest::prelude::*;
use shader_proptest::{shader_struct, Check, Error, FunctionCheck, Gpu, Language, RunConfig, Shader};

/// The error a check of `shader` ends with; panics if it runs.
fn refusal(gpu: &Gpu, check: &dyn Check, shader: &Shader) -> Error {
    let config = RunConfig {
        cases: 64,
        batch: 64,
        ..RunConfig::default()
    };
    match check.run(gpu, shader, &config) {
        Err(error) => {
            println!("{}:\n{error}\n", shader.language());
            error
        }
        Ok(report) => panic!("{}: expected a refusal, got {report}", shader.language()),
    }
}

/// The message of the signature error a check of `shader` ends with.
fn signature_refusal(gpu: &Gpu, check: &dyn Check, shader: &Shader) -> String {
    match refusal(gpu, check, shader) {
        Error::Signature(message) => message,
        other => panic!("{}: expected a signature error, got {other}", shader.language()),
    }
}

/// The falloff in HLSL, which both HLSL back ends compile.
const HLSL_FALLOFF: &str =
    "float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }";

/// A user's `falloff(d, r0, r1)` checked against a Rust function that takes a vector first.
#[test]
fn a_vector_for_a_float_is_refused_in_every_language() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let check = FunctionCheck::new(
        "falloff",
        || (any::<[f32; 3]>(), 0.0f32..1.0, 1.0f32..2.0).prop_map(|(v, r0, r1)| (Vec3::from(v), r0, r1)),
        |(d, r0, r1): (Vec3, f32, f32)| d.x + r0 + r1,
    );
    let shaders = [
        (
            Shader::wgsl(
                "fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }",
            ),
            "shader: falloff(d: f32, r0: f32, r1: f32) -> f32",
        ),
        (
            Shader::glsl(
                "float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }",
            ),
            "shader: falloff(d: float, r0: float, r1: float) -> float",
        ),
        (
            Shader::slang(
                "float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }",
            ),
            "shader: falloff(float, float, float) -> float",
        ),
        (
            Shader::new(Language::HlslGlslang, HLSL_FALLOFF),
            "shader: falloff(float, float, float) -> float",
        ),
        (
            Shader::new(Language::HlslSlangc, HLSL_FALLOFF),
            "shader: falloff(float, float, float) -> float",
        ),
    ];
    assert_eq!(shaders.len(), Language::ALL.len(), "every language");
    for (shader, declared) in shaders {
        let message = signature_refusal(&gpu, &check, &shader);
        assert!(message.contains("Rust:   (Vec3, f32, f32) -> f32"), "{message}");
        assert!(message.contains(declared), "{message}");
    }
}

/// GLSL passes an `int` to a `float` parameter, Slang widens a `float` to a `float3`, and the
/// kernels compile; the signature each kernel calls is held against the Rust one all the same.
#[test]
fn implicit_conversions_are_refused() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let twice = FunctionCheck::new("twice", || (-100i32..100,), |(n,): (i32,)| 2.0 * n as f32);
    let widen = FunctionCheck::new("widen", || (-1.0f32..1.0,), |(x,): (f32,)| Vec3::splat(x));
    let cases: [(&dyn Check, Shader, [&str; 2]); 2] = [
        (
            &twice,
            Shader::glsl("float twice(float x) { return 2.0 * x; }"),
            [
                "Rust:   (i32) -> f32, passed to GLSL as (int) -> float",
                "shader: twice(x: float) -> float",
            ],
        ),
        (
            &widen,
            Shader::slang("float3 widen(float3 v) { return v; }"),
            [
                "Rust:   (f32) -> Vec3, passed to Slang as (float) -> float3",
                "shader: widen(v: float3) -> float3",
            ],
        ),
    ];
    for (check, shader, parts) in cases {
        let message = signature_refusal(&gpu, check, &shader);
        for part in parts {
            assert!(message.contains(part), "{part:?} not in {message}");
        }
    }
}

/// A function the source does not declare is named as missing.
#[test]
fn a_missing_function_is_named() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let check = FunctionCheck::new("absent", || (-1.0f32..1.0,), |(x,): (f32,)| x);
    for shader in [
        Shader::wgsl("fn present(x: f32) -> f32 { return x; }"),
        Shader::glsl("float present(float x) { return x; }"),
        Shader::slang("float present(float x) { return x; }"),
    ] {
        let message = signature_refusal(&gpu, &check, &shader);
        assert!(
            message.contains("source declares no function named `absent`"),
            "{message}"
        );
    }
}

/// A light as a user might share it: an intensity, then a direction.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct Light {
    intensity: f32,
    direction: Vec3,
}

shader_struct!(pod Light as "Light" { intensity: f32, direction: Vec3 });

/// A Rust layout that is not the shader's is an error that says so, with both layouts: WGSL
/// aligns a `vec3<f32>` to 16 bytes, so `direction` sits at 16 where Rust has it at 4. A field
/// one side lacks is named.
#[test]
fn a_layout_mismatch_is_refused_with_the_table() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let check = FunctionCheck::new(
        "brightness",
        || {
            (0.0f32..1.0,).prop_map(|(intensity,)| {
                (Light {
                    intensity,
                    direction: Vec3::Y,
                },)
            })
        },
        |(light,): (Light,)| light.intensity,
    );
    let brightness = "fn brightness(light: Light) -> f32 { return light.intensity; }";
    let misaligned =
        Shader::wgsl("struct Light { intensity: f32, direction: vec3<f32> }").with_source(brightness);
    match refusal(&gpu, &check, &misaligned) {
        Error::Layout(error) => {
            let message = error.to_string();
            assert!(
                message.contains("offset or size differs at direction, (size)"),
                "{message}"
            );
            assert!(message.contains("MISMATCH"), "{message}");
        }
        other => panic!("expected a layout error, got {other}"),
    }
    let padded = Shader::wgsl("struct Light { intensity: f32, pad: vec3<u32>, direction: vec3<f32> }")
        .with_source(brightness);
    match refusal(&gpu, &check, &padded) {
        Error::Layout(error) => {
            assert!(
                error
                    .to_string()
                    .contains("Light.pad: field missing on the Rust side"),
                "{error}"
            )
        }
        other => panic!("expected a layout error, got {other}"),
    }
}
