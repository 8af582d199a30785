//! The proof of [`triangle_base_lod`](ray_footprint::ray_cone::triangle_base_lod): its record and its
//! reference, triangles mapped to UV by a known affine map.

use crate::degenerate::value;
use crate::ray_cone::footprint::shared::{
    area_corners, corners_moved, corners_turned, triangle_with_uvs, vertex_order_turned, Mapped,
    COLLINEAR_UVS, ZERO_AREA, ZERO_AREA_AND_COLLINEAR_UVS,
};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::symmetry::Symmetry;
use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::{self as rc, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{log2_error, ulps};
use shader_proptest::{Args, Value};

/// The record of `rf_triangle_base_lod`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "triangle_base_lod",
        |(p0, p1, p2, uv0, uv1, uv2)| rc::triangle_base_lod(p0, p1, p2, uv0, uv1, uv2),
        triangle_with_uvs,
    )
    // The areas' errors through 0.5 * (log2 uv - log2 world) with the clamps, half of each
    // log2's error, and the subtraction and halving (2 ULP).
    .bound(|&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
        let min = f64::from(MIN_SQUARED_MAGNITUDE);
        let uv_area2 = rc::triangle_uv_area2(uv0, uv1, uv2).max(MIN_SQUARED_MAGNITUDE);
        let world_area2 = rc::triangle_world_area2(p0, p1, p2).max(MIN_SQUARED_MAGNITUDE);
        area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
            0.5 * (uv.max(min).log2() - world.max(min).log2())
        }) + 0.5 * (log2_error(uv_area2.log2()) + log2_error(world_area2.log2()))
            + ulps(2.0, expected)
    })
    .reference(reference())
    .symmetry(Symmetry::scale_in_log(
        "the corners of a triangle whose doubled area is above MIN_SQUARED_MAGNITUDE (not clamped) scaled by s: the LOD less log2 s",
        |&(p0, p1, p2, uv0, uv1, uv2): &(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), s| {
            (p0 * s, p1 * s, p2 * s, uv0, uv1, uv2)
        },
        |lod: f32, s| lod + s.log2(),
    )
    .within(|&(p0, p1, p2, ..)| rc::triangle_world_area2(p0, p1, p2) > MIN_SQUARED_MAGNITUDE))
    .symmetry(corners_turned())
    .symmetry(corners_moved())
    .symmetry(vertex_order_turned())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        value(
            "zero-area triangle",
            "0.5 (log2(uv_area2) - log2(MIN_SQUARED_MAGNITUDE))",
            ZERO_AREA,
            vec![0.5 * (0.0 - MIN_SQUARED_MAGNITUDE.log2())],
        ),
        value(
            "collinear UVs",
            "0.5 (log2(MIN_SQUARED_MAGNITUDE) - log2(world_area2))",
            COLLINEAR_UVS,
            vec![0.5 * (MIN_SQUARED_MAGNITUDE.log2() - 0.0)],
        ),
        value(
            "zero-area triangle and collinear UVs",
            "0",
            ZERO_AREA_AND_COLLINEAR_UVS,
            vec![0.0],
        ),
    ])
}

/// The reference of `rf_triangle_base_lod`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles in random planes mapped to UV by a known affine map M: the base LOD is log2(sqrt(|det M|)) = 0.5 log2 |det M| (RTG Eq. 4)",
        Mapped::strategy,
        |mapped, triangle_base_lod| {
            let got = triangle_base_lod(mapped.arguments());
            let expected = 0.5 * mapped.map.determinant().abs().log2();
            // The areas within their errors; each log2 within 2 ULP of its result (4 u), the
            // difference rounds once, the halving is exact.
            let ((uv, _), (world, _)) = mapped.areas();
            let logs = uv.log2().abs() + world.log2().abs();
            let bound = mapped.corners(|uv, world| 0.5 * (uv.log2() - world.log2())) + gamma(5) * logs;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}
