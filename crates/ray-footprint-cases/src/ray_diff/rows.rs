//! Degenerate rows and row arguments that several `ray_diff` records share (the re-intersection
//! rows also serve `ray_diff_f64`).

use super::OffsetArgs;
use crate::degenerate::{same, value, Row};
use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_diff::{GBufferSample, RayDiff};

/// A pinhole camera of `size` pixels and field of view `fov` at pixel 0, looking down -Z with
/// right X and up Y.
pub(super) fn centre_camera(size: Vec2, fov: f32) -> super::Camera {
    (Vec2::ZERO, size, fov, Vec3::X, Vec3::Y, Vec3::Z)
}

/// A differential whose only non-zero part is `d_origin_dx`.
pub(super) fn zero_diff_dx(d_origin_dx: Vec3) -> RayDiff {
    RayDiff::new(d_origin_dx, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)
}

/// A differential whose only non-zero part is `d_direction_dx`.
pub(super) fn direction_dx(d_direction_dx: Vec3) -> RayDiff {
    RayDiff::new(Vec3::ZERO, Vec3::ZERO, d_direction_dx, Vec3::ZERO)
}

/// A G-buffer sample at `distance` straight down -Z onto a plane facing +Z.
pub(super) fn sample_at(distance: f32) -> GBufferSample {
    GBufferSample {
        eye_direction: -Vec3::Z,
        distance,
        normal: Vec3::Z,
    }
}

/// The rows of the functions of a pixel, the viewport size and the inverse view and projection
/// matrices (`eye_ray_direction_from_matrices`, `eye_ray_diff_from_matrices`, `pixel_directions`):
/// a zero inverse projection gives `zero`, described by `zero_output`.
pub(super) fn matrix_rows(
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

/// `(1, 0, 0) - hit` for the hit of [`collapsed_offset_args`]: what a zero-area triangle gives.
pub(crate) const OFFSET: [f32; 3] = [0.75, -0.25, -0.5];

/// Re-intersection arguments with a triangle collapsed to one point and hit `(0.25, 0.25, 0.5)`.
fn collapsed_offset_args() -> OffsetArgs {
    let point = Vec3::new(0.0, 0.0, -5.0);
    (
        Mat4::IDENTITY,
        Vec3::ZERO,
        point,
        point,
        point,
        Vec3::X * 0.01 - Vec3::Z,
        Vec3::Y * 0.01 - Vec3::Z,
        Vec3::new(0.25, 0.25, 0.5),
    )
}

/// Re-intersection arguments with the triangle `(0, 0, -5)`, `(1, 0, -5)`, `(0, 1, -5)` seen from
/// the origin, hit `(0.25, 0.25, 0.5)` and the given neighbour directions.
fn plane_offset_args(direction_x: Vec3, direction_y: Vec3) -> OffsetArgs {
    let p0 = Vec3::new(0.0, 0.0, -5.0);
    (
        Mat4::IDENTITY,
        Vec3::ZERO,
        p0,
        p0 + Vec3::X,
        p0 + Vec3::Y,
        direction_x,
        direction_y,
        Vec3::new(0.25, 0.25, 0.5),
    )
}

/// The rows of `barycentric_offsets` and `barycentric_deltas`, f32 and f64: a triangle collapsed to
/// a point, and zero neighbour directions, give `collapsed`; a right neighbour ray parallel to the
/// plane gives the clamp, `parallel`. Each described by its `_output`.
pub(crate) fn reintersection_rows(
    collapsed_output: &'static str,
    collapsed: Vec<f32>,
    parallel_output: &'static str,
    parallel: Vec<f32>,
) -> Vec<Row<OffsetArgs>> {
    vec![
        value(
            "zero-area triangle (one point)",
            collapsed_output,
            collapsed_offset_args(),
            collapsed.clone(),
        ),
        value(
            "right neighbour ray parallel to the plane, lower one through p0",
            parallel_output,
            plane_offset_args(Vec3::X, Vec3::NEG_Z),
            parallel,
        ),
        value(
            "zero neighbour directions",
            collapsed_output,
            plane_offset_args(Vec3::ZERO, Vec3::ZERO),
            collapsed,
        ),
    ]
}

/// [`reintersection_rows`] of `barycentric_offsets`: `(1, 0, 0) - hit` both ways when collapsed.
pub(crate) fn offset_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
    reintersection_rows(
        "(1, 0, 0) - hit, both ways",
        [OFFSET; 2].concat(),
        parallel_output,
        parallel,
    )
}

/// [`reintersection_rows`] of `barycentric_deltas`: `2 |(1, 0, 0) - hit|` when collapsed.
pub(crate) fn delta_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
    reintersection_rows(
        "2 |(1, 0, 0) - hit|",
        OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
        parallel_output,
        parallel,
    )
}

/// The arguments of `intersect_triangle_plane` (f32 and f64): ray origin, direction, three vertices.
type PlaneArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// The rows of `intersect_triangle_plane` in f32 and f64: a ray parallel to the plane gives the
/// barycentrics clamped to `+-max`, described by `parallel_output`.
pub(crate) fn plane_intersection_rows(parallel_output: &'static str, max: f32) -> Vec<Row<PlaneArgs>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    vec![
        value(
            "ray parallel to the plane",
            parallel_output,
            (z, x, Vec3::ZERO, x, y),
            vec![max, -max, 0.0],
        ),
        value(
            "zero-area triangle (one point)",
            "(1, 0, 0)",
            (z, -z, x, x, x),
            vec![1.0, 0.0, 0.0],
        ),
        value(
            "zero direction",
            "(1, 0, 0): every cross product with d is 0",
            (z, Vec3::ZERO, Vec3::ZERO, x, y),
            vec![1.0, 0.0, 0.0],
        ),
        value(
            "plane behind the origin",
            "the hit behind it: (0.25, 0.25, 0.5)",
            (Vec3::new(0.25, 0.5, -1.0), -z, Vec3::ZERO, x, y),
            vec![0.25, 0.25, 0.5],
        ),
    ]
}
