//! The proof of [`transfer`](ray_footprint::ray_diff::transfer): its record, its enclosure and its reference.

use crate::degenerate::{parts, value};
use crate::exact::{derivative, log_uniform, plane_hit, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::family::{axis, differential, family_step};
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::rows::{direction_dx, zero_diff_dx};
use crate::ray_diff::strategy::ray_diff;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{distance, normal_and_direction};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, RayDiff, DIFF_MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_transfer`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    Record::new(
        Module::RayDiff,
        "transfer",
        |(diff, direction, t, normal)| rd::transfer(diff, direction, t, normal),
        || {
            (ray_diff(), normal_and_direction(), distance())
                .prop_map(|(diff, (n, d), t)| (diff, d, t, n))
                .boxed()
        },
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "everything turned: the differential turned",
        |&(diff, d, t, n): &(RayDiff, Vec3, f32, Vec3), r| (turned(diff, r), r * d, t, r * n),
        |diff: RayDiff, r| turned(diff, r.transpose()),
    ))
    .symmetry(Symmetry::scale(
        "the origin parts and the distance scaled by s: the origin parts by s",
        |&(diff, d, t, n): &(RayDiff, Vec3, f32, Vec3), s| (origins_scaled(diff, s), d, t * s, n),
        |diff: RayDiff, s| origins_scaled(diff, 1.0 / s),
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the x and y parts exchanged",
        |&(diff, d, t, n): &(RayDiff, Vec3, f32, Vec3)| (swapped(diff), d, t, n),
        swapped,
    ))
    .symmetry(
        Symmetry::exchange(
            "the normal flipped, off the surface's plane by more than DIFF_MIN_COS: the same",
            |&(diff, d, t, n): &(RayDiff, Vec3, f32, Vec3)| (diff, d, t, -n),
            |diff: RayDiff| diff,
        )
        .within(|&(_, d, _, n)| d.dot(n).abs() > DIFF_MIN_COS),
    )
    .fuzz(|d| (d.ray_diff(), d.unit(), d.distance(), d.unit()))
    .degenerate(vec![
        value(
            "ray in the plane (dot(D, N) = 0)",
            "dot(D, N) clamped to +DIFF_MIN_COS: dP = q - dot(q, N) / DIFF_MIN_COS * D",
            (zero_diff_dx(z), x, 1.0, z),
            parts(RayDiff::new(
                Vec3::new(in_plane_cos, 0.0, 1.0),
                Vec3::ZERO,
                Vec3::ZERO,
                Vec3::ZERO,
            )),
        ),
        value(
            "t = 0",
            "dO moved along D onto the plane",
            (zero_diff_dx(Vec3::new(1.0, 0.0, 1.0)), Vec3::NEG_Z, 0.0, z),
            parts(RayDiff::new(x, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "huge t (1e12)",
            "t dD (finite)",
            (direction_dx(Vec3::new(1.0e-3, 0.0, 0.0)), Vec3::NEG_Z, 1.0e12, z),
            parts(RayDiff::new(
                Vec3::new(1.0e-3 * 1.0e12, 0.0, 0.0),
                Vec3::ZERO,
                Vec3::new(1.0e-3, 0.0, 0.0),
                Vec3::ZERO,
            )),
        ),
    ])
}

/// One origin differential transferred to the plane at `t` with normal `normal`; the differential
/// comes as intervals (from earlier operations), the ray and the plane are exact.
pub fn transferred_origin(
    d_origin: Interval3,
    d_direction: Interval3,
    direction: Vec3,
    t: f32,
    normal: Vec3,
) -> Interval3 {
    let cosine = interval3(direction).dot(interval3(normal));
    let q = d_origin + d_direction * Interval::exact(t);
    let dt = (-q.dot(interval3(normal))).div_away(cosine, f64::from(DIFF_MIN_COS));
    q + interval3(direction) * dt
}

/// `rf_transfer` in interval arithmetic, in the same order of operations.
fn enclosure(&(diff, direction, t, normal): &(RayDiff, Vec3, f32, Vec3)) -> Vec<Interval> {
    intervals::ray_diff(
        transferred_origin(
            interval3(diff.d_origin_dx),
            interval3(diff.d_direction_dx),
            direction,
            t,
            normal,
        ),
        transferred_origin(
            interval3(diff.d_origin_dy),
            interval3(diff.d_direction_dy),
            direction,
            t,
            normal,
        ),
        interval3(diff.d_direction_dx),
        interval3(diff.d_direction_dy),
    )
}

/// The reference of `rf_transfer`.
fn reference() -> Reference<(RayDiff, Vec3, f32, Vec3), RayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the exact hit of the ray (h dO, D + h dD) on the plane through t D with normal N (Igehy's transfer); the direction changes pass unchanged",
        || (differential(), unit(), 0.01f64..1.0, 0.0f64..6.3, log_uniform(-2.0, 3.0)).boxed(),
        |&(diff, n, cosine, angle, t), transfer| {
            let direction = towards(n, cosine, angle).as_vec3();
            let (normal, t) = (n.as_vec3(), t as f32);
            let got = transfer((diff, direction, t, normal));
            let (d64, n64, t64) = (direction.as_dvec3(), normal.as_dvec3(), f64::from(t));
            let plane_point = d64 * t64;
            let step = family_step(&diff, t64, cosine, t64);
            let moved = |a: usize| {
                let (o, dd) = axis(&diff, a);
                derivative(|h| plane_hit(o * h, d64 + dd * h, plane_point, n64), step, 2.0 * t64)
            };
            let (dx, dy) = (moved(0), moved(1));
            let (ddx, ddy) = (axis(&diff, 0).1, axis(&diff, 1).1);
            let expected = listed(&[dx.value, dy.value, ddx, ddy], 1);
            let bounds = widths(&enclosure(&(diff, direction, t, normal)));
            let error = dx.error.max(dy.error);
            Some(components(got, &expected, |i| bounds[i] + if i < 8 { error } else { 0.0 }))
        },
    )
}
