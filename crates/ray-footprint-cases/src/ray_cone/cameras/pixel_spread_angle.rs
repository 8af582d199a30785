//! The proof of [`pixel_spread_angle`](ray_footprint::ray_cone::pixel_spread_angle): its record
//! and its reference.

use crate::degenerate::{mirror, same, value, INF, NAN};
use crate::ray_cone::cameras::shared::{camera, pixel_angle, tan_ratio_error};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{fov_y, pixels};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MAX_FOV_Y};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::atan_error;
use shader_proptest::{Args, Value};
use std::f32::consts::FRAC_PI_2;

/// The record of `rf_pixel_spread_angle`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "pixel_spread_angle",
        |(fov, height)| rc::pixel_spread_angle(fov, height),
        || (fov_y(), pixels()).boxed(),
    )
    // atan of the tan ratio: the ratio's error through atan, plus atan's 4096 ULP.
    .bound(|&(fov, height), _, _| {
        atan_error(
            rc::pixel_spread_angle_small(fov, height),
            tan_ratio_error(fov, height),
        )
    })
    .reference(reference())
    .without_symmetry(
        "the arctangent of the pixel's tangent ratio: an angle and a pixel count, no length, frame \
         or order, and no exact change of either input carries through the arctangent",
    )
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(0.0, FRAC_PI_2, "spread angle")
    .degenerate(vec![
        same(
            "zero viewport (H = 0)",
            "as H = 1 (H is clamped to >= 1)",
            (1.0, 0.0),
            (1.0, 1.0),
        ),
        same(
            "negative viewport (H = -100)",
            "as H = 1",
            (1.0, -100.0),
            (1.0, 1.0),
        ),
        value("zero field of view", "0", (0.0, 1080.0), vec![0.0]),
        same(
            "fov_y = 4 (wider than MAX_FOV_Y)",
            "as fov_y = MAX_FOV_Y (3.1)",
            (4.0, 1080.0),
            (MAX_FOV_Y, 1080.0),
        ),
        mirror("NaN in (fov_y)", "CPU: NaN", (NAN, 1080.0), vec![NAN]),
        mirror("infinity in (H = +inf)", "CPU: 0", (1.0, INF), vec![0.0]),
    ])
}

/// The reference of `rf_pixel_spread_angle`.
fn reference() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle between the central ray and the ray through the image-plane point one pixel above it (RTG Eq. 30)",
        camera,
        |&(fov, height), pixel_spread_angle| {
            let got = pixel_spread_angle((fov, height));
            let exact = pixel_angle(fov, height);
            // tan and atan within 2 ULP each (4 u), the division by H (u); atan carries its
            // argument's relative error at most once.
            Some(Deviation::within(f64::from(got), exact, gamma(10) * exact))
        },
    )
}
