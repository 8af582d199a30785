//! What a check says when it ends: passed, failed (with the shrunk case) or not run, and the
//! numbers of the run.

use super::batches::Stats;
use super::config::SEED_ENV;
use crate::back::Language;
use std::fmt;
use std::time::Duration;

/// How a check ended.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Every case agreed.
    Passed,
    /// A case disagreed (or the layouts differ).
    Failed(Box<Failure>),
    /// The device lacks something the shader needs: the reason. Never counted as passed.
    NotRun(String),
}

/// A disagreement, after shrinking.
#[derive(Clone, Debug)]
pub struct Failure {
    /// What differs: a component beyond its tolerance, a non-finite output, or a layout.
    pub reason: String,
    /// The (shrunk) arguments.
    pub input: String,
    /// The mirror's result.
    pub mirror: String,
    /// The shader's result.
    pub shader: String,
    /// Shrinking steps taken (dispatches of one case).
    pub shrink_steps: usize,
    /// The generated kernel.
    pub kernel: String,
}

/// The outcome of one check in one language.
#[derive(Clone, Debug)]
pub struct Report {
    /// The shader function.
    pub function: String,
    /// The language that ran.
    pub language: Language,
    /// Cases compared (shrinking excluded).
    pub cases: usize,
    /// Largest `|shader - mirror|` over every output component.
    pub max_error: f32,
    /// Largest error as a fraction of its tolerance (1 is the limit).
    pub max_ratio: f32,
    /// Share of the cases with a vacuous tolerance: at least as wide as the spread of that
    /// component's mirror outputs over the case's batch (a tolerance that no plausible output
    /// could exceed).
    pub vacuous: f64,
    /// The output component with the most vacuous cases, and its share of the cases.
    pub most_vacuous_component: Option<(usize, f64)>,
    /// The seed that replays this run ([`RunConfig::seed`](super::RunConfig::seed), [`SEED_ENV`]).
    pub seed: u64,
    /// Wall time of the whole check.
    pub elapsed: Duration,
    /// Passed, failed or not run.
    pub outcome: Outcome,
}

impl Report {
    /// The report of a run of `function` in `language` seeded with `seed`, from its counters.
    pub(super) fn new(
        function: String,
        language: Language,
        seed: u64,
        stats: &Stats,
        outcome: Outcome,
        elapsed: Duration,
    ) -> Report {
        let share = |count: usize| count as f64 / stats.cases.max(1) as f64;
        let by_component = &stats.vacuous_by_component;
        Report {
            function,
            language,
            cases: stats.cases,
            max_error: stats.max_error,
            max_ratio: stats.max_ratio,
            vacuous: share(stats.vacuous),
            most_vacuous_component: (0..by_component.len())
                .max_by_key(|&component| by_component[component])
                .filter(|&component| by_component[component] > 0)
                .map(|component| (component, share(by_component[component]))),
            seed,
            elapsed,
            outcome,
        }
    }

    /// Whether every case agreed.
    pub fn passed(&self) -> bool {
        matches!(self.outcome, Outcome::Passed)
    }

    /// Panics with the report unless the check passed (a check that did not run fails too).
    pub fn assert_passed(&self) {
        assert!(self.passed(), "{self}");
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = match &self.outcome {
            Outcome::Passed => String::from("pass"),
            Outcome::Failed(_) => String::from("FAIL"),
            Outcome::NotRun(reason) => format!("not run: {reason}"),
        };
        write!(
            f,
            "{:<38} {:<14} {:>9} cases  max error {:>9.3e}  ({:>6.4} of tolerance)  vacuous {:>6.2}%  {verdict}",
            self.function,
            self.language.name(),
            self.cases,
            self.max_error,
            self.max_ratio,
            100.0 * self.vacuous,
        )?;
        if let Some((component, share)) = self.most_vacuous_component {
            write!(f, " (most: component {component}, {:.2}%)", 100.0 * share)?;
        }
        if let Outcome::Failed(failure) = &self.outcome {
            write!(
                f,
                "\n  {}\n  input:  {}\n  mirror: {}\n  shader: {}\n  shrunk in {} steps; replay with {SEED_ENV}={:#x}\n  kernel:\n{}",
                failure.reason,
                failure.input,
                failure.mirror,
                failure.shader,
                failure.shrink_steps,
                self.seed,
                failure.kernel
            )?;
        }
        Ok(())
    }
}
