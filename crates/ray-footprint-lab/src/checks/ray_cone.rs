//! Agreement checks of the ray-cone module, one per function, in the module's order.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how.

use super::edge::Edge;
use super::strategy::{
    angle, distance, fov_y, magnitude, normal_and_direction, perspective_proj_inv, pixels, scalar,
    small_vec3, triangle, uv_triangle, vec3,
};
use super::{enclosed, per_component};
use super::{registered_checks, Entry};
use glam::{Mat4, Vec2, Vec3, Vec3Swizzles};
use proptest::prelude::*;
use ray_footprint::ray_cone::{
    self as rc, PackedRayCone, RayCone, RefractedRayCone, MAX_FOV_Y, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD,
    MIN_COS, MIN_MAGNITUDE, MIN_ROUGHNESS_DENOMINATOR,
};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3 as v3, select, Interval as I, Interval2 as V2, IntervalVec as V};
use shader_proptest::tolerance::{atan_error, dot_error, log2_error, tan_error, ulps, ULP};
use shader_proptest::{Args, FunctionCheck, Value};

fn ray_cone() -> BoxedStrategy<RayCone> {
    (scalar(), angle())
        .prop_map(|(width, spread_angle)| RayCone { width, spread_angle })
        .boxed()
}

/// A packed cone whose halves are finite f16 (exponent field below 31).
fn packed_ray_cone() -> BoxedStrategy<PackedRayCone> {
    let finite_half = any::<u16>().prop_filter("finite f16", |h| (h >> 10) & 0x1f != 0x1f);
    (finite_half.clone(), finite_half)
        .prop_map(|(lo, hi)| PackedRayCone(u32::from(lo) | u32::from(hi) << 16))
        .boxed()
}

