//! Records of `ray_diff`: Barycentric, texture and LOD derivatives (RTG Eq. 12-24).

use super::enclosure::{self, determinant_well_conditioned, PARALLEL_WITHIN_ROUNDING};
use super::rows::{direction_dx, zero_diff_dx};
use super::strategy::{any_direction, derivatives2, ray_diff};
use super::{reference, BarycentricArgs, MODULE};
use crate::degenerate::{mirror, same, value, INF, NAN};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{distance, image_size, one_argument, triangle, uv_triangle, with_corners};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, DIFF_MAX_VALUE, DIFF_MIN_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval2, Interval};
use shader_proptest::{Args, Value};

/// `rf_barycentric_derivatives`: the enclosure of the four derivatives.
pub fn barycentric_derivatives() -> Record<BarycentricArgs, Derivatives2> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "barycentric_derivatives",
        |(diff, d, t, p0, p1, p2)| rd::barycentric_derivatives(diff, d, t, p0, p1, p2),
        || {
            (ray_diff(), any_direction(), distance(), triangle())
                .prop_map(|(diff, d, t, p)| (diff, d, t, p[0], p[1], p[2]))
                .boxed()
        },
    )
    .conditioned(PARALLEL_WITHIN_ROUNDING, |&(_, d, _, p0, p1, p2)| {
        determinant_well_conditioned(d, p0, p1, p2)
    })
    .enclosure(enclosure::barycentric_derivatives)
    .reference(reference::barycentric_derivatives())
    .fuzz(|d| (d.ray_diff(), d.unit(), d.distance(), d.vec3(), d.vec3(), d.vec3()))
    .range(-rd::DIFF_MAX_VALUE, rd::DIFF_MAX_VALUE, "barycentric derivative")
    .degenerate(vec![
        value(
            "zero-area triangle (p1 = p2)",
            "k clamped to DIFF_MIN_MAGNITUDE, results clamped to +-DIFF_MAX_VALUE",
            (zero_diff_dx(y), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, x),
            vec![rd::DIFF_MAX_VALUE, -rd::DIFF_MAX_VALUE, 0.0, 0.0],
        ),
        value(
            "t = 0, dO = 0",
            "0",
            (direction_dx(x), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, y),
            vec![0.0; 4],
        ),
        value(
            "ray in the triangle's plane (k = 0), dO off the plane",
            "du/dx = -1 / DIFF_MIN_MAGNITUDE clamped to -DIFF_MAX_VALUE; the rest 0",
            (zero_diff_dx(z), x, 0.0, Vec3::ZERO, x, y),
            vec![-max, 0.0, 0.0, 0.0],
        ),
    ])
}

/// `rf_barycentric_w_derivatives`.
pub fn barycentric_w_derivatives() -> Record<impl Args + Perturb, impl Value> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "barycentric_w_derivatives",
        |(b,)| rd::barycentric_w_derivatives(b),
        || one_argument(derivatives2()),
    )
    .enclosure(|&(b,)| {
        let (dx, dy) = (interval2(b.dx), interval2(b.dy));
        vec![-dx.0[0] - dx.0[1], -dy.0[0] - dy.0[1]]
    })
    .reference(reference::barycentric_w_derivatives())
    .fuzz(|d| (d.derivatives2(),))
    .degenerate(vec![
        value("zero", "0", (Derivatives2::default(),), vec![0.0; 2]),
        value(
            "du = -dv",
            "0: w does not change",
            (Derivatives2::new(Vec2::new(1.0, -1.0), Vec2::new(0.5, -0.5)),),
            vec![0.0; 2],
        ),
        value(
            "clamped differentials (+-DIFF_MAX_VALUE)",
            "(-2 DIFF_MAX_VALUE, 0): finite",
            (Derivatives2::new(Vec2::splat(max), Vec2::new(max, -max)),),
            vec![-2.0 * max, 0.0],
        ),
    ])
}

/// `rf_texture_derivatives`: the enclosure of the UV gradients.
pub fn texture_derivatives() -> Record<(Derivatives2, Vec2, Vec2, Vec2), Derivatives2> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "texture_derivatives",
        |(b, t0, t1, t2)| rd::texture_derivatives(b, t0, t1, t2),
        || with_corners(derivatives2(), uv_triangle()),
    )
    .enclosure(|&(b, t0, t1, t2)| {
        let (dx, dy) = enclosure::texture_derivatives(b, t0, t1, t2);
        enclosure::derivatives2(dx, dy)
    })
    .reference(reference::texture_derivatives())
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

