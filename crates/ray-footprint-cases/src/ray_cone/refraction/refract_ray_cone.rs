//! The proof of [`refract_ray_cone`](ray_footprint::ray_cone::refract_ray_cone): its record, its
//! enclosure (the hull of both branches where the normal's side or total internal reflection is
//! within rounding of changing) and its references: the boundary rays traced exactly through flat
//! and spherical interfaces, eta 1, the first-order formulas, the OptiX Toolkit's thin form,
//! negated cones and total internal reflection.

use crate::degenerate::{cone, grazing, same, value, HEAD_ON, IN_PLANE};
use crate::ray_cone::plane_of_incidence::Scattered;
use crate::ray_cone::refraction::shared::{
    either_facing, incidence_sin_cos, normal_incidence, normal_incidence_args, normal_tilt,
    refracted_sin_cos, refraction_cases, refraction_conventions, refraction_decided, relative, Case,
    RefractArgs, REFRACTION_UNDECIDED, THIRTY_DEGREES,
};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{
    self as rc, RayCone, RefractedRayCone, MAX_INCIDENCE_ANGLE, MIN_COS, MIN_MAGNITUDE,
};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{select, Interval, Interval2, IntervalVec};

/// The record of `rf_refract_ray_cone`: the enclosure of the refracted cone (the hull of both branches where
/// the normal's side or total internal reflection is within rounding of changing).
pub fn record() -> Record<RefractArgs, RefractedRayCone> {
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "refract_ray_cone",
        |(cone, n, d, beta, eta)| rc::refract_ray_cone(cone, n, d, beta, eta),
        refraction_cases,
    )
    .conditioned(REFRACTION_UNDECIDED, refraction_decided)
    .enclosure(enclosure)
    .reference(refract_flat())
    .reference(refract_curved())
    .reference(refract_index_one())
    .reference(refract_first_order())
    .reference(refract_optix())
    .reference(refract_negated())
    .reference(refract_total_internal_reflection())
    .symmetry(Symmetry::scale(
        "the width scaled by s: the refracted width by s, the spread the same",
        |&(cone, normal, direction, beta, eta), s| {
            (
                RayCone {
                    width: cone.width * s,
                    ..cone
                },
                normal,
                direction,
                beta,
                eta,
            )
        },
        |refracted: RefractedRayCone, s| RefractedRayCone {
            cone: RayCone {
                width: refracted.cone.width / s,
                ..refracted.cone
            },
            ..refracted
        },
    ))
    .symmetry(Symmetry::rotation(
        "the normal and the ray turned: the same",
        |&(cone, normal, direction, beta, eta), r| (cone, r * normal, r * direction, beta, eta),
        |refracted, _| refracted,
    ))
    .symmetry(Symmetry::exchange(
        "the normal flipped and its spread negated (the same surface), for a ray not exactly in the surface's plane: the same",
        |&(cone, normal, direction, beta, eta): &RefractArgs| (cone, -normal, direction, -beta, eta),
        |refracted| refracted,
    )
    .within(|&(_, normal, direction, ..)| normal.dot(direction) != 0.0))
    .fuzz(|d| (d.cone(), d.unit(), d.unit(), d.angle(), d.scalar()))
    .degenerate(
        [
            value(
                "normal incidence, flat, no spread (eta 1.5)",
                "(width, 0), not reflected",
                (cone(0.5, 0.0), z, HEAD_ON, 0.0, 1.5),
                vec![0.5, 0.0, 0.0],
            ),
            value(
                "zero cone",
                "zero cone",
                (cone(0.0, 0.0), z, THIRTY_DEGREES, 0.0, 1.5),
                vec![0.0, 0.0, 0.0],
            ),
            value(
                "central ray past the critical angle (sin i = 0.8, eta 1.5)",
                "the reflected cone (width, spread + 2 beta), flag set",
                (cone(0.25, 0.125), z, Vec3::new(0.8, 0.0, -0.6), 0.0625, 1.5),
                vec![0.25, 0.25, 1.0],
            ),
            same(
                "grazing (|dot(n, d)| = 1e-6), eta 0.5",
                "as a direction in the surface plane: both boundary rays land at |cos| = MIN_COS",
                (cone(0.01, 0.002), z, grazing(), 0.0, 0.5),
                (cone(0.01, 0.002), z, IN_PLANE, 0.0, 0.5),
            ),
            same(
                "spread wider than the surface allows (3.5 at normal incidence)",
                "as spread 2 MAX_INCIDENCE_ANGLE (both boundary rays graze)",
                (cone(0.01, 3.5), z, HEAD_ON, 0.0, 1.5),
                (cone(0.01, 2.0 * MAX_INCIDENCE_ANGLE), z, HEAD_ON, 0.0, 1.5),
            ),
        ]
        .into_iter()
        .chain(refraction_conventions())
        .collect(),
    )
}

