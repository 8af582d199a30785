//! What the camera functions share: the matrix camera's arguments; the pixels, cameras and
//! matrices they draw and the rows of the matrix camera; the steps of their enclosures (the
//! pixel's NDC, the image extent, the matrix camera's direction); and for their references, the
//! pinhole and matrix cameras they draw, the matrix camera's exact ray and the step of their
//! central differences.

use crate::degenerate::{same, value, Row};
use crate::exact::unit;
use crate::ray_diff::pinhole::Camera;
use crate::ray_diff::strategy::rotation;
use crate::strategy::{fov_y, image_size, perspective_proj_inv, vec2_of, vec3};
use glam::{DMat3, DQuat, DVec2, DVec3, DVec4, Mat4, Quat, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{DIFF_MAX_FOV_Y, DIFF_MIN_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::interval::{mat_vec, Interval, Interval2, Interval3, IntervalVec, F32};
use shader_proptest::one_of;

/// The arguments of the matrix camera functions: pixel, image size, view_inv, proj_inv.
pub type Matrices = (Vec2, Vec2, Mat4, Mat4);

/// A pixel inside an image (or, sometimes, outside it) and the image size (from [`image_size`]).
pub(crate) fn pixel_and_size() -> BoxedStrategy<(Vec2, Vec2)> {
    (
        image_size(),
        vec2_of(uniform(0.0, 1.0), uniform(0.0, 1.0)),
        any::<bool>(),
    )
        .prop_map(|(size, fraction, outside)| {
            let pixel = if outside {
                fraction * 40000.0 - 20000.0
            } else {
                (fraction * size.max(Vec2::ONE)).floor()
            };
            (pixel, size)
        })
        .boxed()
}

/// A camera basis: right, up and view (towards the eye), orthonormal up to rounding.
fn camera_basis() -> BoxedStrategy<(Vec3, Vec3, Vec3)> {
    rotation()
        .prop_map(|q| (q * Vec3::X, q * Vec3::Y, q * Vec3::Z))
        .boxed()
}

/// A rigid transform with a translation from [`vec3`] (a camera-to-world matrix).
fn rigid() -> BoxedStrategy<Mat4> {
    (rotation(), vec3())
        .prop_map(|(q, t)| Mat4::from_rotation_translation(q, t))
        .boxed()
}

/// An inverse projection matrix: perspective (OpenGL or Vulkan, y-flipped), or arbitrary with
/// moderate entries.
fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary =
        prop::array::uniform16(uniform(-10.0, 10.0)).prop_map(|cols| Mat4::from_cols_array(&cols));
    one_of![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// A pinhole camera: a pixel and the image size, a field of view, a camera basis.
pub(crate) fn camera() -> BoxedStrategy<Camera> {
    (pixel_and_size(), fov_y(), camera_basis())
        .prop_map(|((pixel, size), fov, (r, u, v))| (pixel, size, fov, r, u, v))
        .boxed()
}

/// A matrix camera: a pixel and the image size, a camera-to-world matrix, an inverse projection.
pub(crate) fn matrices() -> BoxedStrategy<Matrices> {
    (pixel_and_size(), rigid(), proj_inv())
        .prop_map(|((pixel, size), view_inv, proj_inv)| (pixel, size, view_inv, proj_inv))
        .boxed()
}

/// A pinhole camera of `size` pixels and field of view `fov` at pixel 0, looking down -Z with
/// right X and up Y.
pub(crate) fn centre_camera(size: Vec2, fov: f32) -> Camera {
    (Vec2::ZERO, size, fov, Vec3::X, Vec3::Y, Vec3::Z)
}

/// The rows of the functions of a pixel, the viewport size and the inverse view and projection
/// matrices (`eye_ray_direction_from_matrices`, `eye_ray_diff_from_matrices`, `pixel_directions`):
/// a zero inverse projection gives `zero`, described by `zero_output`.
pub(crate) fn matrix_rows(
    proj_inv: Mat4,
    zero_output: &'static str,
    zero: Vec<f32>,
) -> Vec<Row<(Vec2, Vec2, Mat4, Mat4)>> {
    let (centre, size) = (Vec2::ZERO, Vec2::splat(64.0));
    vec![
        same(
            "zero viewport (0 x 0)",
            "as a 1 x 1 image",
            (centre, Vec2::ZERO, Mat4::IDENTITY, proj_inv),
            (centre, Vec2::ONE, Mat4::IDENTITY, proj_inv),
        ),
        value(
            "zero inverse projection",
            zero_output,
            (centre, size, Mat4::IDENTITY, Mat4::ZERO),
            zero,
        ),
        same(
            "inverse view with a translation (5, -6, 7)",
            "as without: directions ignore it (w = 0)",
            (
                centre,
                size,
                Mat4::from_translation(Vec3::new(5.0, -6.0, 7.0)),
                proj_inv,
            ),
            (centre, size, Mat4::IDENTITY, proj_inv),
        ),
    ]
}

pub(crate) fn zero3() -> Interval3 {
    IntervalVec([Interval::c(0.0); 3])
}

pub(crate) fn eye_ray_extent(image_size: Vec2, fov_y: f32) -> Interval2 {
    let size = image_size.max(Vec2::ONE);
    let f = Interval::tan_exact(0.5 * fov_y.clamp(0.0, DIFF_MAX_FOV_Y));
    IntervalVec([Interval::exact(size.x) / Interval::exact(size.y) * f, f])
}

pub(crate) fn pixel_ndc(pixel: Vec2, image_size: Vec2) -> Interval2 {
    let size = image_size.max(Vec2::ONE);
    IntervalVec(std::array::from_fn(|i| {
        (Interval::exact(pixel[i]) + Interval::c(0.5)) / Interval::exact(size[i]) * Interval::c(2.0)
            - Interval::c(1.0)
    }))
}

fn safe_normalize(v: Interval3) -> Interval3 {
    v / v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE)).sqrt()
}

pub(crate) fn matrix_ray_direction(ndc: Interval2, view_inv: Mat4, proj_inv: Mat4) -> Interval3 {
    let far_point = mat_vec(
        proj_inv,
        IntervalVec([ndc.0[0], ndc.0[1], Interval::c(1.0)]),
        Interval::c(1.0),
        F32,
    );
    mat_vec(view_inv, safe_normalize(far_point), Interval::c(0.0), F32)
}

/// A pixel of an image of 1 to 4096 pixels a side.
fn pixel_of_an_image() -> BoxedStrategy<(Vec2, Vec2)> {
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
fn rounded_rotation() -> BoxedStrategy<Quat> {
    (unit(), 0.0f64..6.3)
        .prop_map(|(axis, angle)| DQuat::from_axis_angle(axis, angle).as_quat())
        .boxed()
}

/// The step, in pixels along `axis`, of the central differences over the pixel: `1e-4` in NDC
/// (`5e-5` of the image's side). The differences' error estimate `|D(h) - D(2h)|` holds only where
/// `h` is small against the scale on which the direction turns, which is NDC, not pixels: a fixed
/// step of a quarter pixel spans a quarter of an image 1 pixel wide. The rounding this step lets
/// through, `64 eps * 10 / h`, stays below `3e-9` for the smallest image (1 pixel).
pub(crate) fn pixel_step(axis: DVec2, size: Vec2) -> f64 {
    5.0e-5 * axis.dot(size.as_dvec2())
}

/// A pinhole camera: pixel, image size, a field of view in `[0.05, 3]`, an orthonormal basis.
pub(crate) fn pinhole() -> BoxedStrategy<Camera> {
    (pixel_of_an_image(), 0.05f32..3.0, rounded_rotation())
        .prop_map(|((pixel, size), fov, q)| (pixel, size, fov, q * Vec3::X, q * Vec3::Y, q * Vec3::Z))
        .boxed()
}

/// A pixel, a rigid camera-to-world matrix and the f32 inverse of an f32 perspective projection
/// (OpenGL's, or Vulkan's with y down), as a renderer computes them.
pub(crate) fn matrix_camera() -> BoxedStrategy<Matrices> {
    (
        pixel_of_an_image(),
        (
            rounded_rotation(),
            (-100.0f32..100.0, -100.0f32..100.0, -100.0f32..100.0),
        ),
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
pub(crate) fn matrix_ray(view_inv: Mat4, proj_inv: Mat4, ndc: DVec2) -> (DVec3, f64) {
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
pub(crate) fn ndc(at: DVec2, size: Vec2) -> DVec2 {
    (at + 0.5) / size.as_dvec2() * 2.0 - 1.0
}
