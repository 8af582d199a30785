//! Case strategies that records of several sections share: rotations, differential vectors, ray
//! differentials, derivative pairs and directions, each drawn where the functions are
//! well-conditioned (ill-conditioned inputs are the special-value suite's).

use crate::strategy::{scalar, small_vec3, unit_vec3, vec2_of, vec3};
use glam::{Quat, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, RayDiff};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;

/// A rotation (axis-aligned ones included).
pub(crate) fn rotation() -> BoxedStrategy<Quat> {
    (unit_vec3(), uniform(0.0, std::f32::consts::TAU))
        .prop_map(|(axis, angle)| Quat::from_axis_angle(axis, angle))
        .boxed()
}

/// A differential vector: ordinary, small (pixel-sized), or anywhere in the domain.
pub(crate) fn differential_vec3() -> BoxedStrategy<Vec3> {
    one_of![
        3 => small_vec3(),
        2 => small_vec3().prop_map(|v| v * 1.0e-4),
        1 => vec3(),
        1 => Just(Vec3::ZERO),
    ]
    .boxed()
}

/// A ray differential: origin differentials from `differential_vec3`, direction differentials
/// ordinary or pixel-sized.
pub(crate) fn ray_diff() -> BoxedStrategy<RayDiff> {
    let direction = || one_of![small_vec3(), small_vec3().prop_map(|v| v * 1.0e-4)];
    (differential_vec3(), differential_vec3(), direction(), direction())
        .prop_map(|(a, b, c, d)| RayDiff::new(a, b, c, d))
        .boxed()
}

/// `(du, dv)` derivatives: ordinary, tiny or huge.
pub(crate) fn derivatives2() -> BoxedStrategy<Derivatives2> {
    let component = || one_of![3 => uniform(-10.0, 10.0), 1 => scalar()];
    (
        vec2_of(component(), component()),
        vec2_of(component(), component()),
    )
        .prop_map(|(dx, dy)| Derivatives2::new(dx, dy))
        .boxed()
}

/// Vector derivatives from [`differential_vec3`].
pub(crate) fn derivatives3() -> BoxedStrategy<Derivatives3> {
    (differential_vec3(), differential_vec3())
        .prop_map(|(dx, dy)| Derivatives3::new(dx, dy))
        .boxed()
}

/// A unit direction or a moderately scaled one (functions that take non-normalized directions).
pub(crate) fn any_direction() -> BoxedStrategy<Vec3> {
    one_of![3 => unit_vec3(), 1 => small_vec3()].boxed()
}
