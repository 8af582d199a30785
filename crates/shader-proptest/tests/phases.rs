//! A report's `phases`: every phase a check went through has time in it, the phases it skipped
//! have none, and the dispatching thread's phases fit in the check's wall time.

use shader_proptest::{run_checks, Check, FunctionCheck, Gpu, Phase, Report, RunConfig, Shader};
use std::time::Duration;

const HALF: &str = "fn half(x: f32) -> f32 { return x * 0.5; }";

/// `x * 0.5`, or a mirror that is off by `offset`.
fn half_check(offset: f32) -> FunctionCheck<(f32,), f32> {
    FunctionCheck::new("half", || (-1.0f32..1.0,), move |(x,)| x * 0.5 + offset)
}

/// Three batches of 4,096 cases from seed 5.
fn config() -> RunConfig {
    RunConfig {
        cases: 3 * 4096,
        batch: 4096,
        seed: Some(5),
        ..RunConfig::default()
    }
}

/// The phases of the thread that dispatches, which follow each other within the check's run.
const DISPATCHING: [Phase; 5] = [
    Phase::Upload,
    Phase::Dispatch,
    Phase::ReadBack,
    Phase::Comparison,
    Phase::WaitForBatch,
];

fn time_in(report: &Report, phases: &[Phase]) -> Duration {
    phases.iter().map(|&phase| report.phases.get(phase)).sum()
}

/// A passing check run by `run_checks`: time in every work phase but shrinking, and the
/// dispatching thread's phases within the check's wall time.
#[test]
fn a_passing_check_spends_time_in_every_phase_but_shrinking() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let check = half_check(0.0);
    let checks: [(&dyn Check, Shader); 1] = [(&check, Shader::wgsl(HALF))];
    let mut reports = Vec::new();
    run_checks(&gpu, &checks, &config(), 1, |_, result| {
        reports.push(result.unwrap_or_else(|error| panic!("{error}")));
    })
    .unwrap_or_else(|error| panic!("{error}"));
    let report = &reports[0];
    report.assert_passed();
    for phase in Phase::ALL.into_iter().filter(|&phase| !phase.is_wait()) {
        let time = report.phases.get(phase);
        match phase {
            Phase::Shrinking => assert!(time.is_zero(), "{phase:?}: {time:?}"),
            _ => assert!(!time.is_zero(), "{phase:?} has no time"),
        }
    }
    assert!(time_in(report, &DISPATCHING) <= report.elapsed);
    assert!(time_in(report, &[Phase::Compile, Phase::Pipeline]) <= report.elapsed);
}

/// A failing check: its shrinking is timed, and fits in the check's wall time.
#[test]
fn a_failing_check_times_its_shrinking() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let report = half_check(1.0)
        .run(&gpu, &Shader::wgsl(HALF), &config())
        .unwrap_or_else(|error| panic!("{error}"));
    assert!(!report.passed());
    let shrinking = report.phases.get(Phase::Shrinking);
    assert!(!shrinking.is_zero());
    assert!(shrinking + time_in(&report, &DISPATCHING) <= report.elapsed);
}
