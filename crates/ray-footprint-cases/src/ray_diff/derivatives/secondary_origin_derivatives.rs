//! The proof of
//! [`secondary_origin_derivatives`](ray_footprint::ray_diff::secondary_origin_derivatives): its
//! record, its enclosure and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::Hit;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{triangle, with_corners};
use glam::{Vec2, Vec3};
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval};
use shader_proptest::{Args, Value};

/// The record of `rf_secondary_origin_derivatives`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "secondary_origin_derivatives",
        |(b, p0, p1, p2)| rd::secondary_origin_derivatives(b, p0, p1, p2),
        || with_corners(derivatives2(), triangle()),
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the triangle turned: the derivatives turned",
        |&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3), r| (b, r * p0, r * p1, r * p2),
        |d: Derivatives3, r| turned3(d, r.transpose()),
    ))
    .symmetry(Symmetry::translation(
        "the triangle moved: the same",
        |&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3), o| (b, p0 + o, p1 + o, p2 + o),
        |d: Derivatives3, _| d,
    ))
    .symmetry(Symmetry::scale(
        "the triangle scaled by s: the derivatives by s",
        |&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3), s| (b, p0 * s, p1 * s, p2 * s),
        |d: Derivatives3, s| Derivatives3::new(d.dx / s, d.dy / s),
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the derivatives exchanged",
        |&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3)| (swapped2(b), p0, p1, p2),
        swapped3,
    ))
    .fuzz(|d| (d.derivatives2(), d.vec3(), d.vec3(), d.vec3()))
    .degenerate(vec![
        value(
            "zero-area triangle (one point)",
            "0: the hit cannot move",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), x, x, x),
            vec![0.0; 6],
        ),
        value(
            "zero barycentric differentials",
            "0",
            (Derivatives2::default(), Vec3::ZERO, x, y),
            vec![0.0; 6],
        ),
        value(
            "clamped differentials (+-DIFF_MAX_VALUE), unit triangle",
            "DIFF_MAX_VALUE e1 and -DIFF_MAX_VALUE e2: finite",
            (
                Derivatives2::new(Vec2::new(max, 0.0), Vec2::new(0.0, -max)),
                Vec3::ZERO,
                x,
                y,
            ),
            vec![max, 0.0, 0.0, 0.0, -max, 0.0],
        ),
    ])
}

/// `rf_secondary_origin_derivatives` in interval arithmetic, in the same order of operations.
fn enclosure(&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3)) -> Vec<Interval> {
    let e1 = interval3(p1) - interval3(p0);
    let e2 = interval3(p2) - interval3(p0);
    intervals::derivatives3(
        e1 * Interval::exact(b.dx.x) + e2 * Interval::exact(b.dx.y),
        e1 * Interval::exact(b.dy.x) + e2 * Interval::exact(b.dy.y),
    )
}

/// The reference of `rf_secondary_origin_derivatives`.
fn reference() -> Reference<(Derivatives2, Vec3, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the re-intersected hit points themselves (origin + s direction, not through barycentrics), against the origins from the exact (du, dv) (RTG Eq. 22)",
        Hit::strategy,
        |hit, secondary_origin_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let [p0, p1, p2] = hit.corners;
            let got = secondary_origin_derivatives((input, p0, p1, p2));
            let [dx, dy] = hit.along(|(_, point)| point);
            let p = hit.corners64();
            let edges = (p[1] - p[0]).length() + (p[2] - p[0]).length();
            let rounding = widths(&enclosure(&(input, p0, p1, p2)));
            let expected = listed(&[dx.value, dy.value], 0);
            let error = dx.error.max(dy.error) + input_error * edges;
            Some(components(got, &expected, |i| rounding[i] + error))
        },
    )
}
