//! Every shader function agrees with its Rust mirror on the local Vulkan device (lavapipe unless
//! `RAY_FOOTPRINT_DEVICE` names another), in WGSL and in GLSL, with the validation layer on.
//!
//! Each test prints one line per function: cases checked, largest error, and that error as a
//! fraction of the function's tolerance.

use ray_footprint::gpu::{suite, FunctionCheck, Gpu, Language, RunConfig};
use ray_footprint::ray_cone;
use ray_footprint::shaders::Module;

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|error| panic!("{error}"))
}

fn agree(module: Module, language: Language) {
    let gpu = gpu();
    println!("device: {}", gpu.name());
    let checks = suite::checks(module);
    assert!(!checks.is_empty(), "module {} has no checks", module.stem());
    let mut failures = Vec::new();
    for check in checks {
        let report = check
            .run(&gpu, language, &RunConfig::default())
            .unwrap_or_else(|error| panic!("{} ({}): {error}", check.function(), language.name()));
        println!("{report}");
        if let Some(failure) = report.failure {
            failures.push(format!("{}: {failure}", check.function()));
        }
    }
    assert!(
        failures.is_empty(),
        "{} function(s) disagree:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

#[test]
fn ray_cone_wgsl() {
    agree(Module::RayCone, Language::Wgsl);
}

#[test]
fn ray_cone_glsl() {
    agree(Module::RayCone, Language::Glsl);
}

/// The harness catches a mirror that is off by one part in a million, and shrinks the batch.
#[test]
fn harness_reports_a_wrong_mirror() {
    let wrong = FunctionCheck {
        module: Module::RayCone,
        function: "width_at",
        strategy: || {
            use proptest::prelude::*;
            (1.0f32..2.0, 0.0f32..1.0, 0.0f32..10.0)
                .prop_map(|(width, spread_angle, t)| (ray_cone::RayCone { width, spread_angle }, t))
                .boxed()
        },
        mirror: |(cone, t)| ray_cone::width_at(cone, t) * 1.000_001,
        tolerance: |_, _, expected| ray_footprint::gpu::tolerance::ulps(2.0, expected),
    };
    let gpu = gpu();
    for language in Language::ALL {
        use ray_footprint::gpu::Check;
        let config = RunConfig {
            cases: 1000,
            batch: 256,
        };
        let report = wrong.run(&gpu, language, &config).expect("the harness runs");
        let failure = report.failure.expect("a mirror off by 1e-6 must be reported");
        assert!(failure.contains("differs by"), "{failure}");
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
fn ray_diff_wgsl() {
    agree(Module::RayDiff, Language::Wgsl);
}

#[test]
fn ray_diff_glsl() {
    agree(Module::RayDiff, Language::Glsl);
}

#[test]
fn ray_diff_f64_wgsl() {
    agree(Module::RayDiffF64, Language::Wgsl);
}

#[test]
fn ray_diff_f64_glsl() {
    agree(Module::RayDiffF64, Language::Glsl);
}
