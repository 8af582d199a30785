//! The proof of [`pinhole_ray_cone_for_ray`](ray_footprint::ray_cone::pinhole_ray_cone_for_ray): its
//! record and its reference.

use crate::degenerate::{mirror, same, value, NAN};
use crate::exact::{derivative, unit};
use crate::ray_cone::bound::unit_excess;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::strategy::{angle, normal_and_direction};
use crate::symmetry::Symmetry;
use glam::{DQuat, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{dot_error, ulps};

/// Arguments of `rf_pinhole_ray_cone_for_ray`: pixel spread angle, direction, view axis.
pub type PinholeRayConeForRayArgs = (f32, Vec3, Vec3);

/// The record of `rf_pinhole_ray_cone_for_ray` (also used by the ray-tracing pipeline's test).
pub fn record() -> Record<PinholeRayConeForRayArgs, RayCone> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let head_on = Vec3::NEG_Z;
    Record::new(
        Module::RayCone,
        "pinhole_ray_cone_for_ray",
        |(spread, direction, view_axis)| rc::pinhole_ray_cone_for_ray(spread, direction, view_axis),
        // A view axis and a ray from on the axis to 90 degrees off it, or behind the camera.
        || {
            (angle(), normal_and_direction(), any::<bool>())
                .prop_map(|(spread, (normal, direction), behind)| {
                    (spread, direction, if behind { normal } else { -normal })
                })
                .boxed()
        },
    )
    // Width: exact. Spread: the dot product's rounding, through the clamp (which cannot widen
    // it), times |spread|, and the product's rounding on the device and in the mirror.
    .bound(|&(spread, direction, view_axis), index, expected| {
        if index == 0 {
            0.0
        } else {
            spread.abs() * dot_error(direction, view_axis) + ulps(2.0, expected)
        }
    })
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the ray and the view axis turned: the same",
        |&(spread, direction, view_axis): &(f32, Vec3, Vec3), r| (spread, r * direction, r * view_axis),
        |cone: RayCone, _| cone,
    ))
    .fuzz(|d| (d.angle(), d.unit(), d.unit()))
    .range(-3.2, 3.2, "width and spread")
    .degenerate(vec![
        value(
            "ray along the view axis",
            "(0, alpha)",
            (0.01, head_on, head_on),
            vec![0.0, 0.01],
        ),
        value(
            "ray at 90 degrees to the view axis",
            "(0, 0)",
            (0.01, x, head_on),
            vec![0.0, 0.0],
        ),
        same(
            "ray behind the camera (dot(d, axis) = -1)",
            "as at 90 degrees: the cosine is clamped to [0, 1]",
            (0.01, z, head_on),
            (0.01, x, head_on),
        ),
        same(
            "direction and axis of length 2 (dot = 4)",
            "as along the axis: never wider than alpha",
            (0.01, 2.0 * head_on, 2.0 * head_on),
            (0.01, head_on, head_on),
        ),
        value(
            "zero direction",
            "(0, 0)",
            (0.01, Vec3::ZERO, head_on),
            vec![0.0, 0.0],
        ),
        mirror(
            "NaN in (direction)",
            "CPU: (0, NaN) (Rust's `clamp` keeps NaN)",
            (0.01, Vec3::new(NAN, 0.0, -1.0), head_on),
            vec![0.0, NAN],
        ),
    ])
}

/// A pinhole camera in a random orientation and one of its pixels.
#[derive(Clone, Debug)]
struct Pinhole {
    fov: f64,
    size: DVec2,
    pixel: DVec2,
    rotation: DQuat,
}

impl Pinhole {
    /// Fields of view up to 160 degrees, images of 200 to 4000 rows at aspects 0.5 to 2.5.
    fn strategy() -> BoxedStrategy<Pinhole> {
        (
            0.2f64..2.8,
            200.0f64..4000.0,
            0.5f64..2.5,
            (0.0f64..1.0, 0.0f64..1.0),
            (unit(), 0.0f64..6.3),
        )
            .prop_map(|(fov, height, aspect, (fx, fy), (axis, angle))| {
                let size = DVec2::new((height * aspect).round(), height.round());
                Pinhole {
                    fov,
                    size,
                    pixel: (DVec2::new(fx, fy) * size).floor(),
                    rotation: DQuat::from_axis_angle(axis, angle),
                }
            })
            .boxed()
    }

    /// Unit direction, in camera space (looking down -z, pixel y down), through the continuous
    /// pixel position `at`.
    fn direction(&self, at: DVec2) -> DVec3 {
        let ndc = (at + 0.5) / self.size * 2.0 - 1.0;
        let f = (0.5 * self.fov).tan();
        DVec3::new(ndc.x * self.size.x / self.size.y * f, -ndc.y * f, -1.0).normalize()
    }
}

/// The reference of `rf_pinhole_ray_cone_for_ray`.
fn reference() -> Reference<(f32, Vec3, Vec3), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "the pixel's footprint on the plane across its ray (the pixel -> ray map differentiated by f64 central differences): the per-ray cone's LOD error lies in [log2(atan(x) / x), log2(2 / (1 + cos^2)) / 2] against the footprint's longer side",
        Pinhole::strategy,
        |camera, pinhole_ray_cone_for_ray| {
            let centre = camera.direction(camera.pixel);
            let on_plane = |step: DVec2| {
                let direction = camera.direction(camera.pixel + step);
                direction / direction.dot(centre)
            };
            let across = derivative(|h| on_plane(DVec2::new(h, 0.0)), 1.0e-3, 2.0);
            let down = derivative(|h| on_plane(DVec2::new(0.0, h)), 1.0e-3, 2.0);
            let longer = across.value.length().max(down.value.length());
            let x = 2.0 * (0.5 * camera.fov).tan() / camera.size.y;
            let alpha = x.atan() as f32;
            let (direction, axis) = ((camera.rotation * centre).as_vec3(), (camera.rotation * DVec3::NEG_Z).as_vec3());
            let cone = pinhole_ray_cone_for_ray((alpha, direction, axis));
            let cosine = -centre.z;
            // A pixel theta off axis spans x cos(theta) across the radial direction and
            // x cos^2(theta) along it (to first order); its longer side, at any angle to the
            // radial direction, lies between x cos sqrt((1 + cos^2) / 2) and x cos. The cone's
            // spread atan(x) cos(theta) is off by alpha's rounding, the dot product's rounding over
            // cos and the product's rounding; the footprint by its central differences' error.
            let terms = (direction.as_dvec3() * axis.as_dvec3()).abs().element_sum();
            let relative = gamma(2) + (gamma(3) * terms + unit_excess(direction, axis)) / cosine
                + across.error.max(down.error) / longer;
            let slack = 1.01 * relative / std::f64::consts::LN_2;
            let low = (f64::from(alpha) / x).log2() - slack;
            let high = 0.5 * (2.0 / (1.0 + cosine * cosine)).log2() + slack;
            let lod_error = (f64::from(cone.spread_angle) / longer).log2();
            Some(Deviation::in_interval(lod_error, low, high).and(Deviation::new(f64::from(cone.width).abs(), 0.0)))
        },
    )
}
