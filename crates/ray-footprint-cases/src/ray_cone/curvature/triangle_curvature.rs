//! The proof of [`triangle_curvature`](ray_footprint::ray_cone::triangle_curvature): its record, its
//! error bound and its reference.

use crate::degenerate::value;
use crate::ray_cone::curvature::shared::{chord_error, edge_curvature_error, Curved};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{small_vec3, triangle};
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The record of `rf_triangle_curvature`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "triangle_curvature",
        |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
        || {
            (triangle(), (small_vec3(), small_vec3(), small_vec3()))
                .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                .boxed()
        },
    )
    .bound(|&(p0, p1, p2, n0, n1, n2), _, _| triangle_curvature_error([p0, p1, p2], [n0, n1, n2]))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the corners scaled by s: the curvature by 1/s",
        |&(p0, p1, p2, n0, n1, n2), s| (p0 * s, p1 * s, p2 * s, n0, n1, n2),
        |curvature, s| curvature * s,
    ))
    .symmetry(Symmetry::rotation(
        "corners and normals turned: the same",
        |&(p0, p1, p2, n0, n1, n2), r| (r * p0, r * p1, r * p2, r * n0, r * n1, r * n2),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::translation(
        "the corners moved: the same",
        |&(p0, p1, p2, n0, n1, n2), t| (p0 + t, p1 + t, p2 + t, n0, n1, n2),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned (0, 1, 2 -> 1, 2, 0): the same",
        |&(p0, p1, p2, n0, n1, n2)| (p1, p2, p0, n1, n2, n0),
        |curvature| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "the normals flipped: the curvature negated",
        |&(p0, p1, p2, n0, n1, n2)| (p0, p1, p2, -n0, -n1, -n2),
        |curvature: f32| -curvature,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero-area triangle (p2 = p0)",
            "the mean of the two real edges' curvatures (the zero edge counts 0): 2/3 here",
            (Vec3::ZERO, x, Vec3::ZERO, z, x, z),
            vec![(1.0 + 1.0 + 0.0) / 3.0],
        ),
        value(
            "flat (equal vertex normals)",
            "0",
            (Vec3::ZERO, x, Vec3::Y, z, z, z),
            vec![0.0],
        ),
        value(
            "vertices and outward normals x, y, z of the unit sphere",
            "1 (each edge 1 / R)",
            (x, Vec3::Y, z, x, Vec3::Y, z),
            vec![1.0],
        ),
        value(
            "all three vertices at one point",
            "0 (three zero-length edges)",
            (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, z, x, Vec3::Y),
            vec![0.0],
        ),
    ])
}

/// Error of [`rc::triangle_curvature`] of the corners `p` and normals `n`: the three edges'
/// `edge_curvature_error`s, then two additions and a division by 3 (5 ULP of the sum of the
/// edges' magnitudes), all divided by 3.
fn triangle_curvature_error(p: [Vec3; 3], n: [Vec3; 3]) -> f32 {
    let edges = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| (p[i], p[j], n[i], n[j]));
    let errors: f32 = edges
        .iter()
        .map(|&(p_i, p_j, n_i, n_j)| edge_curvature_error(p_i, p_j, n_i, n_j))
        .sum();
    let sizes: f32 = edges
        .iter()
        .map(|&(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j).abs())
        .sum();
    (errors + ulps(5.0, sizes)) / 3.0
}

/// The reference of `rf_triangle_curvature`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles inscribed in spheres and cylinders with exact vertex normals: the mean of the three chords' exact curvatures (1 / R on a sphere, JCGT 2021)",
        || Curved::strategy(3),
        |curved, triangle_curvature| {
            let p = [0, 1, 2].map(|i| curved.points[i].as_vec3());
            let n = [0, 1, 2].map(|i| curved.normals[i].as_vec3());
            let got = triangle_curvature((p[0], p[1], p[2], n[0], n[1], n[2]));
            let edges = [(0, 1), (1, 2), (2, 0)];
            let expected = edges.iter().map(|&(i, j)| curved.chord_curvature(i, j)).sum::<f64>() / 3.0;
            // The three edges' errors, then two sums and a division by 3 (gamma(3) of the sum of
            // their magnitudes).
            let errors: f64 = edges
                .iter()
                .map(|&(i, j)| chord_error(p[i], p[j], n[i], n[j], curved.chord_curvature(i, j)))
                .sum();
            let sizes: f64 = edges.iter().map(|&(i, j)| curved.chord_curvature(i, j).abs()).sum();
            let bound = (errors + gamma(3) * sizes) / 3.0;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
