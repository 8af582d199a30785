//! The proof of
//! [`eye_ray_direction_from_matrices`](ray_footprint::ray_diff::eye_ray_direction_from_matrices):
//! its record, its enclosure and its reference.

use crate::degenerate::vulkan_inverse_projection;
use crate::ray_diff::camera::shared::{
    matrices, matrix_camera, matrix_ray, matrix_ray_direction, matrix_rows, ndc, pixel_ndc, Matrices,
};
use crate::ray_diff::changes::*;
use crate::ray_diff::reference::{components, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use glam::Vec3;
use ray_footprint::ray_diff as rd;
use ray_footprint::shaders::Module;
use shader_proptest::interval::Interval3;
use shader_proptest::{Args, Value};

/// The record of `rf_eye_ray_direction_from_matrices`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        Module::RayDiff,
        "eye_ray_direction_from_matrices",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::eye_ray_direction_from_matrices(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(|a| enclosure(a).components())
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the camera turned (its inverse view matrix after a rotation): the direction turned with it",
        |&(pixel, size, view_inv, proj_inv): &(Vec2, Vec2, Mat4, Mat4), r| {
            (pixel, size, Mat4::from_mat3(r) * view_inv, proj_inv)
        },
        |direction: Vec3, r| r.transpose() * direction,
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(
        inverse_projection,
        "0 (the zero vector is not normalized)",
        vec![0.0; 3],
    ))
}

/// `rf_eye_ray_direction_from_matrices` in interval arithmetic, in the same order of operations.
fn enclosure(&(pixel, size, view_inv, proj_inv): &Matrices) -> Interval3 {
    matrix_ray_direction(pixel_ndc(pixel, size), view_inv, proj_inv)
}

/// The reference of `rf_eye_ray_direction_from_matrices`.
fn reference() -> Reference<Matrices, Vec3> {
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
            let bounds = widths(&enclosure(camera).components());
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-12 + eye_offset))
        },
    )
}
