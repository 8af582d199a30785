//! A failing check, as a new user meets one: a WGSL `falloff` whose outer radius is off by one
//! against its Rust twin. The report counts every case it ran, names the device, the inputs, both
//! outputs and the tolerance, and prints once; the case is shrunk to a local minimum, checked
//! against the smallest failing distance computed in f64.

use shader_proptest::{FunctionCheck, Gpu, Outcome, Report, RunConfig, Shader, Tolerance, SEED_ENV};

/// `falloff` with `r1 + 1.0` where `r1` belongs.
const BROKEN_FALLOFF: &str = "
fn falloff(d: f32, r0: f32, r1: f32) -> f32 {
    return 1.0 - smoothstep(r0, r1 + 1.0, d);
}";

/// WGSL's `smoothstep(e0, e1, x)`: `t * t * (3 - 2 t)` with `t = clamp((x - e0) / (e1 - e0), 0, 1)`.
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The Rust twin: 1 inside `r0`, 0 beyond `r1`, a smooth step between.
fn falloff(d: f32, r0: f32, r1: f32) -> f32 {
    1.0 - smoothstep(r0, r1, d)
}

const TOLERANCE: f32 = 1.0e-5;

/// The check of the issue: d in 0..10, r0 in 0..1, r1 in 1.5..5, tolerance 1e-5.
fn falloff_check() -> FunctionCheck<(f32, f32, f32), f32> {
    FunctionCheck::new(
        "falloff",
        || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0),
        |(d, r0, r1)| falloff(d, r0, r1),
    )
    .tolerance(Tolerance::Absolute(TOLERANCE))
}

/// The smallest distance at which the broken falloff differs from the right one by the tolerance,
/// for r0 = 0 and r1 = 1.5, in f64: below `r1`, `smoothstep(0, r, d) = 3 (d/r)^2 - 2 (d/r)^3`, so
/// the difference `smoothstep(0, 1.5, d) - smoothstep(0, 2.5, d)` rises with `d` near 0, and
/// bisection finds where it reaches the tolerance.
fn smallest_failing_distance() -> f64 {
    let step = |r: f64, d: f64| 3.0 * (d / r).powi(2) - 2.0 * (d / r).powi(3);
    let difference = |d: f64| step(1.5, d) - step(2.5, d);
    let (mut low, mut high) = (0.0f64, 0.1f64);
    for _ in 0..100 {
        let middle = 0.5 * (low + high);
        if difference(middle) < f64::from(TOLERANCE) {
            low = middle;
        } else {
            high = middle;
        }
    }
    high
}

/// The floats of a tuple's debug form, `(0.0034, 0.0, 1.5)`.
fn floats(tuple: &str) -> Vec<f32> {
    tuple
        .trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(|x| x.trim().parse().expect("a float"))
        .collect()
}

fn failing_report(seed: u64) -> Report {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let config = RunConfig {
        seed: Some(seed),
        ..RunConfig::default()
    };
    falloff_check()
        .run(&gpu, &Shader::wgsl(BROKEN_FALLOFF), &config)
        .unwrap_or_else(|error| panic!("{error}"))
}

/// At two seeds: r0 shrinks to its lower bound 0, r1 to its lower bound 1.5, and d to within 1%
/// of the smallest failing distance (about 0.0034), in a few dispatches.
#[test]
fn the_falloff_case_shrinks_to_the_smallest_failing_distance() {
    let expected = smallest_failing_distance();
    for seed in [1, 2] {
        let report = failing_report(seed);
        let Outcome::Failed(failure) = &report.outcome else {
            panic!("the broken falloff passed: {report}")
        };
        let [d, r0, r1] = floats(&failure.input)[..] else {
            panic!("three inputs: {}", failure.input)
        };
        println!(
            "seed {seed}: {} shrunk to ({d}, {r0}, {r1}) in {} steps, {} dispatches; smallest failing d {expected:.6}",
            failure.generated, failure.shrink_steps, failure.shrink_dispatches
        );
        assert_eq!((r0, r1), (0.0, 1.5), "{report}");
        assert!(
            (f64::from(d) - expected).abs() < 0.01 * expected,
            "d = {d}, expected {expected}: {report}"
        );
        assert!(failure.shrink_dispatches <= 64, "{report}");
        assert_eq!(failure.not_shrunk, None);
    }
}

/// The header counts every case run, the failing ones included, with a largest error beyond
/// the tolerance, and names the device; the failure names the inputs, both outputs, the
/// tolerance and the seed that replays the run.
#[test]
fn a_failure_report_says_what_failed_where() {
    let report = failing_report(1);
    let Outcome::Failed(failure) = &report.outcome else {
        panic!("the broken falloff passed: {report}")
    };
    assert!(failure.disagreeing > 0 && failure.disagreeing <= report.cases);
    assert!(report.max_ratio > 1.0 && report.max_error > TOLERANCE, "{report}");
    let text = report.to_string();
    let header = text.lines().next().expect("a header");
    println!("{text}");
    for part in [
        format!("{} cases", report.cases),
        format!("FAIL: {} of {} cases disagree", failure.disagreeing, report.cases),
        format!("on {}", report.device),
    ] {
        assert!(header.contains(&part), "{part:?} not in {header:?}");
    }
    let mirror = falloff_check().mirror((floats(&failure.input)[0], 0.0, 1.5));
    for part in [
        format!("input:     {}", failure.input),
        format!("mirror:    {mirror:?}"),
        format!("shader:    {}", failure.shader),
        String::from("tolerance: absolute 1e-5"),
        String::from("component 0 differs by"),
        format!("{SEED_ENV}={:#x}", report.seed),
    ] {
        assert!(text.contains(&part), "{part:?} not in the report:\n{text}");
    }
}

/// `assert_passed` panics with the whole report when it was not printed, and with one line
/// pointing to it when it was.
#[test]
fn printing_and_asserting_print_the_report_once() {
    let report = failing_report(2);
    let message = |report: &Report| {
        let payload =
            std::panic::catch_unwind(|| report.assert_passed()).expect_err("a failing report panics");
        payload
            .downcast_ref::<String>()
            .cloned()
            .expect("a formatted message")
    };
    let unprinted = message(&report.clone());
    assert!(unprinted.contains("input:"), "{unprinted}");
    let printed = report.to_string();
    let after_printing = message(&report);
    assert_eq!(after_printing.lines().count(), 1, "{after_printing}");
    assert!(after_printing.contains("printed above") && !printed.is_empty());
}
