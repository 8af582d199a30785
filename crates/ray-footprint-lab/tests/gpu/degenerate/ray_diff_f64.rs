//! The degenerate-input rows of `ray_diff_f64`.

use super::table::{offset_args, plane_offset_args, value, OFFSET};
use super::{Degenerate, Table};
use glam::{DVec3, Vec3};
use ray_footprint::ray_diff_f64 as rd64;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;

pub fn tables() -> Vec<Box<dyn Degenerate>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    let max = rd64::F64_MAX_VALUE as f32;
    let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
    assert_eq!(offset.to_array(), OFFSET, "the offsets are exact in f32 and f64");
    vec![
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "intersect_triangle_plane_f64",
            mirror: |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
                value(
                    "ray parallel to the plane",
                    "k clamped, u and v clamped to +-F64_MAX_VALUE",
                    (z, x, Vec3::ZERO, x, y),
                    vec![max, -max, 0.0],
                ),
                value(
                    "zero-area triangle (one point)",
                    "(1, 0, 0)",
                    (z, -z, x, x, x),
                    vec![1.0, 0.0, 0.0],
                ),
                value(
                    "zero direction",
                    "(1, 0, 0): every cross product with d is 0",
                    (z, Vec3::ZERO, Vec3::ZERO, x, y),
                    vec![1.0, 0.0, 0.0],
                ),
                value(
                    "plane behind the origin",
                    "the hit behind it: (0.25, 0.25, 0.5)",
                    (Vec3::new(0.25, 0.5, -1.0), -z, Vec3::ZERO, x, y),
                    vec![0.25, 0.25, 0.5],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_offsets_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_offsets_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
                value(
                    "zero-area triangle (one point)",
                    "(1, 0, 0) - hit, both ways",
                    offset_args(),
                    [OFFSET; 2].concat(),
                ),
                value(
                    "right neighbour ray parallel to the plane, lower one through p0",
                    "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
                    plane_offset_args(x, -z),
                    [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
                ),
                value(
                    "zero neighbour directions",
                    "(1, 0, 0) - hit, both ways",
                    plane_offset_args(Vec3::ZERO, Vec3::ZERO),
                    [OFFSET; 2].concat(),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_deltas_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_deltas_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
                value(
                    "zero-area triangle (one point)",
                    "2 |(1, 0, 0) - hit|",
                    offset_args(),
                    OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
                ),
                value(
                    "right neighbour ray parallel to the plane, lower one through p0",
                    "(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32",
                    plane_offset_args(x, -z),
                    vec![max, max, 1.0],
                ),
                value(
                    "zero neighbour directions",
                    "2 |(1, 0, 0) - hit|",
                    plane_offset_args(Vec3::ZERO, Vec3::ZERO),
                    OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
                ),
            ],
        }),
    ]
}