/// `(sin, cos)` of an interval.
fn angle_sin_cos(angle: Interval) -> Interval2 {
    IntervalVec([angle.sin(), angle.cos()])
}

fn boundary_incidence(incidence: Interval2, local: Interval2, side: f64) -> Interval2 {
    let ([sin_i, cos_i], [sin_q, cos_q]) = (incidence.0, local.0);
    IntervalVec([
        sin_i * cos_q + Interval::c(side) * cos_i * sin_q,
        cos_i * cos_q - Interval::c(side) * sin_i * sin_q,
    ])
}

fn boundary_hit(width: f32, side: f64, incidence: Interval2, half_spread: Interval2) -> Interval {
    let [sin_i, cos_i] = incidence.0;
    let [sin_h, cos_h] = half_spread.0;
    let cos_boundary = cos_i * cos_h - Interval::c(side) * sin_i * sin_h;
    Interval::c(side) * Interval::c(0.5) * Interval::exact(width) * cos_h
        / cos_boundary.max_c(f64::from(MIN_COS))
}

fn boundary_offset(
    hit: Interval,
    side: f64,
    refracted: Interval2,
    tilt: Interval2,
    transmitted: Interval2,
) -> Interval {
    let ([sin_tau, cos_tau], [sin_tilt, cos_tilt]) = (refracted.0, tilt.0);
    let cos_rho = cos_tau * cos_tilt + Interval::c(side) * sin_tau * sin_tilt;
    let sin_rho = sin_tau * cos_tilt - Interval::c(side) * cos_tau * sin_tilt;
    hit * cos_rho / (cos_rho * transmitted.0[1] + sin_rho * transmitted.0[0]).max_c(f64::from(MIN_COS))
}

fn refracted_sine_gap(
    eta: f32,
    incidence: Interval2,
    local: Interval2,
    upper: Interval2,
    lower: Interval2,
) -> Interval {
    let eta = Interval::exact(eta);
    let (upper_sine, lower_sine) = (eta * upper.0[0], eta * lower.0[0]);
    let (upper_size, lower_size) = (upper_sine.abs(), lower_sine.abs());
    select(
        upper_size.hi <= 1.0 && lower_size.hi <= 1.0,
        upper_size.lo <= 1.0 && lower_size.lo <= 1.0,
        || vec![Interval::c(2.0) * eta * incidence.0[1] * local.0[0]],
        || vec![upper_sine.clamp_c(-1.0, 1.0) - lower_sine.clamp_c(-1.0, 1.0)],
    )[0]
}

fn refracted_angle_between(sine_gap: Interval, upper: Interval2, lower: Interval2) -> Interval {
    let ([sin_u, cos_u], [sin_l, cos_l]) = (upper.0, lower.0);
    let cos_between = cos_u * cos_l + sin_u * sin_l;
    let cos_sum = (cos_u + cos_l)
        .max((sine_gap * (sin_u + sin_l)).abs().sqrt())
        .max_c(f64::from(MIN_MAGNITUDE));
    let sin_between = sine_gap * (Interval::c(1.0) + cos_between) / cos_sum;
    Interval::atan2(sin_between, cos_between)
}

/// What the two boundary rays of a transmitted cone share: the central ray's incidence and
/// transmitted `(sin, cos)`, the boundary rays' angle to it (`half spread + tilt`), the half
/// spread and the normal tilt as `(sin, cos)`, the cone's width and the relative index.
struct BoundaryInputs {
    incidence: Interval2,
    transmitted: Interval2,
    local: Interval2,
    half: Interval2,
    tilt: Interval2,
    width: f32,
    index: f32,
}

/// One boundary ray of a transmitted cone after refraction: its incidence, its refracted
/// `(sin, cos)`, and its offset from the central transmitted ray.
struct BoundaryRay {
    incidence: Interval2,
    refracted: Interval2,
    offset: Interval,
}

