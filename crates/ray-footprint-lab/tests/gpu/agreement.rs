//! Every shader function agrees with its Rust mirror, in WGSL, GLSL, Slang and HLSL (compiled by
//! glslang and by slangc): each record's
//! agreement check ([`ray_footprint_cases::Record::check`]).
//!
//! Each test prints one line per function: cases checked, largest error, that error as a fraction
//! of the function's tolerance, and the share of cases whose tolerance is vacuous.

use super::{assert_all_pass, gpu};
use ray_footprint::ray_cone;
use ray_footprint::shaders::Module;
use ray_footprint_cases::module_records;
use shader_proptest::{FunctionCheck, Language, Outcome, RunConfig};

fn agree(module: Module, language: Language) {
    let gpu = gpu();
    println!("device: {} ({})", gpu.name(), gpu.driver());
    let checks: Vec<_> = module_records(module)
        .map(|record| record.agreement_check())
        .collect();
    assert!(!checks.is_empty(), "module {} has no records", module.stem());
    let shader = module.shader(language);
    assert_all_pass(
        &gpu,
        &shader,
        language,
        checks.iter().map(AsRef::as_ref),
        "disagree",
    );
}

/// The harness catches a mirror that is off by one part in a million, and shrinks the case.
#[test]
fn harness_reports_a_wrong_mirror() {
    use proptest::prelude::*;
    let wrong = FunctionCheck::new(
        "rf_width_at",
        || {
            (1.0f32..2.0, 0.0f32..1.0, 0.0f32..10.0)
                .prop_map(|(width, spread_angle, t)| (ray_cone::RayCone { width, spread_angle }, t))
        },
        |(cone, t)| ray_cone::width_at(cone, t) * 1.000_001,
    )
    .tolerance(shader_proptest::Tolerance::Ulps(2.0));
    let gpu = gpu();
    for language in Language::ALL {
        let config = RunConfig {
            cases: 1000,
            batch: 256,
            ..RunConfig::default()
        };
        let report = wrong
            .run(&gpu, &Module::RayCone.shader(language), &config)
            .expect("the harness runs");
        let Outcome::Failed(failure) = &report.outcome else {
            panic!("a mirror off by 1e-6 must be reported: {report}")
        };
        assert!(failure.reason.contains("differs by"), "{report}");
        assert!(failure.kernel.contains("rf_width_at("), "{report}");
        println!("{report}");
    }
}

#[test]
fn ray_cone_wgsl() {
    agree(Module::RayCone, Language::Wgsl);
}

#[test]
fn ray_cone_glsl() {
    agree(Module::RayCone, Language::Glsl);
}

#[test]
fn ray_cone_slang() {
    agree(Module::RayCone, Language::Slang);
}

#[test]
fn ray_cone_hlsl_glslang() {
    agree(Module::RayCone, Language::HlslGlslang);
}

#[test]
fn ray_cone_hlsl_slangc() {
    agree(Module::RayCone, Language::HlslSlangc);
}

#[test]
fn wireframe_wgsl() {
    agree(Module::Wireframe, Language::Wgsl);
}

#[test]
fn wireframe_glsl() {
    agree(Module::Wireframe, Language::Glsl);
}

#[test]
fn wireframe_slang() {
    agree(Module::Wireframe, Language::Slang);
}

#[test]
fn wireframe_hlsl_glslang() {
    agree(Module::Wireframe, Language::HlslGlslang);
}

#[test]
fn wireframe_hlsl_slangc() {
    agree(Module::Wireframe, Language::HlslSlangc);
}

#[test]
fn ray_diff_wgsl() {
    agree(Module::RayDiff, Language::Wgsl);
}

#[test]
fn ray_diff_glsl() {
    agree(Module::RayDiff, Language::Glsl);
}

#[test]
fn ray_diff_slang() {
    agree(Module::RayDiff, Language::Slang);
}

#[test]
fn ray_diff_hlsl_glslang() {
    agree(Module::RayDiff, Language::HlslGlslang);
}

#[test]
fn ray_diff_hlsl_slangc() {
    agree(Module::RayDiff, Language::HlslSlangc);
}

#[test]
fn ray_diff_f64_wgsl() {
    agree(Module::RayDiffF64, Language::Wgsl);
}

#[test]
fn ray_diff_f64_glsl() {
    agree(Module::RayDiffF64, Language::Glsl);
}

#[test]
fn ray_diff_f64_slang() {
    agree(Module::RayDiffF64, Language::Slang);
}

#[test]
fn ray_diff_f64_hlsl_glslang() {
    agree(Module::RayDiffF64, Language::HlslGlslang);
}

#[test]
fn ray_diff_f64_hlsl_slangc() {
    agree(Module::RayDiffF64, Language::HlslSlangc);
}
