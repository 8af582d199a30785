//! Independent references of the ray_diff_f64 records ([`crate::reference`]): the same exact
//! geometry as the f32 re-intersection's (the rays intersected with the triangle's plane as a 3x3
//! system in f64, the neighbour rays taken to object space by the matrix's linear part), with the
//! f64 functions' clamp `F64_MAX_VALUE` and origins up to 1e8.
//!
//! The bounds are the enclosures' widths (the f64 rounding of every operation and half an f32 ULP
//! for the conversion back to f32) plus `1e-9` of the largest value for the f64 inverse of the
//! reference's well-conditioned 3x3 system.

use super::enclosure;
use super::{plane_intersections_f64, well_conditioned_offset_args_f64};
use crate::exact::triangle_hit;
use crate::ray_diff::reference::{components, exact_offsets, unclamped, widths};
use crate::ray_diff::OffsetArgs;
use crate::reference::{Kind, Reference};
use glam::{DVec3, Vec3};
use ray_footprint::ray_diff_f64::BarycentricOffsets;
use ray_footprint::ray_diff_f64::F64_MAX_VALUE;
use shader_proptest::interval::{interval3_f64, Interval};

/// `rf_intersect_triangle_plane_f64`.
pub(super) fn intersect_triangle_plane_f64() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3), Vec3> {
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
            let rounding = enclosure::plane_barycentrics_f64(interval3_f64(o), interval3_f64(d), triangle);
            let bounds = widths(&rounding.map(Interval::to_f32).components());
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.abs().max_element()))
        },
    )
}

/// The exact offsets of a case, within the f64 functions' clamp.
fn exact_offsets_f64(args: &OffsetArgs) -> Option<[DVec3; 2]> {
    exact_offsets(args, F64_MAX_VALUE)
}

/// `rf_barycentric_offsets_f64`.
pub(super) fn barycentric_offsets_f64() -> Reference<OffsetArgs, BarycentricOffsets> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays taken to object space by the f64 matrix (the direction by its linear part, cancelling nothing) and intersected with the triangle's plane as a 3x3 system in f64, minus the hit's barycentrics; origins up to 1e8",
        well_conditioned_offset_args_f64,
        |args, barycentric_offsets_f64| {
            let [dx, dy] = exact_offsets_f64(args)?;
            let got = barycentric_offsets_f64(*args);
            let (x, y) = enclosure::barycentric_offsets_f64(args);
            let bounds = widths(&[x.components(), y.components()].concat());
            let scale = dx.abs().max_element().max(dy.abs().max_element());
            let expected: Vec<f64> = [dx, dy].iter().flat_map(|v| v.to_array()).collect();
            Some(components(got, &expected, |i| bounds[i] + 1.0e-9 * scale))
        },
    )
}

/// `rf_barycentric_deltas_f64`.
pub(super) fn barycentric_deltas_f64() -> Reference<OffsetArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "|b_x - b| + |b_y - b| of the exact offsets (neighbour rays taken to object space by the f64 matrix's linear part and intersected in f64); origins up to 1e8",
        well_conditioned_offset_args_f64,
        |args, barycentric_deltas_f64| {
            let [dx, dy] = exact_offsets_f64(args)?;
            let got = barycentric_deltas_f64(*args);
            let (x, y) = enclosure::barycentric_offsets_f64(args);
            let bounds = widths(&(x.abs() + y.abs()).components());
            let expected = dx.abs() + dy.abs();
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.max_element()))
        },
    )
}
