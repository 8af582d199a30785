//! The proof of [`world_footprint`](ray_footprint::ray_cone::world_footprint): its record and its
//! reference.

use crate::degenerate::{cone, grazing, mirror, same, value, HEAD_ON, IN_PLANE, NAN};
use crate::exact::{log_uniform, signed_log};
use crate::ray_cone::bound::{clamped_cos, width_at_error, width_rounding};
use crate::ray_cone::footprint::shared::{cosine_error, slanted_footprint, surface_hit};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{distance, normal_and_direction};
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone, MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{dot_error, ulps};
use shader_proptest::{Args, Value};

/// The record of `rf_world_footprint`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "world_footprint",
        |(cone, t, normal, direction)| rc::world_footprint(cone, t, normal, direction),
        || {
            (ray_cone(), distance(), normal_and_direction())
                .prop_map(|(c, t, (n, d))| (c, t, n, d))
                .boxed()
        },
    )
    // The width's error (as width_at) over |cos|, the division (3 ULP), and the dot's
    // rounding over |cos| as a relative error.
    .bound(|&(cone, t, normal, direction), _, expected| {
        let cos = clamped_cos(normal, direction);
        width_at_error(cone, t) / cos
            + ulps(3.0, expected)
            + expected.abs() * dot_error(normal, direction) / cos
    })
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the width and the distance scaled by s: the footprint by s",
        |&(cone, t, normal, direction): &(RayCone, f32, Vec3, Vec3), s| {
            (
                RayCone {
                    width: cone.width * s,
                    ..cone
                },
                t * s,
                normal,
                direction,
            )
        },
        |footprint: f32, s| footprint / s,
    ))
    .symmetry(Symmetry::rotation(
        "the normal and the ray turned: the same",
        |&(cone, t, normal, direction): &(RayCone, f32, Vec3, Vec3), r| (cone, t, r * normal, r * direction),
        |footprint: f32, _| footprint,
    ))
    .symmetry(Symmetry::exchange(
        "the normal flipped: the same",
        |&(cone, t, normal, direction): &(RayCone, f32, Vec3, Vec3)| (cone, t, -normal, direction),
        |footprint: f32| footprint,
    ))
    .fuzz(|d| (d.cone(), d.distance(), d.unit(), d.unit()))
    .range(0.0, f32::MAX, "footprint")
    .degenerate(vec![
        value(
            "ray in the surface plane (dot(n, d) = 0)",
            "|width + spread t| / MIN_COS",
            (cone(0.0, 0.001), 10.0, z, IN_PLANE),
            vec![(0.0f32 + 0.001 * 10.0).abs() / MIN_COS],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (cone(0.0, 0.001), 10.0, z, grazing()),
            (cone(0.0, 0.001), 10.0, z, IN_PLANE),
        ),
        value(
            "head-on (d = -n)",
            "|width + spread t|",
            (cone(0.0, 0.001), 10.0, z, HEAD_ON),
            vec![0.001 * 10.0],
        ),
        value(
            "t = 0",
            "|width| / |dot(n, d)|",
            (cone(-0.5, 0.001), 0.0, z, HEAD_ON),
            vec![0.5],
        ),
        mirror(
            "NaN in (t)",
            "CPU: NaN",
            (cone(0.0, 0.001), NAN, z, HEAD_ON),
            vec![NAN],
        ),
    ])
}

/// The reference of `rf_world_footprint`.
fn reference() -> Reference<(RayCone, f32, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the two boundary rays of the cone's cross-section at the hit (width |w + s t|, in the plane of incidence) intersected with the surface: |w + s t| / |cos|",
        || {
            let spread = prop_oneof![Just(0.0f64), signed_log(-5.0, -1.0)];
            (signed_log(-4.0, 1.0), spread, log_uniform(-2.0, 3.0), surface_hit()).boxed()
        },
        |&(w, s, t, (n, d)), world_footprint| {
            let (cone, t32, n32, d32) = (
                RayCone {
                    width: w as f32,
                    spread_angle: s as f32,
                },
                t as f32,
                n.as_vec3(),
                d.as_vec3(),
            );
            let got = world_footprint((cone, t32, n32, d32));
            let (w, s, t) = (f64::from(cone.width), f64::from(cone.spread_angle), f64::from(t32));
            let (n, d) = (n32.as_dvec3().normalize(), d32.as_dvec3().normalize());
            let exact = slanted_footprint(w + s * t, n, d);
            // The width's rounding over |cos|; the cosine's relative error and the division's.
            let bound = width_rounding(w, s, t) / n.dot(d).abs() + (cosine_error(n32, d32) + gamma(1)) * exact;
            Some(Deviation::within(f64::from(got), exact, 1.01 * bound))
        },
    )
}