/// The boundary ray on `side` (+1 upper, -1 lower): the steps of `refract_ray_cone` that both
/// boundary rays take (`boundary_incidence`, `refracted_sin_cos`, `boundary_hit`,
/// `boundary_offset`).
fn boundary_ray(inputs: &BoundaryInputs, side: f64) -> BoundaryRay {
    let incidence = boundary_incidence(inputs.incidence, inputs.local, side);
    let refracted = refracted_sin_cos(incidence, inputs.index);
    let hit = boundary_hit(inputs.width, side, inputs.incidence, inputs.half);
    BoundaryRay {
        incidence,
        refracted,
        offset: boundary_offset(hit, side, refracted, inputs.tilt, inputs.transmitted),
    }
}

/// The transmitted cone (its clamps cover the part of `eta sin i`'s interval above 1).
fn transmitted_cone(cone: RayCone, incidence: Interval2, facing_spread: f32, index: f32) -> Vec<Interval> {
    let limit = (Interval::c(f64::from(MAX_INCIDENCE_ANGLE))
        - Interval::atan2(incidence.0[0], incidence.0[1]))
    .max_c(0.0);
    let half_spread = (Interval::c(0.5) * Interval::exact(cone.spread_angle))
        .max(-limit)
        .min(limit);
    let tilt = normal_tilt(cone.width, facing_spread);
    let inputs = BoundaryInputs {
        incidence,
        transmitted: refracted_sin_cos(incidence, index),
        local: angle_sin_cos(half_spread + tilt),
        half: angle_sin_cos(half_spread),
        tilt: angle_sin_cos(tilt),
        width: cone.width,
        index,
    };
    let (upper, lower) = (boundary_ray(&inputs, 1.0), boundary_ray(&inputs, -1.0));
    let sine_gap = refracted_sine_gap(index, incidence, inputs.local, upper.incidence, lower.incidence);
    vec![
        upper.offset - lower.offset,
        refracted_angle_between(sine_gap, upper.refracted, lower.refracted) - Interval::c(2.0) * tilt,
        Interval::c(0.0),
    ]
}

/// Both branches of `refract_ray_cone` for one normal orientation (`facing_spread`).
fn refract_facing(
    &(cone, normal, direction, _, eta): &RefractArgs,
    cosine: Interval,
    facing_spread: f32,
) -> Vec<Interval> {
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let sin_t = Interval::exact(index) * incidence.0[0];
    select(
        sin_t.lo > 1.0,
        sin_t.hi > 1.0,
        || {
            vec![
                Interval::exact(cone.width),
                Interval::exact(cone.spread_angle) + Interval::c(2.0) * Interval::exact(facing_spread),
                Interval::c(1.0),
            ]
        },
        || transmitted_cone(cone, incidence, facing_spread, index),
    )
}

/// `rf_refract_ray_cone` in interval arithmetic, for the normal's orientation as the ray sees it
/// ([`either_facing`]).
fn enclosure(args: &RefractArgs) -> Vec<Interval> {
    either_facing(args, refract_facing)
}

/// Boundary rays that land and leave at cosines of at least 0.05 (away from grazing and from the
/// critical angle, where the f32 inputs' rounding is amplified by up to 20 per cosine).
fn well_conditioned(traced: &Scattered) -> bool {
    traced.min_landing_cos >= 0.05 && traced.min_leaving_cos >= 0.05
}

/// Boundary rays that land and leave at cosines of at least 0.2: the f32 evaluation's error is
/// then at most 30 operations x 5 x 5 x 6e-8 < 1e-4 relative ([`COMFORTABLE_F32_ERROR`]).
fn comfortably_conditioned(traced: &Scattered) -> bool {
    traced.min_landing_cos >= 0.2 && traced.min_leaving_cos >= 0.2
}

/// f32 error bound for [`comfortably_conditioned`] cases.
const COMFORTABLE_F32_ERROR: f64 = 1.0e-4;

/// `sign * 10^e`, the sign negative with probability `negative`.
fn log_signed(low: f64, high: f64, negative: f64) -> BoxedStrategy<f64> {
    (low..high, 0.0f64..1.0)
        .prop_map(move |(e, coin)| {
            if coin < negative {
                -(10f64.powf(e))
            } else {
                10f64.powf(e)
            }
        })
        .boxed()
}

