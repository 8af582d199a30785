//! Interval enclosures of the ray-cone functions that chain dozens of operations (refraction and
//! roughness): each `b_*` re-evaluates a function, or a step of one, in interval arithmetic
//! ([`shader_proptest::interval`]) in the same order of operations as `src/ray_cone.rs`, and its
//! width is the check's tolerance. Also here: whether a refraction's decisions are certain, so that
//! the check keeps to cases whose enclosure says something.

use super::RefractArgs;
use glam::Vec3;
use ray_footprint::ray_cone::{
    RayCone, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD, MIN_COS, MIN_MAGNITUDE, MIN_ROUGHNESS_DENOMINATOR,
};
use shader_proptest::interval::{interval3 as v3, select, Interval as I, Interval2 as V2, IntervalVec as V};

/// An exact f32 input.
fn s(x: f32) -> I {
    I::exact(x)
}

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
pub(super) fn refraction_decided(&(_, normal, direction, _, eta): &RefractArgs) -> bool {
    let cosine = v3(normal).dot(v3(direction));
    let incidence = b_incidence_sin_cos(normal, direction, cosine);
    let sin_t = s(eta.max(0.0)) * incidence.0[0];
    let side_decided = cosine.lo > 0.0 || cosine.hi <= 0.0;
    let reflection_decided = sin_t.lo > 1.0 || sin_t.hi <= 1.0;
    side_decided && reflection_decided
}

pub(super) fn b_refract_ray_cone(args: &RefractArgs) -> Vec<I> {
    let &(_, normal, direction, beta, _) = args;
    let cosine = v3(normal).dot(v3(direction));
    select(
        cosine.lo > 0.0,
        cosine.hi > 0.0,
        || b_refract_facing(args, cosine, -beta),
        || b_refract_facing(args, cosine, beta),
    )
}

pub(super) fn b_roughness_spread_angle(roughness: f32) -> I {
    let r = s(roughness.clamp(0.0, 1.0));
    let alpha = r * r;
    let alpha2 = alpha * alpha;
    let variance = I::c(0.5) * alpha2 / (I::c(1.0) - alpha2).max_c(f64::from(MIN_ROUGHNESS_DENOMINATOR));
    I::c(2.0) * variance.sqrt()
}
