//! Agreement checks of the ray-cone module, one per function, in the module's order.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. Bounds that several checks
//! share are in the `bound` submodule; refraction and roughness, which chain dozens of operations,
//! take the width of an interval enclosure (the `enclosure` submodule); the cases only these
//! checks use are in `strategy`.

mod bound;
mod enclosure;
mod strategy;

use super::edge::Edge;
use super::strategy::{
    angle, distance, fov_y, image_size, magnitude, normal_and_direction, one_argument, pixels, scalar,
    small_vec3, triangle, uv_triangle, vec3,
};
use super::{enclosed, exact, per_component, registered_checks, Entry};
use bound::{
    clamped_cos, edge_curvature_error, tan_ratio_error, uv_area2_error, width_at_error, world_area2_error,
};
use enclosure::{b_refract_ray_cone, b_roughness_spread_angle, refraction_decided};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone, RefractedRayCone, MIN_MAGNITUDE};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{atan_error, dot_error, log2_error, ulps, ULP};
use shader_proptest::{Args, FunctionCheck, Value};
use strategy::{eta, off_the_plane, packed_ray_cone, proj_inv, ray_cone, triangle_with_uvs};

pub use bound::{area_corners, curvature_spread_angle_error, triangle_curvature_error};

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// `rf_pack_ray_cone`.
pub fn pack_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "pack_ray_cone",
        || one_argument(ray_cone()),
        |(cone,)| rc::pack_ray_cone(cone),
        // The rounding mode of packHalf2x16 is the implementation's: one f16 ULP (2^-10
        // relative, 2^-24 absolute for f16 subnormals).
        |_, _, expected| (expected.abs() / 1024.0).max(1.0 / 16_777_216.0),
    )
}

/// `rf_unpack_ray_cone`.
pub fn unpack_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    // f16 to f32 is exact.
    exact(
        "unpack_ray_cone",
        || one_argument(packed_ray_cone()),
        |(packed,)| rc::unpack_ray_cone(packed),
    )
}

/// `rf_pixel_spread_angle`.
pub fn pixel_spread_angle() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "pixel_spread_angle",
        || (fov_y(), pixels()).boxed(),
        |(fov, height)| rc::pixel_spread_angle(fov, height),
        // atan of the tan ratio: the ratio's error through atan, plus atan's 4096 ULP.
        |&(fov, height), _, _| {
            atan_error(
                rc::pixel_spread_angle_small(fov, height),
                tan_ratio_error(fov, height),
            )
        },
    )
}

/// `rf_pixel_spread_angle_small`.
pub fn pixel_spread_angle_small() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "pixel_spread_angle_small",
        || (fov_y(), pixels()).boxed(),
        |(fov, height)| rc::pixel_spread_angle_small(fov, height),
        // tan's error (inherited from sin / cos) scaled by 2 / H.
        |&(fov, height), _, _| tan_ratio_error(fov, height),
    )
}

/// `rf_pixel_spread_angle_from_proj_inv`.
pub fn pixel_spread_angle_from_proj_inv() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "pixel_spread_angle_from_proj_inv",
        || (proj_inv(), pixels()).boxed(),
        |(proj_inv, height)| rc::pixel_spread_angle_from_proj_inv(proj_inv, height),
        // The ratio 2|m|/H has one division (2.5 ULP) and the mirror's rounding; then atan.
        |&(proj_inv, height), _, _| {
            let ratio = 2.0 * proj_inv.y_axis.y.abs() / height.max(1.0);
            atan_error(ratio, ulps(3.5, ratio))
        },
    )
}

/// `rf_pinhole_ray_cone`.
pub fn pinhole_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    // No arithmetic.
    exact(
        "pinhole_ray_cone",
        || one_argument(angle()),
        |(spread,)| rc::pinhole_ray_cone(spread),
    )
}

/// Arguments of `rf_pinhole_ray_cone_for_ray`: pixel spread angle, direction, view axis.
pub type PinholeRayConeForRayArgs = (f32, Vec3, Vec3);

/// `rf_pinhole_ray_cone_for_ray` (also used by the ray-tracing pipeline's test).
pub fn pinhole_ray_cone_for_ray() -> FunctionCheck<PinholeRayConeForRayArgs, RayCone> {
    per_component(
        "pinhole_ray_cone_for_ray",
        // A view axis and a ray from on the axis to 90 degrees off it, or behind the camera.
        || {
            (angle(), normal_and_direction(), any::<bool>())
                .prop_map(|(spread, (normal, direction), behind)| {
                    (spread, direction, if behind { normal } else { -normal })
                })
                .boxed()
        },
        |(spread, direction, view_axis)| rc::pinhole_ray_cone_for_ray(spread, direction, view_axis),
        // Width: exact. Spread: the dot product's rounding, through the clamp (which cannot widen
        // it), times |spread|, and the product's rounding on the device and in the mirror.
        |&(spread, direction, view_axis), index, expected| {
            if index == 0 {
                0.0
            } else {
                spread.abs() * dot_error(direction, view_axis) + ulps(2.0, expected)
            }
        },
    )
}

