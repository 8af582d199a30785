//! The proof of [`orthographic_ray_cone`](ray_footprint::ray_cone::orthographic_ray_cone): its record
//! and its reference.

use crate::degenerate::{mirror, same, value, INF};
use crate::exact::{angle_between, log_uniform, plane_hit};
use crate::ray_cone::cameras::shared::camera;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{magnitude, pixels};
use crate::symmetry::Symmetry;
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The record of `rf_orthographic_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "orthographic_ray_cone",
        |(view_height, height)| rc::orthographic_ray_cone(view_height, height),
        || (magnitude(), pixels()).boxed(),
    )
    // One division: 2.5 ULP on the device, 0.5 in the mirror.
    .bound(|_, _, expected| ulps(3.0, expected))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the view height scaled by s: the width by s",
        |&(view_height, image_height): &(f32, f32), s| (view_height * s, image_height),
        |cone: RayCone, s| RayCone {
            width: cone.width / s,
            ..cone
        },
    ))
    .fuzz(|d| (d.scalar(), d.scalar()))
    .degenerate(vec![
        value(
            "zero viewport (H = 0)",
            "(view_height, 0): H is clamped to >= 1",
            (2.0, 0.0),
            vec![2.0, 0.0],
        ),
        same("negative viewport (H = -5)", "as H = 1", (2.0, -5.0), (2.0, 1.0)),
        value("zero view height", "(0, 0)", (0.0, 1080.0), vec![0.0, 0.0]),
        mirror(
            "infinity in (view_height)",
            "CPU: (inf, 0)",
            (INF, 1080.0),
            vec![INF, 0.0],
        ),
    ])
}

/// The reference of `rf_orthographic_ray_cone`.
fn reference() -> Reference<(f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "an orthographic camera's parallel rays through the top and bottom edges of a random pixel row, V (1/2 - j / H) and V (1/2 - (j + 1) / H) up the image plane: their distance apart and the angle between them",
        || (log_uniform(-3.0, 3.0), camera(), 0.0f64..1.0).boxed(),
        |&(view_height, (_, height), row), orthographic_ray_cone| {
            let view_height = view_height as f32;
            let cone = orthographic_ray_cone((view_height, height));
            let (v, h) = (f64::from(view_height), f64::from(height));
            let j = (row * h).floor();
            let ray = |edge: f64| (DVec3::new(0.0, v * (0.5 - edge / h), 0.0), DVec3::NEG_Z);
            let ((top, top_direction), (bottom, bottom_direction)) = (ray(j), ray(j + 1.0));
            let at = |(origin, direction): (DVec3, DVec3)| plane_hit(origin, direction, DVec3::NEG_Z, DVec3::Z);
            let width = (at((top, top_direction)) - at((bottom, bottom_direction))).length();
            // One division (u); the f64 positions round within 4 ULP of V.
            let width_deviation = Deviation::within(f64::from(cone.width), width, U * width + 4.0 * f64::EPSILON * v);
            let spread = angle_between(top_direction, bottom_direction);
            Some(width_deviation.and(Deviation::within(f64::from(cone.spread_angle), spread, 0.0)))
        },
    )
}
