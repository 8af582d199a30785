//! Records of `ray_cone`: Propagation and curvature: the width along the ray and the spread a curved surface adds.

use super::bound::{
    curvature_spread_angle_error, edge_curvature_error, triangle_curvature_error, width_at_error,
};
use super::strategy::{off_the_plane, ray_cone};
use super::{reference, MODULE};
use crate::degenerate::{cone, direction_at, grazing, mirror, same, value, Row, HEAD_ON, INF, IN_PLANE, NAN};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{angle, distance, normal_and_direction, scalar, small_vec3, triangle, vec3};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS, MIN_SQUARED_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::tolerance::{atan_error, ulps, ULP};
use shader_proptest::{Args, Value};
use std::f32::consts::PI;

// Rows of both normal spread angles (exact and small-angle): 0 for a flat surface and when the
// squares of the derivatives underflow.
fn flat_normal() -> Row<(Vec3, Vec3)> {
    value(
        "zero normal derivatives (flat)",
        "0",
        (Vec3::ZERO, Vec3::ZERO),
        vec![0.0],
    )
}

fn sub_normal_derivatives() -> Row<(Vec3, Vec3)> {
    value(
        "sub-normal derivatives (1e-40 each)",
        "0 (the squares underflow)",
        (Vec3::splat(1.0e-40), Vec3::splat(-1.0e-40)),
        vec![0.0],
    )
}

/// `rf_width_at`.
pub fn width_at() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "width_at",
        |(cone, t)| rc::width_at(cone, t),
        || (ray_cone(), distance()).boxed(),
    )
    .bound(|&(cone, t), _, _| width_at_error(cone, t))
    .reference(reference::width_at())
    .fuzz(|d| (d.cone(), d.distance()))
    .degenerate(vec![
        value("t = 0", "width", (cone(0.5, 0.001), 0.0), vec![0.5]),
        value(
            "huge t (1e12)",
            "width + spread * 1e12",
            (cone(0.5, 0.001), 1.0e12),
            vec![0.5 + 0.001 * 1.0e12],
        ),
        value(
            "negative spread past the apex",
            "negative (signed width; footprints use |width|)",
            (cone(1.0, -0.01), 200.0),
            vec![1.0 - 0.01 * 200.0],
        ),
        mirror("NaN in (t)", "CPU: NaN", (cone(0.5, 0.001), NAN), vec![NAN]),
        mirror("infinity in (t)", "CPU: inf", (cone(0.5, 0.001), INF), vec![INF]),
    ])
}

/// `rf_propagate`.
pub fn propagate() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "propagate",
        |(cone, t, beta)| rc::propagate(cone, t, beta),
        || (ray_cone(), distance(), angle()).boxed(),
    )
    // Width as width_at; spread: one correctly rounded addition, identical.
    .bound(
        |&(cone, t, _), index, _| {
            if index == 0 {
                width_at_error(cone, t)
            } else {
                0.0
            }
        },
    )
    .reference(reference::propagate_planar())
    .reference(reference::propagate_curved())
    .fuzz(|d| (d.cone(), d.distance(), d.angle()))
    .degenerate(vec![
        value(
            "t = 0",
            "(width, spread + beta)",
            (cone(0.5, 0.001), 0.0, 0.25),
            vec![0.5, 0.001 + 0.25],
        ),
        value(
            "huge t (1e12)",
            "(width + spread * 1e12, spread + beta)",
            (cone(0.5, 0.001), 1.0e12, 0.0),
            vec![0.5 + 0.001 * 1.0e12, 0.001],
        ),
        mirror(
            "infinity in (beta)",
            "CPU: (width + spread * t, inf)",
            (cone(0.5, 0.001), 1.0, INF),
            vec![0.5 + 0.001, INF],
        ),
    ])
}

