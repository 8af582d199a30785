//! Records of `ray_diff`: G-buffer differentials (RTG Sec. 20.3.3).

use super::enclosure;
use super::rows::sample_at;
use super::strategy::gbuffer_sample;
use super::{reference, MODULE};
use crate::degenerate::{parts, value};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{distance, magnitude, normal_and_direction, unit_vec3};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, GBufferSample, RayDiff, DIFF_MIN_COS};
use shader_proptest::{Args, Value};

/// `rf_gbuffer_ray_diff`.
pub fn gbuffer_ray_diff() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "gbuffer_ray_diff",
        |(c, r, l, b, a, eps)| rd::gbuffer_ray_diff(c, r, l, b, a, eps),
        // The neighbour choice compares correctly rounded differences: the device makes the same
        // choice as the mirror, so only the chosen branch is enclosed.
        || {
            (
                gbuffer_sample(),
                (gbuffer_sample(), gbuffer_sample()),
                (gbuffer_sample(), gbuffer_sample()),
                magnitude(),
            )
                .prop_map(|(c, (r, l), (b, a), eps)| (c, r, l, b, a, eps))
                .boxed()
        },
    )
    .enclosure(enclosure::gbuffer_ray_diff)
    .reference(reference::gbuffer_ray_diff())
    .fuzz(|d| {
        (
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.distance(),
        )
    })
    .degenerate(vec![
        value(
            "all five samples equal",
            "zero differential",
            (
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::ZERO),
        ),
        value(
            "depth edge on the right (t: left 1.5, centre 1, right 10), epsilon 0.1",
            "the left neighbour: dO/dx = t(0) e(0) - t(-1) e(-1) = (0, 0, 0.5)",
            (
                sample_at(1.0),
                sample_at(10.0),
                sample_at(1.5),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::new(0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "step to the right exactly depth_epsilon (right 1.5, left 1.25, epsilon 0.5)",
            "the right neighbour, dO/dx = (0, 0, -0.5): switching needs a larger step",
            (
                sample_at(1.0),
                sample_at(1.5),
                sample_at(1.25),
                sample_at(1.0),
                sample_at(1.0),
                0.5,
            ),
            parts(RayDiff::new(-0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "right neighbour's normal perpendicular to its eye ray",
            "dD/dx = e(+1) - reflect(e(0), n(0)) = (0, 0, -2)",
            (
                sample_at(1.0),
                GBufferSample {
                    normal: x,
                    ..sample_at(1.0)
                },
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, -2.0 * z, Vec3::ZERO)),
        ),
    ])
}

/// `rf_tangent_plane_offsets`.
pub fn tangent_plane_offsets() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    Record::new(
        MODULE,
        "tangent_plane_offsets",
        |(rd, rdx, rdy, t, n)| rd::tangent_plane_offsets(rd, rdx, rdy, t, n),
        || {
            (normal_and_direction(), (unit_vec3(), unit_vec3()), distance())
                .prop_map(|((n, rd), (rdx, rdy), t)| (rd, rdx, rdy, t, n))
                .boxed()
        },
    )
    .enclosure(|&(r, rdx, rdy, t, n)| {
        let dx = enclosure::tangent_plane_offset(r, rdx, t, n);
        let dy = enclosure::tangent_plane_offset(r, rdy, t, n);
        enclosure::derivatives3(dx, dy)
    })
    .reference(reference::tangent_plane_offsets())
    .fuzz(|d| (d.unit(), d.unit(), d.unit(), d.distance(), d.unit()))
    .degenerate(vec![
        value("t = 0", "0", (-z, x, -z, 0.0, z), vec![0.0; 6]),
        value(
            "neighbour ray in the tangent plane",
            "dot(rdx, n) clamped to +DIFF_MIN_COS",
            (-z, x, -z, 1.0, z),
            vec![in_plane_cos, 0.0, 1.0, 0.0, 0.0, 0.0],
        ),
        value(
            "neighbour rays equal to the centre ray",
            "0",
            (-z, -z, -z, 5.0, z),
            vec![0.0; 6],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![gbuffer_ray_diff, tangent_plane_offsets]
}
