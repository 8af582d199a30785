//! The records of the ray-cone module, one per function, in the module's order, by section.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. Bounds that several records
//! share are in the `bound` submodule; refraction and roughness, which chain dozens of operations,
//! take the width of an interval enclosure (the `enclosure` submodule); the cases only these
//! records use are in `strategy`.

mod bound;
mod camera;
mod enclosure;
mod lod;
mod material;
mod propagation;
mod strategy;

use crate::record::{Function, Record};
use crate::special::Perturb;
use glam::{Vec2, Vec3};
use proptest::strategy::BoxedStrategy;
use ray_footprint::ray_cone::RayCone;
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

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

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
pub type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// Arguments of `rf_pinhole_ray_cone_for_ray`: pixel spread angle, direction, view axis.
pub type PinholeRayConeForRayArgs = (f32, Vec3, Vec3);

/// The record of `function` of this module.
fn record<A: Args + Perturb, R: Value>(
    function: &'static str,
    mirror: fn(A) -> R,
    cases: fn() -> BoxedStrategy<A>,
) -> Record<A, R> {
    Record::new(Module::RayCone, function, mirror, cases)
}

/// Every function's record, in the module's order.
pub fn records() -> Vec<Box<dyn Function>> {
    vec![
        Box::new(pack_ray_cone()),
        Box::new(unpack_ray_cone()),
        Box::new(pixel_spread_angle()),
        Box::new(pixel_spread_angle_small()),
        Box::new(pixel_spread_angle_from_proj_inv()),
        Box::new(pinhole_ray_cone()),
        Box::new(pinhole_ray_cone_for_ray()),
        Box::new(orthographic_ray_cone()),
        Box::new(thin_lens_ray_cone()),
        Box::new(width_at()),
        Box::new(propagate()),
        Box::new(normal_spread_angle()),
        Box::new(normal_spread_angle_small()),
        Box::new(curvature_sign()),
        Box::new(surface_spread_angle()),
        Box::new(edge_curvature()),
        Box::new(triangle_curvature()),
        Box::new(curvature_spread_angle()),
        Box::new(world_footprint()),
        Box::new(triangle_world_area2()),
        Box::new(triangle_uv_area2()),
        Box::new(texel_density()),
        Box::new(triangle_base_lod()),
        Box::new(texture_lod()),
        Box::new(texture_gradient()),
        Box::new(environment_lod()),
        Box::new(refract_ray_cone()),
        Box::new(roughness_spread_angle()),
    ]
}
