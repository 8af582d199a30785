//! Interval arithmetic with Vulkan's rounding allowances, for per-case tolerances derived
//! mechanically.
//!
//! A function that chains dozens of operations is hard to bound by hand. Instead, a check can
//! re-evaluate it in interval arithmetic ([`Interval`]) on the same f32 inputs. After every
//! operation the interval is widened by the largest rounding error that Vulkan allows the device
//! *or* that the Rust mirror makes for that operation (the budgets below, from "Precision and
//! Operation of SPIR-V Instructions"; see [`crate::tolerance`]). Both the device's result and the
//! mirror's result then lie in the final interval, so its width bounds their difference: that
//! width is the tolerance ([`crate::Tolerance::per_case`]).
//!
//! Budgets per operation, in ULP of the largest magnitude the result can have (the mirror's own
//! rounding is at most the device's for each of them):
//! - `+ - *`: 0.5 (correctly rounded; a fused multiply-add only removes a rounding);
//! - `/`: 2.5; `sqrt`: 4.5 (inherited from `1 / inversesqrt`: 2 + 2.5);
//! - `log2`: 3 ULP, or 2^-21 absolute for arguments in `[0.5, 2]`;
//! - `tan`: [`crate::tolerance::tan_error`]; `pow(x, y)`: inherited from `exp2(y * log2(x))`, with
//!   `exp2` within `3 + 2 |y log2 x|` ULP;
//! - `dot`, `cross` and matrix products (whose summation order is the implementation's): `2n - 1`
//!   roundings of the sum of the term magnitudes for `n` terms;
//! - every rounding may also flush a denormal: plus the smallest normal number;
//! - an exact zero (the difference of equal inputs, a product with a zero) is computed exactly;
//! - an f32 result that may exceed `f32::MAX` may overflow to an infinity of its sign, or stay
//!   finite where the device fuses it into the next operation: the interval is unbounded on that
//!   side and keeps its other bound ([`Interval::within_range`]); a sum of products whose partial
//!   sums may overflow is unbounded on both sides (a fused multiply-add overflows where separate
//!   roundings do not, and the other way round, so cancelling terms give either sign).
//!
//! For f64 arithmetic the same budgets apply with f64 units ([`F64`]), and a final conversion to f32
//! adds half an f32 ULP.
//!
//! Branches (a clamp's comparison, total internal reflection) take the hull of both outcomes when
//! the interval straddles the threshold.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// Unit of rounding of one precision: one ULP at 1.0 and the smallest normal number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Precision {
    ulp: f64,
    floor: f64,
}

/// f32 arithmetic (2^-23, 2^-126).
pub const F32: Precision = Precision {
    ulp: f32::EPSILON as f64,
    floor: f32::MIN_POSITIVE as f64,
};

/// f64 arithmetic (2^-52, 2^-1022).
pub const F64: Precision = Precision {
    ulp: f64::EPSILON,
    floor: f64::MIN_POSITIVE,
};

/// An interval `[lo, hi]` enclosing every value the device or the mirror can compute.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// The arithmetic that computes it.
    pub p: Precision,
}

/// `x * y` with `0 * inf = 0` (a zero bound times an unbounded one).
fn product(x: f64, y: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        0.0
    } else {
        x * y
    }
}

fn coarser(a: Precision, b: Precision) -> Precision {
    if a.ulp >= b.ulp {
        a
    } else {
        b
    }
}

impl Interval {
    /// An exact f32 value (an input).
    pub fn exact(x: f32) -> Interval {
        Interval::point(f64::from(x), F32)
    }

    /// An exact f64 value (an input converted to f64, or an f64 constant).
    pub fn exact64(x: f64) -> Interval {
        Interval::point(x, F64)
    }

    /// An exact constant in f32 arithmetic.
    pub fn c(x: f64) -> Interval {
        Interval::point(x, F32)
    }

    fn point(x: f64, p: Precision) -> Interval {
        Interval { lo: x, hi: x, p }
    }

