//! Interval pieces that the enclosures of several sections share: a `RayDiff`'s and a derivative
//! pair's components, the barycentric quotient with its clamps, the determinant it divides by, and
//! whether a determinant or a direction is known well enough for its enclosure to say something
//! ([`crate::conditioning`]).

use crate::conditioning::{well_conditioned, WELL_CONDITIONED};
use glam::Vec3;
use ray_footprint::ray_diff::{DIFF_MAX_VALUE, DIFF_MIN_MAGNITUDE};
use shader_proptest::interval::{interval3, Interval, Interval2, Interval3};

/// A `RayDiff`'s 16 components, pads exactly 0.
pub(crate) fn ray_diff(o_dx: Interval3, o_dy: Interval3, d_dx: Interval3, d_dy: Interval3) -> Vec<Interval> {
    [o_dx, o_dy, d_dx, d_dy]
        .iter()
        .flat_map(|v| v.components().into_iter().chain([Interval::c(0.0)]))
        .collect()
}

pub(crate) fn derivatives2(dx: Interval2, dy: Interval2) -> Vec<Interval> {
    [dx.components(), dy.components()].concat()
}

pub(crate) fn derivatives3(dx: Interval3, dy: Interval3) -> Vec<Interval> {
    [dx.components(), dy.components()].concat()
}

/// `x / k` clamped to `DIFF_MAX_VALUE`, `k` clamped away from 0 to `DIFF_MIN_MAGNITUDE`.
pub(crate) fn barycentric_quotient(numerator: Interval, k: Interval) -> Interval {
    let max = f64::from(DIFF_MAX_VALUE);
    numerator
        .div_away(k, f64::from(DIFF_MIN_MAGNITUDE))
        .clamp_c(-max, max)
}

/// The determinant `k = dot(cross(e1, e2), direction)` of a ray against a triangle's plane (RTG
/// Eq. 12-20): the divisor of every barycentric quotient.
pub(crate) fn determinant(direction: Interval3, p0: Interval3, p1: Interval3, p2: Interval3) -> Interval {
    (p1 - p0).cross(p2 - p0).dot(direction)
}

/// Why a ray against a triangle is left out of a check ([`determinant_well_conditioned`]).
pub(crate) const PARALLEL_WITHIN_ROUNDING: &str =
    "the ray is parallel to the triangle's plane within rounding, or the \
     triangle a sliver (the determinant k is not known to 2^-10): the clamped quotients may take \
     either +-DIFF_MAX_VALUE";

/// Whether the determinant of `direction` against the triangle `p0 p1 p2` is well-conditioned
/// ([`WELL_CONDITIONED`]).
pub(crate) fn determinant_well_conditioned(direction: Vec3, p0: Vec3, p1: Vec3, p2: Vec3) -> bool {
    well_conditioned(determinant(
        interval3(direction),
        interval3(p0),
        interval3(p1),
        interval3(p2),
    ))
}

/// Whether a direction is known to [`WELL_CONDITIONED`]: its widest component's enclosure is at
/// most that fraction of its largest component (an object-space neighbour direction is not, when
/// the origin is so far from the object that `T(O + d) - T(O)` cancels most of its bits).
pub(crate) fn direction_well_conditioned(direction: Interval3) -> bool {
    let width = direction.0.iter().map(|c| c.hi - c.lo).fold(0.0, f64::max);
    let magnitude = direction.0.iter().map(|c| c.magnitude()).fold(0.0, f64::max);
    width <= WELL_CONDITIONED * magnitude
}
