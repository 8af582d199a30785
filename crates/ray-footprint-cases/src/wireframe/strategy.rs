//! Case strategies that the wireframe's two sections share: log-uniform magnitudes, the size
//! settings, the dash settings and whole settings.

use crate::strategy::vec2_of;
use proptest::prelude::*;
use ray_footprint::wireframe::{WireframeSettings, MAX_LINE_THICKNESS};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;

/// `10^exponent` for an exponent drawn from `[low, high)` (log-uniform magnitudes).
pub(crate) fn log_uniform(low: f32, high: f32) -> BoxedStrategy<f32> {
    uniform(low, high).prop_map(|e| 10f32.powf(e)).boxed()
}

/// A size setting (thickness, a thickness_var component, smoothing): the UI range, 0, tiny, huge,
/// beyond the clamp, and negative.
pub(crate) fn size() -> BoxedStrategy<f32> {
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
pub(crate) fn stipple_length() -> BoxedStrategy<f32> {
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
pub(crate) fn stipple_repeats() -> BoxedStrategy<i32> {
    one_of![
        6 => 1i32..=30,
        1 => -5i32..=0,
        1 => 31i32..100_000,
        1 => prop::sample::select(vec![i32::MIN, -1, 1 << 24, i32::MAX]),
    ]
    .boxed()
}

/// Every preset, or random settings over the whole tested range.
pub(crate) fn settings() -> BoxedStrategy<WireframeSettings> {
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
