//! The degenerate-input rows of `ray_diff_f64`.

use super::table::{delta_rows, offset_rows, plane_intersection_rows, OFFSET};
use super::{Degenerate, Table};
use glam::DVec3;
use ray_footprint::ray_diff_f64 as rd64;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;

pub fn tables() -> Vec<Box<dyn Degenerate>> {
    let max = rd64::F64_MAX_VALUE as f32;
    let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
    assert_eq!(offset.to_array(), OFFSET, "the offsets are exact in f32 and f64");
    vec![
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "intersect_triangle_plane_f64",
            mirror: |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            tolerance: |_, e| ulps(1.0, e),
            rows: plane_intersection_rows("k clamped, u and v clamped to +-F64_MAX_VALUE", max),
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_offsets_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_offsets_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: offset_rows(
                "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
                [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
            ),
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_deltas_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_deltas_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: delta_rows("(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32", vec![max, max, 1.0]),
        }),
    ]
}
