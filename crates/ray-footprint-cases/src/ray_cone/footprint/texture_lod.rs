//! The proof of [`texture_lod`](ray_footprint::ray_cone::texture_lod): its record and its reference.

use crate::degenerate::{grazing, mirror, same, value, HEAD_ON, IN_PLANE, NAN};
use crate::exact::signed_log;
use crate::ray_cone::bound::clamped_cos;
use crate::ray_cone::footprint::shared::{cosine_error, slanted_footprint, surface_hit};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::strategy::{image_size, normal_and_direction, scalar};
use crate::symmetry::Symmetry;
use glam::Vec2Swizzles;
use glam::{DVec2, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS, MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::tolerance::{dot_error, log2_error, ulps};
use std::f64::consts::LN_2;

/// Arguments of `rf_texture_lod`: base LOD, width, texture size, normal, direction.
pub type TextureLodArgs = (f32, f32, Vec2, Vec3, Vec3);

/// The record of `rf_texture_lod` (also measured by the harness benchmark).
pub fn record() -> Record<TextureLodArgs, f32> {
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "texture_lod",
        |(base, width, size, normal, direction)| rc::texture_lod(base, width, size, normal, direction),
        || {
            (
                uniform(-20.0, 20.0),
                scalar(),
                image_size(),
                normal_and_direction(),
            )
                .prop_map(|(base, width, size, (n, d))| (base, width, size, n, d))
                .boxed()
        },
    )
    // Four log2 (their own errors), the dot's rounding through log2 (relative error / ln 2),
    // and four additions (4 ULP of the sum of term magnitudes).
    .bound(|&(base, width, size, normal, direction), _, _| {
        let size = size.max(Vec2::ONE);
        let logs = [
            width.abs().max(MIN_MAGNITUDE).log2(),
            size.x.log2(),
            size.y.log2(),
        ];
        let cos = clamped_cos(normal, direction);
        let log_cos = cos.log2();
        log2_error(logs[0])
            + 0.5 * (log2_error(logs[1]) + log2_error(logs[2]))
            + log2_error(log_cos)
            + dot_error(normal, direction) / cos / std::f32::consts::LN_2
            + ulps(
                4.0,
                base.abs() + logs[0].abs() + 0.5 * (logs[1] + logs[2]) + log_cos.abs(),
            )
    })
    .reference(reference())
    .symmetry(
        Symmetry::scale_in_log(
            "a width above MIN_MAGNITUDE (not clamped) scaled by s: the LOD plus log2 s",
            |&(base, width, size, normal, direction), s| (base, width * s, size, normal, direction),
            |lod: f32, s| lod - s.log2(),
        )
        .within(|&(_, width, ..)| width.abs() > MIN_MAGNITUDE),
    )
    .symmetry(Symmetry::rotation(
        "the normal and the ray turned: the same",
        |&(base, width, size, normal, direction), r| (base, width, size, r * normal, r * direction),
        |lod, _| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the texture's width and height exchanged: the same",
        |&(base, width, size, normal, direction)| (base, width, size.yx(), normal, direction),
        |lod| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the normal flipped: the same",
        |&(base, width, size, normal, direction)| (base, width, size, -normal, direction),
        |lod| lod,
    ))
    .fuzz(|d| (d.scalar(), d.scalar(), d.vec2(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero width",
            "base + log2(MIN_MAGNITUDE) + 0.5 (log2 W + log2 H) - log2 |dot|",
            (0.0, 0.0, Vec2::splat(1024.0), z, HEAD_ON),
            vec![0.0 + MIN_MAGNITUDE.log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
        same(
            "zero texture size",
            "as a 1 x 1 texture (W, H clamped to >= 1)",
            (0.0, 1.0, Vec2::ZERO, z, HEAD_ON),
            (0.0, 1.0, Vec2::ONE, z, HEAD_ON),
        ),
        value(
            "ray in the surface plane (dot(n, d) = 0)",
            "base + log2 |width| + 0.5 (log2 W + log2 H) - log2(MIN_COS)",
            (0.0, 1.0, Vec2::ONE, z, IN_PLANE),
            vec![-MIN_COS.log2()],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (0.0, 1.0, Vec2::ONE, z, grazing()),
            (0.0, 1.0, Vec2::ONE, z, IN_PLANE),
        ),
        mirror(
            "NaN in (width)",
            "CPU: as width 0 (Rust's `max` ignores NaN)",
            (0.0, NAN, Vec2::splat(1024.0), z, HEAD_ON),
            vec![MIN_MAGNITUDE.log2() + 10.0],
        ),
    ])
}

/// The reference of `rf_texture_lod`.
fn reference() -> Reference<(f32, f32, Vec2, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the log2 of the cone's slanted footprint in texels: its boundary rays intersected with the surface, |w| / |cos|, times the density 2^base_lod and sqrt(W H) (RTG Eq. 34)",
        || {
            let side = || prop_oneof![(1u32..16384).prop_map(f64::from), 1.0f64..16384.0];
            (-10.0f64..10.0, signed_log(-6.0, 1.0), (side(), side()), surface_hit()).boxed()
        },
        |&(base, w, (width, height), (n, d)), texture_lod| {
            let (base, w, size, n32, d32) = (base as f32, w as f32, DVec2::new(width, height).as_vec2(), n.as_vec3(), d.as_vec3());
            let got = texture_lod((base, w, size, n32, d32));
            let (n, d) = (n32.as_dvec3().normalize(), d32.as_dvec3().normalize());
            let footprint = slanted_footprint(f64::from(w), n, d);
            let texels = footprint * f64::from(base).exp2() * (f64::from(size.x) * f64::from(size.y)).sqrt();
            let expected = texels.log2();
            // Each log2 within 2 ULP of its result (4 u); the cosine's relative error through
            // log2 (over ln 2); four sums and a halving round within gamma(4) of the terms.
            let logs = [f64::from(w).abs().log2(), f64::from(size.x).log2(), f64::from(size.y).log2(), n.dot(d).abs().log2()];
            let terms = f64::from(base).abs() + logs.iter().map(|l| l.abs()).sum::<f64>();
            let bound = gamma(4) * terms + 4.0 * U * terms + 1.01 * cosine_error(n32, d32) / LN_2;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
