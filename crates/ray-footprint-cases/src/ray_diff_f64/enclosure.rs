//! Interval enclosures of the ray_diff_f64 functions: the f64 re-intersection re-evaluated in
//! interval arithmetic with f64 budgets for every intermediate operation (the same ULP counts in
//! units of 2^-52) and half an f32 ULP for each conversion back to f32; and whether both f64
//! intersections of a case are well-conditioned.

use crate::ray_diff::enclosure::{determinant, plane_barycentrics, well_conditioned};
use crate::ray_diff::{direction_well_conditioned, OffsetArgs};
use ray_footprint::ray_diff_f64::{F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use shader_proptest::interval::{interval3_f64, mat_vec, Interval, Interval3, F64};

/// The barycentrics of the ray's hit on the plane of the triangle `p`, in f64: the quotients
/// clamped away from 0 to `F64_MIN_MAGNITUDE` and to `+-F64_MAX_VALUE`.
pub(super) fn plane_barycentrics_f64(
    origin: Interval3,
    direction: Interval3,
    p: [Interval3; 3],
) -> Interval3 {
    plane_barycentrics(origin, direction, p, |numerator, k| {
        numerator
            .div_away(k, F64_MIN_MAGNITUDE)
            .clamp_c(-F64_MAX_VALUE, F64_MAX_VALUE)
    })
}

/// The object-space origin and neighbour directions, in f64.
pub(super) fn object_rays_f64(
    &(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs,
) -> (Interval3, Interval3, Interval3) {
    let transform = |p: Interval3| mat_vec(w2o, p, Interval::exact64(1.0), F64);
    let world = interval3_f64(origin);
    let object_origin = transform(world);
    let object_x = transform(world + interval3_f64(dir_x)) - object_origin;
    let object_y = transform(world + interval3_f64(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

/// Whether both f64 intersections are well-conditioned (see `ray_diff`'s `WELL_CONDITIONED`).
pub(super) fn offsets_well_conditioned_f64(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = object_rays_f64(args);
    let (q0, q1, q2) = (interval3_f64(p0), interval3_f64(p1), interval3_f64(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(determinant(d, q0, q1, q2)))
}

pub(super) fn barycentric_offsets_f64(args: &OffsetArgs) -> (Interval3, Interval3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = object_rays_f64(args);
    let triangle = [p0, p1, p2].map(interval3_f64);
    let offset = |d: Interval3| {
        (plane_barycentrics_f64(object_origin, d, triangle) - interval3_f64(hit)).map(Interval::to_f32)
    };
    (offset(object_x), offset(object_y))
}
