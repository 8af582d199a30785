//! The proof of [`hit_texture_lod`](ray_footprint::ray_cone::hit_texture_lod): its record, its case
//! strategy, its enclosure and its reference, the exact footprint of the cone on the triangle's
//! plane through the triangle's UV Jacobian; what the proof of `hit_texture_gradients` shares with
//! it (the hit's cases, the face normal and the areas in interval arithmetic, the exact hit).

use crate::conditioning::well_conditioned;
use crate::degenerate::{cone, grazing, mirror, same, value, IN_PLANE, NAN};
use crate::exact::{log_uniform, tangent, towards, unit};
use crate::fuzzing::draw::Draw;
use crate::ray_cone::bound::width_rounding;
use crate::ray_cone::curvature::shared::clamped_unit;
use crate::ray_cone::footprint::shared::{COLLINEAR_UVS, ZERO_AREA};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::strategy::{distance, image_size, triangle_and_direction, uv_triangle};
use crate::symmetry::Symmetry;
use glam::{DMat2, DVec2, DVec3, Vec2, Vec2Swizzles, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone, MIN_COS, MIN_MAGNITUDE, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, interval3, sum_of_products, Interval, Interval3};
use std::f64::consts::LN_2;

/// Arguments of `rf_hit_texture_lod`: the cone, the direction, the hit distance, the triangle's
/// corners and UVs, the texture size.
pub type HitLodArgs = (RayCone, Vec3, f32, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2, Vec2);

