//! Agreement checks of the wireframe module, one per function, in the module's order.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. The wireframe's outputs have
//! thresholds (a dash boundary, a hard step) and a steep smoothstep: where a few ULP of difference
//! in an input may legitimately move the output across a threshold, the tolerance accepts either
//! side (as the ray-cone `curvature_sign` check does), and a smoothstep's error is its input's error
//! times its largest slope nearby.

use super::edge::Edge;
use super::strategy::{magnitude, one_argument, scalar, vec2_of, vec3, HUGE, TINY};
use super::{exact, per_component, registered_checks, Entry};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{
    self as wf, WireframeSettings, WireframeSettingsIo, MAX_LINE_THICKNESS, MIN_LINE_RAMP,
};
use shader_proptest::tolerance::{ulps, SIN_COS_ERROR, ULP};
use shader_proptest::{Args, FunctionCheck, Value};

/// `10^exponent` for an exponent drawn from `range` (log-uniform magnitudes).
fn log_uniform(range: std::ops::Range<f32>) -> BoxedStrategy<f32> {
    range.prop_map(|e| 10f32.powf(e)).boxed()
}

/// Barycentrics `(w, u, v)` summing to 1: vertices, edge points (middles included), points a tiny
/// distance inside an edge, interior points, and points a hair outside the triangle (a hit's
/// barycentrics carry rounding), in every order of the components.
fn barycentrics() -> BoxedStrategy<Vec3> {
    let vertex = Just((1.0f32, 0.0f32));
    let edge = prop_oneof![3 => 0.0f32..1.0, 1 => Just(0.5f32)].prop_map(|t| (0.0, t));
    let near_edge = (log_uniform(-9.0..-1.0), 0.0f32..1.0).prop_map(|(gap, t)| (gap, t * (1.0 - gap)));
    let interior = (0.0f32..1.0, 0.0f32..1.0).prop_map(|(a, t)| (a, t * (1.0 - a)));
    let outside = (log_uniform(-9.0..-5.0), 0.0f32..1.0).prop_map(|(gap, t)| (-gap, t));
    let (first, second) = (0usize..3, 0usize..2);
    (
        prop_oneof![1 => vertex, 2 => edge, 2 => near_edge, 3 => interior, 1 => outside],
        first,
        second,
    )
        .prop_map(|((a, b), first, second)| arrange(a, b, 1.0 - a - b, first, second))
        .boxed()
}

/// `(a, b, c)` rotated by `first` and, with `second`, its last two entries swapped: all six orders.
fn arrange(a: f32, b: f32, c: f32, first: usize, second: usize) -> Vec3 {
    let mut values = [a, b, c];
    values.rotate_left(first);
    if second == 1 {
        values.swap(1, 2);
    }
    Vec3::from_array(values)
}

/// One delta component: typical per-pixel barycentric spreads, 0, the whole tested domain, and
/// sometimes negative (the functions use the magnitude).
fn delta() -> BoxedStrategy<f32> {
    prop_oneof![
        4 => log_uniform(-6.0..0.0),
        1 => Just(0.0f32),
        2 => magnitude(),
        1 => scalar(),
    ]
    .boxed()
}

