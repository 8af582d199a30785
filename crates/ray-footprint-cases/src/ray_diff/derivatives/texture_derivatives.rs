//! The proof of [`texture_derivatives`](ray_footprint::ray_diff::texture_derivatives): its record,
//! its enclosure and its reference.

use crate::degenerate::value;
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::{uv_bounds, Hit};
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::strategy::{uv_triangle, with_corners};
use glam::Vec2;
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, Interval, Interval2};

/// The record of `rf_texture_derivatives`: the enclosure of the UV gradients.
pub fn record() -> Record<(Derivatives2, Vec2, Vec2, Vec2), Derivatives2> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "texture_derivatives",
        |(b, t0, t1, t2)| rd::texture_derivatives(b, t0, t1, t2),
        || with_corners(derivatives2(), uv_triangle()),
    )
    .enclosure(|&(b, t0, t1, t2)| {
        let (dx, dy) = enclosure(b, t0, t1, t2);
        intervals::derivatives2(dx, dy)
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the derivatives exchanged",
        |&(b, t0, t1, t2): &(Derivatives2, Vec2, Vec2, Vec2)| (swapped2(b), t0, t1, t2),
        swapped2,
    ))
    .symmetry(Symmetry::translation(
        "the texture coordinates moved: the same",
        |&(b, t0, t1, t2): &(Derivatives2, Vec2, Vec2, Vec2), o| {
            (b, t0 + o.truncate(), t1 + o.truncate(), t2 + o.truncate())
        },
        |g: Derivatives2, _| g,
    ))
    .symmetry(Symmetry::scale(
        "the texture coordinates scaled by s: the derivatives by s",
        |&(b, t0, t1, t2): &(Derivatives2, Vec2, Vec2, Vec2), s| (b, t0 * s, t1 * s, t2 * s),
        |g: Derivatives2, s| Derivatives2::new(g.dx / s, g.dy / s),
    ))
    .fuzz(|d| (d.derivatives2(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        value(
            "collinear UVs",
            "finite, parallel gradients",
            (
                Derivatives2::new(Vec2::X, Vec2::Y),
                Vec2::ZERO,
                Vec2::ONE,
                Vec2::splat(2.0),
            ),
            vec![1.0, 1.0, 2.0, 2.0],
        ),
        value(
            "all UVs equal",
            "0",
            (
                Derivatives2::new(Vec2::X, Vec2::Y),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
            ),
            vec![0.0; 4],
        ),
        value(
            "clamped barycentric differentials (DIFF_MAX_VALUE), unit UVs",
            "finite: (DIFF_MAX_VALUE, 0), (0, DIFF_MAX_VALUE)",
            (
                Derivatives2::new(Vec2::new(max, 0.0), Vec2::new(0.0, max)),
                Vec2::ZERO,
                Vec2::X,
                Vec2::Y,
            ),
            vec![max, 0.0, 0.0, max],
        ),
    ])
}

/// `rf_texture_derivatives` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(b: Derivatives2, t0: Vec2, t1: Vec2, t2: Vec2) -> (Interval2, Interval2) {
    let g1 = interval2(t1) - interval2(t0);
    let g2 = interval2(t2) - interval2(t0);
    (
        g1 * Interval::exact(b.dx.x) + g2 * Interval::exact(b.dx.y),
        g1 * Interval::exact(b.dy.x) + g2 * Interval::exact(b.dy.y),
    )
}

/// The reference of `rf_texture_derivatives`.
fn reference() -> Reference<(Derivatives2, Vec2, Vec2, Vec2), Derivatives2> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the texture coordinates, under an affine map of the plane, of the re-intersected hits, against the gradients from the exact (du, dv) and the corners' UVs (RTG Eq. 21)",
        Hit::strategy,
        |hit, texture_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let (uvs, uv_rounding) = hit.corner_uvs();
            let got = texture_derivatives((input, uvs[0], uvs[1], uvs[2]));
            let [dx, dy] = hit.along(|(_, point)| hit.uv(point));
            let (rx, ry) = enclosure(input, uvs[0], uvs[1], uvs[2]);
            let rounding = widths(&[rx.components(), ry.components()].concat());
            let bounds = uv_bounds(hit, uvs, &rounding, (input_error, uv_rounding, dx.error.max(dy.error)), Vec2::ONE);
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            Some(components(got, &expected, |i| bounds[i]))
        },
    )
}
