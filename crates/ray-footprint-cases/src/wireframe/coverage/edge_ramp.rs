//! The proof of [`edge_ramp`](ray_footprint::wireframe::edge_ramp): its record, its case strategy
//! and its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{magnitude, HUGE, TINY};
use crate::symmetry::Symmetry;
use crate::wireframe::coverage::shared::{edge_ramp_error, ramp_f64, AMBIGUOUS_COVERAGE, AT_AN_EDGE};
use crate::wireframe::strategy::log_uniform;
use glam::Vec3;
use glam::Vec3Swizzles;
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, MIN_LINE_RAMP};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// The record of `rf_edge_ramp`: three independent components.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::Wireframe,
        "edge_ramp",
        |(x, start, width)| wf::edge_ramp(x, start, width),
        || {
            [
                edge_ramp_component(),
                edge_ramp_component(),
                edge_ramp_component(),
            ]
            .prop_map(|[a, b, c]| {
                let x = Vec3::new(a.0, b.0, c.0);
                let start = Vec3::new(a.1, b.1, c.1);
                let width = Vec3::new(a.2, b.2, c.2);
                (x, start, width)
            })
            .boxed()
        },
    )
    .conditioned(AT_AN_EDGE, |&(x, start, width)| {
        (0..3).all(|i| edge_ramp_error(x[i], start[i], width[i], 0.0) < AMBIGUOUS_COVERAGE)
    })
    // start is an input here, so only the division and the polynomial differ.
    .bound(|&(x, start, width), i, _| edge_ramp_error(x[i], start[i], width[i], 0.0))
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the three components rotated together: the ramp's components rotated",
        |&(x, start, width): &(Vec3, Vec3, Vec3)| (x.yzx(), start.yzx(), width.yzx()),
        |ramp: Vec3| ramp.zxy(),
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3()))
    .range(0.0, 1.0, "ramp")
    .degenerate(vec![
        value(
            "zero ramp width, x = start",
            "1 (hard step)",
            (Vec3::splat(0.5), Vec3::splat(0.5), Vec3::ZERO),
            vec![1.0; 3],
        ),
        value(
            "zero ramp width, x < start",
            "0 (hard step)",
            (Vec3::splat(0.4), Vec3::splat(0.5), Vec3::ZERO),
            vec![0.0; 3],
        ),
        mirror(
            "NaN in (x)",
            "CPU: 1 (NaN < start is false, Rust's `min` ignores NaN)",
            (Vec3::splat(NAN), Vec3::splat(0.5), Vec3::ONE),
            vec![1.0; 3],
        ),
    ])
}

/// One component of `rf_edge_ramp`'s arguments `(x, start, width)`: widths down to zero and
/// beyond `MIN_LINE_RAMP`, `x` on the ramp, at its start, or anywhere around it. Components on a
/// ramp steeper than the precision of `x - start` (either coverage is right) are left to the
/// edge-case suite, as in the line checks: three independent components would otherwise triple the
/// share of cases whose tolerance says nothing.
fn edge_ramp_component() -> impl Strategy<Value = (f32, f32, f32)> {
    let width = one_of![
        4 => log_uniform(-6.0, 0.0),
        1 => Just(0.0f32),
        1 => prop::sample::select(vec![1.0e-31f32, MIN_LINE_RAMP, 2.0e-30, TINY, HUGE]),
        1 => magnitude(),
    ];
    (uniform(-0.5, 1.5), magnitude(), width, uniform(0.0, 1.0))
        .prop_flat_map(|(x, start, width, k)| {
            one_of![
                Just((x, start, width)),
                Just((start + (2.0 * k - 0.5) * width, start, width)),
                Just((start, start, width)),
            ]
        })
        .prop_filter(AT_AN_EDGE, |&(x, start, width)| {
            edge_ramp_error(x, start, width, 0.0) < AMBIGUOUS_COVERAGE
        })
}

/// The reference of `rf_edge_ramp`.
fn reference() -> Reference<(Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "each component 0 below start, 3 t^2 - 2 t^3 (t = (x - start) / width, at most 1) above it, a hard step for width <= MIN_LINE_RAMP, in f64",
        || {
            [edge_ramp_component(), edge_ramp_component(), edge_ramp_component()]
                .prop_map(|[a, b, c]| {
                    (Vec3::new(a.0, b.0, c.0), Vec3::new(a.1, b.1, c.1), Vec3::new(a.2, b.2, c.2))
                })
                .boxed()
        },
        |&(x, start, width), edge_ramp| {
            let got = edge_ramp((x, start, width)).as_dvec3();
            let (x64, start64, width64) = (x.as_dvec3(), start.as_dvec3(), width.as_dvec3());
            // The inputs are exact: no start or width error beyond the mirror's own roundings.
            let mut deviations = Vec::new();
            for i in 0..3 {
                let (expected, bound) = ramp_f64(x64[i], start64[i], width64[i], 0.0, 0.0)?;
                deviations.push(Deviation::within(got[i], expected, bound));
            }
            Some(Deviation::worst(deviations))
        },
    )
}