    fn hull_of(values: [f64; 4], p: Precision) -> Interval {
        Interval {
            lo: values.iter().copied().fold(f64::INFINITY, f64::min),
            hi: values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            p,
        }
    }

    /// Largest magnitude in the interval.
    pub fn magnitude(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The width, as an f32 tolerance (rounded up; infinite when unbounded).
    pub fn tolerance(self) -> f32 {
        let width = self.hi - self.lo;
        if width.is_nan() {
            f32::INFINITY
        } else {
            (width * (1.0 + 1.0e-6)) as f32
        }
    }

    /// The width relative to the smallest magnitude in the interval: how well the sign and size of
    /// the value are known. 0 for a point (an exact zero included), infinite when the interval
    /// contains 0 and something else.
    pub fn relative_width(self) -> f64 {
        if self.lo == self.hi {
            0.0
        } else if self.lo <= 0.0 && self.hi >= 0.0 {
            f64::INFINITY
        } else {
            (self.hi - self.lo) / self.lo.abs().min(self.hi.abs())
        }
    }

    /// Whether 0 lies in the interval.
    pub fn contains_zero(self) -> bool {
        self.lo <= 0.0 && self.hi >= 0.0
    }

    /// Whether the interval is exactly zero: an exact zero result is computed exactly (0 is
    /// representable and no rounding or denormal flush moves it), so it is never widened.
    pub fn is_exact_zero(self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }

    /// Widens by `ulps` roundings of the largest magnitude, plus one flushed denormal; an exact
    /// zero stays exact. In f32 arithmetic, an interval reaching beyond `f32::MAX` becomes
    /// unbounded on that side ([`Interval::within_range`]).
    pub fn round(self, ulps: f64) -> Interval {
        if self.is_exact_zero() {
            return self;
        }
        let w = ulps * self.p.ulp * self.magnitude() + self.p.floor;
        Interval {
            lo: self.lo - w,
            hi: self.hi + w,
            p: self.p,
        }
        .within_range()
    }

    /// The interval, unbounded on each side where an f32 result in it may overflow: a value
    /// beyond `f32::MAX` rounds to an infinity of its sign, or stays finite where the device fuses
    /// the operation into the next one (then the exact value goes on, which the other bound still
    /// holds). Interval arithmetic carries the infinite bound on: `inf - inf` gives an interval
    /// unbounded on both sides.
    pub fn within_range(self) -> Interval {
        if self.p != F32 {
            return self;
        }
        let max = f64::from(f32::MAX);
        Interval {
            lo: if self.lo < -max {
                f64::NEG_INFINITY
            } else {
                self.lo
            },
            hi: if self.hi > max { f64::INFINITY } else { self.hi },
            p: F32,
        }
    }

    /// Smallest interval holding both.
    pub fn hull(self, other: Interval) -> Interval {
        Interval {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
            p: coarser(self.p, other.p),
        }
    }

    /// `|x|` (exact).
    pub fn abs(self) -> Interval {
        if self.lo >= 0.0 {
            self
        } else if self.hi <= 0.0 {
            -self
        } else {
            Interval {
                lo: 0.0,
                hi: self.magnitude(),
                p: self.p,
            }
        }
    }

    /// `max(x, y)` (exact).
    pub fn max(self, other: Interval) -> Interval {
        Interval {
            lo: self.lo.max(other.lo),
            hi: self.hi.max(other.hi),
            p: coarser(self.p, other.p),
        }
    }

    /// `min(x, y)` (exact).
    pub fn min(self, other: Interval) -> Interval {
        Interval {
            lo: self.lo.min(other.lo),
            hi: self.hi.min(other.hi),
            p: coarser(self.p, other.p),
        }
    }

    /// `max(x, c)` (exact).
    pub fn max_c(self, c: f64) -> Interval {
        self.max(Interval::point(c, self.p))
    }

    /// `min(x, c)` (exact).
    pub fn min_c(self, c: f64) -> Interval {
        self.min(Interval::point(c, self.p))
    }

    /// `clamp(x, lo, hi)` (exact).
    pub fn clamp_c(self, lo: f64, hi: f64) -> Interval {
        self.max_c(lo).min_c(hi)
    }

    /// `sqrt(max(x, 0))`.
    pub fn sqrt(self) -> Interval {
        Interval {
            lo: self.lo.max(0.0).sqrt(),
            hi: self.hi.max(0.0).sqrt(),
            p: self.p,
        }
        .round(4.5)
    }

    /// `log2(x)` of an interval whose lower end is positive (f32 only).
    pub fn log2(self) -> Interval {
        let (lo, hi) = (self.lo.log2(), self.hi.log2());
        let error = |x: f64| f64::from(crate::tolerance::log2_error(x as f32));
        Interval {
            lo: lo - error(lo),
            hi: hi + error(hi),
            p: self.p,
        }
    }

    /// `tan(x)` of an exact f32 angle in `[0, 1.55]`.
    pub fn tan_exact(angle: f32) -> Interval {
        let value = f64::from(angle).tan();
        let error = f64::from(crate::tolerance::tan_error(angle));
        Interval {
            lo: value - error,
            hi: value + error,
            p: F32,
        }
    }

    /// `pow(x, y)` for an exact `x > 0` and exact `y >= 0` (f32 only): see [`Interval::pow`].
    pub fn pow_exact(x: f32, y: f32) -> Interval {
        Interval::exact(x).pow(y)
    }

    /// `pow(x, y)` for `x` in a positive interval and an exact `y >= 0` (f32 only), computed as
    /// `exp2(y * log2(x))` with the errors of `log2` (absolute `e`), the product (0.5 ULP) and
    /// `exp2` (`3 + 2|z|` ULP), and the mirror's `powf` (1 ULP); increasing in `x`, so each end
    /// of the interval bounds one side.
    pub fn pow(self, y: f32) -> Interval {
        let y = f64::from(y);
        let end = |x: f64, side: f64| {
            let log = x.log2();
            let z = y * log;
            let z_error = y * f64::from(crate::tolerance::log2_error(log as f32)) + 0.5 * F32.ulp * z.abs();
            let value = x.powf(y);
            let relative = (z_error * std::f64::consts::LN_2).exp_m1() + (4.0 + 2.0 * z.abs()) * F32.ulp;
            value + side * (value * relative + F32.floor)
        };
        Interval {
            lo: end(self.lo, -1.0),
            hi: end(self.hi, 1.0),
            p: F32,
        }
    }

    /// `x / clamp_away_from_zero(den, m)`: the divisor is `den`, or `+-m` when `|den| < m`. When the
    /// divisor's interval contains 0 (`m = 0`), the quotient is unbounded.
    pub fn div_away(self, den: Interval, m: f64) -> Interval {
        let p = coarser(self.p, den.p);
        // The divisor's possible values, as one or two intervals that exclude (-m, m).
        let positive = (den.hi >= 0.0).then(|| (den.lo.max(0.0).max(m), den.hi.max(m)));
        let negative = (den.lo < 0.0).then(|| (den.lo.min(-m), den.hi.min(0.0).min(-m)));
        let mut result: Option<Interval> = None;
        for (lo, hi) in positive.into_iter().chain(negative) {
            if lo <= 0.0 && hi >= 0.0 {
                return Interval {
                    lo: f64::NEG_INFINITY,
                    hi: f64::INFINITY,
                    p,
                };
            }
            let quotient = Interval::hull_of([self.lo / lo, self.lo / hi, self.hi / lo, self.hi / hi], p);
            result = Some(result.map_or(quotient, |r| r.hull(quotient)));
        }
        result.expect("a divisor interval").round(2.5)
    }

    /// `sin` of an interval whose ends lie in `[-pi, pi]` (where Vulkan bounds it): the exact range
    /// (the ends, and +-1 where +-pi/2 lies inside), widened by the device's absolute error 2^-11
    /// and the mirror's ULP.
    pub fn sin(self) -> Interval {
        use std::f64::consts::FRAC_PI_2;
        let (mut lo, mut hi) = (self.lo.sin().min(self.hi.sin()), self.lo.sin().max(self.hi.sin()));
        if self.lo <= FRAC_PI_2 && FRAC_PI_2 <= self.hi {
            hi = 1.0;
        }
        if self.lo <= -FRAC_PI_2 && -FRAC_PI_2 <= self.hi {
            lo = -1.0;
        }
        Interval::widened_by_sin_cos_error(lo, hi)
    }

    /// `cos` of an interval whose ends lie in `[-pi, pi]`: the exact range (the ends, and 1 where 0
    /// lies inside), widened as [`Interval::sin`].
    pub fn cos(self) -> Interval {
        let (lo, mut hi) = (self.lo.cos().min(self.hi.cos()), self.lo.cos().max(self.hi.cos()));
        if self.lo <= 0.0 && 0.0 <= self.hi {
            hi = 1.0;
        }
        Interval::widened_by_sin_cos_error(lo, hi)
    }

    fn widened_by_sin_cos_error(lo: f64, hi: f64) -> Interval {
        let error = f64::from(crate::tolerance::SIN_COS_ERROR) + F32.ulp;
        Interval {
            lo: lo - error,
            hi: hi + error,
            p: F32,
        }
    }

    /// `atan2(y, x)`: every angle of the box `y x x`, so `[-pi, pi]` when the box holds the origin
    /// or crosses the negative x axis, else the corners' range; widened by the device's 4096 ULP
    /// and the mirror's one.
    pub fn atan2(y: Interval, x: Interval) -> Interval {
        use std::f64::consts::PI;
        let crosses_cut = x.lo < 0.0 && y.lo <= 0.0 && y.hi >= 0.0;
        let (lo, hi) = if crosses_cut {
            (-PI, PI)
        } else {
            let corners = [
                y.lo.atan2(x.lo),
                y.lo.atan2(x.hi),
                y.hi.atan2(x.lo),
                y.hi.atan2(x.hi),
            ];
            (
                corners.iter().copied().fold(f64::INFINITY, f64::min),
                corners.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        Interval { lo, hi, p: F32 }.round(f64::from(crate::tolerance::ATAN_ULPS) + 1.0)
    }

    /// The part of the interval at or above `floor`: the values a branch taken only there sees.
    pub fn at_least(self, floor: f64) -> Interval {
        Interval {
            lo: self.lo.max(floor),
            hi: self.hi.max(floor),
            ..self
        }
    }

    /// Converts an f64 computation's result to f32 (half an f32 ULP on each side).
    pub fn to_f32(self) -> Interval {
        Interval { p: F32, ..self }.round(0.5)
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo + o.lo,
            hi: self.hi + o.hi,
            p: coarser(self.p, o.p),
        }
        .round(0.5)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo - o.hi,
            hi: self.hi - o.lo,
            p: coarser(self.p, o.p),
        }
        .round(0.5)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
            p: self.p,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        let p = coarser(self.p, o.p);
        Interval::hull_of(
            [
                product(self.lo, o.lo),
                product(self.lo, o.hi),
                product(self.hi, o.lo),
                product(self.hi, o.hi),
            ],
            p,
        )
        .round(0.5)
    }
}

impl Div for Interval {
    type Output = Interval;
    fn div(self, o: Interval) -> Interval {
        self.div_away(o, 0.0)
    }
}

/// `sum(a_i * b_i)` in any order of operations: the exact interval sum of the exact interval
/// products, widened by `2n - 1` roundings of the sum of the term magnitudes.
pub fn sum_of_products(terms: &[(Interval, Interval)]) -> Interval {
    let p = terms.iter().fold(F64, |p, (a, b)| coarser(p, coarser(a.p, b.p)));
    let exact = |&(a, b): &(Interval, Interval)| {
        Interval::hull_of(
            [
                product(a.lo, b.lo),
                product(a.lo, b.hi),
                product(a.hi, b.lo),
                product(a.hi, b.hi),
            ],
            p,
        )
    };
    let (mut sum, mut magnitude, mut all_zero) = (Interval::point(0.0, p), 0.0, true);
    for term in terms.iter().map(exact) {
        sum = Interval {
            lo: sum.lo + term.lo,
            hi: sum.hi + term.hi,
            p,
        };
        magnitude += term.magnitude();
        all_zero &= term.is_exact_zero();
    }
    if all_zero {
        return sum;
    }
    let roundings = (2 * terms.len() - 1) as f64;
    let w = roundings * 0.5 * p.ulp * magnitude + roundings * p.floor;
    // Any partial sum, in any order, is at most the sum of the term magnitudes.
    let partial_sums = Interval {
        lo: -magnitude,
        hi: magnitude,
        p,
    };
    if partial_sums.within_range() != partial_sums {
        return partial_sums.within_range();
    }
    Interval {
        lo: sum.lo - w,
        hi: sum.hi + w,
        p,
    }
}

/// The enclosures of a branch on a condition that intervals decide: `then` where the condition is
/// `certainly` true, `otherwise` where it is not even `possibly` true, and the hull of both,
/// component by component, where the intervals leave it open (the device and the mirror may take
/// different branches there).
pub fn select(
    certainly: bool,
    possibly: bool,
    then: impl Fn() -> Vec<Interval>,
    otherwise: impl Fn() -> Vec<Interval>,
) -> Vec<Interval> {
    match (certainly, possibly) {
        (true, _) => then(),
        (false, false) => otherwise(),
        (false, true) => then()
            .into_iter()
            .zip(otherwise())
            .map(|(a, b)| a.hull(b))
            .collect(),
    }
}

/// A vector of intervals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntervalVec<const N: usize>(pub [Interval; N]);

/// Two intervals.
pub type Interval2 = IntervalVec<2>;
/// Three intervals.
pub type Interval3 = IntervalVec<3>;

impl<const N: usize> IntervalVec<N> {
    /// Component-wise map.
    pub fn map(self, f: impl Fn(Interval) -> Interval) -> IntervalVec<N> {
        IntervalVec(self.0.map(f))
    }

