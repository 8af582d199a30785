//! Case strategies of the wireframe records.

use super::bound::{edge_ramp_error, AMBIGUOUS_COVERAGE, AT_AN_EDGE};
use crate::strategy::{magnitude, scalar, vec2_of, HUGE, TINY};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsIo, MAX_LINE_THICKNESS, MIN_LINE_RAMP};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;

/// `10^exponent` for an exponent drawn from `[low, high)` (log-uniform magnitudes).
pub(super) fn log_uniform(low: f32, high: f32) -> BoxedStrategy<f32> {
    uniform(low, high).prop_map(|e| 10f32.powf(e)).boxed()
}

/// Barycentrics `(w, u, v)` summing to 1: vertices, edge points (middles included), points a tiny
/// distance inside an edge, interior points, and points a hair outside the triangle (a hit's
/// barycentrics carry rounding), in every order of the components.
pub(super) fn barycentrics() -> BoxedStrategy<Vec3> {
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
pub(super) fn arrange(a: f32, b: f32, c: f32, first: usize, second: usize) -> Vec3 {
    let mut values = [a, b, c];
    values.rotate_left(first);
    if second == 1 {
        values.swap(1, 2);
    }
    Vec3::from_array(values)
}

/// One delta component: typical per-pixel barycentric spreads, 0, the whole tested domain, and
/// sometimes negative (the functions use the magnitude).
pub(super) fn delta() -> BoxedStrategy<f32> {
    one_of![
        4 => log_uniform(-6.0, 0.0),
        1 => Just(0.0f32),
        2 => magnitude(),
        1 => scalar(),
    ]
    .boxed()
}

pub(super) fn deltas() -> BoxedStrategy<Vec3> {
    one_of![
        4 => (delta(), delta(), delta()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        1 => delta().prop_map(Vec3::splat),
    ]
    .boxed()
}

/// Deltas and barycentrics with one component a few pixels from its edge (`b_i = k * d_i`,
/// `k` in `[0, 4]`), so that the hard steps and the anti-aliasing ramps are exercised, not only the
/// flat regions either side.
pub(super) fn hit_near_line() -> BoxedStrategy<(Vec3, Vec3)> {
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
pub(super) fn hit() -> BoxedStrategy<(Vec3, Vec3)> {
    one_of![1 => (barycentrics(), deltas()), 1 => hit_near_line()].boxed()
}

/// A size setting (thickness, a thickness_var component, smoothing): the UI range, 0, tiny, huge,
/// beyond the clamp, and negative.
pub(super) fn size() -> BoxedStrategy<f32> {
    one_of![
        6 => uniform(0.0, 5.0),
        2 => Just(0.0f32),
        1 => Just(1.0f32),
        1 => log_uniform(-12.0, -3.0),
        1 => log_uniform(3.0, 12.0),
        1 => Just(MAX_LINE_THICKNESS),
        1 => uniform(-5.0, 0.0),
    ]
    .boxed()
}

/// A dash length: the UI range `[0, 1]`, its ends, and beyond them (clamped).
pub(super) fn stipple_length() -> BoxedStrategy<f32> {
    one_of![
        4 => uniform(0.0, 1.0),
        1 => Just(0.0f32),
        1 => Just(1.0f32),
        1 => uniform(-2.0, 0.0),
        1 => uniform(1.0, 3.0),
    ]
    .boxed()
}

/// A dash count: the UI range 1..=30, zero and negative (no dashes), and the extremes of `i32`.
pub(super) fn stipple_repeats() -> BoxedStrategy<i32> {
    one_of![
        6 => 1i32..=30,
        1 => -5i32..=0,
        1 => 31i32..100_000,
        1 => prop::sample::select(vec![i32::MIN, -1, 1 << 24, i32::MAX]),
    ]
    .boxed()
}

/// Every preset, or random settings over the whole tested range.
pub(super) fn settings() -> BoxedStrategy<WireframeSettings> {
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
    one_of![1 => presets, 2 => random].boxed()
}

/// An integer flag of the Io mirror: 0, 1, -1 and any other `i32`.
pub(super) fn flag() -> BoxedStrategy<i32> {
    one_of![
        2 => Just(0i32),
        2 => Just(1i32),
        1 => Just(-1i32),
        2 => any::<i32>(),
    ]
    .boxed()
}

/// Io mirrors with arbitrary integers in the flags (negative ones included) and bit-exact floats.
pub(super) fn settings_io() -> BoxedStrategy<WireframeSettingsIo> {
    (settings(), flag(), flag())
        .prop_map(|(settings, stipple, screen_space)| WireframeSettingsIo {
            stipple,
            screen_space,
            ..settings.pack()
        })
        .boxed()
}

/// An edge position: its barycentric range `[1/3, 1]`, the ends, and outside `[0, 1]` (clamped).
pub(super) fn position_along_edge() -> BoxedStrategy<f32> {
    one_of![
        6 => uniform(1.0 / 3.0, 1.0),
        1 => prop::sample::select(vec![0.0f32, 1.0 / 3.0, 0.5, 1.0]),
        1 => scalar(),
    ]
    .boxed()
}

/// One component of `rf_edge_ramp`'s arguments `(x, start, width)`: widths down to zero and
/// beyond `MIN_LINE_RAMP`, `x` on the ramp, at its start, or anywhere around it. Components on a
/// ramp steeper than the precision of `x - start` (either coverage is right) are left to the
/// edge-case suite, as in the line checks: three independent components would otherwise triple the
/// share of cases whose tolerance says nothing.
pub(super) fn edge_ramp_component() -> impl Strategy<Value = (f32, f32, f32)> {
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
