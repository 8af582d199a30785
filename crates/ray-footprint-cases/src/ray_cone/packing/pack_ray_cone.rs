//! The proof of [`pack_ray_cone`](ray_footprint::ray_cone::pack_ray_cone): its record and its
//! reference.

use crate::degenerate::{cone, mirror, value, INF};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::one_argument;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, PackedRayCone, RayCone, F16_MAX};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_pack_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "pack_ray_cone",
        |(cone,)| rc::pack_ray_cone(cone),
        || one_argument(ray_cone()),
    )
    // The rounding mode of packHalf2x16 is the implementation's: one f16 ULP (2^-10
    // relative, 2^-24 absolute for f16 subnormals).
    .bound(|_, _, expected| (expected.abs() / 1024.0).max(1.0 / 16_777_216.0))
    .reference(reference())
    .without_symmetry(
        "an encoding into two IEEE halves: the halves' rounding and range depend on the magnitude, \
         so no scale is exact over the documented range, and a cone has no frame, position or order",
    )
    .fuzz(|d| (d.cone(),))
    .range(-rc::F16_MAX, rc::F16_MAX, "unpacked half")
    .degenerate(vec![
        value(
            "values beyond f16 (1e9, -1e9)",
            "(F16_MAX, -F16_MAX), never infinite",
            (cone(1.0e9, -1.0e9),),
            vec![F16_MAX, -F16_MAX],
        ),
        value(
            "halfway between two f16 (1 + 2^-11)",
            "1 (ties to even)",
            (cone(1.0 + 1.0 / 2048.0, 0.0),),
            vec![1.0, 0.0],
        ),
        value(
            "below half the smallest f16 sub-normal (2^-26)",
            "0 (rounds to nearest)",
            (cone(1.0 / 67_108_864.0, -1.0 / 67_108_864.0),),
            vec![0.0, 0.0],
        ),
        mirror(
            "infinity in (width)",
            "CPU: (F16_MAX, spread)",
            (cone(INF, 0.5),),
            vec![F16_MAX, 0.5],
        ),
    ])
}

/// Any finite f32: every bit pattern but infinities and NaNs, and ordinary values.
fn finite_f32() -> BoxedStrategy<f32> {
    prop_oneof![
        any::<u32>()
            .prop_map(f32::from_bits)
            .prop_filter("finite", |x| x.is_finite()),
        -1.0e5f32..1.0e5,
    ]
    .boxed()
}

/// The reference of `rf_pack_ray_cone`.
fn reference() -> Reference<(RayCone,), PackedRayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "the `half` crate's f32 -> f16 conversion (round to nearest, ties to even) of each value clamped to [-F16_MAX, F16_MAX], bit for bit",
        || (finite_f32(), finite_f32()).boxed(),
        |&(width, spread_angle), pack| {
            let got = pack((RayCone { width, spread_angle },));
            let half = |x: f32| u32::from(half::f16::from_f32(x.clamp(-F16_MAX, F16_MAX)).to_bits());
            let expected = half(width) | (half(spread_angle) << 16);
            Some(Deviation::new(f64::from(u8::from(got.0 != expected)), 0.0))
        },
    )
}