/// `rf_normal_spread_angle`.
pub fn normal_spread_angle() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "normal_spread_angle",
        |(dn_dx, dn_dy)| rc::normal_spread_angle(dn_dx, dn_dy),
        || (small_vec3(), small_vec3()).boxed(),
    )
    // sqrt of a 6-term sum (3 ULP of the sum -> 1.5 relative, sqrt ~4.5, mirror 1): 9 ULP
    // on the length, halved and propagated through atan, doubled; plus atan's 4096 ULP.
    .bound(|&(dn_dx, dn_dy), _, _| {
        let length = rc::normal_spread_angle_small(dn_dx, dn_dy);
        2.0 * atan_error(0.5 * length, ulps(9.0, 0.5 * length))
    })
    .reference(reference::normal_spread_angle())
    .fuzz(|d| (d.vec3(), d.vec3()))
    .range(0.0, PI, "normal spread angle")
    .degenerate(vec![
        flat_normal(),
        value(
            "one derivative zero, the other of length 2",
            "2 atan(1) = pi / 2",
            (Vec3::ZERO, Vec3::new(0.0, 0.0, -2.0)),
            vec![std::f32::consts::FRAC_PI_2],
        ),
        sub_normal_derivatives(),
        mirror(
            "infinity in",
            "CPU: pi (2 atan(inf))",
            (Vec3::new(INF, 0.0, 0.0), Vec3::ZERO),
            vec![std::f32::consts::PI],
        ),
    ])
}

/// `rf_normal_spread_angle_small`.
pub fn normal_spread_angle_small() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "normal_spread_angle_small",
        |(dn_dx, dn_dy)| rc::normal_spread_angle_small(dn_dx, dn_dy),
        || (small_vec3(), small_vec3()).boxed(),
    )
    // As above, without atan: 9 ULP.
    .bound(|_, _, expected| ulps(9.0, expected))
    .reference(reference::normal_spread_angle_small())
    .fuzz(|d| (d.vec3(), d.vec3()))
    .range(0.0, f32::MAX, "normal spread angle")
    .degenerate(vec![
        flat_normal(),
        value(
            "derivatives (3, 0, 0) and (0, -4, 0)",
            "5, the length of both together",
            (Vec3::new(3.0, 0.0, 0.0), Vec3::new(0.0, -4.0, 0.0)),
            vec![5.0],
        ),
        sub_normal_derivatives(),
    ])
}

/// Whether the sign of `dot(dp_dx, dn_dx) + dot(dp_dy, dn_dy)` is decided: the sum lies beyond its
/// rounding error (6 terms, 8 ULP of their magnitudes) from zero.
fn curvature_sign_decided(&(dp_dx, dp_dy, dn_dx, dn_dy): &(Vec3, Vec3, Vec3, Vec3)) -> bool {
    let sum = dp_dx.dot(dn_dx) + dp_dy.dot(dn_dy);
    let terms = (dp_dx * dn_dx).abs().element_sum() + (dp_dy * dn_dy).abs().element_sum();
    sum.abs() > 8.0 * ULP * terms
}

/// `rf_curvature_sign`.
pub fn curvature_sign() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    Record::new(
        MODULE,
        "curvature_sign",
        |(dp_dx, dp_dy, dn_dx, dn_dy)| rc::curvature_sign(dp_dx, dp_dy, dn_dx, dn_dy),
        || (small_vec3(), small_vec3(), small_vec3(), small_vec3()).boxed(),
    )
    .conditioned(
        "the sum of dot(dp, dn) is within its rounding error of zero: either sign is right",
        curvature_sign_decided,
    )
    // Exact where the sign is decided; elsewhere either sign is right.
    .bound(|args, _, _| if curvature_sign_decided(args) { 0.0 } else { 2.0 })
    .reference(reference::curvature_sign())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec3()))
    .promise(|_, sign, promises| promises.within(sign.abs(), 1.0, 1.0, "|sign|"))
    .degenerate(vec![
        value(
            "zero derivatives",
            "-1 (sign(0) = -1)",
            (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
            vec![-1.0],
        ),
        value(
            "convex (dot(dp_dx, dn_dx) = 1)",
            "1",
            (x, Vec3::ZERO, x, Vec3::ZERO),
            vec![1.0],
        ),
        value(
            "terms cancelling to exactly 0 (1 - 1)",
            "-1 (sign(0) = -1)",
            (x, Vec3::Y, x, Vec3::NEG_Y),
            vec![-1.0],
        ),
        mirror(
            "NaN in",
            "CPU: -1 (NaN > 0 is false)",
            (Vec3::splat(NAN), x, x, x),
            vec![-1.0],
        ),
    ])
}

