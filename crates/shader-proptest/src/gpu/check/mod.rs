//! Checks: a shader function against its Rust mirror, on batches of generated cases.
//!
//! A check generates each batch of cases from its own seed with a proptest strategy, on as many
//! threads as the machine has, while the device runs the previous batch: one dispatch of a
//! generated kernel per batch ([`batches`]). Every output component is compared with the mirror's
//! within the check's [`Tolerance`]; for finite inputs both outputs must be finite too
//! ([`judge`]). A failing case is shrunk with proptest (re-generated from its batch's seed, then
//! simplified one dispatch at a time, [`shrink`]) and reported with its inputs, both outputs, the
//! tolerance, the seed that replays the run and the kernel's source ([`report`]).

mod batches;
mod config;
mod judge;
mod report;
mod shrink;

pub use config::{RunConfig, SEED_ENV};
pub use report::{Failure, Outcome, Report};

use super::compute::ComputeKernel;
use super::device::{Error, Gpu};
use crate::back::Language;
use crate::kernel::kernel_source;
use crate::shader::Shader;
use crate::tolerance::Tolerance;
use crate::value::{Args, Value};
use batches::{generate, Generator, Stats};
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::TestRng;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A type-erased check, for a registry of checks of different signatures.
pub trait Check: Send + Sync {
    /// The shader function.
    fn function(&self) -> &str;
    /// The source of the kernel that runs the function of `shader`.
    fn kernel(&self, shader: &Shader) -> String;
    /// Runs the check on the function of `shader`: [`Check::prepare`], then [`Check::run_prepared`].
    /// `Err`: the harness could not run (device, compiler, validation layer); a disagreement is a
    /// [`Report`] whose outcome is [`Outcome::Failed`].
    fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error>;
    /// Everything [`Check::run`] does before the first case, which needs no cases: the layout
    /// comparison, the kernel's compilation and its pipeline. Thread-safe, so that a suite can
    /// prepare the next checks while one runs ([`crate::run_checks`]).
    fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error>;
    /// Runs the cases of a check that [`Check::prepare`] made ready.
    fn run_prepared(&self, prepared: PreparedCheck<'_>, config: &RunConfig) -> Result<Report, Error>;
}

/// A check made ready to run on one shader ([`Check::prepare`]): the kernel's source, and its
/// pipeline, or the outcome that stands for running it (the device lacks a feature the shader
/// needs; the Rust and shader layouts differ).
pub struct PreparedCheck<'g> {
    language: Language,
    kernel: String,
    pipeline: Result<ComputeKernel<'g>, Outcome>,
    elapsed: Duration,
}

