//! The proof of [`refract_ray_diff`](ray_footprint::ray_diff::refract_ray_diff): its record, its
//! enclosure and its reference.

use crate::degenerate::{parts, value};
use crate::exact::{derivative, mirrored, snell};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::reflection::reflect_ray_diff;
use crate::ray_diff::reflection::shared::{changes, non_unit, surface_hit};
use crate::ray_diff::rows::direction_dx;
use crate::ray_diff::strategy::{derivatives3, ray_diff};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::normal_and_direction;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives3, RayDiff, RefractedRayDiff, DIFF_MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval3, Interval};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// The record of `rf_refract_ray_diff`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let flat = Derivatives3::default();
    Record::new(
        Module::RayDiff,
        "refract_ray_diff",
        |(diff, d, n, dn, eta)| rd::refract_ray_diff(diff, d, n, dn, eta),
        // Within rounding of the critical angle (the enclosure of `k` contains 0) either branch is
        // right and the flag's tolerance would be vacuous: those cases are checked separately.
        || {
            let eta = one_of![4 => uniform(0.3, 3.0), 1 => Just(1.0f32), 1 => Just(0.0f32), 1 => uniform(0.0, 0.01)];
            (ray_diff(), normal_and_direction(), derivatives3(), eta)
                .prop_map(|(diff, (n, d), dn, eta)| (diff, d, n, dn, eta))
                .boxed()
        },
    )
    .conditioned(
        "within rounding of the critical angle (k = 1 - eta^2 (1 - dot(D, N)^2) encloses 0): the \
         refracted and the reflected branch are both right",
        |args| !refraction_determinant(args).contains_zero(),
    )
    .enclosure(enclosure)
    .found(
        "the sign of the amplified normal term at exactly the critical angle: dot(T, N) = -0 was clamped to +DIFF_MIN_COS where every angle just short of it gives -DIFF_MIN_COS; found by `refraction_keeps_its_sign_at_the_critical_angle`",
    )
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "everything turned: the differential turned",
        |&(diff, d, n, dn, eta): &(RayDiff, Vec3, Vec3, Derivatives3, f32), r| (turned(diff, r), r * d, r * n, turned3(dn, r), eta),
        |refracted: RefractedRayDiff, r| RefractedRayDiff {
            diff: turned(refracted.diff, r.transpose()),
            ..refracted
        },
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the x and y parts exchanged",
        |&(diff, d, n, dn, eta): &(RayDiff, Vec3, Vec3, Derivatives3, f32)| (swapped(diff), d, n, swapped3(dn), eta),
        |refracted: RefractedRayDiff| RefractedRayDiff {
            diff: swapped(refracted.diff),
            ..refracted
        },
    ))
    .fuzz(|d| (d.ray_diff(), d.unit(), d.unit(), d.derivatives3(), d.scalar()))
    .degenerate(vec![
        value(
            "ray in the surface plane, eta = 1",
            "dot(T, N) = 0 clamped to DIFF_MIN_COS: dT = 0 here, no reflection",
            (direction_dx(z), x, z, flat, 1.0),
            [parts(RayDiff::ZERO), vec![0.0]].concat(),
        ),
        value(
            "ray in the surface plane, eta = 1.5",
            "total internal reflection: flag set, the reflected differential",
            (direction_dx(z), x, z, flat, 1.5),
            [parts(direction_dx(-z)), vec![1.0]].concat(),
        ),
        value(
            "head-on, eta = 1 (matched indices)",
            "dD unchanged (mu = 0, dmu = 0), no reflection",
            (direction_dx(x), -z, z, flat, 1.0),
            [parts(direction_dx(x)), vec![0.0]].concat(),
        ),
    ])
}

type RefractArgs = (RayDiff, Vec3, Vec3, Derivatives3, f32);

/// The refracted branch, for the part of `k`'s interval that is `>= 0`.
fn refracted(&(diff, direction, normal, dn, eta): &RefractArgs, k: Interval) -> Vec<Interval> {
    let (d, n, eta) = (interval3(direction), interval3(normal), Interval::exact(eta));
    let cosine = d.dot(n);
    let root = Interval {
        lo: k.lo.max(0.0),
        ..k
    }
    .sqrt();
    // A magnitude with the sign of `cosine`: both signs where `cosine` straddles 0.
    let with_cosine_sign = |magnitude: Interval| {
        if cosine.hi <= 0.0 {
            -magnitude
        } else if cosine.lo > 0.0 {
            magnitude
        } else {
            magnitude.hull(-magnitude)
        }
    };
    let transmitted_cos = with_cosine_sign(root);
    let mu = eta * cosine - transmitted_cos;
    let clamped_cos = with_cosine_sign(root.max_c(f64::from(DIFF_MIN_COS)));
    let rate = eta - (eta * eta * cosine).div_away(clamped_cos, f64::from(DIFF_MIN_COS));
    let refracted = |dd: Vec3, dnormal: Vec3| {
        let (dd, dnormal) = (interval3(dd), interval3(dnormal));
        let d_cos = dd.dot(n) + d.dot(dnormal);
        dd * eta - (dnormal * mu + n * (rate * d_cos))
    };
    intervals::ray_diff(
        interval3(diff.d_origin_dx),
        interval3(diff.d_origin_dy),
        refracted(diff.d_direction_dx, dn.dx),
        refracted(diff.d_direction_dy, dn.dy),
    )
}

