//! The proof of [`lod_isotropic`](ray_footprint::ray_diff::lod_isotropic): its record, its
//! enclosure and its reference.

use crate::degenerate::{mirror, value, INF};
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::texel_gradients;
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::one_argument;
use glam::Vec2;
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, Interval};

/// The record of `rf_lod_isotropic`: the enclosure of the LOD.
pub fn record() -> Record<(Derivatives2,), f32> {
    Record::new(
        Module::RayDiff,
        "lod_isotropic",
        |(g,)| rd::lod_isotropic(g),
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
    .range(0.5 * rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
    .degenerate(vec![
        value(
            "zero gradients",
            "0.5 log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::default(),),
            vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
        ),
        mirror(
            "infinity in",
            "CPU: inf",
            (Derivatives2::new(Vec2::new(INF, 0.0), Vec2::ZERO),),
            vec![INF],
        ),
        value(
            "unit texel gradients",
            "0 (one texel per pixel)",
            (Derivatives2::new(Vec2::X, Vec2::Y),),
            vec![0.0],
        ),
        value(
            "gradients of 1e-16 (rho^2 below DIFF_MIN_MAGNITUDE)",
            "0.5 log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::new(Vec2::new(1.0e-16, 0.0), Vec2::ZERO),),
            vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
        ),
    ])
}

/// `rf_lod_isotropic` in interval arithmetic, in the same order of operations.
fn enclosure(g: Derivatives2) -> Interval {
    let rho2 = interval2(g.dx)
        .dot(interval2(g.dx))
        .max(interval2(g.dy).dot(interval2(g.dy)));
    Interval::c(0.5) * rho2.max_c(f64::from(DIFF_MIN_MAGNITUDE)).log2()
}

/// The reference of `rf_lod_isotropic`.
fn reference() -> Reference<(Derivatives2,), f32> {
    Reference::new(
        Kind::ClosedForm,
        "log2 of the longer texel gradient, each length an f64 hypot, the log as ln / ln 2 (RTG Eq. 1-2)",
        texel_gradients,
        |&g, lod_isotropic| {
            let got = lod_isotropic((g,));
            let longer = f64::from(g.dx.x)
                .hypot(f64::from(g.dx.y))
                .max(f64::from(g.dy.x).hypot(f64::from(g.dy.y)));
            let expected = longer.ln() / std::f64::consts::LN_2;
            let bound = enclosure(g);
            Some(Deviation::within(f64::from(got), expected, bound.hi - bound.lo))
        },
    )
}
