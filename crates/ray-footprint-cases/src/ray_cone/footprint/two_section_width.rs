//! The proof of [`two_section_width`](ray_footprint::ray_cone::two_section_width): its record, its
//! enclosure and its references, the ellipse's rays intersected with the surface and the limit
//! cases.

use crate::degenerate::{grazing, mirror, same, value, HEAD_ON, IN_PLANE, NAN};
use crate::exact::{plane_hit, signed_log, towards, unit};
use crate::ray_cone::bound::unit_excess;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{normal_and_direction, scalar, unit_vec3, vec3, HUGE};
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS, MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, select, Interval};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};
use std::f64::consts::PI;

/// The record of `rf_two_section_width`: the enclosure of the width.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    let sixty_degrees = Vec3::new(0.866_025_4, 0.0, -0.5);
    Record::new(
        Module::RayCone,
        "two_section_width",
        |(tangential, sagittal, axis, normal, direction)| {
            rc::two_section_width(tangential, sagittal, axis, normal, direction)
        },
        || {
            // The axis as a refraction leaves it (across the plane of incidence), any unit vector,
            // any vector, or none.
            let axis = one_of![
                3 => Just(None),
                2 => unit_vec3().prop_map(Some),
                1 => vec3().prop_map(Some),
                1 => Just(Some(Vec3::ZERO)),
            ];
            (scalar(), scalar(), axis, normal_and_direction())
                .prop_map(|(tangential, sagittal, axis, (n, d))| {
                    let axis = axis.unwrap_or_else(|| d.cross(n));
                    (tangential, sagittal, axis, n, d)
                })
                .boxed()
        },
    )
    .conditioned(
        "a width or the axis beyond the domain's magnitudes (1e12), where the enclosure's products \
         overflow, or an axis within 1e-4 of the ray's line, whose part across the ray is rounding \
         and points anywhere",
        |&(tangential, sagittal, axis, _, direction)| {
            let across = axis - axis.dot(direction) * direction;
            let in_domain =
                tangential.abs() <= HUGE && sagittal.abs() <= HUGE && axis.abs().max_element() <= HUGE;
            in_domain && across.length() >= 1.0e-4 * axis.length()
        },
    )
    .enclosure(|args| vec![enclosure(args)])
    .reference(two_section_width_sampled())
    .reference(two_section_width_limits())
    .symmetry(Symmetry::scale(
        "both widths scaled by s: the width by s",
        |&(tangential, sagittal, axis, normal, direction): &(f32, f32, Vec3, Vec3, Vec3), s| {
            (tangential * s, sagittal * s, axis, normal, direction)
        },
        |width: f32, s| width / s,
    ))
    .symmetry(Symmetry::rotation(
        "the axis, the normal and the ray turned: the same",
        |&(tangential, sagittal, axis, normal, direction): &(f32, f32, Vec3, Vec3, Vec3), r| {
            (tangential, sagittal, r * axis, r * normal, r * direction)
        },
        |width: f32, _| width,
    ))
    .symmetry(Symmetry::exchange(
        "the normal and the sagittal axis flipped: the same",
        |&(tangential, sagittal, axis, normal, direction): &(f32, f32, Vec3, Vec3, Vec3)| {
            (tangential, sagittal, -axis, -normal, direction)
        },
        |width: f32| width,
    ))
    .fuzz(|d| (d.scalar(), d.scalar(), d.vec3(), d.unit(), d.unit()))
    .range(0.0, f32::MAX, "width")
    .degenerate(vec![
        value(
            "zero axis",
            "max(|w_t|, |w_s|)",
            (0.01, -0.03, Vec3::ZERO, z, sixty_degrees),
            vec![0.03],
        ),
        same(
            "axis along the ray",
            "as the zero axis",
            (0.01, -0.03, sixty_degrees, z, sixty_degrees),
            (0.01, -0.03, Vec3::ZERO, z, sixty_degrees),
        ),
        value(
            "both widths 0",
            "0",
            (0.0, 0.0, Vec3::Y, z, sixty_degrees),
            vec![0.0],
        ),
        value(
            "ray in the surface plane (dot(n, d) = 0), equal widths",
            "|w|: a round cone at any slant",
            (0.5, 0.5, Vec3::Y, z, IN_PLANE),
            vec![0.5],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (0.01, 0.03, Vec3::Y, z, grazing()),
            (0.01, 0.03, Vec3::Y, z, IN_PLANE),
        ),
        same(
            "axis not across the ray and not unit",
            "as its unit part across the ray",
            (0.01, 0.03, Vec3::new(1.0, 2.0, 0.0), z, HEAD_ON),
            (0.01, 0.03, Vec3::new(0.447_213_6, 0.894_427_2, 0.0), z, HEAD_ON),
        ),
        mirror(
            "NaN width",
            "CPU: NaN",
            (NAN, 0.01, Vec3::Y, z, HEAD_ON),
            vec![NAN],
        ),
    ])
}

