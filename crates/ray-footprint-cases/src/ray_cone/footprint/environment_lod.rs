//! The proof of [`environment_lod`](ray_footprint::ray_cone::environment_lod): its record and its
//! reference.

use crate::degenerate::{mirror, same, value, NAN};
use crate::exact::signed_log;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{angle, pixels};
use crate::symmetry::Symmetry;
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{log2_error, ULP};
use shader_proptest::{Args, Value};
use std::f64::consts::{LN_2, PI};

/// The record of `rf_environment_lod`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "environment_lod",
        |(spread, height)| rc::environment_lod(spread, height),
        || (angle(), pixels()).boxed(),
    )
    // A product and a division (3.5 ULP + the mirror's 1) through log2 (/ ln 2), plus log2's
    // own error.
    .bound(|_, _, expected| 4.5 * ULP / std::f32::consts::LN_2 + log2_error(expected))
    .reference(reference())
    .symmetry(Symmetry::scale_in_log(
        "the spread scaled by s, where spread * height / pi is above MIN_MAGNITUDE (not clamped): the LOD plus log2 s",
        |&(spread, height): &(f32, f32), s| (spread * s, height),
        |lod: f32, s| lod - s.log2(),
    )
    .within(|&(spread, height)| spread.abs() * height.max(1.0) / std::f32::consts::PI > MIN_MAGNITUDE))
    .symmetry(Symmetry::exchange(
        "the spread negated: the same",
        |&(spread, height): &(f32, f32)| (-spread, height),
        |lod: f32| lod,
    ))
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(rc::MIN_MAGNITUDE.log2(), f32::MAX, "environment LOD")
    .degenerate(vec![
        value(
            "zero spread",
            "log2(MIN_MAGNITUDE)",
            (0.0, 1024.0),
            vec![MIN_MAGNITUDE.log2()],
        ),
        same("negative spread", "as |spread|", (-0.01, 1024.0), (0.01, 1024.0)),
        same("zero map height", "as height 1", (0.01, 0.0), (0.01, 1.0)),
        mirror(
            "NaN in (spread)",
            "CPU: log2(MIN_MAGNITUDE) (Rust's `max` ignores NaN)",
            (NAN, 1024.0),
            vec![MIN_MAGNITUDE.log2()],
        ),
    ])
}

/// The reference of `rf_environment_lod`.
fn reference() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the latitudes of a cone's two boundary rays in its vertical plane (atan2 of the f64 directions): the log2 of the texel rows of pi / H between them on a latitude-longitude map",
        || (signed_log(-6.0, 0.0), 1.0f64..8192.0, -1.0f64..1.0, 0.0f64..6.3).boxed(),
        |&(spread, height, latitude, azimuth), environment_lod| {
            let (spread, height) = (spread as f32, height as f32);
            let got = environment_lod((spread, height));
            let (s, h) = (f64::from(spread), f64::from(height));
            // The central direction's latitude keeps both boundary rays off the poles.
            let centre = latitude * (0.5 * PI - 0.5 * s.abs() - 1.0e-3);
            let boundary = |side: f64| {
                let phi = centre + side * 0.5 * s;
                DVec3::new(phi.cos() * azimuth.cos(), phi.sin(), phi.cos() * azimuth.sin())
            };
            let latitude_of = |v: DVec3| v.y.atan2(DVec2::new(v.x, v.z).length());
            let rows = (latitude_of(boundary(1.0)) - latitude_of(boundary(-1.0))).abs() / (PI / h);
            let expected = rows.log2();
            // |s| H / pi: two roundings and f32's pi (within u / 2); log2 within 2 ULP (4 u).
            let bound = gamma(3) / LN_2 + 4.0 * U * expected.abs() + 1.0e-12;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
