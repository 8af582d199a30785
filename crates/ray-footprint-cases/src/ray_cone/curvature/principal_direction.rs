//! The proof of [`principal_direction`](ray_footprint::ray_cone::principal_direction): its record,
//! its enclosure and its reference, cylinders.

use crate::conditioning::WELL_CONDITIONED;
use crate::degenerate::value;
use crate::ray_cone::curvature::shared::{
    axis_in_plane, clamped_unit, conditioned_corners, enclosing, exact_shape_operator,
    principal_half_gap_radius, shape_frame, shape_well_conditioned, unit_corners, Curved,
};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::{small_vec3, triangle};
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, select, Interval, Interval3};

/// The arguments of `rf_principal_direction`: three corners, a shape operator.
pub type PrincipalDirectionArgs = (Vec3, Vec3, Vec3, Vec3);

/// The record of `rf_principal_direction`.
pub fn record() -> Record<PrincipalDirectionArgs, Vec3> {
    let (p0, p1, p2) = unit_corners();
    let shaped = |shape_operator: [f32; 3]| (p0, p1, p2, Vec3::from(shape_operator));
    Record::new(
        Module::RayCone,
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
        enclosure([p0, p1, p2].map(interval3), interval3(shape_operator))
    })
    .reference(principal_direction_cylinder())
    .symmetry(Symmetry::rotation(
        "the corners turned: the direction turned with them",
        |&(p0, p1, p2, shape_operator), r| (r * p0, r * p1, r * p2, shape_operator),
        |direction: Vec3, r| r.transpose() * direction,
    ))
    .symmetry(Symmetry::translation(
        "the corners moved: the same",
        |&(p0, p1, p2, shape_operator), t| (p0 + t, p1 + t, p2 + t, shape_operator),
        |direction, _| direction,
    ))
    .symmetry(Symmetry::scale(
        "the corners scaled by s (the shape operator given in the frame): the same",
        |&(p0, p1, p2, shape_operator), s| (p0 * s, p1 * s, p2 * s, shape_operator),
        |direction, _| direction,
    ))
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

/// `rf_principal_direction` with every argument an interval: each branch the device or the mirror
/// may take (the eigenvector's two forms, the turn to a non-negative `u` component) enclosed, and
/// their hull where the intervals leave the branch open.
fn enclosure(p: [Interval3; 3], shape_operator: Interval3) -> Vec<Interval> {
    let (u, v) = shape_frame(p);
    let f = shape_operator.0[1];
    let (half_gap, radius) = principal_half_gap_radius(shape_operator);
    let direction = |x: Interval, y: Interval| {
        let world = |x: Interval, y: Interval| clamped_unit(u * x + v * y).components();
        select(x.hi < 0.0, x.lo < 0.0, || world(-x, -y), || world(x, y))
    };
    select(
        half_gap.lo >= 0.0,
        half_gap.hi >= 0.0,
        || direction(half_gap + radius, f),
        || direction(f, radius - half_gap),
    )
}

/// Whether `rf_principal_direction`'s frame is known to [`WELL_CONDITIONED`] and so is the
/// radius, the gap between the principal curvatures: away from an umbilic, where rounding turns
/// the direction freely.
fn direction_well_conditioned(p: [Vec3; 3], shape_operator: Vec3) -> bool {
    let (_, radius) = principal_half_gap_radius(interval3(shape_operator));
    shape_well_conditioned(p) && radius.relative_width() <= WELL_CONDITIONED
}

/// The reference of `rf_principal_direction`.
fn principal_direction_cylinder() -> Reference<PrincipalDirectionArgs, Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "triangles of cylinders with their exact shape operator: the greater normal curvature lies across the axis (the plane's normal crossed with a_t, the axis's component in the plane) for outward normals, along a_t for inward ones; compared as an axis (either sign)",
        || Curved::strategy(3),
        |curved, principal_direction| {
            curved.axis?;
            let p = conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            if !direction_well_conditioned(p, shape.as_vec3()) {
                return None;
            }
            let got = principal_direction((p[0], p[1], p[2], shape.as_vec3())).as_dvec3();
            let (in_plane, face) = axis_in_plane(curved);
            let axis = if curved.orientation > 0.0 { face.cross(in_plane) } else { in_plane }.normalize();
            let expected = if got.dot(axis) < 0.0 { -axis } else { axis };
            let widths = enclosure(
                [0, 1, 2].map(|i| enclosing(curved.points[i])),
                enclosing(shape),
            );
            let deviations = (0..3).map(|i| {
                Deviation::within(got[i], expected[i], f64::from(widths[i].tolerance()))
            });
            Some(Deviation::worst(deviations))
        },
    )
}
