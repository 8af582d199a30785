//! The family of rays a differential moves, re-intersected exactly: what the references of the
//! transfer and the derivatives sections share (the differentials they draw, one axis of them, and
//! the step of their central differences).

use crate::exact::{log_uniform, unit};
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::RayDiff;

/// A vector of random direction and a length `10^[low, high)`.
pub(crate) fn vector(low: f64, high: f64) -> BoxedStrategy<DVec3> {
    (unit(), log_uniform(low, high))
        .prop_map(|(v, length)| v * length)
        .boxed()
}

/// A differential: origin changes `10^[-4, 0)` long, direction changes `10^[-4, -1)`.
pub(crate) fn differential() -> BoxedStrategy<RayDiff> {
    (
        vector(-4.0, 0.0),
        vector(-4.0, 0.0),
        vector(-4.0, -1.0),
        vector(-4.0, -1.0),
    )
        .prop_map(|(a, b, c, d)| RayDiff::new(a.as_vec3(), b.as_vec3(), c.as_vec3(), d.as_vec3()))
        .boxed()
}

/// The origin and direction changes of one axis (0: x, 1: y) of a differential.
pub(crate) fn axis(diff: &RayDiff, axis: usize) -> (DVec3, DVec3) {
    let (o, d) = (diff.d_origin(), diff.d_direction());
    if axis == 0 {
        (o.dx.as_dvec3(), d.dx.as_dvec3())
    } else {
        (o.dy.as_dvec3(), d.dy.as_dvec3())
    }
}

/// A step for the central differences of a family of rays moved by `h` times a differential: the
/// hit moves by `h (|dO| + t |dD|) / cos`, kept at `1e-4` of `scale`.
pub(crate) fn family_step(diff: &RayDiff, t: f64, cosine: f64, scale: f64) -> f64 {
    let moves = (0..2)
        .map(|a| {
            let (o, d) = axis(diff, a);
            o.length() + t * d.length()
        })
        .fold(0.0, f64::max);
    1.0e-4 * scale * cosine / moves.max(1.0e-300)
}
