//! The records of the ray_diff module, one per function, in the module's order, one file per
//! section of the module.
//!
//! Every tolerance is the width of an enclosure: the record re-evaluates its function in interval
//! arithmetic on the same inputs, widening after each operation by the rounding error that Vulkan's
//! precision rules allow the device (and that the mirror makes), so both results lie inside. The
//! re-evaluations (one per shader function, in the module's order of operations) are in the
//! `enclosure` submodule, the case strategies in `strategy`, the degenerate rows several records
//! share in `rows`.

mod camera;
mod cones;
mod derivatives;
mod enclosure;
mod gbuffer;
mod mapping;
mod reflection;
mod reintersection;
mod rows;
mod strategy;
mod transfer;

use crate::record::{Function, Record};
use crate::special::Perturb;
use glam::{Mat4, Vec2, Vec3};
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_diff::RayDiff;
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

pub use camera::{
    eye_ray_diff, eye_ray_diff_from_matrices, eye_ray_direction, eye_ray_direction_from_matrices,
    normalized_derivative, pixel_directions,
};
pub use cones::{
    anisotropic_cone_axes, anisotropic_cone_gradients, cone_barycentric_deltas, cone_from_ray_diff,
    ray_diff_from_cone,
};
pub use derivatives::{
    barycentric_derivatives, barycentric_w_derivatives, lod_box, lod_isotropic, sample_grad_gradients,
    secondary_origin_derivatives, texel_derivatives, texture_derivatives,
};
pub use enclosure::{
    b_eye_ray_direction_derivatives, b_reflected_direction, b_transferred_origin, direction_well_conditioned,
    WELL_CONDITIONED,
};
pub use gbuffer::{gbuffer_ray_diff, tangent_plane_offsets};
pub use mapping::{planar_mapping_gradients, triplanar_gradients, triplanar_weights};
pub use reflection::{normal_derivatives, reflect_ray_diff, refract_ray_diff};
pub use reintersection::{
    barycentric_deltas, barycentric_offsets, intersect_triangle_plane, uv_gradients_from_offsets,
};
pub(crate) use rows::{delta_rows, offset_rows, plane_intersection_rows, OFFSET};
pub(crate) use strategy::offset_args;
pub use transfer::transfer;

/// The arguments of the pinhole camera functions: pixel, image size, fov_y, right, up, view.
pub type Camera = (Vec2, Vec2, f32, Vec3, Vec3, Vec3);

/// The arguments of the matrix camera functions: pixel, image size, view_inv, proj_inv.
pub type Matrices = (Vec2, Vec2, Mat4, Mat4);

/// The arguments of `barycentric_derivatives`: differential, direction, t, the triangle.
pub type BarycentricArgs = (RayDiff, Vec3, f32, Vec3, Vec3, Vec3);

/// The arguments of the re-intersection functions (here and in the f64 module).
pub type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `anisotropic_cone_gradients`: width, direction, the triangle, its UVs.
pub type ConeGradientArgs = (f32, Vec3, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

/// The record of `function` of this module.
fn record<A: Args + Perturb, R: Value>(
    function: &'static str,
    mirror: fn(A) -> R,
    cases: fn() -> BoxedStrategy<A>,
) -> Record<A, R> {
    Record::new(Module::RayDiff, function, mirror, cases)
}

/// Every function's record, in the module's order.
pub fn records() -> Vec<Box<dyn Function>> {
    vec![
        Box::new(eye_ray_direction()),
        Box::new(normalized_derivative()),
        Box::new(eye_ray_diff()),
        Box::new(eye_ray_direction_from_matrices()),
        Box::new(eye_ray_diff_from_matrices()),
        Box::new(pixel_directions()),
        Box::new(transfer()),
        Box::new(barycentric_derivatives()),
        Box::new(barycentric_w_derivatives()),
        Box::new(texture_derivatives()),
        Box::new(texel_derivatives()),
        Box::new(secondary_origin_derivatives()),
        Box::new(lod_isotropic()),
        Box::new(lod_box()),
        Box::new(sample_grad_gradients()),
        Box::new(normal_derivatives()),
        Box::new(reflect_ray_diff()),
        Box::new(refract_ray_diff()),
        Box::new(gbuffer_ray_diff()),
        Box::new(tangent_plane_offsets()),
        Box::new(planar_mapping_gradients()),
        Box::new(triplanar_weights()),
        Box::new(triplanar_gradients()),
        Box::new(intersect_triangle_plane()),
        Box::new(barycentric_offsets()),
        Box::new(barycentric_deltas()),
        Box::new(uv_gradients_from_offsets()),
        Box::new(cone_barycentric_deltas()),
        Box::new(anisotropic_cone_axes()),
        Box::new(anisotropic_cone_gradients()),
        Box::new(ray_diff_from_cone()),
        Box::new(cone_from_ray_diff()),
    ]
}
