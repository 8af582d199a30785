//! Judging: whether the device's result for a case is within the tolerance of the mirror's, and
//! again against what a device that flushes subnormals may compute.

use super::oracle::Oracle;
use super::FunctionCheck;
use crate::value::{Args, Value};

/// How one case compares: the largest error and share of its bound over its components, and
/// why it disagrees, where it does.
pub(super) struct Verdict {
    pub max_error: f32,
    pub max_ratio: f32,
    pub disagreement: Option<String>,
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// The tolerance of each of `expected`'s components for the case `args`.
    pub fn bounds(&self, args: &A, expected: &R) -> Vec<f32> {
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, &components(expected), &mut bounds);
        bounds
    }

    /// Compares the shader's result `got` for `args` with the mirror's, within the tolerance: the
    /// largest error as a fraction of its tolerance, or what differs.
    pub fn compare(&self, args: &A, got: &R) -> Result<f32, String> {
        let verdict = self.judge_result(args, got, &self.mirror(args.clone()));
        match verdict.disagreement {
            None => Ok(verdict.max_ratio),
            Some(reason) => Err(reason),
        }
    }

    /// Judges the shader's result `got` for `args` against the result `expected` of it (the
    /// mirror's, or a relation's), within the tolerance.
    pub(super) fn judge_result(&self, args: &A, got: &R, expected: &R) -> Verdict {
        let (expected, bounds) = self.expected_and_bounds(args, expected.clone());
        self.judge_case(args, &components(got), &expected, &bounds)
    }

    /// Judges the device's components `got` for `args` against the mirror's `expected` within
    /// `bounds`. Vulkan lets a device flush subnormal floats to zero, in the inputs and results of
    /// any operation, unless the shader asks to preserve them (`DenormPreserve`), and the kernels
    /// do not ask. A case that disagrees is judged again against what such a device may compute:
    /// the mirror of its inputs flushed ([`flush_subnormals`], where it has subnormal inputs) and
    /// the mirror run with the processor flushing every subnormal operand and result
    /// ([`with_subnormals_flushed`]). Each component must then be within its bound of one of these
    /// results or of `expected` (a device may flush in one operation and not in another, so
    /// components may follow different ones; a copied input, for one, is never flushed). The
    /// verdict of the second judgement where it accepts the case, else of the first. (A relation's
    /// expected result comes from the same device as the result judged, flushing or not: it is
    /// judged once.)
    pub(super) fn judge_case(&self, args: &A, got: &[f32], expected: &[f32], bounds: &[f32]) -> Verdict {
        let first = judge(args.is_finite(), got, expected, bounds);
        let Oracle::Mirror(mirror) = &self.oracle else {
            return first;
        };
        if first.disagreement.is_none() {
            return first;
        }
        let mut allowed = vec![(expected.to_vec(), bounds.to_vec())];
        if let Some(flushed) = flush_subnormals(args) {
            allowed.push(self.expected_and_bounds(&flushed, mirror(flushed.clone())));
        }
        if let Some(result) = with_subnormals_flushed(|| mirror(args.clone())) {
            allowed.push(self.expected_and_bounds(args, result));
        }
        match judge_each_component(args.is_finite(), got, &allowed) {
            Some((max_error, max_ratio)) => Verdict {
                max_error,
                max_ratio,
                disagreement: None,
            },
            None => first,
        }
    }

    /// The components of the mirror's `result` for `args` and their bounds.
    fn expected_and_bounds(&self, args: &A, result: R) -> (Vec<f32>, Vec<f32>) {
        let expected = components(&result);
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, &expected, &mut bounds);
        (expected, bounds)
    }
}

/// The components of `value`, in [`Value::components`] order.
fn components<R: Value>(value: &R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

/// Compares one case's components: the largest error and the largest share of its bound (a
/// non-finite output counts as an infinite error), and the first component that differs beyond
/// its bound, or a non-finite output for finite inputs.
fn judge(finite_input: bool, got: &[f32], expected: &[f32], bounds: &[f32]) -> Verdict {
    let finite = |values: &[f32]| values.iter().all(|x| x.is_finite());
    let mut verdict = Verdict {
        max_error: 0.0,
        max_ratio: 0.0,
        disagreement: (finite_input && !(finite(got) && finite(expected)))
            .then(|| String::from("non-finite output for finite input")),
    };
    for (index, ((&got, &expected), &bound)) in got.iter().zip(expected).zip(bounds).enumerate() {
        let (error, ratio) = match within_bound(finite_input, got, expected, bound) {
            Some(errors) => errors,
            None => {
                let error = (got - expected).abs();
                verdict.disagreement.get_or_insert_with(|| {
                    format!("component {index} differs by {error:e} (tolerance {bound:e})")
                });
                let error = if error.is_nan() { f32::INFINITY } else { error };
                (error, if bound > 0.0 { error / bound } else { f32::INFINITY })
            }
        };
        verdict.max_error = verdict.max_error.max(error);
        verdict.max_ratio = verdict.max_ratio.max(ratio);
    }
    verdict
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
/// inputs are). The largest error and share of the bound, taking each component's closest
/// result; `None` where a component matches none.
fn judge_each_component(
    finite_input: bool,
    got: &[f32],
    allowed: &[(Vec<f32>, Vec<f32>)],
) -> Option<(f32, f32)> {
    if finite_input && !got.iter().all(|x| x.is_finite()) {
        return None;
    }
    let (mut max_error, mut max_ratio) = (0.0f32, 0.0f32);
    for (index, &got) in got.iter().enumerate() {
        let matches = allowed
            .iter()
            .filter_map(|(expected, bounds)| within_bound(finite_input, got, expected[index], bounds[index]));
        let (error, ratio) = matches.min_by(|a, b| a.1.total_cmp(&b.1))?;
        max_error = max_error.max(error);
        max_ratio = max_ratio.max(ratio);
    }
    Some((max_error, max_ratio))
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

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
        // 2^-140, the subnormal 2^9 * 2^-149, from its bits: `powi(-140)` computed at run time
        // (unoptimised builds) inverts 2^140, which overflows, and gives 0.
        let tiny = f32::from_bits(1 << 9);
        assert_eq!(f64::from(tiny), 2f64.powi(-140));
        let scale = move |(x,): (f32,)| glam::Vec2::new(x, x * tiny);
        let check = FunctionCheck::new("copy_and_scale", || (any::<f32>(),), scale);
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
