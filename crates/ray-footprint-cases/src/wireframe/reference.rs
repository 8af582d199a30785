//! Independent references of the wireframe records ([`crate::reference`]): the coverage, the dash
//! pattern and the thickness factor evaluated in f64 another way than the module does (the
//! smoothstep as `3 t^2 - 2 t^3`, `1 - sin(pi e)` as `2 sin^2(pi (e - 1/2) / 2)`, a dash as the
//! distance to the nearest multiple of `1 / repeats`, the coverage as `max_i (1 - ramp_i)`), and the
//! settings' pack round trip.
//!
//! Where an output has a threshold (a hard step, a dash boundary) and the mirror's rounding may put
//! an input on either side of it, either answer is right: such a case is left out (the runner
//! counts it) rather than checked against a bound that cannot fail. Everywhere else the bound is
//! the mirror's f32 rounding, derived next to each reference.

use super::strategy::{
    barycentrics, edge_ramp_component, hit, position_along_edge, settings, settings_io, size, stipple_length,
    stipple_repeats,
};
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use glam::{DVec3, Vec2, Vec3, Vec3Swizzles};
use proptest::prelude::*;
use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsIo, MAX_LINE_THICKNESS, MIN_LINE_RAMP};
use std::f64::consts::PI;

/// `rf_unpack_wireframe_settings`.
pub(super) fn unpack_wireframe_settings() -> Reference<(WireframeSettingsIo,), WireframeSettings> {
    Reference::new(
        Kind::Identity,
        "packing the unpacked settings gives the Io mirror back with each flag 0 or 1 (0 where it was 0), every float bit for bit",
        settings_io,
        |&io, unpack_wireframe_settings| {
            let packed = unpack_wireframe_settings((io,)).pack();
            let flag = |x: i32| i32::from(x != 0);
            let expected = WireframeSettingsIo {
                stipple: flag(io.stipple),
                screen_space: flag(io.screen_space),
                ..io
            };
            // Copies and comparisons: exact, bit for bit (NaN payloads included).
            let same = bytemuck::bytes_of(&packed) == bytemuck::bytes_of(&expected);
            Some(Deviation::new(if same { 0.0 } else { 1.0 }, 0.0))
        },
    )
}

/// `rf_edge_position`.
pub(super) fn edge_position() -> Reference<(Vec3,), f32> {
    Reference::new(
        Kind::Identity,
        "the last of the three barycentrics sorted in f64, the same for all six orders of them",
        barycentrics,
        |&b, edge_position| {
            let mut sorted = b.as_dvec3().to_array();
            sorted.sort_by(f64::total_cmp);
            let orders = [b, b.yzx(), b.zxy(), b.xzy(), b.zyx(), b.yxz()];
            // A selection of one of its arguments: exact.
            Some(Deviation::worst(orders.map(|order| {
                Deviation::within(f64::from(edge_position((order,))), sorted[2], 0.0)
            })))
        },
    )
}

/// `towards_vertex = 1 - sin(pi e)` in f64 as `2 sin^2(pi (e - 1/2) / 2)` (`1 - cos x = 2 sin^2(x / 2)`),
/// `e` clamped to `[0, 1]`.
fn towards_vertex(edge_position: f32) -> f64 {
    let e = f64::from(edge_position.clamp(0.0, 1.0));
    let half = (PI * (e - 0.5) / 2.0).sin();
    (2.0 * half * half).clamp(0.0, 1.0)
}

/// The largest error of the mirror's `1 - sin(e * pi)`: the f32 `pi` (relative 2.8e-8) and the
/// product (u) move the argument by at most `pi (2.8e-8 + u) < 2.8e-7`, which `sin` (slope <= 1)
/// carries through; `sin` itself is within one ULP of its result (`<= 2u` below 1) and `1 - s`
/// rounds once (u): at most `5e-7`.
const TOWARDS_VERTEX_ERROR: f64 = 5.0e-7;

/// The thickness factor `var.x + (var.y - var.x) a` in f64 and the mirror's largest deviation from
/// it: `|var.y - var.x|` times [`TOWARDS_VERTEX_ERROR`] (the clamp of `a` is 1-Lipschitz), and the
/// mix's three roundings (`1 - a`, two products, one sum: `gamma(4)`) of `|var.x| + |var.y|`.
fn edge_thickness_f64(thickness_var: Vec2, edge_position: f32) -> (f64, f64) {
    let factors = thickness_var
        .clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS))
        .as_dvec2();
    let a = towards_vertex(edge_position);
    let value = factors.x + (factors.y - factors.x) * a;
    let error = (factors.y - factors.x).abs() * TOWARDS_VERTEX_ERROR + gamma(4) * (factors.x + factors.y);
    (value, error)
}

