//! The proof of
//! [`intersect_triangle_plane_f64`](ray_footprint::ray_diff_f64::intersect_triangle_plane_f64): its
//! record, its case strategy and its reference.

use crate::conditioning::well_conditioned;
use crate::exact::triangle_hit;
use crate::ray_diff::intervals::determinant;
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::reintersection::shared::{plane_intersection_rows, unclamped};
use crate::ray_diff_f64::reintersection::shared::plane_barycentrics_f64;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{triangle, unit_vec3, vec3};
use crate::symmetry::Symmetry;
use glam::Vec3;
use glam::Vec3Swizzles;
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_diff_f64::{self as rd64, F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3_f64, Interval};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// Why a ray against a triangle is left out of the f64 check ([`determinant_well_conditioned_f64`]).
const PARALLEL_WITHIN_ROUNDING: &str = "the ray is parallel to the triangle's plane within f64 rounding, \
     or the triangle a sliver (the determinant k is not known to 2^-10): the clamped quotients may \
     take either +-F64_MAX_VALUE";

/// Whether the f64 determinant of `d` against the triangle `p0 p1 p2` is known to
/// [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED).
fn determinant_well_conditioned_f64(&(_, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3)) -> bool {
    well_conditioned(determinant(
        interval3_f64(d),
        interval3_f64(p0),
        interval3_f64(p1),
        interval3_f64(p2),
    ))
}

/// The arguments of `intersect_triangle_plane_f64`: an origin, a unit or any direction and a
/// triangle whose f64 determinant is well-conditioned.
fn plane_intersections_f64() -> BoxedStrategy<(Vec3, Vec3, Vec3, Vec3, Vec3)> {
    let direction = one_of![3 => unit_vec3(), 1 => vec3()];
    (vec3(), direction, triangle())
        .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
        .prop_filter(PARALLEL_WITHIN_ROUNDING, determinant_well_conditioned_f64)
        .boxed()
}

/// Whether neither of the function's clamps acts: the determinant `dot(cross(e1, e2), d)`, its edges
/// taken in f64 as the function takes them (in f32 a sliver's determinant can be far off), is
/// above `F64_MIN_MAGNITUDE` (with a margin) and no barycentric reaches `F64_MAX_VALUE`.
fn unclamped_f64(&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3)) -> bool {
    let [q0, q1, q2] = [p0, p1, p2].map(Vec3::as_dvec3);
    let determinant = (q1 - q0).cross(q2 - q0).dot(d.as_dvec3());
    let barycentrics = rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2);
    determinant.abs() > 2.0 * F64_MIN_MAGNITUDE && unclamped(barycentrics.as_dvec3(), F64_MAX_VALUE)
}

/// The record of `rf_intersect_triangle_plane_f64`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    Record::new(
        Module::RayDiffF64,
        "intersect_triangle_plane_f64",
        |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
        plane_intersections_f64,
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, determinant_well_conditioned_f64)
    .enclosure(|&(o, d, p0, p1, p2)| {
        let b = plane_barycentrics_f64(
            interval3_f64(o),
            interval3_f64(d),
            [p0, p1, p2].map(interval3_f64),
        );
        b.map(Interval::to_f32).components()
    })
    .reference(reference())
    .symmetry(
        Symmetry::rotation(
            "the ray and the triangle turned, where no barycentric reaches the clamp: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), r| (r * o, r * d, r * p0, r * p1, r * p2),
            |b: Vec3, _| b,
        )
        .within(unclamped_f64),
    )
    .symmetry(
        Symmetry::translation(
            "the origin and the triangle moved, where no barycentric reaches the clamp: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), t| (o + t, d, p0 + t, p1 + t, p2 + t),
            |b: Vec3, _| b,
        )
        .within(unclamped_f64),
    )
    .symmetry(
        Symmetry::scale(
            "the origin and the triangle scaled by s, where no barycentric reaches the clamp: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), s| (o * s, d, p0 * s, p1 * s, p2 * s),
            |b: Vec3, _| b,
        )
        .within(unclamped_f64),
    )
    .symmetry(
        Symmetry::scale(
            "the direction scaled by s, where no barycentric reaches the clamp: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), s| (o, d * s, p0, p1, p2),
            |b: Vec3, _| b,
        )
        .within(unclamped_f64),
    )
    .symmetry(
        Symmetry::exchange(
            "the vertex order turned, where no barycentric reaches the clamp: the barycentrics rotated",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3)| (o, d, p1, p2, p0),
            |b: Vec3| b.zxy(),
        )
        .within(unclamped_f64),
    )
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec3(), d.vec3()))
    .promise(|_, b, promises| {
        let max = rd64::F64_MAX_VALUE as f32;
        for x in [b.y, b.z] {
            promises.within(x, -max, max, "barycentric");
        }
    })
    .degenerate(plane_intersection_rows(
        "k clamped, u and v clamped to +-F64_MAX_VALUE",
        max,
    ))
}

/// The reference of `rf_intersect_triangle_plane_f64`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "origin + s direction = p0 + u e1 + v e2 solved as a 3x3 system in f64 (the matrix inverted), over the whole domain's origins, directions and triangles (RTG Eq. 13)",
        plane_intersections_f64,
        |&(o, d, p0, p1, p2), intersect_triangle_plane_f64| {
            let (expected, _) = triangle_hit(o.as_dvec3(), d.as_dvec3(), [p0, p1, p2].map(Vec3::as_dvec3));
            if !unclamped(expected, F64_MAX_VALUE) {
                return None;
            }
            let got = intersect_triangle_plane_f64((o, d, p0, p1, p2));
            let triangle = [p0, p1, p2].map(interval3_f64);
            let rounding = plane_barycentrics_f64(interval3_f64(o), interval3_f64(d), triangle);
            let bounds = widths(&rounding.map(Interval::to_f32).components());
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.abs().max_element()))
        },
    )
}
