//! Records of `ray_cone`: Refraction and roughness.

use super::enclosure::{self, refraction_decided};
use super::strategy::{eta, ray_cone};
use super::{reference, RefractArgs, MODULE};
use crate::degenerate::{cone, grazing, same, value, Row, HEAD_ON, IN_PLANE};
use crate::record::Record;
use crate::strategy::{angle, normal_and_direction, one_argument, scalar};
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone::{
    self as rc, RayCone, RefractedRayCone, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD, MIN_ROUGHNESS_DENOMINATOR,
};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;

/// A unit direction 30 degrees from the normal `+z`, towards it.
const THIRTY_DEGREES: Vec3 = Vec3::new(0.5, 0.0, -0.866_025_4);

/// Why a refraction's case may be ill-conditioned ([`refraction_decided`]).
const REFRACTION_UNDECIDED: &str = "within rounding of grazing or of the critical angle: which side of \
    the normal the ray meets, or whether it is totally internally reflected, may go either way";

/// The agreement cases of both refractions: a cone, a normal on either side, a direction, a
/// normal spread and an index ratio.
fn refraction_cases() -> BoxedStrategy<RefractArgs> {
    (ray_cone(), normal_and_direction(), any::<bool>(), angle(), eta())
        .prop_map(|(cone, (n, d), behind, beta, eta)| (cone, if behind { -n } else { n }, d, beta, eta))
        .boxed()
}

/// The degenerate rows both refractions share: inputs that their conventions and clamps turn into
/// others.
fn refraction_conventions() -> Vec<Row<RefractArgs>> {
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

/// `rf_refract_ray_cone`: the enclosure of the refracted cone (the hull of both branches where
/// the normal's side or total internal reflection is within rounding of changing).
pub fn refract_ray_cone() -> Record<RefractArgs, RefractedRayCone> {
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "refract_ray_cone",
        |(cone, n, d, beta, eta)| rc::refract_ray_cone(cone, n, d, beta, eta),
        refraction_cases,
    )
    .conditioned(REFRACTION_UNDECIDED, refraction_decided)
    .enclosure(enclosure::refract_ray_cone)
    .reference(reference::refract_flat())
    .reference(reference::refract_curved())
    .reference(reference::refract_index_one())
    .reference(reference::refract_first_order())
    .reference(reference::refract_optix())
    .reference(reference::refract_negated())
    .reference(reference::refract_total_internal_reflection())
    .fuzz(|d| (d.cone(), d.unit(), d.unit(), d.angle(), d.scalar()))
    .degenerate(
        [
            value(
                "normal incidence, flat, no spread (eta 1.5)",
                "(width, 0), not reflected",
                (cone(0.5, 0.0), z, HEAD_ON, 0.0, 1.5),
                vec![0.5, 0.0, 0.0],
            ),
            value(
                "zero cone",
                "zero cone",
                (cone(0.0, 0.0), z, THIRTY_DEGREES, 0.0, 1.5),
                vec![0.0, 0.0, 0.0],
            ),
            value(
                "central ray past the critical angle (sin i = 0.8, eta 1.5)",
                "the reflected cone (width, spread + 2 beta), flag set",
                (cone(0.25, 0.125), z, Vec3::new(0.8, 0.0, -0.6), 0.0625, 1.5),
                vec![0.25, 0.25, 1.0],
            ),
            same(
                "grazing (|dot(n, d)| = 1e-6), eta 0.5",
                "as a direction in the surface plane: both boundary rays land at |cos| = MIN_COS",
                (cone(0.01, 0.002), z, grazing(), 0.0, 0.5),
                (cone(0.01, 0.002), z, IN_PLANE, 0.0, 0.5),
            ),
            same(
                "spread wider than the surface allows (3.5 at normal incidence)",
                "as spread 2 MAX_INCIDENCE_ANGLE (both boundary rays graze)",
                (cone(0.01, 3.5), z, HEAD_ON, 0.0, 1.5),
                (cone(0.01, 2.0 * MAX_INCIDENCE_ANGLE), z, HEAD_ON, 0.0, 1.5),
            ),
        ]
        .into_iter()
        .chain(refraction_conventions())
        .collect(),
    )
}

