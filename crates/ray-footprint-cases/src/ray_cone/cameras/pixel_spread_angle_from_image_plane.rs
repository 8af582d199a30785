//! The proof of
//! [`pixel_spread_angle_from_image_plane`](ray_footprint::ray_cone::pixel_spread_angle_from_image_plane):
//! its record and its reference, the image plane placed in space.

use crate::degenerate::{mirror, same, value, INF, NAN};
use crate::exact::{angle_between, log_uniform, tangent, unit};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{pixels, scalar};
use crate::symmetry::Symmetry;
use glam::DVec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{atan_error, ulps};
use shader_proptest::{Args, Value};
use std::f32::consts::FRAC_PI_2;

/// The record of `rf_pixel_spread_angle_from_image_plane`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "pixel_spread_angle_from_image_plane",
        |(plane_height, plane_distance, image_height)| {
            rc::pixel_spread_angle_from_image_plane(plane_height, plane_distance, image_height)
        },
        || (scalar(), scalar(), pixels()).boxed(),
    )
    // The ratio |h| / (max(|D|, MIN) max(H, 1)): the product's rounding (at most 1 ULP of the
    // quotient), the division (2.5 ULP) and the mirror's two roundings (2 ULP); then atan.
    .bound(|&(plane_height, plane_distance, image_height), _, _| {
        let ratio = plane_height.abs() / (plane_distance.abs().max(MIN_MAGNITUDE) * image_height.max(1.0));
        atan_error(ratio, ulps(5.5, ratio))
    })
    .reference(reference())
    .symmetry(
        Symmetry::scale(
            "the plane's height and distance scaled by s, where the distance is not clamped (|D| > MIN_MAGNITUDE): the same angle",
            |&(plane_height, plane_distance, image_height): &(f32, f32, f32), s| {
                (plane_height * s, plane_distance * s, image_height)
            },
            |angle: f32, _| angle,
        )
        .within(|&(_, plane_distance, _)| plane_distance.abs() > MIN_MAGNITUDE),
    )
    .symmetry(
        Symmetry::exchange(
            "the plane's height and the image's height doubled, where the image height is not clamped (H >= 1): the same pixel",
            |&(plane_height, plane_distance, image_height): &(f32, f32, f32)| {
                (2.0 * plane_height, plane_distance, 2.0 * image_height)
            },
            |angle: f32| angle,
        )
        .within(|&(_, _, image_height)| image_height >= 1.0),
    )
    .symmetry(Symmetry::exchange(
        "the plane's height and distance negated: the same",
        |&(plane_height, plane_distance, image_height): &(f32, f32, f32)| {
            (-plane_height, -plane_distance, image_height)
        },
        |angle: f32| angle,
    ))
    .fuzz(|d| (d.scalar(), d.scalar(), d.scalar()))
    .range(0.0, FRAC_PI_2, "spread angle")
    .degenerate(vec![
        same(
            "zero viewport (H = 0)",
            "as H = 1 (H is clamped to >= 1)",
            (2.0, 1.0, 0.0),
            (2.0, 1.0, 1.0),
        ),
        same(
            "negative plane height and distance",
            "as their magnitudes",
            (-2.0, -1.0, 225.0),
            (2.0, 1.0, 225.0),
        ),
        value("zero plane height", "0", (0.0, 1.0, 1080.0), vec![0.0]),
        value(
            "zero plane distance",
            "atan(|h| / (MIN_MAGNITUDE H)): pi / 2 in f32",
            (2.0, 0.0, 1080.0),
            vec![(2.0f32 / (MIN_MAGNITUDE * 1080.0)).atan()],
        ),
        value(
            "zero plane height and distance",
            "0",
            (0.0, 0.0, 1080.0),
            vec![0.0],
        ),
        mirror("NaN in (plane_height)", "CPU: NaN", (NAN, 1.0, 1080.0), vec![NAN]),
        mirror(
            "infinity in (plane_height)",
            "CPU: pi / 2",
            (INF, 1.0, 1080.0),
            vec![FRAC_PI_2],
        ),
    ])
}

/// An eye at the origin looking along a random unit axis at an image plane `distance` away
/// (1e-10 to 1e10), whose height is the distance times `tan(fov / 2)` twice for a field of view
/// from 1e-3 to about 3.1 radians, and an image height.
fn image_plane() -> BoxedStrategy<(DVec3, f64, DVec3, f64, f64)> {
    let height = prop_oneof![(1u32..16384).prop_map(f64::from), 1.0f64..16384.0];
    (
        unit(),
        0.0f64..6.3,
        log_uniform(-10.0, 10.0),
        log_uniform(-3.0, 0.49),
        height,
    )
        .prop_map(|(axis, turn, distance, fov, image_height)| {
            let plane_height = (distance * 2.0 * (0.5 * fov).tan()) as f32;
            (
                axis,
                distance as f32 as f64,
                tangent(axis, turn),
                f64::from(plane_height),
                image_height as f32 as f64,
            )
        })
        .boxed()
}

/// The reference of `rf_pixel_spread_angle_from_image_plane`.
fn reference() -> Reference<(f32, f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle at the eye between the image plane's centre and the point one pixel (plane height / H) above it, the plane placed in space along a random axis at distances from 1e-10 to 1e10 (RTG Eq. 30)",
        image_plane,
        |&(axis, distance, up, plane_height, image_height), from_image_plane| {
            let got = from_image_plane((plane_height as f32, distance as f32, image_height as f32));
            let centre = axis * distance;
            let above = centre + up * (plane_height / image_height);
            let exact = angle_between(centre, above);
            // The product and the division (2 u), atan within 2 ULP (4 u); atan carries its
            // argument's relative error at most once.
            Some(Deviation::within(f64::from(got), exact, gamma(6) * exact))
        },
    )
}
