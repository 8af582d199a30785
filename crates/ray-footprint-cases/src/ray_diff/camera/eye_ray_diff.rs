//! The proof of [`eye_ray_diff`](ray_footprint::ray_diff::eye_ray_diff): its record, where it is
//! checked, its enclosure and its reference.

use crate::degenerate::{parts, same, value};
use crate::exact::derivative;
use crate::ray_diff::camera::shared::{camera, centre_camera, eye_ray_extent, pinhole, pixel_step, zero3};
use crate::ray_diff::camera::{eye_ray_direction, normalized_derivative};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::pinhole::{image_plane_point, Camera};
use crate::ray_diff::reference::{components, listed, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use glam::{DVec2, DVec3, Vec2};
use ray_footprint::ray_diff::{self as rd, RayDiff, DIFF_MAX_FOV_Y};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};
use shader_proptest::{Args, Value};

/// Narrowest field of view the eye-ray differential checks use: below it Vulkan's allowance for
/// `tan` (2^-11 absolute, inherited from `sin / cos`) exceeds 2% of `tan(fov / 2)`, and a camera
/// whose field of view is clamped to 0 has no differential to compare; those cameras are checked
/// separately (the degenerate table, the edge-case suite).
const MIN_DIFFERENTIAL_FOV: f32 = 0.05;

/// Why a camera is left out of the eye-ray differential checks ([`has_a_view`]).
const NARROW_VIEW: &str = "a field of view below MIN_DIFFERENTIAL_FOV (0.05), clamped to 0 or \
     so narrow that Vulkan's tan allowance exceeds 2% of tan(fov_y / 2)";

/// Whether a camera's field of view is at least [`MIN_DIFFERENTIAL_FOV`].
fn has_a_view(&(_, _, fov, ..): &Camera) -> bool {
    fov >= MIN_DIFFERENTIAL_FOV
}

/// The record of `rf_eye_ray_diff`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayDiff,
        "eye_ray_diff",
        |(pixel, size, fov, r, u, v)| rd::eye_ray_diff(pixel, size, fov, r, u, v),
        camera,
    )
    .conditioned(NARROW_VIEW, has_a_view)
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the camera's axes turned: the differential turned with them",
        |&(pixel, size, fov, right, up, view): &(Vec2, Vec2, f32, Vec3, Vec3, Vec3), r| {
            (pixel, size, fov, r * right, r * up, r * view)
        },
        |diff: RayDiff, r| turned(diff, r.transpose()),
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.angle(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        same(
            "zero viewport (0 x 0)",
            "as a 1 x 1 image",
            centre_camera(Vec2::ZERO, 1.0),
            centre_camera(Vec2::ONE, 1.0),
        ),
        value(
            "zero field of view",
            "0",
            centre_camera(Vec2::splat(64.0), 0.0),
            parts(RayDiff::ZERO),
        ),
        same(
            "fov_y = 4 (wider than DIFF_MAX_FOV_Y)",
            "as fov_y = DIFF_MAX_FOV_Y (3.1)",
            centre_camera(Vec2::splat(64.0), 4.0),
            centre_camera(Vec2::splat(64.0), DIFF_MAX_FOV_Y),
        ),
    ])
}

/// The direction differentials of `eye_ray_diff` (its origin differentials are exactly 0).
pub fn eye_ray_direction_derivatives(camera: &Camera) -> (Interval3, Interval3) {
    let &(_, image_size, fov, right, up, _) = camera;
    let d = eye_ray_direction::enclosure(camera);
    let size = image_size.max(Vec2::ONE);
    let extent = eye_ray_extent(image_size, fov);
    let dd_dx = interval3(right) * (Interval::c(2.0) * extent.0[0] / Interval::exact(size.x));
    let dd_dy = interval3(up) * -(Interval::c(2.0) * extent.0[1] / Interval::exact(size.y));
    (
        normalized_derivative::enclosure(d, dd_dx),
        normalized_derivative::enclosure(d, dd_dy),
    )
}

/// `rf_eye_ray_diff` in interval arithmetic, in the same order of operations.
fn enclosure(camera: &Camera) -> Vec<Interval> {
    let (dd_dx, dd_dy) = eye_ray_direction_derivatives(camera);
    intervals::ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

/// The reference of `rf_eye_ray_diff`.
fn reference() -> Reference<Camera, RayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences, in pixels, of the unit direction through the pixel unprojected by the f64 inverse matrices (Igehy; RTG Eq. 8-11); the origin does not move",
        pinhole,
        |camera, eye_ray_diff| {
            let got = eye_ray_diff(*camera);
            let pixel = camera.0.as_dvec2();
            let along = |axis: DVec2| {
                let step = pixel_step(axis, camera.1);
                derivative(|h| image_plane_point(camera, pixel + axis * h).normalize(), step, 10.0)
            };
            let (dx, dy) = (along(DVec2::X), along(DVec2::Y));
            let expected = listed(&[DVec3::ZERO, DVec3::ZERO, dx.value, dy.value], 1);
            let bounds = widths(&enclosure(camera));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}
