//! What the functions of cones and differentials together share: the steps of their enclosures
//! (a scaled length, Duff et al.'s tangent, the hull of two vectors); and for their references,
//! the ellipse a cone cuts from a surface and its error, the directions they meet a surface at,
//! the cones and distances they draw, a cone's canonical form and its relative error.

use crate::exact::{log_uniform, plane_hit, signed_log, towards, unit};
use glam::{DMat3, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{DIFF_MIN_MAGNITUDE, DIFF_MIN_SINE};
use shader_proptest::interval::{Interval, Interval3, IntervalVec};

pub(crate) fn scaled_length(v: Interval3) -> Interval {
    let a = v.abs();
    let m = a.0[0]
        .max(a.0[1])
        .max(a.0[2].max_c(f64::from(DIFF_MIN_MAGNITUDE)));
    let unit = v / m;
    m * unit.dot(unit).sqrt()
}

/// Componentwise hull of two vectors.
pub(crate) fn hull3(a: Interval3, b: Interval3) -> Interval3 {
    a.zip(b, |x, y| x.hull(y))
}

pub(crate) fn orthonormal_tangent(n: Interval3) -> Interval3 {
    let branch = |sign: f64| {
        let [x, y, z] = n.0;
        let s = Interval::c(sign);
        let a = Interval::c(-1.0) / (s + z);
        IntervalVec([
            Interval::c(1.0) + s * x * x * a,
            s * x * y * a,
            Interval::c(-sign) * x,
        ])
    };
    let z = n.0[2];
    if z.lo >= 0.0 {
        branch(1.0)
    } else if z.hi < 0.0 {
        branch(-1.0)
    } else {
        hull3(branch(1.0), branch(-1.0))
    }
}

/// Relative f32 error of a value computed through a few dozen roundings of well-conditioned
/// operations (about 40 x 6e-8, rounded up).
pub(crate) const F32_CHAIN: f64 = 1.0e-5;

/// The symmetric matrix `sum_i a_i a_i^T` of an ellipse spanned by conjugate axes `a_i`: the same
/// for every conjugate pair of one ellipse, so it compares ellipses whatever their axes.
pub(crate) fn ellipse(axes: &[DVec3]) -> DMat3 {
    axes.iter()
        .map(|a| DMat3::from_cols(*a * a.x, *a * a.y, *a * a.z))
        .fold(DMat3::ZERO, |m, a| m + a)
}

/// The Frobenius norm.
pub(crate) fn frobenius(m: DMat3) -> f64 {
    m.to_cols_array().iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// How far [`ellipse`] of `axes` can move when each axis moves by up to `errors` (its length):
/// `sum 2 |a| e + e^2`.
pub(crate) fn ellipse_error(axes: &[DVec3], errors: &[f64]) -> f64 {
    axes.iter()
        .zip(errors)
        .map(|(a, e)| 2.0 * a.length() * e + e * e)
        .sum()
}

/// Two conjugate full diameters of the ellipse in which the plane through the origin with unit
/// normal `n` cuts the cylinder of diameter `width` around the unit direction `d`: the images on
/// the plane, along `d`, of two perpendicular diameters of the cylinder's cross-section.
pub(crate) fn cut_cylinder(width: f64, n: DVec3, d: DVec3) -> [DVec3; 2] {
    let a = d.any_orthonormal_vector();
    let b = d.cross(a);
    [a, b].map(|radius| 2.0 * plane_hit(radius * (0.5 * width), d, DVec3::ZERO, n))
}

/// A unit direction meeting the unit normal `n` at `|cos|` from 1e-3 to 1 (exactly 1, and within
/// 1e-10 and 1e-7 of it, around `DIFF_MIN_SINE`), from either side.
pub(crate) fn incidence(n: DVec3) -> BoxedStrategy<DVec3> {
    let cosine = prop_oneof![6 => log_uniform(-3.0, 0.0), 1 => Just(1.0f64), 1 => Just(1.0 - 1.0e-10), 1 => Just(1.0 - 1.0e-7)];
    (cosine, 0.0f64..6.3, any::<bool>())
        .prop_map(move |(cosine, angle, behind)| towards(n, cosine, angle) * if behind { -1.0 } else { 1.0 })
        .boxed()
}

/// How far an ellipse's matrix may lie from the exact one besides the rounding: the inputs'
/// distance from unit length (the major axis scales with it, `3 eta |M|`), and, within twice
/// `DIFF_MIN_SINE` of normal incidence, the fixed tangent in place of the projected direction
/// (`1.5 w^2 (1 / cos^2 - 1)`, below 1e-7 w^2).
pub(crate) fn ellipse_assumptions(n: Vec3, d: Vec3, width: f64, exact: DMat3) -> f64 {
    let (n64, d64) = (n.as_dvec3(), d.as_dvec3());
    let eta = (n64.length() - 1.0).abs() + (d64.length() - 1.0).abs();
    let (n64, d64) = (n64.normalize(), d64.normalize());
    let cosine = n64.dot(d64).abs();
    let near_normal = if n64.cross(d64).length() < 2.0 * f64::from(DIFF_MIN_SINE) {
        1.5 * width * width * (1.0 / (cosine * cosine) - 1.0)
    } else {
        0.0
    };
    3.0 * eta * frobenius(exact) + near_normal
}

/// A cone `(width, spread)`, a unit direction and a distance.
pub(crate) fn cone_and_distance() -> BoxedStrategy<(f64, f64, DVec3, f64)> {
    let spread = prop_oneof![1 => Just(0.0f64), 4 => signed_log(-6.0, 0.0)];
    (signed_log(-6.0, 3.0), spread, unit(), log_uniform(-3.0, 3.0)).boxed()
}

/// `(w, s)` and `(-w, -s)` are the same cone; the form with `w >= 0` (and `s >= 0` when `w = 0`).
pub(crate) fn canonical(width: f64, spread: f64) -> DVec2 {
    if width < 0.0 || (width == 0.0 && spread < 0.0) {
        DVec2::new(-width, -spread)
    } else {
        DVec2::new(width, spread)
    }
}

/// `|got - expected|` relative to the larger of the cone's two magnitudes.
pub(crate) fn cone_error(got: Vec2, expected: DVec2) -> f64 {
    (got.as_dvec2() - expected).abs().max_element() / expected.abs().max_element()
}