/// One shader function, its mirror, the inputs to try and the tolerance.
///
/// ```no_run
/// use glam::Vec3;
/// use proptest::prelude::*;
/// use shader_proptest::{FunctionCheck, Gpu, RunConfig, Shader, Tolerance};
///
/// let gpu = Gpu::new()?;
/// let shader = Shader::wgsl("fn luminance(c: vec3<f32>) -> f32 { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }");
/// let check = FunctionCheck::new(
///     "luminance",
///     || (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0).prop_map(|(r, g, b)| (Vec3::new(r, g, b),)),
///     |(c,): (Vec3,)| c.dot(Vec3::new(0.2126, 0.7152, 0.0722)),
/// )
/// .tolerance(Tolerance::Ulps(4.0));
/// check.run(&gpu, &shader, &RunConfig::default())?.assert_passed();
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct FunctionCheck<A, R> {
    function: String,
    strategy: Arc<dyn Fn() -> BoxedStrategy<A> + Send + Sync>,
    generator: Arc<Generator<A>>,
    mirror: Arc<dyn Fn(A) -> R + Send + Sync>,
    tolerance: Tolerance<A>,
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// A check of the shader function `function` against `mirror`, on cases from the strategies
    /// `strategy` makes (one per generating thread), bit-exact until [`FunctionCheck::tolerance`]
    /// says otherwise.
    pub fn new<S>(
        function: impl Into<String>,
        strategy: impl Fn() -> S + Send + Sync + 'static,
        mirror: impl Fn(A) -> R + Send + Sync + 'static,
    ) -> FunctionCheck<A, R>
    where
        S: Strategy<Value = A> + 'static,
    {
        FunctionCheck::with_parts(function.into(), strategy, Arc::new(mirror), Tolerance::Exact)
    }

    /// A check of `mirror` within `tolerance` on the cases of `strategy`: the boxed strategy that
    /// shrinking replays, and the generator that makes batches through the strategy's own type.
    fn with_parts<S>(
        function: String,
        strategy: impl Fn() -> S + Send + Sync + 'static,
        mirror: Arc<dyn Fn(A) -> R + Send + Sync>,
        tolerance: Tolerance<A>,
    ) -> FunctionCheck<A, R>
    where
        S: Strategy<Value = A> + 'static,
    {
        let strategy = Arc::new(strategy);
        let boxed = Arc::clone(&strategy);
        FunctionCheck {
            function,
            strategy: Arc::new(move || boxed().boxed()),
            generator: Arc::new(move |runner, count, cases| {
                let strategy = strategy();
                for _ in 0..count {
                    cases.push(generate(&strategy, runner)?.current());
                }
                Ok(())
            }),
            mirror,
            tolerance,
        }
    }

    /// The same check with `tolerance`.
    pub fn tolerance(self, tolerance: Tolerance<A>) -> FunctionCheck<A, R> {
        FunctionCheck { tolerance, ..self }
    }

    /// The same check (function, mirror, tolerance) on its cases changed by `perturb`: for example
    /// pushed towards edge values ([`crate::strategy`]). Shrinking simplifies the original case and
    /// perturbs it again with the same random numbers.
    pub fn with_perturbation(
        &self,
        perturb: impl Fn(A, &mut TestRng) -> A + Clone + Send + Sync + 'static,
    ) -> FunctionCheck<A, R> {
        let strategy = Arc::clone(&self.strategy);
        let perturbed = move || {
            let perturb = perturb.clone();
            strategy().prop_perturb(move |args, mut rng| perturb(args, &mut rng))
        };
        FunctionCheck::with_parts(
            self.function.clone(),
            perturbed,
            Arc::clone(&self.mirror),
            self.tolerance.clone(),
        )
    }

    /// The shader function.
    pub fn function(&self) -> &str {
        &self.function
    }

    /// The mirror's result for `args`.
    pub fn mirror(&self, args: A) -> R {
        (self.mirror)(args)
    }

    /// A strategy for the check's arguments.
    pub fn strategy(&self) -> BoxedStrategy<A> {
        (self.strategy)()
    }

    /// The source of the kernel that runs the function of `shader`.
    pub fn kernel(&self, shader: &Shader) -> String {
        kernel_source(shader, &self.function, A::TYPES, R::TYPE)
    }

    /// Runs the check on the function of `shader` (see [`Check::run`]).
    pub fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error> {
        let prepared = self.prepare(gpu, shader)?;
        self.run_prepared(prepared, config)
    }

    /// Compares the layouts and compiles the kernel into a pipeline (see [`Check::prepare`]).
    pub fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error> {
        let started = Instant::now();
        let kernel = self.kernel(shader);
        let pipeline = if let Some(reason) = gpu.missing_feature(shader.features()) {
            Err(Outcome::NotRun(reason))
        } else if let Err(error) = shader.check_layouts(A::TYPES, R::TYPE) {
            Err(Outcome::Failed(Box::new(Failure {
                reason: format!("the Rust and shader layouts differ: {error}"),
                input: String::new(),
                mirror: String::new(),
                shader: String::new(),
                shrink_steps: 0,
                kernel: kernel.clone(),
            })))
        } else {
            Ok(ComputeKernel::compile(gpu, shader, &kernel, 0)?)
        };
        Ok(PreparedCheck {
            language: shader.language(),
            kernel,
            pipeline,
            elapsed: started.elapsed(),
        })
    }

    /// Runs the cases on a prepared check (see [`Check::run_prepared`]). The report's time
    /// includes the preparation's.
    pub fn run_prepared(&self, prepared: PreparedCheck<'_>, config: &RunConfig) -> Result<Report, Error> {
        let started = Instant::now();
        let seed = config.validate()?;
        let (stats, outcome) = match prepared.pipeline {
            Err(outcome) => (Stats::default(), outcome),
            Ok(pipeline) => self.run_cases(&pipeline, config, seed, prepared.kernel)?,
        };
        let elapsed = prepared.elapsed + started.elapsed();
        Ok(Report::new(
            self.function.clone(),
            prepared.language,
            seed,
            &stats,
            outcome,
            elapsed,
        ))
    }

    /// Runs the batches on `pipeline` and shrinks the first disagreement, if any.
    fn run_cases(
        &self,
        pipeline: &ComputeKernel<'_>,
        config: &RunConfig,
        seed: u64,
        kernel: String,
    ) -> Result<(Stats, Outcome), Error> {
        let mut stats = Stats::default();
        let outcome = match self.run_batches(pipeline, config, seed, &mut stats)? {
            None => Outcome::Passed,
            Some(mismatch) => {
                Outcome::Failed(Box::new(self.shrink(pipeline, config, seed, mismatch, kernel)?))
            }
        };
        Ok((stats, outcome))
    }
}

impl<A: Args, R: Value> Check for FunctionCheck<A, R> {
    fn function(&self) -> &str {
        &self.function
    }

    fn kernel(&self, shader: &Shader) -> String {
        FunctionCheck::kernel(self, shader)
    }

    fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error> {
        FunctionCheck::run(self, gpu, shader, config)
    }

    fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error> {
        FunctionCheck::prepare(self, gpu, shader)
    }

    fn run_prepared(&self, prepared: PreparedCheck<'_>, config: &RunConfig) -> Result<Report, Error> {
        FunctionCheck::run_prepared(self, prepared, config)
    }
}

/// Runs `function` of `shader` on each of `cases`, in one dispatch, and returns the results.
pub fn evaluate<A: Args, R: Value>(
    gpu: &Gpu,
    shader: &Shader,
    function: &str,
    cases: &[A],
) -> Result<Vec<R>, Error> {
    let kernel = kernel_source(shader, function, A::TYPES, R::TYPE);
    let pipeline = ComputeKernel::compile(gpu, shader, &kernel, 0)?;
    let mut input = Vec::new();
    cases.iter().for_each(|args| args.write(&mut input));
    let output = pipeline.dispatch(cases.len(), &input, cases.len() * R::TYPE.words())?;
    let mut words = &output[..];
    Ok(cases.iter().map(|_| R::read(&mut words)).collect())
}
