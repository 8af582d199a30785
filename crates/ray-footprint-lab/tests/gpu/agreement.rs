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
        &RunConfig::default(),
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

module_and_language_tests!(agree);
