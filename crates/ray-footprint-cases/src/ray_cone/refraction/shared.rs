//! What the two refractions share: their arguments, agreement cases, conditioning and convention
//! rows; the steps of their enclosures (the incidence, the refracted angle, the normal tilt, the
//! normal's orientation); and for their references, a refraction's f32 inputs traced exactly,
//! relative errors, and the cases at normal incidence that the OptiX Toolkit's thin form covers.

use crate::degenerate::{cone, same, Row, HEAD_ON};
use crate::ray_cone::plane_of_incidence::{rotated, scatter_cone, snell, Scattered, Surface};
use crate::ray_cone::strategy::ray_cone;
use crate::strategy::{angle, normal_and_direction, scalar};
use glam::{DVec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{RayCone, MAX_NORMAL_SPREAD, MIN_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval3, select, Interval, Interval2, IntervalVec};
use shader_proptest::one_of;

/// The arguments of `refract_ray_cone` and `refract_sagittal_cone`: cone, normal, direction, normal
/// spread, eta.
pub type RefractArgs = (RayCone, Vec3, Vec3, f32, f32);

/// A unit direction 30 degrees from the normal `+z`, towards it.
pub(crate) const THIRTY_DEGREES: Vec3 = Vec3::new(0.5, 0.0, -0.866_025_4);

/// Why a refraction's case may be ill-conditioned ([`refraction_decided`]).
pub(crate) const REFRACTION_UNDECIDED: &str =
    "within rounding of grazing or of the critical angle: which side of \
    the normal the ray meets, or whether it is totally internally reflected, may go either way";

/// Index ratios: ordinary, 1, glass in and out, 0, and anything in the domain.
fn eta() -> BoxedStrategy<f32> {
    one_of![
        4 => uniform(0.3, 3.0),
        1 => Just(1.0f32),
        1 => Just(1.5f32),
        1 => Just(1.0f32 / 1.5),
        1 => Just(0.0f32),
        1 => scalar(),
    ]
    .boxed()
}

/// The agreement cases of both refractions: a cone, a normal on either side, a direction, a
/// normal spread and an index ratio.
pub(crate) fn refraction_cases() -> BoxedStrategy<RefractArgs> {
    (ray_cone(), normal_and_direction(), any::<bool>(), angle(), eta())
        .prop_map(|(cone, (n, d), behind, beta, eta)| (cone, if behind { -n } else { n }, d, beta, eta))
        .boxed()
}

/// The degenerate rows both refractions share: inputs that their conventions and clamps turn into
/// others.
pub(crate) fn refraction_conventions() -> Vec<Row<RefractArgs>> {
    let z = Vec3::Z;
    vec![
        same(
            "normal facing away from the ray (dot(n, d) > 0)",
            "as the flipped normal with the negated normal spread",
            (cone(0.01, 0.002), -z, THIRTY_DEGREES, 0.01, 1.5),
            (cone(0.01, 0.002), z, THIRTY_DEGREES, -0.01, 1.5),
        ),
        same(
            "normal spread 10",
            "as MAX_NORMAL_SPREAD",
            (cone(0.01, 0.002), z, THIRTY_DEGREES, 10.0, 1.5),
            (cone(0.01, 0.002), z, THIRTY_DEGREES, MAX_NORMAL_SPREAD, 1.5),
        ),
        same(
            "negative eta",
            "as eta 0",
            (cone(0.01, 0.002), z, THIRTY_DEGREES, 0.01, -2.0),
            (cone(0.01, 0.002), z, THIRTY_DEGREES, 0.01, 0.0),
        ),
        same(
            "zero direction",
            "as normal incidence (d = -n)",
            (cone(0.5, 0.01), z, Vec3::ZERO, 0.01, 1.5),
            (cone(0.5, 0.01), z, HEAD_ON, 0.01, 1.5),
        ),
    ]
}

pub(crate) fn incidence_sin_cos(normal: Vec3, direction: Vec3, cosine: Interval) -> Interval2 {
    let tangential = interval3(direction) - interval3(normal) * cosine;
    let sin_cos = IntervalVec([tangential.dot(tangential).sqrt(), cosine.abs()]);
    let length = sin_cos.dot(sin_cos).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    let components = select(
        length.hi < min,
        length.lo < min,
        || vec![Interval::c(0.0), Interval::c(1.0)],
        || (sin_cos / length.at_least(min)).components(),
    );
    IntervalVec([components[0], components[1]])
}

pub(crate) fn refracted_sin_cos(incidence: Interval2, eta: f32) -> Interval2 {
    let [sin, cos] = incidence.0;
    let eta = Interval::exact(eta);
    let cos2 = cos * cos + ((Interval::c(1.0) - eta) * sin) * ((Interval::c(1.0) + eta) * sin);
    IntervalVec([(eta * sin).clamp_c(-1.0, 1.0), cos2.max_c(0.0).sqrt()])
}

/// `normal_tilt`: half the clamped normal spread, with the width's sign.
pub(crate) fn normal_tilt(width: f32, facing_spread: f32) -> Interval {
    let signed_half = if width < 0.0 { -0.5 } else { 0.5 };
    Interval::c(signed_half) * Interval::exact(facing_spread.clamp(-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD))
}

/// Whether both of `refract_ray_cone`'s decisions are certain: which side of the normal the ray
/// meets, and whether it is totally internally reflected. Within rounding of either (a grazing ray,
/// the critical angle) both answers are right and the flag's tolerance would be vacuous; those
/// cases are checked separately (the degenerate table, the edge-case suite).
pub(crate) fn refraction_decided(&(_, normal, direction, _, eta): &RefractArgs) -> bool {
    let cosine = interval3(normal).dot(interval3(direction));
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let sin_t = Interval::exact(eta.max(0.0)) * incidence.0[0];
    let side_decided = cosine.lo > 0.0 || cosine.hi <= 0.0;
    let reflection_decided = sin_t.lo > 1.0 || sin_t.hi <= 1.0;
    side_decided && reflection_decided
}

/// `facing` (a refraction for one normal orientation) with the normal spread as the ray sees it:
/// negated where the normal faces away from the ray, the hull of both where `dot(n, d)` is within
/// rounding of 0.
pub(crate) fn either_facing(
    args: &RefractArgs,
    facing: fn(&RefractArgs, Interval, f32) -> Vec<Interval>,
) -> Vec<Interval> {
    let &(_, normal, direction, beta, _) = args;
    let cosine = interval3(normal).dot(interval3(direction));
    select(
        cosine.lo > 0.0,
        cosine.hi > 0.0,
        || facing(args, cosine, -beta),
        || facing(args, cosine, beta),
    )
}

/// The f32 inputs of a refraction: the direction at `incidence` in the xz plane (normal +Z), the
/// cone, the normal spread and eta.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Case {
    pub(crate) direction: Vec3,
    pub(crate) cone: RayCone,
    pub(crate) normal_spread: f32,
    pub(crate) eta: f32,
}