/// `rf_surface_spread_angle`.
pub fn surface_spread_angle() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "surface_spread_angle",
        |(phi, sign, k1, k2)| rc::surface_spread_angle(phi, sign, k1, k2),
        || {
            (
                angle(),
                prop::sample::select(vec![1.0f32, -1.0]),
                uniform(-4.0, 4.0),
                angle(),
            )
                .boxed()
        },
    )
    // Three products and a sum, possibly fused: 4 ULP of the larger term.
    .bound(|&(phi, sign, k1, k2), _, _| ulps(4.0, (2.0 * k1 * sign * phi).abs() + k2.abs()))
    .reference(reference::surface_spread_angle())
    .fuzz(|d| (d.angle(), d.scalar().signum(), d.scalar(), d.angle()))
    .degenerate(vec![
        value(
            "flat (phi = 0), RTG's k1 = 1, k2 = 0",
            "0",
            (0.0, 1.0, 1.0, 0.0),
            vec![0.0],
        ),
        value(
            "concave (s = -1), phi = 0.25",
            "-2 phi = -0.5: the cone narrows",
            (0.25, -1.0, 1.0, 0.0),
            vec![-0.5],
        ),
        value(
            "k1 = 0",
            "k2: the curvature is ignored",
            (0.25, 1.0, 0.0, 0.125),
            vec![0.125],
        ),
    ])
}

/// `rf_edge_curvature`.
pub fn edge_curvature() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "edge_curvature",
        |(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j),
        || (vec3(), vec3(), small_vec3(), small_vec3()).boxed(),
    )
    .bound(|&(p_i, p_j, n_i, n_j), _, _| edge_curvature_error(p_i, p_j, n_i, n_j))
    .reference(reference::edge_curvature())
    .fuzz(|d| (d.vec3(), d.vec3(), d.unit(), d.unit()))
    .degenerate(vec![
        value("zero-length edge", "0", (x, x, z, x), vec![0.0]),
        value(
            "edge of length 1e-19 (|edge|^2 below MIN_SQUARED_MAGNITUDE)",
            "dot(n_j - n_i, edge) / MIN_SQUARED_MAGNITUDE",
            (Vec3::ZERO, Vec3::new(1.0e-19, 0.0, 0.0), Vec3::ZERO, x),
            vec![1.0e-19 / MIN_SQUARED_MAGNITUDE],
        ),
        value(
            "edge of the unit sphere (p = n: x, then y)",
            "1 (1 / R)",
            (x, Vec3::Y, x, Vec3::Y),
            vec![1.0],
        ),
        value("equal normals (flat)", "0", (Vec3::ZERO, x, z, z), vec![0.0]),
        value(
            "edge of length 1e-12 along x, the normal turning by x",
            "1e12: the squared length 1e-24 is above MIN_SQUARED_MAGNITUDE",
            (Vec3::ZERO, Vec3::new(1.0e-12, 0.0, 0.0), Vec3::ZERO, x),
            vec![1.0e-12 / (1.0e-12 * 1.0e-12)],
        ),
    ])
}

/// `rf_triangle_curvature`.
pub fn triangle_curvature() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "triangle_curvature",
        |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
        || {
            (triangle(), (small_vec3(), small_vec3(), small_vec3()))
                .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                .boxed()
        },
    )
    .bound(|&(p0, p1, p2, n0, n1, n2), _, _| triangle_curvature_error([p0, p1, p2], [n0, n1, n2]))
    .reference(reference::triangle_curvature())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero-area triangle (p2 = p0)",
            "the mean of the two real edges' curvatures (the zero edge counts 0): 2/3 here",
            (Vec3::ZERO, x, Vec3::ZERO, z, x, z),
            vec![(1.0 + 1.0 + 0.0) / 3.0],
        ),
        value(
            "flat (equal vertex normals)",
            "0",
            (Vec3::ZERO, x, Vec3::Y, z, z, z),
            vec![0.0],
        ),
        value(
            "vertices and outward normals x, y, z of the unit sphere",
            "1 (each edge 1 / R)",
            (x, Vec3::Y, z, x, Vec3::Y, z),
            vec![1.0],
        ),
        value(
            "all three vertices at one point",
            "0 (three zero-length edges)",
            (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, z, x, Vec3::Y),
            vec![0.0],
        ),
    ])
}

