//! References of the refraction and roughness section: the cone's two boundary rays traced
//! exactly in f64 through flat and spherical interfaces, the first-order formulas, the OptiX
//! Toolkit's thin form, the limit cases, and the roughness mapping's closed form.

use super::{quadratic_roots, rotated, scatter_cone, snell, Scattered, Surface};
use crate::exact;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use glam::{DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{RayCone, RefractedRayCone, MAX_INCIDENCE_ANGLE, MIN_ROUGHNESS_DENOMINATOR};

/// The arguments of `refract_ray_cone`.
type Args = (RayCone, Vec3, Vec3, f32, f32);

/// The f32 inputs of a refraction: the direction at `incidence` in the xz plane (normal +Z), the
/// cone, the normal spread and eta.
#[derive(Clone, Copy, Debug)]
struct Case {
    direction: Vec3,
    cone: RayCone,
    normal_spread: f32,
    eta: f32,
}

impl Case {
    fn new(incidence: f64, width: f64, spread: f64, eta: f64) -> Case {
        Case {
            direction: Vec3::new(incidence.sin() as f32, 0.0, -incidence.cos() as f32),
            cone: RayCone {
                width: width as f32,
                spread_angle: spread as f32,
            },
            normal_spread: 0.0,
            eta: eta as f32,
        }
    }

    /// The incidence angle of the f32 direction, exactly.
    fn incidence(&self) -> f64 {
        f64::from(self.direction.x).atan2(-f64::from(self.direction.z))
    }

    /// The cone's boundary rays traced exactly through the interface of `curvature` (the plane of
    /// incidence is the xz plane), from the f32 inputs.
    fn trace(&self, curvature: f64) -> Option<Scattered> {
        let eta = f64::from(self.eta);
        let incidence = self.incidence();
        let cone = (f64::from(self.cone.width), f64::from(self.cone.spread_angle));
        scatter_cone(
            Surface { curvature },
            DVec2::new(incidence.sin(), -incidence.cos()),
            0.0,
            cone,
            |d, n| snell(d, n, eta),
            rotated,
        )
    }

    fn arguments(&self) -> Args {
        (self.cone, Vec3::Z, self.direction, self.normal_spread, self.eta)
    }
}

/// `|a - b| / |b|`.
fn relative(a: f32, b: f64) -> f64 {
    (f64::from(a) - b).abs() / b.abs()
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

/// `rf_refract_ray_cone`: flat interfaces.
pub(in crate::ray_cone) fn refract_flat() -> Reference<Args, RefractedRayCone> {
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

/// `rf_refract_ray_cone`: spherical interfaces.
pub(in crate::ray_cone) fn refract_curved() -> Reference<Args, RefractedRayCone> {
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

/// `rf_refract_ray_cone`: eta 1.
pub(in crate::ray_cone) fn refract_index_one() -> Reference<Args, RefractedRayCone> {
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

/// `rf_refract_ray_cone`: the first-order formulas and the way back out.
pub(in crate::ray_cone) fn refract_first_order() -> Reference<Args, RefractedRayCone> {
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

/// Normal incidence on a curved surface: an index ratio, a curvature, `log10` of the width and a
/// spread, small enough for the OptiX Toolkit's thin form.
fn normal_incidence() -> BoxedStrategy<(f64, f64, f64, f64)> {
    (0.4f64..2.5, -10.0f64..10.0, -6.0f64..-3.0, -2.0e-3f64..2.0e-3).boxed()
}

/// The f32 arguments of a [`normal_incidence`] case: the cone head on at `+z`, the normal spread
/// `curvature * width` (the thin form's `k |w|`).
fn normal_incidence_args((eta, curvature, width, spread): (f64, f64, f64, f64)) -> Args {
    let width = 10f64.powf(width) as f32;
    let beta = (curvature * f64::from(width)) as f32;
    let cone = RayCone {
        width,
        spread_angle: spread as f32,
    };
    (cone, Vec3::Z, Vec3::NEG_Z, beta, eta as f32)
}

/// `rf_refract_ray_cone`: the OptiX Toolkit at normal incidence.
pub(in crate::ray_cone) fn refract_optix() -> Reference<Args, RefractedRayCone> {
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

/// `rf_refract_ray_cone`: negated cones.
pub(in crate::ray_cone) fn refract_negated() -> Reference<Args, RefractedRayCone> {
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

/// `rf_refract_ray_cone`: total internal reflection.
pub(in crate::ray_cone) fn refract_total_internal_reflection() -> Reference<Args, RefractedRayCone> {
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

/// A cone's sagittal section after a spherical surface, traced exactly in 3-D: its spread and
/// width across the scattered central ray, the normals' turn between its boundary hits, and the
/// smallest cosine at which a boundary ray meets the surface.
struct SagittalTrace {
    width: f64,
    spread: f64,
    normal_spread: f64,
    min_landing_cos: f64,
}

/// The sagittal section of the cone `(width, spread)` whose central ray `d` (in the xz plane,
/// `d.z < 0`) meets, at the origin, the sphere of signed `curvature` with its normal `+z` there
/// (centre `(0, 0, -1 / curvature)`: convex towards the ray for `curvature > 0`). Each boundary
/// ray crosses the y axis at `+-width / 2`, turned by `+-spread / 2` about the axis across `d`
/// in the xz plane, meets the sphere where it is nearest that crossing, and is scattered there
/// (`scatter`, from its direction and the unit normal at its hit, facing the ray). The section is
/// symmetric about the xz plane, so the two scattered boundary rays are mirror images: the
/// spread is `2 asin(r . y)` of the upper one and the width twice its `y` where it crosses the
/// plane through the origin across the scattered central ray `scatter(d, z)`.
fn trace_sagittal(
    d: DVec3,
    curvature: f64,
    (width, spread): (f64, f64),
    scatter: impl Fn(DVec3, DVec3) -> Option<DVec3>,
) -> Option<SagittalTrace> {
    let radius = 1.0 / curvature;
    let centre = DVec3::new(0.0, 0.0, -radius);
    let start = DVec3::new(0.0, 0.5 * width, 0.0);
    let direction = d * (0.5 * spread).cos() + DVec3::Y * (0.5 * spread).sin();
    // |start + s direction - centre|^2 = radius^2: s^2 + 2 b s + c = 0, c = |start|^2 + 2 radius
    // start.z (zero) without cancellation; the root nearest 0.
    let offset = start - centre;
    let b = offset.dot(direction);
    let c = start.length_squared() + 2.0 * radius * start.z;
    let [first, second] = quadratic_roots(b, c)?;
    let nearest = if second.abs() < first.abs() { second } else { first };
    let hit = start + direction * nearest;
    let normal = (hit - centre) / radius;
    let central = scatter(d, DVec3::Z)?;
    let leaving = scatter(direction, normal)?;
    let crossing = hit - leaving * (hit.dot(central) / leaving.dot(central));
    Some(SagittalTrace {
        width: 2.0 * crossing.y,
        spread: 2.0 * leaving.y.asin(),
        normal_spread: 2.0 * normal.y.asin(),
        min_landing_cos: direction.dot(normal).abs(),
    })
}

/// The sagittal section checked against its exact trace: the section passes its width on and its
/// spread within `bound` of the spread and the normal turn it has to follow.
fn sagittal_deviation(got: RayCone, traced: &SagittalTrace, bound: f64) -> Deviation {
    let width = Deviation::new(relative(got.width, traced.width), bound);
    let spread_error = (f64::from(got.spread_angle) - traced.spread).abs()
        / (traced.spread.abs() + traced.normal_spread.abs());
    width.and(Deviation::new(spread_error, bound))
}

/// `rf_refract_sagittal_cone`: spherical interfaces.
pub(in crate::ray_cone) fn sagittal_curved() -> Reference<Args, RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "convex and concave unit spheres: the sagittal section's two boundary rays (across the plane of incidence) refracted exactly in 3-D at their own hits, the normal spread taken from those hits; within 4 (|w| + |spread|) / (cos i cos t) relative, the second-order terms",
        || (any::<bool>(), prop_oneof![0.4f64..0.95, 1.05f64..2.5], 0.0f64..1.2, -5.0f64..-3.0, -2.0e-3f64..2.0e-3).boxed(),
        |&(convex, eta, incidence, width, spread), refract| {
            let curvature = if convex { 1.0 } else { -1.0 };
            let mut case = Case::new(incidence, 10f64.powf(width), spread, eta);
            let eta = f64::from(case.eta);
            let (sin_i, cos_i) = case.incidence().sin_cos();
            let cos_t = (1.0 - eta * eta * sin_i * sin_i).max(0.0).sqrt();
            if cos_t < 0.3 {
                return None;
            }
            let d = case.direction.as_dvec3();
            let cone = (f64::from(case.cone.width), f64::from(case.cone.spread_angle));
            let traced = trace_sagittal(d, curvature, cone, |d, n| exact::snell(d, n, eta))?;
            case.normal_spread = traced.normal_spread as f32;
            let refracted = refract(case.arguments());
            // Coddington's equation is the first-order term; the sphere's sag, the boundary rays'
            // own incidence and the asin of the spread are second order in the width and the
            // spread (in radii), magnified by at most 1 / (cos i cos t). 1e-4 for the f32 rounding
            // of a handful of operations.
            let bound = 4.0 * (cone.0.abs() + cone.1.abs()) / (cos_i * cos_t) + 1.0e-4;
            Some(sagittal_deviation(refracted, &traced, bound))
        },
    )
}

/// `rf_refract_sagittal_cone`: the OptiX Toolkit at normal incidence.
pub(in crate::ray_cone) fn sagittal_normal_incidence() -> Reference<Args, RayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "normal incidence on curved surfaces, where the two sections are one: the OptiX Toolkit's thin form (n_out / n_in) (angle + k |w|) - k |w| with beta = k |w|, to f32 rounding; the width passes unchanged",
        normal_incidence,
        |&inputs, refract| {
            let args = normal_incidence_args(inputs);
            let got = refract(args);
            let (cone, _, _, beta, eta) = args;
            let (eta, spread, beta, width) = (f64::from(eta), f64::from(cone.spread_angle), f64::from(beta), cone.width);
            let thin_form = eta * (spread + beta) - beta;
            // cos i = cos t = 1 exactly; two products and two sums round: gamma(4) of the terms.
            let bound = gamma(4) * (eta * spread.abs() + (eta + 1.0) * beta.abs());
            let spread_deviation = Deviation::within(f64::from(got.spread_angle), thin_form, bound);
            Some(spread_deviation.and(Deviation::within(f64::from(got.width), f64::from(width), 0.0)))
        },
    )
}

/// `rf_refract_sagittal_cone`: total internal reflection.
pub(in crate::ray_cone) fn sagittal_total_internal_reflection() -> Reference<Args, RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "past the critical angle (eta sin i > 1) on convex and concave unit spheres: the sagittal boundary rays reflected exactly in 3-D at their own hits, against spread + 2 cos i beta (the sagittal mirror equation); within 4 (|w| + |spread|) / cos i relative",
        || (any::<bool>(), 1.05f64..3.0, 0.0f64..1.0, -5.0f64..-3.0, -2.0e-3f64..2.0e-3).boxed(),
        |&(convex, eta, past, width, spread), refract| {
            let curvature = if convex { 1.0 } else { -1.0 };
            // An incidence between the critical angle (plus a margin for rounding) and 1.3 rad.
            let critical = (1.0 / eta).asin() + 1.0e-4;
            let incidence = critical + past * (1.3 - critical).max(0.0);
            let mut case = Case::new(incidence, 10f64.powf(width), spread, eta);
            let d = case.direction.as_dvec3();
            let cone = (f64::from(case.cone.width), f64::from(case.cone.spread_angle));
            let traced = trace_sagittal(d, curvature, cone, |d, n| Some(exact::mirrored(d, n)))?;
            case.normal_spread = traced.normal_spread as f32;
            let reflected = refract(case.arguments());
            // As the refraction: second order in the width and the spread, over cos i.
            let bound = 4.0 * (cone.0.abs() + cone.1.abs()) / case.incidence().cos() + 1.0e-4;
            (traced.min_landing_cos > 0.05).then(|| sagittal_deviation(reflected, &traced, bound))
        },
    )
}

/// `rf_roughness_spread_angle`: the closed form.
pub(in crate::ray_cone) fn roughness_closed_form() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::ClosedForm,
        "JCGT 2021's mapping in f64: 2 sqrt(0.5 r^4 / max(1 - r^4, MIN_ROUGHNESS_DENOMINATOR)) for roughness r in [0, 1]",
        || prop_oneof![0.0f32..1.0, Just(1.0f32), 0.9f32..1.0].boxed(),
        |&r, roughness_spread_angle| {
            let got = roughness_spread_angle((r,));
            let r = f64::from(r);
            let alpha2 = r.powi(4);
            let denominator = (1.0 - alpha2).max(f64::from(MIN_ROUGHNESS_DENOMINATOR));
            let expected = 2.0 * (0.5 * alpha2 / denominator).sqrt();
            // r^2 and its square: 3 u relative on alpha^2, so 1 - alpha^2 is off by
            // 3 u alpha^2 + u (its own rounding) absolute; the quotient's and the product's
            // roundings add 2 u; the square root halves the relative error and adds u.
            let variance = gamma(5) + (3.0 * U * alpha2 + U) / denominator;
            let bound = (0.5 * variance + U) * expected;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}

/// `rf_roughness_spread_angle`: the small-roughness limit.
pub(in crate::ray_cone) fn roughness_small() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::Identity,
        "the small-roughness limit its source states, sqrt(2) r^2: within r^4 / (1 - r^4) relative for r <= 0.3",
        || (0.0f32..0.3).boxed(),
        |&r, roughness_spread_angle| {
            let got = roughness_spread_angle((r,));
            let r = f64::from(r);
            let limit = std::f64::consts::SQRT_2 * r * r;
            // 1 / sqrt(1 - x) - 1 <= x / (1 - x) for x = r^4 < 1; the f32 rounding (above) is
            // below 8 u here.
            let bound = (r.powi(4) / (1.0 - r.powi(4)) + 8.0 * U) * limit;
            Some(Deviation::within(f64::from(got), limit, bound))
        },
    )
}

/// `rf_roughness_spread_angle`: growth with roughness.
pub(in crate::ray_cone) fn roughness_monotone() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::Identity,
        "the spread never shrinks as roughness grows: r < r' in [0, 1], at least 1e-3 apart, give spread(r) <= spread(r')",
        || (0.0f32..0.999, 0.0f32..1.0).boxed(),
        |&(r, share), roughness_spread_angle| {
            let larger = (r + 1.0e-3 + share * (1.0 - 1.0e-3 - r)).min(1.0);
            let shrink = roughness_spread_angle((r,)) - roughness_spread_angle((larger,));
            Some(Deviation::new(f64::from(shrink.max(0.0)), 0.0))
        },
    )
}
