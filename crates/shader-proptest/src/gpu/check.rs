//! Checks: a shader function against its Rust mirror, on batches of generated cases.
//!
//! A check generates each batch of cases from its own seed with a proptest strategy, on as many
//! threads as the machine has, while the device runs the previous batch: one dispatch of a
//! generated kernel per batch. Every output component is compared with the mirror's within the
//! check's [`Tolerance`]; for finite inputs both outputs must be finite too. A failing case is
//! shrunk with proptest (re-generated from its batch's seed, then simplified one dispatch at a
//! time) and reported with its inputs, both outputs, the tolerance, the seed that replays the run
//! and the kernel's source.

use super::compute::ComputeKernel;
use super::device::{Error, Gpu};
use crate::compile::Language;
use crate::kernel::kernel_source;
use crate::layout::{compare, LayoutError};
use crate::shader::Shader;
use crate::tolerance::Tolerance;
use crate::value::{Args, ShaderType, StructType, Value};
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::fmt;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::sync_channel;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Environment variable that sets [`RunConfig::seed`] (decimal, or hexadecimal after `0x`), to
/// replay a run.
pub const SEED_ENV: &str = "SHADER_PROPTEST_SEED";

/// Strategy rejections (`prop_filter`) tolerated in a row before a check gives up.
const MAX_REJECTIONS: usize = 10_000;

/// How many cases a check runs, how they are batched and generated.
#[derive(Clone, Copy, Debug)]
pub struct RunConfig {
    /// At least this many cases are checked (before any shrinking).
    pub cases: usize,
    /// Cases per batch (one dispatch).
    pub batch: usize,
    /// The seed of the run; batch `i` is generated from a seed derived from it and `i`. `None`: the
    /// seed in [`SEED_ENV`] if that is set, else a fresh seed; either is printed in the report.
    pub seed: Option<u64>,
    /// Threads that generate cases and run the mirror.
    pub threads: usize,
    /// Most shrinking steps (one dispatch each) after a failure.
    pub shrink_steps: usize,
}

impl Default for RunConfig {
    /// 100,000 cases in batches of 8,192, the seed from [`SEED_ENV`] if set (else fresh), one
    /// thread per processor, up to 1,024 shrinking steps.
    fn default() -> Self {
        RunConfig {
            cases: 100_000,
            batch: 8192,
            seed: None,
            threads: std::thread::available_parallelism().map_or(1, usize::from),
            shrink_steps: 1024,
        }
    }
}

impl RunConfig {
    /// The configuration as a run uses it: [`Error::Config`] names the first field that is 0
    /// (`cases`, `batch`, `threads`: a run of nothing, or one no thread generates), or
    /// [`SEED_ENV`] with its value where `seed` is `None` and that variable holds no seed.
    /// Otherwise the seed the run uses: `seed`, else the variable's, else a fresh one.
    pub fn validate(&self) -> Result<u64, Error> {
        let counts = [
            ("cases", self.cases),
            ("batch", self.batch),
            ("threads", self.threads),
        ];
        if let Some(&(field, _)) = counts.iter().find(|(_, count)| *count == 0) {
            return Err(Error::Config {
                field,
                value: "0".into(),
                expected: "at least 1",
            });
        }
        run_seed(self.seed, std::env::var(SEED_ENV).ok())
    }
}

/// The seed of a run: `seed`, else the one in `variable` (the value of [`SEED_ENV`]), else a fresh
/// one; [`Error::Config`] where `variable` holds no seed.
fn run_seed(seed: Option<u64>, variable: Option<String>) -> Result<u64, Error> {
    match (seed, variable) {
        (Some(seed), _) => Ok(seed),
        (None, Some(text)) => parse_seed(&text).ok_or(Error::Config {
            field: SEED_ENV,
            value: text,
            expected: "a decimal seed, or a hexadecimal one after 0x",
        }),
        (None, None) => Ok(fresh_seed()),
    }
}