/// Index ratios: below 1, above 1, glass out and in.
fn eta() -> BoxedStrategy<f64> {
    prop_oneof![0.4f64..0.95, 1.05f64..2.5, Just(1.0 / 1.5), Just(1.5)].boxed()
}

/// A reference of `rf_refract_ray_cone`: flat interfaces.
fn refract_flat() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "flat interfaces: the cone's two boundary rays refracted exactly by Snell's law in f64 and measured across the refracted central ray (RTG II ch. 10's construction is exact there)",
        || (0.0f64..1.5, -6.0f64..3.0, log_signed(-7.0, 0.0, 0.2), eta()).boxed(),
        |&(incidence, width, spread, eta), refract| {
            let case = Case::new(incidence, 10f64.powf(width), spread, eta);
            let traced = case.trace(0.0).filter(well_conditioned)?;
            let refracted = refract(case.arguments());
            // About 30 operations, amplified by at most 20 x 20 (the two cosines of
            // `well_conditioned`): 30 * 400 * 6e-8 < 1e-3 relative.
            let flag = Deviation::new(f64::from(u8::from(refracted.total_internal_reflection)), 0.0);
            let width = Deviation::new(relative(refracted.cone.width, traced.width), 1.0e-3);
            let spread = Deviation::new(relative(refracted.cone.spread_angle, traced.spread), 1.0e-3);
            Some(flag.and(width).and(spread))
        },
    )
}

/// A reference of `rf_refract_ray_cone`: spherical interfaces.
fn refract_curved() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "convex and concave unit spheres: the boundary rays refracted exactly at their own hits, the normal spread taken from those hits; within 4 x (width / cos i) relative, the spheres' sag",
        || (any::<bool>(), prop_oneof![0.4f64..0.95, 1.05f64..2.5], 0.0f64..1.2, -5.0f64..-2.0, -0.02f64..0.02).boxed(),
        |&(convex, eta, incidence, width, spread), refract| {
            let curvature = if convex { 1.0 } else { -1.0 };
            let mut case = Case::new(incidence, 10f64.powf(width), spread, eta);
            let traced = case.trace(curvature).filter(well_conditioned)?;
            case.normal_spread = traced.normal_spread as f32;
            let footprint = f64::from(case.cone.width) / case.incidence().cos();
            let refracted = refract(case.arguments());
            // The crate refracts the boundary rays where they meet the tangent plane, at normals
            // tilted by -+beta / 2; the sphere's hits differ from those by its sag, so the two
            // agree to second order in the footprint x = width / cos i (in radii). 4 x holds with
            // room for the cosines (>= 0.05) and lies far below the first-order effect (beta ~ x)
            // it checks; 1e-3 is the flat case's f32 bound.
            let bound = 4.0 * footprint + 1.0e-3;
            let width = Deviation::new(relative(refracted.cone.width, traced.width), bound);
            let spread_error = (f64::from(refracted.cone.spread_angle) - traced.spread).abs()
                / (traced.spread.abs() + traced.normal_spread.abs());
            Some(width.and(Deviation::new(spread_error, bound)))
        },
    )
}

/// A reference of `rf_refract_ray_cone`: eta 1.
fn refract_index_one() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::Identity,
        "eta = 1 on a flat surface changes nothing, at any incidence up to grazing, for diverging, converging and negative-width cones narrow enough to meet the surface",
        || (0.0f64..f64::from(MAX_INCIDENCE_ANGLE), any::<bool>(), -6.0f64..3.0, any::<bool>(), -9.0f64..-1.0).boxed(),
        |&(incidence, negative_width, width, negative_spread, spread), refract| {
            let room = 1.8 * (f64::from(MAX_INCIDENCE_ANGLE) - incidence);
            let sign = |negative: bool| if negative { -1.0 } else { 1.0 };
            let case = Case::new(
                incidence,
                sign(negative_width) * 10f64.powf(width),
                sign(negative_spread) * 10f64.powf(spread).min(room),
                1.0,
            );
            let same = refract(case.arguments()).cone;
            // Every quantity is then a rotation of the inputs: the flat case's 1e-3 bounds the
            // f32 rounding.
            let width = Deviation::new(relative(same.width, f64::from(case.cone.width)), 1.0e-3);
            let spread = Deviation::new(relative(same.spread_angle, f64::from(case.cone.spread_angle)), 1.0e-3);
            Some(width.and(spread))
        },
    )
}

