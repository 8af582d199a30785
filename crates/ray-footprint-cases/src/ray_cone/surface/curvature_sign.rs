//! The proof of [`curvature_sign`](ray_footprint::ray_cone::curvature_sign): its record, where its
//! sign is decided, and its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::exact::{derivative, log_uniform, unit};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::small_vec3;
use crate::symmetry::Symmetry;
use glam::{DQuat, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ULP;
use shader_proptest::{Args, Value};

/// Whether the sign of `dot(dp_dx, dn_dx) + dot(dp_dy, dn_dy)` is decided: the sum lies beyond its
/// rounding error (6 terms, 8 ULP of their magnitudes) from zero.
fn curvature_sign_decided(&(dp_dx, dp_dy, dn_dx, dn_dy): &(Vec3, Vec3, Vec3, Vec3)) -> bool {
    let sum = dp_dx.dot(dn_dx) + dp_dy.dot(dn_dy);
    let terms = (dp_dx * dn_dx).abs().element_sum() + (dp_dy * dn_dy).abs().element_sum();
    sum.abs() > 8.0 * ULP * terms
}

/// The record of `rf_curvature_sign`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    Record::new(
        Module::RayCone,
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
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "every derivative turned: the same",
        |&(dp_dx, dp_dy, dn_dx, dn_dy): &(Vec3, Vec3, Vec3, Vec3), r| {
            (r * dp_dx, r * dp_dy, r * dn_dx, r * dn_dy)
        },
        |sign: f32, _| sign,
    ))
    .symmetry(Symmetry::scale(
        "the position derivatives scaled by s: the same",
        |&(dp_dx, dp_dy, dn_dx, dn_dy): &(Vec3, Vec3, Vec3, Vec3), s| (dp_dx * s, dp_dy * s, dn_dx, dn_dy),
        |sign: f32, _| sign,
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped (x and y derivatives exchanged): the same",
        |&(dp_dx, dp_dy, dn_dx, dn_dy): &(Vec3, Vec3, Vec3, Vec3)| (dp_dy, dp_dx, dn_dy, dn_dx),
        |sign: f32| sign,
    ))
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

/// A quadric patch `z = (k1 x^2 + k2 y^2) / 2` seen from above, in a random orientation, and two
/// pixel steps on it.
#[derive(Clone, Debug)]
struct Patch {
    curvatures: (f64, f64),
    point: DVec2,
    steps: [DVec2; 2],
    rotation: DQuat,
}

impl Patch {
    fn strategy() -> BoxedStrategy<Patch> {
        let step = || {
            (log_uniform(-3.0, 0.0), 0.0f64..6.3)
                .prop_map(|(length, angle)| DVec2::from_angle(angle) * length)
        };
        (
            log_uniform(-1.0, 1.0),
            log_uniform(-1.0, 1.0),
            any::<bool>(),
            (-0.05f64..0.05, -0.05f64..0.05),
            (step(), step()),
            (unit(), 0.0f64..6.3),
        )
            .prop_map(|(k1, k2, concave, (x, y), (a, b), (axis, angle))| {
                let sign = if concave { 1.0 } else { -1.0 };
                Patch {
                    curvatures: (sign * k1, sign * k2),
                    point: DVec2::new(x, y),
                    steps: [a, b],
                    rotation: DQuat::from_axis_angle(axis, angle),
                }
            })
            .boxed()
    }

    /// The point of the patch over `q` and the unit normal there (facing +z, the viewer).
    fn surface(&self, q: DVec2) -> (DVec3, DVec3) {
        let (k1, k2) = self.curvatures;
        let position = DVec3::new(q.x, q.y, 0.5 * (k1 * q.x * q.x + k2 * q.y * q.y));
        (position, DVec3::new(-k1 * q.x, -k2 * q.y, 1.0).normalize())
    }

    /// The position and normal differentials of a step, exactly (central differences), rotated.
    fn differentials(&self, step: DVec2) -> (Vec3, Vec3) {
        let position = derivative(|h| self.surface(self.point + step * h).0, 1.0e-6, 1.0).value;
        let normal = derivative(|h| self.surface(self.point + step * h).1, 1.0e-6, 1.0).value;
        (
            (self.rotation * position).as_vec3(),
            (self.rotation * normal).as_vec3(),
        )
    }
}

/// The reference of `rf_curvature_sign`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "quadric patches z = (k1 x^2 + k2 y^2) / 2 seen from above with k1, k2 of one sign: the exact position and normal derivatives along two pixel steps give -1 for a bowl (concave), +1 for a dome (convex) (RTG Eq. 33)",
        Patch::strategy,
        |patch, curvature_sign| {
            let (dp_dx, dn_dx) = patch.differentials(patch.steps[0]);
            let (dp_dy, dn_dy) = patch.differentials(patch.steps[1]);
            let got = curvature_sign((dp_dx, dp_dy, dn_dx, dn_dy));
            let expected = -patch.curvatures.0.signum();
            // dot(dp, dn) = -II(step, step), of the curvatures' sign; either answer is right only
            // where the f32 sum lies within its rounding (gamma(6) of its terms) of 0.
            let sum = dp_dx.as_dvec3().dot(dn_dx.as_dvec3()) + dp_dy.as_dvec3().dot(dn_dy.as_dvec3());
            let terms = (dp_dx * dn_dx).abs().element_sum() + (dp_dy * dn_dy).abs().element_sum();
            let bound = if sum.abs() <= gamma(6) * f64::from(terms) { 2.0 } else { 0.0 };
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
