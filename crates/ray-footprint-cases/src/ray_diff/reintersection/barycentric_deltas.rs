//! The proof of [`barycentric_deltas`](ray_footprint::ray_diff::barycentric_deltas): its record and
//! its reference.

use crate::ray_diff::changes::*;
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::reintersection::barycentric_offsets;
use crate::ray_diff::reintersection::shared::{
    delta_rows, exact_offsets, offsets_well_conditioned, well_conditioned_offset_args, OffsetArgs,
    F32_ORIGIN_EXPONENT, REINTERSECTION_ILL_CONDITIONED,
};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use glam::Vec3;
use ray_footprint::ray_diff::{self as rd, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;

/// The record of `rf_barycentric_deltas`: the enclosure of the deltas.
pub fn record() -> Record<OffsetArgs, Vec3> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "barycentric_deltas",
        |(m, o, p0, p1, p2, x, y, b)| rd::barycentric_deltas(m, o, p0, p1, p2, x, y, b),
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
    )
    .conditioned(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned)
    .enclosure(|a| {
        let (dx, dy) = barycentric_offsets::enclosure(a);
        (dx.abs() + dy.abs()).components()
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped (the x and y neighbour rays exchanged), where no clamp acts: the same",
        |&(m, o, p0, p1, p2, x, y, b): &(Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3)| (m, o, p0, p1, p2, y, x, b),
        |deltas: Vec3| deltas,
    ).within(|args| exact_offsets(args, f64::from(DIFF_MAX_VALUE)).is_some()))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (the hit's barycentrics with it), where no clamp acts: the deltas rotated",
        |&(m, o, p0, p1, p2, x, y, b): &(Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3)| (m, o, p1, p2, p0, x, y, b.yzx()),
        |deltas: Vec3| deltas.zxy(),
    ).within(|args| exact_offsets(args, f64::from(DIFF_MAX_VALUE)).is_some()))
    .fuzz(|d| d.reintersection())
    .range(0.0, f32::MAX, "delta")
    .degenerate(delta_rows(
        "(DIFF_MAX_VALUE, DIFF_MAX_VALUE, 1) in f32",
        vec![max, max, 1.0],
    ))
}

/// The reference of `rf_barycentric_deltas`.
fn reference() -> Reference<OffsetArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "|b_x - b| + |b_y - b| of the exact offsets (neighbour rays taken to object space by the f64 matrix's linear part and intersected in f64)",
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |args, barycentric_deltas| {
            let [dx, dy] = exact_offsets(args, f64::from(DIFF_MAX_VALUE))?;
            let got = barycentric_deltas(*args);
            let (x, y) = barycentric_offsets::enclosure(args);
            let bounds = widths(&(x.abs() + y.abs()).components());
            let expected = dx.abs() + dy.abs();
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.max_element()))
        },
    )
}
