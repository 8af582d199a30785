//! The proof of [`process_wireframe`](ray_footprint::wireframe::process_wireframe): its record,
//! its coverage error bound and its reference.

use crate::degenerate::{mirror, same, value, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::symmetry::Symmetry;
use crate::wireframe::coverage::shared::{
    coverage_f64, edge_thickness_error, edge_thickness_f64, hit, line_width_error, stipple_f64,
    stipple_may_flip, AMBIGUOUS_COVERAGE, AT_AN_EDGE,
};
use crate::wireframe::strategy::settings;
use glam::Vec3;
use glam::Vec3Swizzles;
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, WireframeSettings, WIREFRAME_DEFAULT};
use shader_proptest::tolerance::ulps;

/// The record of `rf_process_wireframe`: the coverage error derived in `process_wireframe_error`.
pub fn record() -> Record<(WireframeSettings, Vec3, Vec3), f32> {
    let on_edge = Vec3::new(0.0, 0.5, 0.5);
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    Record::new(
        Module::Wireframe,
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
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the vertex order turned (barycentrics and deltas rotated together): the same",
        |&(settings, b, deltas): &(WireframeSettings, Vec3, Vec3)| (settings, b.yzx(), deltas.yzx()),
        |coverage: f32| coverage,
    ))
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

/// The default settings changed by `f`, for the degenerate rows.
fn default_with(f: impl FnOnce(&mut WireframeSettings)) -> WireframeSettings {
    let mut settings = WIREFRAME_DEFAULT;
    f(&mut settings);
    settings
}

/// Largest `|device - mirror|` of `process_wireframe`: the half width `0.5 * thickness * et` carries
/// `edge_thickness`'s error times `0.5 * thickness`, plus its own rounding (an ULP: a different
/// `et` may round the other way); `thickness * smoothing` is the same product on both sides. Then
/// as `line_width`; a dash boundary within its band allows either coverage (the factor is 0 or 1).
fn process_wireframe_error(settings: WireframeSettings, b: Vec3, deltas: Vec3) -> f32 {
    let e = wf::edge_position(b);
    if settings.stipple && stipple_may_flip(settings.stipple_repeats, settings.stipple_length, e) {
        return 1.0;
    }
    let thickness = settings.thickness.max(0.0);
    let edge_thickness = wf::edge_thickness(settings.thickness_var, e);
    let half_width = 0.5 * thickness * edge_thickness;
    let half_width_error =
        0.5 * thickness * edge_thickness_error(settings.thickness_var) + ulps(1.0, half_width);
    let pixel_deltas = if settings.screen_space { deltas } else { Vec3::ONE };
    let ramp_width = thickness * settings.smoothing;
    line_width_error(pixel_deltas, half_width, half_width_error, ramp_width, b)
}

/// The reference of `rf_process_wireframe`.
fn reference() -> Reference<(WireframeSettings, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the coverage max_i (1 - ramp_i) of the half width 0.5 th (var.x + (var.y - var.x) (1 - sin(pi e))) and ramp th sm, times the dash pattern of e = max b, composed in f64 as the other wireframe references evaluate them",
        || (settings(), hit()).prop_map(|(settings, (b, d))| (settings, b, d)).boxed(),
        |&(settings, b, deltas), process_wireframe| {
            let got = process_wireframe((settings, b, deltas));
            let e = b.max_element();
            let thickness = f64::from(settings.thickness.max(0.0));
            let (factor, factor_error) = edge_thickness_f64(settings.thickness_var, e);
            // 0.5 * th is exact; times the factor: one rounding (u) of the product.
            let half_width = 0.5 * thickness * factor;
            let half_width_error = 0.5 * thickness * factor_error + U * half_width;
            let ramp_width = thickness * f64::from(settings.smoothing);
            let d = if settings.screen_space { deltas } else { Vec3::ONE };
            let (coverage, bound) = coverage_f64(d, half_width, half_width_error, ramp_width, U, b)?;
            let dash = if settings.stipple {
                stipple_f64(settings.stipple_repeats, settings.stipple_length, e)?
            } else {
                1.0
            };
            // The dash is exact (0 or 1): the coverage's bound and the product's rounding (u).
            Some(Deviation::within(f64::from(got), coverage * dash, bound + U))
        },
    )
}
