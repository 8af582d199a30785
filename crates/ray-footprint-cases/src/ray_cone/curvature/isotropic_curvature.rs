//! The proof of [`isotropic_curvature`](ray_footprint::ray_cone::isotropic_curvature): its record,
//! its enclosure, the tolerance of the curvature a hit gives a cone (the chain from the shape
//! operator), and its reference, Euler's formula sampled.

use crate::degenerate::value;
use crate::ray_cone::curvature::{principal_curvatures, triangle_shape_operator};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::symmetry::Symmetry;
use glam::Vec2Swizzles;
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval2, interval3, select, Interval, Interval2};

/// The arguments of `rf_isotropic_curvature`: two principal curvatures.
pub type IsotropicCurvatureArgs = (Vec2,);

/// The record of `rf_isotropic_curvature`.
pub fn record() -> Record<IsotropicCurvatureArgs, f32> {
    let row = |input, output, principal: [f32; 2], curvature: f32| {
        value(input, output, (Vec2::from(principal),), vec![curvature])
    };
    Record::new(
        Module::RayCone,
        "isotropic_curvature",
        |(principal_curvatures,)| rc::isotropic_curvature(principal_curvatures),
        || {
            (uniform(-10.0, 10.0), uniform(-10.0, 10.0))
                .prop_map(|(k1, k2)| (Vec2::new(k1, k2),))
                .boxed()
        },
    )
    .enclosure(|&(principal_curvatures,)| vec![enclosure(interval2(principal_curvatures))])
    .reference(isotropic_curvature_directions())
    .symmetry(Symmetry::scale(
        "the principal curvatures scaled by s: the curvature by s",
        |&(k,), s| (k * s,),
        |curvature, s| curvature / s,
    ))
    .symmetry(Symmetry::exchange(
        "the two principal curvatures exchanged: the same",
        |&(k,)| (k.yx(),),
        |curvature| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "both principal curvatures negated (the normal flipped): the curvature negated",
        |&(k,)| (-k,),
        |curvature: f32| -curvature,
    ))
    .fuzz(|d| (d.vec2(),))
    .degenerate(vec![
        row("a sphere (1/2, 1/2)", "1/2", [0.5, 0.5], 0.5),
        row("convex (1/4, 1/2), the lesser second", "1/4", [0.25, 0.5], 0.25),
        row(
            "concave (-1/4, -1/2)",
            "-1/4: the lesser magnitude",
            [-0.25, -0.5],
            -0.25,
        ),
        row("a saddle (1/2, -1/2)", "0", [0.5, -0.5], 0.0),
        row(
            "a cylinder (1/2, 0)",
            "0: straight along the axis",
            [0.5, 0.0],
            0.0,
        ),
        row("an inward cylinder (0, -1/2)", "0", [0.0, -0.5], 0.0),
        row("flat (0, 0)", "0", [0.0, 0.0], 0.0),
    ])
}

/// `rf_isotropic_curvature` of principal curvatures given as intervals: exact (a minimum, a
/// maximum and a choice), so its width is the inputs'; where a sign is left open, the hull with
/// the other choices.
fn enclosure(principal_curvatures: Interval2) -> Interval {
    let [k1, k2] = principal_curvatures.0;
    let (least, most) = (k1.min(k2), k1.max(k2));
    let zero = || vec![Interval::c(0.0)];
    let negative = || select(most.hi < 0.0, most.lo < 0.0, || vec![most], zero);
    select(least.lo > 0.0, least.hi > 0.0, || vec![least], negative)[0]
}

/// Tolerance of `rf_isotropic_curvature(rf_principal_curvatures(rf_triangle_shape_operator(p,
/// n)))`, the curvature a hit gives an isotropic cone, against the mirror: the width of the three
/// enclosures chained.
pub fn hit_curvature_error(p: [Vec3; 3], n: [Vec3; 3]) -> f32 {
    let shape_operator = triangle_shape_operator::enclosure(p.map(interval3), n.map(interval3));
    enclosure(principal_curvatures::enclosure(shape_operator)).tolerance()
}

/// Directions the normal curvature is sampled along by `isotropic_curvature_directions`: every
/// tenth of a degree of a half turn (both principal directions among them).
const CURVATURE_DIRECTIONS: usize = 1800;

/// The reference of `rf_isotropic_curvature`.
fn isotropic_curvature_directions() -> Reference<IsotropicCurvatureArgs, f32> {
    Reference::new(
        Kind::ClosedForm,
        "the normal curvature k1 cos^2 + k2 sin^2 (Euler's formula) sampled over 1,800 directions in f64: the sampled value of least magnitude when every sample has one sign, 0 when the samples change sign",
        || (-10.0f64..10.0, -10.0f64..10.0).boxed(),
        |&(k1, k2), isotropic_curvature| {
            let principal = Vec2::new(k1 as f32, k2 as f32);
            let got = isotropic_curvature((principal,));
            let samples: Vec<f64> = (0..CURVATURE_DIRECTIONS)
                .map(|i| {
                    let angle = std::f64::consts::PI * i as f64 / CURVATURE_DIRECTIONS as f64;
                    let (sin, cos) = angle.sin_cos();
                    f64::from(principal.x) * cos * cos + f64::from(principal.y) * sin * sin
                })
                .collect();
            let one_sign = samples.iter().all(|&k| k > 0.0) || samples.iter().all(|&k| k < 0.0);
            let least = samples.iter().copied().fold(f64::INFINITY, |least, k| {
                if k.abs() < least.abs() {
                    k
                } else {
                    least
                }
            });
            let expected = if one_sign { least } else { 0.0 };
            // The samples along the principal directions are the inputs within f64 rounding.
            let scale = f64::from(principal.abs().max_element());
            Some(Deviation::within(f64::from(got), expected, 1.0e-12 * scale))
        },
    )
}
