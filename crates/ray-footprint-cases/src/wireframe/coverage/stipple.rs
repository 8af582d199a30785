//! The proof of [`stipple`](ray_footprint::wireframe::stipple): its record and its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::wireframe::coverage::shared::{position_along_edge, stipple_f64, stipple_may_flip};
use crate::wireframe::strategy::{stipple_length, stipple_repeats};
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe as wf;
use shader_proptest::{Args, Value};

/// The record of `rf_stipple`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    // 0 or 1, exact away from a dash boundary. Within its rounding band either value is right, so
    // those positions are checked separately (the edge-case suite).
    Record::new(
        Module::Wireframe,
        "stipple",
        |(repeats, length, e)| wf::stipple(repeats, length, e),
        || {
            (stipple_repeats(), stipple_length(), position_along_edge())
                .prop_filter("within rounding of a dash boundary", |&(repeats, length, e)| {
                    !stipple_may_flip(repeats, length, e)
                })
                .boxed()
        },
    )
    .reference(reference())
    .without_symmetry(
        "a dash pattern of the edge position clamped to [0, 1]: periodic in it, but a shift by a \
         period is not exact in f32 and the clamp ends the pattern",
    )
    .fuzz(|d| (d.int(), d.scalar(), d.scalar()))
    .promise(|_, on, promises| promises.within(on * (1.0 - on), 0.0, 0.0, "stipple * (1 - stipple)"))
    .degenerate(vec![
        value("repeats 0", "1 (no dashes)", (0, 0.5, 0.3), vec![1.0]),
        value("negative repeats", "1 (no dashes)", (-3, 0.5, 0.3), vec![1.0]),
        value("stipple length 0", "0 (nothing drawn)", (5, 0.0, 0.3), vec![0.0]),
        mirror(
            "NaN in (stipple length)",
            "CPU: 0 (pattern < NaN is false)",
            (5, NAN, 0.3),
            vec![0.0],
        ),
    ])
}

/// The reference of `rf_stipple`.
fn reference() -> Reference<(i32, f32, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "drawn where e lies within length / 2 of a multiple of 1 / repeats (dashes centred on the multiples), in f64; no dashes for repeats <= 0",
        || (stipple_repeats(), stipple_length(), position_along_edge()).boxed(),
        |&(repeats, length, e), stipple| {
            let got = stipple((repeats, length, e));
            // Off the boundaries the pattern is exact.
            Some(Deviation::within(f64::from(got), stipple_f64(repeats, length, e)?, 0.0))
        },
    )
}
