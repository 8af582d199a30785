//! Interval enclosures of the ray_diff_f64 functions: the f64 re-intersection re-evaluated in
//! interval arithmetic with f64 budgets for every intermediate operation (the same ULP counts in
//! units of 2^-52) and half an f32 ULP for each conversion back to f32; and whether both f64
//! intersections of a case are well-conditioned.

use crate::ray_diff::{direction_well_conditioned, OffsetArgs, WELL_CONDITIONED};
use ray_footprint::ray_diff_f64::{F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use shader_proptest::interval::{interval3_f64, mat_vec, Interval, Interval3, IntervalVec, F64};

/// The determinant of a ray against a triangle's plane, in f64.
pub(super) fn determinant_f64(direction: Interval3, p0: Interval3, p1: Interval3, p2: Interval3) -> Interval {
    (p1 - p0).cross(p2 - p0).dot(direction)
}

pub(super) fn plane_barycentrics_f64(
    origin: Interval3,
    direction: Interval3,
    p0: Interval3,
    p1: Interval3,
    p2: Interval3,
) -> Interval3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = determinant_f64(direction, p0, p1, p2);
    let quotient = |n: Interval| {
        n.div_away(k, F64_MIN_MAGNITUDE)
            .clamp_c(-F64_MAX_VALUE, F64_MAX_VALUE)
    };
    let u = quotient(e2.cross(direction).dot(s0));
    let v = quotient(direction.cross(e1).dot(s0));
    IntervalVec([Interval::exact64(1.0) - u - v, u, v])
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
    [object_x, object_y].iter().all(|&d| {
        direction_well_conditioned(d) && determinant_f64(d, q0, q1, q2).relative_width() <= WELL_CONDITIONED
    })
}

pub(super) fn barycentric_offsets_f64(args: &OffsetArgs) -> (Interval3, Interval3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = object_rays_f64(args);
    let (q0, q1, q2) = (interval3_f64(p0), interval3_f64(p1), interval3_f64(p2));
    let offset = |d: Interval3| {
        (plane_barycentrics_f64(object_origin, d, q0, q1, q2) - interval3_f64(hit)).map(Interval::to_f32)
    };
    (offset(object_x), offset(object_y))
}