fn parse_seed(text: &str) -> Option<u64> {
    match text.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

/// A seed no earlier run used: the clock's nanoseconds mixed with the process id.
fn fresh_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |elapsed| elapsed.as_nanos() as u64);
    splitmix(nanos ^ u64::from(std::process::id()).rotate_left(32))
}

/// SplitMix64's finaliser: spreads the bits of `x`.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The proptest runner that generates batch `batch` of a run seeded with `seed`.
fn batch_runner(seed: u64, batch: usize) -> TestRunner {
    let first = splitmix(seed ^ splitmix(batch as u64));
    let mut bytes = [0u8; 16];
    bytes[..8].copy_from_slice(&first.to_le_bytes());
    bytes[8..].copy_from_slice(&splitmix(first).to_le_bytes());
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::XorShift, &bytes),
    )
}

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
    /// The seed that replays this run ([`RunConfig::seed`], [`SEED_ENV`]).
    pub seed: u64,
    /// Wall time of the whole check.
    pub elapsed: Duration,
    /// Passed, failed or not run.
    pub outcome: Outcome,
}

impl Report {
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
            "{:<38} {:<5} {:>9} cases  max error {:>9.3e}  ({:>6.4} of tolerance)  vacuous {:>6.2}%  {verdict}",
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

/// Counters of a run.
#[derive(Default)]
struct Stats {
    cases: usize,
    max_error: f32,
    max_ratio: f32,
    vacuous: usize,
    vacuous_by_component: Vec<usize>,
}

/// A batch generated by a worker: the cases, their words, the mirror's components and bounds.
struct Prepared<A> {
    index: usize,
    cases: Vec<A>,
    input: Vec<u32>,
    expected: Vec<f32>,
    bounds: Vec<f32>,
    vacuous: Vacuous,
}

/// Cases of a batch with a vacuous bound: in any component, and per component.
#[derive(Default)]
struct Vacuous {
    cases: usize,
    by_component: Vec<usize>,
}

/// Where a case first disagreed, and how.
struct Mismatch {
    batch: usize,
    case: usize,
    reason: String,
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

    /// The tolerance of each of `expected`'s components for the case `args`.
    pub fn bounds(&self, args: &A, expected: &R) -> Vec<f32> {
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, &components(expected), &mut bounds);
        bounds
    }