/// `rf_orthographic_ray_cone`.
pub fn orthographic_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "orthographic_ray_cone",
        || (magnitude(), pixels()).boxed(),
        |(view_height, height)| rc::orthographic_ray_cone(view_height, height),
        // One division: 2.5 ULP on the device, 0.5 in the mirror.
        |_, _, expected| ulps(3.0, expected),
    )
}

/// `rf_thin_lens_ray_cone`.
pub fn thin_lens_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "thin_lens_ray_cone",
        || (angle(), magnitude(), scalar()).boxed(),
        |(spread, aperture, focus)| rc::thin_lens_ray_cone(spread, aperture, focus),
        // Width: a copy. Spread: a division (2.5 ULP + 0.5) then a subtraction (0.5 + 0.5 ULP
        // of the larger operand).
        |&(spread, aperture, focus), index, _| {
            let quotient = aperture / focus.max(MIN_MAGNITUDE);
            if index == 0 {
                0.0
            } else {
                ulps(4.0, spread.abs() + quotient.abs())
            }
        },
    )
}

/// `rf_width_at`.
pub fn width_at() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "width_at",
        || (ray_cone(), distance()).boxed(),
        |(cone, t)| rc::width_at(cone, t),
        |&(cone, t), _, _| width_at_error(cone, t),
    )
}

/// `rf_propagate`.
pub fn propagate() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "propagate",
        || (ray_cone(), distance(), angle()).boxed(),
        |(cone, t, beta)| rc::propagate(cone, t, beta),
        // Width as width_at; spread: one correctly rounded addition, identical.
        |&(cone, t, _), index, _| {
            if index == 0 {
                width_at_error(cone, t)
            } else {
                0.0
            }
        },
    )
}

/// `rf_normal_spread_angle`.
pub fn normal_spread_angle() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "normal_spread_angle",
        || (small_vec3(), small_vec3()).boxed(),
        |(dn_dx, dn_dy)| rc::normal_spread_angle(dn_dx, dn_dy),
        // sqrt of a 6-term sum (3 ULP of the sum -> 1.5 relative, sqrt ~4.5, mirror 1): 9 ULP
        // on the length, halved and propagated through atan, doubled; plus atan's 4096 ULP.
        |&(dn_dx, dn_dy), _, _| {
            let length = rc::normal_spread_angle_small(dn_dx, dn_dy);
            2.0 * atan_error(0.5 * length, ulps(9.0, 0.5 * length))
        },
    )
}

/// `rf_normal_spread_angle_small`.
pub fn normal_spread_angle_small() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "normal_spread_angle_small",
        || (small_vec3(), small_vec3()).boxed(),
        |(dn_dx, dn_dy)| rc::normal_spread_angle_small(dn_dx, dn_dy),
        // As above, without atan: 9 ULP.
        |_, _, expected| ulps(9.0, expected),
    )
}

/// `rf_curvature_sign`.
pub fn curvature_sign() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "curvature_sign",
        || (small_vec3(), small_vec3(), small_vec3(), small_vec3()).boxed(),
        |(dp_dx, dp_dy, dn_dx, dn_dy)| rc::curvature_sign(dp_dx, dp_dy, dn_dx, dn_dy),
        // Exact, unless the sum is within its rounding error (6 terms, 8 ULP) of zero: then
        // either sign is right.
        |&(dp_dx, dp_dy, dn_dx, dn_dy), _, _| {
            let sum = dp_dx.dot(dn_dx) + dp_dy.dot(dn_dy);
            let terms = (dp_dx * dn_dx).abs().element_sum() + (dp_dy * dn_dy).abs().element_sum();
            if sum.abs() <= 8.0 * ULP * terms {
                2.0
            } else {
                0.0
            }
        },
    )
}

/// `rf_surface_spread_angle`.
pub fn surface_spread_angle() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "surface_spread_angle",
        || {
            (
                angle(),
                prop::sample::select(vec![1.0f32, -1.0]),
                -4.0f32..4.0,
                angle(),
            )
                .boxed()
        },
        |(phi, sign, k1, k2)| rc::surface_spread_angle(phi, sign, k1, k2),
        // Three products and a sum, possibly fused: 4 ULP of the larger term.
        |&(phi, sign, k1, k2), _, _| ulps(4.0, (2.0 * k1 * sign * phi).abs() + k2.abs()),
    )
}

