//! Records of `ray_diff`: Ray cones and ray differentials together.

use super::enclosure;
use super::strategy::{ray_diff, triangle_and_direction};
use super::{reference, ConeGradientArgs, MODULE};
use crate::degenerate::{grazing, parts, same, value};
use crate::record::Record;
use crate::strategy::{
    angle, normal_and_direction, scalar, triangle, unit_vec3, uv_triangle, vec2_of, with_corners,
};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, RayDiff, DIFF_MIN_COS};
use shader_proptest::interval::interval3;

/// `rf_cone_barycentric_deltas`: the enclosure of the deltas.
pub fn cone_barycentric_deltas() -> Record<(f32, Vec3, Vec3, Vec3), Vec3> {
    let x = Vec3::X;
    Record::new(
        MODULE,
        "cone_barycentric_deltas",
        |(f, p0, p1, p2)| rd::cone_barycentric_deltas(f, p0, p1, p2),
        || with_corners(scalar(), triangle()),
    )
    .conditioned(
        "a sliver or a repeated vertex within rounding (the doubled area is not known to 2^-10): \
         the deltas may take anything up to the clamp DIFF_MAX_VALUE",
        enclosure::area_well_conditioned,
    )
    .enclosure(enclosure::cone_barycentric_deltas)
    .reference(reference::cone_barycentric_deltas())
    .fuzz(|d| (d.scalar(), d.vec3(), d.vec3(), d.vec3()))
    .range(0.0, rd::DIFF_MAX_VALUE, "delta")
    .degenerate(vec![
        value(
            "zero-area triangle",
            "DIFF_MAX_VALUE each",
            (1.0, Vec3::ZERO, x, 2.0 * x),
            vec![rd::DIFF_MAX_VALUE; 3],
        ),
        value(
            "zero-area triangle, zero footprint",
            "0",
            (0.0, Vec3::ZERO, x, 2.0 * x),
            vec![0.0; 3],
        ),
        same(
            "negative footprint, zero-area triangle",
            "as |footprint|",
            (-1.0, Vec3::ZERO, x, 2.0 * x),
            (1.0, Vec3::ZERO, x, 2.0 * x),
        ),
    ])
}

