//! References of the camera section: the pinhole's pixel unprojected through the f64 inverse of
//! its projection and view matrices, the matrix camera's ray as the intersection of two planes of
//! the f64-inverted projection, and their central differences.

use super::super::{enclosure, Camera, Matrices};
use super::{components, listed, widths};
use crate::exact::{derivative, log_uniform, unit, Derivative};
use crate::reference::{Kind, Reference};
use glam::dcamera::rh::proj::opengl;
use glam::{DMat3, DMat4, DQuat, DVec2, DVec3, DVec4, Mat4, Quat, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{NeighbourDirections, RayDiff};
use shader_proptest::interval::interval3;

/// A pixel of an image of 1 to 4096 pixels a side.
fn pixel_and_size() -> BoxedStrategy<(Vec2, Vec2)> {
    let side = || prop_oneof![(1u32..4096).prop_map(|n| n as f32), 1.0f32..4096.0];
    (side(), side(), 0.0f32..1.0, 0.0f32..1.0)
        .prop_map(|(w, h, x, y)| {
            let size = Vec2::new(w, h);
            (
                (Vec2::new(x, y) * size).floor().min(size - 1.0).max(Vec2::ZERO),
                size,
            )
        })
        .boxed()
}

/// A rotation in f32.
fn rotation() -> BoxedStrategy<Quat> {
    (unit(), 0.0f64..6.3)
        .prop_map(|(axis, angle)| DQuat::from_axis_angle(axis, angle).as_quat())
        .boxed()
}

/// The step, in pixels along `axis`, of the central differences over the pixel: `1e-4` in NDC
/// (`5e-5` of the image's side). The differences' error estimate `|D(h) - D(2h)|` holds only where
/// `h` is small against the scale on which the direction turns, which is NDC, not pixels: a fixed
/// step of a quarter pixel spans a quarter of an image 1 pixel wide. The rounding this step lets
/// through, `64 eps * 10 / h`, stays below `3e-9` for the smallest image (1 pixel).
fn pixel_step(axis: DVec2, size: Vec2) -> f64 {
    5.0e-5 * axis.dot(size.as_dvec2())
}

/// A pinhole camera: pixel, image size, a field of view in `[0.05, 3]`, an orthonormal basis.
fn pinhole() -> BoxedStrategy<Camera> {
    (pixel_and_size(), 0.05f32..3.0, rotation())
        .prop_map(|((pixel, size), fov, q)| (pixel, size, fov, q * Vec3::X, q * Vec3::Y, q * Vec3::Z))
        .boxed()
}

/// The point with camera-space `z = -1` on the ray through the continuous pixel position `at`:
/// the pixel's NDC (y up) unprojected through the f64 inverse of the OpenGL perspective matrix
/// times the view matrix (the inverse of the basis `right, up, view`; eye at the origin).
pub(super) fn image_plane_point(&(_, size, fov, right, up, view): &Camera, at: DVec2) -> DVec3 {
    let size = size.as_dvec2();
    let camera_to_world = DMat4::from_cols(
        right.as_dvec3().extend(0.0),
        up.as_dvec3().extend(0.0),
        view.as_dvec3().extend(0.0),
        DVec4::W,
    );
    let world_to_camera = camera_to_world.inverse();
    let projection = opengl::perspective(f64::from(fov), size.x / size.y, 1.0, 10.0);
    let unproject = (projection * world_to_camera).inverse();
    let ndc = (at + 0.5) / size * 2.0 - 1.0;
    let point = unproject * DVec4::new(ndc.x, -ndc.y, 0.0, 1.0);
    let point = point.truncate() / point.w;
    let depth = (world_to_camera * point.extend(1.0)).z;
    point * (-1.0 / depth)
}

/// `rf_eye_ray_direction`.
pub(in crate::ray_diff) fn eye_ray_direction() -> Reference<Camera, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "the pixel centre's NDC unprojected through the f64 inverse of the perspective matrix times the view matrix, scaled to the image plane at distance 1 (RTG Eq. 8-9)",
        pinhole,
        |camera, eye_ray_direction| {
            let got = eye_ray_direction(*camera);
            let expected = image_plane_point(camera, camera.0.as_dvec2());
            // The mirror's rounding (the enclosure); the f64 unprojection within 1e-12.
            let rounding = enclosure::eye_ray_direction(camera).components();
            let bounds = widths(&rounding);
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-12 * expected.length()))
        },
    )
}

