//! Tolerances: how far a shader's result may be from the mirror's, and error bounds derived from
//! Vulkan's precision rules (Vulkan spec, "Precision and Operation of SPIR-V Instructions") plus
//! the mirror's own rounding, to build them from.
//!
//! - `+ - *` are correctly rounded, but an implementation may fuse `a * b + c`, so a short sum of
//!   products may differ from the mirror by a few units in the last place of its largest term.
//! - Division: 2.5 ULP. `inversesqrt`: 2 ULP; `sqrt` and `length` inherit `1 / inversesqrt`.
//! - `log2`: 3 ULP outside `[0.5, 2]`, absolute `2^-21` inside.
//! - `sin`, `cos`: absolute `2^-11` in `[-pi, pi]`; `tan` inherits `sin / cos`.
//! - `atan`: inherits `atan2`, 4096 ULP.
//! - Denormals may be flushed to zero, so every bound has an absolute floor of the smallest normal.
//!
//! For functions that chain many operations, [`crate::interval`] derives a bound per case
//! mechanically.

use std::fmt;
use std::sync::Arc;

/// A bound per case and component: `bound(arguments, component index, expected value)`.
pub type ComponentBound<A> = dyn Fn(&A, usize, f32) -> f32 + Send + Sync;

/// The bounds of every component of a case: `bounds(arguments, expected components)`.
pub type CaseBounds<A> = dyn Fn(&A, &[f32]) -> Vec<f32> + Send + Sync;

/// The largest `|shader - mirror|` a check accepts, per output component. The crate's README has
/// a guide to which tolerance suits which function.
///
/// ```
/// use shader_proptest::tolerance::ULP;
/// use shader_proptest::Tolerance;
///
/// // A dot product of three terms, 1.5 here: three roundings, and one ULP of the mirror's own.
/// let dot: Tolerance<(glam::Vec3,)> = Tolerance::ulps(4);
/// let mut bounds = Vec::new();
/// dot.bounds(&(glam::Vec3::ONE,), &[1.5], &mut bounds);
/// assert_eq!(bounds, [4.0 * ULP * 1.5 + f32::MIN_POSITIVE]);
///
/// // A bound that depends on the case: half a ULP of the input, for a copy of it.
/// let copy = Tolerance::per_component(|&(x,): &(f32,), _, _| 0.5 * ULP * x.abs());
/// bounds.clear();
/// copy.bounds(&(2.0,), &[2.0], &mut bounds);
/// assert_eq!(bounds, [ULP]);
/// ```
pub enum Tolerance<A> {
    /// Bit-for-bit equal.
    Exact,
    /// `n` ULP of each expected component, plus the smallest normal number (a flushed denormal).
    Ulps(f32),
    /// The same absolute bound for every component.
    Absolute(f32),
    /// A fraction of each expected component's magnitude, plus the smallest normal number.
    Relative(f32),
    /// A bound per case and component: `bound(arguments, component index, expected value)`.
    PerComponent(Arc<ComponentBound<A>>),
    /// The bounds of every component of a case at once, from the arguments and the expected
    /// components: for bounds that one computation gives for all components (an interval
    /// enclosure, [`crate::interval`]).
    PerCase(Arc<CaseBounds<A>>),
}

impl<A> Tolerance<A> {
    /// [`Tolerance::Ulps`] of `n` units in the last place: `Tolerance::ulps(4)`.
    pub fn ulps(n: u32) -> Tolerance<A> {
        Tolerance::Ulps(n as f32)
    }

    /// [`Tolerance::PerComponent`] from a closure.
    pub fn per_component(bound: impl Fn(&A, usize, f32) -> f32 + Send + Sync + 'static) -> Tolerance<A> {
        Tolerance::PerComponent(Arc::new(bound))
    }

    /// [`Tolerance::PerCase`] from a closure; it must return one bound per expected component.
    pub fn per_case(bounds: impl Fn(&A, &[f32]) -> Vec<f32> + Send + Sync + 'static) -> Tolerance<A> {
        Tolerance::PerCase(Arc::new(bounds))
    }

