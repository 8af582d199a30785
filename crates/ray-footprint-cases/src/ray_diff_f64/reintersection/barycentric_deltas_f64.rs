//! The proof of [`barycentric_deltas_f64`](ray_footprint::ray_diff_f64::barycentric_deltas_f64):
//! its record and its reference.

use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::reintersection::shared::{delta_rows, exact_offsets, OffsetArgs};
use crate::ray_diff_f64::reintersection::barycentric_offsets_f64;
use crate::ray_diff_f64::reintersection::shared::{
    exact_offsets_f64, reintersection_record, well_conditioned_offset_args_f64,
};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::symmetry::Symmetry;
use glam::Vec3;
use glam::Vec3Swizzles;
use ray_footprint::ray_diff_f64::{self as rd64, F64_MAX_VALUE};
use shader_proptest::{Args, Value};

/// The record of `rf_barycentric_deltas_f64`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    reintersection_record("barycentric_deltas_f64", |(m, o, p0, p1, p2, x, y, b)| {
        rd64::barycentric_deltas_f64(m, o, p0, p1, p2, x, y, b)
    })
    .enclosure(|a| {
        let (dx, dy) = barycentric_offsets_f64::enclosure(a);
        (dx.abs() + dy.abs()).components()
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped (the x and y neighbour rays exchanged), where no barycentric reaches the clamp: the same",
        |&(m, o, p0, p1, p2, x, y, b): &OffsetArgs| (m, o, p0, p1, p2, y, x, b),
        |deltas: Vec3| deltas,
    )
    .within(|args: &OffsetArgs| exact_offsets(args, F64_MAX_VALUE).is_some()))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (the hit's barycentrics with it), where no barycentric reaches the clamp: the deltas rotated",
        |&(m, o, p0, p1, p2, x, y, b): &OffsetArgs| (m, o, p1, p2, p0, x, y, b.yzx()),
        |deltas: Vec3| deltas.zxy(),
    )
    .within(|args: &OffsetArgs| exact_offsets(args, F64_MAX_VALUE).is_some()))
    .fuzz(|d| d.reintersection())
    .range(0.0, f32::MAX, "delta")
    .degenerate(delta_rows(
        "(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32",
        vec![max, max, 1.0],
    ))
}

/// The reference of `rf_barycentric_deltas_f64`.
fn reference() -> Reference<OffsetArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "|b_x - b| + |b_y - b| of the exact offsets (neighbour rays taken to object space by the f64 matrix's linear part and intersected in f64); origins up to 1e8",
        well_conditioned_offset_args_f64,
        |args, barycentric_deltas_f64| {
            let [dx, dy] = exact_offsets_f64(args)?;
            let got = barycentric_deltas_f64(*args);
            let (x, y) = barycentric_offsets_f64::enclosure(args);
            let bounds = widths(&(x.abs() + y.abs()).components());
            let expected = dx.abs() + dy.abs();
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.max_element()))
        },
    )
}
