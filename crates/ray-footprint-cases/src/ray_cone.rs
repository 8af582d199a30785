//! The records of the ray-cone module, one per function, in the module's order, by section.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. Bounds that several records
//! share are in the `bound` submodule; refraction and roughness, which chain dozens of operations,
//! take the width of an interval enclosure (the `enclosure` submodule); the cases only these
//! records use are in `strategy`; the independent references in `reference`.
//!
//! Each section file lists its own records (its `records()`, in the module's order) and is
//! re-exported whole, so a new function's record is an edit of its section file alone.

mod bound;
mod camera;
mod enclosure;
mod lod;
mod material;
mod propagation;
mod reference;
mod shape;
mod strategy;

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::RayCone;
use ray_footprint::shaders::Module;

pub use bound::{area_corners, curvature_spread_angle_error, triangle_curvature_error};
pub use camera::*;
pub use lod::*;
pub use material::*;
pub use propagation::*;
pub use shape::*;

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
pub type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// Arguments of `rf_pinhole_ray_cone_for_ray`: pixel spread angle, direction, view axis.
pub type PinholeRayConeForRayArgs = (f32, Vec3, Vec3);

/// The module of these records.
const MODULE: Module = Module::RayCone;

/// The module's records, section by section in the module's order.
pub(crate) fn records() -> Vec<Box<dyn crate::Function>> {
    [
        camera::records(),
        propagation::records(),
        lod::records(),
        material::records(),
    ]
    .into_iter()
    .flatten()
    .collect()
}
