//! References of the planar and triplanar mapping section: the mappings evaluated at a point and
//! at the point moved by its differentials, and the blend weights as a softmax of logarithms.

use super::super::enclosure;
use super::{components, widths};
use crate::exact::{log_uniform, unit};
use crate::reference::{Kind, Reference, U};
use glam::{DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{
    Derivatives2, Derivatives3, TriplanarGradients, DIFF_MAX_SHARPNESS, DIFF_MIN_MAGNITUDE,
};

/// A point within 10 of the origin and its position differentials, `10^[-4, 0)` long.
fn point_and_differentials() -> BoxedStrategy<(DVec3, Derivatives3)> {
    let change = || (unit(), log_uniform(-4.0, 0.0)).prop_map(|(v, l)| (v * l).as_vec3());
    (unit(), 0.0f64..10.0, change(), change())
        .prop_map(|(p, distance, dx, dy)| (p * distance, Derivatives3::new(dx, dy)))
        .boxed()
}

/// The change of `map` from the point `p` to `p` moved by each differential, in f64, listed.
fn moved<const N: usize>(p: DVec3, d: Derivatives3, map: impl Fn(DVec3) -> [f64; N]) -> Vec<f64> {
    let change = |step: Vec3| {
        let (from, to) = (map(p), map(p + step.as_dvec3()));
        std::array::from_fn::<f64, N, _>(|i| to[i] - from[i])
    };
    [change(d.dx), change(d.dy)].concat()
}

/// The f64 cancellation of a difference of two mappings of points within `p` of the origin, at a
/// scale `scale`: 4 f64 ULP of the larger.
fn cancellation(p: DVec3, d: Derivatives3, scale: f64) -> f64 {
    4.0 * f64::EPSILON * (p.length() + d.dx.length().max(d.dy.length()) as f64) * scale
}

/// `rf_planar_mapping_gradients`.
pub(in crate::ray_diff) fn planar_mapping_gradients() -> Reference<(Derivatives3, Vec2), Derivatives2> {
    Reference::new(
        Kind::ClosedForm,
        "the planar mapping uv = p.xz * scale evaluated at a point and at the point moved by each position differential, in f64: their differences (Quilez)",
        || (point_and_differentials(), -10.0f32..10.0, -10.0f32..10.0).boxed(),
        |&((p, d), sx, sy), planar_mapping_gradients| {
            let scale = Vec2::new(sx, sy);
            let got = planar_mapping_gradients((d, scale));
            let s = scale.as_dvec2();
            let expected = moved(p, d, |q| [q.x * s.x, q.z * s.y]);
            // One product each.
            let slack = cancellation(p, d, s.length());
            Some(components(got, &expected, |i| U * expected[i].abs() + slack))
        },
    )
}

/// `rf_triplanar_weights`.
pub(in crate::ray_diff) fn triplanar_weights() -> Reference<(Vec3, f32), Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "a softmax of logarithms in f64: w_i = exp(k ln a_i - ln sum_j exp(k ln a_j)) with a = |n| / max|n_j| clamped to >= DIFF_MIN_MAGNITUDE and k clamped to [0, DIFF_MAX_SHARPNESS] (Quilez)",
        || {
            let length = prop_oneof![Just(1.0f64), log_uniform(-3.0, 3.0)];
            (unit(), length, prop_oneof![4 => 0.0f32..16.0, 1 => 16.0f32..DIFF_MAX_SHARPNESS, 1 => Just(0.0f32)]).boxed()
        },
        |&(n, length, sharpness), triplanar_weights| {
            let normal = (n * length).as_vec3();
            let got = triplanar_weights((normal, sharpness));
            let a = normal.as_dvec3().abs();
            let largest = a.max_element();
            let logs = (a / largest).max(DVec3::splat(f64::from(DIFF_MIN_MAGNITUDE))).to_array().map(f64::ln);
            let k = f64::from(sharpness.clamp(0.0, DIFF_MAX_SHARPNESS));
            let top = logs.iter().map(|l| k * l).fold(f64::MIN, f64::max);
            let total = top + logs.iter().map(|l| (k * l - top).exp()).sum::<f64>().ln();
            let expected = logs.map(|l| (k * l - total).exp());
            let bounds = widths(&enclosure::triplanar_weights(normal, sharpness));
            Some(components(got, &expected, |i| bounds[i] + 1.0e-14))
        },
    )
}

/// `rf_triplanar_gradients`.
pub(in crate::ray_diff) fn triplanar_gradients() -> Reference<(Derivatives3, f32), TriplanarGradients> {
    Reference::new(
        Kind::ClosedForm,
        "the three projections p.yz, p.zx, p.xy times the scale evaluated at a point and at the point moved by each position differential, in f64: their differences (Quilez)",
        || (point_and_differentials(), -10.0f32..10.0).boxed(),
        |&((p, d), scale), triplanar_gradients| {
            let got = triplanar_gradients((d, scale));
            let s = f64::from(scale);
            let projection = |f: fn(DVec3) -> DVec2| moved(p, d, move |q| (f(q) * s).to_array());
            let expected = [
                projection(|q| DVec2::new(q.y, q.z)),
                projection(|q| DVec2::new(q.z, q.x)),
                projection(|q| DVec2::new(q.x, q.y)),
            ]
            .concat();
            let slack = cancellation(p, d, s.abs());
            Some(components(got, &expected, |i| U * expected[i].abs() + slack))
        },
    )
}
