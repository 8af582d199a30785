//! The proof of [`hit_texture_gradients`](ray_footprint::ray_cone::hit_texture_gradients): its
//! record, its enclosure and its reference, the exact footprint of the cone on the triangle's
//! plane through the triangle's UV Jacobian (the hit's cases and geometry are `hit_texture_lod`'s).

use crate::degenerate::{cone, grazing, mirror, same, value, IN_PLANE, NAN};
use crate::ray_cone::footprint::hit_texture_lod::{
    areas, face_normal, fuzz_hit, hit_cases, hit_conditioned, unclamped_hit, Hit, HitGradientArgs,
    ILL_CONDITIONED,
};
use crate::ray_cone::footprint::shared::{COLLINEAR_UVS, ZERO_AREA};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::symmetry::Symmetry;
use glam::{Vec2, Vec3, Vec4};
use ray_footprint::ray_cone::{self as rc, RayCone, F16_MAX, MIN_COS, MIN_MAGNITUDE, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval};

/// The record of `rf_hit_texture_gradients`: the enclosure of the gradients.
pub fn record() -> Record<HitGradientArgs, Vec4> {
    let (p0, p1, p2, uv0, uv1, uv2) = (Vec3::ZERO, Vec3::X, Vec3::Y, Vec2::ZERO, Vec2::X, Vec2::Y);
    let (z0, z1, z2, zuv0, zuv1, zuv2) = ZERO_AREA;
    let (c0, c1, c2, cuv0, cuv1, cuv2) = COLLINEAR_UVS;
    let down = Vec3::NEG_Z;
    let narrow = cone(1.0 / 64.0, 0.0);
    let g = 1.0f32 / 64.0;
    Record::new(
        Module::RayCone,
        "hit_texture_gradients",
        |(cone, d, t, p0, p1, p2, uv0, uv1, uv2)| {
            rc::hit_texture_gradients(cone, d, t, p0, p1, p2, uv0, uv1, uv2)
        },
        hit_cases,
    )
    .conditioned(ILL_CONDITIONED, hit_conditioned)
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(
        Symmetry::scale(
            "the corners, the cone's width and the hit distance scaled by s, where neither the world area, the width nor the gradient is clamped: the same (the footprint grows by s, the texel density falls by it)",
            |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs, s| {
                let cone = RayCone {
                    width: cone.width * s,
                    ..cone
                };
                (cone, d, t * s, p0 * s, p1 * s, p2 * s, uv0, uv1, uv2)
            },
            |gradients: Vec4, _| gradients,
        )
        .within(|&(cone, d, t, p0, p1, p2, uv0, uv1, uv2)| {
            unclamped_hit(cone, t, p0, p1, p2)
                && rc::hit_texture_gradients(cone, d, t, p0, p1, p2, uv0, uv1, uv2).x < 0.5 * F16_MAX
                && rc::texel_density(p0, p1, p2, uv0, uv1, uv2) > MIN_MAGNITUDE
        }),
    )
    .symmetry(Symmetry::rotation(
        "the ray and the corners turned: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs, r| {
            (cone, r * d, t, r * p0, r * p1, r * p2, uv0, uv1, uv2)
        },
        |gradients: Vec4, _| gradients,
    ))
    .symmetry(Symmetry::translation(
        "the corners moved: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs, offset| {
            (cone, d, t, p0 + offset, p1 + offset, p2 + offset, uv0, uv1, uv2)
        },
        |gradients: Vec4, _| gradients,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs| (cone, d, t, p1, p2, p0, uv1, uv2, uv0),
        |gradients: Vec4| gradients,
    ))
    .symmetry(Symmetry::exchange(
        "the ray reversed: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs| (cone, -d, t, p0, p1, p2, uv0, uv1, uv2),
        |gradients: Vec4| gradients,
    ))
    .fuzz(fuzz_hit)
    .degenerate(vec![
        value(
            "head on, unit triangle, uv = xy",
            "(g, 0, 0, g) with g = |width|",
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2),
            vec![g, 0.0, 0.0, g],
        ),
        value(
            "zero-area triangle (repeated vertex)",
            "the face normal is 0: g = |width| / MIN_COS * sqrt(uv_area2) / sqrt(MIN_SQUARED_MAGNITUDE), clamped to about F16_MAX",
            (narrow, down, 5.0, z0, z1, z2, zuv0, zuv1, zuv2),
            {
                let density = 1.0f32.sqrt() / MIN_SQUARED_MAGNITUDE.sqrt();
                let g = (g / MIN_COS).min(F16_MAX / density.max(MIN_MAGNITUDE)) * density;
                vec![g, 0.0, 0.0, g]
            },
        ),
        value(
            "zero UV area (collinear UVs)",
            "0 (samples mip 0)",
            (narrow, down, 5.0, c0, c1, c2, cuv0, cuv1, cuv2),
            vec![0.0; 4],
        ),
        same(
            "t = 0",
            "the cone's width at its origin",
            (cone(1.0 / 64.0, 0.01), down, 0.0, p0, p1, p2, uv0, uv1, uv2),
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2),
        ),
        value(
            "zero cone (width and spread 0)",
            "0",
            (cone(0.0, 0.0), down, 5.0, p0, p1, p2, uv0, uv1, uv2),
            vec![0.0; 4],
        ),
        value(
            "ray in the triangle's plane",
            "g = |width| / MIN_COS",
            (narrow, IN_PLANE, 5.0, p0, p1, p2, uv0, uv1, uv2),
            {
                let g = (g / MIN_COS).min(F16_MAX / 1.0) * 1.0;
                vec![g, 0.0, 0.0, g]
            },
        ),
        value(
            "huge cone on a zero-area triangle with huge UVs, in its plane",
            "about F16_MAX: the footprint clamped to F16_MAX / density before the product (1e16 * 1e22 overflows)",
            (
                cone(1.0e12, 0.0),
                IN_PLANE,
                5.0,
                z0,
                z1,
                z2,
                Vec2::ZERO,
                Vec2::new(1.0e12, 0.0),
                Vec2::new(0.0, 1.0e12),
            ),
            {
                let density = (1.0e12f32 * 1.0e12).sqrt() / MIN_SQUARED_MAGNITUDE.sqrt();
                let g = (1.0e12f32 / MIN_COS).min(F16_MAX / density.max(MIN_MAGNITUDE)) * density;
                vec![g, 0.0, 0.0, g]
            },
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as the ray in the plane",
            (narrow, grazing(), 5.0, p0, p1, p2, uv0, uv1, uv2),
            (narrow, IN_PLANE, 5.0, p0, p1, p2, uv0, uv1, uv2),
        ),
        mirror(
            "NaN in (t)",
            "CPU: F16_MAX (the clamp's `min` ignores NaN)",
            (narrow, down, NAN, p0, p1, p2, uv0, uv1, uv2),
            vec![F16_MAX, 0.0, 0.0, F16_MAX],
        ),
    ])
}

