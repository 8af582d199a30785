//! Records of `ray_diff`: Transfer to a hit (Igehy).

use super::enclosure;
use super::rows::{direction_dx, zero_diff_dx};
use super::strategy::ray_diff;
use super::{reference, MODULE};
use crate::degenerate::{parts, value};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{distance, normal_and_direction};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, RayDiff, DIFF_MIN_COS};
use shader_proptest::{Args, Value};

/// `rf_transfer`.
pub fn transfer() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    Record::new(
        MODULE,
        "transfer",
        |(diff, direction, t, normal)| rd::transfer(diff, direction, t, normal),
        || {
            (ray_diff(), normal_and_direction(), distance())
                .prop_map(|(diff, (n, d), t)| (diff, d, t, n))
                .boxed()
        },
    )
    .enclosure(enclosure::transfer)
    .reference(reference::transfer())
    .fuzz(|d| (d.ray_diff(), d.unit(), d.distance(), d.unit()))
    .degenerate(vec![
        value(
            "ray in the plane (dot(D, N) = 0)",
            "dot(D, N) clamped to +DIFF_MIN_COS: dP = q - dot(q, N) / DIFF_MIN_COS * D",
            (zero_diff_dx(z), x, 1.0, z),
            parts(RayDiff::new(
                Vec3::new(in_plane_cos, 0.0, 1.0),
                Vec3::ZERO,
                Vec3::ZERO,
                Vec3::ZERO,
            )),
        ),
        value(
            "t = 0",
            "dO moved along D onto the plane",
            (zero_diff_dx(Vec3::new(1.0, 0.0, 1.0)), Vec3::NEG_Z, 0.0, z),
            parts(RayDiff::new(x, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "huge t (1e12)",
            "t dD (finite)",
            (direction_dx(Vec3::new(1.0e-3, 0.0, 0.0)), Vec3::NEG_Z, 1.0e12, z),
            parts(RayDiff::new(
                Vec3::new(1.0e-3 * 1.0e12, 0.0, 0.0),
                Vec3::ZERO,
                Vec3::new(1.0e-3, 0.0, 0.0),
                Vec3::ZERO,
            )),
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![transfer]
}
