//! Every WGSL function agrees with its Rust mirror in the browser: each record's agreement check
//! ([`ray_footprint_cases::Record::check`]), 100,000 cases a function, at the tolerance it has
//! through naga on Vulkan. The f64 module's checks end as not run: WebGPU has no 64-bit floats.
//!
//! Each test prints one line per function and a summary: functions passed, cases, the largest
//! error as a fraction of its tolerance.

use super::browser;
use ray_footprint::shaders::Module;
use ray_footprint_cases::module_records;
use shader_proptest::proptest::prelude::Just;
use shader_proptest::{FunctionCheck, Language, Outcome, Report, RunConfig, Shader};

/// Disagreements found in Chromium's WebGPU whose fix is a change of the shader modules: the
/// function, the start of its failure's reason, and why. Such a check must still fail, and so
/// counts as failed, never as passed; once the function agrees, its entry must go.
const FINDINGS: [(&str, &str, &str); 1] = [(
    "rf_refract_ray_cone",
    "component 1 differs by 3.14",
    "on Chromium's SwiftShader atan2(-0.0, x) is pi for x > 0 and 0 for x < 0 \
     (atan2_of_negative_zero_is_wrong_in_chromium); rf_refracted_angle_between takes the atan2 of \
     a sine that is -0.0 where eta or cos i is 0, so the refracted spread comes out pi",
)];

/// Runs every record's agreement check of `module` in the browser, printing each report and a
/// summary; the reports.
fn run(module: Module) -> Vec<Report> {
    let device = browser();
    println!("device: {}", device.description());
    let shader = module.shader(Language::Wgsl);
    let reports: Vec<Report> = module_records(module)
        .map(|record| {
            let check = record.agreement_check();
            let report = check
                .run_browser(&device, &shader, &RunConfig::default())
                .unwrap_or_else(|error| panic!("{} (WGSL in the browser): {error}", check.function()));
            println!("{report}");
            report
        })
        .collect();
    print_summary(module, &reports);
    reports
}

/// Functions passed, cases, and the largest error ratio among the passed.
fn print_summary(module: Module, reports: &[Report]) {
    let passed: Vec<&Report> = reports.iter().filter(|report| report.passed()).collect();
    let cases: usize = reports.iter().map(|report| report.cases).sum();
    let largest = passed.iter().max_by(|a, b| a.max_ratio.total_cmp(&b.max_ratio));
    println!(
        "{}: {} of {} functions passed, {cases} cases, largest error {}",
        module.stem(),
        passed.len(),
        reports.len(),
        largest.map_or("-".into(), |report| format!(
            "{:.4} of tolerance ({})",
            report.max_ratio, report.function
        ))
    );
}

/// Every function of `module` passes, but those of [`FINDINGS`], which fail as recorded there.
fn agree(module: Module) {
    let reports = run(module);
    assert!(!reports.is_empty(), "module {} has no records", module.stem());
    let mut unexpected = Vec::new();
    for report in &reports {
        match FINDINGS
            .iter()
            .find(|(function, ..)| *function == report.function)
        {
            Some((function, reason, why)) => {
                let Outcome::Failed(failure) = &report.outcome else {
                    panic!("{function} no longer disagrees in the browser: remove it from FINDINGS\n{report}")
                };
                assert!(
                    failure.reason.starts_with(reason),
                    "{function} fails otherwise than recorded:\n{report}"
                );
                println!("{function}: a known disagreement, counted as failed: {why}");
            }
            None if !report.passed() => unexpected.push(report.to_string()),
            None => {}
        }
    }
    assert!(
        unexpected.is_empty(),
        "{} function(s) disagree in the browser:\n{}",
        unexpected.len(),
        unexpected.join("\n\n")
    );
}

#[test]
fn ray_cone_wgsl() {
    agree(Module::RayCone);
}

#[test]
fn ray_diff_wgsl() {
    agree(Module::RayDiff);
}

#[test]
fn wireframe_wgsl() {
    agree(Module::Wireframe);
}

/// Each f64 check ends as not run, saying why, and none counts as passed.
#[test]
fn ray_diff_f64_is_not_run() {
    for report in run(Module::RayDiffF64) {
        assert!(!report.passed(), "{report}");
        match &report.outcome {
            Outcome::NotRun(reason) => assert_eq!(reason, "WebGPU has no 64-bit floats"),
            _ => panic!("an f64 check ran in the browser: {report}"),
        }
    }
}

/// The root of the refraction's finding, alone: `atan2(y, x)` of a `y` read from a buffer as
/// -0.0 is pi for x = 1 in Chromium's WebGPU on SwiftShader, where -0.0 (or 0.0) is right; naga's
/// SPIR-V on lavapipe gives -0.0. When this test fails, Chromium is right again: check the
/// refraction's entry in [`FINDINGS`].
#[test]
fn atan2_of_negative_zero_is_wrong_in_chromium() {
    let device = browser();
    let shader = Shader::wgsl("fn angle(y: f32, x: f32) -> f32 { return atan2(y, x); }");
    let check = FunctionCheck::new(
        "angle",
        || Just((-0.0f32, 1.0f32)),
        |(y, x): (f32, f32)| y.atan2(x),
    );
    let config = RunConfig {
        cases: 64,
        seed: Some(1),
        ..RunConfig::default()
    };
    let report = check
        .run_browser(&device, &shader, &config)
        .unwrap_or_else(|error| panic!("{error}"));
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("atan2(-0.0, 1.0) is right in the browser now: {report}")
    };
    assert_eq!(failure.shader, std::f32::consts::PI.to_string(), "{report}");
    println!("atan2(-0.0, 1.0) in {}: {}", device.description(), failure.shader);
}