/// `rf_edge_curvature`.
pub fn edge_curvature() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "edge_curvature",
        || (vec3(), vec3(), small_vec3(), small_vec3()).boxed(),
        |(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j),
        |&(p_i, p_j, n_i, n_j), _, _| edge_curvature_error(p_i, p_j, n_i, n_j),
    )
}

/// `rf_triangle_curvature`.
pub fn triangle_curvature() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "triangle_curvature",
        || {
            (triangle(), (small_vec3(), small_vec3(), small_vec3()))
                .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                .boxed()
        },
        |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
        |&(p0, p1, p2, n0, n1, n2), _, _| triangle_curvature_error([p0, p1, p2], [n0, n1, n2]),
    )
}

/// `rf_curvature_spread_angle`.
pub fn curvature_spread_angle() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "curvature_spread_angle",
        // Signed curvatures and widths; the ray meets the normal's side or the other one, never
        // within the dot product's rounding of the surface plane (see `off_the_plane`).
        || {
            (scalar(), scalar(), normal_and_direction(), any::<bool>())
                .prop_map(|(k, w, (n, d), behind)| {
                    let d = off_the_plane(n, d);
                    (k, w, if behind { -n } else { n }, d)
                })
                .boxed()
        },
        |(curvature, width, normal, direction)| {
            rc::curvature_spread_angle(curvature, width, normal, direction)
        },
        |&(_, _, normal, direction), _, expected| curvature_spread_angle_error(normal, direction, expected),
    )
}

/// `rf_world_footprint`.
pub fn world_footprint() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "world_footprint",
        || {
            (ray_cone(), distance(), normal_and_direction())
                .prop_map(|(c, t, (n, d))| (c, t, n, d))
                .boxed()
        },
        |(cone, t, normal, direction)| rc::world_footprint(cone, t, normal, direction),
        // The width's error (as width_at) over |cos|, the division (3 ULP), and the dot's
        // rounding over |cos| as a relative error.
        |&(cone, t, normal, direction), _, expected| {
            let cos = clamped_cos(normal, direction);
            width_at_error(cone, t) / cos
                + ulps(3.0, expected)
                + expected.abs() * dot_error(normal, direction) / cos
        },
    )
}

/// `rf_triangle_world_area2`.
pub fn triangle_world_area2() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "triangle_world_area2",
        || triangle().prop_map(|p| (p[0], p[1], p[2])).boxed(),
        |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
        |&(p0, p1, p2), _, _| world_area2_error([p0, p1, p2]),
    )
}

/// `rf_triangle_uv_area2`.
pub fn triangle_uv_area2() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "triangle_uv_area2",
        || uv_triangle().prop_map(|uv| (uv[0], uv[1], uv[2])).boxed(),
        |(uv0, uv1, uv2)| rc::triangle_uv_area2(uv0, uv1, uv2),
        |&(uv0, uv1, uv2), _, _| uv_area2_error([uv0, uv1, uv2]),
    )
}

/// `rf_texel_density`.
pub fn texel_density() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "texel_density",
        triangle_with_uvs,
        |(p0, p1, p2, uv0, uv1, uv2)| rc::texel_density(p0, p1, p2, uv0, uv1, uv2),
        // The areas' errors through sqrt(uv) / sqrt(max(world, MIN)), plus two square roots
        // (4.5 ULP each), the division (2.5) and the mirror's 3.
        |&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
            let min = f64::from(MIN_MAGNITUDE);
            area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
                uv.sqrt() / world.max(min).sqrt()
            }) + ulps(14.5, expected)
        },
    )
}

/// `rf_triangle_base_lod`.
pub fn triangle_base_lod() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "triangle_base_lod",
        triangle_with_uvs,
        |(p0, p1, p2, uv0, uv1, uv2)| rc::triangle_base_lod(p0, p1, p2, uv0, uv1, uv2),
        // The areas' errors through 0.5 * (log2 uv - log2 world) with the clamps, half of each
        // log2's error, and the subtraction and halving (2 ULP).
        |&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
            let min = f64::from(MIN_MAGNITUDE);
            let uv_area2 = rc::triangle_uv_area2(uv0, uv1, uv2).max(MIN_MAGNITUDE);
            let world_area2 = rc::triangle_world_area2(p0, p1, p2).max(MIN_MAGNITUDE);
            area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
                0.5 * (uv.max(min).log2() - world.max(min).log2())
            }) + 0.5 * (log2_error(uv_area2.log2()) + log2_error(world_area2.log2()))
                + ulps(2.0, expected)
        },
    )
}

