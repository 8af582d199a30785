//! Checks: a shader function against its Rust mirror, or against itself under a transformation of
//! its inputs ([`MetamorphicCheck`]), on batches of generated cases.
//!
//! A check generates each batch of cases from its own seed with a proptest strategy, on as many
//! threads as the machine has, while the device runs the previous batch: one dispatch of a
//! generated kernel per batch and shader, each batch generated once however many shaders (the
//! function in several languages) it runs on ([`batches`]). Every output component is compared
//! with the mirror's within the check's [`Tolerance`]; for finite inputs both outputs must be
//! finite too ([`judge`]). The expected result is the mirror's, or, for a metamorphic check,
//! what the device's result for the case as given says the transformed case's must be
//! ([`oracle`]: each case then runs twice in the same dispatch). A failing case is shrunk through the random words its strategy drew,
//! many candidates per dispatch ([`shrink`]), and reported with its inputs, both outputs, the
//! tolerance, the seed that replays the run and the kernel's source ([`report`]).

mod batches;
mod config;
mod judge;
mod metamorphic;
mod oracle;
mod report;
mod shrink;

pub use config::{RunConfig, SEED_ENV};
pub use metamorphic::{case_seed, MetamorphicCheck};
pub use report::{Failure, Outcome, Report, MAX_VACUOUS};

use super::call::compile_call;
use super::compute::{ComputeKernel, Dispatch};
use super::device::Gpu;
use super::error::Error;
use super::phases::{Phase, PhaseTimes};
use crate::kernel::kernel_source;
use crate::language::Language;
use crate::shader::Shader;
use crate::signature::Call;
use crate::tolerance::Tolerance;
use crate::value::{Args, Value};
use batches::{generate, Generator, Lane, Stats, MAX_REJECTIONS};
use oracle::Oracle;
use proptest::prelude::any;
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{RngAlgorithm, TestRng};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A type-erased check, for a registry of checks of different signatures.
pub trait Check: Send + Sync {
    /// The shader function.
    fn function(&self) -> &str;
    /// The source of the kernel that runs the function of `shader`.
    fn kernel(&self, shader: &Shader) -> String;
    /// Runs the check on the function of `shader`: [`Check::prepare`], then [`Check::run_prepared`]
    /// with that one.
    /// `Err`: the harness could not run (device, compiler, validation layer); a disagreement is a
    /// [`Report`] whose outcome is [`Outcome::Failed`].
    fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error>;
    /// Everything [`Check::run`] does before the first case, which needs no cases: the layout
    /// comparison ([`Error::Layout`]), the kernel's compilation and the signature comparison
    /// ([`Error::Signature`]), and the pipeline. Thread-safe, so that a suite can prepare the next
    /// checks while one runs ([`crate::run_checks`]).
    fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error>;
    /// Runs the cases on checks that [`Check::prepare`] made ready, for one shader or several (the
    /// function in several languages): each batch is generated once and runs on every one of them,
    /// so that they all see the same cases. One result per prepared check, in their order.
    fn run_prepared(
        &self,
        prepared: Vec<PreparedCheck<'_>>,
        config: &RunConfig,
    ) -> Vec<Result<Report, Error>>;
    /// [`Check::prepare`] in a browser's WebGPU (feature `browser`): WGSL only, compiled by naga
    /// and then by the browser.
    #[cfg(feature = "browser")]
    fn prepare_browser<'g>(
        &self,
        device: &'g super::BrowserDevice,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error>;
    /// [`Check::run`] in a browser's WebGPU (feature `browser`).
    #[cfg(feature = "browser")]
    fn run_browser(
        &self,
        device: &super::BrowserDevice,
        shader: &Shader,
        config: &RunConfig,
    ) -> Result<Report, Error> {
        let prepared = self.prepare_browser(device, shader)?;
        let mut reports = self.run_prepared(vec![prepared], config);
        reports.pop().expect("one report per prepared check")
    }
}

/// A check made ready to run on one shader ([`Check::prepare`]): the kernel's source and its
/// pipeline on the device, or why the device cannot run it (it lacks a feature the shader needs).
pub struct PreparedCheck<'g> {
    language: Language,
    device: String,
    kernel: String,
    pipeline: Result<Box<dyn Dispatch + 'g>, String>,
    elapsed: Duration,
    times: PhaseTimes,
}