    /// Compares the shader's result `got` for `args` with the mirror's, within the tolerance: the
    /// largest error as a fraction of its tolerance, or what differs.
    pub fn compare(&self, args: &A, got: &R) -> Result<f32, String> {
        let expected = components(&self.mirror(args.clone()));
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, &expected, &mut bounds);
        self.judge_case(args, &components(got), &expected, &bounds)
            .map(|(_, max_ratio)| max_ratio)
    }

    /// Judges the device's components `got` for `args` against the mirror's `expected` within
    /// `bounds`. Vulkan lets a device flush subnormal floats to zero, in the inputs and results of
    /// any operation, unless the shader asks to preserve them (`DenormPreserve`), and the kernels
    /// do not ask. A case that disagrees is judged again against what such a device may compute:
    /// the mirror of its inputs flushed ([`flush_subnormals`], where it has subnormal inputs) and
    /// the mirror run with the processor flushing every subnormal operand and result
    /// ([`with_subnormals_flushed`]). Each component must then be within its bound of one of these
    /// results or of `expected` (a device may flush in one operation and not in another, so
    /// components may follow different ones; a copied input, for one, is never flushed). Returns
    /// the largest error and share of the bound, or the first judgement's reason.
    fn judge_case(
        &self,
        args: &A,
        got: &[f32],
        expected: &[f32],
        bounds: &[f32],
    ) -> Result<(f32, f32), String> {
        let first = match judge(args.is_finite(), got, expected, bounds) {
            Ok(errors) => return Ok(errors),
            Err(reason) => reason,
        };
        let mut allowed = vec![(expected.to_vec(), bounds.to_vec())];
        if let Some(flushed) = flush_subnormals(args) {
            allowed.push(self.expected_and_bounds(&flushed, self.mirror(flushed.clone())));
        }
        if let Some(result) = with_subnormals_flushed(|| self.mirror(args.clone())) {
            allowed.push(self.expected_and_bounds(args, result));
        }
        judge_each_component(args.is_finite(), got, &allowed).map_err(|_| first)
    }

    /// The components of the mirror's `result` for `args` and their bounds.
    fn expected_and_bounds(&self, args: &A, result: R) -> (Vec<f32>, Vec<f32>) {
        let expected = components(&result);
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, &expected, &mut bounds);
        (expected, bounds)
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
        let pipeline = if let Some(reason) = missing_feature(gpu, shader) {
            Err(Outcome::NotRun(reason))
        } else if let Err(error) = check_layouts(shader, A::TYPES, R::TYPE) {
            Err(Outcome::Failed(Box::new(Failure {
                reason: format!("the Rust and shader layouts differ: {error}"),
                input: String::new(),
                mirror: String::new(),
                shader: String::new(),
                shrink_steps: 0,
                kernel: kernel.clone(),
            })))
        } else {
            Ok(ComputeKernel::new(gpu, &compile(shader, &kernel)?, 0)?)
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
        let mut report = Report {
            function: self.function.clone(),
            language: prepared.language,
            cases: 0,
            max_error: 0.0,
            max_ratio: 0.0,
            vacuous: 0.0,
            most_vacuous_component: None,
            seed,
            elapsed: Duration::ZERO,
            outcome: Outcome::Passed,
        };
        match prepared.pipeline {
            Err(outcome) => report.outcome = outcome,
            Ok(pipeline) => {
                let mut stats = Stats::default();
                let mismatch = self.run_batches(&pipeline, config, seed, &mut stats)?;
                report.cases = stats.cases;
                report.max_error = stats.max_error;
                report.max_ratio = stats.max_ratio;
                let share = |count: usize| count as f64 / stats.cases.max(1) as f64;
                report.vacuous = share(stats.vacuous);
                report.most_vacuous_component = (0..stats.vacuous_by_component.len())
                    .max_by_key(|&component| stats.vacuous_by_component[component])
                    .filter(|&component| stats.vacuous_by_component[component] > 0)
                    .map(|component| (component, share(stats.vacuous_by_component[component])));
                if let Some(mismatch) = mismatch {
                    let failure = self.shrink(&pipeline, config, seed, mismatch, prepared.kernel)?;
                    report.outcome = Outcome::Failed(Box::new(failure));
                }
            }
        }
        report.elapsed = prepared.elapsed + started.elapsed();
        Ok(report)
    }

    /// Generates the batches on worker threads and runs them on the device as they arrive; returns
    /// the first disagreement (lowest batch, then case) among the batches run.
    fn run_batches(
        &self,
        pipeline: &ComputeKernel<'_>,
        config: &RunConfig,
        seed: u64,
        stats: &mut Stats,
    ) -> Result<Option<Mismatch>, Error> {
        let (batch, total) = (config.batch, config.cases);
        let batches = total.div_ceil(batch);
        let next = AtomicUsize::new(0);
        let stop = AtomicBool::new(false);
        let (sender, receiver) = sync_channel::<Result<Prepared<A>, Error>>(config.threads);
        std::thread::scope(|scope| {
            for _ in 0..config.threads {
                let sender = sender.clone();
                let (next, stop) = (&next, &stop);
                scope.spawn(move || loop {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    if index >= batches || stop.load(Ordering::Relaxed) {
                        break;
                    }
                    let size = batch.min(total - index * batch);
                    if sender.send(self.prepare_batch(seed, index, size)).is_err() {
                        break;
                    }
                });
            }
            drop(sender);
            let mut first: Option<Mismatch> = None;
            let mut error = None;
            for prepared in receiver {
                let outcome = prepared.and_then(|prepared| self.dispatch_batch(pipeline, &prepared, stats));
                match outcome {
                    Ok(None) => {}
                    Ok(Some(mismatch)) => {
                        stop.store(true, Ordering::Relaxed);
                        if first
                            .as_ref()
                            .is_none_or(|f| (mismatch.batch, mismatch.case) < (f.batch, f.case))
                        {
                            first = Some(mismatch);
                        }
                    }
                    Err(e) => {
                        stop.store(true, Ordering::Relaxed);
                        error.get_or_insert(e);
                    }
                }
            }
            match error {
                Some(e) => Err(e),
                None => Ok(first),
            }
        })
    }

    /// Generates batch `index` (`size` cases) and runs the mirror and the tolerance on it.
    fn prepare_batch(&self, seed: u64, index: usize, size: usize) -> Result<Prepared<A>, Error> {
        let mut runner = batch_runner(seed, index);
        let mut prepared = Prepared {
            index,
            cases: Vec::with_capacity(size),
            input: Vec::new(),
            expected: Vec::new(),
            bounds: Vec::new(),
            vacuous: Vacuous::default(),
        };
        (self.generator)(&mut runner, size, &mut prepared.cases)?;
        for args in &prepared.cases {
            args.write(&mut prepared.input);
            let start = prepared.expected.len();
            self.mirror(args.clone()).components(&mut prepared.expected);
            self.tolerance
                .bounds(args, &prepared.expected[start..], &mut prepared.bounds);
        }
        prepared.vacuous = count_vacuous(&prepared.expected, &prepared.bounds, size);
        Ok(prepared)
    }

    /// Runs one prepared batch and compares it: the first disagreeing case, if any.
    fn dispatch_batch(
        &self,
        pipeline: &ComputeKernel<'_>,
        prepared: &Prepared<A>,
        stats: &mut Stats,
    ) -> Result<Option<Mismatch>, Error> {
        let count = prepared.cases.len();
        let output = pipeline.dispatch(count, &prepared.input, count * R::TYPE.words())?;
        let per_case = prepared.expected.len() / count.max(1);
        let mut words = &output[..];
        let mut got = Vec::with_capacity(per_case);
        for (case, args) in prepared.cases.iter().enumerate() {
            got.clear();
            R::read(&mut words).components(&mut got);
            let range = case * per_case..(case + 1) * per_case;
            match self.judge_case(
                args,
                &got,
                &prepared.expected[range.clone()],
                &prepared.bounds[range],
            ) {
                Ok((max_error, max_ratio)) => {
                    stats.max_error = stats.max_error.max(max_error);
                    stats.max_ratio = stats.max_ratio.max(max_ratio);
                    stats.cases += 1;
                }
                Err(reason) => {
                    return Ok(Some(Mismatch {
                        batch: prepared.index,
                        case,
                        reason,
                    }))
                }
            }
        }
        // The batch agreed: its vacuous cases count (a failing batch's are not compared).
        stats.vacuous += prepared.vacuous.cases;
        let components = &prepared.vacuous.by_component;
        stats
            .vacuous_by_component
            .resize(stats.vacuous_by_component.len().max(components.len()), 0);
        stats
            .vacuous_by_component
            .iter_mut()
            .zip(components)
            .for_each(|(total, count)| *total += count);
        Ok(None)
    }

    /// Re-generates the failing case from its batch's seed and simplifies it while it still
    /// fails, one dispatch per step.
    fn shrink(
        &self,
        pipeline: &ComputeKernel<'_>,
        config: &RunConfig,
        seed: u64,
        mismatch: Mismatch,
        kernel: String,
    ) -> Result<Failure, Error> {
        let mut runner = batch_runner(seed, mismatch.batch);
        let strategy = (self.strategy)();
        let mut tree = generate(&strategy, &mut runner)?;
        for _ in 0..mismatch.case {
            tree = generate(&strategy, &mut runner)?;
        }
        let mut smallest = (tree.current(), mismatch.reason);
        let mut steps = 0;
        let mut simplified = tree.simplify();
        while simplified && steps < config.shrink_steps {
            steps += 1;
            let candidate = tree.current();
            match self.evaluate_one(pipeline, &candidate)? {
                Err(reason) => {
                    smallest = (candidate, reason);
                    simplified = tree.simplify();
                }
                Ok(()) => simplified = tree.complicate(),
            }
        }
        let (args, reason) = smallest;
        let shader = self.run_one(pipeline, &args)?;
        Ok(Failure {
            reason,
            input: format!("{args:?}"),
            mirror: format!("{:?}", self.mirror(args.clone())),
            shader: format!("{shader:?}"),
            shrink_steps: steps,
            kernel,
        })
    }

    fn run_one(&self, pipeline: &ComputeKernel<'_>, args: &A) -> Result<R, Error> {
        let mut input = Vec::new();
        args.write(&mut input);
        let output = pipeline.dispatch(1, &input, R::TYPE.words())?;
        Ok(R::read(&mut &output[..]))
    }

    /// Runs one case: `Ok(Err(reason))` when it disagrees.
    fn evaluate_one(&self, pipeline: &ComputeKernel<'_>, args: &A) -> Result<Result<(), String>, Error> {
        let got = self.run_one(pipeline, args)?;
        Ok(self.compare(args, &got).map(|_| ()))
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
    let pipeline = ComputeKernel::new(gpu, &compile(shader, &kernel)?, 0)?;
    let mut input = Vec::new();
    cases.iter().for_each(|args| args.write(&mut input));
    let output = pipeline.dispatch(cases.len(), &input, cases.len() * R::TYPE.words())?;
    let mut words = &output[..];
    Ok(cases.iter().map(|_| R::read(&mut words)).collect())
}

