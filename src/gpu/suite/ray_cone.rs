//! Agreement checks of the ray-cone module, one per function, in the module's order.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`crate::gpu::tolerance`]); the comment next to it says how.

use crate::gpu::check::{Check, FunctionCheck};
use crate::gpu::strategy::{
    angle, distance, fov_y, magnitude, normal_and_direction, pixels, scalar, small_vec3, triangle,
    uv_triangle, vec3,
};
use crate::gpu::suite::ray_diff::bound::{v3, F32, I, V, V2};
use crate::gpu::tolerance::{
    atan_error, dot_error, log2_error, tan_error, ulps, ATAN_ULPS, SIN_COS_ERROR, ULP,
};
use crate::gpu::value::{GpuValue, ShaderType, StructType, RAY_CONE};
use crate::ray_cone::{
    self as rc, PackedRayCone, RayCone, RefractedRayCone, MAX_FOV_Y, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD,
    MIN_COS, MIN_MAGNITUDE, MIN_ROUGHNESS_DENOMINATOR,
};
use crate::shaders::Module;
use glam::{Mat4, Vec2, Vec3, Vec3Swizzles};
use proptest::prelude::*;

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
    let perspective =
        (0.05f32..3.0, 0.2f32..5.0, 0.01f32..10.0, any::<bool>()).prop_map(|(fov, aspect, near, vulkan)| {
            let projection = if vulkan {
                glam::camera::rh::proj::vulkan::perspective(fov, aspect, near, near * 1000.0)
            } else {
                glam::camera::rh::proj::opengl::perspective(fov, aspect, near, near * 1000.0)
            };
            projection.inverse()
        });
    let arbitrary = prop::array::uniform16(scalar()).prop_map(|cols| Mat4::from_cols_array(&cols));
    prop_oneof![3 => perspective, 1 => arbitrary].boxed()
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
// Refraction and roughness: enclosures (`ray_diff::bound`, same order of operations as
// src/ray_cone.rs), since these chain dozens of operations
// ---------------------------------------------------------------------------------------------

/// `RfRefractedRayCone`.
pub const REFRACTED_RAY_CONE: StructType = StructType {
    name: "RfRefractedRayCone",
    fields: &[
        ("cone", ShaderType::Struct(&RAY_CONE)),
        ("total_internal_reflection", ShaderType::Bool),
    ],
};

/// A struct with a bool: written field by field.
impl GpuValue for RefractedRayCone {
    const TYPE: ShaderType = ShaderType::Struct(&REFRACTED_RAY_CONE);
    fn write(&self, words: &mut Vec<u32>) {
        self.cone.write(words);
        self.total_internal_reflection.write(words);
    }
    fn read(words: &mut &[u32]) -> Self {
        let cone = RayCone::read(words);
        RefractedRayCone {
            cone,
            total_internal_reflection: bool::read(words),
        }
    }
    fn components(&self, out: &mut Vec<f32>) {
        self.cone.components(out);
        self.total_internal_reflection.components(out);
    }
    fn is_finite(&self) -> bool {
        self.cone.is_finite()
    }
}

/// `[lo, hi]` in f32 arithmetic.
fn interval(lo: f64, hi: f64) -> I {
    I { lo, hi, p: F32 }
}

/// `sin` over an interval whose ends lie in `[-pi, pi]` (where Vulkan bounds it): the exact range
/// (the ends, and +-1 where `+-pi / 2` lies inside), widened by the device's absolute error 2^-11
/// plus the mirror's ULP.
fn b_sin(x: I) -> I {
    use std::f64::consts::FRAC_PI_2;
    let (mut lo, mut hi) = (x.lo.sin().min(x.hi.sin()), x.lo.sin().max(x.hi.sin()));
    if x.lo <= FRAC_PI_2 && FRAC_PI_2 <= x.hi {
        hi = 1.0;
    }
    if x.lo <= -FRAC_PI_2 && -FRAC_PI_2 <= x.hi {
        lo = -1.0;
    }
    let error = f64::from(SIN_COS_ERROR) + f64::from(ULP);
    interval(lo - error, hi + error)
}