/// `rf_normalized_derivative`.
pub(in crate::ray_diff) fn normalized_derivative() -> Reference<(Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of (v + h dv) / |v + h dv| at h = 0 (Igehy; RTG Eq. 10)",
        || (unit(), log_uniform(-2.0, 2.0), unit(), log_uniform(-4.0, 1.0)).boxed(),
        |&(v_direction, v_length, dv_direction, dv_length), normalized_derivative| {
            let (v, dv) = (
                (v_direction * v_length).as_vec3(),
                (dv_direction * dv_length).as_vec3(),
            );
            let got = normalized_derivative((v, dv));
            let (v64, dv64) = (v.as_dvec3(), dv.as_dvec3());
            let step = 1.0e-3 * v64.length() / dv64.length();
            let expected = derivative(|h| (v64 + dv64 * h).normalize(), step, 1.0);
            let bounds = widths(&enclosure::normalized_derivative(interval3(v), interval3(dv)).components());
            Some(components(got, &expected.value.to_array(), |i| {
                bounds[i] + expected.error
            }))
        },
    )
}

/// `rf_eye_ray_diff`.
pub(in crate::ray_diff) fn eye_ray_diff() -> Reference<Camera, RayDiff> {
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
            let bounds = widths(&enclosure::eye_ray_diff(camera));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}

/// A pixel, a rigid camera-to-world matrix and the f32 inverse of an f32 perspective projection
/// (OpenGL's, or Vulkan's with y down), as a renderer computes them.
fn matrix_camera() -> BoxedStrategy<Matrices> {
    (
        pixel_and_size(),
        (rotation(), (-100.0f32..100.0, -100.0f32..100.0, -100.0f32..100.0)),
        (0.05f32..3.0, 0.2f32..5.0, 0.01f32..10.0, any::<bool>()),
    )
        .prop_map(|((pixel, size), (q, (x, y, z)), (fov, aspect, near, vulkan))| {
            let view_inv = Mat4::from_rotation_translation(q, Vec3::new(x, y, z));
            let projection = if vulkan {
                glam::camera::rh::proj::vulkan::perspective(fov, aspect, near, near * 1000.0)
            } else {
                glam::camera::rh::proj::opengl::perspective(fov, aspect, near, near * 1000.0)
            };
            (pixel, size, view_inv, projection.inverse())
        })
        .boxed()
}

/// The unit world direction of the ray through NDC `ndc` of the camera `(view_inv, proj_inv)`,
/// and how far the projection's eye lies from the origin relative to the far point: with
/// `P = proj_inv^-1` inverted in f64 and its rows `r0, r1, r3`, the ray from the eye `e`
/// (`r0 . e = r1 . e = r3 . e = 0`, homogeneous) through NDC `(x, y)` is the intersection of the
/// planes `(r0 - x r3) . X = 0` and `(r1 - y r3) . X = 0`: its direction is their normals' cross
/// product, turned to the front (`r3 . d > 0`, positive w).
fn matrix_ray(view_inv: Mat4, proj_inv: Mat4, ndc: DVec2) -> (DVec3, f64) {
    let projection = proj_inv.as_dmat4().inverse();
    let row = |i: usize| projection.row(i);
    let (r0, r1, r3) = (row(0), row(1), row(3));
    let direction = (r0.truncate() - r3.truncate() * ndc.x).cross(r1.truncate() - r3.truncate() * ndc.y);
    let direction = direction * direction.dot(r3.truncate()).signum();
    let eye = DMat3::from_cols(r0.truncate(), r1.truncate(), r3.truncate())
        .transpose()
        .inverse()
        * -DVec3::new(r0.w, r1.w, r3.w);
    let far = proj_inv.as_dmat4() * DVec4::new(ndc.x, ndc.y, 1.0, 1.0);
    let far_point = far.truncate() / far.w;
    let rotation = DMat3::from_mat4(view_inv.as_dmat4());
    (
        (rotation * direction.normalize()),
        eye.length() / far_point.length(),
    )
}