fn deltas() -> BoxedStrategy<Vec3> {
    prop_oneof![
        4 => (delta(), delta(), delta()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        1 => delta().prop_map(Vec3::splat),
    ]
    .boxed()
}

/// Deltas and barycentrics with one component a few pixels from its edge (`b_i = k * d_i`,
/// `k` in `[0, 4]`), so that the hard steps and the anti-aliasing ramps are exercised, not only the
/// flat regions either side.
fn hit_near_line() -> BoxedStrategy<(Vec3, Vec3)> {
    let spread = log_uniform(-5.0..-1.0);
    (
        spread,
        (0.5f32..2.0, 0.5f32..2.0),
        0.0f32..4.0,
        0.0f32..1.0,
        0usize..3,
        0usize..2,
    )
        .prop_map(|(d, (dy, dz), k, t, first, second)| {
            let near = k * d;
            let rest = 1.0 - near;
            let b = arrange(near, t * rest, rest - t * rest, first, second);
            let mut delta = [d, d * dy, d * dz];
            delta.rotate_left(first);
            if second == 1 {
                delta.swap(1, 2);
            }
            (b, Vec3::from_array(delta))
        })
        .boxed()
}

/// Barycentrics and deltas: independent, or near a line.
fn hit() -> BoxedStrategy<(Vec3, Vec3)> {
    prop_oneof![1 => (barycentrics(), deltas()), 1 => hit_near_line()].boxed()
}

/// A size setting (thickness, a thickness_var component, smoothing): the UI range, 0, tiny, huge,
/// beyond the clamp, and negative.
fn size() -> BoxedStrategy<f32> {
    prop_oneof![
        6 => 0.0f32..5.0,
        2 => Just(0.0f32),
        1 => Just(1.0f32),
        1 => log_uniform(-12.0..-3.0),
        1 => log_uniform(3.0..12.0),
        1 => Just(MAX_LINE_THICKNESS),
        1 => -5.0f32..0.0,
    ]
    .boxed()
}

/// A dash length: the UI range `[0, 1]`, its ends, and beyond them (clamped).
fn stipple_length() -> BoxedStrategy<f32> {
    prop_oneof![
        4 => 0.0f32..1.0,
        1 => Just(0.0f32),
        1 => Just(1.0f32),
        1 => -2.0f32..0.0,
        1 => 1.0f32..3.0,
    ]
    .boxed()
}

/// A dash count: the UI range 1..=30, zero and negative (no dashes), and the extremes of `i32`.
fn stipple_repeats() -> BoxedStrategy<i32> {
    prop_oneof![
        6 => 1i32..=30,
        1 => -5i32..=0,
        1 => 31i32..100_000,
        1 => prop::sample::select(vec![i32::MIN, -1, 1 << 24, i32::MAX]),
    ]
    .boxed()
}

/// Every preset, or random settings over the whole tested range.
fn settings() -> BoxedStrategy<WireframeSettings> {
    let presets = prop::sample::select(WireframeSettings::PRESETS.map(|(_, settings)| settings).to_vec());
    let random = (
        vec2_of(size(), size()),
        size(),
        size(),
        any::<bool>(),
        stipple_length(),
        stipple_repeats(),
        any::<bool>(),
    )
        .prop_map(
            |(thickness_var, thickness, smoothing, stipple, length, repeats, screen_space)| {
                WireframeSettings::new(
                    thickness,
                    thickness_var,
                    smoothing,
                    stipple,
                    length,
                    repeats,
                    screen_space,
                )
            },
        );
    prop_oneof![1 => presets, 2 => random].boxed()
}

/// An integer flag of the Io mirror: 0, 1, -1 and any other `i32`.
fn flag() -> BoxedStrategy<i32> {
    prop_oneof![
        2 => Just(0i32),
        2 => Just(1i32),
        1 => Just(-1i32),
        2 => any::<i32>(),
    ]
    .boxed()
}

/// Io mirrors with arbitrary integers in the flags (negative ones included) and bit-exact floats.
fn settings_io() -> BoxedStrategy<WireframeSettingsIo> {
    (settings(), flag(), flag())
        .prop_map(|(settings, stipple, screen_space)| WireframeSettingsIo {
            stipple,
            screen_space,
            ..settings.pack()
        })
        .boxed()
}

/// An edge position: its barycentric range `[1/3, 1]`, the ends, and outside `[0, 1]` (clamped).
fn position_along_edge() -> BoxedStrategy<f32> {
    prop_oneof![
        6 => 1.0f32 / 3.0..1.0,
        1 => prop::sample::select(vec![0.0f32, 1.0 / 3.0, 0.5, 1.0]),
        1 => scalar(),
    ]
    .boxed()
}

/// Largest slope of the smoothstep `t * t * (3 - 2 * t)`, `6 t (1 - t)`, over `[t - dt, t + dt]`:
/// at the point of that interval nearest to 1/2.
fn ramp_slope(t: f32, dt: f32) -> f32 {
    let nearest = 0.5f32.clamp(t - dt, t + dt).clamp(0.0, 1.0);
    6.0 * nearest * (1.0 - nearest)
}

/// Largest `|device - mirror|` of `edge_ramp(x, start, width)` when the device's `start` may be off
/// by `start_error`. Hard step: either side within `start_error` of the step, else exact. Ramp: the
/// numerator `x - start` is off by `start_error` plus one rounding, the quotient by 3 ULP (2.5 for
/// the device's division, 0.5 for the mirror's); through the smoothstep's slope, plus 8 ULP for the
/// three products and one difference of the polynomial on each side.
fn edge_ramp_error(x: f32, start: f32, width: f32, start_error: f32) -> f32 {
    if width <= MIN_LINE_RAMP {
        let near_step = start_error > 0.0 && (x - start).abs() <= start_error;
        return if near_step { 1.0 } else { 0.0 };
    }
    if x < start - start_error {
        return 0.0;
    }
    let t = ((x - start) / width).clamp(0.0, 1.0);
    let dt = (start_error + ulps(1.0, x - start)) / width + ulps(3.0, t);
    ramp_slope(t, dt) * dt + ulps(8.0, 1.0)
}

/// Largest `|device - mirror|` of `line_width(deltas, thickness, smoothing, b)` when the device's
/// `thickness` may be off by `thickness_error`. Each start `|d_i| * th` is off by `|d_i|` times that,
/// plus half an ULP (the device may fuse the product into `x - start`, or flush a denormal product);
/// the widths `|d_i| * sm` are identical products. The coverage `1 - min` adds one rounding.
fn line_width_error(deltas: Vec3, thickness: f32, thickness_error: f32, smoothing: f32, b: Vec3) -> f32 {
    let magnitude = deltas.abs();
    let start = magnitude * thickness.clamp(0.0, MAX_LINE_THICKNESS);
    let width = magnitude * smoothing.clamp(0.0, MAX_LINE_THICKNESS);
    let start_error = magnitude * thickness_error + Vec3::splat(0.5 * ULP) * start + f32::MIN_POSITIVE;
    let errors: Vec<f32> = (0..3)
        .map(|i| edge_ramp_error(b[i], start[i], width[i], start_error[i]))
        .collect();
    errors.iter().fold(0.0f32, |a, &e| a.max(e)) + ULP
}

/// Largest `|device - mirror|` of `edge_thickness(var, e)`: the argument `e * pi` is the same
/// product on both sides; the device's `sin` is off by 2^-11 (Vulkan, inside `[-pi, pi]`), the
/// mirror's by an ULP, and `1 - sin` may round differently (an ULP; the clamp to `[0, 1]` does not
/// widen a difference): that moves the mix by `|var.y - var.x|` times as much. The mix itself (`x (1 - a) + y a`, or `x + (y - x) a` on the
/// device) rounds at most 4 times on each side: 4 ULP of `|x| + |y|`.
fn edge_thickness_error(thickness_var: Vec2) -> f32 {
    let factors = thickness_var.clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS));
    (factors.y - factors.x).abs() * (SIN_COS_ERROR + 2.0 * ULP) + ulps(4.0, factors.x + factors.y)
}