/// `rf_refract_sagittal_cone`: the enclosure of the sagittal section.
pub fn refract_sagittal_cone() -> Record<RefractArgs, RayCone> {
    let z = Vec3::Z;
    let past_critical = Vec3::new(0.8, 0.0, -0.6);
    Record::new(
        MODULE,
        "refract_sagittal_cone",
        |(cone, n, d, beta, eta)| rc::refract_sagittal_cone(cone, n, d, beta, eta),
        refraction_cases,
    )
    .conditioned(REFRACTION_UNDECIDED, refraction_decided)
    .enclosure(enclosure::refract_sagittal_cone)
    .reference(reference::sagittal_curved())
    .reference(reference::sagittal_normal_incidence())
    .reference(reference::sagittal_total_internal_reflection())
    .fuzz(|d| (d.cone(), d.unit(), d.unit(), d.angle(), d.scalar()))
    .degenerate(
        [
            value(
                "normal incidence, flat, no spread (eta 1.5)",
                "(width, 0)",
                (cone(0.5, 0.0), z, HEAD_ON, 0.0, 1.5),
                vec![0.5, 0.0],
            ),
            value(
                "zero cone",
                "zero cone",
                (cone(0.0, 0.0), z, THIRTY_DEGREES, 0.0, 1.5),
                vec![0.0, 0.0],
            ),
            value(
                "central ray past the critical angle (sin i = 0.8, eta 1.5)",
                "the reflected section (width, spread + 2 cos i beta)",
                (cone(0.25, 0.125), z, past_critical, 0.0625, 1.5),
                vec![0.25, 0.125 + 2.0 * 0.6 * 0.0625],
            ),
            value(
                "negative width (past a focus), 30 degrees, eta 1.5",
                "beta takes the width's sign: eta spread - (eta cos i - cos t) beta",
                (cone(-0.01, 0.002), z, THIRTY_DEGREES, 0.01, 1.5),
                vec![
                    -0.01,
                    1.5 * 0.002 - (1.5 * 0.866_025_4 - (1.0f32 - 2.25 * 0.25).sqrt()) * 0.01,
                ],
            ),
            value(
                "ray in the surface plane (dot(n, d) = 0), eta 0.5",
                "eta spread - cos t beta, cos t = sqrt(1 - eta^2)",
                (cone(0.01, 0.002), z, IN_PLANE, 0.01, 0.5),
                vec![0.01, 0.5 * 0.002 - 0.75f32.sqrt() * 0.01],
            ),
        ]
        .into_iter()
        .chain(refraction_conventions())
        .collect(),
    )
}

/// `rf_roughness_spread_angle`: the enclosure of the spread.
pub fn roughness_spread_angle() -> Record<(f32,), f32> {
    Record::new(
        MODULE,
        "roughness_spread_angle",
        |(r,)| rc::roughness_spread_angle(r),
        || {
            let roughness = one_of![
                4 => uniform(0.0, 1.0),
                1 => Just(0.0f32),
                1 => Just(1.0f32),
                1 => uniform(0.99, 1.0),
                1 => scalar(),
            ];
            one_argument(roughness)
        },
    )
    .enclosure(|&(r,)| vec![enclosure::roughness_spread_angle(r)])
    .reference(reference::roughness_closed_form())
    .reference(reference::roughness_small())
    .reference(reference::roughness_monotone())
    .fuzz(|d| (d.scalar(),))
    .range(0.0, 142.0, "roughness spread")
    .degenerate(vec![
        value("roughness 0", "0", (0.0,), vec![0.0]),
        value(
            "roughness 1",
            "2 sqrt(0.5 / MIN_ROUGHNESS_DENOMINATOR), about 141.4",
            (1.0,),
            vec![2.0 * (0.5 / MIN_ROUGHNESS_DENOMINATOR).sqrt()],
        ),
        same("negative roughness", "as roughness 0", (-0.5,), (0.0,)),
        same("roughness 2", "as roughness 1", (2.0,), (1.0,)),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![refract_ray_cone, refract_sagittal_cone, roughness_spread_angle]
}
