//! The proof of [`cone_barycentric_deltas`](ray_footprint::ray_diff::cone_barycentric_deltas): its
//! record, where it is checked, its enclosure and its reference.

use crate::conditioning::well_conditioned;
use crate::degenerate::{same, value};
use crate::exact::signed_log;
use crate::ray_diff::changes::*;
use crate::ray_diff::cones::shared::scaled_length;
use crate::ray_diff::reference::{components, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::strategy::{scalar, triangle, with_corners};
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, DIFF_MAX_VALUE, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};

/// The record of `rf_cone_barycentric_deltas`: the enclosure of the deltas.
pub fn record() -> Record<(f32, Vec3, Vec3, Vec3), Vec3> {
    let x = Vec3::X;
    Record::new(
        Module::RayDiff,
        "cone_barycentric_deltas",
        |(f, p0, p1, p2)| rd::cone_barycentric_deltas(f, p0, p1, p2),
        || with_corners(scalar(), triangle()),
    )
    .conditioned(
        "a sliver or a repeated vertex within rounding (the doubled area is not known to 2^-10): \
         the deltas may take anything up to the clamp DIFF_MAX_VALUE",
        area_well_conditioned,
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the triangle turned: the same",
        |&(f, p0, p1, p2): &(f32, Vec3, Vec3, Vec3), r| (f, r * p0, r * p1, r * p2),
        |deltas: Vec3, _| deltas,
    ))
    .symmetry(Symmetry::translation(
        "the triangle moved: the same",
        |&(f, p0, p1, p2): &(f32, Vec3, Vec3, Vec3), t| (f, p0 + t, p1 + t, p2 + t),
        |deltas: Vec3, _| deltas,
    ))
    .symmetry(
        Symmetry::scale(
            "the footprint and the triangle scaled by s, where no clamp acts: the same",
            |&(f, p0, p1, p2): &(f32, Vec3, Vec3, Vec3), s| (f * s, p0 * s, p1 * s, p2 * s),
            |deltas: Vec3, _| deltas,
        )
        .within(|&(f, p0, p1, p2)| {
            let area2 = (p1 - p0).as_dvec3().cross((p2 - p0).as_dvec3()).length();
            let deltas = rd::cone_barycentric_deltas(f, p0, p1, p2);
            area2 > 2.0 * f64::from(DIFF_MIN_MAGNITUDE) && deltas.max_element() < 0.5 * DIFF_MAX_VALUE
        }),
    )
    .symmetry(Symmetry::exchange(
        "the vertex order turned: the deltas rotated",
        |&(f, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)| (f, p1, p2, p0),
        |deltas: Vec3| deltas.zxy(),
    ))
    .fuzz(|d| (d.scalar(), d.vec3(), d.vec3(), d.vec3()))
    .range(0.0, rd::DIFF_MAX_VALUE, "delta")
    .degenerate(vec![
        value(
            "zero-area triangle",
            "DIFF_MAX_VALUE each",
            (1.0, Vec3::ZERO, x, 2.0 * x),
            vec![rd::DIFF_MAX_VALUE; 3],
        ),
        value(
            "zero-area triangle, zero footprint",
            "0",
            (0.0, Vec3::ZERO, x, 2.0 * x),
            vec![0.0; 3],
        ),
        same(
            "negative footprint, zero-area triangle",
            "as |footprint|",
            (-1.0, Vec3::ZERO, x, 2.0 * x),
            (1.0, Vec3::ZERO, x, 2.0 * x),
        ),
    ])
}

/// The enclosure of twice the area of the triangle `p0 p1 p2`, `|cross(p1 - p0, p2 - p0)|`.
fn doubled_area(p0: Interval3, p1: Interval3, p2: Interval3) -> Interval {
    scaled_length((p1 - p0).cross(p2 - p0))
}

/// Whether the doubled area of the triangle is known to
/// [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED) (an exact 0 is).
fn area_well_conditioned(&(_, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> bool {
    well_conditioned(doubled_area(interval3(p0), interval3(p1), interval3(p2)))
}

/// `rf_cone_barycentric_deltas` in interval arithmetic, in the same order of operations.
fn enclosure(&(footprint, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> Vec<Interval> {
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    let area2 = doubled_area(p0, p1, p2).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    [p2 - p1, p2 - p0, p1 - p0]
        .iter()
        .map(|&edge| {
            (Interval::exact(footprint.abs()) * scaled_length(edge) / area2).min_c(f64::from(DIFF_MAX_VALUE))
        })
        .collect()
}

/// The height of `vertex` over the line through `a` and `b`: its distance from the foot of the
/// perpendicular.
fn height(vertex: DVec3, a: DVec3, b: DVec3) -> f64 {
    let edge = b - a;
    let foot = a + edge * ((vertex - a).dot(edge) / edge.dot(edge));
    (vertex - foot).length()
}

/// The reference of `rf_cone_barycentric_deltas`.
fn reference() -> Reference<(f32, Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "|footprint| over each vertex's height above its opposite edge, the height measured to the foot of the perpendicular in f64",
        || {
            (signed_log(-6.0, 2.0), triangle())
                .prop_filter("a sliver", |(_, p)| {
                    let (e1, e2) = ((p[1] - p[0]).as_dvec3(), (p[2] - p[0]).as_dvec3());
                    e1.cross(e2).length() > 1.0e-3 * e1.length() * e2.length()
                })
                .boxed()
        },
        |&(footprint, p), cone_barycentric_deltas| {
            let footprint = footprint as f32;
            let q = p.map(Vec3::as_dvec3);
            let f = f64::from(footprint).abs();
            let expected = [f / height(q[0], q[1], q[2]), f / height(q[1], q[2], q[0]), f / height(q[2], q[0], q[1])];
            if expected.iter().any(|&delta| delta > 0.99 * f64::from(DIFF_MAX_VALUE)) {
                return None;
            }
            let got = cone_barycentric_deltas((footprint, p[0], p[1], p[2]));
            let bounds = widths(&enclosure(&(footprint, p[0], p[1], p[2])));
            Some(components(got, &expected, |i| bounds[i] + 1.0e-12 * expected[i]))
        },
    )
}
