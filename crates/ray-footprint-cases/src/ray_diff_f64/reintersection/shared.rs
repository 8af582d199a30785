//! What the f64 re-intersection functions share: the f64 re-intersection re-evaluated in interval
//! arithmetic with f64 budgets for every intermediate operation (the same ULP counts in units of
//! 2^-52) and half an f32 ULP for each conversion back to f32; whether both f64 intersections of a
//! case are well-conditioned and the cases where they are; the record of an f64 re-intersection;
//! and the exact offsets within the f64 clamp, for the references.

use crate::conditioning::well_conditioned;
use crate::ray_diff::intervals::{determinant, direction_well_conditioned};
use crate::ray_diff::reintersection::shared::{exact_offsets, offset_args, plane_barycentrics, OffsetArgs};
use crate::record::Record;
use glam::DVec3;
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_diff_f64::{F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3_f64, mat_vec, Interval, Interval3, F64};
use shader_proptest::Value;

/// Why a re-intersection is left out of the f64 checks ([`offsets_well_conditioned_f64`]).
pub(crate) const REINTERSECTION_ILL_CONDITIONED: &str =
    "a neighbour ray is parallel to the triangle's plane within \
     f64 rounding, or its object-space direction is lost to the cancellation of a far origin (not \
     known to 2^-10): the clamped barycentrics may take either +-F64_MAX_VALUE";

/// [`offset_args`] with origins up to 1e8 where both f64 intersections are well-conditioned.
pub(crate) fn well_conditioned_offset_args_f64() -> BoxedStrategy<OffsetArgs> {
    offset_args(8.0)
        .prop_filter(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned_f64)
        .boxed()
}

/// The record of the f64 re-intersection `function` (its Rust `mirror`) on the offset arguments
/// where both f64 intersections are well-conditioned ([`well_conditioned_offset_args_f64`]).
pub(crate) fn reintersection_record<R: Value>(
    function: &'static str,
    mirror: fn(OffsetArgs) -> R,
) -> Record<OffsetArgs, R> {
    Record::new(
        Module::RayDiffF64,
        function,
        mirror,
        well_conditioned_offset_args_f64,
    )
    .conditioned(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned_f64)
}

/// The barycentrics of the ray's hit on the plane of the triangle `p`, in f64: the quotients
/// clamped away from 0 to `F64_MIN_MAGNITUDE` and to `+-F64_MAX_VALUE`.
pub(crate) fn plane_barycentrics_f64(
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
pub(crate) fn object_rays_f64(
    &(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs,
) -> (Interval3, Interval3, Interval3) {
    let transform = |p: Interval3| mat_vec(w2o, p, Interval::exact64(1.0), F64);
    let world = interval3_f64(origin);
    let object_origin = transform(world);
    let object_x = transform(world + interval3_f64(dir_x)) - object_origin;
    let object_y = transform(world + interval3_f64(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

/// Whether both f64 intersections are well-conditioned
/// ([`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED)).
pub(crate) fn offsets_well_conditioned_f64(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = object_rays_f64(args);
    let (q0, q1, q2) = (interval3_f64(p0), interval3_f64(p1), interval3_f64(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(determinant(d, q0, q1, q2)))
}

/// The exact offsets of a case, within the f64 functions' clamp.
pub(crate) fn exact_offsets_f64(args: &OffsetArgs) -> Option<[DVec3; 2]> {
    exact_offsets(args, F64_MAX_VALUE)
}
