//! Agreement checks of the ray_diff_f64 module, one per function, in the module's order.
//!
//! Tolerances are enclosure widths as in [`super::ray_diff`], with f64 budgets for every
//! intermediate operation (the same ULP counts in units of 2^-52) and half an f32 ULP for each
//! conversion back to f32.

use super::enclosed;
use super::ray_diff::{offset_args, OffsetArgs};
use super::strategy::{triangle, unit_vec3, vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff_f64::{self as rd64, F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use shader_proptest::interval::{
    interval3_f64 as v3_64, mat_vec, Interval as I, Interval3 as V3, IntervalVec as V, F64,
};
use shader_proptest::Check;

fn b_plane_barycentrics_f64(origin: V3, direction: V3, p0: V3, p1: V3, p2: V3) -> V3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = e1.cross(e2).dot(direction);
    let quotient = |n: I| {
        n.div_away(k, F64_MIN_MAGNITUDE)
            .clamp_c(-F64_MAX_VALUE, F64_MAX_VALUE)
    };
    let u = quotient(e2.cross(direction).dot(s0));
    let v = quotient(direction.cross(e1).dot(s0));
    V([I::exact64(1.0) - u - v, u, v])
}

fn b_barycentric_offsets_f64(&(w2o, origin, p0, p1, p2, dir_x, dir_y, hit): &OffsetArgs) -> (V3, V3) {
    let transform = |p: V3| mat_vec(w2o, p, I::exact64(1.0), F64);
    let world = v3_64(origin);
    let object_origin = transform(world);
    let object_x = transform(world + v3_64(dir_x)) - object_origin;
    let object_y = transform(world + v3_64(dir_y)) - object_origin;
    let (q0, q1, q2) = (v3_64(p0), v3_64(p1), v3_64(p2));
    let offset = |d: V3| (b_plane_barycentrics_f64(object_origin, d, q0, q1, q2) - v3_64(hit)).map(I::to_f32);
    (offset(object_x), offset(object_y))
}

/// Every check of the module.
pub fn checks() -> Vec<Box<dyn Check>> {
    vec![
        Box::new(enclosed(
            "intersect_triangle_plane_f64",
            || {
                let direction = prop_oneof![3 => unit_vec3(), 1 => vec3()];
                (vec3(), direction, triangle())
                    .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
                    .boxed()
            },
            |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            |&(o, d, p0, p1, p2)| {
                let b = b_plane_barycentrics_f64(v3_64(o), v3_64(d), v3_64(p0), v3_64(p1), v3_64(p2));
                b.map(I::to_f32).components()
            },
        )),
        Box::new(enclosed(
            "barycentric_offsets_f64",
            || offset_args(8.0),
            |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_offsets_f64(m, o, p0, p1, p2, x, y, b),
            |a| {
                let (dx, dy) = b_barycentric_offsets_f64(a);
                [dx.components(), dy.components()].concat()
            },
        )),
        Box::new(enclosed(
            "barycentric_deltas_f64",
            || offset_args(8.0),
            |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_deltas_f64(m, o, p0, p1, p2, x, y, b),
            |a| {
                let (dx, dy) = b_barycentric_offsets_f64(a);
                (dx.abs() + dy.abs()).components()
            },
        )),
    ]
}
