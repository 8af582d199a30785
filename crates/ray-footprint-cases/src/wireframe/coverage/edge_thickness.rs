//! The proof of [`edge_thickness`](ray_footprint::wireframe::edge_thickness): its record and its
//! reference.

use crate::degenerate::same;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::vec2_of;
use crate::wireframe::coverage::shared::{edge_thickness_error, edge_thickness_f64, position_along_edge};
use crate::wireframe::strategy::size;
use glam::Vec2;
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe as wf;
use shader_proptest::{Args, Value};

/// The record of `rf_edge_thickness`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::Wireframe,
        "edge_thickness",
        |(var, e)| wf::edge_thickness(var, e),
        || (vec2_of(size(), size()), position_along_edge()).boxed(),
    )
    .bound(|&(var, _), _, _| edge_thickness_error(var))
    .reference(reference())
    .without_symmetry(
        "a blend of two clamped factors by 1 - sin(pi e): the factors' clamp to \
         [0, MAX_LINE_THICKNESS] rules out a scale, and the reflection e -> 1 - e is not exact \
         in f32",
    )
    .fuzz(|d| (d.vec2(), d.scalar()))
    .range(0.0, wf::MAX_LINE_THICKNESS, "thickness")
    .degenerate(vec![
        same(
            "edge position 2",
            "as edge position 1 (clamped to `[0, 1]`)",
            (Vec2::new(0.5, 2.0), 2.0),
            (Vec2::new(0.5, 2.0), 1.0),
        ),
        same(
            "edge position -1",
            "as edge position 0",
            (Vec2::new(0.5, 2.0), -1.0),
            (Vec2::new(0.5, 2.0), 0.0),
        ),
        same(
            "negative thickness_var",
            "as 0",
            (Vec2::new(-1.0, 2.0), 0.5),
            (Vec2::new(0.0, 2.0), 0.5),
        ),
    ])
}

/// The reference of `rf_edge_thickness`.
fn reference() -> Reference<(Vec2, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "var.x + (var.y - var.x) a with 1 - sin(pi e) as 2 sin^2(pi (e - 1/2) / 2), in f64: var.x at an edge middle, var.y at a vertex",
        || ((size(), size()), position_along_edge()).prop_map(|((x, y), e)| (Vec2::new(x, y), e)).boxed(),
        |&(thickness_var, e), edge_thickness| {
            let got = edge_thickness((thickness_var, e));
            let (expected, error) = edge_thickness_f64(thickness_var, e);
            Some(Deviation::within(f64::from(got), expected, error))
        },
    )
}