/// Compiles a kernel of `shader`, naming the kernel in the error.
pub(crate) fn compile(shader: &Shader, kernel: &str) -> Result<Vec<u32>, Error> {
    shader
        .compile_kernel(kernel)
        .map_err(|error| Error::Compile(format!("{error}\n--- kernel ---\n{kernel}")))
}

/// The first feature `shader` needs that `gpu` lacks, as a reason.
pub(crate) fn missing_feature(gpu: &Gpu, shader: &Shader) -> Option<String> {
    shader
        .features()
        .iter()
        .find(|&&feature| !gpu.has(feature))
        .map(|feature| format!("{} lacks {}", gpu.name(), feature.name()))
}

/// Compares the Rust layout of every `pod` struct among the types with the shader's
/// ([`Shader::struct_layout`]).
fn check_layouts(shader: &Shader, parameters: &[ShaderType], result: ShaderType) -> Result<(), LayoutError> {
    let mut structs: Vec<&'static StructType> = Vec::new();
    parameters
        .iter()
        .chain([&result])
        .for_each(|ty| ty.structs(&mut structs));
    for ty in structs {
        let Some(rust_layout) = ty.rust_layout else {
            continue;
        };
        compare(&rust_layout(), &shader.struct_layout(ty.name)?)?;
    }
    Ok(())
}

