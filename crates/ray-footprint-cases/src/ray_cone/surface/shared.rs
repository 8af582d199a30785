//! What the functions of the surface spread share: the degenerate rows of both normal spread
//! angles, and for their references the normal derivatives they draw and the angle between the
//! normals at a pixel's ends.

use crate::degenerate::{value, Row};
use crate::exact::angle_between;
use glam::{DVec3, Vec3};
use proptest::prelude::*;

// Rows of both normal spread angles (exact and small-angle): 0 for a flat surface and when the
// squares of the derivatives underflow.
pub(crate) fn flat_normal() -> Row<(Vec3, Vec3)> {
    value(
        "zero normal derivatives (flat)",
        "0",
        (Vec3::ZERO, Vec3::ZERO),
        vec![0.0],
    )
}

pub(crate) fn sub_normal_derivatives() -> Row<(Vec3, Vec3)> {
    value(
        "sub-normal derivatives (1e-40 each)",
        "0 (the squares underflow)",
        (Vec3::splat(1.0e-40), Vec3::splat(-1.0e-40)),
        vec![0.0],
    )
}

/// Normal derivatives: each component small, ordinary or tiny (lengths down to about 1e-12).
pub(crate) fn normal_derivatives() -> BoxedStrategy<(Vec3, Vec3)> {
    let component = || prop_oneof![3 => -2.0f32..2.0, 1 => (-12.0f32..0.0).prop_map(|e| 10f32.powf(e))];
    let vector = || (component(), component(), component()).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    (vector(), vector()).boxed()
}

/// The angle between the unit normals at the two ends of a pixel across which the normal turns
/// by the combined length `length` of its derivatives (RTG Eq. 31): the normals `n +- g / 2`, `g`
/// perpendicular to the unit `n` with `|g| = length`, normalised.
pub(crate) fn normals_across_a_pixel(length: f64) -> f64 {
    let n = DVec3::new(0.36, 0.48, 0.8);
    let g = n.any_orthonormal_vector() * length;
    angle_between((n + 0.5 * g).normalize(), (n - 0.5 * g).normalize())
}

/// `sqrt(|dn_dx|^2 + |dn_dy|^2)` in f64.
pub(crate) fn derivative_length(dn_dx: Vec3, dn_dy: Vec3) -> f64 {
    (dn_dx.as_dvec3().length_squared() + dn_dy.as_dvec3().length_squared()).sqrt()
}
