//! What the footprint and texture-LOD functions share: the errors of a triangle's doubled areas and
//! how far a quantity of both moves within them (tolerances); triangles with UVs (cases) and the
//! degenerate ones of the rows; and for the references, hits on a surface at any slant, a cone's
//! slanted footprint, the error of an f32 cosine, and triangles mapped to UV by a known affine
//! map.

use crate::conditioning::WELL_CONDITIONED;
use crate::exact::{heron_area2, log_uniform, plane_hit, signed_log, towards, unit};
use crate::ray_cone::bound::unit_excess;
use crate::reference::gamma;
use crate::strategy::{triangle, uv_triangle};
use crate::symmetry::Symmetry;
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3, Vec3Swizzles};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use shader_proptest::tolerance::ulps;

/// Error of a triangle's doubled world area: each cross-product component `a*b - c*d` is off by at
/// most 2 ULP of `|a*b| + |c*d|` (the edges are computed identically); the scaling division
/// (2.5 ULP), `length` (8 ULP) and the rescaling product (0.5 ULP) add 11 ULP of the result; and
/// a device may flush a denormal edge component or product to zero ([`flushed_edges`]).
pub(crate) fn world_area2_error(p: [Vec3; 3]) -> f32 {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let terms = (e1.yzx() * e2.zxy()).abs() + (e1.zxy() * e2.yzx()).abs();
    ulps(2.0, terms.element_sum())
        + ulps(11.0, rc::triangle_world_area2(p[0], p[1], p[2]))
        + 3.0 * flushed_edges(e1.abs().element_sum() + e2.abs().element_sum())
}

/// Error of a triangle's doubled UV area: 2 ULP of `|e1.x*e2.y| + |e1.y*e2.x|`, and the flushed
/// denormals ([`flushed_edges`]).
pub(crate) fn uv_area2_error(uv: [Vec2; 3]) -> f32 {
    let (e1, e2) = (uv[1] - uv[0], uv[2] - uv[0]);
    ulps(2.0, (e1.x * e2.y).abs() + (e1.y * e2.x).abs())
        + flushed_edges(e1.abs().element_sum() + e2.abs().element_sum())
}

/// What flushing denormals to zero, which Vulkan allows, can take from one cross-product component
/// `a*b - c*d` of two edges whose components sum to `edge_sum` in magnitude: an edge component
/// that is a denormal difference of two corners (smaller than `f32::MIN_POSITIVE`) may become 0,
/// moving a product by at most `f32::MIN_POSITIVE` times the other edge's component, and each of
/// the two products may itself be a flushed denormal. Two corners a denormal apart make the area
/// of a sliver of length 1e12 about 1e-33 on the mirror and 0 on an NVIDIA H200.
fn flushed_edges(edge_sum: f32) -> f32 {
    f32::MIN_POSITIVE * (2.0 * edge_sum + 2.0)
}