/// `rf_edge_thickness`.
pub(super) fn edge_thickness() -> Reference<(Vec2, f32), f32> {
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

/// The dash pattern in f64 (1 drawn, 0 a gap), or `None` where the mirror may give either: the dashes are
/// the `e` within `length / 2` of a multiple of `1 / repeats` (`(e + offset) repeats` in `[k, k +
/// length)` is `e repeats - k` in `[-length / 2, length / 2)`); the mirror computes
/// `(e + offset) repeats` with three roundings (the offset's quotient, the sum, the product) and
/// `repeats` rounded to f32, each relative to at most `repeats + 1`: within `4u (repeats + 1)` of
/// a boundary either answer is right, elsewhere the pattern is exact.
fn stipple_f64(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> Option<f64> {
    if stipple_repeats <= 0 {
        return Some(1.0);
    }
    let repeats = f64::from(stipple_repeats);
    let half = 0.5 * f64::from(stipple_length.clamp(0.0, 1.0));
    let period = f64::from(edge_position.clamp(0.0, 1.0)) * repeats;
    let from_centre = period - period.round();
    let drawn = (-half..half).contains(&from_centre);
    let margin = (from_centre.abs() - half)
        .abs()
        .min((from_centre.abs() - (1.0 - half)).abs());
    let ambiguous = margin <= 4.0 * U * (repeats + 1.0);
    (!ambiguous).then_some(if drawn { 1.0 } else { 0.0 })
}

/// `rf_stipple`.
pub(super) fn stipple() -> Reference<(i32, f32, f32), f32> {
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

/// The ramp of one component in f64, `0` below `start`, `3 t^2 - 2 t^3` with
/// `t = min((x - start) / width, 1)` above it, the hard step where `width <= MIN_LINE_RAMP`; and the
/// mirror's largest deviation from it when its `start` is off by at most `start_error` and its
/// `width` by at most `width_error` relative:
/// - on a ramp, the mirror's `t` is off by at most `(start_error / width + (width_error + gamma(2))
///   min(t, 1)) (1 + 4u)` (its numerator and quotient round once each), which the smoothstep's slope
///   `6 t (1 - t) <= 1.5` carries, plus the smoothstep's three roundings (`gamma(3)`); a start
///   moved past `x` changes the result by no more (the ramp starts at 0);
/// - on a hard step, exact, but `None` within a non-zero `start_error` of `start` (either side is
///   right);
///
/// `None` too where the ramp's bound reaches 1 (a ramp steeper than the precision of `start`).
fn ramp_f64(x: f64, start: f64, width: f64, start_error: f64, width_error: f64) -> Option<(f64, f64)> {
    if width <= f64::from(MIN_LINE_RAMP) {
        let step = if x < start { 0.0 } else { 1.0 };
        let ambiguous = start_error > 0.0 && (x - start).abs() <= start_error;
        return (!ambiguous).then_some((step, 0.0));
    }
    let t = ((x - start) / width).min(1.0);
    let value = if x < start {
        0.0
    } else {
        3.0 * t * t - 2.0 * t * t * t
    };
    let t_error = (start_error / width + (width_error + gamma(2)) * t.clamp(0.0, 1.0)) * (1.0 + 4.0 * U);
    let bound = 1.5 * t_error + gamma(3);
    (bound < 1.0).then_some((value, bound))
}

/// `rf_edge_ramp`.
pub(super) fn edge_ramp() -> Reference<(Vec3, Vec3, Vec3), Vec3> {
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

/// The coverage `max_i (1 - ramp_i)` in f64, with `start_i = d_i half_width` and
/// `width_i = d_i ramp_width` (each clamped to `[0, MAX_LINE_THICKNESS]` first), and the mirror's
/// largest deviation: each product rounds once (u, relative) on top of the given errors of
/// `half_width` (absolute) and `ramp_width` (relative), [`ramp_f64`] carries them, `min` is
/// 1-Lipschitz and `1 - m` rounds once (u). `None` where a component may take either side of a
/// threshold.
fn coverage_f64(
    deltas: Vec3,
    half_width: f64,
    half_width_error: f64,
    ramp_width: f64,
    ramp_width_error: f64,
    b: Vec3,
) -> Option<(f64, f64)> {
    let limit = f64::from(MAX_LINE_THICKNESS);
    let clamped = |value: f64, error: f64| {
        // Beyond the clamp (both sides of the error) the mirror clamps too: no error left.
        (
            value.clamp(0.0, limit),
            if value - error > limit { 0.0 } else { error },
        )
    };
    let (half_width, half_width_error) = clamped(half_width, half_width_error);
    let (ramp_width, ramp_width_error) = clamped(ramp_width, ramp_width_error);
    let d: DVec3 = deltas.abs().as_dvec3();
    let mut coverage: f64 = 0.0;
    let mut bound: f64 = 0.0;
    for i in 0..3 {
        let start = d[i] * half_width;
        let start_error = d[i] * half_width_error + U * start;
        let width = d[i] * ramp_width;
        let (ramp, error) = ramp_f64(f64::from(b[i]), start, width, start_error, ramp_width_error + U)?;
        coverage = coverage.max(1.0 - ramp);
        bound = bound.max(error);
    }
    Some((coverage, bound + U))
}

/// `rf_line_width`.
pub(super) fn line_width() -> Reference<(Vec3, f32, f32, Vec3), f32> {
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

/// `rf_process_wireframe`.
pub(super) fn process_wireframe() -> Reference<(WireframeSettings, Vec3, Vec3), f32> {
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
