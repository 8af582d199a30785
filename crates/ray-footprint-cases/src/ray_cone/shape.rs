//! Records of `ray_cone`: the shape operator of a triangle, its normal curvature along a
//! direction, its principal curvatures and the direction of the greater. Every tolerance is the
//! width of an interval enclosure (the `enclosure` submodule): a least-squares fit solved by
//! cofactors, and an eigenvector chosen by branches, have too many operations to bound by hand.

use super::enclosure::{
    self, direction_well_conditioned, projection_well_conditioned, shape_well_conditioned,
};
use super::{reference, MODULE};
use crate::degenerate::{value, Row};
use crate::record::Record;
use crate::strategy::{small_vec3, triangle, unit_vec3};
use crate::symmetry::Symmetry;
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval2, interval3};

/// The arguments of `rf_triangle_shape_operator`: three corners, three normals.
pub type ShapeOperatorArgs = (Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `rf_normal_curvature`: three corners, a shape operator, a direction.
pub type NormalCurvatureArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `rf_principal_curvatures`: a shape operator.
pub type PrincipalCurvaturesArgs = (Vec3,);

/// The arguments of `rf_principal_direction`: three corners, a shape operator.
pub type PrincipalDirectionArgs = (Vec3, Vec3, Vec3, Vec3);

/// The arguments of `rf_isotropic_curvature`: two principal curvatures.
pub type IsotropicCurvatureArgs = (Vec2,);

/// Why a record leaves a triangle out of its agreement and special-value checks.
const SLIVER: &str = "a sliver or a repeated vertex within rounding (the determinant of the normal \
     equations is not known to 2^-10), or edges shorter than about 1e-10: the fit may take \
     anything up to what the clamps allow";

/// The corners `0, x, y`: the frame is `(x, y)` exactly, and every sum of the fit is a dyadic
/// number, so the documented values are exact.
fn unit_corners() -> (Vec3, Vec3, Vec3) {
    (Vec3::ZERO, Vec3::X, Vec3::Y)
}

/// Tolerance of `rf_isotropic_curvature(rf_principal_curvatures(rf_triangle_shape_operator(p,
/// n)))`, the curvature a hit gives an isotropic cone, against the mirror: the width of the three
/// enclosures chained.
pub fn hit_curvature_error(p: [Vec3; 3], n: [Vec3; 3]) -> f32 {
    let shape_operator = enclosure::triangle_shape_operator(p.map(interval3), n.map(interval3));
    enclosure::isotropic_curvature(enclosure::principal_curvatures(shape_operator)).tolerance()
}

/// `rf_triangle_shape_operator`.
pub fn triangle_shape_operator() -> Record<ShapeOperatorArgs, Vec3> {
    let (p0, p1, p2) = unit_corners();
    let z = Vec3::Z;
    // Normals changing linearly along the triangle: n = z + S p, whose fit is S exactly.
    let linear = |s: fn(Vec3) -> Vec3| (p0, p1, p2, z + s(p0), z + s(p1), z + s(p2));
    Record::new(
        MODULE,
        "triangle_shape_operator",
        |(p0, p1, p2, n0, n1, n2)| rc::triangle_shape_operator(p0, p1, p2, n0, n1, n2),
        || {
            (triangle(), (unit_vec3(), unit_vec3(), unit_vec3()))
                .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                .boxed()
        },
    )
    .conditioned(SLIVER, |&(p0, p1, p2, ..)| shape_well_conditioned([p0, p1, p2]))
    .enclosure(|&(p0, p1, p2, n0, n1, n2)| {
        enclosure::triangle_shape_operator([p0, p1, p2].map(interval3), [n0, n1, n2].map(interval3))
            .components()
    })
    .reference(reference::shape_operator_linear_normals())
    .reference(reference::shape_operator_quadric())
    .symmetry(Symmetry::scale(
        "corners scaled by s: the shape operator by 1/s",
        |&(p0, p1, p2, n0, n1, n2), s| (p0 * s, p1 * s, p2 * s, n0, n1, n2),
        |shape_operator, s| shape_operator * s,
    ))
    .symmetry(Symmetry::rotation(
        "corners and normals turned: the same, in the triangle's own frame",
        |&(p0, p1, p2, n0, n1, n2), r| (r * p0, r * p1, r * p2, r * n0, r * n1, r * n2),
        |shape_operator, _| shape_operator,
    ))
    .symmetry(Symmetry::translation(
        "corners moved: the same",
        |&(p0, p1, p2, n0, n1, n2), t| (p0 + t, p1 + t, p2 + t, n0, n1, n2),
        |shape_operator, _| shape_operator,
    ))
    .symmetry(Symmetry::exchange(
        "normals flipped: the shape operator negated",
        |&(p0, p1, p2, n0, n1, n2)| (p0, p1, p2, -n0, -n1, -n2),
        |shape_operator| -shape_operator,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "flat (equal vertex normals)",
            "(0, 0, 0)",
            (p0, p1, p2, z, z, z),
            vec![0.0; 3],
        ),
        value(
            "corners 0, x, y; normals z + p / 2 (a sphere of radius 2, linearised)",
            "(1/2, 0, 1/2)",
            linear(|p| p / 2.0),
            vec![0.5, 0.0, 0.5],
        ),
        value(
            "corners 0, x, y; normals z + (x, -y, 0) / 2 (a saddle, linearised)",
            "(1/2, 0, -1/2): opposite signs",
            linear(|p| Vec3::new(p.x, -p.y, 0.0) / 2.0),
            vec![0.5, 0.0, -0.5],
        ),
        value(
            "zero-area triangle (p2 = p0)",
            "(0, 0, 0): no second axis, so nothing to fit",
            (Vec3::ZERO, Vec3::X, Vec3::ZERO, z, Vec3::X, z),
            vec![0.0; 3],
        ),
        value(
            "collinear corners (p2 = 2 p1 - p0)",
            "(0, 0, 0)",
            (Vec3::ZERO, Vec3::X, 2.0 * Vec3::X, z, Vec3::X, Vec3::Y),
            vec![0.0; 3],
        ),
        value(
            "all three corners at one point",
            "(0, 0, 0)",
            (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, z, Vec3::X, Vec3::Y),
            vec![0.0; 3],
        ),
    ])
}

