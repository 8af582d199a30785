//! The proof of [`barycentric_offsets_f64`](ray_footprint::ray_diff_f64::barycentric_offsets_f64):
//! its record, its enclosure and its reference.

use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::reintersection::shared::{exact_offsets, offset_rows, OffsetArgs, OFFSET};
use crate::ray_diff_f64::reintersection::shared::{
    exact_offsets_f64, object_rays_f64, plane_barycentrics_f64, reintersection_record,
    well_conditioned_offset_args_f64,
};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::symmetry::Symmetry;
use glam::Vec3Swizzles;
use ray_footprint::ray_diff_f64::{self as rd64, BarycentricOffsets, F64_MAX_VALUE};
use shader_proptest::interval::{interval3_f64, Interval, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_barycentric_offsets_f64`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    reintersection_record("barycentric_offsets_f64", |(m, o, p0, p1, p2, x, y, b)| {
        rd64::barycentric_offsets_f64(m, o, p0, p1, p2, x, y, b)
    })
    .enclosure(|a| {
        let (dx, dy) = enclosure(a);
        [dx.components(), dy.components()].concat()
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped (the x and y neighbour rays exchanged), where no barycentric reaches the clamp: the offsets exchanged",
        |&(m, o, p0, p1, p2, x, y, b): &OffsetArgs| (m, o, p0, p1, p2, y, x, b),
        |offsets: BarycentricOffsets| BarycentricOffsets {
            dx: offsets.dy,
            dy: offsets.dx,
        },
    )
    .within(|args: &OffsetArgs| exact_offsets(args, F64_MAX_VALUE).is_some()))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (the hit's barycentrics with it), where no barycentric reaches the clamp: the offsets rotated",
        |&(m, o, p0, p1, p2, x, y, b): &OffsetArgs| (m, o, p1, p2, p0, x, y, b.yzx()),
        |offsets: BarycentricOffsets| BarycentricOffsets {
            dx: offsets.dx.zxy(),
            dy: offsets.dy.zxy(),
        },
    )
    .within(|args: &OffsetArgs| exact_offsets(args, F64_MAX_VALUE).is_some()))
    .fuzz(|d| d.reintersection())
    .degenerate(offset_rows(
        "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
        [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
    ))
}

/// `rf_barycentric_offsets_f64` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(args: &OffsetArgs) -> (Interval3, Interval3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = object_rays_f64(args);
    let triangle = [p0, p1, p2].map(interval3_f64);
    let offset = |d: Interval3| {
        (plane_barycentrics_f64(object_origin, d, triangle) - interval3_f64(hit)).map(Interval::to_f32)
    };
    (offset(object_x), offset(object_y))
}

/// The reference of `rf_barycentric_offsets_f64`.
fn reference() -> Reference<OffsetArgs, BarycentricOffsets> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays taken to object space by the f64 matrix (the direction by its linear part, cancelling nothing) and intersected with the triangle's plane as a 3x3 system in f64, minus the hit's barycentrics; origins up to 1e8",
        well_conditioned_offset_args_f64,
        |args, barycentric_offsets_f64| {
            let [dx, dy] = exact_offsets_f64(args)?;
            let got = barycentric_offsets_f64(*args);
            let (x, y) = enclosure(args);
            let bounds = widths(&[x.components(), y.components()].concat());
            let scale = dx.abs().max_element().max(dy.abs().max_element());
            let expected: Vec<f64> = [dx, dy].iter().flat_map(|v| v.to_array()).collect();
            Some(components(got, &expected, |i| bounds[i] + 1.0e-9 * scale))
        },
    )
}
