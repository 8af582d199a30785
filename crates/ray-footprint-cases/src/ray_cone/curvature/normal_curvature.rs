//! The proof of [`normal_curvature`](ray_footprint::ray_cone::normal_curvature): its record, its
//! enclosure and its reference, Euler's formula.

use crate::conditioning::WELL_CONDITIONED;
use crate::degenerate::{value, Row};
use crate::ray_cone::curvature::shared::{
    clamped_unit, conditioned_corners, enclosing, exact_frame, exact_shape_operator, linear_shape,
    shape_frame, shape_well_conditioned, unit_corners, Curved,
};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::{small_vec3, triangle, unit_vec3};
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};

/// The arguments of `rf_normal_curvature`: three corners, a shape operator, a direction.
pub type NormalCurvatureArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// The record of `rf_normal_curvature`.
pub fn record() -> Record<NormalCurvatureArgs, f32> {
    let (p0, p1, p2) = unit_corners();
    // e = 1, f = 1/4, g = -1/2: mean curvature 1/4.
    let shape = Vec3::new(1.0, 0.25, -0.5);
    let along = |direction: Vec3| (p0, p1, p2, shape, direction);
    Record::new(
        Module::RayCone,
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
        vec![enclosure(
            [p0, p1, p2].map(interval3),
            interval3(shape_operator),
            interval3(direction),
        )]
    })
    .reference(normal_curvature_euler())
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
    // A cylinder of radius 2 about z: its triangle's frame has u = (-1, 1, 0) / sqrt 2 across the
    // axis (curvature 1/2) and v = z along it (0).
    let (c0, c1, c2) = (
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(0.0, 2.0, 0.0),
        Vec3::new(2.0, 0.0, 1.0),
    );
    let across = |length: f32| (c0, c1, c2, Vec3::new(0.5, 0.0, 0.0), (c1 - c0) * length);
    // A triangle of the unit cylinder about z whose face normal is not axis-aligned, and that
    // normal rounded to f32.
    let (q0, q1, q2) = (
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.6, 0.8, 0.5),
        Vec3::new(0.8, -0.6, 1.0),
    );
    let face = (q1 - q0)
        .as_dvec3()
        .cross((q2 - q0).as_dvec3())
        .normalize()
        .as_vec3();
    vec![
        value(
            "cylinder of radius 2, direction (p1 - p0) * 1e-10 (across the axis, short)",
            "1/2 for any length",
            across(1.0e-10),
            vec![0.5],
        ),
        value(
            "the same direction times 1e-11",
            "1/2",
            across(1.0e-11),
            vec![0.5],
        ),
        value(
            "a tilted face's unit normal, rounded to f32 (in-plane components about 1e-8)",
            "the mean curvature (e + g) / 2 = 0.555",
            (q0, q1, q2, Vec3::new(0.8, 0.3, 0.31), face),
            vec![0.555],
        ),
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

/// `rf_normal_curvature` with every argument an interval.
fn enclosure(p: [Interval3; 3], shape_operator: Interval3, direction: Interval3) -> Interval {
    let (u, v) = shape_frame(p);
    let unit = clamped_unit(direction);
    let (a, b) = (unit.dot(u), unit.dot(v));
    let [e, f, g] = shape_operator.0;
    let normal_weight = Interval::exact(MIN_COS) * Interval::exact(MIN_COS);
    let mean = Interval::c(0.5) * (e + g);
    let (a2, b2) = (a.abs() * a.abs(), b.abs() * b.abs());
    (e * a * a + Interval::c(2.0) * f * a * b + g * b * b + normal_weight * mean) / (a2 + b2 + normal_weight)
}

/// Whether `rf_normal_curvature`'s frame and the direction's squared length in the triangle's
/// plane are known to [`WELL_CONDITIONED`].
fn projection_well_conditioned(p: [Vec3; 3], direction: Vec3) -> bool {
    let (u, v) = shape_frame(p.map(interval3));
    let d = clamped_unit(interval3(direction));
    let (a, b) = (d.dot(u), d.dot(v));
    let in_plane = a.abs() * a.abs() + b.abs() * b.abs();
    shape_well_conditioned(p) && in_plane.relative_width() <= WELL_CONDITIONED
}

/// The reference of `rf_normal_curvature`.
fn normal_curvature_euler() -> Reference<NormalCurvatureArgs, f32> {
    Reference::new(
        Kind::ClosedForm,
        "triangles of spheres and cylinders with their exact shape operator: Euler's formula in 3-D, t^T S t for t the direction's unit projection into the triangle's plane (1 / R on a sphere, (1 - (a . t)^2) / R on a cylinder)",
        || (Curved::strategy(3), crate::exact::unit()).boxed(),
        |(curved, direction), normal_curvature| {
            let p = conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            let d = direction.as_vec3();
            if !projection_well_conditioned(p, d) {
                return None;
            }
            let got = normal_curvature((p[0], p[1], p[2], shape.as_vec3(), d));
            let exact = [0, 1, 2].map(|i| curved.points[i]);
            let (u, v) = exact_frame(exact);
            let d = d.as_dvec3();
            let in_plane = u * d.dot(u) + v * d.dot(v);
            let t = in_plane.normalize();
            let euler = t.dot(linear_shape(curved) * t);
            // The function's MIN_COS^2 terms move it from Euler's value by
            // MIN_COS^2 (mean - k) / (|d_t|^2 + MIN_COS^2), d the unit direction.
            let weight = f64::from(MIN_COS).powi(2);
            let offset = weight * (0.5 * (e + g) - euler) / (in_plane.length_squared() / d.length_squared() + weight);
            let width = enclosure(
                exact.map(enclosing),
                enclosing(shape),
                shader_proptest::interval::interval3(d.as_vec3()),
            )
            .tolerance();
            Some(Deviation::within(f64::from(got), euler, f64::from(width) + offset.abs()))
        },
    )
}
