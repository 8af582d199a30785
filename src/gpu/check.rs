//! Agreement checks: a shader function against its Rust mirror, on batches of generated cases.
//!
//! A check generates batches with proptest (so a failing batch is shrunk to a small counterexample),
//! runs each batch as one dispatch of a generated kernel, and compares every output component with
//! the mirror's within a per-function tolerance. For finite inputs, both outputs must also be finite.

use super::device::{Gpu, GpuError, Pipeline};
use super::kernel::{compile, kernel_source, Language};
use super::value::{GpuArgs, GpuValue};
use crate::shaders::Module;
use proptest::collection::vec;
use proptest::strategy::BoxedStrategy;
use proptest::test_runner::{Config, TestCaseError, TestError, TestRunner};
use std::cell::RefCell;
use std::fmt;

/// How many cases a check runs and how they are batched.
#[derive(Clone, Copy, Debug)]
pub struct RunConfig {
    /// At least this many cases are checked (before any shrinking).
    pub cases: usize,
    /// Largest batch (one dispatch); batches hold between half of this and this many cases.
    pub batch: usize,
}

impl Default for RunConfig {
    /// 100,000 cases in batches of 4,096 to 8,192.
    fn default() -> Self {
        RunConfig {
            cases: 100_000,
            batch: 8192,
        }
    }
}

/// The outcome of one check in one language.
#[derive(Clone, Debug)]
pub struct Report {
    /// The module of the function.
    pub module: Module,
    /// The function name without the `rf_` prefix.
    pub function: &'static str,
    /// The shader language that ran.
    pub language: Language,
    /// Cases compared (shrinking included).
    pub cases: usize,
    /// Largest `|shader - mirror|` over every output component.
    pub max_error: f32,
    /// Largest error as a fraction of its tolerance (1 is the limit).
    pub max_ratio: f32,
    /// The (shrunk) counterexample when the check failed.
    pub failure: Option<String>,
}

impl Report {
    /// Whether the check passed.
    pub fn passed(&self) -> bool {
        self.failure.is_none()
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:<10} {:<34} {:<5} {:>9} cases  max error {:>9.3e}  ({:>6.4} of tolerance)  {}",
            self.module.stem(),
            self.function,
            self.language.name(),
            self.cases,
            self.max_error,
            self.max_ratio,
            if self.passed() { "pass" } else { "FAIL" }
        )
    }
}

/// A type-erased agreement check.
pub trait Check: Sync {
    /// The module of the function.
    fn module(&self) -> Module;
    /// The function name without the `rf_` prefix.
    fn function(&self) -> &'static str;
    /// Runs the check. `Err` means the harness could not run (device, compiler or validation
    /// layer); a disagreement is a [`Report`] with a failure.
    fn run(&self, gpu: &Gpu, language: Language, config: &RunConfig) -> Result<Report, GpuError>;
}

/// One shader function, its mirror, its inputs and its tolerance.
pub struct FunctionCheck<A, R> {
    /// The module declaring `rf_<function>`.
    pub module: Module,
    /// The function name without the `rf_` prefix.
    pub function: &'static str,
    /// Inputs, covering the ordinary range and the edges.
    pub strategy: fn() -> BoxedStrategy<A>,
    /// The Rust mirror.
    pub mirror: fn(A) -> R,
    /// Allowed `|shader - mirror|` for output component `index` whose mirror value is `expected`.
    pub tolerance: fn(&A, usize, f32) -> f32,
}

#[derive(Default)]
struct Stats {
    cases: usize,
    max_error: f32,
    max_ratio: f32,
}

impl<A: GpuArgs + 'static, R: GpuValue + 'static> FunctionCheck<A, R> {
    /// The source of this check's kernel.
    pub fn kernel(&self, language: Language) -> String {
        kernel_source(language, self.module, self.function, A::TYPES, R::TYPE)
    }

    /// Compiles this check's kernel for `language` into a pipeline (destroy it with
    /// [`Gpu::destroy_pipeline`]).
    pub fn pipeline(&self, gpu: &Gpu, language: Language) -> Result<Pipeline, GpuError> {
        gpu.pipeline(&compile(language, self.module, &self.kernel(language))?, 0)
    }

