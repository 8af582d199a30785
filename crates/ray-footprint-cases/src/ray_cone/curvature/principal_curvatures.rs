//! The proof of [`principal_curvatures`](ray_footprint::ray_cone::principal_curvatures): its record,
//! its enclosure and its reference, Euler's theorem.

use crate::degenerate::value;
use crate::ray_cone::curvature::shared::{
    axis_in_plane, conditioned_corners, enclosing, exact_shape_operator, principal_half_gap_radius, Curved,
};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::small_vec3;
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec2, Vec3};
use glam::{Vec2Swizzles, Vec3Swizzles};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval2, Interval3, IntervalVec};

/// The arguments of `rf_principal_curvatures`: a shape operator.
pub type PrincipalCurvaturesArgs = (Vec3,);

/// The record of `rf_principal_curvatures`.
pub fn record() -> Record<PrincipalCurvaturesArgs, Vec2> {
    let row = |input, output, shape_operator: [f32; 3], curvatures: [f32; 2]| {
        value(input, output, (Vec3::from(shape_operator),), curvatures.to_vec())
    };
    Record::new(
        Module::RayCone,
        "principal_curvatures",
        |(shape_operator,)| rc::principal_curvatures(shape_operator),
        || small_vec3().prop_map(|shape_operator| (shape_operator,)).boxed(),
    )
    .enclosure(|&(shape_operator,)| enclosure(interval3(shape_operator)).components())
    .reference(principal_curvatures_euler())
    .symmetry(Symmetry::scale(
        "the shape operator scaled by s: the curvatures by s",
        |&(shape_operator,), s| (shape_operator * s,),
        |curvatures, s| curvatures / s,
    ))
    .symmetry(Symmetry::exchange(
        "the frame's v axis flipped (f negated): the same",
        |&(shape_operator,)| (shape_operator * Vec3::new(1.0, -1.0, 1.0),),
        |curvatures| curvatures,
    ))
    .symmetry(Symmetry::exchange(
        "the frame's axes exchanged (e and g exchanged): the same",
        |&(shape_operator,)| (shape_operator.zyx(),),
        |curvatures| curvatures,
    ))
    .symmetry(Symmetry::exchange(
        "the shape operator negated (the normal flipped): the curvatures negated and exchanged",
        |&(shape_operator,)| (-shape_operator,),
        |curvatures: Vec2| -curvatures.yx(),
    ))
    .fuzz(|d| (d.vec3(),))
    .degenerate(vec![
        row("flat (0, 0, 0)", "(0, 0)", [0.0; 3], [0.0; 2]),
        row(
            "umbilic (1/2, 0, 1/2), a sphere of radius 2",
            "(1/2, 1/2)",
            [0.5, 0.0, 0.5],
            [0.5, 0.5],
        ),
        row(
            "cylinder (1, 0, 0), bending along u",
            "(1, 0)",
            [1.0, 0.0, 0.0],
            [1.0, 0.0],
        ),
        row(
            "saddle (-1/2, 0, 1/2), the greater along v",
            "(1/2, -1/2): the greater first",
            [-0.5, 0.0, 0.5],
            [0.5, -0.5],
        ),
        row(
            "saddle (0, 1/2, 0), principal axes at 45 degrees to the frame",
            "(1/2, -1/2)",
            [0.0, 0.5, 0.0],
            [0.5, -0.5],
        ),
        row(
            "saddle (3/2, 2, -3/2)",
            "(5/2, -5/2): radius |(3/2, 2)| = 5/2",
            [1.5, 2.0, -1.5],
            [2.5, -2.5],
        ),
    ])
}

/// `rf_principal_curvatures` of a shape operator given as intervals.
pub(crate) fn enclosure(shape_operator: Interval3) -> Interval2 {
    let [e, _, g] = shape_operator.0;
    let mean = Interval::c(0.5) * (e + g);
    let (_, radius) = principal_half_gap_radius(shape_operator);
    IntervalVec([mean + radius, mean - radius])
}

/// The reference of `rf_principal_curvatures`.
fn principal_curvatures_euler() -> Reference<PrincipalCurvaturesArgs, Vec2> {
    Reference::new(
        Kind::ClosedForm,
        "the exact shape operators of triangles of spheres and cylinders: the extremes of the normal curvature over the triangle's plane (Euler's theorem), 1 / R twice on a sphere, 1 / R and (1 - |a_t|^2) / R on a cylinder whose axis has the component a_t in the plane, times the normals' orientation, the greater first",
        || Curved::strategy(3),
        |curved, principal_curvatures| {
            conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            let got = principal_curvatures((shape.as_vec3(),));
            let (in_plane, _) = axis_in_plane(curved);
            let extremes = [1.0, 1.0 - in_plane.length_squared()].map(|k| k * curved.orientation / curved.radius);
            let expected = [extremes[0].max(extremes[1]), extremes[0].min(extremes[1])];
            let widths = enclosure(enclosing(shape));
            let deviations = (0..2).map(|i| {
                Deviation::within(f64::from(got[i]), expected[i], f64::from(widths.0[i].tolerance()))
            });
            Some(Deviation::worst(deviations))
        },
    )
}
