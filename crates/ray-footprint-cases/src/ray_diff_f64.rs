//! The records of the ray_diff_f64 module, one per function, in the module's order.
//!
//! Tolerances are enclosure widths as in [`super::ray_diff`], with f64 budgets for every
//! intermediate operation (the same ULP counts in units of 2^-52) and half an f32 ULP for each
//! conversion back to f32 (the `enclosure` submodule).

mod enclosure;
mod reference;

use crate::ray_diff::enclosure::{determinant, well_conditioned};
use crate::ray_diff::{delta_rows, offset_args, offset_rows, plane_intersection_rows, OffsetArgs, OFFSET};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{triangle, unit_vec3, vec3};
use glam::Vec3;
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_diff_f64 as rd64;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3_f64, Interval};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// Why a re-intersection is left out of the f64 checks ([`enclosure::offsets_well_conditioned_f64`]).
const REINTERSECTION_ILL_CONDITIONED: &str = "a neighbour ray is parallel to the triangle's plane within \
     f64 rounding, or its object-space direction is lost to the cancellation of a far origin (not \
     known to 2^-10): the clamped barycentrics may take either +-F64_MAX_VALUE";

/// Why a ray against a triangle is left out of the f64 check ([`determinant_well_conditioned_f64`]).
const PARALLEL_WITHIN_ROUNDING: &str = "the ray is parallel to the triangle's plane within f64 rounding, \
     or the triangle a sliver (the determinant k is not known to 2^-10): the clamped quotients may \
     take either +-F64_MAX_VALUE";

/// [`offset_args`] with origins up to 1e8 where both f64 intersections are well-conditioned.
fn well_conditioned_offset_args_f64() -> BoxedStrategy<OffsetArgs> {
    offset_args(8.0)
        .prop_filter(
            REINTERSECTION_ILL_CONDITIONED,
            enclosure::offsets_well_conditioned_f64,
        )
        .boxed()
}

/// Whether the f64 determinant of `d` against the triangle `p0 p1 p2` is known to
/// [`WELL_CONDITIONED`](crate::ray_diff::WELL_CONDITIONED).
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

/// The module of these records.
const MODULE: Module = Module::RayDiffF64;

/// `rf_intersect_triangle_plane_f64`.
pub fn intersect_triangle_plane_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    Record::new(
        MODULE,
        "intersect_triangle_plane_f64",
        |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
        plane_intersections_f64,
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, determinant_well_conditioned_f64)
    .enclosure(|&(o, d, p0, p1, p2)| {
        let b = enclosure::plane_barycentrics_f64(
            interval3_f64(o),
            interval3_f64(d),
            [p0, p1, p2].map(interval3_f64),
        );
        b.map(Interval::to_f32).components()
    })
    .reference(reference::intersect_triangle_plane_f64())
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

/// The record of the f64 re-intersection `function` (its Rust `mirror`) on the offset arguments
/// where both f64 intersections are well-conditioned ([`well_conditioned_offset_args_f64`]).
fn reintersection_record<R: Value>(
    function: &'static str,
    mirror: fn(OffsetArgs) -> R,
) -> Record<OffsetArgs, R> {
    Record::new(MODULE, function, mirror, well_conditioned_offset_args_f64).conditioned(
        REINTERSECTION_ILL_CONDITIONED,
        enclosure::offsets_well_conditioned_f64,
    )
}

/// `rf_barycentric_offsets_f64`.
pub fn barycentric_offsets_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    reintersection_record("barycentric_offsets_f64", |(m, o, p0, p1, p2, x, y, b)| {
        rd64::barycentric_offsets_f64(m, o, p0, p1, p2, x, y, b)
    })
    .enclosure(|a| {
        let (dx, dy) = enclosure::barycentric_offsets_f64(a);
        [dx.components(), dy.components()].concat()
    })
    .reference(reference::barycentric_offsets_f64())
    .fuzz(|d| d.reintersection())
    .degenerate(offset_rows(
        "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
        [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
    ))
}

/// `rf_barycentric_deltas_f64`.
pub fn barycentric_deltas_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    reintersection_record("barycentric_deltas_f64", |(m, o, p0, p1, p2, x, y, b)| {
        rd64::barycentric_deltas_f64(m, o, p0, p1, p2, x, y, b)
    })
    .enclosure(|a| {
        let (dx, dy) = enclosure::barycentric_offsets_f64(a);
        (dx.abs() + dy.abs()).components()
    })
    .reference(reference::barycentric_deltas_f64())
    .fuzz(|d| d.reintersection())
    .range(0.0, f32::MAX, "delta")
    .degenerate(delta_rows(
        "(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32",
        vec![max, max, 1.0],
    ))
}

/// The module's records, in the module's order.
pub(crate) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        intersect_triangle_plane_f64,
        barycentric_offsets_f64,
        barycentric_deltas_f64
    ]
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    /// The collapsed triangle's offsets, `(1, 0, 0) - hit`, are the same in f32 and f64.
    #[test]
    fn the_collapsed_offsets_are_exact_in_f32_and_f64() {
        let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
        assert_eq!(offset.to_array(), super::OFFSET);
    }
}
