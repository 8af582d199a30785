//! References of the re-intersection section: the rays intersected with the triangle's plane as a
//! 3x3 system in f64, the neighbour rays taken to object space by the matrix's linear part (no
//! cancellation), and texture coordinates of an affine map of the plane.

use super::super::strategy::{plane_intersections, well_conditioned_offset_args, F32_ORIGIN_EXPONENT};
use super::super::{enclosure, OffsetArgs};
use super::{components, listed, widths};
use crate::exact::{log_uniform, tangent, triangle_hit, unit};
use crate::reference::{gamma, Kind, Reference};
use glam::{DMat2, DMat3, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, DIFF_MAX_VALUE};
use shader_proptest::interval::{interval3, Interval3};

/// Whether barycentrics lie inside `[-limit, limit]`, the range the functions clamp to (with a
/// margin).
pub(crate) fn unclamped(b: DVec3, limit: f64) -> bool {
    b.abs().max_element() < 0.99 * limit
}

/// `rf_intersect_triangle_plane`.
pub(in crate::ray_diff) fn intersect_triangle_plane() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "origin + s direction = p0 + u e1 + v e2 solved as a 3x3 system in f64 (the matrix inverted), over the whole domain's origins, directions and triangles (RTG Eq. 13)",
        plane_intersections,
        |&(o, d, p0, p1, p2), intersect_triangle_plane| {
            let (expected, _) = triangle_hit(o.as_dvec3(), d.as_dvec3(), [p0, p1, p2].map(Vec3::as_dvec3));
            if !unclamped(expected, f64::from(DIFF_MAX_VALUE)) {
                return None;
            }
            let got = intersect_triangle_plane((o, d, p0, p1, p2));
            let rounding = enclosure::intersect_triangle_plane(interval3(o), interval3(d), interval3(p0), interval3(p1), interval3(p2));
            let bounds = widths(&rounding.components());
            // The f64 inverse: relative 1e-9 of the largest coordinate, far below f32's rounding.
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.abs().max_element()))
        },
    )
}

/// The exact offsets `(b_x - b, b_y - b)` of the re-intersection: the world origin and the
/// neighbour directions taken to object space in f64 (the direction by the matrix's linear part,
/// so `T(O + d) - T(O)` cancels nothing), intersected with the triangle's plane; `None` where a
/// neighbour's barycentrics leave `[-limit, limit]`.
pub(crate) fn exact_offsets(
    &(world_to_object, origin, p0, p1, p2, dir_x, dir_y, hit): &OffsetArgs,
    limit: f64,
) -> Option<[DVec3; 2]> {
    let matrix = world_to_object.as_dmat4();
    let object_origin = matrix.transform_point3(origin.as_dvec3());
    let linear = DMat3::from_mat4(matrix);
    let p = [p0, p1, p2].map(Vec3::as_dvec3);
    let offset = |direction: Vec3| {
        let (b, _) = triangle_hit(object_origin, linear * direction.as_dvec3(), p);
        unclamped(b, limit).then(|| b - hit.as_dvec3())
    };
    Some([offset(dir_x)?, offset(dir_y)?])
}

/// The enclosures of the two offsets.
fn offset_enclosures(args: &OffsetArgs) -> (Interval3, Interval3) {
    enclosure::barycentric_offsets(args)
}

/// `rf_barycentric_offsets`.
pub(in crate::ray_diff) fn barycentric_offsets() -> Reference<OffsetArgs, Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays taken to object space by the f64 matrix (the direction by its linear part, cancelling nothing) and intersected with the triangle's plane as a 3x3 system in f64, minus the hit's barycentrics",
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |args, barycentric_offsets| {
            let [dx, dy] = exact_offsets(args, f64::from(DIFF_MAX_VALUE))?;
            let got = barycentric_offsets(*args);
            let (x, y) = offset_enclosures(args);
            let bounds = widths(&[x.components(), y.components()].concat());
            let scale = dx.abs().max_element().max(dy.abs().max_element());
            Some(components(got, &listed(&[dx, dy], 0), |i| bounds[i] + 1.0e-9 * scale))
        },
    )
}

/// `rf_barycentric_deltas`.
pub(in crate::ray_diff) fn barycentric_deltas() -> Reference<OffsetArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "|b_x - b| + |b_y - b| of the exact offsets (neighbour rays taken to object space by the f64 matrix's linear part and intersected in f64)",
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |args, barycentric_deltas| {
            let [dx, dy] = exact_offsets(args, f64::from(DIFF_MAX_VALUE))?;
            let got = barycentric_deltas(*args);
            let (x, y) = offset_enclosures(args);
            let bounds = widths(&(x.abs() + y.abs()).components());
            let expected = dx.abs() + dy.abs();
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-9 * expected.max_element()))
        },
    )
}