    /// Component-wise combination.
    pub fn zip(self, o: IntervalVec<N>, f: impl Fn(Interval, Interval) -> Interval) -> IntervalVec<N> {
        IntervalVec(std::array::from_fn(|i| f(self.0[i], o.0[i])))
    }

    /// Order-independent dot product.
    pub fn dot(self, o: IntervalVec<N>) -> Interval {
        let terms: [(Interval, Interval); N] = std::array::from_fn(|i| (self.0[i], o.0[i]));
        sum_of_products(&terms)
    }

    /// Component-wise `|x|`.
    pub fn abs(self) -> IntervalVec<N> {
        self.map(Interval::abs)
    }

    /// The components, in order.
    pub fn components(self) -> Vec<Interval> {
        self.0.to_vec()
    }
}

impl Interval3 {
    /// Order-independent cross product (each component a two-term sum of products).
    pub fn cross(self, o: Interval3) -> Interval3 {
        let [a, b] = [self.0, o.0];
        IntervalVec([
            sum_of_products(&[(a[1], b[2]), (-a[2], b[1])]),
            sum_of_products(&[(a[2], b[0]), (-a[0], b[2])]),
            sum_of_products(&[(a[0], b[1]), (-a[1], b[0])]),
        ])
    }
}

impl<const N: usize> Add for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn add(self, o: IntervalVec<N>) -> IntervalVec<N> {
        self.zip(o, |a, b| a + b)
    }
}

