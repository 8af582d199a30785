//! Agreement checks of the ray_diff_f64 module, one per function, in the module's order.
//!
//! Tolerances are enclosure widths as in [`super::ray_diff`], with f64 budgets for every
//! intermediate operation (the same ULP counts in units of 2^-52) and half an f32 ULP for each
//! conversion back to f32.

use super::ray_diff::bound::{mat_vec, v3_64, F64, I, V, V3};
use super::ray_diff::{offset_args, OffsetArgs};
use crate::gpu::check::{Check, FunctionCheck};
use crate::gpu::strategy::{triangle, unit_vec3, vec3};
use crate::gpu::value::{float_value, GpuValue, ShaderType, StructType};
use crate::ray_diff_f64::{self as rd64, BarycentricOffsets, F64_MAX_VALUE, F64_MIN_MAGNITUDE};
use crate::shaders::Module;
use glam::Vec3;
use proptest::prelude::*;

/// `RfBarycentricOffsets`.
pub const BARYCENTRIC_OFFSETS: StructType = StructType {
    name: "RfBarycentricOffsets",
    fields: &[("dx", ShaderType::Vec3), ("dy", ShaderType::Vec3)],
};

#[rustfmt::skip]
float_value!(
    BarycentricOffsets,
    ShaderType::Struct(&BARYCENTRIC_OFFSETS),
    |v| [v.dx.x, v.dx.y, v.dx.z, v.dy.x, v.dy.y, v.dy.z],
    |w| BarycentricOffsets { dx: Vec3::new(w(), w(), w()), dy: Vec3::new(w(), w(), w()) }
);

fn component(bounds: Vec<I>, index: usize) -> f32 {
    bounds[index].tolerance()
}

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
        Box::new(FunctionCheck {
            module: Module::RayDiffF64,
            function: "intersect_triangle_plane_f64",
            strategy: || {
                let direction = prop_oneof![3 => unit_vec3(), 1 => vec3()];
                (vec3(), direction, triangle())
                    .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
                    .boxed()
            },
            mirror: |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            tolerance: |&(o, d, p0, p1, p2), i, _| {
                let b = b_plane_barycentrics_f64(v3_64(o), v3_64(d), v3_64(p0), v3_64(p1), v3_64(p2));
                component(b.map(I::to_f32).components(), i)
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayDiffF64,
            function: "barycentric_offsets_f64",
            strategy: || offset_args(8.0),
            mirror: |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_offsets_f64(m, o, p0, p1, p2, x, y, b),
            tolerance: |a, i, _| {
                let (dx, dy) = b_barycentric_offsets_f64(a);
                component([dx.components(), dy.components()].concat(), i)
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayDiffF64,
            function: "barycentric_deltas_f64",
            strategy: || offset_args(8.0),
            mirror: |(m, o, p0, p1, p2, x, y, b)| rd64::barycentric_deltas_f64(m, o, p0, p1, p2, x, y, b),
            tolerance: |a, i, _| {
                let (dx, dy) = b_barycentric_offsets_f64(a);
                component((dx.abs() + dy.abs()).components(), i)
            },
        }),
    ]
}
