//! The proof of [`intersect_triangle_plane`](ray_footprint::ray_diff::intersect_triangle_plane):
//! its record, its case strategy, its enclosure and its reference.

use crate::exact::triangle_hit;
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals::{
    barycentric_quotient, determinant_well_conditioned, PARALLEL_WITHIN_ROUNDING,
};
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::reintersection::shared::{plane_barycentrics, plane_intersection_rows, unclamped};
use crate::ray_diff::strategy::any_direction;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{triangle, vec3};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval3};
use shader_proptest::{Args, Value};

/// Whether neither of the function's clamps acts: the determinant `dot(cross(e1, e2), d)` is
/// above `DIFF_MIN_MAGNITUDE` (with a margin) and no barycentric reaches `DIFF_MAX_VALUE`.
fn plane_unclamped(&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3)) -> bool {
    let [e1, e2] = [p1 - p0, p2 - p0].map(Vec3::as_dvec3);
    let determinant = e1.cross(e2).dot(d.as_dvec3());
    let barycentrics = ray_footprint::ray_diff::intersect_triangle_plane(o, d, p0, p1, p2);
    determinant.abs() > 2.0 * f64::from(ray_footprint::ray_diff::DIFF_MIN_MAGNITUDE)
        && unclamped(
            barycentrics.as_dvec3(),
            f64::from(ray_footprint::ray_diff::DIFF_MAX_VALUE),
        )
}

/// The record of `rf_intersect_triangle_plane`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayDiff,
        "intersect_triangle_plane",
        |(o, d, p0, p1, p2)| rd::intersect_triangle_plane(o, d, p0, p1, p2),
        plane_intersections,
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, |&(_, d, p0, p1, p2)| {
        determinant_well_conditioned(d, p0, p1, p2)
    })
    .enclosure(|&(o, d, p0, p1, p2)| {
        enclosure(
            interval3(o),
            interval3(d),
            interval3(p0),
            interval3(p1),
            interval3(p2),
        )
        .components()
    })
    .reference(reference())
    .symmetry(
        Symmetry::rotation(
            "the ray and the triangle turned, where no clamp acts: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), r| (r * o, r * d, r * p0, r * p1, r * p2),
            |b: Vec3, _| b,
        )
        .within(plane_unclamped),
    )
    .symmetry(
        Symmetry::translation(
            "the origin and the triangle moved, where no clamp acts: the same",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3), t| (o + t, d, p0 + t, p1 + t, p2 + t),
            |b: Vec3, _| b,
        )
        .within(plane_unclamped),
    )
    .symmetry(
        Symmetry::exchange(
            "the vertex order turned, where no clamp acts: the barycentrics rotated",
            |&(o, d, p0, p1, p2): &(Vec3, Vec3, Vec3, Vec3, Vec3)| (o, d, p1, p2, p0),
            |b: Vec3| b.zxy(),
        )
        .within(plane_unclamped),
    )
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec3(), d.vec3()))
    .promise(|_, b, promises| {
        for x in [b.y, b.z] {
            promises.within(x, -rd::DIFF_MAX_VALUE, rd::DIFF_MAX_VALUE, "barycentric");
        }
    })
    .degenerate(plane_intersection_rows(
        "k clamped, u and v clamped to +-DIFF_MAX_VALUE",
        rd::DIFF_MAX_VALUE,
    ))
}

/// The arguments of `intersect_triangle_plane`: an origin and a direction (unit or not) from the
/// whole domain, and a triangle, whose determinant is well-conditioned.
fn plane_intersections() -> BoxedStrategy<(Vec3, Vec3, Vec3, Vec3, Vec3)> {
    (vec3(), any_direction(), triangle())
        .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
        .prop_filter(PARALLEL_WITHIN_ROUNDING, |&(_, d, p0, p1, p2)| {
            determinant_well_conditioned(d, p0, p1, p2)
        })
        .boxed()
}

/// `rf_intersect_triangle_plane` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(
    origin: Interval3,
    direction: Interval3,
    p0: Interval3,
    p1: Interval3,
    p2: Interval3,
) -> Interval3 {
    plane_barycentrics(origin, direction, [p0, p1, p2], barycentric_quotient)
}

/// The reference of `rf_intersect_triangle_plane`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "origin + s direction = p0 + u e1 + v e2 solved as a 3x3 system in f64 (the matrix inverted), over the whole domain's origins, directions and triangles (RTG Eq. 13)",
        plane_intersections,
        |&(o, d, p0, p1, p2), intersect_triangle_plane| {
            let (expected, _) = triangle_hit(o.as_dvec3(), d.as_dvec3(), [p0, p1, p2].map(Vec3::as_dvec3));
            if !unclamped(expected, f64::from(DIFF_MAX_VALUE)) {
                return None;
            }
            let got = intersect_triangle_plane((o, d, p0, p1, p2));
            let rounding = enclosure(interval3(o), interval3(d), interval3(p0), interval3(p1), interval3(p2));
            let bounds = widths(&rounding.components());
            // The f64 inverse: relative 1e-9 of the largest coordinate, far below f32's rounding.
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.abs().max_element()))
        },
    )
}
