//! The proof of [`triplanar_gradients`](ray_footprint::ray_diff::triplanar_gradients): its record
//! and its reference.

use crate::degenerate::{parts, value};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::mapping::shared::{cancellation, moved, point_and_differentials};
use crate::ray_diff::reference::components;
use crate::ray_diff::strategy::derivatives3;
use crate::record::Record;
use crate::reference::{Kind, Reference, U};
use crate::special::Perturb;
use glam::{DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, TriplanarGradients};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval3, Interval, Interval3, IntervalVec};
use shader_proptest::{Args, Value};

/// The record of `rf_triplanar_gradients`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    Record::new(
        Module::RayDiff,
        "triplanar_gradients",
        |(dp, scale)| rd::triplanar_gradients(dp, scale),
        || (derivatives3(), uniform(-10.0, 10.0)).boxed(),
    )
    .enclosure(|&(dp, scale)| {
        let (dx, dy) = (
            interval3(dp.dx) * Interval::exact(scale),
            interval3(dp.dy) * Interval::exact(scale),
        );
        let pick = |v: Interval3, a: usize, b: usize| IntervalVec([v.0[a], v.0[b]]);
        let planes = [(1, 2), (2, 0), (0, 1)];
        let all: Vec<Interval> = planes
            .iter()
            .flat_map(|&(a, b)| intervals::derivatives2(pick(dx, a, b), pick(dy, a, b)))
            .collect();
        all
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: each projection's gradients exchanged",
        |&(dp, scale): &(Derivatives3, f32)| (swapped3(dp), scale),
        |g: TriplanarGradients| TriplanarGradients {
            yz: swapped2(g.yz),
            zx: swapped2(g.zx),
            xy: swapped2(g.xy),
        },
    ))
    .symmetry(Symmetry::scale(
        "the position derivatives scaled by s: the gradients by s",
        |&(dp, scale): &(Derivatives3, f32), s| (Derivatives3::new(dp.dx * s, dp.dy * s), scale),
        |g: TriplanarGradients, s| {
            let back = |d: Derivatives2| Derivatives2::new(d.dx / s, d.dy / s);
            TriplanarGradients {
                yz: back(g.yz),
                zx: back(g.zx),
                xy: back(g.xy),
            }
        },
    ))
    .fuzz(|d| (d.derivatives3(), d.scalar()))
    .degenerate(vec![
        value(
            "zero scale",
            "0 for every projection",
            (Derivatives3::new(Vec3::ONE, Vec3::ONE), 0.0),
            vec![0.0; 12],
        ),
        value(
            "zero position differentials",
            "0 for every projection",
            (Derivatives3::default(), 2.0),
            vec![0.0; 12],
        ),
        value(
            "dp/dx = (1, 0, 0), dp/dy = (0, 1, 0), scale 2",
            "each projection sees its own two axes: yz gets (0, 0) and (2, 0)",
            (Derivatives3::new(x, y), 2.0),
            parts(TriplanarGradients {
                yz: Derivatives2::new(Vec2::ZERO, Vec2::new(2.0, 0.0)),
                zx: Derivatives2::new(Vec2::new(0.0, 2.0), Vec2::ZERO),
                xy: Derivatives2::new(Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0)),
            }),
        ),
    ])
}

/// The reference of `rf_triplanar_gradients`.
fn reference() -> Reference<(Derivatives3, f32), TriplanarGradients> {
    Reference::new(
        Kind::ClosedForm,
        "the three projections p.yz, p.zx, p.xy times the scale evaluated at a point and at the point moved by each position differential, in f64: their differences (Quilez)",
        || (point_and_differentials(), -10.0f32..10.0).boxed(),
        |&((p, d), scale), triplanar_gradients| {
            let got = triplanar_gradients((d, scale));
            let s = f64::from(scale);
            let projection = |f: fn(DVec3) -> DVec2| moved(p, d, move |q| (f(q) * s).to_array());
            let expected = [
                projection(|q| DVec2::new(q.y, q.z)),
                projection(|q| DVec2::new(q.z, q.x)),
                projection(|q| DVec2::new(q.x, q.y)),
            ]
            .concat();
            let slack = cancellation(p, d, s.abs());
            Some(components(got, &expected, |i| U * expected[i].abs() + slack))
        },
    )
}