/// Leading relative corrections to the first-order refraction of a cone of half spread `h` on a
/// flat interface (incidence `i`, index ratio `eta`), from the Taylor expansions of the exact maps:
/// with `tau(theta) = asin(eta sin theta)` and its derivatives `d1, d2, d3` at `i`, the spread
/// `tau(i + h) - tau(i - h)` is `2 h d1 (1 + (h^2 / 6) d3 / d1)`, and the width
/// `w cos(h) (f(i + h) + f(i - h)) / 2` with `f(theta) = cos tau / (cos theta cos(tau - t))` is
/// `w (cos t / cos i) (1 + (h^2 / 2) (f'' / f - 1))`. Returns the two corrections' magnitudes.
fn second_order_corrections(incidence: f64, eta: f64, h: f64) -> (f64, f64) {
    let sin_t = eta * incidence.sin();
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let tan_t = sin_t / cos_t;
    let d1 = eta * incidence.cos() / cos_t;
    let d2 = tan_t * (d1 * d1 - 1.0);
    let d3_over_d1 = (d1 * d1 - 1.0) * (1.0 / (cos_t * cos_t) + 2.0 * tan_t * tan_t);
    let g1 = -tan_t * d1 + incidence.tan();
    let g2 = -d1 * d1 / (cos_t * cos_t) - tan_t * d2 + 1.0 / incidence.cos().powi(2) + d1 * d1;
    (
        h * h / 6.0 * d3_over_d1.abs(),
        h * h / 2.0 * (g2 + g1 * g1 - 1.0).abs(),
    )
}

/// A reference of `rf_refract_ray_cone`: the first-order formulas and the way back out.
fn refract_first_order() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::ClosedForm,
        "small cones on flat interfaces: spread' = m spread with m = eta cos i / cos t, width' = width cos t / cos i (RTG II ch. 10, first order) within twice the leading second-order correction; refracted back out (1 / eta) the cone returns",
        || (prop_oneof![0.4f64..0.95, 1.05f64..2.5], 0.0f64..1.5, -6.0f64..3.0, log_signed(-7.0, -2.0, 0.5)).boxed(),
        |&(eta, incidence, width, spread), refract| {
            let case = Case::new(incidence, 10f64.powf(width), spread, eta);
            case.trace(0.0).filter(comfortably_conditioned)?;
            let (incidence, eta) = (case.incidence(), f64::from(case.eta));
            let h = 0.5 * f64::from(case.cone.spread_angle);
            let (spread_correction, width_correction) = second_order_corrections(incidence, eta, h);
            let sin_t = eta * incidence.sin();
            let cos_t = (1.0 - sin_t * sin_t).sqrt();
            let m = eta * incidence.cos() / cos_t;
            let inside = refract(case.arguments()).cone;
            let back = Case {
                direction: Vec3::new(sin_t as f32, 0.0, -cos_t as f32),
                cone: inside,
                normal_spread: 0.0,
                eta: 1.0 / case.eta,
            };
            let back_h = 0.5 * f64::from(inside.spread_angle);
            let (back_spread, back_width) = second_order_corrections(back.incidence(), f64::from(back.eta), back_h);
            let corrections = [spread_correction, width_correction, back_spread, back_width];
            // Higher orders are negligible below corrections of 1e-3.
            if corrections.iter().any(|&c| c > 1.0e-3) {
                return None;
            }
            back.trace(0.0).filter(comfortably_conditioned)?;
            let spread_deviation = Deviation::new(
                relative(inside.spread_angle, m * f64::from(case.cone.spread_angle)),
                2.0 * spread_correction + COMFORTABLE_F32_ERROR,
            );
            let width_deviation = Deviation::new(
                relative(inside.width, f64::from(case.cone.width) * cos_t / incidence.cos()),
                2.0 * width_correction + COMFORTABLE_F32_ERROR,
            );
            // The first-order maps are each other's inverses: the way back restores the cone
            // within both passes' corrections.
            let out = refract(back.arguments()).cone;
            let round_trip = relative(out.width, f64::from(case.cone.width))
                .max(relative(out.spread_angle, f64::from(case.cone.spread_angle)));
            let round_trip_bound = 2.0 * corrections.iter().sum::<f64>() + 2.0 * COMFORTABLE_F32_ERROR;
            Some(spread_deviation.and(width_deviation).and(Deviation::new(round_trip, round_trip_bound)))
        },
    )
}

