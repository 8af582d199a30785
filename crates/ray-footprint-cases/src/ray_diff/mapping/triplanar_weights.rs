//! The proof of [`triplanar_weights`](ray_footprint::ray_diff::triplanar_weights): its record, its
//! enclosure and its reference.

use crate::degenerate::value;
use crate::exact::{log_uniform, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::reference::{components, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::unit_vec3;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, DIFF_MAX_SHARPNESS, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::Interval;
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// The record of `rf_triplanar_weights`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayDiff,
        "triplanar_weights",
        |(normal, sharpness)| rd::triplanar_weights(normal, sharpness),
        || {
            let normal = one_of![8 => unit_vec3(), 1 => Just(Vec3::ZERO)];
            (normal, one_of![4 => uniform(0.0, 16.0), 1 => uniform(-2.0, 100.0)]).boxed()
        },
    )
    .enclosure(|&(normal, sharpness)| enclosure(normal, sharpness))
    .found(
        "inf / inf for normals longer than about 2 at high sharpness (now divided by the largest component first); found by the special-value suite",
    )
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the normal flipped: the same",
        |&(normal, sharpness): &(Vec3, f32)| (-normal, sharpness),
        |weights: Vec3| weights,
    ))
    .symmetry(Symmetry::exchange(
        "the world's axes turned (x, y, z -> y, z, x): the weights turned",
        |&(normal, sharpness): &(Vec3, f32)| (normal.yzx(), sharpness),
        |weights: Vec3| weights.zxy(),
    ))
    .fuzz(|d| (d.unit(), d.scalar()))
    .range(0.0, 1.0, "weight")
    .degenerate(vec![
        value(
            "zero normal, sharpness 1",
            "1/3 each",
            (Vec3::ZERO, 1.0),
            vec![DIFF_MIN_MAGNITUDE / (3.0 * DIFF_MIN_MAGNITUDE); 3],
        ),
        value(
            "zero normal, sharpness 4",
            "0 each (DIFF_MIN_MAGNITUDE^4 underflows)",
            (Vec3::ZERO, 4.0),
            vec![0.0; 3],
        ),
        value(
            "sharpness 0",
            "1/3 each",
            (Vec3::new(0.6, 0.0, 0.8), 0.0),
            vec![1.0 / 3.0; 3],
        ),
    ])
}

/// `rf_triplanar_weights` in interval arithmetic, in the same order of operations.
fn enclosure(normal: Vec3, sharpness: f32) -> Vec<Interval> {
    let k = sharpness.clamp(0.0, DIFF_MAX_SHARPNESS);
    let size = normal.abs();
    let largest = Interval::exact(size.x.max(size.y).max(size.z.max(DIFF_MIN_MAGNITUDE)));
    let m: [Interval; 3] = std::array::from_fn(|i| {
        (Interval::exact(size[i]) / largest)
            .max_c(f64::from(DIFF_MIN_MAGNITUDE))
            .pow(k)
    });
    let sum = (m[0] + m[1] + m[2]).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    m.iter().map(|&x| x / sum).collect()
}

/// The reference of `rf_triplanar_weights`.
fn reference() -> Reference<(Vec3, f32), Vec3> {
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
            let bounds = widths(&enclosure(normal, sharpness));
            Some(components(got, &expected, |i| bounds[i] + 1.0e-14))
        },
    )
}
