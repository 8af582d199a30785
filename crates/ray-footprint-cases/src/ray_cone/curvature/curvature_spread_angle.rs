//! The proof of [`curvature_spread_angle`](ray_footprint::ray_cone::curvature_spread_angle): its
//! record, its error bound, its case strategy and its reference.

use crate::degenerate::{direction_at, grazing, same, value, HEAD_ON, IN_PLANE};
use crate::exact::{signed_log, towards, unit};
use crate::ray_cone::bound::{clamped_cos, unit_excess};
use crate::ray_cone::plane_of_incidence::{reflected_first_order, step, Surface};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{normal_and_direction, scalar};
use crate::symmetry::Symmetry;
use glam::{DVec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{dot_error, ulps};
use shader_proptest::{Args, Value};

/// The record of `rf_curvature_spread_angle`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
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
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the normal and the ray turned: the same",
        |&(curvature, width, normal, direction): &(f32, f32, Vec3, Vec3), r| (curvature, width, r * normal, r * direction),
        |spread: f32, _| spread,
    ))
    .symmetry(Symmetry::scale(
        "lengths scaled by s (the width by s, the curvature by 1/s): the same",
        |&(curvature, width, normal, direction): &(f32, f32, Vec3, Vec3), s| (curvature / s, width * s, normal, direction),
        |spread: f32, _| spread,
    ))
    .symmetry(Symmetry::exchange(
        "the normal and the ray both reversed: the same",
        |&(curvature, width, normal, direction): &(f32, f32, Vec3, Vec3)| (curvature, width, -normal, -direction),
        |spread: f32| spread,
    ))
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

/// Error of [`rc::curvature_spread_angle`] returning `expected`: relative, two products and a
/// division (5 ULP with the mirror's), and the rounding of `dot(normal, direction)` over the
/// clamped `|cos|`. Where the dot product lies within its rounding of 0, the device may find the
/// ray on the other side of the normal and return `-expected`, which is as right: 2 `|expected|`
/// more.
pub fn curvature_spread_angle_error(normal: Vec3, direction: Vec3, expected: f32) -> f32 {
    let dot_rounding = dot_error(normal, direction);
    let error = ulps(5.0, expected) + expected.abs() * dot_rounding / clamped_cos(normal, direction);
    if normal.dot(direction).abs() <= dot_rounding {
        error + 2.0 * expected.abs()
    } else {
        error
    }
}

/// `direction`, tilted by 1e-5 towards `-normal` when it lies within the rounding of
/// `dot(normal, direction)` of the surface plane. There either side is right, the tolerance of
/// [`curvature_spread_angle_error`] allows either sign, and the check could not catch a wrong one;
/// tilted, the ray meets the normal's side, still inside the `MIN_COS` clamp. The degenerate table
/// covers rays exactly in the plane.
pub(crate) fn off_the_plane(normal: Vec3, direction: Vec3) -> Vec3 {
    if normal.dot(direction).abs() <= dot_error(normal, direction) {
        (direction - 1.0e-5 * normal).normalize()
    } else {
        direction
    }
}

/// The reference of `rf_curvature_spread_angle`.
fn reference() -> Reference<(f32, f32, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "a sphere of radius 1 / |k| (stored normals outward for k > 0, inward for k < 0) hit from outside or inside: the spread between the exactly reflected boundary rays of a zero-spread cone of width w, to first order (f64 central differences), in the plane of incidence",
        || {
            (signed_log(-2.0, 2.0), signed_log(-4.0, 1.0), unit(), 0.05f64..1.0, 0.0f64..6.3, any::<bool>()).boxed()
        },
        |&(k, w, normal, cosine, angle, behind), curvature_spread_angle| {
            let d = towards(normal, cosine, angle);
            let (k, w, n, d) = (k as f32, w as f32, normal.as_vec3(), (if behind { -d } else { d }).as_vec3());
            let got = curvature_spread_angle((k, w, n, d));
            let (n64, d64) = (n.as_dvec3().normalize(), d.as_dvec3().normalize());
            let c = d64.dot(n64);
            // The plane of incidence with +y on the ray's side; the sphere is convex towards the
            // ray where it comes from the side its outward normal sign(k) n points to.
            let y = n64 * -c.signum();
            let x = (d64 - y * d64.dot(y)).try_normalize().unwrap_or_else(|| y.any_orthonormal_vector());
            let incoming = DVec2::new(d64.dot(x), d64.dot(y)).normalize();
            let curvature = -f64::from(k) * c.signum();
            let width = f64::from(w);
            let beta = reflected_first_order(
                Surface { curvature },
                incoming,
                0.0,
                (width, 0.0),
                step((width, 0.0), 0.0, curvature, c.abs()),
            );
            // 2 k w / dn: two roundings; dn = -dot(n, d) is off by the dot product's rounding
            // (gamma(3) of its terms) and by the inputs' distance from unit length, relatively.
            let terms = (n.as_dvec3() * d.as_dvec3()).abs().element_sum();
            let relative = gamma(2) + gamma(3) * terms / c.abs() + unit_excess(n, d);
            Some(Deviation::within(
                f64::from(got),
                beta.value.y,
                relative * beta.value.y.abs() + beta.error,
            ))
        },
    )
}
