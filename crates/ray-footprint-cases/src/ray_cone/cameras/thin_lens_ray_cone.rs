//! The proof of [`thin_lens_ray_cone`](ray_footprint::ray_cone::thin_lens_ray_cone): its record and
//! its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::exact::{log_uniform, plane_hit};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{angle, magnitude, scalar};
use crate::symmetry::Symmetry;
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone, MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The record of `rf_thin_lens_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "thin_lens_ray_cone",
        |(spread, aperture, focus)| rc::thin_lens_ray_cone(spread, aperture, focus),
        || (angle(), magnitude(), scalar()).boxed(),
    )
    // Width: a copy. Spread: a division (2.5 ULP + 0.5) then a subtraction (0.5 + 0.5 ULP
    // of the larger operand).
    .bound(|&(spread, aperture, focus), index, _| {
        let quotient = aperture / focus.max(MIN_MAGNITUDE);
        if index == 0 {
            0.0
        } else {
            ulps(4.0, spread.abs() + quotient.abs())
        }
    })
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the aperture and the focus distance (above MIN_MAGNITUDE, where it is not clamped) scaled by s: the width by s, the spread the same",
        |&(spread, aperture, focus): &(f32, f32, f32), s| (spread, aperture * s, focus * s),
        |cone: RayCone, s| RayCone {
            width: cone.width / s,
            ..cone
        },
    )
    .within(|&(_, _, focus)| focus > MIN_MAGNITUDE))
    .fuzz(|d| (d.angle(), d.scalar(), d.distance()))
    .degenerate(vec![
        value(
            "zero focus distance",
            "(A, alpha - A / MIN_MAGNITUDE)",
            (0.001, 0.01, 0.0),
            vec![0.01, 0.001 - 0.01 / MIN_MAGNITUDE],
        ),
        value(
            "zero aperture",
            "(0, alpha): a pinhole",
            (0.001, 0.0, 5.0),
            vec![0.0, 0.001],
        ),
        mirror(
            "NaN in (focus distance)",
            "CPU: as focus distance 0 (Rust's `max` ignores NaN)",
            (0.001, 0.01, NAN),
            vec![0.01, 0.001 - 0.01 / MIN_MAGNITUDE],
        ),
    ])
}

/// The reference of `rf_thin_lens_ray_cone`.
fn reference() -> Reference<(f32, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a thin lens focused at F: the rays from the aperture's edges (+-A/2) through the pixel's edge points on the focal plane (+-F tan(alpha / 2)), intersected with the plane at t; the cone's width at t within t alpha^3 / (12 cos^4(alpha / 2))",
        || (log_uniform(-5.0, -0.3), 0.0f64..1.0, log_uniform(-1.0, 2.0), 0.0f64..1000.0).boxed(),
        |&(alpha, aperture, focus, t), thin_lens_ray_cone| {
            let (alpha, aperture, focus) = (alpha as f32, aperture as f32, focus as f32);
            let cone = thin_lens_ray_cone((alpha, aperture, focus));
            let (alpha, aperture, focus) = (f64::from(alpha), f64::from(aperture), f64::from(focus));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * t;
            let marginal = |side: f64| {
                let lens = DVec3::new(0.0, side * 0.5 * aperture, 0.0);
                let focal = DVec3::new(0.0, side * focus * (0.5 * alpha).tan(), -focus);
                plane_hit(lens, focal - lens, DVec3::NEG_Z * t, DVec3::Z).y
            };
            let exact = marginal(1.0) - marginal(-1.0);
            // The marginal rays separate at 2 tan(alpha / 2) - A / F per unit, the cone at
            // alpha - A / F: t (2 tan(alpha / 2) - alpha) apart (see `width_at`); the spread's
            // division and difference round twice; the width is a copy.
            let approximation = t * alpha.powi(3) / (12.0 * (0.5 * alpha).cos().powi(4));
            let rounding = t * gamma(2) * (2.0 * aperture / focus + alpha) + 1.0e-13 * (aperture + t * alpha);
            Some(Deviation::within(width, exact, approximation + rounding))
        },
    )
}
