//! The proof of [`ray_diff_from_cone`](ray_footprint::ray_diff::ray_diff_from_cone): its record,
//! its enclosure and its references, the differential's rays and the round trip.

use crate::degenerate::{parts, value};
use crate::ray_diff::changes::*;
use crate::ray_diff::cones::shared::{
    canonical, cone_and_distance, cone_error, orthonormal_tangent, F32_CHAIN,
};
use crate::ray_diff::intervals::{self};
use crate::ray_diff::reference::widths;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::strategy::{angle, scalar, unit_vec3, vec2_of};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, RayDiff};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval};

/// The record of `rf_ray_diff_from_cone`: the enclosure of the differential.
pub fn record() -> Record<(Vec2, Vec3), RayDiff> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "ray_diff_from_cone",
        |(cone, d)| rd::ray_diff_from_cone(cone, d),
        || (vec2_of(scalar(), angle()), unit_vec3()).boxed(),
    )
    .enclosure(enclosure)
    .reference(reference())
    .reference(ray_diff_from_cone_round_trip())
    .symmetry(Symmetry::scale(
        "the width scaled by s: the origin parts by s",
        |&(cone, d): &(Vec2, Vec3), s| (Vec2::new(cone.x * s, cone.y), d),
        |diff: RayDiff, s| origins_scaled(diff, 1.0 / s),
    ))
    .symmetry(Symmetry::exchange(
        "the cone negated (the same cone, its sides exchanged): the differential negated",
        |&(cone, d): &(Vec2, Vec3)| (-cone, d),
        |diff: RayDiff| {
            RayDiff::new(
                -diff.d_origin_dx,
                -diff.d_origin_dy,
                -diff.d_direction_dx,
                -diff.d_direction_dy,
            )
        },
    ))
    .fuzz(|d| (d.vec2(), d.unit()))
    .degenerate(vec![
        value("zero cone", "zero differential", (Vec2::ZERO, -z), vec![0.0; 16]),
        value(
            "direction -Z",
            "u = (1, 0, 0), v = (0, -1, 0)",
            (Vec2::new(0.5, 0.25), -z),
            parts(RayDiff::new(0.5 * x, -0.5 * y, 0.25 * x, -0.25 * y)),
        ),
        value(
            "direction +Z",
            "u = (1, 0, 0), v = (0, 1, 0)",
            (Vec2::new(0.5, 0.25), z),
            parts(RayDiff::new(0.5 * x, 0.5 * y, 0.25 * x, 0.25 * y)),
        ),
        value(
            "zero direction",
            "u = (1, 0, 0), v = 0: the y differentials vanish",
            (Vec2::new(0.5, 0.25), Vec3::ZERO),
            parts(RayDiff::new(0.5 * x, Vec3::ZERO, 0.25 * x, Vec3::ZERO)),
        ),
    ])
}

/// `rf_ray_diff_from_cone` in interval arithmetic, in the same order of operations.
fn enclosure(&(cone, direction): &(Vec2, Vec3)) -> Vec<Interval> {
    let d = interval3(direction);
    let u = orthonormal_tangent(d);
    let v = d.cross(u);
    let (width, spread) = (Interval::exact(cone.x), Interval::exact(cone.y));
    intervals::ray_diff(u * width, v * width, u * spread, v * spread)
}

/// A reference of `rf_ray_diff_from_cone`: the differential's rays.
fn reference() -> Reference<(Vec2, Vec3), RayDiff> {
    Reference::new(
        Kind::ExactGeometry,
        "the differential's neighbour rays (O + dO, D + dD) per axis: after any distance t they lie |w + s t| from the central ray, across d, in two perpendicular directions",
        cone_and_distance,
        |&(w, s, d, t), ray_diff_from_cone| {
            let (cone, direction) = (Vec2::new(w as f32, s as f32), d.as_vec3());
            let diff = ray_diff_from_cone((cone, direction));
            let (w, s) = (f64::from(cone.x), f64::from(cone.y));
            let across = (w + s * t).abs();
            let d = direction.as_dvec3().normalize();
            let at = |o: Vec3, turn: Vec3| o.as_dvec3() + turn.as_dvec3() * t;
            let (x, y) = (at(diff.d_origin_dx, diff.d_direction_dx), at(diff.d_origin_dy, diff.d_direction_dy));
            let rounding = widths(&enclosure(&(cone, direction)));
            let vector = |i: usize| rounding[i..i + 3].iter().map(|r| r * r).sum::<f64>().sqrt();
            let (ex, ey) = (vector(0) + t * vector(8), vector(4) + t * vector(12));
            // Duff et al.'s tangent of a direction that is unit only to rounding is unit and
            // perpendicular to it within a few times that.
            let eta = 8.0 * ((direction.as_dvec3().length() - 1.0).abs() + U);
            let deviations = [
                Deviation::new((x.length() - across).abs(), ex + eta * across),
                Deviation::new((y.length() - across).abs(), ey + eta * across),
                Deviation::new(x.dot(y).abs(), ex * y.length() + ey * x.length() + ex * ey + eta * across * across),
                Deviation::new(x.dot(d).abs(), ex + eta * across),
                Deviation::new(y.dot(d).abs(), ey + eta * across),
            ];
            Some(Deviation::worst(deviations))
        },
    )
}

/// A reference of `rf_ray_diff_from_cone`: the round trip.
fn ray_diff_from_cone_round_trip() -> Reference<(Vec2, Vec3), RayDiff> {
    Reference::new(
        Kind::Identity,
        "cone -> differential -> cone (cone_from_ray_diff) returns the cone in its canonical form, (w, s) or (-w, -s) with w >= 0",
        cone_and_distance,
        |&(w, s, d, _), ray_diff_from_cone| {
            let (cone, direction) = (Vec2::new(w as f32, s as f32), d.as_vec3());
            let back = rd::cone_from_ray_diff(ray_diff_from_cone((cone, direction)), direction);
            let expected = canonical(f64::from(cone.x), f64::from(cone.y));
            Some(Deviation::new(cone_error(back, expected), F32_CHAIN))
        },
    )
}
