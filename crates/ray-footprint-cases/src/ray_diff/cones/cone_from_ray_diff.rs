//! The proof of [`cone_from_ray_diff`](ray_footprint::ray_diff::cone_from_ray_diff): its record,
//! where it is checked, its enclosure and its references, a differential built from two cones and
//! propagation.

use crate::degenerate::value;
use crate::exact::{log_uniform, signed_log, tangent, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::cones::shared::{canonical, cone_and_distance, cone_error, scaled_length, F32_CHAIN};
use crate::ray_diff::intervals::direction_well_conditioned;
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::strategy::ray_diff;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::strategy::unit_vec3;
use glam::{DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::ray_diff::{self as rd, RayDiff};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};

/// The record of `rf_cone_from_ray_diff`: the enclosure of the cone.
pub fn record() -> Record<(RayDiff, Vec3), Vec2> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "cone_from_ray_diff",
        |(diff, d)| rd::cone_from_ray_diff(diff, d),
        || (ray_diff(), unit_vec3()).boxed(),
    )
    .conditioned(
        "an origin or direction change lies along the ray within rounding (its part across the \
         ray is not known to 2^-10), or the two are orthogonal within rounding: the width is \
         rounding noise, or the spread's sign (converging or diverging) may go either way",
        transverse_well_conditioned,
    )
    .enclosure(enclosure)
    .reference(reference())
    .reference(cone_from_ray_diff_propagation())
    .symmetry(Symmetry::rotation(
        "the differential and the ray turned: the same",
        |&(diff, d): &(RayDiff, Vec3), r| (turned(diff, r), r * d),
        |cone: Vec2, _| cone,
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the same",
        |&(diff, d): &(RayDiff, Vec3)| (swapped(diff), d),
        |cone: Vec2| cone,
    ))
    .symmetry(Symmetry::scale(
        "the origin parts scaled by s: the width by s",
        |&(diff, d): &(RayDiff, Vec3), s| (origins_scaled(diff, s), d),
        |cone: Vec2, s| Vec2::new(cone.x / s, cone.y),
    ))
    .fuzz(|d| (d.ray_diff(), d.unit()))
    .promise(|_, cone, promises| promises.within(cone.x, 0.0, f32::MAX, "width"))
    .degenerate(vec![
        value("zero differential", "(0, 0)", (RayDiff::ZERO, -z), vec![0.0, 0.0]),
        value(
            "pinhole eye ray (dO = 0), |dD/dx| = 0.01, |dD/dy| = 0.02",
            "(0, mean spread 0.015), diverging",
            (RayDiff::new(Vec3::ZERO, Vec3::ZERO, 0.01 * x, 0.02 * y), -z),
            vec![0.0, 0.5 * (0.01 + 0.02)],
        ),
        value(
            "origin and direction changes pointing apart",
            "negative spread (converging)",
            (RayDiff::new(x, y, -0.5 * x, -0.5 * y), -z),
            vec![1.0, -0.5],
        ),
        value(
            "changes along the ray only",
            "(0, 0): only the parts across the ray count",
            (RayDiff::new(2.0 * z, 2.0 * z, z, z), -z),
            vec![0.0, 0.0],
        ),
    ])
}