/// `rf_two_section_width` in interval arithmetic, in the same order of operations.
fn enclosure(
    &(tangential_width, sagittal_width, axis, normal, direction): &(f32, f32, Vec3, Vec3, Vec3),
) -> Interval {
    let larger_width = Interval::exact(tangential_width.abs().max(sagittal_width.abs()));
    let (axis, normal, direction) = (interval3(axis), interval3(normal), interval3(direction));
    let across = axis - direction * axis.dot(direction);
    let across_length = across.dot(across).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    select(
        across_length.hi < min,
        across_length.lo < min,
        || vec![larger_width],
        || {
            let sagittal = across / across_length.at_least(min);
            let tangential = sagittal.cross(direction);
            let cosine = normal.dot(direction).abs().max_c(f64::from(MIN_COS));
            let scale = larger_width.max_c(min);
            let tangential_share = Interval::exact(tangential_width) / scale;
            let sagittal_share = Interval::exact(sagittal_width) / scale;
            let tangential_tilt = tangential_share * normal.dot(tangential);
            let sagittal_tilt = sagittal_share * normal.dot(sagittal);
            let squared_cos = cosine * cosine;
            let tangential_square =
                squared_cos * tangential_share * tangential_share + tangential_tilt * tangential_tilt;
            let sagittal_square =
                squared_cos * sagittal_share * sagittal_share + sagittal_tilt * sagittal_tilt;
            let half_sum = Interval::c(0.5) * (tangential_square + sagittal_square);
            let half_difference = Interval::c(0.5) * (tangential_square - sagittal_square);
            let off_diagonal = tangential_tilt * sagittal_tilt;
            let larger = half_sum + (half_difference * half_difference + off_diagonal * off_diagonal).sqrt();
            vec![scale * larger.sqrt()]
        },
    )[0]
}

/// The arguments of `rf_two_section_width`: tangential width, sagittal width, sagittal axis,
/// normal, direction.
type TwoSectionArgs = (f32, f32, Vec3, Vec3, Vec3);

/// A two-section beam meeting a surface: widths from 1e-4 to 10 of either sign, a unit normal,
/// a unit direction meeting it at `|cos|` from 0.05 to 1, and the sagittal axis: a unit vector
/// across the ray turned by `turn` from the plane of incidence's normal `cross(d, n)`.
fn two_section_beam() -> BoxedStrategy<(f64, f64, f64, DVec3, DVec3)> {
    (
        signed_log(-4.0, 1.0),
        signed_log(-4.0, 1.0),
        0.0f64..6.3,
        unit(),
        0.05f64..1.0,
        0.0f64..6.3,
    )
        .prop_map(|(tangential, sagittal, turn, n, cosine, angle)| {
            (tangential, sagittal, turn, n, towards(n, cosine, angle))
        })
        .boxed()
}

/// The unit vectors across `d` (unit) that a turn of `turn` from `cross(d, n)` gives: the sagittal
/// axis and the tangential one, `cross(sagittal, d)`.
fn section_axes(n: DVec3, d: DVec3, turn: f64) -> (DVec3, DVec3) {
    let first = d
        .cross(n)
        .try_normalize()
        .unwrap_or_else(|| d.any_orthonormal_vector());
    let second = first.cross(d);
    let sagittal = first * turn.cos() + second * turn.sin();
    (sagittal, sagittal.cross(d))
}

