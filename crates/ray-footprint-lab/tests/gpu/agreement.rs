//! Every shader function agrees with its Rust mirror, in WGSL, GLSL and Slang.
//!
//! Each test prints one line per function: cases checked, largest error, that error as a fraction
//! of the function's tolerance, and the share of cases whose tolerance is vacuous.

use super::{assert_all_pass, gpu};
use ray_footprint::ray_cone;
use ray_footprint::registry::{check_registry, Coverage, Registered};
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks;
use shader_proptest::{FunctionCheck, Language, Outcome, RunConfig};

fn agree(module: Module, language: Language) {
    let gpu = gpu();
    println!("device: {} ({})", gpu.name(), gpu.driver());
    let checks = checks::checks(module);
    assert!(!checks.is_empty(), "module {} has no checks", module.stem());
    let shader = module.shader(language);
    assert_all_pass(
        &gpu,
        &shader,
        language,
        checks.iter().map(AsRef::as_ref),
        "disagree",
    );
}

/// Every public function of every module has an agreement check, registered in module order
/// under the name of the function the check calls. (The helper functions the shader modules
/// declare and the Rust mirror keeps private are checked through the public functions that call
/// them.)
#[test]
fn every_function_has_a_check_in_module_order() {
    let entries = checks::all_entries();
    check_registry(&entries, Coverage::Complete).unwrap_or_else(|error| panic!("{error}"));
    for entry in &entries {
        let calls = format!("rf_{}", entry.function);
        assert_eq!(entry.item.check.function(), calls, "{}", module_name(entry));
        assert_eq!(entry.item.edge.function(), calls, "{}", module_name(entry));
    }
    println!("{} functions, each with an agreement check", entries.len());
}

fn module_name(entry: &Registered<checks::Entry>) -> String {
    format!("{}::{}", entry.module.stem(), entry.function)
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
