//! Error bounds that functions of several sections share, one term per operation: of the device
//! against the mirror (Vulkan's precision rules, [`shader_proptest::tolerance`]) for the records'
//! tolerances, and of the mirror's f32 evaluation against an exact f64 value for the references.

use crate::reference::gamma;
use glam::Vec3;
use ray_footprint::ray_cone::{RayCone, MIN_COS};
use shader_proptest::tolerance::ulps;

/// `|cos|` as the functions clamp it.
pub(crate) fn clamped_cos(normal: Vec3, direction: Vec3) -> f32 {
    normal.dot(direction).abs().max(MIN_COS)
}

/// Error of [`rc::width_at`], `width + spread_angle * t`, possibly fused: 2 ULP of the larger term.
pub(crate) fn width_at_error(cone: RayCone, t: f32) -> f32 {
    ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs())
}

/// Rounding of `width + spread * t` in f32 (possibly the mirror's `width_at`): a product and a sum,
/// `gamma(2) (|width| + 2 |spread t|)`.
pub(crate) fn width_rounding(width: f64, spread: f64, t: f64) -> f64 {
    gamma(2) * (width.abs() + 2.0 * (spread * t).abs())
}

/// `|1 - |a| |b||`: how far the f32 "unit" vectors `a` and `b` make a dot product from the cosine
/// of their angle, relatively.
pub(crate) fn unit_excess(a: Vec3, b: Vec3) -> f64 {
    (1.0 - a.as_dvec3().length() * b.as_dvec3().length()).abs()
}