/// `rf_curvature_spread_angle`.
pub fn curvature_spread_angle() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "curvature_spread_angle",
        |(curvature, width, normal, direction)| {
            rc::curvature_spread_angle(curvature, width, normal, direction)
        },
        // Signed curvatures and widths; the ray meets the normal's side or the other one, never
        // within the dot product's rounding of the surface plane (see `off_the_plane`).
        || {
            (scalar(), scalar(), normal_and_direction(), any::<bool>())
                .prop_map(|(k, w, (n, d), behind)| {
                    let d = off_the_plane(n, d);
                    (k, w, if behind { -n } else { n }, d)
                })
                .boxed()
        },
    )
    .bound(|&(_, _, normal, direction), _, expected| {
        curvature_spread_angle_error(normal, direction, expected)
    })
    .found(
        "the reflected cone's curvature sign: past a focus and on hits behind the stored normals the spread had the wrong sign (it used |width| and |dot(n, d)|); found by the convex- and concave-mirror reproductions of `tests/ray_cone_math.rs`",
    )
    .reference(reference::curvature_spread_angle())
    .fuzz(|d| (d.scalar(), d.scalar(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "ray in the surface plane (dot(n, d) = +0)",
            "2 k width / MIN_COS: dn = 0 counts as the normal's side",
            (0.5, 0.01, z, IN_PLANE),
            vec![2.0 * 0.5 * 0.01 / MIN_COS],
        ),
        same(
            "ray in the surface plane (dot(n, d) = -0)",
            "as dot(n, d) = +0: either zero gives dn = +MIN_COS",
            (0.5, 0.01, z, Vec3::new(-1.0, -0.0, -0.0)),
            (0.5, 0.01, z, IN_PLANE),
        ),
        same(
            "grazing on the normal's side (dot(n, d) = -1e-6)",
            "as dot(n, d) = 0 (dn clamped to MIN_COS)",
            (0.5, 0.01, z, grazing()),
            (0.5, 0.01, z, IN_PLANE),
        ),
        value(
            "grazing behind the normal (dot(n, d) = +1e-6)",
            "-2 k width / MIN_COS (dn clamped to -MIN_COS, its sign kept)",
            (0.5, 0.01, z, direction_at(-1.0e-6)),
            vec![-2.0 * 0.5 * 0.01 / MIN_COS],
        ),
        value(
            "head-on (d = -n)",
            "2 k width",
            (0.5, 0.01, z, HEAD_ON),
            vec![2.0 * 0.5 * 0.01],
        ),
        value(
            "head-on from behind the normal (d = n)",
            "-2 k width: the surface's normals point away from the ray",
            (0.5, 0.01, z, z),
            vec![-2.0 * 0.5 * 0.01],
        ),
        value(
            "negative width (past a focus)",
            "2 k width, negative: widens the inverted cone on a convex mirror",
            (0.5, -0.01, z, HEAD_ON),
            vec![-2.0 * 0.5 * 0.01],
        ),
        value("zero width (at a focus)", "0", (0.5, 0.0, z, HEAD_ON), vec![0.0]),
    ])
}

/// This section's records, in the module's order; the shape operator's five, between
/// `triangle_curvature` and `curvature_spread_angle` in the module, are declared in `shape.rs`.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    use super::shape::{
        isotropic_curvature, normal_curvature, principal_curvatures, principal_direction,
        triangle_shape_operator,
    };
    records![
        width_at,
        propagate,
        normal_spread_angle,
        normal_spread_angle_small,
        curvature_sign,
        surface_spread_angle,
        edge_curvature,
        triangle_curvature,
        triangle_shape_operator,
        normal_curvature,
        principal_curvatures,
        principal_direction,
        isotropic_curvature,
        curvature_spread_angle
    ]
}