/// Arguments of `rf_hit_texture_gradients`, the first nine of `rf_hit_texture_lod`: the cone, the
/// direction, the hit distance, the triangle's corners and UVs.
pub type HitGradientArgs = (RayCone, Vec3, f32, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

/// The unit right triangle in the xy plane (face normal +Z, the rows' normal) with UVs = xy.
const UNIT: (Vec3, Vec3, Vec3, Vec2, Vec2, Vec2) =
    (Vec3::ZERO, Vec3::X, Vec3::Y, Vec2::ZERO, Vec2::X, Vec2::Y);

/// The record of `rf_hit_texture_lod`: the enclosure of the level.
pub fn record() -> Record<HitLodArgs, f32> {
    let size = Vec2::splat(1024.0);
    let (p0, p1, p2, uv0, uv1, uv2) = UNIT;
    let (z0, z1, z2, zuv0, zuv1, zuv2) = ZERO_AREA;
    let (c0, c1, c2, cuv0, cuv1, cuv2) = COLLINEAR_UVS;
    let down = Vec3::NEG_Z;
    let narrow = cone(1.0 / 64.0, 0.0);
    Record::new(
        Module::RayCone,
        "hit_texture_lod",
        |(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size)| {
            rc::hit_texture_lod(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size)
        },
        || {
            (hit_cases(), image_size())
                .prop_map(|((cone, d, t, p0, p1, p2, uv0, uv1, uv2), size)| {
                    (cone, d, t, p0, p1, p2, uv0, uv1, uv2, size)
                })
                .boxed()
        },
    )
    .conditioned(ILL_CONDITIONED, |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, _)| {
        hit_conditioned(&(cone, d, t, p0, p1, p2, uv0, uv1, uv2))
    })
    .enclosure(|args| vec![enclosure(args)])
    .reference(reference())
    .symmetry(
        Symmetry::scale_in_log(
            "the corners, the cone's width and the hit distance scaled by s, where neither the world area nor the width is clamped: the same (the base LOD falls by log2 s, the width's log2 rises by it)",
            |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs, s| {
                let cone = RayCone {
                    width: cone.width * s,
                    ..cone
                };
                (cone, d, t * s, p0 * s, p1 * s, p2 * s, uv0, uv1, uv2, size)
            },
            |lod: f32, _| lod,
        )
        .within(|&(cone, _, t, p0, p1, p2, ..)| unclamped_hit(cone, t, p0, p1, p2)),
    )
    .symmetry(Symmetry::rotation(
        "the ray and the corners turned: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs, r| {
            (cone, r * d, t, r * p0, r * p1, r * p2, uv0, uv1, uv2, size)
        },
        |lod: f32, _| lod,
    ))
    .symmetry(Symmetry::translation(
        "the corners moved: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs, offset| {
            (cone, d, t, p0 + offset, p1 + offset, p2 + offset, uv0, uv1, uv2, size)
        },
        |lod: f32, _| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs| {
            (cone, d, t, p1, p2, p0, uv1, uv2, uv0, size)
        },
        |lod: f32| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the ray reversed: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs| {
            (cone, -d, t, p0, p1, p2, uv0, uv1, uv2, size)
        },
        |lod: f32| lod,
    ))
    .symmetry(Symmetry::exchange(
        "the texture's width and height exchanged: the same",
        |&(cone, d, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs| {
            (cone, d, t, p0, p1, p2, uv0, uv1, uv2, size.yx())
        },
        |lod: f32| lod,
    ))
    .fuzz(|d| {
        let (cone, direction, t, p0, p1, p2, uv0, uv1, uv2) = fuzz_hit(d);
        (cone, direction, t, p0, p1, p2, uv0, uv1, uv2, d.vec2())
    })
    .degenerate(vec![
        value(
            "head on, unit triangle, uv = xy",
            "log2 |width| + 0.5 (log2 W + log2 H)",
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2, size),
            vec![0.0 + (1.0f32 / 64.0).log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
        value(
            "zero-area triangle (repeated vertex)",
            "the face normal is 0: base LOD of MIN_SQUARED_MAGNITUDE's area, |dot| = MIN_COS",
            (narrow, down, 5.0, z0, z1, z2, zuv0, zuv1, zuv2, size),
            vec![
                0.5 * (0.0 - MIN_SQUARED_MAGNITUDE.log2()) + (1.0f32 / 64.0).log2() + 0.5 * (10.0 + 10.0)
                    - MIN_COS.log2(),
            ],
        ),
        value(
            "zero UV area (collinear UVs)",
            "base LOD 0.5 (log2(MIN_SQUARED_MAGNITUDE) - log2(world_area2))",
            (narrow, down, 5.0, c0, c1, c2, cuv0, cuv1, cuv2, size),
            vec![0.5 * (MIN_SQUARED_MAGNITUDE.log2() - 0.0) + (1.0f32 / 64.0).log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
        same(
            "t = 0",
            "the cone's width at its origin",
            (cone(1.0 / 64.0, 0.01), down, 0.0, p0, p1, p2, uv0, uv1, uv2, size),
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2, size),
        ),
        value(
            "zero cone (width and spread 0)",
            "log2(MIN_MAGNITUDE) + 0.5 (log2 W + log2 H)",
            (cone(0.0, 0.0), down, 5.0, p0, p1, p2, uv0, uv1, uv2, size),
            vec![0.0 + MIN_MAGNITUDE.log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
        value(
            "ray in the triangle's plane",
            "... - log2(MIN_COS)",
            (narrow, IN_PLANE, 5.0, p0, p1, p2, uv0, uv1, uv2, size),
            vec![0.0 + (1.0f32 / 64.0).log2() + 0.5 * (10.0 + 10.0) - MIN_COS.log2()],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as the ray in the plane",
            (narrow, grazing(), 5.0, p0, p1, p2, uv0, uv1, uv2, size),
            (narrow, IN_PLANE, 5.0, p0, p1, p2, uv0, uv1, uv2, size),
        ),
        same(
            "zero texture size",
            "as a 1 x 1 texture (W, H clamped to >= 1)",
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2, Vec2::ZERO),
            (narrow, down, 5.0, p0, p1, p2, uv0, uv1, uv2, Vec2::ONE),
        ),
        mirror(
            "NaN in (t)",
            "CPU: as t = 0 through width 0 (Rust's `max` ignores NaN): log2(MIN_MAGNITUDE) + 10",
            (narrow, down, NAN, p0, p1, p2, uv0, uv1, uv2, size),
            vec![0.0 + MIN_MAGNITUDE.log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
    ])
}

/// The arguments both hit functions share: a cone, a direction, a hit distance, a triangle and
/// its UVs ([`triangle_and_direction`]).
pub(crate) fn hit_cases() -> BoxedStrategy<HitGradientArgs> {
    (ray_cone(), distance(), triangle_and_direction(), uv_triangle())
        .prop_map(|(cone, t, (p, direction), uv)| (cone, direction, t, p[0], p[1], p[2], uv[0], uv[1], uv[2]))
        .boxed()
}

/// The fuzz draw of the arguments both hit functions share, in their order.
pub(crate) fn fuzz_hit(d: &mut Draw) -> HitGradientArgs {
    (
        d.cone(),
        d.unit(),
        d.distance(),
        d.vec3(),
        d.vec3(),
        d.vec3(),
        d.vec2(),
        d.vec2(),
        d.vec2(),
    )
}

/// Why a hit is left to the special-value suite's clamps: what the hit functions divide by or
/// take the logarithm of is not known to
/// [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED).
pub(crate) const ILL_CONDITIONED: &str = "the face normal's clamped cosine with the ray or a clamped doubled area not known to 2^-10 (a sliver or a ray in the triangle's plane within rounding), where the enclosure is as wide as the outputs";

/// Whether the clamped cosine of the face normal with the ray and the clamped doubled areas are
/// known to [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED) ([`well_conditioned`]).
pub(crate) fn hit_conditioned(&(_, direction, _, p0, p1, p2, uv0, uv1, uv2): &HitGradientArgs) -> bool {
    let min = f64::from(MIN_SQUARED_MAGNITUDE);
    let p = [p0, p1, p2].map(interval3);
    let (uv_area2, world_area2) = areas(p, [uv0, uv1, uv2]);
    let cosine = face_normal(p)
        .dot(interval3(direction))
        .abs()
        .max_c(f64::from(MIN_COS));
    well_conditioned(cosine)
        && well_conditioned(uv_area2.max_c(min))
        && well_conditioned(world_area2.max_c(min))
}

/// Whether a hit is one that a uniform scale scales throughout: the triangle's doubled area above
/// `MIN_SQUARED_MAGNITUDE` and the cone's width at the hit above `MIN_MAGNITUDE` (neither clamped).
pub(crate) fn unclamped_hit(cone: RayCone, t: f32, p0: Vec3, p1: Vec3, p2: Vec3) -> bool {
    rc::triangle_world_area2(p0, p1, p2) > MIN_SQUARED_MAGNITUDE
        && rc::width_at(cone, t).abs() > MIN_MAGNITUDE
}

/// The face normal `unit(unit(p1 - p0) x unit(p2 - p0))`, as `face_normal(shape_frame_u(p0, p1), p0, p2)`.
pub(crate) fn face_normal(p: [Interval3; 3]) -> Interval3 {
    clamped_unit(clamped_unit(p[1] - p[0]).cross(clamped_unit(p[2] - p[0])))
}

/// The doubled areas `(uv_area2, world_area2)`, as `triangle_uv_area2` and
/// `triangle_world_area2` (the cross product divided by its largest component before its length).
pub(crate) fn areas(p: [Interval3; 3], uv: [Vec2; 3]) -> (Interval, Interval) {
    let (g1, g2) = (
        interval2(uv[1]) - interval2(uv[0]),
        interval2(uv[2]) - interval2(uv[0]),
    );
    let uv_area2 = sum_of_products(&[(g1.0[0], g2.0[1]), (-g1.0[1], g2.0[0])]).abs();
    let c = (p[1] - p[0]).cross(p[2] - p[0]);
    let scale = c.0[0]
        .abs()
        .max(c.0[1].abs())
        .max(c.0[2].abs().max_c(f64::from(MIN_MAGNITUDE)));
    let scaled = c / scale;
    (uv_area2, scale * scaled.dot(scaled).sqrt())
}

/// `rf_hit_texture_lod` in interval arithmetic, in the same order of operations: the base LOD of
/// the clamped areas, the cone's width at `t`, the texture size and the face normal's cosine.
fn enclosure(&(cone, direction, t, p0, p1, p2, uv0, uv1, uv2, size): &HitLodArgs) -> Interval {
    let min_area = f64::from(MIN_SQUARED_MAGNITUDE);
    let p = [p0, p1, p2].map(interval3);
    let (uv_area2, world_area2) = areas(p, [uv0, uv1, uv2]);
    let base = Interval::c(0.5) * (uv_area2.max_c(min_area).log2() - world_area2.max_c(min_area).log2());
    let width = Interval::exact(cone.width) + Interval::exact(cone.spread_angle) * Interval::exact(t);
    let size = interval2(size).map(|side| side.max_c(1.0));
    let cosine = face_normal(p)
        .dot(interval3(direction))
        .abs()
        .max_c(f64::from(MIN_COS));
    base + width.abs().max_c(f64::from(MIN_MAGNITUDE)).log2()
        + Interval::c(0.5) * (size.0[0].log2() + size.0[1].log2())
        - cosine.log2()
}

/// A hit for the references: a triangle of any shape but a sliver (its angle at `p0` above about
/// 6 degrees), at a scale from 1e-8 to 1e8, in a random plane up to 10 of its sizes from the
/// origin, with UVs an affine map of its plane (entries 1e-3 to 1e3, offset up to 5 UV sizes);
/// a ray meeting its plane at `|cos|` from 1e-3 to 1 from either side; a diverging cone whose
/// width at the hit is 1e-3 to 1 of the triangle's size; a texture from 1 to 16384 texels a side.
/// Everything is rounded to the f32 arguments, from which the reference's geometry is computed
/// exactly.
#[derive(Clone, Debug)]
pub(crate) struct Hit {
    pub(crate) cone: RayCone,
    pub(crate) direction: Vec3,
    pub(crate) t: f32,
    pub(crate) p: [Vec3; 3],
    pub(crate) uv: [Vec2; 3],
    pub(crate) size: Vec2,
}

impl Hit {
    pub(crate) fn strategy() -> BoxedStrategy<Hit> {
        let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
        let entry = || {
            (log_uniform(-3.0, 3.0), any::<bool>()).prop_map(|(m, negative)| if negative { -m } else { m })
        };
        let cosine = prop_oneof![2 => 0.05f64..1.0, 1 => log_uniform(-3.0, 0.0)];
        let side = || prop_oneof![(1u32..16384).prop_map(|s| s as f32), 1.0f32..16384.0];
        (
            (
                (corner(), corner(), corner()),
                log_uniform(-8.0, 8.0),
                (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
            ),
            (
                unit(),
                0.0f64..6.3,
                (entry(), entry(), entry(), entry()),
                (-5.0f64..5.0, -5.0f64..5.0),
            ),
            (cosine, 0.0f64..6.3, any::<bool>()),
            (
                log_uniform(-3.0, 0.0),
                prop_oneof![Just(0.0f64), log_uniform(-6.0, -1.0)],
                log_uniform(-1.0, 3.0),
            ),
            (side(), side()),
        )
            .prop_map(
                |(
                    (q, scale, (x, y, z)),
                    (normal, turn, (m00, m01, m10, m11), (ox, oy)),
                    (cos, spin, behind),
                    (w, s, t),
                    (width, height),
                )| {
                    let (u, v) = (tangent(normal, turn), normal.cross(tangent(normal, turn)));
                    let centre = DVec3::new(x, y, z) * scale;
                    let q = [q.0, q.1, q.2].map(|q| q * scale);
                    let map = DMat2::from_cols(DVec2::new(m00, m10), DVec2::new(m01, m11));
                    let uv_size = scale * (m00.abs() + m01.abs() + m10.abs() + m11.abs());
                    let d = towards(normal, cos, spin);
                    // The width at the hit is w times the triangle's size, split between the cone's
                    // width at its origin and its spread over t (t in triangle sizes).
                    let t = t * scale;
                    let at_hit = w * scale;
                    let spread = s.min(0.5 * at_hit / t);
                    Hit {
                        cone: RayCone {
                            width: (at_hit - spread * t) as f32,
                            spread_angle: spread as f32,
                        },
                        direction: (if behind { -d } else { d }).as_vec3(),
                        t: t as f32,
                        p: q.map(|q| (centre + u * q.x + v * q.y).as_vec3()),
                        uv: q.map(|q| (map * q + DVec2::new(ox, oy) * uv_size).as_vec2()),
                        size: Vec2::new(width, height),
                    }
                },
            )
            .prop_filter("a sliver or a degenerate UV map", |hit| {
                let (e1, e2) = hit.edges();
                let (g1, g2) = hit.uv_edges();
                e1.cross(e2).length() > 0.1 * e1.length() * e2.length()
                    && g1.perp_dot(g2).abs() > 1.0e-3 * g1.length() * g2.length()
            })
            .boxed()
    }

    /// The arguments of `hit_texture_gradients`.
    pub(crate) fn gradient_arguments(&self) -> HitGradientArgs {
        let (p, uv) = (self.p, self.uv);
        (
            self.cone,
            self.direction,
            self.t,
            p[0],
            p[1],
            p[2],
            uv[0],
            uv[1],
            uv[2],
        )
    }

    /// The edges `p1 - p0`, `p2 - p0` of the f32 corners, in f64 (exact).
    fn edges(&self) -> (DVec3, DVec3) {
        let p = self.p.map(Vec3::as_dvec3);
        (p[1] - p[0], p[2] - p[0])
    }

    /// The UV edges of the f32 UVs, in f64 (exact).
    fn uv_edges(&self) -> (DVec2, DVec2) {
        let uv = self.uv.map(Vec2::as_dvec2);
        (uv[1] - uv[0], uv[2] - uv[0])
    }

    /// The exact hit of the f32 arguments: the cone's footprint on the triangle's plane (its two
    /// boundary rays, `|w + s t|` apart across the ray in the plane of incidence, meet the plane
    /// `|w + s t| / |cos|` apart) and the triangle's texel density, `sqrt(|det J|)` of the Jacobian
    /// `J = G E^-1` that maps in-plane coordinates to UV (`E`: the edges in an orthonormal basis of
    /// the plane, `G`: the UV edges); then the mirror's relative error of their product.
    pub(crate) fn exact(&self) -> Exact {
        let (e1, e2) = self.edges();
        let (g1, g2) = self.uv_edges();
        let area_normal = e1.cross(e2);
        let n = area_normal.normalize();
        let (a, b) = (e1.normalize(), n.cross(e1.normalize()));
        let in_plane = DMat2::from_cols(DVec2::new(e1.dot(a), e1.dot(b)), DVec2::new(e2.dot(a), e2.dot(b)));
        let jacobian = DMat2::from_cols(g1, g2) * in_plane.inverse();
        let density = jacobian.determinant().abs().sqrt();
        let d = self.direction.as_dvec3();
        let cos = n.dot(d.normalize()).abs();
        let (w, s, t) = (
            f64::from(self.cone.width),
            f64::from(self.cone.spread_angle),
            f64::from(self.t),
        );
        let width = (w + s * t).abs();
        let footprint = width / cos;
        // The doubled areas as the mirror computes them: the world one within
        // gamma(6) (|e1| |e2| + area), the UV one within gamma(4) |g1| |g2|; the density is the
        // square root of their ratio.
        let world = area_normal.length();
        let uv_area = g1.perp_dot(g2).abs();
        let area_error = gamma(6) * (e1.length() * e2.length() + world) / world
            + gamma(4) * g1.length() * g2.length() / uv_area;
        // The face normal: unit edges within gamma(4) each, their cross product within
        // gamma(11) of the exact one, whose length is sin = world / (|e1| |e2|); normalizing
        // it turns its direction by at most twice the error over its length, and rounds (gamma(4)).
        let sine = world / (e1.length() * e2.length());
        let normal = 2.0 * gamma(11) / sine + gamma(4);
        // The cosine: the normal's turn, the dot product (gamma(3)) and the direction's distance
        // from unit length, relative to |cos|.
        let cosine = (normal + gamma(3)) / cos + (1.0 - d.length()).abs();
        Exact {
            footprint,
            density,
            cos,
            width,
            areas: (uv_area, world),
            relative: 0.5 * area_error + cosine + width_rounding(w, s, t) / width,
        }
    }
}

/// The exact quantities of a [`Hit`].
pub(crate) struct Exact {
    /// The cone's footprint on the plane, world units.
    pub(crate) footprint: f64,
    /// The triangle's texel density, UV units per world unit.
    pub(crate) density: f64,
    /// `|cos|` of the ray and the plane.
    pub(crate) cos: f64,
    /// The cone's width at the hit.
    pub(crate) width: f64,
    /// The doubled areas `(uv, world)`.
    pub(crate) areas: (f64, f64),
    /// The relative error of the mirror's footprint times density, to first order.
    pub(crate) relative: f64,
}

/// The reference of `rf_hit_texture_lod`.
fn reference() -> Reference<HitLodArgs, f32> {
    Reference::new(
        Kind::ExactGeometry,
        "log2 of the cone's exact footprint on the triangle's plane (|w + s t| / |cos|) times the texel density sqrt|det J| of the triangle's UV Jacobian and sqrt(W H), triangles at scales 1e-8 to 1e8 in random planes (RTG Eq. 34)",
        Hit::strategy,
        |hit, hit_texture_lod| {
            let (cone, d, t, p0, p1, p2, uv0, uv1, uv2) = hit.gradient_arguments();
            let got = hit_texture_lod((cone, d, t, p0, p1, p2, uv0, uv1, uv2, hit.size));
            let exact = hit.exact();
            if exact.areas.0.min(exact.areas.1) < 1.0e2 * f64::from(MIN_SQUARED_MAGNITUDE) {
                // The areas' clamp, a degenerate row's business.
                return None;
            }
            let (width, height) = (f64::from(hit.size.x), f64::from(hit.size.y));
            let expected = (exact.footprint * exact.density * (width * height).sqrt()).log2();
            // The relative errors through log2 (over ln 2); six log2 within 2 ULP of their
            // results (4 u) and six sums and halvings within gamma(6) of the terms' magnitudes.
            let terms = 0.5 * (exact.areas.0.log2().abs() + exact.areas.1.log2().abs())
                + 0.5 * (width.log2() + height.log2())
                + exact.width.log2().abs()
                + exact.cos.log2().abs();
            let bound = 1.01 * exact.relative / LN_2 + (gamma(6) + 4.0 * U) * terms;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
