//! What the ray_diff records' symmetries do to a differential and to a pair of derivatives: turned
//! by a rotation, the image axes swapped, the origin parts scaled, and the types the declarations
//! name.

pub(crate) use crate::symmetry::Symmetry;
pub(crate) use glam::{Mat3, Mat4, Vec2, Vec2Swizzles, Vec3, Vec3Swizzles};
pub(crate) use ray_footprint::ray_diff::{Derivatives2, Derivatives3, RayDiff};

/// Every vector of `diff` turned by `rotation`.
pub(crate) fn turned(diff: RayDiff, rotation: Mat3) -> RayDiff {
    RayDiff::new(
        rotation * diff.d_origin_dx,
        rotation * diff.d_origin_dy,
        rotation * diff.d_direction_dx,
        rotation * diff.d_direction_dy,
    )
}

/// `diff` with the image axes swapped: its x and y parts exchanged.
pub(crate) fn swapped(diff: RayDiff) -> RayDiff {
    RayDiff::new(
        diff.d_origin_dy,
        diff.d_origin_dx,
        diff.d_direction_dy,
        diff.d_direction_dx,
    )
}

/// `diff` with its origin parts (lengths) scaled by `scale`, its direction parts kept.
pub(crate) fn origins_scaled(diff: RayDiff, scale: f32) -> RayDiff {
    RayDiff::new(
        diff.d_origin_dx * scale,
        diff.d_origin_dy * scale,
        diff.d_direction_dx,
        diff.d_direction_dy,
    )
}

/// Both derivatives turned by `rotation`.
pub(crate) fn turned3(derivatives: Derivatives3, rotation: Mat3) -> Derivatives3 {
    Derivatives3::new(rotation * derivatives.dx, rotation * derivatives.dy)
}

/// The x and y derivatives exchanged.
pub(crate) fn swapped2(derivatives: Derivatives2) -> Derivatives2 {
    Derivatives2::new(derivatives.dy, derivatives.dx)
}

/// The x and y derivatives exchanged.
pub(crate) fn swapped3(derivatives: Derivatives3) -> Derivatives3 {
    Derivatives3::new(derivatives.dy, derivatives.dx)
}