impl<const N: usize> Sub for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn sub(self, o: IntervalVec<N>) -> IntervalVec<N> {
        self.zip(o, |a, b| a - b)
    }
}

impl<const N: usize> Neg for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn neg(self) -> IntervalVec<N> {
        self.map(|a| -a)
    }
}

impl<const N: usize> Mul for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn mul(self, o: IntervalVec<N>) -> IntervalVec<N> {
        self.zip(o, |a, b| a * b)
    }
}

impl<const N: usize> Mul<Interval> for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn mul(self, s: Interval) -> IntervalVec<N> {
        self.map(|a| a * s)
    }
}

impl<const N: usize> Div<Interval> for IntervalVec<N> {
    type Output = IntervalVec<N>;
    fn div(self, s: Interval) -> IntervalVec<N> {
        self.map(|a| a / s)
    }
}

/// An exact f32 vector.
pub fn interval3(v: glam::Vec3) -> Interval3 {
    IntervalVec([Interval::exact(v.x), Interval::exact(v.y), Interval::exact(v.z)])
}

/// An exact f32 vector.
pub fn interval2(v: glam::Vec2) -> Interval2 {
    IntervalVec([Interval::exact(v.x), Interval::exact(v.y)])
}

/// An exact f32 vector converted to f64.
pub fn interval3_f64(v: glam::Vec3) -> Interval3 {
    IntervalVec([
        Interval::exact64(f64::from(v.x)),
        Interval::exact64(f64::from(v.y)),
        Interval::exact64(f64::from(v.z)),
    ])
}

