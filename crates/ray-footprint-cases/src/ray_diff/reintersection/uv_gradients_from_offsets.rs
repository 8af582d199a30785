//! The proof of [`uv_gradients_from_offsets`](ray_footprint::ray_diff::uv_gradients_from_offsets):
//! its record and its reference.

use crate::degenerate::value;
use crate::exact::{log_uniform, tangent, triangle_hit, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::components;
use crate::ray_diff::strategy::derivatives3;
use crate::record::Record;
use crate::reference::{gamma, Kind, Reference};
use crate::strategy::{uv_triangle, with_corners};
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, DIFF_MAX_VALUE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval2, Interval};

/// The record of `rf_uv_gradients_from_offsets`: the enclosure of the UV gradients.
pub fn record() -> Record<(Derivatives3, Vec2, Vec2, Vec2), Derivatives2> {
    let max = DIFF_MAX_VALUE;
    Record::new(
        Module::RayDiff,
        "uv_gradients_from_offsets",
        |(o, uv0, uv1, uv2)| rd::uv_gradients_from_offsets(o, uv0, uv1, uv2),
        || with_corners(derivatives3(), uv_triangle()),
    )
    .enclosure(|&(o, uv0, uv1, uv2)| {
        let sum = |w: Vec3| {
            interval2(uv0) * Interval::exact(w.x)
                + interval2(uv1) * Interval::exact(w.y)
                + interval2(uv2) * Interval::exact(w.z)
        };
        intervals::derivatives2(sum(o.dx), sum(o.dy))
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the gradients exchanged",
        |&(o, uv0, uv1, uv2): &(Derivatives3, Vec2, Vec2, Vec2)| (swapped3(o), uv0, uv1, uv2),
        swapped2,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (the offsets' components with it): the same",
        |&(o, uv0, uv1, uv2): &(Derivatives3, Vec2, Vec2, Vec2)| {
            (Derivatives3::new(o.dx.yzx(), o.dy.yzx()), uv1, uv2, uv0)
        },
        |g: Derivatives2| g,
    ))
    .symmetry(Symmetry::scale(
        "the UVs scaled by s: the gradients by s",
        |&(o, uv0, uv1, uv2): &(Derivatives3, Vec2, Vec2, Vec2), s| (o, uv0 * s, uv1 * s, uv2 * s),
        |g: Derivatives2, s| Derivatives2::new(g.dx / s, g.dy / s),
    ))
    .fuzz(|d| (d.derivatives3(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        value(
            "zero offsets",
            "0",
            (Derivatives3::default(), Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.0; 4],
        ),
        value(
            "offsets summing to 0, all UVs equal",
            "0: the UV does not change",
            (
                Derivatives3::new(Vec3::new(0.5, -0.25, -0.25), Vec3::new(-1.0, 0.5, 0.5)),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
                Vec2::splat(0.5),
            ),
            vec![0.0; 4],
        ),
        value(
            "clamped offsets (+-DIFF_MAX_VALUE), UVs in [0, 1]",
            "finite: (-DIFF_MAX_VALUE, 0) towards the right neighbour",
            (
                Derivatives3::new(Vec3::new(max, -max, 0.0), Vec3::ZERO),
                Vec2::ZERO,
                Vec2::X,
                Vec2::Y,
            ),
            vec![-max, 0.0, 0.0, 0.0],
        ),
    ])
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

/// The reference of `rf_uv_gradients_from_offsets`.
fn reference() -> Reference<(Derivatives3, Vec2, Vec2, Vec2), Derivatives2> {
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
