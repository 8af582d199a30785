//! The proof of [`sample_grad_gradients`](ray_footprint::ray_diff::sample_grad_gradients): its
//! record and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::texel_gradients;
use crate::ray_diff::intervals::{self};
use crate::ray_diff::reference::components;
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Kind, Reference, U};
use crate::special::Perturb;
use glam::Vec2;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval2, Interval};
use shader_proptest::{Args, Value};

/// The record of `rf_sample_grad_gradients`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayDiff,
        "sample_grad_gradients",
        |(g, scale)| rd::sample_grad_gradients(g, scale),
        || (derivatives2(), uniform(-1.0, 4.0)).boxed(),
    )
    .enclosure(|&(g, scale)| {
        let scale = Interval::exact(scale.max(0.0));
        intervals::derivatives2(interval2(g.dx) * scale, interval2(g.dy) * scale)
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the gradients exchanged",
        |&(g, scale): &(Derivatives2, f32)| (swapped2(g), scale),
        swapped2,
    ))
    .symmetry(Symmetry::scale(
        "the gradients scaled by s: the result by s",
        |&(g, scale): &(Derivatives2, f32), s| (Derivatives2::new(g.dx * s, g.dy * s), scale),
        |g: Derivatives2, s| Derivatives2::new(g.dx / s, g.dy / s),
    ))
    .fuzz(|d| (d.derivatives2(), d.scalar()))
    .degenerate(vec![
        value(
            "negative scale",
            "0 (scale clamped to >= 0)",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), -1.0),
            vec![0.0; 4],
        ),
        value(
            "scale 0",
            "0 (samples mip 0)",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), 0.0),
            vec![0.0; 4],
        ),
        value(
            "scale 1",
            "the gradients unchanged",
            (Derivatives2::new(Vec2::new(0.5, -0.25), Vec2::new(2.0, 1.0)), 1.0),
            vec![0.5, -0.25, 2.0, 1.0],
        ),
    ])
}

/// The reference of `rf_sample_grad_gradients`.
fn reference() -> Reference<(Derivatives2, f32), Derivatives2> {
    Reference::new(
        Kind::ClosedForm,
        "the UV gradients scaled in f64 by max(tex_grad_scale, 0): mip 0 for a scale of 0 or below, the footprint blurred above 1",
        || (texel_gradients(), prop_oneof![-1.0f32..4.0, Just(0.0f32), Just(1.0f32)]).boxed(),
        |&(g, scale), sample_grad_gradients| {
            let got = sample_grad_gradients((g, scale));
            let s = f64::from(scale).max(0.0);
            let expected = [g.dx.x, g.dx.y, g.dy.x, g.dy.y].map(|c| f64::from(c) * s);
            // One product each.
            Some(components(got, &expected, |i| U * expected[i].abs()))
        },
    )
}
