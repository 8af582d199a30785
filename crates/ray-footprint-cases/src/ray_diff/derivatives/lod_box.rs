//! The proof of [`lod_box`](ray_footprint::ray_diff::lod_box): its record, its enclosure and its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::texel_gradients;
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::one_argument;
use glam::{DVec2, Vec2};
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, Interval};
use shader_proptest::{Args, Value};

/// The record of `rf_lod_box`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayDiff,
        "lod_box",
        |(g,)| rd::lod_box(g),
        || one_argument(derivatives2()),
    )
    .enclosure(|&(g,)| vec![enclosure(g)])
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the same",
        |&(g,): &(Derivatives2,)| (swapped2(g),),
        |lod: f32| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the gradients negated: the same",
        |&(g,): &(Derivatives2,)| (Derivatives2::new(-g.dx, -g.dy),),
        |lod: f32| lod,
    ))
    .symmetry(Symmetry::scale_in_log(
        "the gradients scaled by s, where their size is above DIFF_MIN_MAGNITUDE (not clamped): the LOD plus log2 s",
        |&(g,): &(Derivatives2,), s| (Derivatives2::new(g.dx * s, g.dy * s),),
        |lod: f32, s| lod - s.log2(),
    ).within(|&(g,)| g.dx.abs().max_element().max(g.dy.abs().max_element()) > 1.0e-14))
    .fuzz(|d| (d.derivatives2(),))
    .range(rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
    .degenerate(vec![
        value(
            "zero gradients",
            "log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::default(),),
            vec![DIFF_MIN_MAGNITUDE.log2()],
        ),
        mirror(
            "NaN in",
            "CPU: log2 of the other components' extent (Rust's `max` ignores NaN)",
            (Derivatives2::new(Vec2::new(NAN, 1.0), Vec2::ZERO),),
            vec![0.0],
        ),
        value(
            "unit texel gradients",
            "0",
            (Derivatives2::new(Vec2::X, Vec2::Y),),
            vec![0.0],
        ),
        value(
            "dx = (1, 0), dy = (-1, 0)",
            "1: the box adds magnitudes, opposite signs do not cancel",
            (Derivatives2::new(Vec2::X, Vec2::NEG_X),),
            vec![1.0],
        ),
    ])
}

/// `rf_lod_box` in interval arithmetic, in the same order of operations.
fn enclosure(g: Derivatives2) -> Interval {
    let extent = interval2(g.dx).abs() + interval2(g.dy).abs();
    extent.0[0]
        .max(extent.0[1])
        .max_c(f64::from(DIFF_MIN_MAGNITUDE))
        .log2()
}

/// The reference of `rf_lod_box`.
fn reference() -> Reference<(Derivatives2,), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "log2 of the larger side of the axis-aligned box around the footprint parallelogram, from its four corners 0, dx, dy, dx + dy (RTG Sec. 20.1)",
        texel_gradients,
        |&g, lod_box| {
            let got = lod_box((g,));
            let corners = [DVec2::ZERO, g.dx.as_dvec2(), g.dy.as_dvec2(), (g.dx.as_dvec2() + g.dy.as_dvec2())];
            let side = |axis: usize| {
                let values = corners.map(|c| c[axis]);
                values.iter().copied().fold(f64::MIN, f64::max) - values.iter().copied().fold(f64::MAX, f64::min)
            };
            let expected = side(0).max(side(1)).log2();
            let bound = enclosure(g);
            Some(Deviation::within(f64::from(got), expected, bound.hi - bound.lo + 1.0e-15))
        },
    )
}