/// A coverage error bound from which on the coverage is ambiguous: the case lies within rounding
/// of a hard edge, a ramp steeper than its inputs' precision, or a dash boundary, where either side
/// is right. The line checks leave those cases to the edge-case suite, which checks them for a
/// finite coverage in `[0, 1]`; everywhere else the bound is far below it.
const AMBIGUOUS_COVERAGE: f32 = 0.5;

/// Why a case is left out of the line checks ([`AMBIGUOUS_COVERAGE`]).
const AT_AN_EDGE: &str = "within rounding of a hard edge or a dash boundary";

/// Whether the device may legitimately land on the other side of a dash boundary. The device's
/// `offset = 0.5 * length / repeats` is off by 3 ULP (2.5 for its division, 0.5 for the mirror's);
/// `e + offset` adds a rounding (1 ULP of the sum between the two sides) and the product with
/// `repeats` scales both and adds 1 ULP of the period; `fract` is exact. Within that band of the
/// dash length or of a period boundary (where `fract` wraps), either value is right.
fn stipple_may_flip(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> bool {
    if stipple_repeats <= 0 {
        return false;
    }
    let repeats = stipple_repeats as f32;
    let drawn = stipple_length.clamp(0.0, 1.0);
    let offset = 0.5 * drawn / repeats;
    let sum = edge_position.clamp(0.0, 1.0) + offset;
    let period = sum * repeats;
    let pattern = period - period.floor();
    let band = repeats * (ulps(3.0, offset) + ulps(1.0, sum)) + ulps(1.0, period);
    (pattern - drawn).abs() <= band || pattern <= band || 1.0 - pattern <= band
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

/// `rf_unpack_wireframe_settings`.
pub fn unpack_wireframe_settings() -> FunctionCheck<impl Args + Edge, impl Value> {
    // Copies and integer comparisons: exact.
    exact(
        "unpack_wireframe_settings",
        || one_argument(settings_io()),
        |(io,)| wf::unpack_wireframe_settings(io),
    )
}

/// `rf_edge_position`.
pub fn edge_position() -> FunctionCheck<impl Args + Edge, impl Value> {
    // max is exact.
    exact(
        "edge_position",
        || one_argument(prop_oneof![3 => barycentrics(), 1 => vec3()]),
        |(b,)| wf::edge_position(b),
    )
}

/// `rf_edge_thickness`.
pub fn edge_thickness() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "edge_thickness",
        || (vec2_of(size(), size()), position_along_edge()).boxed(),
        |(var, e)| wf::edge_thickness(var, e),
        |&(var, _), _, _| edge_thickness_error(var),
    )
}

