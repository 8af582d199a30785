//! Records of `ray_diff`: Planar and triplanar mapping (Quilez).

use super::enclosure;
use super::strategy::derivatives3;
use super::{reference, MODULE};
use crate::degenerate::{parts, value};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{unit_vec3, vec2_of};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, TriplanarGradients, DIFF_MIN_MAGNITUDE,
};
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval2, interval3, Interval, Interval3, IntervalVec};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// `rf_planar_mapping_gradients`.
pub fn planar_mapping_gradients() -> Record<impl Args + Perturb, impl Value> {
    let y = Vec3::Y;
    Record::new(
        MODULE,
        "planar_mapping_gradients",
        |(dp, scale)| rd::planar_mapping_gradients(dp, scale),
        || {
            (
                derivatives3(),
                vec2_of(uniform(-10.0, 10.0), uniform(-10.0, 10.0)),
            )
                .boxed()
        },
    )
    .enclosure(|&(dp, scale)| {
        let project = |v: Vec3| interval2(Vec2::new(v.x, v.z)) * interval2(scale);
        enclosure::derivatives2(project(dp.dx), project(dp.dy))
    })
    .reference(reference::planar_mapping_gradients())
    .fuzz(|d| (d.derivatives3(), d.vec2()))
    .degenerate(vec![
        value(
            "zero scale",
            "0",
            (Derivatives3::new(Vec3::ONE, Vec3::ONE), Vec2::ZERO),
            vec![0.0; 4],
        ),
        value(
            "position changing along y only (normal to the mapping plane)",
            "0",
            (Derivatives3::new(y, -2.0 * y), Vec2::ONE),
            vec![0.0; 4],
        ),
        value(
            "negative scale (-1, 0.5)",
            "mirrored in u: dx = (-1, 1), dy = (0, -2)",
            (
                Derivatives3::new(Vec3::new(1.0, 0.0, 2.0), Vec3::new(0.0, 0.0, -4.0)),
                Vec2::new(-1.0, 0.5),
            ),
            vec![-1.0, 1.0, 0.0, -2.0],
        ),
    ])
}

/// `rf_triplanar_weights`.
pub fn triplanar_weights() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "triplanar_weights",
        |(normal, sharpness)| rd::triplanar_weights(normal, sharpness),
        || {
            let normal = one_of![8 => unit_vec3(), 1 => Just(Vec3::ZERO)];
            (normal, one_of![4 => uniform(0.0, 16.0), 1 => uniform(-2.0, 100.0)]).boxed()
        },
    )
    .enclosure(|&(normal, sharpness)| enclosure::triplanar_weights(normal, sharpness))
    .found(
        "inf / inf for normals longer than about 2 at high sharpness (now divided by the largest component first); found by the special-value suite",
    )
    .reference(reference::triplanar_weights())
    .fuzz(|d| (d.unit(), d.scalar()))
    .range(0.0, 1.0, "weight")
    .degenerate(vec![
        value(
            "zero normal, sharpness 1",
            "1/3 each",
            (Vec3::ZERO, 1.0),
            vec![DIFF_MIN_MAGNITUDE / (3.0 * DIFF_MIN_MAGNITUDE); 3],
        ),
        value(
            "zero normal, sharpness 4",
            "0 each (DIFF_MIN_MAGNITUDE^4 underflows)",
            (Vec3::ZERO, 4.0),
            vec![0.0; 3],
        ),
        value(
            "sharpness 0",
            "1/3 each",
            (Vec3::new(0.6, 0.0, 0.8), 0.0),
            vec![1.0 / 3.0; 3],
        ),
    ])
}

/// `rf_triplanar_gradients`.
pub fn triplanar_gradients() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    Record::new(
        MODULE,
        "triplanar_gradients",
        |(dp, scale)| rd::triplanar_gradients(dp, scale),
        || (derivatives3(), uniform(-10.0, 10.0)).boxed(),
    )
    .enclosure(|&(dp, scale)| {
        let (dx, dy) = (
            interval3(dp.dx) * Interval::exact(scale),
            interval3(dp.dy) * Interval::exact(scale),
        );
        let pick = |v: Interval3, a: usize, b: usize| IntervalVec([v.0[a], v.0[b]]);
        let planes = [(1, 2), (2, 0), (0, 1)];
        let all: Vec<Interval> = planes
            .iter()
            .flat_map(|&(a, b)| enclosure::derivatives2(pick(dx, a, b), pick(dy, a, b)))
            .collect();
        all
    })
    .reference(reference::triplanar_gradients())
    .fuzz(|d| (d.derivatives3(), d.scalar()))
    .degenerate(vec![
        value(
            "zero scale",
            "0 for every projection",
            (Derivatives3::new(Vec3::ONE, Vec3::ONE), 0.0),
            vec![0.0; 12],
        ),
        value(
            "zero position differentials",
            "0 for every projection",
            (Derivatives3::default(), 2.0),
            vec![0.0; 12],
        ),
        value(
            "dp/dx = (1, 0, 0), dp/dy = (0, 1, 0), scale 2",
            "each projection sees its own two axes: yz gets (0, 0) and (2, 0)",
            (Derivatives3::new(x, y), 2.0),
            parts(TriplanarGradients {
                yz: Derivatives2::new(Vec2::ZERO, Vec2::new(2.0, 0.0)),
                zx: Derivatives2::new(Vec2::new(0.0, 2.0), Vec2::ZERO),
                xy: Derivatives2::new(Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0)),
            }),
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![planar_mapping_gradients, triplanar_weights, triplanar_gradients]
}