/// `cos` over an interval whose ends lie in `[-pi, pi]`: the exact range (the ends, and 1 where 0
/// lies inside), widened as [`b_sin`].
fn b_cos(x: I) -> I {
    let (lo, mut hi) = (x.lo.cos().min(x.hi.cos()), x.lo.cos().max(x.hi.cos()));
    if x.lo <= 0.0 && 0.0 <= x.hi {
        hi = 1.0;
    }
    let error = f64::from(SIN_COS_ERROR) + f64::from(ULP);
    interval(lo - error, hi + error)
}

/// `(sin, cos)` of an interval.
fn b_angle_sin_cos(angle: I) -> V2 {
    V([b_sin(angle), b_cos(angle)])
}

/// `atan2(y, x)`: every angle of the box `y x x`, i.e. `[-pi, pi]` when the box holds the origin or
/// crosses the negative x axis, else the corners' range; widened by the device's 4096 ULP and the
/// mirror's one.
fn b_atan2(y: I, x: I) -> I {
    use std::f64::consts::PI;
    let crosses_cut = x.lo < 0.0 && y.lo <= 0.0 && y.hi >= 0.0;
    let (lo, hi) = if crosses_cut {
        (-PI, PI)
    } else {
        let corners = [
            y.lo.atan2(x.lo),
            y.lo.atan2(x.hi),
            y.hi.atan2(x.lo),
            y.hi.atan2(x.hi),
        ];
        (
            corners.iter().copied().fold(f64::INFINITY, f64::min),
            corners.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    };
    interval(lo, hi).round(f64::from(ATAN_ULPS) + 1.0)
}

/// The part of `x` at or above `floor` (the values a branch taken only there can see).
fn at_least(x: I, floor: f64) -> I {
    I {
        lo: x.lo.max(floor),
        hi: x.hi.max(floor),
        ..x
    }
}

/// `then` where `condition` is certainly true, `otherwise` where certainly false, and the hull of
/// both component by component where the interval leaves it open.
fn b_select(
    certainly: bool,
    possibly: bool,
    then: impl Fn() -> Vec<I>,
    otherwise: impl Fn() -> Vec<I>,
) -> Vec<I> {
    match (certainly, possibly) {
        (true, _) => then(),
        (false, false) => otherwise(),
        (false, true) => then()
            .into_iter()
            .zip(otherwise())
            .map(|(a, b)| a.hull(b))
            .collect(),
    }
}

fn b_incidence_sin_cos(normal: Vec3, direction: Vec3, cosine: I) -> V2 {
    let tangential = v3(direction) - v3(normal) * cosine;
    let sin_cos = V([tangential.dot(tangential).sqrt(), cosine.abs()]);
    let length = sin_cos.dot(sin_cos).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    let components = b_select(
        length.hi < min,
        length.lo < min,
        || vec![I::c(0.0), I::c(1.0)],
        || (sin_cos / at_least(length, min)).components(),
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
    b_select(
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
    b_atan2(sin_between, cos_between)
}

/// The arguments of `refract_ray_cone`: cone, normal, direction, normal spread, eta.
type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// The transmitted cone (its clamps cover the part of `eta sin i`'s interval above 1).
fn b_transmitted_cone(cone: RayCone, incidence: V2, facing_spread: f32, index: f32) -> Vec<I> {
    let transmitted = b_refracted_sin_cos(incidence, index);
    let limit = (I::c(f64::from(MAX_INCIDENCE_ANGLE)) - b_atan2(incidence.0[0], incidence.0[1])).max_c(0.0);
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
    b_select(
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

fn b_refract_ray_cone(args: &RefractArgs) -> Vec<I> {
    let &(_, normal, direction, beta, _) = args;
    let cosine = v3(normal).dot(v3(direction));
    b_select(
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

/// `rf_refract_ray_cone`: the enclosure of the refracted cone (the hull of both branches where
/// the normal's side or total internal reflection is within rounding of changing).
pub fn refract_ray_cone() -> FunctionCheck<RefractArgs, RefractedRayCone> {
    FunctionCheck {
        module: Module::RayCone,
        function: "refract_ray_cone",
        strategy: || {
            (ray_cone(), normal_and_direction(), any::<bool>(), angle(), eta())
                .prop_map(|(cone, (n, d), behind, beta, eta)| {
                    (cone, if behind { -n } else { n }, d, beta, eta)
                })
                .boxed()
        },
        mirror: |(cone, n, d, beta, eta)| rc::refract_ray_cone(cone, n, d, beta, eta),
        tolerance: |a, i, _| b_refract_ray_cone(a)[i].tolerance(),
    }
}

/// `rf_roughness_spread_angle`: the enclosure of the spread.
pub fn roughness_spread_angle() -> FunctionCheck<(f32,), f32> {
    FunctionCheck {
        module: Module::RayCone,
        function: "roughness_spread_angle",
        strategy: || {
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
        mirror: |(r,)| rc::roughness_spread_angle(r),
        tolerance: |&(r,), _, _| b_roughness_spread_angle(r).tolerance(),
    }
}

/// Every check of the module.
pub fn checks() -> Vec<Box<dyn Check>> {
    vec![
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "pack_ray_cone",
            strategy: || ray_cone().prop_map(|c| (c,)).boxed(),
            mirror: |(cone,)| rc::pack_ray_cone(cone),
            // The rounding mode of packHalf2x16 is the implementation's: one f16 ULP (2^-10
            // relative, 2^-24 absolute for f16 subnormals).
            tolerance: |_, _, expected| (expected.abs() / 1024.0).max(1.0 / 16_777_216.0),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "unpack_ray_cone",
            strategy: || packed_ray_cone().prop_map(|p| (p,)).boxed(),
            mirror: |(packed,)| rc::unpack_ray_cone(packed),
            // f16 to f32 is exact.
            tolerance: |_, _, _| 0.0,
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "pixel_spread_angle",
            strategy: || (fov_y(), pixels()).boxed(),
            mirror: |(fov, height)| rc::pixel_spread_angle(fov, height),
            // atan of the tan ratio: the ratio's error through atan, plus atan's 4096 ULP.
            tolerance: |&(fov, height), _, _| {
                atan_error(
                    rc::pixel_spread_angle_small(fov, height),
                    tan_ratio_error(fov, height),
                )
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "pixel_spread_angle_small",
            strategy: || (fov_y(), pixels()).boxed(),
            mirror: |(fov, height)| rc::pixel_spread_angle_small(fov, height),
            // tan's error (inherited from sin / cos) scaled by 2 / H.
            tolerance: |&(fov, height), _, _| tan_ratio_error(fov, height),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "pixel_spread_angle_from_proj_inv",
            strategy: || (proj_inv(), pixels()).boxed(),
            mirror: |(proj_inv, height)| rc::pixel_spread_angle_from_proj_inv(proj_inv, height),
            // The ratio 2|m|/H has one division (2.5 ULP) and the mirror's rounding; then atan.
            tolerance: |&(proj_inv, height), _, _| {
                let ratio = 2.0 * proj_inv.y_axis.y.abs() / height.max(1.0);
                atan_error(ratio, ulps(3.5, ratio))
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "pinhole_ray_cone",
            strategy: || angle().prop_map(|a| (a,)).boxed(),
            mirror: |(spread,)| rc::pinhole_ray_cone(spread),
            // No arithmetic.
            tolerance: |_, _, _| 0.0,
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "orthographic_ray_cone",
            strategy: || (magnitude(), pixels()).boxed(),
            mirror: |(view_height, height)| rc::orthographic_ray_cone(view_height, height),
            // One division: 2.5 ULP on the device, 0.5 in the mirror.
            tolerance: |_, _, expected| ulps(3.0, expected),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "thin_lens_ray_cone",
            strategy: || (angle(), magnitude(), scalar()).boxed(),
            mirror: |(spread, aperture, focus)| rc::thin_lens_ray_cone(spread, aperture, focus),
            // Width: a copy. Spread: a division (2.5 ULP + 0.5) then a subtraction (0.5 + 0.5 ULP
            // of the larger operand).
            tolerance: |&(spread, aperture, focus), index, _| {
                let quotient = aperture / focus.max(MIN_MAGNITUDE);
                if index == 0 {
                    0.0
                } else {
                    ulps(4.0, spread.abs() + quotient.abs())
                }
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "width_at",
            strategy: || (ray_cone(), distance()).boxed(),
            mirror: |(cone, t)| rc::width_at(cone, t),
            // width + spread * t, possibly fused: 2 ULP of the larger term.
            tolerance: |&(cone, t), _, _| ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs()),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "propagate",
            strategy: || (ray_cone(), distance(), angle()).boxed(),
            mirror: |(cone, t, beta)| rc::propagate(cone, t, beta),
            // Width as width_at; spread: one correctly rounded addition, identical.
            tolerance: |&(cone, t, _), index, _| {
                if index == 0 {
                    ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs())
                } else {
                    0.0
                }
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "normal_spread_angle",
            strategy: || (small_vec3(), small_vec3()).boxed(),
            mirror: |(dn_dx, dn_dy)| rc::normal_spread_angle(dn_dx, dn_dy),
            // sqrt of a 6-term sum (3 ULP of the sum -> 1.5 relative, sqrt ~4.5, mirror 1): 9 ULP
            // on the length, halved and propagated through atan, doubled; plus atan's 4096 ULP.
            tolerance: |&(dn_dx, dn_dy), _, _| {
                let length = rc::normal_spread_angle_small(dn_dx, dn_dy);
                2.0 * atan_error(0.5 * length, ulps(9.0, 0.5 * length))
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "normal_spread_angle_small",
            strategy: || (small_vec3(), small_vec3()).boxed(),
            mirror: |(dn_dx, dn_dy)| rc::normal_spread_angle_small(dn_dx, dn_dy),
            // As above, without atan: 9 ULP.
            tolerance: |_, _, expected| ulps(9.0, expected),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "curvature_sign",
            strategy: || (small_vec3(), small_vec3(), small_vec3(), small_vec3()).boxed(),
            mirror: |(dp_dx, dp_dy, dn_dx, dn_dy)| rc::curvature_sign(dp_dx, dp_dy, dn_dx, dn_dy),
            // Exact, unless the sum is within its rounding error (6 terms, 8 ULP) of zero: then
            // either sign is right.
            tolerance: |&(dp_dx, dp_dy, dn_dx, dn_dy), _, _| {
                let sum = dp_dx.dot(dn_dx) + dp_dy.dot(dn_dy);
                let terms = (dp_dx * dn_dx).abs().element_sum() + (dp_dy * dn_dy).abs().element_sum();
                if sum.abs() <= 8.0 * ULP * terms {
                    2.0
                } else {
                    0.0
                }
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "surface_spread_angle",
            strategy: || {
                (
                    angle(),
                    prop::sample::select(vec![1.0f32, -1.0]),
                    -4.0f32..4.0,
                    angle(),
                )
                    .boxed()
            },
            mirror: |(phi, sign, k1, k2)| rc::surface_spread_angle(phi, sign, k1, k2),
            // Three products and a sum, possibly fused: 4 ULP of the larger term.
            tolerance: |&(phi, sign, k1, k2), _, _| ulps(4.0, (2.0 * k1 * sign * phi).abs() + k2.abs()),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "edge_curvature",
            strategy: || (vec3(), vec3(), small_vec3(), small_vec3()).boxed(),
            mirror: |(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j),
            tolerance: |&(p_i, p_j, n_i, n_j), _, _| edge_curvature_error(p_i, p_j, n_i, n_j),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "triangle_curvature",
            strategy: || {
                (triangle(), (small_vec3(), small_vec3(), small_vec3()))
                    .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                    .boxed()
            },
            mirror: |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
            // The three edge errors, then two additions and a division by 3 (5 ULP of the sum of
            // magnitudes), all divided by 3.
            tolerance: |&(p0, p1, p2, n0, n1, n2), _, _| {
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
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "curvature_spread_angle",
            strategy: || {
                (scalar(), scalar(), normal_and_direction())
                    .prop_map(|(k, w, (n, d))| (k, w, n, d))
                    .boxed()
            },
            mirror: |(curvature, width, normal, direction)| {
                rc::curvature_spread_angle(curvature, width, normal, direction)
            },
            // Relative: two products and a division (5 ULP), plus the dot's rounding over |cos|.
            tolerance: |&(_, _, normal, direction), _, expected| {
                ulps(5.0, expected)
                    + expected.abs() * dot_error(normal, direction) / clamped_cos(normal, direction)
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "world_footprint",
            strategy: || {
                (ray_cone(), distance(), normal_and_direction())
                    .prop_map(|(c, t, (n, d))| (c, t, n, d))
                    .boxed()
            },
            mirror: |(cone, t, normal, direction)| rc::world_footprint(cone, t, normal, direction),
            // The width's error (as width_at) over |cos|, the division (3 ULP), and the dot's
            // rounding over |cos| as a relative error.
            tolerance: |&(cone, t, normal, direction), _, expected| {
                let cos = clamped_cos(normal, direction);
                ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs()) / cos
                    + ulps(3.0, expected)
                    + expected.abs() * dot_error(normal, direction) / cos
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "triangle_world_area2",
            strategy: || triangle().prop_map(|p| (p[0], p[1], p[2])).boxed(),
            mirror: |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
            tolerance: |&(p0, p1, p2), _, _| world_area2_error([p0, p1, p2]),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "triangle_uv_area2",
            strategy: || uv_triangle().prop_map(|uv| (uv[0], uv[1], uv[2])).boxed(),
            mirror: |(uv0, uv1, uv2)| rc::triangle_uv_area2(uv0, uv1, uv2),
            tolerance: |&(uv0, uv1, uv2), _, _| uv_area2_error([uv0, uv1, uv2]),
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "texel_density",
            strategy: || {
                (triangle(), uv_triangle())
                    .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                    .boxed()
            },
            mirror: |(p0, p1, p2, uv0, uv1, uv2)| rc::texel_density(p0, p1, p2, uv0, uv1, uv2),
            // The areas' errors through sqrt(uv) / sqrt(max(world, MIN)), plus two square roots
            // (4.5 ULP each), the division (2.5) and the mirror's 3.
            tolerance: |&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
                let min = f64::from(MIN_MAGNITUDE);
                area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
                    uv.sqrt() / world.max(min).sqrt()
                }) + ulps(14.5, expected)
            },
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "triangle_base_lod",
            strategy: || {
                (triangle(), uv_triangle())
                    .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                    .boxed()
            },
            mirror: |(p0, p1, p2, uv0, uv1, uv2)| rc::triangle_base_lod(p0, p1, p2, uv0, uv1, uv2),
            // The areas' errors through 0.5 * (log2 uv - log2 world) with the clamps, half of each
            // log2's error, and the subtraction and halving (2 ULP).
            tolerance: |&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
                let min = f64::from(MIN_MAGNITUDE);
                let uv_area2 = rc::triangle_uv_area2(uv0, uv1, uv2).max(MIN_MAGNITUDE);
                let world_area2 = rc::triangle_world_area2(p0, p1, p2).max(MIN_MAGNITUDE);
                area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
                    0.5 * (uv.max(min).log2() - world.max(min).log2())
                }) + 0.5 * (log2_error(uv_area2.log2()) + log2_error(world_area2.log2()))
                    + ulps(2.0, expected)
            },
        }),
        Box::new(texture_lod()),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "texture_gradient",
            strategy: || (scalar(), -1.0f32..4.0).boxed(),
            mirror: |(uv_footprint, scale)| rc::texture_gradient(uv_footprint, scale),
            // One correctly rounded product.
            tolerance: |_, _, _| f32::MIN_POSITIVE,
        }),
        Box::new(FunctionCheck {
            module: Module::RayCone,
            function: "environment_lod",
            strategy: || (angle(), pixels()).boxed(),
            mirror: |(spread, height)| rc::environment_lod(spread, height),
            // A product and a division (3.5 ULP + the mirror's 1) through log2 (/ ln 2), plus log2's
            // own error.
            tolerance: |_, _, expected| 4.5 * ULP / std::f32::consts::LN_2 + log2_error(expected),
        }),
        Box::new(refract_ray_cone()),
        Box::new(roughness_spread_angle()),
    ]
}

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The check of `rf_texture_lod` (also measured by the harness benchmark).
pub fn texture_lod() -> FunctionCheck<TextureLodArgs, f32> {
    FunctionCheck {
        module: Module::RayCone,
        function: "texture_lod",
        strategy: || {
            (
                -20.0f32..20.0,
                scalar(),
                (pixels(), pixels()),
                normal_and_direction(),
            )
                .prop_map(|(base, width, (w, h), (n, d))| (base, width, Vec2::new(w, h), n, d))
                .boxed()
        },
        mirror: |(base, width, size, normal, direction)| {
            rc::texture_lod(base, width, size, normal, direction)
        },
        // Four log2 (their own errors), the dot's rounding through log2 (relative error / ln 2),
        // and four additions (4 ULP of the sum of term magnitudes).
        tolerance: |&(base, width, size, normal, direction), _, _| {
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
    }
}