/// The NDC of the continuous pixel position `at` in an image of `size` (RTG Eq. 8, `c = 2p - 1`).
fn ndc(at: DVec2, size: Vec2) -> DVec2 {
    (at + 0.5) / size.as_dvec2() * 2.0 - 1.0
}

/// `rf_eye_ray_direction_from_matrices`.
pub(in crate::ray_diff) fn eye_ray_direction_from_matrices() -> Reference<Matrices, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "the ray through the pixel as the intersection of two planes of the projection matrix inverted in f64 (rows r0 - x r3, r1 - y r3), from the projection's eye, rotated by view_inv",
        matrix_camera,
        |camera, eye_ray_direction_from_matrices| {
            let &(pixel, size, view_inv, proj_inv) = camera;
            let got = eye_ray_direction_from_matrices(*camera);
            let (expected, eye_offset) = matrix_ray(view_inv, proj_inv, ndc(pixel.as_dvec2(), size));
            // The mirror's rounding (the enclosure); the f64 inversion within 1e-12; the mirror
            // measures from the origin, the projection's eye lies within its rounding of it.
            let bounds = widths(&enclosure::eye_ray_direction_from_matrices(camera).components());
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-12 + eye_offset))
        },
    )
}

/// `rf_eye_ray_diff_from_matrices`.
pub(in crate::ray_diff) fn eye_ray_diff_from_matrices() -> Reference<Matrices, RayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences, in pixels, of the unit world direction of the ray through the pixel as the intersection of two planes of the f64-inverted projection (RTG Eq. 10 applied to the matrix camera)",
        matrix_camera,
        |camera, eye_ray_diff_from_matrices| {
            let &(pixel, size, view_inv, proj_inv) = camera;
            let got = eye_ray_diff_from_matrices(*camera);
            let along = |axis: DVec2| {
                derivative(
                    |h| matrix_ray(view_inv, proj_inv, ndc(pixel.as_dvec2() + axis * h, size)).0,
                    pixel_step(axis, size),
                    10.0,
                )
            };
            let (dx, dy): (Derivative<DVec3>, Derivative<DVec3>) = (along(DVec2::X), along(DVec2::Y));
            let expected = listed(&[DVec3::ZERO, DVec3::ZERO, dx.value, dy.value], 1);
            let bounds = widths(&enclosure::eye_ray_diff_from_matrices(camera));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error) + 1.0e-12))
        },
    )
}

/// `rf_pixel_directions`.
pub(in crate::ray_diff) fn pixel_directions() -> Reference<Matrices, NeighbourDirections> {
    Reference::new(
        Kind::ExactGeometry,
        "the rays through the right and the lower neighbour pixel's centres as intersections of two planes of the f64-inverted projection, rotated by view_inv",
        matrix_camera,
        |camera, pixel_directions| {
            let &(pixel, size, view_inv, proj_inv) = camera;
            let got = pixel_directions(*camera);
            let neighbour = |step: DVec2| matrix_ray(view_inv, proj_inv, ndc(pixel.as_dvec2() + step, size));
            let ((right, right_eye), (below, below_eye)) = (neighbour(DVec2::X), neighbour(DVec2::Y));
            let bounds = widths(&enclosure::pixel_directions(camera));
            let eye_offset = right_eye.max(below_eye);
            Some(components(got, &listed(&[right, below], 0), |i| bounds[i] + 1.0e-12 + eye_offset))
        },
    )
}
