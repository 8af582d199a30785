//! The proof of [`normalized_derivative`](ray_footprint::ray_diff::normalized_derivative): its
//! record, its enclosure and its reference.

use crate::degenerate::value;
use crate::exact::{derivative, log_uniform, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::strategy::{any_direction, differential_vec3};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_normalized_derivative`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "normalized_derivative",
        |(v, dv)| rd::normalized_derivative(v, dv),
        || (any_direction(), differential_vec3()).boxed(),
    )
    .enclosure(|&(v, dv)| enclosure(interval3(v), interval3(dv)).components())
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "both vectors turned: the derivative turned",
        |&(v, dv): &(Vec3, Vec3), r| (r * v, r * dv),
        |derivative: Vec3, r| r.transpose() * derivative,
    ))
    .symmetry(Symmetry::scale(
        "the vector and its derivative scaled by s: the same",
        |&(v, dv): &(Vec3, Vec3), s| (v * s, dv * s),
        |derivative: Vec3, _| derivative,
    ))
    .symmetry(Symmetry::scale(
        "the derivative scaled by s: the result by s",
        |&(v, dv): &(Vec3, Vec3), s| (v, dv * s),
        |derivative: Vec3, s| derivative / s,
    ))
    .fuzz(|d| (d.vec3(), d.vec3()))
    .degenerate(vec![
        value(
            "zero vector",
            "dv / sqrt(DIFF_MIN_MAGNITUDE)",
            (Vec3::ZERO, z),
            vec![0.0, 0.0, 1.0 / DIFF_MIN_MAGNITUDE.sqrt()],
        ),
        value(
            "dv parallel to v (v = (2, 0, 0), dv = (1, 0, 0))",
            "0: the length changes, the direction does not",
            (2.0 * x, x),
            vec![0.0; 3],
        ),
        value(
            "v of length 2, dv perpendicular",
            "dv / |v|",
            (2.0 * z, x),
            vec![0.5, 0.0, 0.0],
        ),
    ])
}

/// `rf_normalized_derivative` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(v: Interval3, dv: Interval3) -> Interval3 {
    let length2 = v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    (dv - v * (v.dot(dv) / length2)) / length2.sqrt()
}

/// The reference of `rf_normalized_derivative`.
fn reference() -> Reference<(Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of (v + h dv) / |v + h dv| at h = 0 (Igehy; RTG Eq. 10)",
        || (unit(), log_uniform(-2.0, 2.0), unit(), log_uniform(-4.0, 1.0)).boxed(),
        |&(v_direction, v_length, dv_direction, dv_length), normalized_derivative| {
            let (v, dv) = (
                (v_direction * v_length).as_vec3(),
                (dv_direction * dv_length).as_vec3(),
            );
            let got = normalized_derivative((v, dv));
            let (v64, dv64) = (v.as_dvec3(), dv.as_dvec3());
            let step = 1.0e-3 * v64.length() / dv64.length();
            let expected = derivative(|h| (v64 + dv64 * h).normalize(), step, 1.0);
            let bounds = widths(&enclosure(interval3(v), interval3(dv)).components());
            Some(components(got, &expected.value.to_array(), |i| {
                bounds[i] + expected.error
            }))
        },
    )
}
