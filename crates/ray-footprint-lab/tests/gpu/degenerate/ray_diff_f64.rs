//! The degenerate-input rows of `ray_diff_f64`.

use super::table::{delta_rows, offset_rows, plane_intersection_rows, OFFSET};
use super::{register, Degenerate};
use glam::DVec3;
use ray_footprint::ray_diff_f64 as rd64;
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;

pub fn tables() -> Vec<Registered<Box<dyn Degenerate>>> {
    let max = rd64::F64_MAX_VALUE as f32;
    let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
    assert_eq!(offset.to_array(), OFFSET, "the offsets are exact in f32 and f64");
    vec![
        register(
            Module::RayDiffF64,
            "intersect_triangle_plane_f64",
            |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            |_, e| ulps(1.0, e),
            plane_intersection_rows("k clamped, u and v clamped to +-F64_MAX_VALUE", max),
        ),
        register(
            Module::RayDiffF64,
            "barycentric_offsets_f64",
            |(m, o, p0, p1, p2, dx, dy, hit)| rd64::barycentric_offsets_f64(m, o, p0, p1, p2, dx, dy, hit),
            |_, e| ulps(1.0, e),
            offset_rows(
                "(F64_MAX_VALUE, -F64_MAX_VALUE, 0) - hit rounded to f32 (clamped u, v), (1, 0, 0) - hit",
                [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
            ),
        ),
        register(
            Module::RayDiffF64,
            "barycentric_deltas_f64",
            |(m, o, p0, p1, p2, dx, dy, hit)| rd64::barycentric_deltas_f64(m, o, p0, p1, p2, dx, dy, hit),
            |_, e| ulps(1.0, e),
            delta_rows("(F64_MAX_VALUE, F64_MAX_VALUE, 1) in f32", vec![max, max, 1.0]),
        ),
    ]
}