    /// Appends the bound of each of `expected`'s components for the case `args`.
    ///
    /// # Panics
    /// If a [`Tolerance::PerCase`] closure returns the wrong number of bounds.
    pub fn bounds(&self, args: &A, expected: &[f32], out: &mut Vec<f32>) {
        match self {
            Tolerance::Exact => out.extend(expected.iter().map(|_| 0.0)),
            Tolerance::Ulps(n) => out.extend(expected.iter().map(|&e| ulps(*n, e))),
            Tolerance::Absolute(bound) => out.extend(expected.iter().map(|_| *bound)),
            Tolerance::Relative(fraction) => {
                out.extend(expected.iter().map(|&e| fraction * e.abs() + f32::MIN_POSITIVE))
            }
            Tolerance::PerComponent(bound) => out.extend(
                expected
                    .iter()
                    .enumerate()
                    .map(|(index, &e)| bound(args, index, e)),
            ),
            Tolerance::PerCase(bounds) => {
                let case = bounds(args, expected);
                assert_eq!(
                    case.len(),
                    expected.len(),
                    "a per-case tolerance returned {} bounds for {} components",
                    case.len(),
                    expected.len()
                );
                out.extend(case);
            }
        }
    }
}

impl<A> Clone for Tolerance<A> {
    fn clone(&self) -> Self {
        match self {
            Tolerance::Exact => Tolerance::Exact,
            Tolerance::Ulps(n) => Tolerance::Ulps(*n),
            Tolerance::Absolute(bound) => Tolerance::Absolute(*bound),
            Tolerance::Relative(fraction) => Tolerance::Relative(*fraction),
            Tolerance::PerComponent(bound) => Tolerance::PerComponent(Arc::clone(bound)),
            Tolerance::PerCase(bounds) => Tolerance::PerCase(Arc::clone(bounds)),
        }
    }
}

impl<A> fmt::Debug for Tolerance<A> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tolerance::Exact => write!(f, "exact"),
            Tolerance::Ulps(n) => write!(f, "{n} ULP"),
            Tolerance::Absolute(bound) => write!(f, "absolute {bound:e}"),
            Tolerance::Relative(fraction) => write!(f, "relative {fraction:e}"),
            Tolerance::PerComponent(_) => write!(f, "per component"),
            Tolerance::PerCase(_) => write!(f, "per case"),
        }
    }
}

/// One unit in the last place at 1.0 (2^-23); `n` of them times a magnitude bounds `n` roundings.
pub const ULP: f32 = f32::EPSILON;
/// Absolute error of `sin` and `cos` (2^-11).
pub const SIN_COS_ERROR: f32 = 1.0 / 2048.0;
/// Relative error of `atan` (4096 ULP).
pub const ATAN_ULPS: f32 = 4096.0;

/// `n` roundings of a value of size `scale`, with the denormal floor.
pub fn ulps(n: f32, scale: f32) -> f32 {
    n * ULP * scale.abs() + f32::MIN_POSITIVE
}

/// Error of `log2` returning `result` on the device (3 ULP, or 2^-21 near 0), plus the mirror's ULP.
pub fn log2_error(result: f32) -> f32 {
    (4.0 * ULP * result.abs()).max(1.0 / 2_097_152.0 + ULP * result.abs())
}

/// Error of `atan(x)` when `x` itself is off by `x_error`: the propagated error `x_error / (1 + x^2)`
/// plus 4096 ULP of the result and the mirror's ULP.
pub fn atan_error(x: f32, x_error: f32) -> f32 {
    let x = f64::from(x);
    (f64::from(x_error) / (1.0 + x * x)) as f32 + ulps(ATAN_ULPS + 1.0, x.atan() as f32)
}

/// Error of `tan(angle)` computed as `sin / cos` with absolute errors of 2^-11 each:
/// `(2^-11 / |cos|) * (1 + |tan|)`, plus the division's 2.5 ULP and the mirror's ULP.
pub fn tan_error(angle: f32) -> f32 {
    let (sin, cos) = f64::from(angle).sin_cos();
    let tan = (sin / cos).abs();
    (f64::from(SIN_COS_ERROR) / cos.abs() * (1.0 + tan)) as f32 + ulps(3.5, tan as f32)
}

/// Rounding error of a dot product `sum(a_i * b_i)`: 3 roundings of the sum of term magnitudes.
pub fn dot_error(a: glam::Vec3, b: glam::Vec3) -> f32 {
    ulps(3.0, (a * b).abs().element_sum())
}

/// Cases of a batch with a vacuous bound (one that could not have failed): in any component, and
/// per component.
#[derive(Default)]
pub struct Vacuous {
    /// Cases with a vacuous bound in any component.
    pub cases: usize,
    /// Cases with a vacuous bound, per component.
    pub by_component: Vec<usize>,
}

/// The cases of a batch (`cases` of them, as many components each) with a vacuous bound: one at
/// least as wide as the spread of its component's (finite) expected values over the batch, where
/// that spread is not zero.
pub fn count_vacuous(expected: &[f32], bounds: &[f32], cases: usize) -> Vacuous {
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
