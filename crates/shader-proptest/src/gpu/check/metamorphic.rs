//! Metamorphic checks: a shader function compared with itself under a transformation of its
//! inputs, for functions with no Rust twin.

use super::config::splitmix;
use super::oracle::Oracle;
use super::{Check, FunctionCheck, PreparedCheck, Report, RunConfig};
use crate::gpu::device::Gpu;
use crate::gpu::error::Error;
use crate::shader::Shader;
use crate::tolerance::Tolerance;
use crate::value::{Args, Value};
use proptest::strategy::{BoxedStrategy, Strategy};
use std::sync::Arc;

/// A shader function checked against itself: for every case `x` the device computes `f(x)` and
/// `f(transform(x))`, and `restore(x, f(transform(x)))`, the second result taken back to the
/// case's own terms, must be within the tolerance of `f(x)`. It needs no Rust twin of the
/// function, only a property it has: invariance under a translation, a rotation or a uniform
/// scale, equivariance (a footprint that scales with the scene: `restore` divides by the scale;
/// a direction that turns with it: `restore` turns it back), a sign or an order that does not
/// matter.
///
/// Everything else is a [`FunctionCheck`]'s: cases from a proptest strategy in batches (each
/// case and its transform in one dispatch), the validation layer, the tolerance (its bound for a
/// case is computed from the case as given and `f(x)`'s components), the vacuous share (against
/// the spread of `f(x)`, in the case's own terms), and a failure shrunk to a simpler case and
/// reported with the seed that replays it. A
/// transformation with a random parameter (a scale, a rotation) draws it from the case itself,
/// [`case_seed`], so that a case and its transform replay and shrink together.
///
/// ```
/// use shader_proptest::{case_seed, Gpu, MetamorphicCheck, RunConfig, Shader, Tolerance};
///
/// // A falloff between two radii, with no Rust twin. Scaling every length by the same power of
/// // two, 2^-20 to 2^20 drawn from the case, must leave it unchanged.
/// let shader = Shader::wgsl("fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }");
/// fn scale(case: &(f32, f32, f32)) -> f32 {
///     2f32.powi((case_seed(case) % 41) as i32 - 20)
/// }
/// let check = MetamorphicCheck::new(
///     "falloff",
///     || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0),
///     |case: &(f32, f32, f32)| {
///         let s = scale(case);
///         (case.0 * s, case.1 * s, case.2 * s)
///     },
///     |_, falloff: f32| falloff,
/// )
/// .tolerance(Tolerance::Absolute(1e-6));
/// let report = check.run(&Gpu::new()?, &shader, &RunConfig::default())?;
/// println!("{report}");
/// report.assert_passed();
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct MetamorphicCheck<A, R> {
    check: FunctionCheck<A, R>,
}

impl<A: Args, R: Value> MetamorphicCheck<A, R> {
    /// A check that `restore(x, function(transform(x)))` is `function(x)` for the cases `x` from
    /// the strategies `strategy` makes (one per generating thread), bit-exact until
    /// [`MetamorphicCheck::tolerance`] says otherwise.
    pub fn new<S>(
        function: impl Into<String>,
        strategy: impl Fn() -> S + Send + Sync + 'static,
        transform: impl Fn(&A) -> A + Send + Sync + 'static,
        restore: impl Fn(&A, R) -> R + Send + Sync + 'static,
    ) -> MetamorphicCheck<A, R>
    where
        S: Strategy<Value = A> + 'static,
    {
        let relation = Oracle::Relation {
            transform: Arc::new(transform),
            restore: Arc::new(restore),
        };
        MetamorphicCheck {
            check: FunctionCheck::with_parts(function.into(), strategy, relation, Tolerance::Exact),
        }
    }

    /// The same check with `tolerance`: the largest `|restore(x, function(transform(x))) -
    /// function(x)|` per component, its bounds computed from `x` and `function(x)`'s components.
    pub fn tolerance(self, tolerance: Tolerance<A>) -> MetamorphicCheck<A, R> {
        MetamorphicCheck {
            check: self.check.tolerance(tolerance),
        }
    }

    /// The same check on those of its cases that `keep` accepts; `reason` names the others
    /// ([`FunctionCheck::with_filter`]).
    pub fn with_filter(
        &self,
        reason: &'static str,
        keep: impl Fn(&A) -> bool + Clone + Send + Sync + 'static,
    ) -> MetamorphicCheck<A, R> {
        MetamorphicCheck {
            check: self.check.with_filter(reason, keep),
        }
    }

    /// The shader function.
    pub fn function(&self) -> &str {
        self.check.function()
    }

    /// A strategy for the check's cases (before their transformation).
    pub fn strategy(&self) -> BoxedStrategy<A> {
        self.check.strategy()
    }

    /// The source of the kernel that runs the function of `shader` (once per case and once per
    /// transformed case).
    pub fn kernel(&self, shader: &Shader) -> String {
        self.check.kernel(shader)
    }

    /// Runs the check on the function of `shader` (see [`Check::run`]).
    pub fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error> {
        self.check.run(gpu, shader, config)
    }
}

impl<A: Args, R: Value> Check for MetamorphicCheck<A, R> {
    fn function(&self) -> &str {
        self.check.function()
    }

