//! The proof of [`edge_position`](ray_footprint::wireframe::edge_position): its record and its
//! reference.

use crate::degenerate::{mirror, value, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{one_argument, vec3};
use crate::symmetry::Symmetry;
use crate::wireframe::coverage::shared::barycentrics;
use glam::{Vec3, Vec3Swizzles};
use ray_footprint::shaders::Module;
use ray_footprint::wireframe as wf;
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// The record of `rf_edge_position`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    // max is exact.
    Record::new(
        Module::Wireframe,
        "edge_position",
        |(b,)| wf::edge_position(b),
        || one_argument(one_of![3 => barycentrics(), 1 => vec3()]),
    )
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the vertex order turned (barycentrics rotated): the same",
        |&(b,): &(Vec3,)| (b.yzx(),),
        |e: f32| e,
    ))
    .symmetry(Symmetry::exchange(
        "two vertices exchanged: the same",
        |&(b,): &(Vec3,)| (b.yxz(),),
        |e: f32| e,
    ))
    .fuzz(|d| (d.vec3(),))
    .promise(|&(b,), e, promises| promises.within(e - b.max_element(), 0.0, 0.0, "edge position - max(b)"))
    .degenerate(vec![
        mirror(
            "NaN in (b.x)",
            "CPU: max(b.y, b.z) (Rust's `max` ignores NaN)",
            (Vec3::new(NAN, 0.2, 0.3),),
            vec![0.3],
        ),
        value("at a vertex (0, 1, 0)", "1", (Vec3::Y,), vec![1.0]),
        value(
            "at the centroid (1/3 each)",
            "1/3",
            (Vec3::splat(1.0 / 3.0),),
            vec![1.0 / 3.0],
        ),
        value(
            "outside the triangle (-0.5, 0.75, 0.75)",
            "0.75, the largest component",
            (Vec3::new(-0.5, 0.75, 0.75),),
            vec![0.75],
        ),
    ])
}

/// The reference of `rf_edge_position`.
fn reference() -> Reference<(Vec3,), f32> {
    Reference::new(
        Kind::Identity,
        "the last of the three barycentrics sorted in f64, the same for all six orders of them",
        barycentrics,
        |&b, edge_position| {
            let mut sorted = b.as_dvec3().to_array();
            sorted.sort_by(f64::total_cmp);
            let orders = [b, b.yzx(), b.zxy(), b.xzy(), b.zyx(), b.yxz()];
            // A selection of one of its arguments: exact.
            Some(Deviation::worst(orders.map(|order| {
                Deviation::within(f64::from(edge_position((order,))), sorted[2], 0.0)
            })))
        },
    )
}
