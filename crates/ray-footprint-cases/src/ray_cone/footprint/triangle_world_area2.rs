//! The proof of [`triangle_world_area2`](ray_footprint::ray_cone::triangle_world_area2): its record and
//! its reference, Heron's formula.

use crate::degenerate::{mirror, value, INF, NAN};
use crate::exact::heron_area2;
use crate::ray_cone::footprint::shared::world_area2_error;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::triangle;
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_triangle_world_area2`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    Record::new(
        Module::RayCone,
        "triangle_world_area2",
        |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
        || triangle().prop_map(|p| (p[0], p[1], p[2])).boxed(),
    )
    .bound(|&(p0, p1, p2), _, _| world_area2_error([p0, p1, p2]))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the corners scaled by s: the area by s^2",
        |&(p0, p1, p2): &(Vec3, Vec3, Vec3), s| (p0 * s, p1 * s, p2 * s),
        |area: f32, s| area / (s * s),
    ))
    .symmetry(Symmetry::rotation(
        "the corners turned: the same",
        |&(p0, p1, p2): &(Vec3, Vec3, Vec3), r| (r * p0, r * p1, r * p2),
        |area: f32, _| area,
    ))
    .symmetry(Symmetry::translation(
        "the corners moved: the same",
        |&(p0, p1, p2): &(Vec3, Vec3, Vec3), t| (p0 + t, p1 + t, p2 + t),
        |area: f32, _| area,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned: the same",
        |&(p0, p1, p2): &(Vec3, Vec3, Vec3)| (p1, p2, p0),
        |area: f32| area,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3()))
    .range(0.0, f32::MAX, "area")
    .degenerate(vec![
        value(
            "zero-area triangle (repeated vertex)",
            "0",
            (Vec3::ZERO, x, Vec3::ZERO),
            vec![0.0],
        ),
        value(
            "zero-area triangle (collinear vertices)",
            "0",
            (Vec3::ZERO, Vec3::ONE, Vec3::splat(2.0)),
            vec![0.0],
        ),
        mirror(
            "infinity in",
            "CPU: NaN (inf - inf in the cross product)",
            (Vec3::splat(INF), x, Vec3::Y),
            vec![NAN],
        ),
    ])
}

/// The reference of `rf_triangle_world_area2`.
fn reference() -> Reference<(Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ClosedForm,
        "Heron's formula (Kahan's stable form) from the three side lengths in f64, over ordinary, huge, tiny, sliver and degenerate triangles",
        triangle,
        |&[p0, p1, p2], triangle_world_area2| {
            let got = triangle_world_area2((p0, p1, p2));
            let exact = heron_area2([p0, p1, p2].map(Vec3::as_dvec3));
            // The edges round (u each, 2 u |e1| |e2| in the cross product), each cross component
            // a b - c d by gamma(2) (|a b| + |c d|) (at most sqrt(2) gamma(2) |e1| |e2| in all),
            // the scaled length by gamma(5) of the result.
            let (e1, e2) = ((p1 - p0).as_dvec3(), (p2 - p0).as_dvec3());
            let bound = gamma(6) * (e1.length() * e2.length() + exact);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}
