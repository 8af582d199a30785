//! The proof of [`pinhole_ray_cone`](ray_footprint::ray_cone::pinhole_ray_cone): its record and its
//! reference.

use crate::degenerate::{mirror, value, NAN};
use crate::exact::{log_uniform, plane_hit};
use crate::ray_cone::cameras::shared::{camera, pixel_height};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{angle, one_argument};
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_pinhole_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    // No arithmetic.
    Record::new(
        Module::RayCone,
        "pinhole_ray_cone",
        |(spread,)| rc::pinhole_ray_cone(spread),
        || one_argument(angle()),
    )
    .reference(reference())
    .without_symmetry("the cone is its argument with a zero width: nothing to transform")
    .fuzz(|d| (d.angle(),))
    .degenerate(vec![
        value("zero spread", "(0, 0)", (0.0,), vec![0.0, 0.0]),
        value(
            "negative spread (-0.01)",
            "(0, -0.01), kept",
            (-0.01,),
            vec![0.0, -0.01],
        ),
        mirror("NaN in", "CPU: (0, NaN)", (NAN,), vec![0.0, NAN]),
    ])
}

/// The reference of `rf_pinhole_ray_cone`.
fn reference() -> Reference<(f32,), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "the central pixel's footprint on the plane across the view axis at distance t: the rays through its top and bottom edges intersected with the plane, 2 t tan(fov / 2) / H apart, against the cone's width at t",
        || (camera(), log_uniform(-2.0, 4.0)).boxed(),
        |&((fov, height), t), pinhole_ray_cone| {
            let spread = pixel_height(fov, height) as f32;
            let cone = pinhole_ray_cone((spread,));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * t;
            let edge = |ndc_y: f64| {
                let direction = DVec3::new(0.0, ndc_y * (0.5 * f64::from(fov)).tan(), -1.0);
                plane_hit(DVec3::ZERO, direction, DVec3::NEG_Z * t, DVec3::Z).y
            };
            let h = f64::from(height);
            let exact = edge(1.0 / h) - edge(-1.0 / h);
            // The spread is the footprint's angle rounded to f32 (u); f64 rounding below 1e-14.
            Some(Deviation::within(width, exact, (U + 1.0e-14) * exact))
        },
    )
}
