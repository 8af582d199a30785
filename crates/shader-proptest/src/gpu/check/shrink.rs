//! Shrinking: the failing case re-generated from its batch's seed and simplified by proptest while
//! it still fails, one dispatch per step.

use super::batches::{generate, Mismatch};
use super::config::{batch_runner, RunConfig};
use super::report::Failure;
use super::FunctionCheck;
use crate::gpu::compute::ComputeKernel;
use crate::gpu::device::Error;
use crate::value::{Args, Value};
use proptest::strategy::ValueTree;

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// Re-generates the failing case from its batch's seed and simplifies it while it still
    /// fails, one dispatch per step.
    pub(super) fn shrink(
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
