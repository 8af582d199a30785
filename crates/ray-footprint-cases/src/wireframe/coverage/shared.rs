//! What the coverage functions share: their cases (barycentrics, deltas, hits near a line,
//! positions along an edge); the largest `|device - mirror|` of each step and where the coverage is
//! ambiguous (either side of a threshold is right); and the steps evaluated in f64 another way
//! than the module does, with the mirror's largest deviation, for the references.

use crate::reference::{gamma, U};
use crate::strategy::{magnitude, scalar};
use crate::wireframe::strategy::log_uniform;
use glam::{DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::wireframe::{MAX_LINE_THICKNESS, MIN_LINE_RAMP};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use shader_proptest::tolerance::{ulps, SIN_COS_ERROR, ULP};
use std::f64::consts::PI;

/// Barycentrics `(w, u, v)` summing to 1: vertices, edge points (middles included), points a tiny
/// distance inside an edge, interior points, and points a hair outside the triangle (a hit's
/// barycentrics carry rounding), in every order of the components.
pub(crate) fn barycentrics() -> BoxedStrategy<Vec3> {
    let vertex = Just((1.0f32, 0.0f32));
    let edge = one_of![3 => uniform(0.0, 1.0), 1 => Just(0.5f32)].prop_map(|t| (0.0, t));
    let near_edge = (log_uniform(-9.0, -1.0), uniform(0.0, 1.0)).prop_map(|(gap, t)| (gap, t * (1.0 - gap)));
    let interior = (uniform(0.0, 1.0), uniform(0.0, 1.0)).prop_map(|(a, t)| (a, t * (1.0 - a)));
    let outside = (log_uniform(-9.0, -5.0), uniform(0.0, 1.0)).prop_map(|(gap, t)| (-gap, t));
    let (first, second) = (0usize..3, 0usize..2);
    (
        one_of![1 => vertex, 2 => edge, 2 => near_edge, 3 => interior, 1 => outside],
        first,
        second,
    )
        .prop_map(|((a, b), first, second)| arrange(a, b, 1.0 - a - b, first, second))
        .boxed()
}

/// `(a, b, c)` rotated by `first` and, with `second`, its last two entries swapped: all six orders.
pub(crate) fn arrange(a: f32, b: f32, c: f32, first: usize, second: usize) -> Vec3 {
    let mut values = [a, b, c];
    values.rotate_left(first);
    if second == 1 {
        values.swap(1, 2);
    }
    Vec3::from_array(values)
}

/// One delta component: typical per-pixel barycentric spreads, 0, the whole tested domain, and
/// sometimes negative (the functions use the magnitude).
pub(crate) fn delta() -> BoxedStrategy<f32> {
    one_of![
        4 => log_uniform(-6.0, 0.0),
        1 => Just(0.0f32),
        2 => magnitude(),
        1 => scalar(),
    ]
    .boxed()
}

pub(crate) fn deltas() -> BoxedStrategy<Vec3> {
    one_of![
        4 => (delta(), delta(), delta()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        1 => delta().prop_map(Vec3::splat),
    ]
    .boxed()
}

/// Deltas and barycentrics with one component a few pixels from its edge (`b_i = k * d_i`,
/// `k` in `[0, 4]`), so that the hard steps and the anti-aliasing ramps are exercised, not only the
/// flat regions either side.
pub(crate) fn hit_near_line() -> BoxedStrategy<(Vec3, Vec3)> {
    let spread = log_uniform(-5.0, -1.0);
    (
        spread,
        (uniform(0.5, 2.0), uniform(0.5, 2.0)),
        uniform(0.0, 4.0),
        uniform(0.0, 1.0),
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
pub(crate) fn hit() -> BoxedStrategy<(Vec3, Vec3)> {
    one_of![1 => (barycentrics(), deltas()), 1 => hit_near_line()].boxed()
}

/// An edge position: its barycentric range `[1/3, 1]`, the ends, and outside `[0, 1]` (clamped).
pub(crate) fn position_along_edge() -> BoxedStrategy<f32> {
    one_of![
        6 => uniform(1.0 / 3.0, 1.0),
        1 => prop::sample::select(vec![0.0f32, 1.0 / 3.0, 0.5, 1.0]),
        1 => scalar(),
    ]
    .boxed()
}

/// Largest slope of the smoothstep `t * t * (3 - 2 * t)`, `6 t (1 - t)`, over `[t - dt, t + dt]`:
/// at the point of that interval nearest to 1/2.
pub(crate) fn ramp_slope(t: f32, dt: f32) -> f32 {
    let nearest = 0.5f32.clamp(t - dt, t + dt).clamp(0.0, 1.0);
    6.0 * nearest * (1.0 - nearest)
}

/// Largest `|device - mirror|` of `edge_ramp(x, start, width)` when the device's `start` may be off
/// by `start_error`. Hard step: either side within `start_error` of the step, else exact. Ramp: the
/// numerator `x - start` is off by `start_error` plus one rounding, the quotient by 3 ULP (2.5 for
/// the device's division, 0.5 for the mirror's); through the smoothstep's slope, plus 8 ULP for the
/// three products and one difference of the polynomial on each side.
pub(crate) fn edge_ramp_error(x: f32, start: f32, width: f32, start_error: f32) -> f32 {
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
pub(crate) fn line_width_error(
    deltas: Vec3,
    thickness: f32,
    thickness_error: f32,
    smoothing: f32,
    b: Vec3,
) -> f32 {
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
pub(crate) fn edge_thickness_error(thickness_var: Vec2) -> f32 {
    let factors = thickness_var.clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS));
    (factors.y - factors.x).abs() * (SIN_COS_ERROR + 2.0 * ULP) + ulps(4.0, factors.x + factors.y)
}

/// A coverage error bound from which on the coverage is ambiguous: the case lies within rounding
/// of a hard edge, a ramp steeper than its inputs' precision, or a dash boundary, where either side
/// is right. The line checks leave those cases to the edge-case suite, which checks them for a
/// finite coverage in `[0, 1]`; everywhere else the bound is far below it.
pub(crate) const AMBIGUOUS_COVERAGE: f32 = 0.5;

/// Why a case is left out of the line checks ([`AMBIGUOUS_COVERAGE`]).
pub(crate) const AT_AN_EDGE: &str = "within rounding of a hard edge or a dash boundary";

/// Whether the device may legitimately land on the other side of a dash boundary. The device's
/// `offset = 0.5 * length / repeats` is off by 3 ULP (2.5 for its division, 0.5 for the mirror's);
/// `e + offset` adds a rounding (1 ULP of the sum between the two sides) and the product with
/// `repeats` scales both and adds 1 ULP of the period; `fract` is exact. Within that band of the
/// dash length or of a period boundary (where `fract` wraps), either value is right.
pub(crate) fn stipple_may_flip(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> bool {
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

/// `towards_vertex = 1 - sin(pi e)` in f64 as `2 sin^2(pi (e - 1/2) / 2)` (`1 - cos x = 2 sin^2(x / 2)`),
/// `e` clamped to `[0, 1]`.
pub(crate) fn towards_vertex(edge_position: f32) -> f64 {
    let e = f64::from(edge_position.clamp(0.0, 1.0));
    let half = (PI * (e - 0.5) / 2.0).sin();
    (2.0 * half * half).clamp(0.0, 1.0)
}

/// The largest error of the mirror's `1 - sin(e * pi)`: the f32 `pi` (relative 2.8e-8) and the
/// product (u) move the argument by at most `pi (2.8e-8 + u) < 2.8e-7`, which `sin` (slope <= 1)
/// carries through; `sin` itself is within one ULP of its result (`<= 2u` below 1) and `1 - s`
/// rounds once (u): at most `5e-7`.
pub(crate) const TOWARDS_VERTEX_ERROR: f64 = 5.0e-7;

/// The thickness factor `var.x + (var.y - var.x) a` in f64 and the mirror's largest deviation from
/// it: `|var.y - var.x|` times [`TOWARDS_VERTEX_ERROR`] (the clamp of `a` is 1-Lipschitz), and the
/// mix's three roundings (`1 - a`, two products, one sum: `gamma(4)`) of `|var.x| + |var.y|`.
pub(crate) fn edge_thickness_f64(thickness_var: Vec2, edge_position: f32) -> (f64, f64) {
    let factors = thickness_var
        .clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS))
        .as_dvec2();
    let a = towards_vertex(edge_position);
    let value = factors.x + (factors.y - factors.x) * a;
    let error = (factors.y - factors.x).abs() * TOWARDS_VERTEX_ERROR + gamma(4) * (factors.x + factors.y);
    (value, error)
}

/// The dash pattern in f64 (1 drawn, 0 a gap), or `None` where the mirror may give either: the dashes are
/// the `e` within `length / 2` of a multiple of `1 / repeats` (`(e + offset) repeats` in `[k, k +
/// length)` is `e repeats - k` in `[-length / 2, length / 2)`); the mirror computes
/// `(e + offset) repeats` with three roundings (the offset's quotient, the sum, the product) and
/// `repeats` rounded to f32, each relative to at most `repeats + 1`: within `4u (repeats + 1)` of
/// a boundary either answer is right, elsewhere the pattern is exact.
pub(crate) fn stipple_f64(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> Option<f64> {
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
pub(crate) fn ramp_f64(
    x: f64,
    start: f64,
    width: f64,
    start_error: f64,
    width_error: f64,
) -> Option<(f64, f64)> {
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

/// The coverage `max_i (1 - ramp_i)` in f64, with `start_i = d_i half_width` and
/// `width_i = d_i ramp_width` (each clamped to `[0, MAX_LINE_THICKNESS]` first), and the mirror's
/// largest deviation: each product rounds once (u, relative) on top of the given errors of
/// `half_width` (absolute) and `ramp_width` (relative), [`ramp_f64`] carries them, `min` is
/// 1-Lipschitz and `1 - m` rounds once (u). `None` where a component may take either side of a
/// threshold.
pub(crate) fn coverage_f64(
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
