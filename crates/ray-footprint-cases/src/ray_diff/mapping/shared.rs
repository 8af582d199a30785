//! What the references of the planar and triplanar mappings share: a point with its position
//! differentials, the change of a mapping from the point to its moved neighbours, and the f64
//! cancellation of that difference.

use crate::exact::{log_uniform, unit};
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::Derivatives3;

/// A point within 10 of the origin and its position differentials, `10^[-4, 0)` long.
pub(crate) fn point_and_differentials() -> BoxedStrategy<(DVec3, Derivatives3)> {
    let change = || (unit(), log_uniform(-4.0, 0.0)).prop_map(|(v, l)| (v * l).as_vec3());
    (unit(), 0.0f64..10.0, change(), change())
        .prop_map(|(p, distance, dx, dy)| (p * distance, Derivatives3::new(dx, dy)))
        .boxed()
}

/// The change of `map` from the point `p` to `p` moved by each differential, in f64, listed.
pub(crate) fn moved<const N: usize>(p: DVec3, d: Derivatives3, map: impl Fn(DVec3) -> [f64; N]) -> Vec<f64> {
    let change = |step: Vec3| {
        let (from, to) = (map(p), map(p + step.as_dvec3()));
        std::array::from_fn::<f64, N, _>(|i| to[i] - from[i])
    };
    [change(d.dx), change(d.dy)].concat()
}

/// The f64 cancellation of a difference of two mappings of points within `p` of the origin, at a
/// scale `scale`: 4 f64 ULP of the larger.
pub(crate) fn cancellation(p: DVec3, d: Derivatives3, scale: f64) -> f64 {
    4.0 * f64::EPSILON * (p.length() + d.dx.length().max(d.dy.length()) as f64) * scale
}