/// An inverse projection matrix of a perspective camera (y-flipped or not), or an arbitrary matrix.
fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary = prop::array::uniform16(scalar()).prop_map(|cols| Mat4::from_cols_array(&cols));
    prop_oneof![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// `|cos|` as the functions clamp it.
fn clamped_cos(normal: Vec3, direction: Vec3) -> f32 {
    normal.dot(direction).abs().max(MIN_COS)
}

/// Error of `2 * tan(fov / 2) / H` with the clamps: `tan`'s error scaled by `2 / H`, plus 3.5 ULP.
fn tan_ratio_error(fov: f32, height: f32) -> f32 {
    let angle = 0.5 * fov.clamp(0.0, MAX_FOV_Y);
    2.0 * tan_error(angle) / height.max(1.0) + ulps(3.5, rc::pixel_spread_angle_small(fov, height))
}

/// Error of a triangle's doubled world area: each cross-product component `a*b - c*d` is off by at
/// most 2 ULP of `|a*b| + |c*d|` (the edges are computed identically); the scaling division
/// (2.5 ULP), `length` (8 ULP) and the rescaling product (0.5 ULP) add 11 ULP of the result.
pub fn world_area2_error(p: [Vec3; 3]) -> f32 {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let terms = (e1.yzx() * e2.zxy()).abs() + (e1.zxy() * e2.yzx()).abs();
    ulps(2.0, terms.element_sum()) + ulps(11.0, rc::triangle_world_area2(p[0], p[1], p[2]))
}

/// Error of a triangle's doubled UV area: 2 ULP of `|e1.x*e2.y| + |e1.y*e2.x|`.
pub fn uv_area2_error(uv: [Vec2; 3]) -> f32 {
    let (e1, e2) = (uv[1] - uv[0], uv[2] - uv[0]);
    ulps(2.0, (e1.x * e2.y).abs() + (e1.y * e2.x).abs())
}

/// Widest change of `f(uv_area2, world_area2)` when each area moves within its error bound; `f` is
/// monotonic in each area, so the extremes lie at the corners. Evaluated in f64.
pub fn area_corners(p: [Vec3; 3], uv: [Vec2; 3], f: impl Fn(f64, f64) -> f64) -> f32 {
    let uv_area = f64::from(rc::triangle_uv_area2(uv[0], uv[1], uv[2]));
    let world_area = f64::from(rc::triangle_world_area2(p[0], p[1], p[2]));
    let (uv_err, world_err) = (f64::from(uv_area2_error(uv)), f64::from(world_area2_error(p)));
    let centre = f(uv_area, world_area);
    [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
        .iter()
        .map(|(a, b)| {
            (f(
                (uv_area + a * uv_err).max(0.0),
                (world_area + b * world_err).max(0.0),
            ) - centre)
                .abs()
        })
        .fold(0.0, f64::max) as f32
}

/// Error of [`rc::edge_curvature`]: the dot product's rounding over the squared length, and the
/// relative error of the squared length (3 ULP) and the division (2.5 ULP) times the result.
pub fn edge_curvature_error(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3) -> f32 {
    let edge = p_j - p_i;
    dot_error(n_j - n_i, edge) / edge.dot(edge).max(MIN_MAGNITUDE)
        + ulps(7.0, rc::edge_curvature(p_i, p_j, n_i, n_j))
}

// ---------------------------------------------------------------------------------------------
// Refraction and roughness: enclosures (`shader_proptest::interval`, in src/ray_cone.rs's order of
// operations), since these chain dozens of operations
// ---------------------------------------------------------------------------------------------

/// `(sin, cos)` of an interval.
fn b_angle_sin_cos(angle: I) -> V2 {
    V([angle.sin(), angle.cos()])
}

fn b_incidence_sin_cos(normal: Vec3, direction: Vec3, cosine: I) -> V2 {
    let tangential = v3(direction) - v3(normal) * cosine;
    let sin_cos = V([tangential.dot(tangential).sqrt(), cosine.abs()]);
    let length = sin_cos.dot(sin_cos).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    let components = select(
        length.hi < min,
        length.lo < min,
        || vec![I::c(0.0), I::c(1.0)],
        || (sin_cos / length.at_least(min)).components(),
    );
    V([components[0], components[1]])
}

fn b_boundary_incidence(incidence: V2, local: V2, side: f64) -> V2 {
    let ([sin_i, cos_i], [sin_q, cos_q]) = (incidence.0, local.0);
    V([
        sin_i * cos_q + I::c(side) * cos_i * sin_q,
        cos_i * cos_q - I::c(side) * sin_i * sin_q,
    ])
}

fn b_refracted_sin_cos(incidence: V2, eta: f32) -> V2 {
    let [sin, cos] = incidence.0;
    let eta = s(eta);
    let cos2 = cos * cos + ((I::c(1.0) - eta) * sin) * ((I::c(1.0) + eta) * sin);
    V([(eta * sin).clamp_c(-1.0, 1.0), cos2.max_c(0.0).sqrt()])
}

fn b_boundary_hit(width: f32, side: f64, incidence: V2, half_spread: V2) -> I {
    let [sin_i, cos_i] = incidence.0;
    let [sin_h, cos_h] = half_spread.0;
    let cos_boundary = cos_i * cos_h - I::c(side) * sin_i * sin_h;
    I::c(side) * I::c(0.5) * s(width) * cos_h / cos_boundary.max_c(f64::from(MIN_COS))
}

fn b_boundary_offset(hit: I, side: f64, refracted: V2, tilt: V2, transmitted: V2) -> I {
    let ([sin_tau, cos_tau], [sin_tilt, cos_tilt]) = (refracted.0, tilt.0);
    let cos_rho = cos_tau * cos_tilt + I::c(side) * sin_tau * sin_tilt;
    let sin_rho = sin_tau * cos_tilt - I::c(side) * cos_tau * sin_tilt;
    hit * cos_rho / (cos_rho * transmitted.0[1] + sin_rho * transmitted.0[0]).max_c(f64::from(MIN_COS))
}

fn b_refracted_sine_gap(eta: f32, incidence: V2, local: V2, upper: V2, lower: V2) -> I {
    let eta = s(eta);
    let (upper_sine, lower_sine) = (eta * upper.0[0], eta * lower.0[0]);
    let (upper_size, lower_size) = (upper_sine.abs(), lower_sine.abs());
    select(
        upper_size.hi <= 1.0 && lower_size.hi <= 1.0,
        upper_size.lo <= 1.0 && lower_size.lo <= 1.0,
        || vec![I::c(2.0) * eta * incidence.0[1] * local.0[0]],
        || vec![upper_sine.clamp_c(-1.0, 1.0) - lower_sine.clamp_c(-1.0, 1.0)],
    )[0]
}

fn b_refracted_angle_between(sine_gap: I, upper: V2, lower: V2) -> I {
    let ([sin_u, cos_u], [sin_l, cos_l]) = (upper.0, lower.0);
    let cos_between = cos_u * cos_l + sin_u * sin_l;
    let cos_sum = (cos_u + cos_l)
        .max((sine_gap * (sin_u + sin_l)).abs().sqrt())
        .max_c(f64::from(MIN_MAGNITUDE));
    let sin_between = sine_gap * (I::c(1.0) + cos_between) / cos_sum;
    I::atan2(sin_between, cos_between)
}

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// The transmitted cone (its clamps cover the part of `eta sin i`'s interval above 1).
fn b_transmitted_cone(cone: RayCone, incidence: V2, facing_spread: f32, index: f32) -> Vec<I> {
    let transmitted = b_refracted_sin_cos(incidence, index);
    let limit = (I::c(f64::from(MAX_INCIDENCE_ANGLE)) - I::atan2(incidence.0[0], incidence.0[1])).max_c(0.0);
    let half_spread = (I::c(0.5) * s(cone.spread_angle)).max(-limit).min(limit);
    let signed_half = if cone.width < 0.0 { -0.5 } else { 0.5 };
    let tilt = I::c(signed_half) * s(facing_spread.clamp(-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD));
    let local = b_angle_sin_cos(half_spread + tilt);
    let upper_incidence = b_boundary_incidence(incidence, local, 1.0);
    let lower_incidence = b_boundary_incidence(incidence, local, -1.0);
    let upper = b_refracted_sin_cos(upper_incidence, index);
    let lower = b_refracted_sin_cos(lower_incidence, index);
    let sine_gap = b_refracted_sine_gap(index, incidence, local, upper_incidence, lower_incidence);
    let half = b_angle_sin_cos(half_spread);
    let tilt_sin_cos = b_angle_sin_cos(tilt);
    let upper_hit = b_boundary_hit(cone.width, 1.0, incidence, half);
    let lower_hit = b_boundary_hit(cone.width, -1.0, incidence, half);
    vec![
        b_boundary_offset(upper_hit, 1.0, upper, tilt_sin_cos, transmitted)
            - b_boundary_offset(lower_hit, -1.0, lower, tilt_sin_cos, transmitted),
        b_refracted_angle_between(sine_gap, upper, lower) - I::c(2.0) * tilt,
        I::c(0.0),
    ]
}

/// Both branches of `refract_ray_cone` for one normal orientation (`facing_spread`).
fn b_refract_facing(
    &(cone, normal, direction, _, eta): &RefractArgs,
    cosine: I,
    facing_spread: f32,
) -> Vec<I> {
    let incidence = b_incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let sin_t = s(index) * incidence.0[0];
    select(
        sin_t.lo > 1.0,
        sin_t.hi > 1.0,
        || {
            vec![
                s(cone.width),
                s(cone.spread_angle) + I::c(2.0) * s(facing_spread),
                I::c(1.0),
            ]
        },
        || b_transmitted_cone(cone, incidence, facing_spread, index),
    )
}

/// Whether both of `refract_ray_cone`'s decisions are certain: which side of the normal the ray
/// meets, and whether it is totally internally reflected. Within rounding of either (a grazing ray,
/// the critical angle) both answers are right and the flag's tolerance would be vacuous; those
/// cases are checked separately (the degenerate table, the edge-case suite).
fn refraction_decided(&(_, normal, direction, _, eta): &RefractArgs) -> bool {
    let cosine = v3(normal).dot(v3(direction));
    let incidence = b_incidence_sin_cos(normal, direction, cosine);
    let sin_t = s(eta.max(0.0)) * incidence.0[0];
    let side_decided = cosine.lo > 0.0 || cosine.hi <= 0.0;
    let reflection_decided = sin_t.lo > 1.0 || sin_t.hi <= 1.0;
    side_decided && reflection_decided
}

fn b_refract_ray_cone(args: &RefractArgs) -> Vec<I> {
    let &(_, normal, direction, beta, _) = args;
    let cosine = v3(normal).dot(v3(direction));
    select(
        cosine.lo > 0.0,
        cosine.hi > 0.0,
        || b_refract_facing(args, cosine, -beta),
        || b_refract_facing(args, cosine, beta),
    )
}

fn b_roughness_spread_angle(roughness: f32) -> I {
    let r = s(roughness.clamp(0.0, 1.0));
    let alpha = r * r;
    let alpha2 = alpha * alpha;
    let variance = I::c(0.5) * alpha2 / (I::c(1.0) - alpha2).max_c(f64::from(MIN_ROUGHNESS_DENOMINATOR));
    I::c(2.0) * variance.sqrt()
}

/// An exact f32 input.
fn s(x: f32) -> I {
    I::exact(x)
}

/// Index ratios: ordinary, 1, glass in and out, 0, and anything in the domain.
fn eta() -> BoxedStrategy<f32> {
    prop_oneof![
        4 => 0.3f32..3.0,
        1 => Just(1.0f32),
        1 => Just(1.5f32),
        1 => Just(1.0f32 / 1.5),
        1 => Just(0.0f32),
        1 => scalar(),
    ]
    .boxed()
}

/// Error of [`rc::curvature_spread_angle`] returning `expected`: relative, two products and a
/// division (5 ULP with the mirror's), and the rounding of `dot(normal, direction)` over the
/// clamped `|cos|`. Where the dot product lies within its rounding of 0, the device may find the
/// ray on the other side of the normal and return `-expected`, which is as right: 2 `|expected|`
/// more.
pub fn curvature_spread_angle_error(normal: Vec3, direction: Vec3, expected: f32) -> f32 {
    let dot_rounding = dot_error(normal, direction);
    let error = ulps(5.0, expected) + expected.abs() * dot_rounding / clamped_cos(normal, direction);
    if normal.dot(direction).abs() <= dot_rounding {
        error + 2.0 * expected.abs()
    } else {
        error
    }
}

/// `direction`, tilted by 1e-5 towards `-normal` when it lies within the rounding of
/// `dot(normal, direction)` of the surface plane. There either side is right, the tolerance of
/// [`curvature_spread_angle_error`] allows either sign, and the check could not catch a wrong one;
/// tilted, the ray meets the normal's side, still inside the `MIN_COS` clamp. The degenerate table
/// covers rays exactly in the plane.
fn off_the_plane(normal: Vec3, direction: Vec3) -> Vec3 {
    if normal.dot(direction).abs() <= dot_error(normal, direction) {
        (direction - 1.0e-5 * normal).normalize()
    } else {
        direction
    }
}

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// `rf_pack_ray_cone`.
pub fn pack_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "pack_ray_cone",
        || ray_cone().prop_map(|c| (c,)).boxed(),
        |(cone,)| rc::pack_ray_cone(cone),
        // The rounding mode of packHalf2x16 is the implementation's: one f16 ULP (2^-10
        // relative, 2^-24 absolute for f16 subnormals).
        |_, _, expected| (expected.abs() / 1024.0).max(1.0 / 16_777_216.0),
    )
}

