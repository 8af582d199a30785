//! One record per public function of ray-footprint, and the runners that iterate the records.
//!
//! A [`Record`] declares once everything the verification of one function needs: its Rust mirror,
//! the strategy of its agreement cases, its tolerance (a bound derived from Vulkan's precision rules
//! or an interval enclosure), its documented degenerate inputs, and how the fuzzer draws its
//! arguments and what it promises. [`records`] lists every record in module order, and
//! [`order::check_order`] holds that list to the modules' public functions. The runners iterate it:
//!
//! - [`agreement::run_all_checks`]: the agreement checks in every language on one device (the
//!   lab's `verify` and its GPU tests), and each record's special-value check ([`special`]);
//! - [`degenerate`]: the degenerate-input table, rendered into the root crate's
//!   `src/degenerate.md` and run on the CPU and the GPU;
//! - [`fuzzing`]: the cargo-fuzz targets and the replay of their corpora;
//! - [`reference`](mod@reference): each function against independent references (exact geometry, f64 finite
//!   differences, closed forms computed another way, identities, peer originals), and the table of
//!   the root crate's `src/proven.md`.
//!
//! Not published: the product (`ray-footprint`) is the shader modules and the Rust mirror.

pub mod agreement;
pub mod degenerate;
pub mod exact;
pub mod fuzzing;
pub mod order;
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
mod record;
pub mod reference;
pub mod special;
pub mod strategy;
pub mod wireframe;

pub use record::{Function, IllConditioned, Promises, Record};

use ray_footprint::shaders::Module;
use std::sync::OnceLock;

/// `every_record![module: function, ...; ...]`: the records the functions of the modules make,
/// boxed, in the order given.
macro_rules! every_record {
    ($($module:ident: $($function:ident),+;)+) => {
        vec![$($(Box::new($module::$function()) as Box<dyn Function>,)+)+]
    };
}

/// Every record, in module order (built once).
pub fn records() -> &'static [Box<dyn Function>] {
    static RECORDS: OnceLock<Vec<Box<dyn Function>>> = OnceLock::new();
    RECORDS.get_or_init(|| {
        every_record![
            ray_cone: pack_ray_cone, unpack_ray_cone, pixel_spread_angle, pixel_spread_angle_small,
                pixel_spread_angle_from_proj_inv, pinhole_ray_cone, pinhole_ray_cone_for_ray,
                orthographic_ray_cone, thin_lens_ray_cone, width_at, propagate, normal_spread_angle,
                normal_spread_angle_small, curvature_sign, surface_spread_angle, edge_curvature,
                triangle_curvature, triangle_shape_operator, normal_curvature, curvature_spread_angle, world_footprint, triangle_world_area2,
                triangle_uv_area2, texel_density, triangle_base_lod, texture_lod, texture_gradient,
                environment_lod, refract_ray_cone, roughness_spread_angle;
            ray_diff: eye_ray_direction, normalized_derivative, eye_ray_diff,
                eye_ray_direction_from_matrices, eye_ray_diff_from_matrices, pixel_directions, transfer,
                barycentric_derivatives, barycentric_w_derivatives, texture_derivatives, texel_derivatives,
                secondary_origin_derivatives, lod_isotropic, lod_box, sample_grad_gradients,
                normal_derivatives, reflect_ray_diff, refract_ray_diff, gbuffer_ray_diff,
                tangent_plane_offsets, planar_mapping_gradients, triplanar_weights, triplanar_gradients,
                intersect_triangle_plane, barycentric_offsets, barycentric_deltas,
                uv_gradients_from_offsets, cone_barycentric_deltas, anisotropic_cone_axes,
                anisotropic_cone_gradients, ray_diff_from_cone, cone_from_ray_diff;
            ray_diff_f64: intersect_triangle_plane_f64, barycentric_offsets_f64, barycentric_deltas_f64;
            wireframe: unpack_wireframe_settings, edge_position, edge_thickness, stipple, edge_ramp,
                line_width, process_wireframe;
        ]
    })
}

/// The records of `module`, in the module's order.
pub fn module_records(module: Module) -> impl Iterator<Item = &'static dyn Function> {
    records()
        .iter()
        .filter(move |record| record.module() == module)
        .map(AsRef::as_ref)
}
