//! The proof of [`unpack_ray_cone`](ray_footprint::ray_cone::unpack_ray_cone): its record, its case
//! strategy and its reference.

use crate::degenerate::{mirror, value, INF, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::one_argument;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, PackedRayCone, RayCone, F16_MAX};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_unpack_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    // f16 to f32 is exact.
    Record::new(
        Module::RayCone,
        "unpack_ray_cone",
        |(packed,)| rc::unpack_ray_cone(packed),
        || one_argument(packed_ray_cone()),
    )
    .reference(reference())
    .without_symmetry("a decoding of two IEEE halves: bits in, no length, frame, position or order")
    .fuzz(|d| (d.packed_cone(),))
    .degenerate(vec![
        value("zero bits", "(0, 0)", (PackedRayCone(0),), vec![0.0, 0.0]),
        value(
            "largest finite f16 (0x7bff, 0xfbff)",
            "(F16_MAX, -F16_MAX)",
            (PackedRayCone(0xfbff_7bff),),
            vec![F16_MAX, -F16_MAX],
        ),
        value(
            "smallest f16 sub-normal (0x0001), negative zero (0x8000)",
            "(2^-24, -0), exact",
            (PackedRayCone(0x8000_0001),),
            vec![1.0 / 16_777_216.0, -0.0],
        ),
        mirror(
            "f16 infinity and NaN bits (0x7c00, 0x7e00)",
            "CPU: (inf, NaN)",
            (PackedRayCone(0x7e00_7c00),),
            vec![INF, NAN],
        ),
    ])
}

/// A packed cone whose halves are finite f16 (exponent field below 31).
fn packed_ray_cone() -> BoxedStrategy<PackedRayCone> {
    let finite_half = any::<u16>().prop_filter("finite f16", |h| (h >> 10) & 0x1f != 0x1f);
    (finite_half.clone(), finite_half)
        .prop_map(|(lo, hi)| PackedRayCone(u32::from(lo) | u32::from(hi) << 16))
        .boxed()
}

/// The reference of `rf_unpack_ray_cone`.
fn reference() -> Reference<(PackedRayCone,), RayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "the `half` crate's f16 -> f32 conversion of both halves, bit for bit (NaN as NaN), over every bit pattern",
        || any::<u32>().boxed(),
        |&bits, unpack| {
            let got = unpack((PackedRayCone(bits),));
            let same = |value: f32, half_bits: u32| {
                let expected = half::f16::from_bits(half_bits as u16).to_f32();
                value.to_bits() == expected.to_bits() || (value.is_nan() && expected.is_nan())
            };
            let both = same(got.width, bits & 0xffff) && same(got.spread_angle, bits >> 16);
            Some(Deviation::new(f64::from(u8::from(!both)), 0.0))
        },
    )
}
