//! What the references of the reflection and the refraction share: the surface hits they draw
//! (unit vectors and changes perpendicular to them), how far the f32 inputs lie from what the
//! formulas assume, and the changes of one axis.

use crate::exact::{log_uniform, towards, unit};
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives3, RayDiff};

/// A vector perpendicular to the unit `v`, of random direction and a length `10^[low, high)`.
fn perpendicular(v: DVec3, low: f64, high: f64) -> BoxedStrategy<DVec3> {
    (0.0f64..6.3, log_uniform(low, high))
        .prop_map(move |(angle, length)| crate::exact::tangent(v, angle) * length)
        .boxed()
}

/// A unit direction and a unit normal at `|cos|` 0.05 to 1 from either side, a differential whose
/// direction changes are perpendicular to the direction, and normal changes perpendicular to the
/// normal (as the derivatives of unit vectors are), all rounded to f32.
pub(crate) fn surface_hit() -> BoxedStrategy<(RayDiff, Vec3, Vec3, Derivatives3)> {
    (unit(), 0.05f64..1.0, 0.0f64..6.3, any::<bool>())
        .prop_flat_map(|(n, cosine, angle, behind)| {
            let d = towards(n, cosine, angle) * if behind { -1.0 } else { 1.0 };
            let origin = || (unit(), log_uniform(-4.0, 0.0)).prop_map(|(v, l)| v * l);
            (
                (
                    origin(),
                    origin(),
                    perpendicular(d, -4.0, -1.0),
                    perpendicular(d, -4.0, -1.0),
                ),
                (perpendicular(n, -4.0, 0.0), perpendicular(n, -4.0, 0.0)),
            )
                .prop_map(move |((a, b, c, e), (dn_dx, dn_dy))| {
                    let f = |v: DVec3| v.as_vec3();
                    (
                        RayDiff::new(f(a), f(b), f(c), f(e)),
                        f(d),
                        f(n),
                        Derivatives3::new(f(dn_dx), f(dn_dy)),
                    )
                })
        })
        .boxed()
}

/// How far the f32 inputs lie from what the formulas assume, relatively: unit `direction` and
/// `normal`, and changes perpendicular to them.
pub(crate) fn non_unit(diff: &RayDiff, direction: Vec3, normal: Vec3, dn: Derivatives3) -> f64 {
    let (d, n) = (direction.as_dvec3(), normal.as_dvec3());
    let along =
        |v: Vec3, unit: DVec3| v.as_dvec3().dot(unit.normalize()).abs() / v.as_dvec3().length().max(1.0e-300);
    (d.length() - 1.0).abs()
        + (n.length() - 1.0).abs()
        + along(diff.d_direction_dx, d).max(along(diff.d_direction_dy, d))
        + along(dn.dx, n).max(along(dn.dy, n))
}

/// The changes of one axis: origin, direction, normal.
pub(crate) fn changes(diff: &RayDiff, dn: Derivatives3, axis: usize) -> (DVec3, DVec3, DVec3) {
    let pick = |x: Vec3, y: Vec3| if axis == 0 { x } else { y }.as_dvec3();
    (
        pick(diff.d_origin_dx, diff.d_origin_dy),
        pick(diff.d_direction_dx, diff.d_direction_dy),
        pick(dn.dx, dn.dy),
    )
}
