//! Records of `ray_diff`: Camera rays and their differentials (RTG Eq. 8-11; wireframe tutorial).

use super::enclosure;
use super::rows::{centre_camera, matrix_rows};
use super::strategy::{any_direction, camera, differential_vec3, has_a_view, matrices, NARROW_VIEW};
use super::{reference, Matrices, MODULE};
use crate::degenerate::{mirror, parts, same, value, vulkan_inverse_projection, NAN};
use crate::record::Record;
use crate::special::Perturb;
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, NeighbourDirections, RayDiff, DIFF_MAX_FOV_Y, DIFF_MIN_MAGNITUDE};
use shader_proptest::interval::interval3;
use shader_proptest::{Args, Value};

/// `rf_eye_ray_direction`.
pub fn eye_ray_direction() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "eye_ray_direction",
        |(pixel, size, fov, r, u, v)| rd::eye_ray_direction(pixel, size, fov, r, u, v),
        camera,
    )
    .enclosure(|a| enclosure::eye_ray_direction(a).components())
    .reference(reference::eye_ray_direction())
    .fuzz(|d| (d.vec2(), d.vec2(), d.angle(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero viewport (0 x 0)",
            "-view (a 1 x 1 image: the centre ray)",
            centre_camera(Vec2::ZERO, 1.0),
            vec![0.0, 0.0, -1.0],
        ),
        value(
            "zero field of view",
            "-view for every pixel",
            (Vec2::new(10.0, 5.0), Vec2::new(100.0, 50.0), 0.0, x, y, z),
            vec![0.0, 0.0, -1.0],
        ),
        mirror(
            "NaN in (fov_y)",
            "CPU: NaN",
            centre_camera(Vec2::splat(64.0), NAN),
            vec![NAN; 3],
        ),
    ])
}

/// `rf_normalized_derivative`.
pub fn normalized_derivative() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "normalized_derivative",
        |(v, dv)| rd::normalized_derivative(v, dv),
        || (any_direction(), differential_vec3()).boxed(),
    )
    .enclosure(|&(v, dv)| enclosure::normalized_derivative(interval3(v), interval3(dv)).components())
    .reference(reference::normalized_derivative())
    .fuzz(|d| (d.vec3(), d.vec3()))
    .degenerate(vec![
        value(
            "zero vector",
            "dv / sqrt(DIFF_MIN_MAGNITUDE)",
            (Vec3::ZERO, z),
            vec![0.0, 0.0, 1.0 / DIFF_MIN_MAGNITUDE.sqrt()],
        ),
        value(
            "dv parallel to v (v = (2, 0, 0), dv = (1, 0, 0))",
            "0: the length changes, the direction does not",
            (2.0 * x, x),
            vec![0.0; 3],
        ),
        value(
            "v of length 2, dv perpendicular",
            "dv / |v|",
            (2.0 * z, x),
            vec![0.5, 0.0, 0.0],
        ),
    ])
}

/// `rf_eye_ray_diff`.
pub fn eye_ray_diff() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "eye_ray_diff",
        |(pixel, size, fov, r, u, v)| rd::eye_ray_diff(pixel, size, fov, r, u, v),
        camera,
    )
    .conditioned(NARROW_VIEW, has_a_view)
    .enclosure(enclosure::eye_ray_diff)
    .reference(reference::eye_ray_diff())
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

/// `rf_eye_ray_direction_from_matrices`.
pub fn eye_ray_direction_from_matrices() -> Record<impl Args + Perturb, impl Value> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        MODULE,
        "eye_ray_direction_from_matrices",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::eye_ray_direction_from_matrices(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(|a| enclosure::eye_ray_direction_from_matrices(a).components())
    .reference(reference::eye_ray_direction_from_matrices())
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(
        inverse_projection,
        "0 (the zero vector is not normalized)",
        vec![0.0; 3],
    ))
}

/// `rf_eye_ray_diff_from_matrices`: the enclosure of every component.
pub fn eye_ray_diff_from_matrices() -> Record<Matrices, RayDiff> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        MODULE,
        "eye_ray_diff_from_matrices",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::eye_ray_diff_from_matrices(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(enclosure::eye_ray_diff_from_matrices)
    .reference(reference::eye_ray_diff_from_matrices())
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(inverse_projection, "0", parts(RayDiff::ZERO)))
}

/// `rf_pixel_directions`: the enclosure of both directions.
pub fn pixel_directions() -> Record<Matrices, NeighbourDirections> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        MODULE,
        "pixel_directions",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::pixel_directions(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(enclosure::pixel_directions)
    .reference(reference::pixel_directions())
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(inverse_projection, "0", vec![0.0; 6]))
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        eye_ray_direction,
        normalized_derivative,
        eye_ray_diff,
        eye_ray_direction_from_matrices,
        eye_ray_diff_from_matrices,
        pixel_directions
    ]
}
