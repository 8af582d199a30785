//! The records of the ray_diff module, one per function, in the module's order, one file per
//! section of the module.
//!
//! Every tolerance is the width of an enclosure: the record re-evaluates its function in interval
//! arithmetic on the same inputs, widening after each operation by the rounding error that Vulkan's
//! precision rules allow the device (and that the mirror makes), so both results lie inside. The
//! re-evaluations (one per shader function, in the module's order of operations) are in the
//! `enclosure` submodule, the case strategies in `strategy`, the degenerate rows several records
//! share in `rows`, the independent references in `reference`.
//!
//! Each section file lists its own records (its `records()`, in the module's order) and is
//! re-exported whole, so a new function's record is an edit of its section file alone.

mod camera;
mod cones;
mod derivatives;
pub mod enclosure;
mod gbuffer;
mod mapping;
pub(crate) mod reference;
mod reflection;
mod reintersection;
mod rows;
mod strategy;
mod transfer;

use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_diff::{GBufferSample, RayDiff};
use ray_footprint::shaders::Module;

pub use camera::*;
pub use cones::*;
pub use derivatives::*;
pub use enclosure::{direction_well_conditioned, WELL_CONDITIONED};
pub use gbuffer::*;
pub use mapping::*;
pub use reflection::*;
pub use reintersection::*;
pub(crate) use rows::{delta_rows, offset_rows, plane_intersection_rows, OFFSET};
pub(crate) use strategy::offset_args;
pub use transfer::*;

/// The arguments of the pinhole camera functions: pixel, image size, fov_y, right, up, view.
pub type Camera = (Vec2, Vec2, f32, Vec3, Vec3, Vec3);

/// The arguments of the matrix camera functions: pixel, image size, view_inv, proj_inv.
pub type Matrices = (Vec2, Vec2, Mat4, Mat4);

/// The arguments of `barycentric_derivatives`: differential, direction, t, the triangle.
pub type BarycentricArgs = (RayDiff, Vec3, f32, Vec3, Vec3, Vec3);

/// The arguments of the re-intersection functions (here and in the f64 module).
pub type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `gbuffer_ray_diff`: centre, right, left, below, above, depth epsilon.
pub type GBufferArgs = (
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    f32,
);

/// The arguments of `anisotropic_cone_gradients`: width, direction, the triangle, its UVs.
pub type ConeGradientArgs = (f32, Vec3, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

/// The module of these records.
const MODULE: Module = Module::RayDiff;

/// The module's records, section by section in the module's order.
pub(crate) fn records() -> Vec<Box<dyn crate::Function>> {
    [
        camera::records(),
        transfer::records(),
        derivatives::records(),
        reflection::records(),
        gbuffer::records(),
        mapping::records(),
        reintersection::records(),
        cones::records(),
    ]
    .into_iter()
    .flatten()
    .collect()
}
