//! Records of `ray_diff`: Re-intersection of the neighbour rays (RTG Eq. 13).

use super::enclosure;
use super::enclosure::{
    determinant_well_conditioned, offsets_well_conditioned, PARALLEL_WITHIN_ROUNDING,
    REINTERSECTION_ILL_CONDITIONED,
};
use super::rows::{delta_rows, offset_rows, plane_intersection_rows, OFFSET};
use super::strategy::{derivatives3, plane_intersections, well_conditioned_offset_args, F32_ORIGIN_EXPONENT};
use super::{reference, OffsetArgs, MODULE};
use crate::degenerate::value;
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{uv_triangle, with_corners};
use glam::{Vec2, Vec3};
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, DIFF_MAX_VALUE};
use shader_proptest::interval::{interval2, interval3, Interval};
use shader_proptest::{Args, Value};

/// `rf_intersect_triangle_plane`.
pub fn intersect_triangle_plane() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "intersect_triangle_plane",
        |(o, d, p0, p1, p2)| rd::intersect_triangle_plane(o, d, p0, p1, p2),
        plane_intersections,
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, |&(_, d, p0, p1, p2)| {
        determinant_well_conditioned(d, p0, p1, p2)
    })
    .enclosure(|&(o, d, p0, p1, p2)| {
        enclosure::intersect_triangle_plane(
            interval3(o),
            interval3(d),
            interval3(p0),
            interval3(p1),
            interval3(p2),
        )
        .components()
    })
    .reference(reference::intersect_triangle_plane())
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

/// `rf_barycentric_offsets`: the enclosure of the signed differences.
pub fn barycentric_offsets() -> Record<OffsetArgs, Derivatives3> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "barycentric_offsets",
        |(m, o, p0, p1, p2, x, y, b)| rd::barycentric_offsets(m, o, p0, p1, p2, x, y, b),
        // Where a neighbour ray is parallel to the triangle plane within rounding (its determinant
        // `k` encloses 0), the device and the mirror may clamp to opposite +-DIFF_MAX_VALUE, and
        // the enclosure (clamped to that range) is 2 * DIFF_MAX_VALUE wide: either side is right.
        // Those cases are checked separately; here both determinants are well-conditioned, and
        // origins stay below 1e5 (`F32_ORIGIN_EXPONENT`), where `O + direction` keeps the
        // direction; beyond, the ray_diff_f64 module is the tool.
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
    )
    .conditioned(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned)
    .enclosure(|a| {
        let (dx, dy) = enclosure::barycentric_offsets(a);
        enclosure::derivatives3(dx, dy)
    })
    .reference(reference::barycentric_offsets())
    .fuzz(|d| d.reintersection())
    .degenerate(offset_rows(
        "(DIFF_MAX_VALUE, -DIFF_MAX_VALUE, 0) - hit in f32 (clamped u, v), (1, 0, 0) - hit",
        [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
    ))
}

/// `rf_barycentric_deltas`: the enclosure of the deltas.
pub fn barycentric_deltas() -> Record<OffsetArgs, Vec3> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "barycentric_deltas",
        |(m, o, p0, p1, p2, x, y, b)| rd::barycentric_deltas(m, o, p0, p1, p2, x, y, b),
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
    )
    .conditioned(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned)
    .enclosure(|a| {
        let (dx, dy) = enclosure::barycentric_offsets(a);
        (dx.abs() + dy.abs()).components()
    })
    .reference(reference::barycentric_deltas())
    .fuzz(|d| d.reintersection())
    .range(0.0, f32::MAX, "delta")
    .degenerate(delta_rows(
        "(DIFF_MAX_VALUE, DIFF_MAX_VALUE, 1) in f32",
        vec![max, max, 1.0],
    ))
}

/// `rf_uv_gradients_from_offsets`: the enclosure of the UV gradients.
pub fn uv_gradients_from_offsets() -> Record<(Derivatives3, Vec2, Vec2, Vec2), Derivatives2> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "uv_gradients_from_offsets",
        |(o, uv0, uv1, uv2)| rd::uv_gradients_from_offsets(o, uv0, uv1, uv2),
        || with_corners(derivatives3(), uv_triangle()),
    )
    .enclosure(|&(o, uv0, uv1, uv2)| {
        let sum = |w: Vec3| {
            interval2(uv0) * Interval::exact(w.x)
                + interval2(uv1) * Interval::exact(w.y)
                + interval2(uv2) * Interval::exact(w.z)
        };
        enclosure::derivatives2(sum(o.dx), sum(o.dy))
    })
    .reference(reference::uv_gradients_from_offsets())
    .fuzz(|d| (d.derivatives3(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        value(
            "zero offsets",
            "0",
            (Derivatives3::default(), Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.0; 4],
        ),
        value(
            "offsets summing to 0, all UVs equal",
            "0: the UV does not change",
            (
                Derivatives3::new(Vec3::new(0.5, -0.25, -0.25), Vec3::new(-1.0, 0.5, 0.5)),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
            ),
            vec![0.0; 4],
        ),
        value(
            "clamped offsets (+-DIFF_MAX_VALUE), UVs in [0, 1]",
            "finite: (-DIFF_MAX_VALUE, 0) towards the right neighbour",
            (
                Derivatives3::new(Vec3::new(max, -max, 0.0), Vec3::ZERO),
                Vec2::ZERO,
                Vec2::X,
                Vec2::Y,
            ),
            vec![-max, 0.0, 0.0, 0.0],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        intersect_triangle_plane,
        barycentric_offsets,
        barycentric_deltas,
        uv_gradients_from_offsets
    ]
}
