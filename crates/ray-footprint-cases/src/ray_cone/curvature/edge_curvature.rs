//! The proof of [`edge_curvature`](ray_footprint::ray_cone::edge_curvature): its record and its
//! reference.

use crate::degenerate::value;
use crate::ray_cone::curvature::shared::{chord_error, edge_curvature_error, Curved};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{small_vec3, vec3};
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_edge_curvature`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "edge_curvature",
        |(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j),
        || (vec3(), vec3(), small_vec3(), small_vec3()).boxed(),
    )
    .bound(|&(p_i, p_j, n_i, n_j), _, _| edge_curvature_error(p_i, p_j, n_i, n_j))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the positions scaled by s: the curvature by 1/s",
        |&(p_i, p_j, n_i, n_j), s| (p_i * s, p_j * s, n_i, n_j),
        |curvature, s| curvature * s,
    ))
    .symmetry(Symmetry::rotation(
        "positions and normals turned: the same",
        |&(p_i, p_j, n_i, n_j), r| (r * p_i, r * p_j, r * n_i, r * n_j),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::translation(
        "the positions moved: the same",
        |&(p_i, p_j, n_i, n_j), t| (p_i + t, p_j + t, n_i, n_j),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "the edge's ends exchanged: the same",
        |&(p_i, p_j, n_i, n_j)| (p_j, p_i, n_j, n_i),
        |curvature| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "the normals flipped: the curvature negated",
        |&(p_i, p_j, n_i, n_j)| (p_i, p_j, -n_i, -n_j),
        |curvature: f32| -curvature,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.unit(), d.unit()))
    .degenerate(vec![
        value("zero-length edge", "0", (x, x, z, x), vec![0.0]),
        value(
            "edge of length 1e-19 (|edge|^2 below MIN_SQUARED_MAGNITUDE)",
            "dot(n_j - n_i, edge) / MIN_SQUARED_MAGNITUDE",
            (Vec3::ZERO, Vec3::new(1.0e-19, 0.0, 0.0), Vec3::ZERO, x),
            vec![1.0e-19 / MIN_SQUARED_MAGNITUDE],
        ),
        value(
            "edge of the unit sphere (p = n: x, then y)",
            "1 (1 / R)",
            (x, Vec3::Y, x, Vec3::Y),
            vec![1.0],
        ),
        value("equal normals (flat)", "0", (Vec3::ZERO, x, z, z), vec![0.0]),
        value(
            "edge of length 1e-12 along x, the normal turning by x",
            "1e12: the squared length 1e-24 is above MIN_SQUARED_MAGNITUDE",
            (Vec3::ZERO, Vec3::new(1.0e-12, 0.0, 0.0), Vec3::ZERO, x),
            vec![1.0e-12 / (1.0e-12 * 1.0e-12)],
        ),
    ])
}

/// The reference of `rf_edge_curvature`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "chords of spheres and cylinders with exact vertex normals (outward or inward): 1 / R on a sphere, (1 - (axis . chord)^2) / R on a cylinder (JCGT 2021 Sec. 3; Euler's formula), negated for inward normals",
        || Curved::strategy(2),
        |curved, edge_curvature| {
            let [p_i, p_j] = [0, 1].map(|i| curved.points[i].as_vec3());
            let [n_i, n_j] = [0, 1].map(|i| curved.normals[i].as_vec3());
            let got = edge_curvature((p_i, p_j, n_i, n_j));
            let expected = curved.chord_curvature(0, 1);
            Some(Deviation::within(f64::from(got), expected, chord_error(p_i, p_j, n_i, n_j, expected)))
        },
    )
}
