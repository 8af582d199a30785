//! The proof of [`barycentric_w_derivatives`](ray_footprint::ray_diff::barycentric_w_derivatives):
//! its record and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::Hit;
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::one_argument;
use glam::Vec2;
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::interval2;
use shader_proptest::{Args, Value};

/// The record of `rf_barycentric_w_derivatives`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "barycentric_w_derivatives",
        |(b,)| rd::barycentric_w_derivatives(b),
        || one_argument(derivatives2()),
    )
    .enclosure(|&(b,)| {
        let (dx, dy) = (interval2(b.dx), interval2(b.dy));
        vec![-dx.0[0] - dx.0[1], -dy.0[0] - dy.0[1]]
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the two derivatives exchanged",
        |&(b,): &(Derivatives2,)| (swapped2(b),),
        |w: Vec2| w.yx(),
    ))
    .symmetry(Symmetry::scale(
        "the derivatives scaled by s: the result by s",
        |&(b,): &(Derivatives2,), s| (Derivatives2::new(b.dx * s, b.dy * s),),
        |w: Vec2, s| w / s,
    ))
    .fuzz(|d| (d.derivatives2(),))
    .degenerate(vec![
        value("zero", "0", (Derivatives2::default(),), vec![0.0; 2]),
        value(
            "du = -dv",
            "0: w does not change",
            (Derivatives2::new(Vec2::new(1.0, -1.0), Vec2::new(0.5, -0.5)),),
            vec![0.0; 2],
        ),
        value(
            "clamped differentials (+-DIFF_MAX_VALUE)",
            "(-2 DIFF_MAX_VALUE, 0): finite",
            (Derivatives2::new(Vec2::splat(max), Vec2::new(max, -max)),),
            vec![-2.0 * max, 0.0],
        ),
    ])
}

/// The reference of `rf_barycentric_w_derivatives`.
fn reference() -> Reference<(Derivatives2,), Vec2> {
    Reference::new(
        Kind::ClosedForm,
        "f64 central differences of w at the re-intersected hits computed as an area ratio, cross(p1 - P, p2 - P) . n / cross(e1, e2) . n, from the exact (du, dv) (RTG Eq. 20)",
        Hit::strategy,
        |hit, barycentric_w_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let got = barycentric_w_derivatives((input,));
            let p = hit.corners64();
            let n = (p[1] - p[0]).cross(p[2] - p[0]);
            let [dx, dy] = hit.along(|(_, point)| (p[1] - point).cross(p[2] - point).dot(n) / n.dot(n));
            // -du - dv: one rounding; the input's distance from the exact derivatives, twice.
            let bound = |b: Vec2, error: f64| U * f64::from((b.x + b.y).abs()) + 2.0 * input_error + error;
            let x = Deviation::within(f64::from(got.x), dx.value, bound(input.dx, dx.error));
            let y = Deviation::within(f64::from(got.y), dy.value, bound(input.dy, dy.error));
            Some(x.and(y))
        },
    )
}