/// The longer semi-axis of the footprint that the rays `p(phi) + s d` leave on the plane through
/// the origin with normal `n`, `p(phi) = a cos phi + b sin phi` across `d`: each ray intersected
/// with the plane ([`plane_hit`]), the distance from the origin maximized over `phi` by 3,600
/// samples and a ternary search about the best one (the distance squared is a sinusoid of
/// `2 phi`, with one maximum in every half turn).
fn sampled_longer_axis(a: DVec3, b: DVec3, n: DVec3, d: DVec3) -> f64 {
    let reach = |phi: f64| plane_hit(a * phi.cos() + b * phi.sin(), d, DVec3::ZERO, n).length();
    let step = PI / 3600.0;
    let (best, _) = (0..3600)
        .map(|k| f64::from(k) * step)
        .map(|phi| (phi, reach(phi)))
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap_or((0.0, 0.0));
    let (mut low, mut high) = (best - step, best + step);
    for _ in 0..100 {
        let (left, right) = (low + (high - low) / 3.0, high - (high - low) / 3.0);
        if reach(left) < reach(right) {
            low = left;
        } else {
            high = right;
        }
    }
    reach(0.5 * (low + high))
}

/// The relative error of `rf_two_section_width` for the unit normal and direction `n`, `d`: the
/// f32 axis is off the exact one by its rounding (u), the unit inputs by theirs (`unit_excess`);
/// every term of the eigenvalue is at most twice the eigenvalue, so the evaluation's twenty-odd
/// roundings stay within 24 u of it, except the tilts' (`n . t`), whose absolute error (4 u)
/// becomes `4 u |tilt| / lambda <= 4 u / c` relative once squared; the square roots halve what is
/// left.
fn two_section_error(n: Vec3, d: Vec3) -> f64 {
    let cosine = n.as_dvec3().normalize().dot(d.as_dvec3().normalize()).abs();
    (24.0 + 8.0 / cosine) * U + 4.0 * unit_excess(n, d)
}

/// A reference of `rf_two_section_width`: the ellipse's rays intersected with the surface.
fn two_section_width_sampled() -> Reference<TwoSectionArgs, f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the beam's rays around its two sections (a = w_t t, b = w_s s across the ray) each intersected with the surface in f64, the longest distance from the hit found by sampling and a ternary search; times |cos|",
        two_section_beam,
        |&(tangential, sagittal, turn, n, d), two_section_width| {
            let (sagittal_axis, _) = section_axes(n, d, turn);
            let args = (tangential as f32, sagittal as f32, sagittal_axis.as_vec3(), n.as_vec3(), d.as_vec3());
            let got = two_section_width(args);
            let (n, d) = (args.3.as_dvec3().normalize(), args.4.as_dvec3().normalize());
            let (sagittal_axis, tangential_axis) = section_axes(n, d, turn);
            let (w_t, w_s) = (f64::from(args.0), f64::from(args.1));
            let exact = n.dot(d).abs() * sampled_longer_axis(tangential_axis * w_t, sagittal_axis * w_s, n, d);
            // 1.01 for the search's own error.
            let relative = two_section_error(args.3, args.4);
            Some(Deviation::within(f64::from(got), exact, 1.01 * relative * exact))
        },
    )
}

/// A reference of `rf_two_section_width`: what a round beam, a head-on beam and the same beam described the
/// other way round give.
fn two_section_width_limits() -> Reference<TwoSectionArgs, f32> {
    Reference::new(
        Kind::Identity,
        "equal widths are a round cone (|w| at any slant); head on the larger width; the sections swapped with the axis turned a quarter turn are the same beam, the same width",
        two_section_beam,
        |&(tangential, sagittal, turn, n, d), two_section_width| {
            let (sagittal_axis, tangential_axis) = section_axes(n, d, turn);
            let (n32, d32, w_t, w_s) = (n.as_vec3(), d.as_vec3(), tangential as f32, sagittal as f32);
            let round = two_section_width((w_t, w_t, sagittal_axis.as_vec3(), n32, d32));
            let head_on = two_section_width((w_t, w_s, sagittal_axis.as_vec3(), n32, -n32));
            let given = two_section_width((w_t, w_s, sagittal_axis.as_vec3(), n32, d32));
            let swapped = two_section_width((w_s, w_t, tangential_axis.as_vec3(), n32, d32));
            // Twice the error for the swap (both sides round); head on every tilt is within 4 u
            // of 0.
            let relative = two_section_error(n32, d32);
            let larger = f64::from(w_t.abs().max(w_s.abs()));
            let round = Deviation::within(f64::from(round), f64::from(w_t.abs()), relative * f64::from(w_t.abs()));
            let head_on = Deviation::within(f64::from(head_on), larger, 32.0 * U * larger);
            let swap = Deviation::within(f64::from(swapped), f64::from(given), 2.0 * relative * f64::from(given));
            Some(round.and(head_on).and(swap))
        },
    )
}
