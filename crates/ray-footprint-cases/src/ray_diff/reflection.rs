//! Records of `ray_diff`: Reflection and refraction (Igehy).

use super::enclosure;
use super::rows::direction_dx;
use super::strategy::{derivatives2, derivatives3, ray_diff};
use super::{reference, MODULE};
use crate::degenerate::{parts, value};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{normal_and_direction, unit_vec3, vec2_of};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, RayDiff, DIFF_MIN_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// `rf_normal_derivatives`.
pub fn normal_derivatives() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    Record::new(
        MODULE,
        "normal_derivatives",
        |(n0, n1, n2, uv, b)| rd::normal_derivatives(n0, n1, n2, uv, b),
        || {
            (
                (unit_vec3(), unit_vec3(), unit_vec3()),
                vec2_of(uniform(-1.0, 2.0), uniform(-1.0, 2.0)),
                derivatives2(),
            )
                .prop_map(|((n0, n1, n2), uv, b)| (n0, n1, n2, uv, b))
                .boxed()
        },
    )
    .enclosure(enclosure::normal_derivatives)
    .reference(reference::normal_derivatives())
    .fuzz(|d| (d.unit(), d.unit(), d.unit(), d.vec2(), d.derivatives2()))
    .degenerate(vec![
        value(
            "interpolated normal of length 0 (opposite vertex normals)",
            "dn / sqrt(DIFF_MIN_MAGNITUDE)",
            (z, -z, z, Vec2::new(0.5, 0.0), g),
            vec![0.0, 0.0, -2.0 / DIFF_MIN_MAGNITUDE.sqrt(), 0.0, 0.0, 0.0],
        ),
        value(
            "equal vertex normals (flat)",
            "0",
            (z, z, z, Vec2::splat(0.25), Derivatives2::new(Vec2::X, Vec2::Y)),
            vec![0.0; 6],
        ),
        value(
            "zero barycentric differentials",
            "0",
            (z, x, y, Vec2::splat(0.25), Derivatives2::default()),
            vec![0.0; 6],
        ),
    ])
}

/// `rf_reflect_ray_diff`.
pub fn reflect_ray_diff() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let flat = Derivatives3::default();
    Record::new(
        MODULE,
        "reflect_ray_diff",
        |(diff, d, n, dn)| rd::reflect_ray_diff(diff, d, n, dn),
        || {
            (ray_diff(), normal_and_direction(), derivatives3())
                .prop_map(|(diff, (n, d), dn)| (diff, d, n, dn))
                .boxed()
        },
    )
    .enclosure(enclosure::reflect_ray_diff)
    .reference(reference::reflect_ray_diff())
    .reference(reference::reflect_ray_diff_mirror_camera())
    .fuzz(|d| (d.ray_diff(), d.unit(), d.unit(), d.derivatives3()))
    .degenerate(vec![
        value(
            "ray in the surface plane, flat surface",
            "dD - 2 dot(dD, N) N",
            (direction_dx(z), x, z, flat),
            parts(direction_dx(-z)),
        ),
        value(
            "zero direction differentials, flat surface",
            "zero direction differentials, origin differentials kept",
            (RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO), -z, z, flat),
            parts(RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "head-on (D = -N), normal turning by dN/dx = (1, 0, 0)",
            "dR/dx = 2 dN/dx",
            (RayDiff::ZERO, -z, z, Derivatives3::new(x, Vec3::ZERO)),
            parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, 2.0 * x, Vec3::ZERO)),
        ),
    ])
}

/// `rf_refract_ray_diff`.
pub fn refract_ray_diff() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let flat = Derivatives3::default();
    Record::new(
        MODULE,
        "refract_ray_diff",
        |(diff, d, n, dn, eta)| rd::refract_ray_diff(diff, d, n, dn, eta),
        // Within rounding of the critical angle (the enclosure of `k` contains 0) either branch is
        // right and the flag's tolerance would be vacuous: those cases are checked separately.
        || {
            let eta = one_of![4 => uniform(0.3, 3.0), 1 => Just(1.0f32), 1 => Just(0.0f32), 1 => uniform(0.0, 0.01)];
            (ray_diff(), normal_and_direction(), derivatives3(), eta)
                .prop_map(|(diff, (n, d), dn, eta)| (diff, d, n, dn, eta))
                .boxed()
        },
    )
    .conditioned(
        "within rounding of the critical angle (k = 1 - eta^2 (1 - dot(D, N)^2) encloses 0): the \
         refracted and the reflected branch are both right",
        |args| !enclosure::refraction_determinant(args).contains_zero(),
    )
    .enclosure(enclosure::refract_ray_diff)
    .found(
        "the sign of the amplified normal term at exactly the critical angle: dot(T, N) = -0 was clamped to +DIFF_MIN_COS where every angle just short of it gives -DIFF_MIN_COS; found by `refraction_keeps_its_sign_at_the_critical_angle`",
    )
    .reference(reference::refract_ray_diff())
    .fuzz(|d| (d.ray_diff(), d.unit(), d.unit(), d.derivatives3(), d.scalar()))
    .degenerate(vec![
        value(
            "ray in the surface plane, eta = 1",
            "dot(T, N) = 0 clamped to DIFF_MIN_COS: dT = 0 here, no reflection",
            (direction_dx(z), x, z, flat, 1.0),
            [parts(RayDiff::ZERO), vec![0.0]].concat(),
        ),
        value(
            "ray in the surface plane, eta = 1.5",
            "total internal reflection: flag set, the reflected differential",
            (direction_dx(z), x, z, flat, 1.5),
            [parts(direction_dx(-z)), vec![1.0]].concat(),
        ),
        value(
            "head-on, eta = 1 (matched indices)",
            "dD unchanged (mu = 0, dmu = 0), no reflection",
            (direction_dx(x), -z, z, flat, 1.0),
            [parts(direction_dx(x)), vec![0.0]].concat(),
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![normal_derivatives, reflect_ray_diff, refract_ray_diff]
}
