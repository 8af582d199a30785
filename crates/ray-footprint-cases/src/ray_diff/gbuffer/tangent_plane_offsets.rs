//! The proof of [`tangent_plane_offsets`](ray_footprint::ray_diff::tangent_plane_offsets): its
//! record, its enclosure and its reference.

use crate::degenerate::value;
use crate::exact::{log_uniform, tangent, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{distance, normal_and_direction, unit_vec3};
use glam::{DMat3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives3, DIFF_MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_tangent_plane_offsets`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    Record::new(
        Module::RayDiff,
        "tangent_plane_offsets",
        |(rd, rdx, rdy, t, n)| rd::tangent_plane_offsets(rd, rdx, rdy, t, n),
        || {
            (normal_and_direction(), (unit_vec3(), unit_vec3()), distance())
                .prop_map(|((n, rd), (rdx, rdy), t)| (rd, rdx, rdy, t, n))
                .boxed()
        },
    )
    .enclosure(|&(r, rdx, rdy, t, n)| {
        let dx = tangent_plane_offset(r, rdx, t, n);
        let dy = tangent_plane_offset(r, rdy, t, n);
        intervals::derivatives3(dx, dy)
    })
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the rays and the normal turned: the offsets turned",
        |&(rd, rdx, rdy, t, n): &(Vec3, Vec3, Vec3, f32, Vec3), r| (r * rd, r * rdx, r * rdy, t, r * n),
        |o: Derivatives3, r| turned3(o, r.transpose()),
    ))
    .symmetry(Symmetry::scale(
        "the distance scaled by s: the offsets by s",
        |&(rd, rdx, rdy, t, n): &(Vec3, Vec3, Vec3, f32, Vec3), s| (rd, rdx, rdy, t * s, n),
        |o: Derivatives3, s| Derivatives3::new(o.dx / s, o.dy / s),
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the offsets exchanged",
        |&(rd, rdx, rdy, t, n): &(Vec3, Vec3, Vec3, f32, Vec3)| (rd, rdy, rdx, t, n),
        swapped3,
    ))
    .symmetry(Symmetry::exchange(
        "the normal flipped, the neighbour rays off the surface's plane by more than DIFF_MIN_COS: the same",
        |&(rd, rdx, rdy, t, n): &(Vec3, Vec3, Vec3, f32, Vec3)| (rd, rdx, rdy, t, -n),
        |o: Derivatives3| o,
    )
    .within(|&(_, rdx, rdy, _, n)| rdx.dot(n).abs() > DIFF_MIN_COS && rdy.dot(n).abs() > DIFF_MIN_COS))
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

fn tangent_plane_offset(rd: Vec3, rd_neighbour: Vec3, t: f32, normal: Vec3) -> Interval3 {
    let (rd, rdn, n) = (interval3(rd), interval3(rd_neighbour), interval3(normal));
    let ratio = rd.dot(n).div_away(rdn.dot(n), f64::from(DIFF_MIN_COS));
    (rdn * ratio - rd) * Interval::exact(t)
}

/// The reference of `rf_tangent_plane_offsets`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, f32, Vec3), Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays from the eye intersected with the tangent plane at t rd, each solved as a 3x3 system (ray parameter and in-plane coordinates) in f64 (Quilez)",
        || {
            let offset = || (0.0f64..6.3, log_uniform(-4.0, -2.0));
            (unit(), (offset(), offset()), log_uniform(-1.0, 3.0), 0.05f64..1.0, 0.0f64..6.3).boxed()
        },
        |&(rd, ((ax, lx), (ay, ly)), t, cosine, angle), tangent_plane_offsets| {
            let neighbour = |a: f64, l: f64| (rd + tangent(rd, a) * l).normalize().as_vec3();
            let (rdx, rdy, normal) = (neighbour(ax, lx), neighbour(ay, ly), towards(rd, cosine, angle).as_vec3());
            let (rd, t) = (rd.as_vec3(), t as f32);
            let got = tangent_plane_offsets((rd, rdx, rdy, t, normal));
            let hit = rd.as_dvec3() * f64::from(t);
            let n = normal.as_dvec3();
            let (u, v) = (n.any_orthonormal_vector(), n.cross(n.any_orthonormal_vector()));
            let offset = |ray: Vec3| {
                let ray = ray.as_dvec3();
                let solution = DMat3::from_cols(ray, -u, -v).inverse() * hit;
                ray * solution.x - hit
            };
            let expected = listed(&[offset(rdx), offset(rdy)], 0);
            let rounding = [
                tangent_plane_offset(rd, rdx, t, normal).components(),
                tangent_plane_offset(rd, rdy, t, normal).components(),
            ]
            .concat();
            let bounds = widths(&rounding);
            Some(components(got, &expected, |i| bounds[i] + 1.0e-12 * hit.length()))
        },
    )
}
