//! The proof of [`roughness_spread_angle`](ray_footprint::ray_cone::roughness_spread_angle): its
//! record, its enclosure and its references: the closed form, the small-roughness limit and its
//! growth with roughness.

use crate::degenerate::{same, value};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::strategy::{one_argument, scalar};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_ROUGHNESS_DENOMINATOR};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::Interval;
use shader_proptest::one_of;

/// The record of `rf_roughness_spread_angle`: the enclosure of the spread.
pub fn record() -> Record<(f32,), f32> {
    Record::new(
        Module::RayCone,
        "roughness_spread_angle",
        |(r,)| rc::roughness_spread_angle(r),
        || {
            let roughness = one_of![
                4 => uniform(0.0, 1.0),
                1 => Just(0.0f32),
                1 => Just(1.0f32),
                1 => uniform(0.99, 1.0),
                1 => scalar(),
            ];
            one_argument(roughness)
        },
    )
    .enclosure(|&(r,)| vec![enclosure(r)])
    .reference(roughness_closed_form())
    .reference(roughness_small())
    .reference(roughness_monotone())
    .without_symmetry(
        "a function of the roughness alone, clamped to [0, 1]: no length, frame or order, and no \
         exact change of the roughness carries through its fourth power and square root",
    )
    .fuzz(|d| (d.scalar(),))
    .range(0.0, 142.0, "roughness spread")
    .degenerate(vec![
        value("roughness 0", "0", (0.0,), vec![0.0]),
        value(
            "roughness 1",
            "2 sqrt(0.5 / MIN_ROUGHNESS_DENOMINATOR), about 141.4",
            (1.0,),
            vec![2.0 * (0.5 / MIN_ROUGHNESS_DENOMINATOR).sqrt()],
        ),
        same("negative roughness", "as roughness 0", (-0.5,), (0.0,)),
        same("roughness 2", "as roughness 1", (2.0,), (1.0,)),
    ])
}

/// `rf_roughness_spread_angle` in interval arithmetic, in the same order of operations.
fn enclosure(roughness: f32) -> Interval {
    let r = Interval::exact(roughness.clamp(0.0, 1.0));
    let alpha = r * r;
    let alpha2 = alpha * alpha;
    let variance =
        Interval::c(0.5) * alpha2 / (Interval::c(1.0) - alpha2).max_c(f64::from(MIN_ROUGHNESS_DENOMINATOR));
    Interval::c(2.0) * variance.sqrt()
}

/// A reference of `rf_roughness_spread_angle`: the closed form.
fn roughness_closed_form() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::ClosedForm,
        "JCGT 2021's mapping in f64: 2 sqrt(0.5 r^4 / max(1 - r^4, MIN_ROUGHNESS_DENOMINATOR)) for roughness r in [0, 1]",
        || prop_oneof![0.0f32..1.0, Just(1.0f32), 0.9f32..1.0].boxed(),
        |&r, roughness_spread_angle| {
            let got = roughness_spread_angle((r,));
            let r = f64::from(r);
            let alpha2 = r.powi(4);
            let denominator = (1.0 - alpha2).max(f64::from(MIN_ROUGHNESS_DENOMINATOR));
            let expected = 2.0 * (0.5 * alpha2 / denominator).sqrt();
            // r^2 and its square: 3 u relative on alpha^2, so 1 - alpha^2 is off by
            // 3 u alpha^2 + u (its own rounding) absolute; the quotient's and the product's
            // roundings add 2 u; the square root halves the relative error and adds u.
            let variance = gamma(5) + (3.0 * U * alpha2 + U) / denominator;
            let bound = (0.5 * variance + U) * expected;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}

/// A reference of `rf_roughness_spread_angle`: the small-roughness limit.
fn roughness_small() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::Identity,
        "the small-roughness limit its source states, sqrt(2) r^2: within r^4 / (1 - r^4) relative for r <= 0.3",
        || (0.0f32..0.3).boxed(),
        |&r, roughness_spread_angle| {
            let got = roughness_spread_angle((r,));
            let r = f64::from(r);
            let limit = std::f64::consts::SQRT_2 * r * r;
            // 1 / sqrt(1 - x) - 1 <= x / (1 - x) for x = r^4 < 1; the f32 rounding (above) is
            // below 8 u here.
            let bound = (r.powi(4) / (1.0 - r.powi(4)) + 8.0 * U) * limit;
            Some(Deviation::within(f64::from(got), limit, bound))
        },
    )
}

/// A reference of `rf_roughness_spread_angle`: growth with roughness.
fn roughness_monotone() -> Reference<(f32,), f32> {
    Reference::new(
        Kind::Identity,
        "the spread never shrinks as roughness grows: r < r' in [0, 1], at least 1e-3 apart, give spread(r) <= spread(r')",
        || (0.0f32..0.999, 0.0f32..1.0).boxed(),
        |&(r, share), roughness_spread_angle| {
            let larger = (r + 1.0e-3 + share * (1.0 - 1.0e-3 - r)).min(1.0);
            let shrink = roughness_spread_angle((r,)) - roughness_spread_angle((larger,));
            Some(Deviation::new(f64::from(shrink.max(0.0)), 0.0))
        },
    )
}
