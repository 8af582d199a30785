//! Records of `ray_cone`: the shape operator of a triangle and its normal curvature along a
//! direction. Both tolerances are the widths of interval enclosures (the `enclosure` submodule):
//! a least-squares fit solved by cofactors has too many operations to bound by hand.

use super::enclosure::{self, projection_well_conditioned, shape_well_conditioned};
use super::{reference, MODULE};
use crate::degenerate::{value, Row};
use crate::record::Record;
use crate::strategy::{small_vec3, triangle, unit_vec3};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use shader_proptest::interval::interval3;

/// The arguments of `rf_triangle_shape_operator`: three corners, three normals.
pub type ShapeOperatorArgs = (Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `rf_normal_curvature`: three corners, a shape operator, a direction.
pub type NormalCurvatureArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// Why a record leaves a triangle out of its agreement and special-value checks.
const SLIVER: &str = "a sliver or a repeated vertex within rounding (the determinant of the normal \
     equations is not known to 2^-10), or edges shorter than about 1e-10: the fit may take \
     anything up to what the clamps allow";

/// The corners `0, x, y`: the frame is `(x, y)` exactly, and every sum of the fit is a dyadic
/// number, so the documented values are exact.
fn unit_corners() -> (Vec3, Vec3, Vec3) {
    (Vec3::ZERO, Vec3::X, Vec3::Y)
}

/// Tolerance of `rf_normal_curvature(p, rf_triangle_shape_operator(p, n), direction)`, a hit's
/// signed curvature in its plane of incidence, against the mirror: the width of the two enclosures
/// chained.
pub fn hit_curvature_error(p: [Vec3; 3], n: [Vec3; 3], direction: Vec3) -> f32 {
    let p = p.map(interval3);
    let shape_operator = enclosure::triangle_shape_operator(p, n.map(interval3));
    enclosure::normal_curvature(p, shape_operator, interval3(direction)).tolerance()
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
            "direction (1, 1, 0), not unit length",
            "(e + 2 f + g) / 2 = 1/2",
            along(Vec3::new(1.0, 1.0, 0.0)),
            vec![0.5],
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
