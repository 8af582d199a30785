//! The proof of [`line_width`](ray_footprint::wireframe::line_width): its record and its
//! reference.

use crate::degenerate::value;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::symmetry::Symmetry;
use crate::wireframe::coverage::shared::{
    coverage_f64, hit, line_width_error, AMBIGUOUS_COVERAGE, AT_AN_EDGE,
};
use crate::wireframe::strategy::size;
use glam::Vec3;
use glam::Vec3Swizzles;
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe as wf;
use shader_proptest::{Args, Value};

/// The record of `rf_line_width`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    Record::new(
        Module::Wireframe,
        "line_width",
        |(d, thickness, smoothing, b)| wf::line_width(d, thickness, smoothing, b),
        || {
            (hit(), size(), size())
                .prop_map(|((b, d), thickness, smoothing)| (d, thickness, smoothing, b))
                .boxed()
        },
    )
    .conditioned(AT_AN_EDGE, |&(d, thickness, smoothing, b)| {
        line_width_error(d, thickness, 0.0, smoothing, b) < AMBIGUOUS_COVERAGE
    })
    .bound(|&(d, thickness, smoothing, b), _, _| line_width_error(d, thickness, 0.0, smoothing, b))
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the vertex order turned (deltas and barycentrics rotated together): the same",
        |&(deltas, thickness, smoothing, b): &(Vec3, f32, f32, Vec3)| {
            (deltas.yzx(), thickness, smoothing, b.yzx())
        },
        |coverage: f32| coverage,
    ))
    .symmetry(Symmetry::exchange(
        "the deltas negated: the same",
        |&(deltas, thickness, smoothing, b): &(Vec3, f32, f32, Vec3)| (-deltas, thickness, smoothing, b),
        |coverage: f32| coverage,
    ))
    .fuzz(|d| (d.vec3(), d.scalar(), d.scalar(), d.vec3()))
    .range(0.0, 1.0, "coverage")
    .degenerate(vec![
        value(
            "smoothing 0, inside the line",
            "1 (hard step)",
            (deltas, 1.0, 0.0, near_edge),
            vec![1.0],
        ),
        value(
            "smoothing 0, outside the line",
            "0 (hard step)",
            (deltas, 0.1, 0.0, near_edge),
            vec![0.0],
        ),
        value(
            "zero deltas",
            "0 (a line of zero width)",
            (Vec3::ZERO, 1.0, 1.0, near_edge),
            vec![0.0],
        ),
    ])
}

/// The reference of `rf_line_width`.
fn reference() -> Reference<(Vec3, f32, f32, Vec3), f32> {
    Reference::new(
        Kind::ClosedForm,
        "max_i (1 - ramp_i) with ramp_i = 3 t^2 - 2 t^3 from |d_i| th to |d_i| (th + sm), a hard step where |d_i| sm <= MIN_LINE_RAMP, in f64",
        || (hit(), size(), size()).prop_map(|((b, d), th, sm)| (d, th, sm, b)).boxed(),
        |&(deltas, thickness, smoothing, b), line_width| {
            let got = line_width((deltas, thickness, smoothing, b));
            let (th, sm) = (f64::from(thickness), f64::from(smoothing));
            let (expected, bound) = coverage_f64(deltas, th, 0.0, sm, 0.0, b)?;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