/// `rf_texel_derivatives`.
pub fn texel_derivatives() -> Record<impl Args + Perturb, impl Value> {
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    Record::new(
        MODULE,
        "texel_derivatives",
        |(b, t0, t1, t2, size)| rd::texel_derivatives(b, t0, t1, t2, size),
        || {
            (derivatives2(), uv_triangle(), image_size())
                .prop_map(|(b, t, size)| (b, t[0], t[1], t[2], size))
                .boxed()
        },
    )
    .enclosure(|&(b, t0, t1, t2, size)| {
        let (dx, dy) = enclosure::texture_derivatives(b, t0, t1, t2);
        let size = interval2(size.max(Vec2::ONE));
        enclosure::derivatives2(dx * size, dy * size)
    })
    .reference(reference::texel_derivatives())
    .fuzz(|d| (d.derivatives2(), d.vec2(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        same(
            "zero texture size",
            "as a 1 x 1 texture",
            (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ZERO),
            (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE),
        ),
        same(
            "negative texture size",
            "as a 1 x 1 texture",
            (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::new(-4.0, -8.0)),
            (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE),
        ),
        value(
            "zero barycentric differentials",
            "0",
            (
                Derivatives2::default(),
                Vec2::ZERO,
                Vec2::X,
                Vec2::Y,
                Vec2::splat(1024.0),
            ),
            vec![0.0; 4],
        ),
    ])
}

/// `rf_secondary_origin_derivatives`.
pub fn secondary_origin_derivatives() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let max = DIFF_MAX_VALUE;
    Record::new(
        MODULE,
        "secondary_origin_derivatives",
        |(b, p0, p1, p2)| rd::secondary_origin_derivatives(b, p0, p1, p2),
        || with_corners(derivatives2(), triangle()),
    )
    .enclosure(enclosure::secondary_origin_derivatives)
    .reference(reference::secondary_origin_derivatives())
    .fuzz(|d| (d.derivatives2(), d.vec3(), d.vec3(), d.vec3()))
    .degenerate(vec![
        value(
            "zero-area triangle (one point)",
            "0: the hit cannot move",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), x, x, x),
            vec![0.0; 6],
        ),
        value(
            "zero barycentric differentials",
            "0",
            (Derivatives2::default(), Vec3::ZERO, x, y),
            vec![0.0; 6],
        ),
        value(
            "clamped differentials (+-DIFF_MAX_VALUE), unit triangle",
            "DIFF_MAX_VALUE e1 and -DIFF_MAX_VALUE e2: finite",
            (
                Derivatives2::new(Vec2::new(max, 0.0), Vec2::new(0.0, -max)),
                Vec3::ZERO,
                x,
                y,
            ),
            vec![max, 0.0, 0.0, 0.0, -max, 0.0],
        ),
    ])
}

/// `rf_lod_isotropic`: the enclosure of the LOD.
pub fn lod_isotropic() -> Record<(Derivatives2,), f32> {
    Record::new(
        MODULE,
        "lod_isotropic",
        |(g,)| rd::lod_isotropic(g),
        || one_argument(derivatives2()),
    )
    .enclosure(|&(g,)| vec![enclosure::lod_isotropic(g)])
    .reference(reference::lod_isotropic())
    .fuzz(|d| (d.derivatives2(),))
    .range(0.5 * rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
    .degenerate(vec![
        value(
            "zero gradients",
            "0.5 log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::default(),),
            vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
        ),
        mirror(
            "infinity in",
            "CPU: inf",
            (Derivatives2::new(Vec2::new(INF, 0.0), Vec2::ZERO),),
            vec![INF],
        ),
        value(
            "unit texel gradients",
            "0 (one texel per pixel)",
            (Derivatives2::new(Vec2::X, Vec2::Y),),
            vec![0.0],
        ),
        value(
            "gradients of 1e-16 (rho^2 below DIFF_MIN_MAGNITUDE)",
            "0.5 log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::new(Vec2::new(1.0e-16, 0.0), Vec2::ZERO),),
            vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
        ),
    ])
}

/// `rf_lod_box`.
pub fn lod_box() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "lod_box",
        |(g,)| rd::lod_box(g),
        || one_argument(derivatives2()),
    )
    .enclosure(|&(g,)| vec![enclosure::lod_box(g)])
    .reference(reference::lod_box())
    .fuzz(|d| (d.derivatives2(),))
    .range(rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
    .degenerate(vec![
        value(
            "zero gradients",
            "log2(DIFF_MIN_MAGNITUDE)",
            (Derivatives2::default(),),
            vec![DIFF_MIN_MAGNITUDE.log2()],
        ),
        mirror(
            "NaN in",
            "CPU: log2 of the other components' extent (Rust's `max` ignores NaN)",
            (Derivatives2::new(Vec2::new(NAN, 1.0), Vec2::ZERO),),
            vec![0.0],
        ),
        value(
            "unit texel gradients",
            "0",
            (Derivatives2::new(Vec2::X, Vec2::Y),),
            vec![0.0],
        ),
        value(
            "dx = (1, 0), dy = (-1, 0)",
            "1: the box adds magnitudes, opposite signs do not cancel",
            (Derivatives2::new(Vec2::X, Vec2::NEG_X),),
            vec![1.0],
        ),
    ])
}

/// `rf_sample_grad_gradients`.
pub fn sample_grad_gradients() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "sample_grad_gradients",
        |(g, scale)| rd::sample_grad_gradients(g, scale),
        || (derivatives2(), uniform(-1.0, 4.0)).boxed(),
    )
    .enclosure(|&(g, scale)| {
        let scale = Interval::exact(scale.max(0.0));
        enclosure::derivatives2(interval2(g.dx) * scale, interval2(g.dy) * scale)
    })
    .reference(reference::sample_grad_gradients())
    .fuzz(|d| (d.derivatives2(), d.scalar()))
    .degenerate(vec![
        value(
            "negative scale",
            "0 (scale clamped to >= 0)",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), -1.0),
            vec![0.0; 4],
        ),
        value(
            "scale 0",
            "0 (samples mip 0)",
            (Derivatives2::new(Vec2::ONE, Vec2::ONE), 0.0),
            vec![0.0; 4],
        ),
        value(
            "scale 1",
            "the gradients unchanged",
            (Derivatives2::new(Vec2::new(0.5, -0.25), Vec2::new(2.0, 1.0)), 1.0),
            vec![0.5, -0.25, 2.0, 1.0],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        barycentric_derivatives,
        barycentric_w_derivatives,
        texture_derivatives,
        texel_derivatives,
        secondary_origin_derivatives,
        lod_isotropic,
        lod_box,
        sample_grad_gradients
    ]
}