/// `rf_hit_texture_gradients` in interval arithmetic, in the same order of operations: the cone's
/// slanted footprint with the face normal, clamped to `F16_MAX / max(density, MIN_MAGNITUDE)`,
/// times the texel density of the clamped world area.
fn enclosure(&(cone, direction, t, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs) -> Vec<Interval> {
    let p = [p0, p1, p2].map(interval3);
    let (uv_area2, world_area2) = areas(p, [uv0, uv1, uv2]);
    let width = Interval::exact(cone.width) + Interval::exact(cone.spread_angle) * Interval::exact(t);
    let cosine = face_normal(p)
        .dot(interval3(direction))
        .abs()
        .max_c(f64::from(MIN_COS));
    let density = uv_area2.sqrt() / world_area2.max_c(f64::from(MIN_SQUARED_MAGNITUDE)).sqrt();
    let limit = Interval::c(f64::from(F16_MAX)) / density.max_c(f64::from(MIN_MAGNITUDE));
    let gradient = (width.abs() / cosine).min(limit) * density;
    vec![gradient, Interval::c(0.0), Interval::c(0.0), gradient]
}

/// The reference of `rf_hit_texture_gradients`.
fn reference() -> Reference<HitGradientArgs, Vec4> {
    Reference::new(
        Kind::ExactGeometry,
        "(g, 0, 0, g) with g the cone's exact footprint on the triangle's plane (|w + s t| / |cos|) times the texel density sqrt|det J| of the triangle's UV Jacobian, triangles at scales 1e-8 to 1e8 in random planes (ray-cone tutorial's textureGrad form)",
        Hit::strategy,
        |hit, hit_texture_gradients| {
            let got = hit_texture_gradients(hit.gradient_arguments());
            let exact = hit.exact();
            if exact.areas.0.min(exact.areas.1) < 1.0e2 * f64::from(MIN_SQUARED_MAGNITUDE) {
                // The areas' clamp, a degenerate row's business.
                return None;
            }
            let expected = exact.footprint * exact.density;
            if expected > 0.5 * f64::from(F16_MAX) {
                // Near or past the clamp to F16_MAX, a degenerate row's business.
                return None;
            }
            // The relative errors of the areas, the cosine and the width, and six roundings: the
            // division by the cosine, two square roots, their quotient, the product (gamma(6)).
            let bound = 1.01 * (exact.relative + gamma(6)) * expected;
            let diagonal = Deviation::within(f64::from(got.x), expected, bound)
                .and(Deviation::within(f64::from(got.w), expected, bound));
            let off_diagonal = Deviation::within(f64::from(got.y), 0.0, 0.0).and(Deviation::within(f64::from(got.z), 0.0, 0.0));
            Some(diagonal.and(off_diagonal))
        },
    )
}
