//! Edge cases: values that real scenes produce and uniform sampling almost never does, for
//! [`crate::FunctionCheck::with_perturbation`].
//!
//! [`special_values`] are both zeros, the smallest subnormal and normal numbers, 1 and the floats
//! one ULP on either side of it, and any bounds the caller names (the ends of a domain, clamp
//! constants) with their neighbours one ULP away, each of either sign; [`relate`] ties one vector
//! of a case to another (equal, opposite, a multiple, one ULP away, orthogonal).

use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::TestRng;

/// Special magnitudes every edge float may take (each also negated): zero, the smallest subnormal
/// and normal numbers, one ULP below and above 1, and 1.
pub const SPECIAL_F32: [f32; 6] = [
    0.0,
    1.0e-45,
    f32::MIN_POSITIVE,
    1.0 - f32::EPSILON / 2.0,
    1.0,
    1.0 + f32::EPSILON,
];

/// The float one ULP away from `x` towards `+inf` (`up`) or `-inf`; `x` itself when it is not finite.
pub fn next_f32(x: f32, up: bool) -> f32 {
    if !x.is_finite() {
        return x;
    }
    if x == 0.0 {
        let smallest = f32::from_bits(1);
        return if up { smallest } else { -smallest };
    }
    let bits = x.to_bits();
    let away = (x > 0.0) == up;
    f32::from_bits(if away { bits + 1 } else { bits - 1 })
}

/// Every value of [`SPECIAL_F32`] and of `bounds` (with its neighbours one ULP away), and each
/// negated.
pub fn special_values(bounds: &[f32]) -> Vec<f32> {
    let mut values: Vec<f32> = SPECIAL_F32.to_vec();
    for &bound in bounds {
        values.extend([bound, next_f32(bound, true), next_f32(bound, false)]);
    }
    let negated: Vec<f32> = values.iter().map(|x| -x).collect();
    values.extend(negated);
    values
}

/// Makes `target` one of: a copy of `source`, its negation, a multiple of it, `source` one ULP away
/// in one component, or a vector orthogonal to it (`source x` an axis).
pub fn relate(source: Vec3, target: &mut Vec3, rng: &mut TestRng) {
    *target = match rng.random_range(0..5) {
        0 => source,
        1 => -source,
        2 => source * rng.random_range(0.5f32..2.0),
        3 => {
            let mut nudged = source;
            let component = rng.random_range(0..3);
            nudged[component] = next_f32(nudged[component], rng.random());
            nudged
        }
        _ => source.cross([Vec3::X, Vec3::Y, Vec3::Z][rng.random_range(0..3)]),
    };
}