impl Case {
    pub(crate) fn new(incidence: f64, width: f64, spread: f64, eta: f64) -> Case {
        Case {
            direction: Vec3::new(incidence.sin() as f32, 0.0, -incidence.cos() as f32),
            cone: RayCone {
                width: width as f32,
                spread_angle: spread as f32,
            },
            normal_spread: 0.0,
            eta: eta as f32,
        }
    }

    /// The incidence angle of the f32 direction, exactly.
    pub(crate) fn incidence(&self) -> f64 {
        f64::from(self.direction.x).atan2(-f64::from(self.direction.z))
    }

    /// The cone's boundary rays traced exactly through the interface of `curvature` (the plane of
    /// incidence is the xz plane), from the f32 inputs.
    pub(crate) fn trace(&self, curvature: f64) -> Option<Scattered> {
        let eta = f64::from(self.eta);
        let incidence = self.incidence();
        let cone = (f64::from(self.cone.width), f64::from(self.cone.spread_angle));
        scatter_cone(
            Surface { curvature },
            DVec2::new(incidence.sin(), -incidence.cos()),
            0.0,
            cone,
            |d, n| snell(d, n, eta),
            rotated,
        )
    }

    pub(crate) fn arguments(&self) -> RefractArgs {
        (self.cone, Vec3::Z, self.direction, self.normal_spread, self.eta)
    }
}

/// `|a - b| / |b|`.
pub(crate) fn relative(a: f32, b: f64) -> f64 {
    (f64::from(a) - b).abs() / b.abs()
}

/// Normal incidence on a curved surface: an index ratio, a curvature, `log10` of the width and a
/// spread, small enough for the OptiX Toolkit's thin form.
pub(crate) fn normal_incidence() -> BoxedStrategy<(f64, f64, f64, f64)> {
    (0.4f64..2.5, -10.0f64..10.0, -6.0f64..-3.0, -2.0e-3f64..2.0e-3).boxed()
}

/// The f32 arguments of a [`normal_incidence`] case: the cone head on at `+z`, the normal spread
/// `curvature * width` (the thin form's `k |w|`).
pub(crate) fn normal_incidence_args((eta, curvature, width, spread): (f64, f64, f64, f64)) -> RefractArgs {
    let width = 10f64.powf(width) as f32;
    let beta = (curvature * f64::from(width)) as f32;
    let cone = RayCone {
        width,
        spread_angle: spread as f32,
    };
    (cone, Vec3::Z, Vec3::NEG_Z, beta, eta as f32)
}
