//! Metamorphic checks on the device: a falloff with no Rust twin checked against itself under a
//! uniform scale of every length, in WGSL, GLSL and HLSL; a falloff that is not scale-invariant
//! is reported with the case, its transform, and the shader's results for both, shrunk.

use shader_proptest::{case_seed, Gpu, Language, MetamorphicCheck, Outcome, RunConfig, Shader, Tolerance};

/// The falloff's arguments: a distance and two radii.
type Falloff = (f32, f32, f32);

/// A power of two from 2^-20 to 2^20, drawn from the case.
fn scale(case: &Falloff) -> f32 {
    2f32.powi((case_seed(case) % 41) as i32 - 20)
}

/// `falloff(s d, s r0, s r1) = falloff(d, r0, r1)` for a power of two `s`: exact in any
/// arithmetic that is, so the tolerance is one that `smoothstep`'s own rounding fits in.
fn scale_invariance() -> MetamorphicCheck<Falloff, f32> {
    MetamorphicCheck::new(
        "falloff",
        || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0),
        |case: &Falloff| {
            let s = scale(case);
            (case.0 * s, case.1 * s, case.2 * s)
        },
        |_, falloff: f32| falloff,
    )
    .tolerance(Tolerance::Absolute(1e-6))
}

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|error| panic!("{error}"))
}

#[test]
fn a_scale_invariant_falloff_passes_in_every_language() {
    let gpu = gpu();
    let config = RunConfig {
        cases: 20_000,
        ..RunConfig::default()
    };
    let shaders = [
        Shader::wgsl("fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }"),
        Shader::glsl("float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }"),
        Shader::new(
            Language::HlslGlslang,
            "float falloff(float d, float r0, float r1) { return 1.0 - smoothstep(r0, r1, d); }",
        ),
    ];
    for shader in &shaders {
        let report = scale_invariance()
            .run(&gpu, shader, &config)
            .unwrap_or_else(|error| panic!("{error}"));
        println!("{report}");
        report.assert_passed();
        assert_eq!(report.cases, config.cases);
    }
}

#[test]
fn a_falloff_that_is_not_scale_invariant_is_reported_with_its_transform() {
    let broken = Shader::wgsl(
        "fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1 + 1.0, d); }",
    );
    let config = RunConfig {
        seed: Some(3),
        ..RunConfig::default()
    };
    let report = scale_invariance()
        .run(&gpu(), &broken, &config)
        .unwrap_or_else(|error| panic!("{error}"));
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("a falloff with a fixed offset is not scale-invariant: {report}")
    };
    let text = report.to_string();
    println!("{text}");
    let transformed = failure.transformed.as_ref().expect("the transformed case");
    for part in [
        format!("input:     {}", failure.input),
        format!("transformed: {transformed}"),
        format!("expected:  {}", failure.mirror),
        format!("shader:    {}", failure.shader),
        String::from("component 0 differs by"),
    ] {
        assert!(text.contains(&part), "{part:?} not in the report:\n{text}");
    }
    assert_eq!(failure.not_shrunk, None);
    assert!(failure.shrink_steps > 0, "{text}");
}