/// `rf_unpack_ray_cone`.
pub fn unpack_ray_cone() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "unpack_ray_cone",
        || packed_ray_cone().prop_map(|p| (p,)).boxed(),
        |(packed,)| rc::unpack_ray_cone(packed),
        // f16 to f32 is exact.
        |_, _, _| 0.0,
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
    per_component(
        "pinhole_ray_cone",
        || angle().prop_map(|a| (a,)).boxed(),
        |(spread,)| rc::pinhole_ray_cone(spread),
        // No arithmetic.
        |_, _, _| 0.0,
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
        // width + spread * t, possibly fused: 2 ULP of the larger term.
        |&(cone, t), _, _| ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs()),
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
                ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs())
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
        // The three edge errors, then two additions and a division by 3 (5 ULP of the sum of
        // magnitudes), all divided by 3.
        |&(p0, p1, p2, n0, n1, n2), _, _| {
            let edges = [(p0, p1, n0, n1), (p1, p2, n1, n2), (p2, p0, n2, n0)];
            let errors: f32 = edges
                .iter()
                .map(|&(a, b, m, n)| edge_curvature_error(a, b, m, n))
                .sum();
            let sizes: f32 = edges
                .iter()
                .map(|&(a, b, m, n)| rc::edge_curvature(a, b, m, n).abs())
                .sum();
            (errors + ulps(5.0, sizes)) / 3.0
        },
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
            ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs()) / cos
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
        || {
            (triangle(), uv_triangle())
                .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                .boxed()
        },
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
        || {
            (triangle(), uv_triangle())
                .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                .boxed()
        },
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
            (
                -20.0f32..20.0,
                scalar(),
                (pixels(), pixels()),
                normal_and_direction(),
            )
                .prop_map(|(base, width, (w, h), (n, d))| (base, width, Vec2::new(w, h), n, d))
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
            prop_oneof![
                4 => 0.0f32..1.0,
                1 => Just(0.0f32),
                1 => Just(1.0f32),
                1 => 0.99f32..1.0,
                1 => scalar(),
            ]
            .prop_map(|r| (r,))
            .boxed()
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
