//! The records of the ray-cone module, one per function, in the module's order, by section.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. Bounds that several records
//! share are in the `bound` submodule; refraction and roughness, which chain dozens of operations,
//! take the width of an interval enclosure (the `enclosure` submodule); the cases only these
//! records use are in `strategy`; the independent references in `reference`.

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
pub use camera::{
    orthographic_ray_cone, pack_ray_cone, pinhole_ray_cone, pinhole_ray_cone_for_ray, pixel_spread_angle,
    pixel_spread_angle_from_proj_inv, pixel_spread_angle_small, thin_lens_ray_cone, unpack_ray_cone,
};
pub use lod::{
    environment_lod, texel_density, texture_gradient, texture_lod, triangle_base_lod, triangle_uv_area2,
    triangle_world_area2, world_footprint,
};
pub use material::{refract_ray_cone, roughness_spread_angle};
pub use propagation::{
    curvature_sign, curvature_spread_angle, edge_curvature, normal_spread_angle, normal_spread_angle_small,
    propagate, surface_spread_angle, triangle_curvature, width_at,
};
pub use shape::{
    hit_curvature_error, normal_curvature, triangle_shape_operator, NormalCurvatureArgs, ShapeOperatorArgs,
};

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
pub type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// Arguments of `rf_pinhole_ray_cone_for_ray`: pixel spread angle, direction, view axis.
pub type PinholeRayConeForRayArgs = (f32, Vec3, Vec3);

/// The module of these records.
const MODULE: Module = Module::RayCone;