/// The check of `rf_texture_lod` (also measured by the harness benchmark).
pub fn texture_lod() -> FunctionCheck<TextureLodArgs, f32> {
    per_component(
        "texture_lod",
        || {
            (-20.0f32..20.0, scalar(), image_size(), normal_and_direction())
                .prop_map(|(base, width, size, (n, d))| (base, width, size, n, d))
                .boxed()
        },
        |(base, width, size, normal, direction)| rc::texture_lod(base, width, size, normal, direction),
        // Four log2 (their own errors), the dot's rounding through log2 (relative error / ln 2),
        // and four additions (4 ULP of the sum of term magnitudes).
        |&(base, width, size, normal, direction), _, _| {
            let size = size.max(Vec2::ONE);
            let logs = [
                width.abs().max(MIN_MAGNITUDE).log2(),
                size.x.log2(),
                size.y.log2(),
            ];
            let cos = clamped_cos(normal, direction);
            let log_cos = cos.log2();
            log2_error(logs[0])
                + 0.5 * (log2_error(logs[1]) + log2_error(logs[2]))
                + log2_error(log_cos)
                + dot_error(normal, direction) / cos / std::f32::consts::LN_2
                + ulps(
                    4.0,
                    base.abs() + logs[0].abs() + 0.5 * (logs[1] + logs[2]) + log_cos.abs(),
                )
        },
    )
}

/// `rf_texture_gradient`.
pub fn texture_gradient() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "texture_gradient",
        || (scalar(), -1.0f32..4.0).boxed(),
        |(uv_footprint, scale)| rc::texture_gradient(uv_footprint, scale),
        // One correctly rounded product.
        |_, _, _| f32::MIN_POSITIVE,
    )
}

/// `rf_environment_lod`.
pub fn environment_lod() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "environment_lod",
        || (angle(), pixels()).boxed(),
        |(spread, height)| rc::environment_lod(spread, height),
        // A product and a division (3.5 ULP + the mirror's 1) through log2 (/ ln 2), plus log2's
        // own error.
        |_, _, expected| 4.5 * ULP / std::f32::consts::LN_2 + log2_error(expected),
    )
}

/// `rf_refract_ray_cone`: the enclosure of the refracted cone (the hull of both branches where
/// the normal's side or total internal reflection is within rounding of changing).
pub fn refract_ray_cone() -> FunctionCheck<RefractArgs, RefractedRayCone> {
    enclosed(
        "refract_ray_cone",
        || {
            (ray_cone(), normal_and_direction(), any::<bool>(), angle(), eta())
                .prop_map(|(cone, (n, d), behind, beta, eta)| {
                    (cone, if behind { -n } else { n }, d, beta, eta)
                })
                .prop_filter(
                    "within rounding of grazing or of the critical angle",
                    refraction_decided,
                )
                .boxed()
        },
        |(cone, n, d, beta, eta)| rc::refract_ray_cone(cone, n, d, beta, eta),
        b_refract_ray_cone,
    )
}

/// `rf_roughness_spread_angle`: the enclosure of the spread.
pub fn roughness_spread_angle() -> FunctionCheck<(f32,), f32> {
    enclosed(
        "roughness_spread_angle",
        || {
            let roughness = prop_oneof![
                4 => 0.0f32..1.0,
                1 => Just(0.0f32),
                1 => Just(1.0f32),
                1 => 0.99f32..1.0,
                1 => scalar(),
            ];
            one_argument(roughness)
        },
        |(r,)| rc::roughness_spread_angle(r),
        |&(r,)| vec![b_roughness_spread_angle(r)],
    )
}

/// Every function's checks, in the module's function order.
pub fn entries() -> Vec<Registered<Entry>> {
    registered_checks!(
        Module::RayCone,
        [
            pack_ray_cone,
            unpack_ray_cone,
            pixel_spread_angle,
            pixel_spread_angle_small,
            pixel_spread_angle_from_proj_inv,
            pinhole_ray_cone,
            pinhole_ray_cone_for_ray,
            orthographic_ray_cone,
            thin_lens_ray_cone,
            width_at,
            propagate,
            normal_spread_angle,
            normal_spread_angle_small,
            curvature_sign,
            surface_spread_angle,
            edge_curvature,
            triangle_curvature,
            curvature_spread_angle,
            world_footprint,
            triangle_world_area2,
            triangle_uv_area2,
            texel_density,
            triangle_base_lod,
            texture_lod,
            texture_gradient,
            environment_lod,
            refract_ray_cone,
            roughness_spread_angle
        ]
    )
}
