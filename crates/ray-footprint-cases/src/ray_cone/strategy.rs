//! Case strategies of the ray-cone checks that only they use: cones (packed or not), inverse
//! projections, triangles with UVs, refractive index ratios, and a direction kept off a surface's
//! plane.

use crate::strategy::{angle, perspective_proj_inv, scalar, triangle, uv_triangle};
use glam::{Mat4, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{PackedRayCone, RayCone};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use shader_proptest::tolerance::dot_error;

/// A cone: a width from [`scalar`], a spread angle from [`angle`].
pub(super) fn ray_cone() -> BoxedStrategy<RayCone> {
    (scalar(), angle())
        .prop_map(|(width, spread_angle)| RayCone { width, spread_angle })
        .boxed()
}

/// A triangle's vertices ([`triangle`]), then its UVs ([`uv_triangle`]), as six arguments.
pub(super) fn triangle_with_uvs() -> BoxedStrategy<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2)> {
    (triangle(), uv_triangle())
        .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
        .boxed()
}

/// A packed cone whose halves are finite f16 (exponent field below 31).
pub(super) fn packed_ray_cone() -> BoxedStrategy<PackedRayCone> {
    let finite_half = any::<u16>().prop_filter("finite f16", |h| (h >> 10) & 0x1f != 0x1f);
    (finite_half.clone(), finite_half)
        .prop_map(|(lo, hi)| PackedRayCone(u32::from(lo) | u32::from(hi) << 16))
        .boxed()
}

/// An inverse projection matrix of a perspective camera (y-flipped or not), or an arbitrary matrix.
pub(super) fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary = prop::array::uniform16(scalar()).prop_map(|cols| Mat4::from_cols_array(&cols));
    one_of![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// Index ratios: ordinary, 1, glass in and out, 0, and anything in the domain.
pub(super) fn eta() -> BoxedStrategy<f32> {
    one_of![
        4 => uniform(0.3, 3.0),
        1 => Just(1.0f32),
        1 => Just(1.5f32),
        1 => Just(1.0f32 / 1.5),
        1 => Just(0.0f32),
        1 => scalar(),
    ]
    .boxed()
}

/// `direction`, tilted by 1e-5 towards `-normal` when it lies within the rounding of
/// `dot(normal, direction)` of the surface plane. There either side is right, the tolerance of
/// [`super::curvature_spread_angle_error`] allows either sign, and the check could not catch a wrong one;
/// tilted, the ray meets the normal's side, still inside the `MIN_COS` clamp. The degenerate table
/// covers rays exactly in the plane.
pub(super) fn off_the_plane(normal: Vec3, direction: Vec3) -> Vec3 {
    if normal.dot(direction).abs() <= dot_error(normal, direction) {
        (direction - 1.0e-5 * normal).normalize()
    } else {
        direction
    }
}