    /// Runs one batch as one dispatch and compares every case with the mirror; `Ok(Err(_))`
    /// describes the first disagreement.
    pub fn check_batch(
        &self,
        gpu: &Gpu,
        pipeline: &Pipeline,
        batch: &[A],
    ) -> Result<Result<(), String>, GpuError> {
        self.compare(gpu, pipeline, batch, &mut Stats::default())
    }

    fn compare(
        &self,
        gpu: &Gpu,
        pipeline: &Pipeline,
        batch: &[A],
        stats: &mut Stats,
    ) -> Result<Result<(), String>, GpuError> {
        let mut input = Vec::new();
        batch.iter().for_each(|args| args.write(&mut input));
        let output = gpu.dispatch(pipeline, batch.len(), &input, batch.len() * R::TYPE.words())?;
        let mut words = &output[..];
        let (mut shader, mut mirror) = (Vec::new(), Vec::new());
        for args in batch {
            let shader_value = R::read(&mut words);
            let mirror_value = (self.mirror)(args.clone());
            if args.is_finite() && !(shader_value.is_finite() && mirror_value.is_finite()) {
                return Ok(Err(format!(
                    "non-finite output for finite input\n  input:  {args:?}\n  mirror: {mirror_value:?}\n  shader: {shader_value:?}"
                )));
            }
            shader.clear();
            mirror.clear();
            shader_value.components(&mut shader);
            mirror_value.components(&mut mirror);
            for (index, (&got, &expected)) in shader.iter().zip(&mirror).enumerate() {
                let error = if got == expected {
                    0.0
                } else {
                    (got - expected).abs()
                };
                let tolerance = (self.tolerance)(args, index, expected);
                if error.is_nan() || error > tolerance {
                    return Ok(Err(format!(
                        "component {index} differs by {error:e} (tolerance {tolerance:e})\n  input:  {args:?}\n  mirror: {mirror_value:?}\n  shader: {shader_value:?}"
                    )));
                }
                stats.max_error = stats.max_error.max(error);
                if tolerance > 0.0 {
                    stats.max_ratio = stats.max_ratio.max(error / tolerance);
                }
            }
            stats.cases += 1;
        }
        Ok(Ok(()))
    }
}

impl<A: GpuArgs + 'static, R: GpuValue + 'static> Check for FunctionCheck<A, R> {
    fn module(&self) -> Module {
        self.module
    }

    fn function(&self) -> &'static str {
        self.function
    }

    fn run(&self, gpu: &Gpu, language: Language, config: &RunConfig) -> Result<Report, GpuError> {
        let pipeline = self.pipeline(gpu, language)?;
        let half = (config.batch / 2).max(1);
        let batches = config.cases.div_ceil(half).max(1) as u32;
        let mut runner = TestRunner::new(Config {
            cases: batches,
            failure_persistence: None,
            max_shrink_iters: 512,
            ..Config::default()
        });
        let stats = RefCell::new(Stats::default());
        let gpu_error = RefCell::new(None);
        let outcome = runner.run(&vec((self.strategy)(), half..=config.batch.max(half)), |batch| {
            if gpu_error.borrow().is_some() {
                return Ok(());
            }
            match self.compare(gpu, &pipeline, &batch, &mut stats.borrow_mut()) {
                Ok(Ok(())) => Ok(()),
                Ok(Err(mismatch)) => Err(TestCaseError::fail(mismatch)),
                Err(error) => {
                    *gpu_error.borrow_mut() = Some(error);
                    Ok(())
                }
            }
        });
        gpu.destroy_pipeline(pipeline);
        if let Some(error) = gpu_error.into_inner() {
            return Err(error);
        }
        let failure = match outcome {
            Ok(()) => None,
            Err(TestError::Fail(reason, _)) => Some(reason.to_string()),
            Err(TestError::Abort(reason)) => Some(format!("aborted: {reason}")),
        };
        let stats = stats.into_inner();
        Ok(Report {
            module: self.module,
            function: self.function,
            language,
            cases: stats.cases,
            max_error: stats.max_error,
            max_ratio: stats.max_ratio,
            failure,
        })
    }
}