/// Widest change of `f(uv_area2, world_area2)` when each area moves within its error bound; `f` is
/// monotonic in each area, so the extremes lie at the corners. Evaluated in f64.
pub fn area_corners(p: [Vec3; 3], uv: [Vec2; 3], f: impl Fn(f64, f64) -> f64) -> f32 {
    let uv_area = f64::from(rc::triangle_uv_area2(uv[0], uv[1], uv[2]));
    let world_area = f64::from(rc::triangle_world_area2(p[0], p[1], p[2]));
    let (uv_err, world_err) = (f64::from(uv_area2_error(uv)), f64::from(world_area2_error(p)));
    let centre = f(uv_area, world_area);
    [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
        .iter()
        .map(|(a, b)| {
            (f(
                (uv_area + a * uv_err).max(0.0),
                (world_area + b * world_err).max(0.0),
            ) - centre)
                .abs()
        })
        .fold(0.0, f64::max) as f32
}

/// Whether both doubled areas of a triangle are known to
/// [`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED) of themselves ([`world_area2_error`],
/// [`uv_area2_error`]); an area computed exactly, a repeated vertex's 0 among them, is. A quotient
/// of the areas is ill-conditioned elsewhere: a device that fuses the cross product's multiply and
/// subtraction leaves a residual area of a repeated vertex that depends on the vertex order.
fn areas_known(&(p0, p1, p2, uv0, uv1, uv2): &TriangleWithUvs) -> bool {
    let known = |area: f32, error: f32| f64::from(error) <= WELL_CONDITIONED * f64::from(area);
    known(
        rc::triangle_world_area2(p0, p1, p2),
        world_area2_error([p0, p1, p2]),
    ) && known(
        rc::triangle_uv_area2(uv0, uv1, uv2),
        uv_area2_error([uv0, uv1, uv2]),
    )
}

/// `texel_density`'s and `triangle_base_lod`'s rotation: the corners turned, the same result,
/// where both areas are known ([`areas_known`]).
pub(crate) fn corners_turned() -> Symmetry<TriangleWithUvs, f32> {
    Symmetry::rotation(
        "the corners turned, where both areas are known to 2^-10: the same",
        |&(p0, p1, p2, uv0, uv1, uv2): &TriangleWithUvs, r| (r * p0, r * p1, r * p2, uv0, uv1, uv2),
        |value: f32, _| value,
    )
    .within(areas_known)
}

/// `texel_density`'s and `triangle_base_lod`'s translation: the corners moved, the same result.
pub(crate) fn corners_moved() -> Symmetry<TriangleWithUvs, f32> {
    Symmetry::translation(
        "the corners moved: the same",
        |&(p0, p1, p2, uv0, uv1, uv2): &TriangleWithUvs, t| (p0 + t, p1 + t, p2 + t, uv0, uv1, uv2),
        |value: f32, _| value,
    )
}

/// `texel_density`'s and `triangle_base_lod`'s exchange: the vertex order turned, the same result,
/// where both areas are known ([`areas_known`]).
pub(crate) fn vertex_order_turned() -> Symmetry<TriangleWithUvs, f32> {
    Symmetry::exchange(
        "the vertex order turned, where both areas are known to 2^-10: the same",
        |&(p0, p1, p2, uv0, uv1, uv2): &TriangleWithUvs| (p1, p2, p0, uv1, uv2, uv0),
        |value: f32| value,
    )
    .within(areas_known)
}

/// A triangle's vertices ([`triangle`]), then its UVs ([`uv_triangle`]), as six arguments.
pub(crate) fn triangle_with_uvs() -> BoxedStrategy<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2)> {
    (triangle(), uv_triangle())
        .prop_map(|(p, uv)| (p[0], p[1], p[2], uv[0], uv[1], uv[2]))
        .boxed()
}

