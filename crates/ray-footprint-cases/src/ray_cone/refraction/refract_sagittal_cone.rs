//! The proof of [`refract_sagittal_cone`](ray_footprint::ray_cone::refract_sagittal_cone): its record,
//! its enclosure and its references: the sagittal boundary rays traced exactly in 3-D through
//! spherical interfaces, refracted and totally internally reflected, and the OptiX Toolkit's thin
//! form at normal incidence.

use crate::degenerate::{cone, value, HEAD_ON, IN_PLANE};
use crate::exact;
use crate::ray_cone::plane_of_incidence::quadratic_roots;
use crate::ray_cone::refraction::shared::{
    either_facing, incidence_sin_cos, normal_incidence, normal_incidence_args, normal_tilt,
    refracted_sin_cos, refraction_cases, refraction_conventions, refraction_decided, relative, Case,
    RefractArgs, REFRACTION_UNDECIDED, THIRTY_DEGREES,
};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{select, Interval};

/// The record of `rf_refract_sagittal_cone`: the enclosure of the sagittal section.
pub fn record() -> Record<RefractArgs, RayCone> {
    let z = Vec3::Z;
    let past_critical = Vec3::new(0.8, 0.0, -0.6);
    Record::new(
        Module::RayCone,
        "refract_sagittal_cone",
        |(cone, n, d, beta, eta)| rc::refract_sagittal_cone(cone, n, d, beta, eta),
        refraction_cases,
    )
    .conditioned(REFRACTION_UNDECIDED, refraction_decided)
    .enclosure(enclosure)
    .reference(sagittal_curved())
    .reference(sagittal_normal_incidence())
    .reference(sagittal_total_internal_reflection())
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
        |cone: RayCone, s| RayCone {
            width: cone.width / s,
            ..cone
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
                "(width, 0)",
                (cone(0.5, 0.0), z, HEAD_ON, 0.0, 1.5),
                vec![0.5, 0.0],
            ),
            value(
                "zero cone",
                "zero cone",
                (cone(0.0, 0.0), z, THIRTY_DEGREES, 0.0, 1.5),
                vec![0.0, 0.0],
            ),
            value(
                "central ray past the critical angle (sin i = 0.8, eta 1.5)",
                "the reflected section (width, spread + 2 cos i beta)",
                (cone(0.25, 0.125), z, past_critical, 0.0625, 1.5),
                vec![0.25, 0.125 + 2.0 * 0.6 * 0.0625],
            ),
            value(
                "negative width (past a focus), 30 degrees, eta 1.5",
                "beta takes the width's sign: eta spread - (eta cos i - cos t) beta",
                (cone(-0.01, 0.002), z, THIRTY_DEGREES, 0.01, 1.5),
                vec![
                    -0.01,
                    1.5 * 0.002 - (1.5 * 0.866_025_4 - (1.0f32 - 2.25 * 0.25).sqrt()) * 0.01,
                ],
            ),
            value(
                "ray in the surface plane (dot(n, d) = 0), eta 0.5",
                "eta spread - cos t beta, cos t = sqrt(1 - eta^2)",
                (cone(0.01, 0.002), z, IN_PLANE, 0.01, 0.5),
                vec![0.01, 0.5 * 0.002 - 0.75f32.sqrt() * 0.01],
            ),
        ]
        .into_iter()
        .chain(refraction_conventions())
        .collect(),
    )
}

/// `rf_refract_sagittal_cone` for one normal orientation (`facing_spread`): the hull of the
/// reflected and the refracted section where `eta sin i` is within rounding of 1.
fn sagittal_facing(
    &(cone, normal, direction, _, eta): &RefractArgs,
    cosine: Interval,
    facing_spread: f32,
) -> Vec<Interval> {
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let turn = Interval::c(2.0) * normal_tilt(cone.width, facing_spread);
    let spread = Interval::exact(cone.spread_angle);
    let sin_t = Interval::exact(index) * incidence.0[0];
    let leaving_spread = select(
        sin_t.lo > 1.0,
        sin_t.hi > 1.0,
        || vec![spread + Interval::c(2.0) * incidence.0[1] * turn],
        || {
            let transmitted = refracted_sin_cos(incidence, index);
            let index = Interval::exact(index);
            vec![index * spread + (index * incidence.0[1] - transmitted.0[1]) * turn]
        },
    )[0];
    vec![Interval::exact(cone.width), leaving_spread]
}

/// `rf_refract_sagittal_cone` in interval arithmetic, for the normal's orientation as the ray sees
/// it ([`either_facing`]).
fn enclosure(args: &RefractArgs) -> Vec<Interval> {
    either_facing(args, sagittal_facing)
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

/// A reference of `rf_refract_sagittal_cone`: spherical interfaces.
fn sagittal_curved() -> Reference<RefractArgs, RayCone> {
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

/// A reference of `rf_refract_sagittal_cone`: the OptiX Toolkit at normal incidence.
fn sagittal_normal_incidence() -> Reference<RefractArgs, RayCone> {
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

/// A reference of `rf_refract_sagittal_cone`: total internal reflection.
fn sagittal_total_internal_reflection() -> Reference<RefractArgs, RayCone> {
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