/// A reference of `rf_refract_ray_cone`: the OptiX Toolkit at normal incidence.
fn refract_optix() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "normal incidence on curved surfaces: the OptiX Toolkit's thin form (n_out / n_in) (angle + k |w|) - k |w| with beta = k |w|, within (eta q)^3 for q = (spread + beta) / 2; the width passes unchanged",
        normal_incidence,
        |&inputs, refract| {
            let args = normal_incidence_args(inputs);
            let refracted = refract(args);
            let (cone, _, _, beta, eta) = args;
            let (eta, spread, beta, width) = (f64::from(eta), f64::from(cone.spread_angle), f64::from(beta), cone.width);
            let thin_form = eta * (spread + beta) - beta;
            // The construction gives 2 asin(eta sin q) - beta, which differs from the thin form by
            // O(q^3): below (eta q)^3; plus 1e-6 relative for the f32 rounding.
            let q = 0.5 * (spread + beta).abs();
            let bound = (eta * q).powi(3) + 1.0e-6 * (thin_form.abs() + beta.abs());
            let spread_deviation = Deviation::within(f64::from(refracted.cone.spread_angle), thin_form, bound);
            Some(spread_deviation.and(Deviation::within(f64::from(refracted.cone.width), f64::from(width), 0.0)))
        },
    )
}

/// A reference of `rf_refract_ray_cone`: negated cones.
fn refract_negated() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::Identity,
        "(w, s) and (-w, -s) describe the same cone (the boundary rays swap sides): the refracted cones are each other's negatives bit for bit, on curved surfaces too",
        || (0.0f64..1.5, -6.0f64..3.0, -1.0f64..1.0, 0.3f64..3.0, -0.1f64..0.1).boxed(),
        |&(incidence, width, spread, eta, normal_spread), refract| {
            let case = Case {
                normal_spread: normal_spread as f32,
                ..Case::new(incidence, 10f64.powf(width), spread, eta)
            };
            let negated = Case {
                cone: RayCone {
                    width: -case.cone.width,
                    spread_angle: -case.cone.spread_angle,
                },
                ..case
            };
            let (a, b) = (refract(case.arguments()), refract(negated.arguments()));
            let same_flag = a.total_internal_reflection == b.total_internal_reflection;
            let negatives = a.total_internal_reflection
                || (a.cone.width.to_bits() == (-b.cone.width).to_bits()
                    && a.cone.spread_angle.to_bits() == (-b.cone.spread_angle).to_bits());
            Some(Deviation::new(f64::from(u8::from(!(same_flag && negatives))), 0.0))
        },
    )
}

/// A reference of `rf_refract_ray_cone`: total internal reflection.
fn refract_total_internal_reflection() -> Reference<RefractArgs, RefractedRayCone> {
    Reference::new(
        Kind::Identity,
        "past the critical angle (eta sin i > 1) the central ray is reflected: the flag is set and the cone is the reflected one, (w, s + 2 beta), beta negated where the normal faces away from the ray",
        || (1.05f64..3.0, 0.0f64..1.0, -1.0f64..1.0, -0.5f64..0.5, -0.1f64..0.1, any::<bool>()).boxed(),
        |&(eta, past, width, spread, beta, behind), refract| {
            // An incidence between the critical angle (plus a margin for rounding) and grazing.
            let critical = (1.0 / eta).asin() + 1.0e-4;
            let incidence = critical + past * (0.5 * std::f64::consts::PI - 1.0e-4 - critical);
            let case = Case {
                normal_spread: beta as f32,
                ..Case::new(incidence, width, spread, eta)
            };
            let normal = if behind { Vec3::NEG_Z } else { Vec3::Z };
            let (cone, _, d, normal_spread, eta) = case.arguments();
            let got = refract((cone, normal, d, normal_spread, eta));
            let facing = if behind { -f64::from(normal_spread) } else { f64::from(normal_spread) };
            let spread = f64::from(cone.spread_angle) + 2.0 * facing;
            // One sum rounds (the doubling is exact).
            let flag = Deviation::new(f64::from(u8::from(!got.total_internal_reflection)), 0.0);
            let width = Deviation::within(f64::from(got.cone.width), f64::from(cone.width), 0.0);
            Some(flag.and(width).and(Deviation::within(f64::from(got.cone.spread_angle), spread, U * spread.abs())))
        },
    )
}