/// The parts of one axis's origin and direction changes across the ray, and their alignment.
fn transverse_parts(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> (Interval3, Interval3, Interval) {
    let d = interval3(direction);
    let across = |v: Vec3| interval3(v) - d * interval3(v).dot(d);
    let (origin, turn) = (across(d_origin), across(d_direction));
    (origin, turn, origin.dot(turn))
}

/// Whether each axis of the cone is well-conditioned: the origin and direction changes across the
/// ray are known to [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED)
/// ([`direction_well_conditioned`]; not a change along the ray within rounding), and the sign of
/// the spread is decided (their alignment does not enclose 0, or the origin change is exactly 0).
fn transverse_well_conditioned(&(diff, direction): &(RayDiff, Vec3)) -> bool {
    let decided = |d_origin: Vec3, d_direction: Vec3| {
        let (origin, turn, alignment) = transverse_parts(d_origin, d_direction, direction);
        let sign_decided = d_origin == Vec3::ZERO || alignment.lo >= 0.0 || alignment.hi < 0.0;
        sign_decided && direction_well_conditioned(origin) && direction_well_conditioned(turn)
    };
    decided(diff.d_origin_dx, diff.d_direction_dx) && decided(diff.d_origin_dy, diff.d_direction_dy)
}

/// One axis; the sign of the spread is exact when the origin change is exactly 0 (then the dot
/// product is exactly 0 on every implementation), else the hull of both where rounding leaves it
/// open.
fn transverse_cone(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> [Interval; 2] {
    let (origin, turn, alignment) = transverse_parts(d_origin, d_direction, direction);
    let spread = scaled_length(turn);
    let signed = if alignment.lo >= 0.0 || d_origin == Vec3::ZERO {
        spread
    } else if alignment.hi < 0.0 {
        -spread
    } else {
        spread.hull(-spread)
    };
    [scaled_length(origin), signed]
}

/// `rf_cone_from_ray_diff` in interval arithmetic, in the same order of operations.
fn enclosure(&(diff, direction): &(RayDiff, Vec3)) -> Vec<Interval> {
    let x = transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    vec![Interval::c(0.5) * (x[0] + y[0]), Interval::c(0.5) * (x[1] + y[1])]
}

/// A reference of `rf_cone_from_ray_diff`: a differential built from two cones.
fn reference() -> Reference<(RayDiff, Vec3), Vec2> {
    Reference::new(
        Kind::Identity,
        "a differential built from one cone per axis (origin change w a, direction change s a across d, plus changes along d that the conversion drops) converts to the mean of the two cones' canonical forms",
        || {
            let axis = || (0.0f64..6.3, signed_log(-6.0, 2.0), signed_log(-6.0, 0.0), -10.0f64..10.0, -1.0f64..1.0);
            (unit(), axis(), axis()).boxed()
        },
        |&(d, x, y), cone_from_ray_diff| {
            let build = |(angle, w, s, along_o, along_d): (f64, f64, f64, f64, f64)| {
                let a = tangent(d, angle);
                (a * w + d * (along_o * w.abs()), a * s + d * along_d)
            };
            let ((ox, dx), (oy, dy)) = (build(x), build(y));
            let diff = RayDiff::new(ox.as_vec3(), oy.as_vec3(), dx.as_vec3(), dy.as_vec3());
            let direction = d.as_vec3();
            let got = cone_from_ray_diff((diff, direction));
            let expected = 0.5 * (canonical(x.1, x.2) + canonical(y.1, y.2));
            // The conversion's rounding (the enclosure), the inputs' rounding (u of each change)
            // and the direction's distance from unit length (the changes along d leave that much
            // across it), halved by the mean.
            let eta = (direction.as_dvec3().length() - 1.0).abs() + U;
            let rounding = widths(&enclosure(&(diff, direction)));
            let input = |a: DVec3, b: DVec3| 0.5 * (U + 3.0 * eta) * (a.length() + b.length());
            let bounds = [rounding[0] + input(ox, oy), rounding[1] + input(dx, dy)];
            Some(components(got, &expected.to_array(), |i| bounds[i]))
        },
    )
}

/// A reference of `rf_cone_from_ray_diff`: propagation.
fn cone_from_ray_diff_propagation() -> Reference<(RayDiff, Vec3), Vec2> {
    Reference::new(
        Kind::Identity,
        "converting commutes with propagation: the cone of a cone's differential transferred to a plane at |cos| >= 0.01 is the propagated cone (ray_cone::propagate), within an f32 error that grows as 1 / |cos|",
        || (cone_and_distance(), log_uniform(-2.0, 0.0), 0.0f64..6.3).boxed(),
        |&((w, s, d, t), cosine, angle), cone_from_ray_diff| {
            let (cone, direction, t) = (Vec2::new(w as f32, s as f32), d.as_vec3(), t as f32);
            let normal = towards(d, cosine, angle).as_vec3();
            let diff = rd::ray_diff_from_cone(cone, direction);
            let transferred = cone_from_ray_diff((rd::transfer(diff, direction, t, normal), direction));
            let propagated = rc::propagate(RayCone { width: cone.x, spread_angle: cone.y }, t, 0.0);
            let expected = canonical(f64::from(propagated.width), f64::from(propagated.spread_angle));
            // The transfer adds dt D with |dt| ~ |dO| / |cos|, which the conversion removes again.
            Some(Deviation::new(cone_error(transferred, expected), F32_CHAIN / cosine))
        },
    )
}
