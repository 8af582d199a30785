//! What a check holds the device's results against: the Rust mirror of the function, or the
//! shader function itself under a transformation of its inputs (a metamorphic relation).

use crate::value::{Args, Value};
use std::sync::Arc;

/// A Rust twin of the shader function: the expected result of a case.
pub(super) type Mirror<A, R> = dyn Fn(A) -> R + Send + Sync;

/// How a case is changed: the case the device runs beside it.
pub(super) type Transform<A> = dyn Fn(&A) -> A + Send + Sync;

/// The transformed case's result taken back to the case's own terms (a scale undone, a rotation
/// turned back), given the case.
pub(super) type Restore<A, R> = dyn Fn(&A, R) -> R + Send + Sync;

/// The expected result of each case.
pub(super) enum Oracle<A, R> {
    /// The mirror's result for the case, known before the device runs it.
    Mirror(Arc<Mirror<A, R>>),
    /// The device runs each case twice, as given and transformed; the transformed case's result,
    /// restored, is expected to be the result as given.
    Relation {
        transform: Arc<Transform<A>>,
        restore: Arc<Restore<A, R>>,
    },
}

impl<A, R> Clone for Oracle<A, R> {
    fn clone(&self) -> Self {
        match self {
            Oracle::Mirror(mirror) => Oracle::Mirror(Arc::clone(mirror)),
            Oracle::Relation { transform, restore } => Oracle::Relation {
                transform: Arc::clone(transform),
                restore: Arc::clone(restore),
            },
        }
    }
}

/// The device's result for a case, the result expected of it, and why they disagree, if they do.
#[derive(Clone)]
pub(super) struct Judged<R> {
    /// The device's result: for a relation, its result for the transformed case, restored.
    pub shader: R,
    /// The mirror's result, or for a relation the device's result for the case as given.
    pub expected: R,
    /// What differs beyond the tolerance.
    pub disagreement: Option<String>,
}

impl<A: Args, R: Value> Oracle<A, R> {
    /// Kernel invocations per case: one, or two for a relation (the case and its transform).
    pub fn invocations(&self) -> usize {
        match self {
            Oracle::Mirror(_) => 1,
            Oracle::Relation { .. } => 2,
        }
    }

    /// Appends the words the device reads for `args`: the case, and for a relation the
    /// transformed case after it.
    pub fn encode(&self, args: &A, input: &mut Vec<u32>) {
        args.write(input);
        if let Oracle::Relation { transform, .. } = self {
            transform(args).write(input);
        }
    }

    /// Reads the device's results for `args` from `words` (advancing it): the result to judge
    /// (for a relation, the transformed case's, restored), and for a relation the result expected
    /// of it (the case's as given).
    pub fn read(&self, args: &A, words: &mut &[u32]) -> (R, Option<R>) {
        match self {
            Oracle::Mirror(_) => (R::read(words), None),
            Oracle::Relation { restore, .. } => {
                let given = R::read(words);
                let transformed = R::read(words);
                (restore(args, transformed), Some(given))
            }
        }
    }

    /// The transformed case, for a relation.
    pub fn transformed(&self, args: &A) -> Option<A> {
        match self {
            Oracle::Mirror(_) => None,
            Oracle::Relation { transform, .. } => Some(transform(args)),
        }
    }
}
