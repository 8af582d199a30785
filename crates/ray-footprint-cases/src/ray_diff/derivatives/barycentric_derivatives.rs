//! The proof of [`barycentric_derivatives`](ray_footprint::ray_diff::barycentric_derivatives): its
//! record, its enclosure and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::{BarycentricArgs, Hit};
use crate::ray_diff::intervals::{
    self, barycentric_quotient, determinant, determinant_well_conditioned, PARALLEL_WITHIN_ROUNDING,
};
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::rows::{direction_dx, zero_diff_dx};
use crate::ray_diff::strategy::{any_direction, ray_diff};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::strategy::{distance, triangle};
use glam::{DVec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, IntervalVec};

/// Whether neither clamp acts: the determinant `dot(cross(e1, e2), d)` is above
/// `DIFF_MIN_MAGNITUDE` (with a margin) and every derivative below half of `DIFF_MAX_VALUE`.
fn unclamped_derivatives(&(diff, d, t, p0, p1, p2): &BarycentricArgs) -> bool {
    let [e1, e2] = [p1 - p0, p2 - p0].map(Vec3::as_dvec3);
    let determinant = e1.cross(e2).dot(d.as_dvec3());
    let b = rd::barycentric_derivatives(diff, d, t, p0, p1, p2);
    let largest = b.dx.abs().max_element().max(b.dy.abs().max_element());
    determinant.abs() > 2.0 * f64::from(rd::DIFF_MIN_MAGNITUDE) && largest < 0.5 * DIFF_MAX_VALUE
}

/// The record of `rf_barycentric_derivatives`: the enclosure of the four derivatives.
pub fn record() -> Record<BarycentricArgs, Derivatives2> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "barycentric_derivatives",
        |(diff, d, t, p0, p1, p2)| rd::barycentric_derivatives(diff, d, t, p0, p1, p2),
        || {
            (ray_diff(), any_direction(), distance(), triangle())
                .prop_map(|(diff, d, t, p)| (diff, d, t, p[0], p[1], p[2]))
                .boxed()
        },
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, |&(_, d, _, p0, p1, p2)| {
        determinant_well_conditioned(d, p0, p1, p2)
    })
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the differential, the ray and the triangle turned: the same",
        |&(diff, d, t, p0, p1, p2): &(RayDiff, Vec3, f32, Vec3, Vec3, Vec3), r| {
            (turned(diff, r), r * d, t, r * p0, r * p1, r * p2)
        },
        |b: Derivatives2, _| b,
    ))
    .symmetry(Symmetry::translation(
        "the triangle moved: the same",
        |&(diff, d, t, p0, p1, p2): &(RayDiff, Vec3, f32, Vec3, Vec3, Vec3), o| {
            (diff, d, t, p0 + o, p1 + o, p2 + o)
        },
        |b: Derivatives2, _| b,
    ))
    .symmetry(Symmetry::scale(
        "lengths scaled by s (the origin parts, the distance, the triangle), where no clamp acts: the same",
        |&(diff, d, t, p0, p1, p2): &(RayDiff, Vec3, f32, Vec3, Vec3, Vec3), s| {
            (origins_scaled(diff, s), d, t * s, p0 * s, p1 * s, p2 * s)
        },
        |b: Derivatives2, _| b,
    )
    .within(unclamped_derivatives))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the derivatives exchanged",
        |&(diff, d, t, p0, p1, p2): &(RayDiff, Vec3, f32, Vec3, Vec3, Vec3)| {
            (swapped(diff), d, t, p0, p1, p2)
        },
        swapped2,
    ))
    .fuzz(|d| (d.ray_diff(), d.unit(), d.distance(), d.vec3(), d.vec3(), d.vec3()))
    .range(-rd::DIFF_MAX_VALUE, rd::DIFF_MAX_VALUE, "barycentric derivative")
    .degenerate(vec![
        value(
            "zero-area triangle (p1 = p2)",
            "k clamped to DIFF_MIN_MAGNITUDE, results clamped to +-DIFF_MAX_VALUE",
            (zero_diff_dx(y), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, x),
            vec![rd::DIFF_MAX_VALUE, -rd::DIFF_MAX_VALUE, 0.0, 0.0],
        ),
        value(
            "t = 0, dO = 0",
            "0",
            (direction_dx(x), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, y),
            vec![0.0; 4],
        ),
        value(
            "ray in the triangle's plane (k = 0), dO off the plane",
            "du/dx = -1 / DIFF_MIN_MAGNITUDE clamped to -DIFF_MAX_VALUE; the rest 0",
            (zero_diff_dx(z), x, 0.0, Vec3::ZERO, x, y),
            vec![-max, 0.0, 0.0, 0.0],
        ),
    ])
}

/// `rf_barycentric_derivatives` in interval arithmetic, in the same order of operations.
fn enclosure(&(diff, direction, t, p0, p1, p2): &BarycentricArgs) -> Vec<Interval> {
    let d = interval3(direction);
    let e1 = interval3(p1) - interval3(p0);
    let e2 = interval3(p2) - interval3(p0);
    let k = determinant(d, interval3(p0), interval3(p1), interval3(p2));
    let cu = e2.cross(d);
    let cv = d.cross(e1);
    let q = interval3(diff.d_origin_dx) + interval3(diff.d_direction_dx) * Interval::exact(t);
    let r = interval3(diff.d_origin_dy) + interval3(diff.d_direction_dy) * Interval::exact(t);
    let quotient = |n: Interval| barycentric_quotient(n, k);
    intervals::derivatives2(
        IntervalVec([quotient(cu.dot(q)), quotient(cv.dot(q))]),
        IntervalVec([quotient(cu.dot(r)), quotient(cv.dot(r))]),
    )
}

/// The reference of `rf_barycentric_derivatives`.
fn reference() -> Reference<BarycentricArgs, Derivatives2> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the barycentrics (u, v) of the rays (O + h dO, D + h dD) re-intersected with the triangle's plane, a 3x3 system solved in f64 (RTG Eq. 12-19)",
        Hit::strategy,
        |hit, barycentric_derivatives| {
            let got = barycentric_derivatives(hit.arguments());
            let [dx, dy] = hit.along(|(b, _)| DVec2::new(b.y, b.z));
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            let bounds = widths(&enclosure(&hit.arguments()));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}
