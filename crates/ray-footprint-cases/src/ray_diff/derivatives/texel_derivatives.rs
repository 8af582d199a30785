//! The proof of [`texel_derivatives`](ray_footprint::ray_diff::texel_derivatives): its record and
//! its reference.

use crate::degenerate::{same, value};
use crate::ray_diff::changes::*;
use crate::ray_diff::derivatives::shared::{uv_bounds, Hit};
use crate::ray_diff::derivatives::texture_derivatives;
use crate::ray_diff::intervals::{self};
use crate::ray_diff::reference::{components, widths};
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{image_size, uv_triangle};
use glam::Vec2;
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, Interval};
use shader_proptest::{Args, Value};

/// The record of `rf_texel_derivatives`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    Record::new(
        Module::RayDiff,
        "texel_derivatives",
        |(b, t0, t1, t2, size)| rd::texel_derivatives(b, t0, t1, t2, size),
        || {
            (derivatives2(), uv_triangle(), image_size())
                .prop_map(|(b, t, size)| (b, t[0], t[1], t[2], size))
                .boxed()
        },
    )
    .enclosure(|&(b, t0, t1, t2, size)| {
        let (dx, dy) = texture_derivatives::enclosure(b, t0, t1, t2);
        let size = interval2(size.max(Vec2::ONE));
        intervals::derivatives2(dx * size, dy * size)
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the derivatives exchanged",
        |&(b, t0, t1, t2, size): &(Derivatives2, Vec2, Vec2, Vec2, Vec2)| (swapped2(b), t0, t1, t2, size),
        swapped2,
    ))
    .symmetry(Symmetry::translation(
        "the texture coordinates moved: the same",
        |&(b, t0, t1, t2, size): &(Derivatives2, Vec2, Vec2, Vec2, Vec2), o| {
            (b, t0 + o.truncate(), t1 + o.truncate(), t2 + o.truncate(), size)
        },
        |g: Derivatives2, _| g,
    ))
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

/// The reference of `rf_texel_derivatives`.
fn reference() -> Reference<(Derivatives2, Vec2, Vec2, Vec2, Vec2), Derivatives2> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the texel coordinates (UV of an affine map of the plane times the texture size) of the re-intersected hits (RTG Eq. 21)",
        || (Hit::strategy(), 1.0f32..4096.0, 1.0f32..4096.0).boxed(),
        |(hit, width, height), texel_derivatives| {
            let size = Vec2::new(*width, *height);
            let (input, input_error) = hit.barycentric_input();
            let (uvs, uv_rounding) = hit.corner_uvs();
            let got = texel_derivatives((input, uvs[0], uvs[1], uvs[2], size));
            let [dx, dy] = hit.along(|(_, point)| hit.uv(point) * size.as_dvec2());
            let (rx, ry) = texture_derivatives::enclosure(input, uvs[0], uvs[1], uvs[2]);
            let scaled = |r: Interval, s: f32| r * Interval::exact(s);
            let rounding = widths(&[
                scaled(rx.0[0], size.x),
                scaled(rx.0[1], size.y),
                scaled(ry.0[0], size.x),
                scaled(ry.0[1], size.y),
            ]);
            let bounds = uv_bounds(hit, uvs, &rounding, (input_error, uv_rounding, 0.0), size);
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}
