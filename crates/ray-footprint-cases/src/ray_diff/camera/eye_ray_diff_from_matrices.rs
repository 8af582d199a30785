//! The proof of
//! [`eye_ray_diff_from_matrices`](ray_footprint::ray_diff::eye_ray_diff_from_matrices): its record,
//! its enclosure and its reference.

use crate::degenerate::{parts, vulkan_inverse_projection};
use crate::exact::{derivative, Derivative};
use crate::ray_diff::camera::normalized_derivative;
use crate::ray_diff::camera::shared::{
    matrices, matrix_camera, matrix_ray, matrix_rows, ndc, pixel_ndc, pixel_step, zero3, Matrices,
};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use glam::{DVec2, DVec3, Vec2, Vec4Swizzles};
use ray_footprint::ray_diff::{self as rd, RayDiff};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, mat_vec, Interval, IntervalVec, F32};

/// The record of `rf_eye_ray_diff_from_matrices`: the enclosure of every component.
pub fn record() -> Record<Matrices, RayDiff> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        Module::RayDiff,
        "eye_ray_diff_from_matrices",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::eye_ray_diff_from_matrices(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the camera turned (its inverse view matrix after a rotation): the differential turned with it",
        |&(pixel, size, view_inv, proj_inv): &(Vec2, Vec2, Mat4, Mat4), r| {
            (pixel, size, Mat4::from_mat3(r) * view_inv, proj_inv)
        },
        |diff: RayDiff, r| turned(diff, r.transpose()),
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(inverse_projection, "0", parts(RayDiff::ZERO)))
}

/// `rf_eye_ray_diff_from_matrices` in interval arithmetic, in the same order of operations.
fn enclosure(&(pixel, image_size, view_inv, proj_inv): &Matrices) -> Vec<Interval> {
    let size = image_size.max(Vec2::ONE);
    let ndc = pixel_ndc(pixel, image_size);
    let far_point = mat_vec(
        proj_inv,
        IntervalVec([ndc.0[0], ndc.0[1], Interval::c(1.0)]),
        Interval::c(1.0),
        F32,
    );
    let dfar_dx = interval3(proj_inv.x_axis.xyz()) * (Interval::c(2.0) / Interval::exact(size.x));
    let dfar_dy = interval3(proj_inv.y_axis.xyz()) * (Interval::c(2.0) / Interval::exact(size.y));
    let dd_dx = mat_vec(
        view_inv,
        normalized_derivative::enclosure(far_point, dfar_dx),
        Interval::c(0.0),
        F32,
    );
    let dd_dy = mat_vec(
        view_inv,
        normalized_derivative::enclosure(far_point, dfar_dy),
        Interval::c(0.0),
        F32,
    );
    intervals::ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

/// The reference of `rf_eye_ray_diff_from_matrices`.
fn reference() -> Reference<Matrices, RayDiff> {
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
            let bounds = widths(&enclosure(camera));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error) + 1.0e-12))
        },
    )
}