/// `k = 1 - eta^2 (1 - dot(D, N)^2)`: negative for total internal reflection.
fn refraction_determinant(&(_, direction, normal, _, eta): &RefractArgs) -> Interval {
    let cosine = interval3(direction).dot(interval3(normal));
    Interval::c(1.0) - Interval::exact(eta) * Interval::exact(eta) * (Interval::c(1.0) - cosine * cosine)
}

/// Either branch, or the hull of both (flag `[0, 1]`) when `k`'s sign is uncertain.
fn enclosure(args: &RefractArgs) -> Vec<Interval> {
    let &(diff, direction, normal, dn, _) = args;
    let k = refraction_determinant(args);
    let reflected = || {
        [
            reflect_ray_diff::enclosure(&(diff, direction, normal, dn)),
            vec![Interval::c(1.0)],
        ]
        .concat()
    };
    let refracted = || [refracted(args, k), vec![Interval::c(0.0)]].concat();
    if k.hi < 0.0 {
        reflected()
    } else if k.lo >= 0.0 {
        refracted()
    } else {
        reflected()
            .into_iter()
            .zip(refracted())
            .map(|(a, b)| a.hull(b))
            .collect()
    }
}

/// The reference of `rf_refract_ray_diff`.
fn reference() -> Reference<(RayDiff, Vec3, Vec3, Derivatives3, f32), RefractedRayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of Snell's law (GLSL's refract, the normal turned to the ray) for normalize(D + h dD) at normalize(N + h dN), or of the reflection past the critical angle, with the flag (Igehy)",
        || (surface_hit(), 0.3f64..3.0).boxed(),
        |&((diff, direction, normal, dn), eta), refract_ray_diff| {
            let eta32 = eta as f32;
            let (d, n, eta) = (direction.as_dvec3(), normal.as_dvec3(), f64::from(eta32));
            let cosine = d.normalize().dot(n.normalize());
            let k = 1.0 - eta * eta * (1.0 - cosine * cosine);
            // Near the critical angle the map is singular (sqrt(k)): left to its own test.
            if k.abs() < 0.05 {
                return None;
            }
            let got = refract_ray_diff((diff, direction, normal, dn, eta32));
            let scattered = |dd: DVec3, dnormal: DVec3, h: f64| {
                let (d, n) = ((d + dd * h).normalize(), (n + dnormal * h).normalize());
                snell(d, n, eta).unwrap_or_else(|| mirrored(d, n))
            };
            let turned = |axis: usize| {
                let (_, dd, dnormal) = changes(&diff, dn, axis);
                let step = 1.0e-4 * k.abs() / (dd.length() + dnormal.length());
                derivative(|h| scattered(dd, dnormal, h), step, 4.0)
            };
            let (tx, ty) = (turned(0), turned(1));
            let mut expected = listed(&[changes(&diff, dn, 0).0, changes(&diff, dn, 1).0, tx.value, ty.value], 1);
            expected.push(if k < 0.0 { 1.0 } else { 0.0 });
            // The formula takes D and N unit and the changes perpendicular to them; its terms
            // (eta |dD|, mu |dN| and the rate times both, rate = eta - eta^2 cos / cos t) are off
            // by twice the inputs' relative distance from that.
            let transmitted = k.max(0.0).sqrt().max(f64::from(rd::DIFF_MIN_COS));
            let (rate, mu) = if k < 0.0 {
                (2.0, 2.0)
            } else {
                ((eta - eta * eta * cosine.abs() / transmitted).abs(), eta * cosine.abs() + k.sqrt())
            };
            let assumption = 2.0 * non_unit(&diff, direction, normal, dn);
            let bounds = widths(&enclosure(&(diff, direction, normal, dn, eta32)));
            Some(components(got, &expected, |i| {
                let (_, dd, dnormal) = changes(&diff, dn, (i / 4) % 2);
                let terms = eta.max(1.0) * dd.length() + mu * dnormal.length() + rate * (dd.length() + dnormal.length());
                let extra = if (8..16).contains(&i) {
                    tx.error.max(ty.error) + assumption * terms
                } else {
                    0.0
                };
                bounds[i] + extra
            }))
        },
    )
}