/// `rf_stipple`.
pub fn stipple() -> FunctionCheck<impl Args + Edge, impl Value> {
    // 0 or 1, exact away from a dash boundary. Within its rounding band either value is right, so
    // those positions are checked separately (the edge-case suite).
    exact(
        "stipple",
        || {
            (stipple_repeats(), stipple_length(), position_along_edge())
                .prop_filter("within rounding of a dash boundary", |&(repeats, length, e)| {
                    !stipple_may_flip(repeats, length, e)
                })
                .boxed()
        },
        |(repeats, length, e)| wf::stipple(repeats, length, e),
    )
}

/// One component of `rf_edge_ramp`'s arguments `(x, start, width)`: widths down to zero and
/// beyond `MIN_LINE_RAMP`, `x` on the ramp, at its start, or anywhere around it. Components on a
/// ramp steeper than the precision of `x - start` (either coverage is right) are left to the
/// edge-case suite, as in the line checks: three independent components would otherwise triple the
/// share of cases whose tolerance says nothing.
fn edge_ramp_component() -> impl Strategy<Value = (f32, f32, f32)> {
    let width = prop_oneof![
        4 => log_uniform(-6.0..0.0),
        1 => Just(0.0f32),
        1 => prop::sample::select(vec![1.0e-31f32, MIN_LINE_RAMP, 2.0e-30, TINY, HUGE]),
        1 => magnitude(),
    ];
    (-0.5f32..1.5, magnitude(), width, 0.0f32..1.0)
        .prop_flat_map(|(x, start, width, k)| {
            prop_oneof![
                Just((x, start, width)),
                Just((start + (2.0 * k - 0.5) * width, start, width)),
                Just((start, start, width)),
            ]
        })
        .prop_filter(AT_AN_EDGE, |&(x, start, width)| {
            edge_ramp_error(x, start, width, 0.0) < AMBIGUOUS_COVERAGE
        })
}

/// `rf_edge_ramp`: three independent components.
pub fn edge_ramp() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "edge_ramp",
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
        |(x, start, width)| wf::edge_ramp(x, start, width),
        // start is an input here, so only the division and the polynomial differ.
        |&(x, start, width), i, _| edge_ramp_error(x[i], start[i], width[i], 0.0),
    )
}

/// `rf_line_width`.
pub fn line_width() -> FunctionCheck<impl Args + Edge, impl Value> {
    per_component(
        "line_width",
        || {
            (hit(), size(), size())
                .prop_map(|((b, d), thickness, smoothing)| (d, thickness, smoothing, b))
                .prop_filter(AT_AN_EDGE, |&(d, thickness, smoothing, b)| {
                    line_width_error(d, thickness, 0.0, smoothing, b) < AMBIGUOUS_COVERAGE
                })
                .boxed()
        },
        |(d, thickness, smoothing, b)| wf::line_width(d, thickness, smoothing, b),
        |&(d, thickness, smoothing, b), _, _| line_width_error(d, thickness, 0.0, smoothing, b),
    )
}

/// `rf_process_wireframe`: the coverage error derived in `process_wireframe_error`.
pub fn process_wireframe() -> FunctionCheck<(WireframeSettings, Vec3, Vec3), f32> {
    per_component(
        "process_wireframe",
        || {
            (settings(), hit())
                .prop_map(|(settings, (b, d))| (settings, b, d))
                .prop_filter(AT_AN_EDGE, |&(settings, b, d)| {
                    process_wireframe_error(settings, b, d) < AMBIGUOUS_COVERAGE
                })
                .boxed()
        },
        |(settings, b, d)| wf::process_wireframe(settings, b, d),
        |&(settings, b, d), _, _| process_wireframe_error(settings, b, d),
    )
}

/// Every function's checks, in the module's function order.
pub fn entries() -> Vec<Registered<Entry>> {
    registered_checks!(
        Module::Wireframe,
        [
            unpack_wireframe_settings,
            edge_position,
            edge_thickness,
            stipple,
            edge_ramp,
            line_width,
            process_wireframe
        ]
    )
}