/// `rf_normal_curvature`.
pub fn normal_curvature() -> Record<NormalCurvatureArgs, f32> {
    let (p0, p1, p2) = unit_corners();
    // e = 1, f = 1/4, g = -1/2: mean curvature 1/4.
    let shape = Vec3::new(1.0, 0.25, -0.5);
    let along = |direction: Vec3| (p0, p1, p2, shape, direction);
    Record::new(
        MODULE,
        "normal_curvature",
        |(p0, p1, p2, shape_operator, direction)| rc::normal_curvature(p0, p1, p2, shape_operator, direction),
        || {
            (triangle(), small_vec3(), unit_vec3())
                .prop_map(|(p, shape_operator, direction)| (p[0], p[1], p[2], shape_operator, direction))
                .boxed()
        },
    )
    .conditioned(
        "a sliver within rounding, or a direction within rounding of the face normal: the \
         frame or the direction's projection is not known to 2^-10",
        |&(p0, p1, p2, _, direction)| projection_well_conditioned([p0, p1, p2], direction),
    )
    .enclosure(|&(p0, p1, p2, shape_operator, direction)| {
        vec![enclosure::normal_curvature(
            [p0, p1, p2].map(interval3),
            interval3(shape_operator),
            interval3(direction),
        )]
    })
    .reference(reference::normal_curvature_euler())
    .symmetry(Symmetry::scale(
        "corners scaled by s and the shape operator by 1/s: the curvature by 1/s",
        |&(p0, p1, p2, shape_operator, direction), s| (p0 * s, p1 * s, p2 * s, shape_operator / s, direction),
        |curvature, s| curvature * s,
    ))
    .symmetry(Symmetry::scale(
        "the direction scaled by s: the same",
        |&(p0, p1, p2, shape_operator, direction), s| (p0, p1, p2, shape_operator, direction * s),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::rotation(
        "corners and direction turned: the same",
        |&(p0, p1, p2, shape_operator, direction), r| (r * p0, r * p1, r * p2, shape_operator, r * direction),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::translation(
        "corners moved: the same",
        |&(p0, p1, p2, shape_operator, direction), t| (p0 + t, p1 + t, p2 + t, shape_operator, direction),
        |curvature, _| curvature,
    ))
    .symmetry(Symmetry::exchange(
        "the direction reversed: the same",
        |&(p0, p1, p2, shape_operator, direction)| (p0, p1, p2, shape_operator, -direction),
        |curvature| curvature,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec3(), d.unit()))
    .degenerate(normal_curvature_rows(along))
}

fn normal_curvature_rows(along: impl Fn(Vec3) -> NormalCurvatureArgs) -> Vec<Row<NormalCurvatureArgs>> {
    let shape = along(Vec3::ZERO).3;
    vec![
        value(
            "direction along the frame's u (x)",
            "e = 1",
            along(Vec3::X),
            vec![1.0],
        ),
        value(
            "direction 2 x, not unit length",
            "e = 1: made unit first",
            along(2.0 * Vec3::X),
            vec![1.0],
        ),
        value(
            "direction 1e-12 x, a short one",
            "e = 1: made unit first",
            along(1.0e-12 * Vec3::X),
            vec![1.0],
        ),
        value(
            "direction along the face normal (z): no plane of incidence",
            "the mean curvature (e + g) / 2 = 1/4",
            along(Vec3::Z),
            vec![0.25],
        ),
        value(
            "zero direction",
            "the mean curvature (e + g) / 2 = 1/4",
            along(Vec3::ZERO),
            vec![0.25],
        ),
        value(
            "zero-area triangle (p2 = p0, no second axis), direction y",
            "the mean curvature (e + g) / 2 = 1/4",
            (Vec3::ZERO, Vec3::X, Vec3::ZERO, shape, Vec3::Y),
            vec![0.25],
        ),
    ]
}

/// `rf_principal_curvatures`.
pub fn principal_curvatures() -> Record<PrincipalCurvaturesArgs, Vec2> {
    let row = |input, output, shape_operator: [f32; 3], curvatures: [f32; 2]| {
        value(input, output, (Vec3::from(shape_operator),), curvatures.to_vec())
    };
    Record::new(
        MODULE,
        "principal_curvatures",
        |(shape_operator,)| rc::principal_curvatures(shape_operator),
        || small_vec3().prop_map(|shape_operator| (shape_operator,)).boxed(),
    )
    .enclosure(|&(shape_operator,)| enclosure::principal_curvatures(interval3(shape_operator)).components())
    .reference(reference::principal_curvatures_euler())
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

/// `rf_principal_direction`.
pub fn principal_direction() -> Record<PrincipalDirectionArgs, Vec3> {
    let (p0, p1, p2) = unit_corners();
    let shaped = |shape_operator: [f32; 3]| (p0, p1, p2, Vec3::from(shape_operator));
    Record::new(
        MODULE,
        "principal_direction",
        |(p0, p1, p2, shape_operator)| rc::principal_direction(p0, p1, p2, shape_operator),
        || {
            (triangle(), small_vec3())
                .prop_map(|(p, shape_operator)| (p[0], p[1], p[2], shape_operator))
                .boxed()
        },
    )
    .conditioned(
        "a sliver within rounding, or a shape operator whose principal curvatures are equal within \
         rounding (near an umbilic every direction is nearly principal, and rounding turns the \
         answer freely)",
        |&(p0, p1, p2, shape_operator)| direction_well_conditioned([p0, p1, p2], shape_operator),
    )
    .enclosure(|&(p0, p1, p2, shape_operator)| {
        enclosure::principal_direction([p0, p1, p2].map(interval3), interval3(shape_operator))
    })
    .reference(reference::principal_direction_cylinder())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec3()))
    .degenerate(vec![
        value(
            "corners 0, x, y (frame (x, y)); cylinder (1, 0, 0)",
            "x",
            shaped([1.0, 0.0, 0.0]),
            vec![1.0, 0.0, 0.0],
        ),
        value(
            "corners 0, x, y; cylinder (0, 0, 1)",
            "y",
            shaped([0.0, 0.0, 1.0]),
            vec![0.0, 1.0, 0.0],
        ),
        value(
            "corners 0, x, y; inward cylinder (-1, 0, 0)",
            "y: the greater curvature, 0, lies along the axis",
            shaped([-1.0, 0.0, 0.0]),
            vec![0.0, 1.0, 0.0],
        ),
        value(
            "corners 0, x, y; umbilic (1/2, 0, 1/2), a sphere",
            "(0, 0, 0): every direction is principal",
            shaped([0.5, 0.0, 0.5]),
            vec![0.0; 3],
        ),
        value(
            "corners 0, x, y; flat (0, 0, 0)",
            "(0, 0, 0)",
            shaped([0.0; 3]),
            vec![0.0; 3],
        ),
        value(
            "zero-area triangle (p2 = p0, no second axis); cylinder (0, 0, 1)",
            "(0, 0, 0): the direction lies along the missing axis",
            (Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec3::Z),
            vec![0.0; 3],
        ),
    ])
}

/// `rf_isotropic_curvature`.
pub fn isotropic_curvature() -> Record<IsotropicCurvatureArgs, f32> {
    let row = |input, output, principal: [f32; 2], curvature: f32| {
        value(input, output, (Vec2::from(principal),), vec![curvature])
    };
    Record::new(
        MODULE,
        "isotropic_curvature",
        |(principal_curvatures,)| rc::isotropic_curvature(principal_curvatures),
        || {
            (uniform(-10.0, 10.0), uniform(-10.0, 10.0))
                .prop_map(|(k1, k2)| (Vec2::new(k1, k2),))
                .boxed()
        },
    )
    .enclosure(|&(principal_curvatures,)| {
        vec![enclosure::isotropic_curvature(interval2(principal_curvatures))]
    })
    .reference(reference::isotropic_curvature_directions())
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