impl<'g> PreparedCheck<'g> {
    /// The check of `shader`'s `kernel` on `device`, prepared since `started`, its compilation
    /// and pipeline creation timed in `times`.
    pub(in crate::gpu) fn new(
        shader: &Shader,
        device: String,
        kernel: String,
        pipeline: Result<Box<dyn Dispatch + 'g>, String>,
        (started, times): (Instant, PhaseTimes),
    ) -> PreparedCheck<'g> {
        PreparedCheck {
            language: shader.language(),
            device,
            kernel,
            pipeline,
            elapsed: started.elapsed(),
            times,
        }
    }
}

/// One shader function, its mirror, the inputs to try and the tolerance.
///
/// ```
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
    oracle: Oracle<A, R>,
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
        let mirror = Oracle::Mirror(Arc::new(mirror));
        FunctionCheck::with_parts(function.into(), strategy, mirror, Tolerance::Exact)
    }

    /// A check against `oracle` within `tolerance` on the cases of `strategy`: the boxed strategy
    /// that shrinking replays, and the generator that makes batches through the strategy's own
    /// type.
    fn with_parts<S>(
        function: String,
        strategy: impl Fn() -> S + Send + Sync + 'static,
        oracle: Oracle<A, R>,
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
                    cases.push(generate(&strategy, runner, MAX_REJECTIONS)?.current());
                }
                Ok(())
            }),
            oracle,
            tolerance,
        }
    }

    /// The same check with `tolerance`.
    pub fn tolerance(self, tolerance: Tolerance<A>) -> FunctionCheck<A, R> {
        FunctionCheck { tolerance, ..self }
    }

    /// The same check (function, mirror, tolerance) on its cases changed by `perturb`: for example
    /// pushed towards edge values ([`crate::strategy`]). The random numbers `perturb` takes come
    /// from a generator seeded by four words the case's strategy draws, so that shrinking replays
    /// and simplifies the perturbation with the rest of the case.
    pub fn with_perturbation(
        &self,
        perturb: impl Fn(A, &mut TestRng) -> A + Clone + Send + Sync + 'static,
    ) -> FunctionCheck<A, R> {
        let strategy = Arc::clone(&self.strategy);
        let perturbed = move || {
            let perturb = perturb.clone();
            (strategy(), any::<[u32; 4]>()).prop_map(move |(args, seed)| {
                let bytes: Vec<u8> = seed.iter().flat_map(|word| word.to_le_bytes()).collect();
                perturb(args, &mut TestRng::from_seed(RngAlgorithm::XorShift, &bytes))
            })
        };
        FunctionCheck::with_parts(
            self.function.clone(),
            perturbed,
            self.oracle.clone(),
            self.tolerance.clone(),
        )
    }

    /// The same check (function, mirror, tolerance) on those of its cases that `keep` accepts;
    /// `reason` names the others. A filter after [`FunctionCheck::with_perturbation`] keeps the
    /// perturbed cases of a domain, for example those where the function is well-conditioned.
    pub fn with_filter(
        &self,
        reason: &'static str,
        keep: impl Fn(&A) -> bool + Clone + Send + Sync + 'static,
    ) -> FunctionCheck<A, R> {
        let strategy = Arc::clone(&self.strategy);
        let filtered = move || {
            let keep = keep.clone();
            strategy().prop_filter(reason, move |args| keep(args))
        };
        FunctionCheck::with_parts(
            self.function.clone(),
            filtered,
            self.oracle.clone(),
            self.tolerance.clone(),
        )
    }

    /// The shader function.
    pub fn function(&self) -> &str {
        &self.function
    }

    /// The mirror's result for `args`.
    pub fn mirror(&self, args: A) -> R {
        match &self.oracle {
            Oracle::Mirror(mirror) => mirror(args),
            // A check against a relation is a `MetamorphicCheck`'s, which never lends it out.
            Oracle::Relation { .. } => unreachable!("a metamorphic check has no mirror"),
        }
    }

    /// A strategy for the check's arguments.
    pub fn strategy(&self) -> BoxedStrategy<A> {
        (self.strategy)()
    }

    /// The source of the kernel that runs the function of `shader`.
    pub fn kernel(&self, shader: &Shader) -> String {
        kernel_source(shader, &self.function, A::TYPES, R::TYPE)
    }

    /// The SPIR-V of `kernel`, this check's kernel of `shader`, after the layout and signature
    /// comparisons ([`compile_call`]).
    pub(in crate::gpu) fn compile(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, Error> {
        let call = Call {
            function: &self.function,
            parameters: A::TYPES,
            result: R::TYPE,
        };
        compile_call(shader, &call, kernel)
    }

    /// Runs the check on the function of `shader` (see [`Check::run`]).
    pub fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error> {
        let prepared = self.prepare(gpu, shader)?;
        self.run_prepared_one(prepared, config)
    }

    /// Compares the layouts, compiles the kernel, compares the signature and makes the pipeline
    /// (see [`Check::prepare`]).
    pub fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error> {
        let started = Instant::now();
        let (mut clock, mut times) = (started, PhaseTimes::default());
        let kernel = self.kernel(shader);
        let pipeline = match gpu.missing_feature(shader.features()) {
            Some(reason) => Err(reason),
            None => {
                let spirv = self.compile(shader, &kernel)?;
                times.lap(Phase::Compile, &mut clock);
                let pipeline = ComputeKernel::new(gpu, &spirv, 0)?;
                times.lap(Phase::Pipeline, &mut clock);
                Ok(Box::new(pipeline) as Box<dyn Dispatch>)
            }
        };
        Ok(PreparedCheck::new(
            shader,
            gpu.description(),
            kernel,
            pipeline,
            (started, times),
        ))
    }

    /// Runs the cases on prepared checks, each batch once for all of them (see
    /// [`Check::run_prepared`]). Each report's time includes its preparation's and the whole run's.
    pub fn run_prepared(
        &self,
        prepared: Vec<PreparedCheck<'_>>,
        config: &RunConfig,
    ) -> Vec<Result<Report, Error>> {
        let started = Instant::now();
        let seed = match config.validate() {
            Ok(seed) => seed,
            Err(e) => return prepared.iter().map(|_| Err(e.clone())).collect(),
        };
        let mut lanes: Vec<Lane<'_>> = prepared
            .iter()
            .filter_map(|check| check.pipeline.as_ref().ok())
            .map(|pipeline| Lane::new(pipeline.as_ref()))
            .collect();
        let generation = self.run_batches(&mut lanes, config, seed);
        let mut lanes = lanes.into_iter();
        prepared
            .iter()
            .map(|check| {
                let (mut stats, outcome) = match &check.pipeline {
                    Err(reason) => (Stats::default(), Outcome::NotRun(reason.clone())),
                    Ok(_) => {
                        let lane = lanes.next().expect("a lane per pipeline");
                        generation.as_ref().map_err(Error::clone)?;
                        self.judge_lane(lane, config, seed, &check.kernel)?
                    }
                };
                stats.times += check.times;
                Ok(Report::new(
                    self.function.clone(),
                    check.language,
                    check.device.clone(),
                    seed,
                    &stats,
                    outcome,
                    check.elapsed + started.elapsed(),
                ))
            })
            .collect()
    }

    /// [`FunctionCheck::run_prepared`] on one prepared check.
    pub(in crate::gpu) fn run_prepared_one(
        &self,
        prepared: PreparedCheck<'_>,
        config: &RunConfig,
    ) -> Result<Report, Error> {
        let mut reports = self.run_prepared(vec![prepared], config);
        reports.pop().expect("one report per prepared check")
    }

    /// The outcome of a lane whose batches have run: its error, or the shrunk first disagreement,
    /// or passed.
    fn judge_lane(
        &self,
        lane: Lane<'_>,
        config: &RunConfig,
        seed: u64,
        kernel: &str,
    ) -> Result<(Stats, Outcome), Error> {
        let mut stats = lane.stats;
        if let Some(e) = lane.error {
            return Err(e);
        }
        let outcome = match lane.first {
            None => Outcome::Passed,
            Some(mismatch) => {
                let shrinking = Instant::now();
                let shrunk = self.shrink(lane.pipeline, config, seed, mismatch)?;
                stats.times.add(Phase::Shrinking, shrinking.elapsed());
                Outcome::Failed(Box::new(self.failure(
                    shrunk,
                    stats.disagreeing,
                    kernel.to_string(),
                )))
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

    fn run_prepared(
        &self,
        prepared: Vec<PreparedCheck<'_>>,
        config: &RunConfig,
    ) -> Vec<Result<Report, Error>> {
        FunctionCheck::run_prepared(self, prepared, config)
    }

    #[cfg(feature = "browser")]
    fn prepare_browser<'g>(
        &self,
        device: &'g super::BrowserDevice,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error> {
        FunctionCheck::prepare_browser(self, device, shader)
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
    let call = Call {
        function,
        parameters: A::TYPES,
        result: R::TYPE,
    };
    let pipeline = ComputeKernel::new(gpu, &compile_call(shader, &call, &kernel)?, 0)?;
    let mut input = Vec::new();
    cases.iter().for_each(|args| args.write(&mut input));
    let output = pipeline.dispatch(cases.len(), &input, cases.len() * R::TYPE.words())?;
    let mut words = &output[..];
    Ok(cases.iter().map(|_| R::read(&mut words)).collect())
}
