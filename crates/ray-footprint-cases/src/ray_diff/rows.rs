//! Row arguments that degenerate rows of several sections share.

use glam::Vec3;
use ray_footprint::ray_diff::RayDiff;

/// A differential whose only non-zero part is `d_origin_dx`.
pub(crate) fn zero_diff_dx(d_origin_dx: Vec3) -> RayDiff {
    RayDiff::new(d_origin_dx, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)
}

/// A differential whose only non-zero part is `d_direction_dx`.
pub(crate) fn direction_dx(d_direction_dx: Vec3) -> RayDiff {
    RayDiff::new(Vec3::ZERO, Vec3::ZERO, d_direction_dx, Vec3::ZERO)
}
