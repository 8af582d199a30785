//! The proof of [`propagate`](ray_footprint::ray_cone::propagate): its record and its references, a
//! planar mirror and curved ones to first order.

use crate::degenerate::{cone, mirror, value, INF};
use crate::exact::{log_uniform, signed_log};
use crate::ray_cone::bound::{width_at_error, width_rounding};
use crate::ray_cone::plane_of_incidence::{reflected_first_order, step, Surface};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{angle, distance};
use crate::symmetry::Symmetry;
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_propagate`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "propagate",
        |(cone, t, beta)| rc::propagate(cone, t, beta),
        || (ray_cone(), distance(), angle()).boxed(),
    )
    // Width as width_at; spread: one correctly rounded addition, identical.
    .bound(
        |&(cone, t, _), index, _| {
            if index == 0 {
                width_at_error(cone, t)
            } else {
                0.0
            }
        },
    )
    .reference(propagate_planar())
    .reference(propagate_curved())
    .symmetry(Symmetry::scale(
        "the width and the distance scaled by s: the width by s, the spread the same",
        |&(cone, t, beta): &(RayCone, f32, f32), s| {
            (
                RayCone {
                    width: cone.width * s,
                    ..cone
                },
                t * s,
                beta,
            )
        },
        |cone: RayCone, s| RayCone {
            width: cone.width / s,
            ..cone
        },
    ))
    .fuzz(|d| (d.cone(), d.distance(), d.angle()))
    .degenerate(vec![
        value(
            "t = 0",
            "(width, spread + beta)",
            (cone(0.5, 0.001), 0.0, 0.25),
            vec![0.5, 0.001 + 0.25],
        ),
        value(
            "huge t (1e12)",
            "(width + spread * 1e12, spread + beta)",
            (cone(0.5, 0.001), 1.0e12, 0.0),
            vec![0.5 + 0.001 * 1.0e12, 0.001],
        ),
        mirror(
            "infinity in (beta)",
            "CPU: (width + spread * t, inf)",
            (cone(0.5, 0.001), 1.0, INF),
            vec![0.5 + 0.001, INF],
        ),
    ])
}

/// Chord between the two pixel-edge rays (angle `alpha` apart) of a pinhole camera at the origin
/// after a planar mirror hit at distance `t0` with the given incidence angle (the mirror tilted by
/// `roll` about the axis), once each edge ray has travelled `t0 + t1` in all. Explicit ray-plane
/// intersections in f64.
fn reflected_chord(alpha: f64, t0: f64, t1: f64, incidence: f64, roll: f64) -> f64 {
    let axis = DVec3::NEG_Z;
    let tilt = DVec3::new(roll.cos(), roll.sin(), 0.0);
    let normal = -axis * incidence.cos() + tilt * incidence.sin();
    let plane_point = axis * t0;
    // The edge rays spread in the plane of incidence, where the slant matters most.
    let spread_direction = (tilt - axis * tilt.dot(axis)).normalize();
    let edge = |side: f64| {
        let direction =
            (axis * (0.5 * alpha).cos() + spread_direction * side * (0.5 * alpha).sin()).normalize();
        let hit = crate::exact::plane_hit(DVec3::ZERO, direction, plane_point, normal);
        let reflected = direction - normal * 2.0 * direction.dot(normal);
        hit + reflected * (t0 + t1 - hit.length())
    };
    (edge(1.0) - edge(-1.0)).length()
}

/// A reference of `rf_propagate`: a planar mirror.
fn propagate_planar() -> Reference<(RayCone, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a planar mirror is a mirror-image camera (RTG Eq. 35): a pinhole cone reflected at t0 and traced t1 further is as wide as the chord between the reflected pixel-edge rays, 2 (t0 + t1) sin(alpha / 2), within alpha^2 / 24",
        || {
            (1.0e-4f64..0.05, 0.1f64..100.0, 0.0f64..100.0, 0.0f64..1.4, 0.0f64..std::f64::consts::TAU).boxed()
        },
        |&(alpha, t0, t1, incidence, roll), propagate| {
            let (alpha32, t0_32, t1_32) = (alpha as f32, t0 as f32, t1 as f32);
            let pinhole = RayCone {
                width: 0.0,
                spread_angle: alpha32,
            };
            let cone = propagate((pinhole, t0_32, 0.0));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * f64::from(t1_32);
            let chord = reflected_chord(alpha, t0, t1, incidence, roll);
            // The linear width alpha (t0 + t1) exceeds the chord by alpha / (2 sin(alpha / 2)) - 1
            // = alpha^2 / 24 + 7 alpha^4 / 5760 + ... relative; the fourth-order term (< 8e-9 here)
            // and the f32 rounding of alpha, t0, t1 and of alpha * t0 (4 u) lie within 8 u.
            let bound = (alpha * alpha / 24.0 + 8.0 * U) * chord;
            Some(Deviation::within(width, chord, bound))
        },
    )
}

/// A reference of `rf_propagate`: planar and spherical mirrors to first order.
fn propagate_curved() -> Reference<(RayCone, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a cone's boundary rays traced t to a planar or spherical mirror and reflected exactly (f64 central differences in the cone's size): its width is w + s t and its spread s plus the spread beta the mirror gives a cone of zero spread",
        || {
            let curvature = prop_oneof![1 => Just(0.0f64), 2 => signed_log(-2.0, 2.0)];
            let spread = prop_oneof![1 => Just(0.0f64), 3 => signed_log(-5.0, -0.5)];
            (signed_log(-4.0, 1.0), spread, log_uniform(-2.0, 3.0), curvature, 0.05f64..1.0).boxed()
        },
        |&(w, s, t, curvature, cosine), propagate| {
            let (w, s, t) = (w as f32, s as f32, t as f32);
            let (w64, s64, t64) = (f64::from(w), f64::from(s), f64::from(t));
            let surface = Surface { curvature };
            let d = DVec2::new((1.0 - cosine * cosine).sqrt(), -cosine);
            let at_hit = w64 + s64 * t64;
            let beta = reflected_first_order(surface, d, 0.0, (at_hit, 0.0), step((at_hit, 0.0), 0.0, curvature, cosine));
            let expected = reflected_first_order(surface, d, t64, (w64, s64), step((w64, s64), t64, curvature, cosine));
            let beta32 = beta.value.y as f32;
            let got = propagate((RayCone { width: w, spread_angle: s }, t, beta32));
            // Width: the f32 width_at; spread: beta rounded to f32 and one sum in f32.
            let width = Deviation::within(
                f64::from(got.width),
                expected.value.x,
                width_rounding(w64, s64, t64) + expected.error,
            );
            let spread_bound = U * (beta.value.y.abs() + (s64 + f64::from(beta32)).abs())
                + beta.error
                + expected.error;
            let spread = Deviation::within(f64::from(got.spread_angle), expected.value.y, spread_bound);
            Some(width.and(spread))
        },
    )
}