/// Appends `count` cases from `runner` to a batch, each made by [`generate`] from the check's
/// strategy in its own type (no boxed value trees): the values, and the random numbers drawn, are
/// those of the boxed strategy that shrinking replays.
type Generator<A> = dyn Fn(&mut TestRunner, usize, &mut Vec<A>) -> Result<(), Error> + Send + Sync;

/// A value tree from `strategy`, retrying rejected values.
fn generate<S: Strategy>(strategy: &S, runner: &mut TestRunner) -> Result<S::Tree, Error> {
    for _ in 0..MAX_REJECTIONS {
        if let Ok(tree) = strategy.new_tree(runner) {
            return Ok(tree);
        }
    }
    Err(Error::Strategy(format!(
        "the strategy rejected {MAX_REJECTIONS} values in a row"
    )))
}

fn components<R: Value>(value: &R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

/// Compares one case's components: the largest error and the largest share of its bound, or
/// `Err` naming the first component that differs beyond its bound, or a non-finite output for
/// finite inputs.
fn judge(finite_input: bool, got: &[f32], expected: &[f32], bounds: &[f32]) -> Result<(f32, f32), String> {
    let finite = |values: &[f32]| values.iter().all(|x| x.is_finite());
    if finite_input && !(finite(got) && finite(expected)) {
        return Err(String::from("non-finite output for finite input"));
    }
    let (mut max_error, mut max_ratio) = (0.0f32, 0.0f32);
    for (index, ((&got, &expected), &bound)) in got.iter().zip(expected).zip(bounds).enumerate() {
        let Some((error, ratio)) = within_bound(finite_input, got, expected, bound) else {
            let error = (got - expected).abs();
            return Err(format!(
                "component {index} differs by {error:e} (tolerance {bound:e})"
            ));
        };
        max_error = max_error.max(error);
        max_ratio = max_ratio.max(ratio);
    }
    Ok((max_error, max_ratio))
}

/// `got`'s error from `expected` and its share of `bound` (0 for a bound of 0), where the error
/// is within the bound and `expected` is finite (where the inputs are).
fn within_bound(finite_input: bool, got: f32, expected: f32, bound: f32) -> Option<(f32, f32)> {
    let error = if got == expected {
        0.0
    } else {
        (got - expected).abs()
    };
    let within = (expected.is_finite() || !finite_input) && error <= bound;
    within.then_some((error, if bound > 0.0 { error / bound } else { 0.0 }))
}

/// Compares one case's components with several allowed results (components and bounds): each
/// component must be within its bound of the same component of one of them (finite, where the
/// inputs are). The largest error and share of the bound, taking each component's closest result.
fn judge_each_component(
    finite_input: bool,
    got: &[f32],
    allowed: &[(Vec<f32>, Vec<f32>)],
) -> Result<(f32, f32), String> {
    if finite_input && !got.iter().all(|x| x.is_finite()) {
        return Err(String::from("non-finite output for finite input"));
    }
    let (mut max_error, mut max_ratio) = (0.0f32, 0.0f32);
    for (index, &got) in got.iter().enumerate() {
        let matches = allowed
            .iter()
            .filter_map(|(expected, bounds)| within_bound(finite_input, got, expected[index], bounds[index]));
        let Some((error, ratio)) = matches.min_by(|a, b| a.1.total_cmp(&b.1)) else {
            return Err(format!("component {index} matches no allowed result"));
        };
        max_error = max_error.max(error);
        max_ratio = max_ratio.max(ratio);
    }
    Ok((max_error, max_ratio))
}

/// Runs `f` with the processor flushing subnormal operands and results of f32 arithmetic to zero
/// (x86-64's MXCSR bits DAZ and FTZ, restored afterwards), as a device without `DenormPreserve`
/// may: the mirror's SSE arithmetic then flushes in every operation. `None` on other processors.
fn with_subnormals_flushed<T>(f: impl FnOnce() -> T) -> Option<T> {
    #[cfg(target_arch = "x86_64")]
    {
        // Deprecated in favour of inline assembly; the intrinsics say what they do.
        #[allow(deprecated)]
        use std::arch::x86_64::{_mm_getcsr, _mm_setcsr};
        /// MXCSR's flush-to-zero (results) and denormals-are-zero (operands) bits.
        const FLUSH_TO_ZERO: u32 = 1 << 15;
        const DENORMALS_ARE_ZERO: u32 = 1 << 6;
        /// Restores the saved control word, also when `f` unwinds.
        struct Restore(u32);
        impl Drop for Restore {
            #[allow(deprecated)]
            fn drop(&mut self) {
                // SAFETY: writes back the control word this thread had before.
                unsafe { _mm_setcsr(self.0) };
            }
        }
        // SAFETY: reads and writes this thread's SSE control word; DAZ and FTZ change only how
        // subnormals are read and rounded, and the guard restores the word.
        #[allow(deprecated)]
        let _restore = unsafe {
            let saved = _mm_getcsr();
            _mm_setcsr(saved | FLUSH_TO_ZERO | DENORMALS_ARE_ZERO);
            Restore(saved)
        };
        Some(f())
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = f;
        None
    }
}

/// `args` with every subnormal float read as a zero of its sign, as a device that flushes
/// subnormal inputs sees them, or `None` when `args` holds no subnormal float.
fn flush_subnormals<A: Args>(args: &A) -> Option<A> {
    let mut words = Vec::new();
    args.write(&mut words);
    let mut is_float = Vec::new();
    A::TYPES.iter().for_each(|ty| ty.float_words(&mut is_float));
    let mut flushed = false;
    for (word, float) in words.iter_mut().zip(is_float) {
        if float && f32::from_bits(*word).is_subnormal() {
            *word &= 0x8000_0000;
            flushed = true;
        }
    }
    flushed.then(|| A::read(&mut &words[..]))
}

/// The cases of a batch with a vacuous bound: one at least as wide as the spread of its
/// component's (finite) mirror values over the batch, where that spread is not zero.
fn count_vacuous(expected: &[f32], bounds: &[f32], cases: usize) -> Vacuous {
    let per_case = expected.len() / cases.max(1);
    let spreads: Vec<f32> = (0..per_case)
        .map(|component| {
            let values = expected
                .iter()
                .skip(component)
                .step_by(per_case.max(1))
                .filter(|x| x.is_finite());
            let (low, high) = values.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            });
            high - low
        })
        .collect();
    let mut vacuous = Vacuous {
        cases: 0,
        by_component: vec![0; per_case],
    };
    for case in 0..cases {
        let mut any = false;
        for (component, &spread) in spreads.iter().enumerate() {
            if spread > 0.0 && bounds[case * per_case + component] >= spread {
                vacuous.by_component[component] += 1;
                any = true;
            }
        }
        vacuous.cases += usize::from(any);
    }
    vacuous
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A run of 0 cases, batches of 0 or 0 threads is refused, naming the field and the value.
    #[test]
    fn zero_counts_are_refused_naming_the_field() {
        let zero_cases = RunConfig {
            cases: 0,
            ..RunConfig::default()
        };
        let zero_batch = RunConfig {
            batch: 0,
            ..RunConfig::default()
        };
        let zero_threads = RunConfig {
            threads: 0,
            ..RunConfig::default()
        };
        for (config, field) in [
            (zero_cases, "cases"),
            (zero_batch, "batch"),
            (zero_threads, "threads"),
        ] {
            let message = config.validate().expect_err(field).to_string();
            assert_eq!(message, format!("{field} = \"0\": expected at least 1"));
        }
    }

    /// The seed comes from the configuration, else from the variable; a variable that holds no
    /// seed is refused, naming the variable and its value.
    #[test]
    fn the_seed_variable_must_hold_a_seed() {
        assert_eq!(run_seed(Some(5), Some("banana".into())).ok(), Some(5));
        assert_eq!(run_seed(None, Some("0x1f".into())).ok(), Some(31));
        assert_eq!(run_seed(None, Some("31".into())).ok(), Some(31));
        for text in ["banana", "", "0x", "-1", "0x1g"] {
            let message = run_seed(None, Some(text.into())).expect_err(text).to_string();
            assert!(
                message.starts_with(&format!("{SEED_ENV} = {text:?}")),
                "{message}"
            );
        }
    }

    /// A batch's cases are the values that shrinking re-generates from the batch's seed through
    /// the boxed strategy, case by case, rejections included.
    #[test]
    fn batches_replay_through_the_boxed_strategy() {
        let check = FunctionCheck::new(
            "f",
            || {
                let mixed = prop_oneof![3 => -1.0f32..1.0, 1 => Just(0.0f32)];
                (mixed, 0u32..100).prop_filter("odd", |(_, n)| n % 2 == 0)
            },
            |(x, n): (f32, u32)| x + n as f32,
        );
        let mut cases = Vec::new();
        (check.generator)(&mut batch_runner(7, 3), 500, &mut cases).expect("cases");
        let strategy = check.strategy();
        let mut runner = batch_runner(7, 3);
        for case in &cases {
            let replayed = generate(&strategy, &mut runner).expect("a case").current();
            assert_eq!(case.0.to_bits(), replayed.0.to_bits());
            assert_eq!(case.1, replayed.1);
        }
        assert!(cases.iter().all(|(_, n)| n % 2 == 0));
    }

    /// Subnormal inputs are read as zeros of their sign, every other word as it was; a case is
    /// accepted against the flushed inputs' mirror, and only when it matches that one or the
    /// mirror of the inputs as given.
    #[test]
    fn subnormal_inputs_may_be_flushed() {
        let tiny = f32::from_bits(1);
        let args = (tiny, glam::Vec3::new(-tiny, 1.0, f32::MIN_POSITIVE), 7u32);
        let (x, v, n) = flush_subnormals(&args).expect("subnormals to flush");
        assert_eq!(x.to_bits(), 0);
        assert_eq!(v.x.to_bits(), (-0.0f32).to_bits());
        assert_eq!((v.y, v.z, n), (1.0, f32::MIN_POSITIVE, 7));
        assert!(flush_subnormals(&(1.0f32, glam::Vec3::ONE, 1u32)).is_none());

        // x * 2^100: 2^-49 for the smallest subnormal as given, 0 when it is flushed.
        let check = FunctionCheck::new("scale", || (any::<f32>(),), |(x,): (f32,)| x * 2.0f32.powi(100));
        let as_given = tiny * 2.0f32.powi(100);
        assert!(check.compare(&(tiny,), &as_given).is_ok());
        assert!(check.compare(&(tiny,), &0.0).is_ok());
        assert!(check.compare(&(tiny,), &(2.0 * as_given)).is_err());
        assert!(check.compare(&(1.0,), &0.0).is_err());
    }

    /// A subnormal result of normal inputs may be flushed (x * 2^-140 for x = 1 is 2^-140 as
    /// computed, 0 flushed), and each component may follow its own choice: a copied input keeps
    /// its subnormal while the product beside it is flushed. Nothing else is accepted.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn subnormal_results_may_be_flushed() {
        let scale = |(x,): (f32,)| glam::Vec2::new(x, x * 2.0f32.powi(-140));
        let check = FunctionCheck::new("copy_and_scale", || (any::<f32>(),), scale);
        let tiny = 2.0f32.powi(-140);
        assert!(check.compare(&(1.0,), &glam::Vec2::new(1.0, tiny)).is_ok());
        assert!(check.compare(&(1.0,), &glam::Vec2::new(1.0, 0.0)).is_ok());
        assert!(check.compare(&(1.0,), &glam::Vec2::new(1.0, 2.0 * tiny)).is_err());
        assert!(check.compare(&(1.0,), &glam::Vec2::new(0.0, 0.0)).is_err());
        // 2^-140 copied as given beside its product 2^-280, which is 0 either way; or both flushed.
        assert!(check.compare(&(tiny,), &glam::Vec2::new(tiny, 0.0)).is_ok());
        assert!(check.compare(&(tiny,), &glam::Vec2::new(0.0, 0.0)).is_ok());
        let double = || std::hint::black_box(tiny) * std::hint::black_box(2.0);
        assert_eq!(with_subnormals_flushed(double), Some(0.0));
        assert_eq!(double(), 2.0 * tiny, "the control word is restored");
    }
}
