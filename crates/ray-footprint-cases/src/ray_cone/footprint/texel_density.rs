//! The proof of [`texel_density`](ray_footprint::ray_cone::texel_density): its record and its
//! reference, triangles mapped to UV by a known affine map.

use crate::degenerate::value;
use crate::ray_cone::footprint::shared::{
    area_corners, corners_moved, corners_turned, triangle_with_uvs, vertex_order_turned, Mapped,
    TriangleWithUvs, COLLINEAR_UVS, ZERO_AREA, ZERO_AREA_AND_COLLINEAR_UVS,
};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::symmetry::Symmetry;
use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::{self as rc, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The unit right triangle in both spaces.
const UNIT_RIGHT_TRIANGLES: TriangleWithUvs = (Vec3::ZERO, Vec3::X, Vec3::Y, Vec2::ZERO, Vec2::X, Vec2::Y);

/// The record of `rf_texel_density`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "texel_density",
        |(p0, p1, p2, uv0, uv1, uv2)| rc::texel_density(p0, p1, p2, uv0, uv1, uv2),
        triangle_with_uvs,
    )
    // The areas' errors through sqrt(uv) / sqrt(max(world, MIN)), plus two square roots
    // (4.5 ULP each), the division (2.5) and the mirror's 3.
    .bound(|&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
        let min = f64::from(MIN_SQUARED_MAGNITUDE);
        area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
            uv.sqrt() / world.max(min).sqrt()
        }) + ulps(14.5, expected)
    })
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the corners of a triangle whose doubled area is above MIN_SQUARED_MAGNITUDE (not clamped) scaled by s: the density by 1/s",
        |&(p0, p1, p2, uv0, uv1, uv2): &(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), s| {
            (p0 * s, p1 * s, p2 * s, uv0, uv1, uv2)
        },
        |density: f32, s| density * s,
    )
    .within(|&(p0, p1, p2, ..)| rc::triangle_world_area2(p0, p1, p2) > MIN_SQUARED_MAGNITUDE))
    .symmetry(corners_turned())
    .symmetry(corners_moved())
    .symmetry(vertex_order_turned())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2()))
    .range(0.0, f32::MAX, "density")
    .degenerate(vec![
        value(
            "zero-area triangle",
            "sqrt(uv_area2) / sqrt(MIN_SQUARED_MAGNITUDE)",
            ZERO_AREA,
            vec![1.0 / MIN_SQUARED_MAGNITUDE.sqrt()],
        ),
        value("collinear UVs", "0", COLLINEAR_UVS, vec![0.0]),
        value(
            "zero-area triangle and collinear UVs",
            "0 (0 / sqrt(MIN_SQUARED_MAGNITUDE))",
            ZERO_AREA_AND_COLLINEAR_UVS,
            vec![0.0],
        ),
        value(
            "unit right triangle in both spaces",
            "1",
            UNIT_RIGHT_TRIANGLES,
            vec![1.0],
        ),
    ])
}

/// The reference of `rf_texel_density`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles in random planes mapped to UV by a known affine map M of their in-plane coordinates: the density is sqrt(|det M|), whatever the triangle",
        Mapped::strategy,
        |mapped, texel_density| {
            let got = texel_density(mapped.arguments());
            let expected = mapped.map.determinant().abs().sqrt();
            // The areas within their errors; two square roots and a division (gamma(3)).
            let bound = mapped.corners(|uv, world| (uv / world).sqrt()) + gamma(3) * expected;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}