/// A triangle in a random plane with the UVs of an affine map of the plane, a point in it and
/// two neighbour points in the plane.
#[derive(Clone, Debug)]
struct Mapped {
    corners: [Vec3; 3],
    axes: [DVec3; 2],
    map: DMat2,
    offset: DVec2,
    point: DVec3,
    neighbours: [DVec3; 2],
}

impl Mapped {
    fn strategy() -> BoxedStrategy<Mapped> {
        let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
        let step = || (0.0f64..6.3, log_uniform(-4.0, 0.0)).prop_map(|(a, l)| DVec2::from_angle(a) * l);
        (
            (
                (corner(), corner(), corner()),
                (unit(), 0.0f64..6.3),
                (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
            ),
            (
                (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0),
                (-2.0f64..2.0, -2.0f64..2.0),
            ),
            (corner(), step(), step()),
        )
            .prop_map(|((q, (normal, roll), (x, y, z)), (m, o), (at, sx, sy))| {
                let u = tangent(normal, roll);
                let v = normal.cross(u);
                let centre = DVec3::new(x, y, z);
                let place = |q: DVec2| centre + u * q.x + v * q.y;
                Mapped {
                    corners: [q.0, q.1, q.2].map(|q| place(q).as_vec3()),
                    axes: [u, v],
                    map: DMat2::from_cols(DVec2::new(m.0, m.2), DVec2::new(m.1, m.3)),
                    offset: DVec2::new(o.0, o.1),
                    point: place(at),
                    neighbours: [place(at + sx), place(at + sy)],
                }
            })
            .prop_filter("a sliver", |mapped| {
                let p = mapped.corners.map(Vec3::as_dvec3);
                let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
                e1.cross(e2).length() > 0.1 * e1.length() * e2.length()
            })
            .boxed()
    }

    /// The texture coordinates of a point: the affine map of its in-plane coordinates.
    fn uv(&self, point: DVec3) -> DVec2 {
        self.map * DVec2::new(point.dot(self.axes[0]), point.dot(self.axes[1])) + self.offset
    }

    /// The barycentrics of a point of the (f32 corners') plane: the ray along the normal through it.
    fn barycentrics(&self, point: DVec3) -> DVec3 {
        let p = self.corners.map(Vec3::as_dvec3);
        let normal = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
        triangle_hit(point + normal, -normal, p).0
    }
}

/// `rf_uv_gradients_from_offsets`.
pub(in crate::ray_diff) fn uv_gradients_from_offsets(
) -> Reference<(Derivatives3, Vec2, Vec2, Vec2), Derivatives2> {
    Reference::new(
        Kind::ExactGeometry,
        "the texture coordinates, under an affine map of the plane, of the neighbour hits minus the hit's, computed from the points themselves; the offsets are the points' exact barycentrics minus the hit's",
        Mapped::strategy,
        |mapped, uv_gradients_from_offsets| {
            let b = mapped.barycentrics(mapped.point);
            let offsets = mapped.neighbours.map(|q| mapped.barycentrics(q) - b);
            let input = Derivatives3::new(offsets[0].as_vec3(), offsets[1].as_vec3());
            let uvs = mapped.corners.map(|p| mapped.uv(p.as_dvec3()).as_vec2());
            let got = uv_gradients_from_offsets((input, uvs[0], uvs[1], uvs[2]));
            // The points of the f32 corners' plane: the neighbours' UV change under the map.
            let expected: Vec<f64> = mapped
                .neighbours
                .iter()
                .flat_map(|&q| (mapped.uv(q) - mapped.uv(mapped.point)).to_array())
                .collect();
            // sum_i delta_i uv_i: the offsets' and the UVs' rounding (u each) and the three
            // products and two sums (gamma(3)) of the terms; the corners' f32 plane differs
            // from the map's by their rounding, which the UVs carry (gamma(2) of the UVs' size).
            let sizes = uvs.map(|uv| f64::from(uv.length()));
            let terms = |d: DVec3| d.abs().to_array().iter().zip(sizes).map(|(a, b)| a * b).sum::<f64>();
            let bounds = [terms(offsets[0]), terms(offsets[1])].map(|t| gamma(6) * t + 1.0e-9 * t);
            Some(components(got, &expected, |i| bounds[i / 2]))
        },
    )
}
