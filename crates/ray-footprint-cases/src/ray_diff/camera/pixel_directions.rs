//! The proof of [`pixel_directions`](ray_footprint::ray_diff::pixel_directions): its record, its
//! enclosure and its reference.

use crate::degenerate::vulkan_inverse_projection;
use crate::ray_diff::camera::shared::{
    matrices, matrix_camera, matrix_ray, matrix_ray_direction, matrix_rows, ndc, pixel_ndc, Matrices,
};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use glam::DVec2;
use ray_footprint::ray_diff::{self as rd, NeighbourDirections};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{Interval, IntervalVec};

/// The record of `rf_pixel_directions`: the enclosure of both directions.
pub fn record() -> Record<Matrices, NeighbourDirections> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        Module::RayDiff,
        "pixel_directions",
        |(pixel, size, view_inv, inverse_projection)| {
            rd::pixel_directions(pixel, size, view_inv, inverse_projection)
        },
        matrices,
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the camera turned (its inverse view matrix after a rotation): both directions turned with it",
        |&(pixel, size, view_inv, proj_inv): &(Vec2, Vec2, Mat4, Mat4), r| {
            (pixel, size, Mat4::from_mat3(r) * view_inv, proj_inv)
        },
        |directions: NeighbourDirections, r| NeighbourDirections {
            right: r.transpose() * directions.right,
            below: r.transpose() * directions.below,
        },
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.rigid(), d.mat4()))
    .degenerate(matrix_rows(inverse_projection, "0", vec![0.0; 6]))
}

/// `rf_pixel_directions` in interval arithmetic, in the same order of operations.
fn enclosure(&(pixel, size, view_inv, proj_inv): &Matrices) -> Vec<Interval> {
    let ndc = pixel_ndc(pixel, size);
    let next = pixel_ndc(pixel + 1.0, size);
    let right = matrix_ray_direction(IntervalVec([next.0[0], ndc.0[1]]), view_inv, proj_inv);
    let below = matrix_ray_direction(IntervalVec([ndc.0[0], next.0[1]]), view_inv, proj_inv);
    intervals::derivatives3(right, below)
}

/// The reference of `rf_pixel_directions`.
fn reference() -> Reference<Matrices, NeighbourDirections> {
    Reference::new(
        Kind::ExactGeometry,
        "the rays through the right and the lower neighbour pixel's centres as intersections of two planes of the f64-inverted projection, rotated by view_inv",
        matrix_camera,
        |camera, pixel_directions| {
            let &(pixel, size, view_inv, proj_inv) = camera;
            let got = pixel_directions(*camera);
            let neighbour = |step: DVec2| matrix_ray(view_inv, proj_inv, ndc(pixel.as_dvec2() + step, size));
            let ((right, right_eye), (below, below_eye)) = (neighbour(DVec2::X), neighbour(DVec2::Y));
            let bounds = widths(&enclosure(camera));
            let eye_offset = right_eye.max(below_eye);
            Some(components(got, &listed(&[right, below], 0), |i| bounds[i] + 1.0e-12 + eye_offset))
        },
    )
}
