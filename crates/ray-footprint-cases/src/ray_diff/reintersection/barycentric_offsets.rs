//! The proof of [`barycentric_offsets`](ray_footprint::ray_diff::barycentric_offsets): its record,
//! its enclosure and its reference.

use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::reintersection::intersect_triangle_plane;
use crate::ray_diff::reintersection::shared::{
    exact_offsets, object_rays, offset_rows, offsets_well_conditioned, well_conditioned_offset_args,
    OffsetArgs, F32_ORIGIN_EXPONENT, OFFSET, REINTERSECTION_ILL_CONDITIONED,
};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use ray_footprint::ray_diff::{self as rd, Derivatives3, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval3};

/// The record of `rf_barycentric_offsets`: the enclosure of the signed differences.
pub fn record() -> Record<OffsetArgs, Derivatives3> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
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
        let (dx, dy) = enclosure(a);
        intervals::derivatives3(dx, dy)
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped (the x and y neighbour rays exchanged), where no clamp acts: the offsets exchanged",
        |&(m, o, p0, p1, p2, x, y, b): &(Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3)| (m, o, p0, p1, p2, y, x, b),
        swapped3,
    ).within(|args| exact_offsets(args, f64::from(DIFF_MAX_VALUE)).is_some()))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (the hit's barycentrics with it), where no clamp acts: the offsets rotated",
        |&(m, o, p0, p1, p2, x, y, b): &(Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3)| (m, o, p1, p2, p0, x, y, b.yzx()),
        |offsets: Derivatives3| Derivatives3::new(offsets.dx.zxy(), offsets.dy.zxy()),
    ).within(|args| exact_offsets(args, f64::from(DIFF_MAX_VALUE)).is_some()))
    .fuzz(|d| d.reintersection())
    .degenerate(offset_rows(
        "(DIFF_MAX_VALUE, -DIFF_MAX_VALUE, 0) - hit in f32 (clamped u, v), (1, 0, 0) - hit",
        [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
    ))
}

/// `rf_barycentric_offsets` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(args: &OffsetArgs) -> (Interval3, Interval3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = object_rays(args);
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    (
        intersect_triangle_plane::enclosure(object_origin, object_x, p0, p1, p2) - interval3(hit),
        intersect_triangle_plane::enclosure(object_origin, object_y, p0, p1, p2) - interval3(hit),
    )
}

/// The reference of `rf_barycentric_offsets`.
fn reference() -> Reference<OffsetArgs, Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays taken to object space by the f64 matrix (the direction by its linear part, cancelling nothing) and intersected with the triangle's plane as a 3x3 system in f64, minus the hit's barycentrics",
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |args, barycentric_offsets| {
            let [dx, dy] = exact_offsets(args, f64::from(DIFF_MAX_VALUE))?;
            let got = barycentric_offsets(*args);
            let (x, y) = enclosure(args);
            let bounds = widths(&[x.components(), y.components()].concat());
            let scale = dx.abs().max_element().max(dy.abs().max_element());
            Some(components(got, &listed(&[dx, dy], 0), |i| bounds[i] + 1.0e-9 * scale))
        },
    )
}