/// A triangle's vertices and UVs, the arguments of `texel_density` and `triangle_base_lod`.
pub(crate) type TriangleWithUvs = (Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

/// A zero-area triangle (a repeated vertex) with the unit right triangle's UVs.
pub(crate) const ZERO_AREA: TriangleWithUvs = (Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec2::ZERO, Vec2::X, Vec2::Y);

/// The unit right triangle with collinear UVs.
pub(crate) const COLLINEAR_UVS: TriangleWithUvs = (
    Vec3::ZERO,
    Vec3::X,
    Vec3::Y,
    Vec2::ZERO,
    Vec2::splat(0.5),
    Vec2::ONE,
);

/// A zero-area triangle with collinear UVs.
pub(crate) const ZERO_AREA_AND_COLLINEAR_UVS: TriangleWithUvs = (
    Vec3::ZERO,
    Vec3::X,
    Vec3::ZERO,
    Vec2::ZERO,
    Vec2::splat(0.5),
    Vec2::ONE,
);

/// A unit normal and a unit direction meeting it at `|cos|` from 1e-3 to 1, from either side.
pub(crate) fn surface_hit() -> BoxedStrategy<(DVec3, DVec3)> {
    let cosine = prop_oneof![2 => 0.05f64..1.0, 1 => log_uniform(-3.0, 0.0)];
    (unit(), cosine, 0.0f64..6.3, any::<bool>())
        .prop_map(|(n, cosine, angle, behind)| {
            let d = towards(n, cosine, angle);
            (n, if behind { -d } else { d })
        })
        .boxed()
}

/// The length of the footprint that a cone of width `width` around the direction `d` leaves on
/// the plane with normal `n` through the hit: its two boundary rays, `width` apart across `d` in
/// the plane of `d` and `n`, intersected with the plane.
pub(crate) fn slanted_footprint(width: f64, n: DVec3, d: DVec3) -> f64 {
    let across = (n - d * n.dot(d))
        .try_normalize()
        .unwrap_or_else(|| d.any_orthonormal_vector());
    let hit = |side: f64| plane_hit(across * (side * 0.5 * width), d, DVec3::ZERO, n);
    (hit(1.0) - hit(-1.0)).length()
}

/// The relative error of `|dot(n, d)|` in f32 against the cosine of the unit vectors' angle: the
/// dot product's rounding (`gamma(3)` of its terms) and the inputs' distance from unit length.
pub(crate) fn cosine_error(n: Vec3, d: Vec3) -> f64 {
    let terms = (n.as_dvec3() * d.as_dvec3()).abs().element_sum();
    let cosine = n.as_dvec3().normalize().dot(d.as_dvec3().normalize()).abs();
    gamma(3) * terms / cosine + unit_excess(n, d)
}

/// How far a doubled triangle area moves when its corners move by `deltas`, the sides opposite
/// them being `sides` long: `sum delta_i side_i + 3 max delta^2` (each corner moves the area by at
/// most its displacement times the opposite side, and the products of two displacements add the
/// rest).
fn moved(deltas: [f64; 3], sides: [f64; 3]) -> f64 {
    let largest = deltas.iter().copied().fold(0.0, f64::max);
    deltas.iter().zip(sides).map(|(d, side)| d * side).sum::<f64>() + 3.0 * largest * largest
}

/// A triangle in a random plane mapped to UV by the affine map `uv = M q + o` of its in-plane
/// coordinates `q`: its texel density is `sqrt(|det M|)` whatever the triangle.
#[derive(Clone, Debug)]
pub(crate) struct Mapped {
    points: [DVec3; 3],
    uvs: [DVec2; 3],
    pub(crate) map: DMat2,
}

impl Mapped {
    pub(crate) fn strategy() -> BoxedStrategy<Mapped> {
        let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
        let entry = || prop_oneof![4 => -2.0f64..2.0, 1 => signed_log(-3.0, 3.0)];
        (
            (corner(), corner(), corner()),
            log_uniform(-3.0, 3.0),
            (
                (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
                unit(),
                0.0f64..6.3,
            ),
            (entry(), entry(), entry(), entry()),
            (-5.0f64..5.0, -5.0f64..5.0),
        )
            .prop_map(
                |((a, b, c), size, ((x, y, z), normal, angle), (m00, m01, m10, m11), (ox, oy))| {
                    // The triangle lies within 10 of its own size from the origin, its UVs within 5
                    // of their own size: every input keeps its precision relative to the triangle.
                    let u = crate::exact::tangent(normal, angle);
                    let v = normal.cross(u);
                    let centre = DVec3::new(x, y, z) * size;
                    let q = [a, b, c].map(|q| q * size);
                    let map = DMat2::from_cols(DVec2::new(m00, m10), DVec2::new(m01, m11));
                    let uv_size = size * (m00.abs() + m01.abs() + m10.abs() + m11.abs());
                    Mapped {
                        points: q.map(|q| centre + u * q.x + v * q.y),
                        uvs: q.map(|q| map * q + DVec2::new(ox, oy) * uv_size),
                        map,
                    }
                },
            )
            .prop_filter("a triangle of (nearly) no area", |mapped| {
                let edges = |p: [DVec3; 3]| (p[1] - p[0]).length() * (p[2] - p[0]).length();
                heron_area2(mapped.points) > 1.0e-3 * edges(mapped.points)
                    && mapped.map.determinant().abs()
                        > 1.0e-3 * mapped.map.to_cols_array().iter().map(|m| m * m).sum::<f64>()
            })
            .boxed()
    }

    /// The f32 arguments: corners and UVs.
    pub(crate) fn arguments(&self) -> (Vec3, Vec3, Vec3, Vec2, Vec2, Vec2) {
        let [p0, p1, p2] = self.points.map(DVec3::as_vec3);
        let [t0, t1, t2] = self.uvs.map(DVec2::as_vec2);
        (p0, p1, p2, t0, t1, t2)
    }

    /// The exact doubled areas `(uv, world)` and the bounds of the f32 ones' errors: the corners
    /// rounded to f32 move a doubled area by at most `sum |delta_i| |opposite edge_i| + 3 max
    /// |delta|^2`, and the mirror's own rounding adds `gamma(6) (|e1| |e2| + area)` (world, as in
    /// `triangle_world_area2`) or `gamma(4) |g1| |g2|` (UV).
    pub(crate) fn areas(&self) -> ((f64, f64), (f64, f64)) {
        let (p0, p1, p2, t0, t1, t2) = self.arguments();
        let world = heron_area2(self.points);
        let uv = (self.map.determinant() * world).abs();
        let world_moved = moved(
            [0, 1, 2].map(|i| ([p0, p1, p2][i].as_dvec3() - self.points[i]).length()),
            [0, 1, 2].map(|i| (self.points[(i + 2) % 3] - self.points[(i + 1) % 3]).length()),
        );
        let uv_moved = moved(
            [0, 1, 2].map(|i| ([t0, t1, t2][i].as_dvec2() - self.uvs[i]).length()),
            [0, 1, 2].map(|i| (self.uvs[(i + 2) % 3] - self.uvs[(i + 1) % 3]).length()),
        );
        let e = (self.points[1] - self.points[0]).length() * (self.points[2] - self.points[0]).length();
        let g = (self.uvs[1] - self.uvs[0]).length() * (self.uvs[2] - self.uvs[0]).length();
        (
            (uv, uv_moved + gamma(4) * g),
            (world, world_moved + gamma(6) * (e + world)),
        )
    }

    /// The largest change of `f(uv_area2, world_area2)` with each area moved within its error;
    /// `f` is monotonic in each, so at the corners.
    pub(crate) fn corners(&self, f: impl Fn(f64, f64) -> f64) -> f64 {
        let ((uv, uv_error), (world, world_error)) = self.areas();
        let centre = f(uv, world);
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
            .iter()
            .map(|(a, b)| {
                (f((uv + a * uv_error).max(0.0), (world + b * world_error).max(0.0)) - centre).abs()
            })
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Corners a denormal apart, as an NVIDIA H200 sees them: the edge between them flushed to zero
    /// (the same corner twice) gives an area within the bound of the mirror's, which keeps the
    /// denormal.
    #[test]
    fn a_flushed_denormal_edge_is_within_the_area_bound() {
        let within = |kept: f32, flushed: f32, bound: f32| {
            assert!(
                kept > 0.0 && flushed == 0.0,
                "the mirror keeps {kept}, flushing gives {flushed}"
            );
            assert!(
                (kept - flushed).abs() <= bound,
                "{kept} against the bound {bound}"
            );
        };
        let p0 = Vec3::new(-1.1754945e-38, -1.0e-4, 1.0e12);
        let p1 = Vec3::splat(-10.0);
        let p2 = Vec3::new(-1.1754944e-38, -1.0e-4, 1.0e12);
        within(
            rc::triangle_world_area2(p0, p1, p2),
            rc::triangle_world_area2(p0, p1, p0),
            world_area2_error([p0, p1, p2]),
        );
        let (uv0, uv1) = (Vec2::new(1.0, -1.1754945e-38), Vec2::new(1.0e6, 3.0));
        let uv2 = Vec2::new(1.0, -1.1754944e-38);
        within(
            rc::triangle_uv_area2(uv0, uv1, uv2),
            rc::triangle_uv_area2(uv0, uv1, uv0),
            uv_area2_error([uv0, uv1, uv2]),
        );
    }
}
