//! The records of the ray_diff_f64 module, one per function, in the module's order.
//!
//! Tolerances are enclosure widths as in [`super::ray_diff`], with f64 budgets for every
//! intermediate operation (the same ULP counts in units of 2^-52) and half an f32 ULP for each
//! conversion back to f32.

use crate::ray_diff::{
    delta_rows, direction_well_conditioned, offset_args, offset_rows, plane_intersection_rows, OffsetArgs,
    OFFSET, WELL_CONDITIONED,
};
use crate::record::{Function, Record};
use crate::special::Perturb;
use crate::strategy::{triangle, unit_vec3, vec3};
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_diff_f64::{self as rd64, F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{
    interval3_f64 as v3_64, mat_vec, Interval as I, Interval3 as V3, IntervalVec as V, F64,
};
use shader_proptest::{Args, Value};

/// The determinant of a ray against a triangle's plane, in f64.
fn b_determinant_f64(direction: V3, p0: V3, p1: V3, p2: V3) -> I {
    (p1 - p0).cross(p2 - p0).dot(direction)
}

fn b_plane_barycentrics_f64(origin: V3, direction: V3, p0: V3, p1: V3, p2: V3) -> V3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = b_determinant_f64(direction, p0, p1, p2);
    let quotient = |n: I| {
        n.div_away(k, F64_MIN_MAGNITUDE)
            .clamp_c(-F64_MAX_VALUE, F64_MAX_VALUE)
    };
    let u = quotient(e2.cross(direction).dot(s0));
    let v = quotient(direction.cross(e1).dot(s0));
    V([I::exact64(1.0) - u - v, u, v])
}

/// The object-space origin and neighbour directions, in f64.
fn b_object_rays_f64(&(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs) -> (V3, V3, V3) {
    let transform = |p: V3| mat_vec(w2o, p, I::exact64(1.0), F64);
    let world = v3_64(origin);
    let object_origin = transform(world);
    let object_x = transform(world + v3_64(dir_x)) - object_origin;
    let object_y = transform(world + v3_64(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

/// Whether both f64 intersections are well-conditioned (see `ray_diff`'s `WELL_CONDITIONED`).
fn offsets_well_conditioned_f64(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = b_object_rays_f64(args);
    let (q0, q1, q2) = (v3_64(p0), v3_64(p1), v3_64(p2));
    [object_x, object_y].iter().all(|&d| {
        direction_well_conditioned(d) && b_determinant_f64(d, q0, q1, q2).relative_width() <= WELL_CONDITIONED
    })
}

/// [`offset_args`] with origins up to 1e8 where both f64 intersections are well-conditioned.
fn well_conditioned_offset_args_f64() -> BoxedStrategy<OffsetArgs> {
    offset_args(8.0)
        .prop_filter("an ill-conditioned re-intersection", offsets_well_conditioned_f64)
        .boxed()
}

fn b_barycentric_offsets_f64(args: &OffsetArgs) -> (V3, V3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = b_object_rays_f64(args);
    let (q0, q1, q2) = (v3_64(p0), v3_64(p1), v3_64(p2));
    let offset = |d: V3| (b_plane_barycentrics_f64(object_origin, d, q0, q1, q2) - v3_64(hit)).map(I::to_f32);
    (offset(object_x), offset(object_y))
}

/// The record of `function` of this module.
fn record<A: Args + Perturb, R: Value>(
    function: &'static str,
    mirror: fn(A) -> R,
    cases: fn() -> BoxedStrategy<A>,
) -> Record<A, R> {
    Record::new(Module::RayDiffF64, function, mirror, cases)
}

/// `rf_intersect_triangle_plane_f64`.
pub fn intersect_triangle_plane_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    record(
        "intersect_triangle_plane_f64",
        |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
        || {
            let direction = prop_oneof![3 => unit_vec3(), 1 => vec3()];
            (vec3(), direction, triangle())
                .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
                .prop_filter("an ill-conditioned determinant", |&(_, d, p0, p1, p2)| {
                    let k = b_determinant_f64(v3_64(d), v3_64(p0), v3_64(p1), v3_64(p2));
                    k.relative_width() <= WELL_CONDITIONED
                })
                .boxed()
        },
    )
    .enclosure(|&(o, d, p0, p1, p2)| {
        let b = b_plane_barycentrics_f64(v3_64(o), v3_64(d), v3_64(p0), v3_64(p1), v3_64(p2));
        b.map(I::to_f32).components()
    })
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

/// `rf_barycentric_offsets_f64`.
pub fn barycentric_offsets_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    record(
        "barycentric_offsets_f64",
        |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_offsets_f64(m, o, p0, p1, p2, x, y, b),
        well_conditioned_offset_args_f64,
    )
    .enclosure(|a| {
        let (dx, dy) = b_barycentric_offsets_f64(a);
        [dx.components(), dy.components()].concat()
    })
    .fuzz(|d| d.reintersection())
    .degenerate(offset_rows(
        "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
        [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
    ))
}

/// `rf_barycentric_deltas_f64`.
pub fn barycentric_deltas_f64() -> Record<impl Args + Perturb, impl Value> {
    let max = rd64::F64_MAX_VALUE as f32;
    record(
        "barycentric_deltas_f64",
        |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_deltas_f64(m, o, p0, p1, p2, x, y, b),
        well_conditioned_offset_args_f64,
    )
    .enclosure(|a| {
        let (dx, dy) = b_barycentric_offsets_f64(a);
        (dx.abs() + dy.abs()).components()
    })
    .fuzz(|d| d.reintersection())
    .range(0.0, f32::MAX, "delta")
    .degenerate(delta_rows(
        "(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32",
        vec![max, max, 1.0],
    ))
}

/// Every function's record, in the module's order.
pub fn records() -> Vec<Box<dyn Function>> {
    vec![
        Box::new(intersect_triangle_plane_f64()),
        Box::new(barycentric_offsets_f64()),
        Box::new(barycentric_deltas_f64()),
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