    fn kernel(&self, shader: &Shader) -> String {
        self.check.kernel(shader)
    }

    fn run(&self, gpu: &Gpu, shader: &Shader, config: &RunConfig) -> Result<Report, Error> {
        self.check.run(gpu, shader, config)
    }

    fn prepare<'g>(&self, gpu: &'g Gpu, shader: &Shader) -> Result<PreparedCheck<'g>, Error> {
        self.check.prepare(gpu, shader)
    }

    fn run_prepared(
        &self,
        prepared: Vec<PreparedCheck<'_>>,
        config: &RunConfig,
    ) -> Vec<Result<Report, Error>> {
        self.check.run_prepared(prepared, config)
    }

    #[cfg(feature = "browser")]
    fn prepare_browser<'g>(
        &self,
        device: &'g crate::gpu::BrowserDevice,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error> {
        self.check.prepare_browser(device, shader)
    }
}

/// A number drawn from a case's words alone (SplitMix64 over them): the random parameter of a
/// transformation (a scale's exponent, a rotation's index) that replays with the case and
/// changes when shrinking changes it.
///
/// ```
/// use shader_proptest::case_seed;
///
/// assert_eq!(case_seed(&(1.0f32, 2u32)), case_seed(&(1.0f32, 2u32)));
/// assert_ne!(case_seed(&(1.0f32, 2u32)), case_seed(&(1.0f32, 3u32)));
/// ```
pub fn case_seed<A: Args>(args: &A) -> u64 {
    let mut words = Vec::with_capacity(A::TYPES.iter().map(|ty| ty.words()).sum());
    args.write(&mut words);
    words
        .iter()
        .fold(0, |seed, &word| splitmix(seed ^ u64::from(word)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::check::batches::Lane;
    use crate::gpu::compute::{Dispatch, KernelRun};
    use crate::gpu::phases::PhaseTimes;

    /// A device that computes `x * 0.5` for cases of one `f32` on the processor, and `x * 0.25`
    /// above `wrong_above`.
    struct Half {
        wrong_above: f32,
    }

    impl Dispatch for Half {
        fn dispatch(&self, run: KernelRun<'_>, _times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
            let half = |x: f32| if x > self.wrong_above { x * 0.25 } else { x * 0.5 };
            assert_eq!(run.input.len(), run.invocations, "one word per invocation");
            Ok(run
                .input
                .iter()
                .map(|&word| half(f32::from_bits(word)).to_bits())
                .collect())
        }
    }

    /// `half(2 x) = 2 half(x)`, on `x` in `[-1, 1]`.
    fn doubling() -> MetamorphicCheck<(f32,), f32> {
        MetamorphicCheck::new(
            "half",
            || (-1.0f32..1.0,),
            |&(x,)| (2.0 * x,),
            |_, half| 0.5 * half,
        )
    }

    const CONFIG: RunConfig = RunConfig {
        cases: 10_000,
        batch: 1000,
        seed: Some(5),
        threads: 2,
        shrink_steps: 1024,
    };

    /// A device that has the property passes every case: each case and its transform ran.
    #[test]
    fn a_relation_that_holds_passes() {
        let device = Half {
            wrong_above: f32::INFINITY,
        };
        let mut lanes = [Lane::new(&device)];
        doubling()
            .check
            .run_batches(&mut lanes, &CONFIG, 5)
            .expect("runs");
        let [lane] = lanes;
        assert!(lane.first.is_none() && lane.error.is_none());
        assert_eq!(lane.stats.cases, CONFIG.cases);
        assert_eq!(lane.stats.max_error, 0.0);
    }

    /// A device that breaks the property above 1.5 fails where the transformed case crosses it,
    /// and the case shrinks toward 0 until it just does: `x` just above 0.75, transformed to
    /// just above 1.5, whose result halved is held to the device's result for `x`.
    #[test]
    fn a_broken_relation_is_shrunk_to_its_edge() {
        let device = Half { wrong_above: 1.5 };
        let check = doubling();
        let mut lanes = [Lane::new(&device)];
        check.check.run_batches(&mut lanes, &CONFIG, 5).expect("runs");
        let [lane] = lanes;
        let mismatch = lane.first.expect("a disagreement");
        let shrunk = check
            .check
            .shrink(&device, &CONFIG, 5, mismatch)
            .expect("shrinks");
        let (x,) = shrunk.args;
        assert!(x > 0.75 && x < 0.751, "shrunk to {x}");
        assert_eq!(shrunk.shader, 0.5 * (2.0 * x * 0.25));
        assert_eq!(shrunk.expected, x * 0.5);
        let failure = check.check.failure(shrunk, lane.stats.disagreeing, String::new());
        assert_eq!(failure.transformed, Some(format!("({:?},)", 2.0 * x)));
    }

    /// The seed of a case follows from its words: equal cases, equal seeds.
    #[test]
    fn case_seeds_follow_the_words() {
        let seeds: std::collections::HashSet<u64> = (0..1000u32).map(|n| case_seed(&(n, 1.0f32))).collect();
        assert_eq!(seeds.len(), 1000);
        assert_eq!(case_seed(&(-0.0f32,)), case_seed(&(-0.0f32,)));
        assert_ne!(case_seed(&(-0.0f32,)), case_seed(&(0.0f32,)));
    }
}
