//! The proof of [`planar_mapping_gradients`](ray_footprint::ray_diff::planar_mapping_gradients):
//! its record and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::mapping::shared::{cancellation, moved, point_and_differentials};
use crate::ray_diff::reference::components;
use crate::ray_diff::strategy::derivatives3;
use crate::record::Record;
use crate::reference::{Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::vec2_of;
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::interval2;
use shader_proptest::{Args, Value};

/// The record of `rf_planar_mapping_gradients`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let y = Vec3::Y;
    Record::new(
        Module::RayDiff,
        "planar_mapping_gradients",
        |(dp, scale)| rd::planar_mapping_gradients(dp, scale),
        || {
            (
                derivatives3(),
                vec2_of(uniform(-10.0, 10.0), uniform(-10.0, 10.0)),
            )
                .boxed()
        },
    )
    .enclosure(|&(dp, scale)| {
        let project = |v: Vec3| interval2(Vec2::new(v.x, v.z)) * interval2(scale);
        intervals::derivatives2(project(dp.dx), project(dp.dy))
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the gradients exchanged",
        |&(dp, scale): &(Derivatives3, Vec2)| (swapped3(dp), scale),
        swapped2,
    ))
    .symmetry(Symmetry::scale(
        "the position derivatives scaled by s: the gradients by s",
        |&(dp, scale): &(Derivatives3, Vec2), s| (Derivatives3::new(dp.dx * s, dp.dy * s), scale),
        |g: Derivatives2, s| Derivatives2::new(g.dx / s, g.dy / s),
    ))
    .fuzz(|d| (d.derivatives3(), d.vec2()))
    .degenerate(vec![
        value(
            "zero scale",
            "0",
            (Derivatives3::new(Vec3::ONE, Vec3::ONE), Vec2::ZERO),
            vec![0.0; 4],
        ),
        value(
            "position changing along y only (normal to the mapping plane)",
            "0",
            (Derivatives3::new(y, -2.0 * y), Vec2::ONE),
            vec![0.0; 4],
        ),
        value(
            "negative scale (-1, 0.5)",
            "mirrored in u: dx = (-1, 1), dy = (0, -2)",
            (
                Derivatives3::new(Vec3::new(1.0, 0.0, 2.0), Vec3::new(0.0, 0.0, -4.0)),
                Vec2::new(-1.0, 0.5),
            ),
            vec![-1.0, 1.0, 0.0, -2.0],
        ),
    ])
}

/// The reference of `rf_planar_mapping_gradients`.
fn reference() -> Reference<(Derivatives3, Vec2), Derivatives2> {
    Reference::new(
        Kind::ClosedForm,
        "the planar mapping uv = p.xz * scale evaluated at a point and at the point moved by each position differential, in f64: their differences (Quilez)",
        || (point_and_differentials(), -10.0f32..10.0, -10.0f32..10.0).boxed(),
        |&((p, d), sx, sy), planar_mapping_gradients| {
            let scale = Vec2::new(sx, sy);
            let got = planar_mapping_gradients((d, scale));
            let s = scale.as_dvec2();
            let expected = moved(p, d, |q| [q.x * s.x, q.z * s.y]);
            // One product each.
            let slack = cancellation(p, d, s.length());
            Some(components(got, &expected, |i| U * expected[i].abs() + slack))
        },
    )
}
