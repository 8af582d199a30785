//! The proof of [`width_at`](ray_footprint::ray_cone::width_at): its record and its reference.

use crate::degenerate::{cone, mirror, value, INF, NAN};
use crate::exact::{log_uniform, signed_log};
use crate::ray_cone::bound::{width_at_error, width_rounding};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::distance;
use crate::symmetry::Symmetry;
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_width_at`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "width_at",
        |(cone, t)| rc::width_at(cone, t),
        || (ray_cone(), distance()).boxed(),
    )
    .bound(|&(cone, t), _, _| width_at_error(cone, t))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the width and the distance scaled by s: the width by s",
        |&(cone, t): &(RayCone, f32), s| {
            (
                RayCone {
                    width: cone.width * s,
                    ..cone
                },
                t * s,
            )
        },
        |width: f32, s| width / s,
    ))
    .fuzz(|d| (d.cone(), d.distance()))
    .degenerate(vec![
        value("t = 0", "width", (cone(0.5, 0.001), 0.0), vec![0.5]),
        value(
            "huge t (1e12)",
            "width + spread * 1e12",
            (cone(0.5, 0.001), 1.0e12),
            vec![0.5 + 0.001 * 1.0e12],
        ),
        value(
            "negative spread past the apex",
            "negative (signed width; footprints use |width|)",
            (cone(1.0, -0.01), 200.0),
            vec![1.0 - 0.01 * 200.0],
        ),
        mirror("NaN in (t)", "CPU: NaN", (cone(0.5, 0.001), NAN), vec![NAN]),
        mirror("infinity in (t)", "CPU: inf", (cone(0.5, 0.001), INF), vec![INF]),
    ])
}

/// `2 tan(s / 2) - s`, the excess of the boundary rays' separation rate over the linear width's,
/// is at most `|s|^3 / (12 cos^4(s / 2))` (from `tan x - x <= x^3 / (3 cos^4 x)`, which integrates
/// `tan^2 x <= x^2 / cos^4 x`).
fn tangent_excess_bound(spread: f64) -> f64 {
    spread.abs().powi(3) / (12.0 * (0.5 * spread).cos().powi(4))
}

/// The reference of `rf_width_at`.
fn reference() -> Reference<(RayCone, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the two boundary rays (width w apart, spread s) intersected with the plane across the central ray at t: within t |s|^3 / (12 cos^4(s / 2)) of w + s t",
        || (signed_log(-6.0, 2.0), signed_log(-6.0, 0.17), log_uniform(-3.0, 4.0)).boxed(),
        |&(w, s, t), width_at| {
            let (w, s, t) = (w as f32, s as f32, t as f32);
            let got = width_at((RayCone { width: w, spread_angle: s }, t));
            let (w, s, t) = (f64::from(w), f64::from(s), f64::from(t));
            let crossing = |side: f64| {
                let start = DVec3::new(0.0, side * 0.5 * w, 0.0);
                let direction = DVec3::new((0.5 * s).cos(), side * (0.5 * s).sin(), 0.0);
                crate::exact::plane_hit(start, direction, DVec3::X * t, DVec3::X).y
            };
            let exact = crossing(1.0) - crossing(-1.0);
            let bound = t * tangent_excess_bound(s) + width_rounding(w, s, t);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}