/// The xyz part of `matrix * (v, w)` for an exact matrix whose entries enter an arithmetic of
/// precision `p`, order-independent.
pub fn mat_vec(matrix: glam::Mat4, v: Interval3, w: Interval, p: Precision) -> Interval3 {
    let columns = matrix.to_cols_array_2d();
    IntervalVec(std::array::from_fn(|row| {
        let entry = |c: usize| Interval::point(f64::from(columns[c][row]), p);
        sum_of_products(&[
            (entry(0), v.0[0]),
            (entry(1), v.0[1]),
            (entry(2), v.0[2]),
            (entry(3), w),
        ])
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A product beyond `f32::MAX` may be an infinity of its sign on the device: unbounded on
    /// that side, in f32 only; a clamp after it gives the clamp's bound.
    #[test]
    fn a_product_that_may_overflow_is_unbounded() {
        let big = Interval::exact(1.0e20);
        let product = big * big;
        assert_eq!(product.hi, f64::INFINITY);
        assert!(product.lo > 0.99e40 && product.lo < 1.0e40);
        let negative = -big * big;
        assert_eq!(negative.lo, f64::NEG_INFINITY);
        assert!(negative.hi < -0.99e40);
        let clamped = product.clamp_c(-1.0, 1.0);
        assert_eq!((clamped.lo, clamped.hi), (1.0, 1.0));
        let difference = product - product;
        assert_eq!((difference.lo, difference.hi), (f64::NEG_INFINITY, f64::INFINITY));
        let in_f64 = Interval::exact64(1.0e20) * Interval::exact64(1.0e20);
        assert!(in_f64.magnitude() < 1.01e40);
        let small = Interval::exact(1.0e18) * Interval::exact(1.0e18);
        assert!(small.hi.is_finite());
    }

    /// Two cancelling products, each beyond `f32::MAX`: the exact sum is 0, but a device that
    /// fuses one product into the sum overflows the other alone. Unbounded, and so is a quotient
    /// of it, which the clamp then bounds by the clamp's range only.
    #[test]
    fn a_cancelling_sum_of_overflowing_products_is_unbounded() {
        let huge = Interval::exact(1.0e20);
        let sum = sum_of_products(&[(huge, huge), (-huge, huge)]);
        assert_eq!((sum.lo, sum.hi), (f64::NEG_INFINITY, f64::INFINITY));
        let clamped = sum.div_away(Interval::exact(1.0), 1.0e-30).clamp_c(-1.0, 1.0);
        assert_eq!((clamped.lo, clamped.hi), (-1.0, 1.0));
        let finite = sum_of_products(&[(Interval::exact(1.0e18), huge), (-huge, Interval::exact(1.0e18))]);
        assert!(finite.hi.is_finite() && finite.contains_zero());
    }
}
