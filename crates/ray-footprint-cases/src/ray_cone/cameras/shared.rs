//! What the camera functions share: the error of the pixel's tan ratio (a tolerance), the cameras
//! their references draw, and a pixel's height and angle on the image plane in f64.

use crate::exact::angle_between;
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MAX_FOV_Y};
use shader_proptest::tolerance::{tan_error, ulps};

/// Error of `2 * tan(fov / 2) / H` with the clamps: `tan`'s error scaled by `2 / H`, plus 3.5 ULP.
pub(crate) fn tan_ratio_error(fov: f32, height: f32) -> f32 {
    let angle = 0.5 * fov.clamp(0.0, MAX_FOV_Y);
    2.0 * tan_error(angle) / height.max(1.0) + ulps(3.5, rc::pixel_spread_angle_small(fov, height))
}

/// A field of view in `(0, MAX_FOV_Y]` and an image height of at least one pixel.
pub(crate) fn camera() -> BoxedStrategy<(f32, f32)> {
    let height = prop_oneof![(1u32..16384).prop_map(|h| h as f32), 1.0f32..16384.0];
    (prop_oneof![0.001f32..3.1, Just(3.1f32)], height).boxed()
}

/// `2 tan(fov / 2) / H` in f64: the height of one pixel on the image plane at distance 1.
pub(crate) fn pixel_height(fov: f32, height: f32) -> f64 {
    2.0 * (0.5 * f64::from(fov)).tan() / f64::from(height)
}

/// The angle between the central ray and the ray through the point one pixel above it on the
/// image plane at distance 1.
pub(crate) fn pixel_angle(fov: f32, height: f32) -> f64 {
    angle_between(DVec3::NEG_Z, DVec3::new(0.0, pixel_height(fov, height), -1.0))
}