/// `rf_anisotropic_cone_axes`: the enclosure of the axes.
pub fn anisotropic_cone_axes() -> Record<(f32, Vec3, Vec3), Derivatives3> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "anisotropic_cone_axes",
        |(width, n, d)| rd::anisotropic_cone_axes(width, n, d),
        || {
            (scalar(), normal_and_direction(), any::<bool>())
                .prop_map(|(width, (n, d), behind)| (width, if behind { -n } else { n }, d))
                .boxed()
        },
    )
    .enclosure(|&(width, n, d)| {
        let (major, minor) = enclosure::anisotropic_cone_axes(width, interval3(n), interval3(d));
        enclosure::derivatives3(major, minor)
    })
    .reference(reference::anisotropic_cone_axes())
    .reference(reference::anisotropic_cone_axes_growth())
    .reference(reference::anisotropic_cone_axes_optix())
    .fuzz(|d| (d.scalar(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "normal incidence (d = -n)",
            "a circle: |width| along Duff et al.'s tangent of n and along cross(n, tangent)",
            (0.5, z, -z),
            vec![0.5, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value(
            "ray in the surface plane",
            "major axis |width| / DIFF_MIN_COS along d, minor |width|",
            (0.5, z, x),
            vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value(
            "grazing (|dot(n, d)| = 1e-6)",
            "as the ray in the surface plane (|cos| clamped to DIFF_MIN_COS)",
            (0.5, z, grazing()),
            vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value("zero width", "zero axes", (0.0, z, -z), vec![0.0; 6]),
        same("negative width", "as |width|", (-0.5, z, -z), (0.5, z, -z)),
    ])
}

/// `rf_anisotropic_cone_gradients`: the enclosure of the UV gradients.
pub fn anisotropic_cone_gradients() -> Record<ConeGradientArgs, Derivatives2> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "anisotropic_cone_gradients",
        |(w, d, p0, p1, p2, uv0, uv1, uv2)| rd::anisotropic_cone_gradients(w, d, p0, p1, p2, uv0, uv1, uv2),
        || {
            (scalar(), triangle_and_direction(), uv_triangle())
                .prop_map(|(w, (p, d), uv)| (w, d, p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                .boxed()
        },
    )
    .enclosure(enclosure::anisotropic_cone_gradients)
    .found(
        "NaN for clamped barycentric changes times large texture coordinates (1e30 * 1e12 overflowed; DIFF_MAX_VALUE is now 2^40); found by the special-value suite",
    )
    .reference(reference::anisotropic_cone_gradients())
    .reference(reference::anisotropic_cone_gradients_isotropic())
    .fuzz(|d| {
        (
            d.scalar(),
            d.unit(),
            d.vec3(),
            d.vec3(),
            d.vec3(),
            d.vec2(),
            d.vec2(),
            d.vec2(),
        )
    })
    .degenerate(vec![
        value(
            "normal incidence, unit triangle, uv = xy",
            "(|width|, 0), (0, |width|)",
            (0.5, -z, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.5, 0.0, 0.0, 0.5],
        ),
        value(
            "ray in the triangle's plane",
            "(|width| / DIFF_MIN_COS, 0), (0, |width|)",
            (0.5, x, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.5],
        ),
        value(
            "zero-area triangle (repeated vertex)",
            "zero gradients (the unit normal is 0)",
            (0.5, -z, Vec3::ZERO, x, Vec3::ZERO, Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.0; 4],
        ),
        value(
            "zero width",
            "zero gradients",
            (0.0, -z, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
            vec![0.0; 4],
        ),
    ])
}

/// `rf_ray_diff_from_cone`: the enclosure of the differential.
pub fn ray_diff_from_cone() -> Record<(Vec2, Vec3), RayDiff> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "ray_diff_from_cone",
        |(cone, d)| rd::ray_diff_from_cone(cone, d),
        || (vec2_of(scalar(), angle()), unit_vec3()).boxed(),
    )
    .enclosure(enclosure::ray_diff_from_cone)
    .reference(reference::ray_diff_from_cone())
    .reference(reference::ray_diff_from_cone_round_trip())
    .fuzz(|d| (d.vec2(), d.unit()))
    .degenerate(vec![
        value("zero cone", "zero differential", (Vec2::ZERO, -z), vec![0.0; 16]),
        value(
            "direction -Z",
            "u = (1, 0, 0), v = (0, -1, 0)",
            (Vec2::new(0.5, 0.25), -z),
            parts(RayDiff::new(0.5 * x, -0.5 * y, 0.25 * x, -0.25 * y)),
        ),
        value(
            "direction +Z",
            "u = (1, 0, 0), v = (0, 1, 0)",
            (Vec2::new(0.5, 0.25), z),
            parts(RayDiff::new(0.5 * x, 0.5 * y, 0.25 * x, 0.25 * y)),
        ),
        value(
            "zero direction",
            "u = (1, 0, 0), v = 0: the y differentials vanish",
            (Vec2::new(0.5, 0.25), Vec3::ZERO),
            parts(RayDiff::new(0.5 * x, Vec3::ZERO, 0.25 * x, Vec3::ZERO)),
        ),
    ])
}

/// `rf_cone_from_ray_diff`: the enclosure of the cone.
pub fn cone_from_ray_diff() -> Record<(RayDiff, Vec3), Vec2> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "cone_from_ray_diff",
        |(diff, d)| rd::cone_from_ray_diff(diff, d),
        || (ray_diff(), unit_vec3()).boxed(),
    )
    .conditioned(
        "an origin or direction change lies along the ray within rounding (its part across the \
         ray is not known to 2^-10), or the two are orthogonal within rounding: the width is \
         rounding noise, or the spread's sign (converging or diverging) may go either way",
        enclosure::transverse_well_conditioned,
    )
    .enclosure(enclosure::cone_from_ray_diff)
    .reference(reference::cone_from_ray_diff())
    .reference(reference::cone_from_ray_diff_propagation())
    .fuzz(|d| (d.ray_diff(), d.unit()))
    .promise(|_, cone, promises| promises.within(cone.x, 0.0, f32::MAX, "width"))
    .degenerate(vec![
        value("zero differential", "(0, 0)", (RayDiff::ZERO, -z), vec![0.0, 0.0]),
        value(
            "pinhole eye ray (dO = 0), |dD/dx| = 0.01, |dD/dy| = 0.02",
            "(0, mean spread 0.015), diverging",
            (RayDiff::new(Vec3::ZERO, Vec3::ZERO, 0.01 * x, 0.02 * y), -z),
            vec![0.0, 0.5 * (0.01 + 0.02)],
        ),
        value(
            "origin and direction changes pointing apart",
            "negative spread (converging)",
            (RayDiff::new(x, y, -0.5 * x, -0.5 * y), -z),
            vec![1.0, -0.5],
        ),
        value(
            "changes along the ray only",
            "(0, 0): only the parts across the ray count",
            (RayDiff::new(2.0 * z, 2.0 * z, z, z), -z),
            vec![0.0, 0.0],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        cone_barycentric_deltas,
        anisotropic_cone_axes,
        anisotropic_cone_gradients,
        ray_diff_from_cone,
        cone_from_ray_diff
    ]
}
