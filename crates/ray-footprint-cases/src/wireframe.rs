//! The records of the wireframe module, one per function, in the module's order.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. The wireframe's outputs have
//! thresholds (a dash boundary, a hard step) and a steep smoothstep: where a few ULP of difference
//! in an input may legitimately move the output across a threshold, the tolerance accepts either
//! side (as the ray-cone `curvature_sign` check does), and a smoothstep's error is its input's error
//! times its largest slope nearby.

mod bound;
mod reference;
mod strategy;

use crate::degenerate::{mirror, parts, same, value, NAN};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{one_argument, vec2_of, vec3};
use bound::{
    edge_ramp_error, edge_thickness_error, line_width_error, process_wireframe_error, stipple_may_flip,
    AMBIGUOUS_COVERAGE, AT_AN_EDGE,
};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, WireframeSettings, WireframeSettingsIo, WIREFRAME_DEFAULT};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};
use strategy::{
    barycentrics, edge_ramp_component, hit, position_along_edge, settings, settings_io, size, stipple_length,
    stipple_repeats,
};

/// The module of these records.
const MODULE: Module = Module::Wireframe;

/// The default settings changed by `f`, for the degenerate rows.
fn default_with(f: impl FnOnce(&mut WireframeSettings)) -> WireframeSettings {
    let mut settings = WIREFRAME_DEFAULT;
    f(&mut settings);
    settings
}

/// `rf_unpack_wireframe_settings`.
pub fn unpack_wireframe_settings() -> Record<impl Args + Perturb, impl Value> {
    let io = WireframeSettingsIo {
        stipple: 7,
        ..WIREFRAME_DEFAULT.pack()
    };
    // Copies and integer comparisons: exact.
    Record::new(
        MODULE,
        "unpack_wireframe_settings",
        |(io,)| wf::unpack_wireframe_settings(io),
        || one_argument(settings_io()),
    )
    .reference(reference::unpack_wireframe_settings())
    .fuzz(|d| (d.settings_io(),))
    .degenerate(vec![
        value(
            "flag 7 (any non-zero)",
            "true (packed again as 1)",
            (io,),
            parts(WireframeSettings {
                stipple: true,
                ..WIREFRAME_DEFAULT
            }),
        ),
        mirror(
            "NaN in (thickness)",
            "CPU: kept",
            (WireframeSettingsIo {
                thickness: NAN,
                ..WIREFRAME_DEFAULT.pack()
            },),
            parts(WireframeSettings {
                thickness: NAN,
                ..WIREFRAME_DEFAULT
            }),
        ),
        value(
            "flags 0",
            "false",
            (WireframeSettingsIo {
                stipple: 0,
                screen_space: 0,
                ..WIREFRAME_DEFAULT.pack()
            },),
            parts(WireframeSettings {
                stipple: false,
                screen_space: false,
                ..WIREFRAME_DEFAULT
            }),
        ),
        value(
            "flags -1 (negative)",
            "true (any non-zero)",
            (WireframeSettingsIo {
                stipple: -1,
                screen_space: -1,
                ..WIREFRAME_DEFAULT.pack()
            },),
            parts(WireframeSettings {
                stipple: true,
                screen_space: true,
                ..WIREFRAME_DEFAULT
            }),
        ),
    ])
}

/// `rf_edge_position`.
pub fn edge_position() -> Record<impl Args + Perturb, impl Value> {
    // max is exact.
    Record::new(
        MODULE,
        "edge_position",
        |(b,)| wf::edge_position(b),
        || one_argument(one_of![3 => barycentrics(), 1 => vec3()]),
    )
    .reference(reference::edge_position())
    .fuzz(|d| (d.vec3(),))
    .promise(|&(b,), e, promises| promises.within(e - b.max_element(), 0.0, 0.0, "edge position - max(b)"))
    .degenerate(vec![
        mirror(
            "NaN in (b.x)",
            "CPU: max(b.y, b.z) (Rust's `max` ignores NaN)",
            (Vec3::new(NAN, 0.2, 0.3),),
            vec![0.3],
        ),
        value("at a vertex (0, 1, 0)", "1", (Vec3::Y,), vec![1.0]),
        value(
            "at the centroid (1/3 each)",
            "1/3",
            (Vec3::splat(1.0 / 3.0),),
            vec![1.0 / 3.0],
        ),
        value(
            "outside the triangle (-0.5, 0.75, 0.75)",
            "0.75, the largest component",
            (Vec3::new(-0.5, 0.75, 0.75),),
            vec![0.75],
        ),
    ])
}

/// `rf_edge_thickness`.
pub fn edge_thickness() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "edge_thickness",
        |(var, e)| wf::edge_thickness(var, e),
        || (vec2_of(size(), size()), position_along_edge()).boxed(),
    )
    .bound(|&(var, _), _, _| edge_thickness_error(var))
    .reference(reference::edge_thickness())
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

/// `rf_stipple`.
pub fn stipple() -> Record<impl Args + Perturb, impl Value> {
    // 0 or 1, exact away from a dash boundary. Within its rounding band either value is right, so
    // those positions are checked separately (the edge-case suite).
    Record::new(
        MODULE,
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
    .reference(reference::stipple())
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

/// `rf_edge_ramp`: three independent components.
pub fn edge_ramp() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
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
    .reference(reference::edge_ramp())
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

/// `rf_line_width`.
pub fn line_width() -> Record<impl Args + Perturb, impl Value> {
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    Record::new(
        MODULE,
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
    .reference(reference::line_width())
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

/// `rf_process_wireframe`: the coverage error derived in `process_wireframe_error`.
pub fn process_wireframe() -> Record<(WireframeSettings, Vec3, Vec3), f32> {
    let on_edge = Vec3::new(0.0, 0.5, 0.5);
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    Record::new(
        MODULE,
        "process_wireframe",
        |(settings, b, d)| wf::process_wireframe(settings, b, d),
        || {
            (settings(), hit())
                .prop_map(|(settings, (b, d))| (settings, b, d))
                .boxed()
        },
    )
    .conditioned(AT_AN_EDGE, |&(settings, b, d)| {
        process_wireframe_error(settings, b, d) < AMBIGUOUS_COVERAGE
    })
    .bound(|&(settings, b, d), _, _| process_wireframe_error(settings, b, d))
    .reference(reference::process_wireframe())
    .fuzz(|d| (d.settings(), d.vec3(), d.vec3()))
    .range(0.0, 1.0, "coverage")
    .degenerate(vec![
        value(
            "smoothing 0, on an edge",
            "1 (hard step)",
            (default_with(|s| s.smoothing = 0.0), on_edge, deltas),
            vec![1.0],
        ),
        same(
            "stipple on, repeats 0",
            "as stipple off",
            (
                default_with(|s| {
                    s.stipple = true;
                    s.stipple_repeats = 0
                }),
                near_edge,
                deltas,
            ),
            (WIREFRAME_DEFAULT, near_edge, deltas),
        ),
        value(
            "thickness 0, on an edge",
            "0 (no line)",
            (default_with(|s| s.thickness = 0.0), on_edge, deltas),
            vec![0.0],
        ),
        mirror(
            "NaN in (thickness)",
            "CPU: 0 (the ramp's NaN bounds compare false)",
            (default_with(|s| s.thickness = NAN), near_edge, deltas),
            vec![0.0],
        ),
    ])
}

/// The module's records, in the module's order.
pub(crate) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        unpack_wireframe_settings,
        edge_position,
        edge_thickness,
        stipple,
        edge_ramp,
        line_width,
        process_wireframe
    ]
}
