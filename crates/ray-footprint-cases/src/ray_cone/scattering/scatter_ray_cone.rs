//! The proof of [`scatter_ray_cone`](ray_footprint::ray_cone::scatter_ray_cone): its record, its
//! error bound, its case strategy and its references, a reflection about a normal that turns with
//! the shading frame and a direction that turns with it, each traced exactly.

use crate::conditioning::WELL_CONDITIONED;
use crate::degenerate::{cone, same, value, HEAD_ON, IN_PLANE};
use crate::exact::{derivative, log_uniform, signed_log, Derivative};
use crate::ray_cone::bound::{clamped_cos, unit_excess, width_at_error, width_rounding};
use crate::ray_cone::curvature::curvature_spread_angle::{curvature_spread_angle_error, off_the_plane};
use crate::ray_cone::plane_of_incidence::{reflect, rotate, scatter_cone, step, Surface};
use crate::ray_cone::strategy::ray_cone;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{distance, normal_and_direction, scalar, unit_vec3};
use crate::symmetry::Symmetry;
use glam::{DVec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{
    self as rc, RayCone, LOBE_DIFFUSE, LOBE_REFLECTION, MAX_NORMAL_SPREAD, MIN_COS,
};
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::{dot_error, ulps};
use shader_proptest::{Args, Value};
use std::f64::consts::FRAC_PI_2;

/// A reference's cone and surface in f64: the width, the spread, the hit distance, the curvature
/// and the incidence cosine.
type ReferenceCone = (f64, f64, f64, f64, f64);

/// The arguments: the cone, the hit distance, the curvature, the normal, the direction, the
/// leaving direction, the lobe.
type Arguments = (RayCone, f32, f32, Vec3, Vec3, Vec3, u32);

/// The record of `rf_scatter_ray_cone`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    Record::new(
        Module::RayCone,
        "scatter_ray_cone",
        |(cone, t, curvature, normal, direction, leaving, lobe)| {
            rc::scatter_ray_cone(cone, t, curvature, normal, direction, leaving, lobe)
        },
        // Either lobe, or any other value (a reflection); the ray kept off the surface plane by
        // more than the dot product's rounding, as for `curvature_spread_angle`; any leaving
        // direction.
        || {
            let lobe = prop_oneof![2 => Just(LOBE_DIFFUSE), 2 => Just(LOBE_REFLECTION), 1 => any::<u32>()];
            (ray_cone(), distance(), scalar(), normal_and_direction(), any::<bool>(), unit_vec3(), lobe)
                .prop_map(|(cone, t, k, (n, d), behind, leaving, lobe)| {
                    let d = off_the_plane(n, d);
                    (cone, t, k, if behind { -n } else { n }, d, leaving, lobe)
                })
                .boxed()
        },
    )
    .conditioned(
        "the ray within rounding of the surface plane, or the width at the hit not known to 2^-10 (a \
         width cancelled by a converging spread): which side the ray meets, or the normal's turn \
         across the footprint, may go either way",
        |&(cone, t, _, normal, direction, _, _)| turn_well_conditioned(cone, t, normal, direction),
    )
    .bound(|&(cone, t, curvature, normal, direction, _, lobe), index, expected| {
        if index == 0 {
            width_error(cone, t, normal, direction, expected)
        } else {
            spread_error(cone, t, curvature, normal, direction, lobe, expected)
        }
    })
    .reference(reflection_reference())
    .reference(diffuse_reference())
    .symmetry(Symmetry::rotation(
        "the normal and both rays turned: the same",
        |&(cone, t, curvature, normal, direction, leaving, lobe): &Arguments, r| {
            (cone, t, curvature, r * normal, r * direction, r * leaving, lobe)
        },
        |cone: RayCone, _| cone,
    ))
    .symmetry(Symmetry::scale(
        "lengths scaled by s (the width and the distance by s, the curvature by 1/s): the width by s, the spread the same",
        |&(cone, t, curvature, normal, direction, leaving, lobe): &Arguments, s| {
            let scaled = RayCone {
                width: cone.width * s,
                ..cone
            };
            (scaled, t * s, curvature / s, normal, direction, leaving, lobe)
        },
        |cone: RayCone, s| RayCone {
            width: cone.width / s,
            ..cone
        },
    ))
    .symmetry(Symmetry::exchange(
        "the stored normal and the curvature both flipped: the same",
        |&(cone, t, curvature, normal, direction, leaving, lobe): &Arguments| {
            (cone, t, -curvature, -normal, direction, leaving, lobe)
        },
        |cone: RayCone| cone,
    ))
    .fuzz(|d| (d.cone(), d.distance(), d.scalar(), d.unit(), d.unit(), d.unit(), d.uint()))
    .degenerate(vec![
        value(
            "diffuse on a flat surface (curvature 0), head on, leaving along the normal",
            "(width + spread t, 0): a beam as wide as the footprint",
            (cone(0.0, 0.001), 3.0, 0.0, z, HEAD_ON, z, LOBE_DIFFUSE),
            vec![0.003, 0.0],
        ),
        value(
            "diffuse on a flat surface, 60 degrees from the normal, leaving along the normal",
            "(2 (width + spread t), 0): the footprint, 1 / cos 60° long, seen from above",
            (cone(0.0, 0.001), 3.0, 0.0, z, sixty_degrees(), z, LOBE_DIFFUSE),
            vec![0.006, 0.0],
        ),
        value(
            "reflection on a flat surface (curvature 0), leaving as a mirror's",
            "(width + spread t, spread): a planar mirror",
            (cone(0.0, 0.001), 3.0, 0.0, z, HEAD_ON, z, LOBE_REFLECTION),
            vec![0.003, 0.001],
        ),
        value(
            "ray in the surface plane (dot(n, d) = +0), diffuse leaving along the ray",
            "(w, k w / MIN_COS): dn = 0 counts as the normal's side; the footprint seen along the ray is the cone's section",
            (cone(1.0e-5, 0.0), 0.0, 0.5, z, IN_PLANE, IN_PLANE, LOBE_DIFFUSE),
            vec![1.0e-5, 0.5 * 1.0e-5 / MIN_COS],
        ),
        value(
            "ray in the surface plane (dot(n, d) = +0), reflection leaving along the ray",
            "(w, spread + 2 k w / MIN_COS)",
            (cone(1.0e-5, 0.25), 0.0, 0.5, z, IN_PLANE, IN_PLANE, LOBE_REFLECTION),
            vec![1.0e-5, 0.25 + 2.0 * (0.5 * 1.0e-5 / MIN_COS)],
        ),
        value(
            "the normal's turn beyond MAX_NORMAL_SPREAD (k w = 1e12), diffuse",
            "(w, MAX_NORMAL_SPREAD)",
            (cone(1.0, 0.0), 0.0, 1.0e12, z, HEAD_ON, z, LOBE_DIFFUSE),
            vec![1.0, MAX_NORMAL_SPREAD],
        ),
        value(
            "the normal's turn beyond -MAX_NORMAL_SPREAD past the f32 range (k w / MIN_COS = -1e40), reflection",
            "(w, spread - 2 MAX_NORMAL_SPREAD), finite",
            (cone(1.0e24, 0.25), 0.0, -1.0e12, z, IN_PLANE, IN_PLANE, LOBE_REFLECTION),
            vec![1.0e24, 0.25 - 2.0 * MAX_NORMAL_SPREAD],
        ),
        value(
            "zero width at the hit (a focus), diffuse",
            "(0, 0): the spread is forgotten",
            (cone(0.0, 0.25), 0.0, 0.5, z, HEAD_ON, z, LOBE_DIFFUSE),
            vec![0.0, 0.0],
        ),
        same(
            "a lobe that is neither (u32::MAX)",
            "as LOBE_REFLECTION",
            (cone(0.01, 0.25), 2.0, 0.5, z, HEAD_ON, z, u32::MAX),
            (cone(0.01, 0.25), 2.0, 0.5, z, HEAD_ON, z, LOBE_REFLECTION),
        ),
    ])
}

/// A unit direction 60 degrees from `-z`, towards `+x`.
fn sixty_degrees() -> Vec3 {
    Vec3::new(0.75f32.sqrt(), 0.0, -0.5)
}

/// Whether the normal's turn is well-conditioned: the ray off the surface plane by more than the
/// dot product's rounding, and the width at the hit, `width + spread_angle * t`, known to
/// [`WELL_CONDITIONED`] (or exactly 0).
fn turn_well_conditioned(cone: RayCone, t: f32, normal: Vec3, direction: Vec3) -> bool {
    let width = rc::width_at(cone, t);
    let side_known = normal.dot(direction).abs() > dot_error(normal, direction);
    let width_known = width == 0.0 && cone.width == 0.0
        || f64::from(width_at_error(cone, t)) <= WELL_CONDITIONED * f64::from(width.abs());
    side_known && width_known
}

/// Error of the width of [`rc::scatter_ray_cone`] returning `expected`: the width at the hit
/// ([`width_at_error`]) times the stretch, the width times the stretch's error
/// ([`stretch_error`]), and the product's rounding.
fn width_error(cone: RayCone, t: f32, normal: Vec3, direction: Vec3, expected: f32) -> f32 {
    let width = rc::width_at(cone, t);
    let stretch = if width == 0.0 { 0.0 } else { expected / width };
    stretch.abs() * width_at_error(cone, t)
        + width.abs() * stretch_error(normal, direction, stretch)
        + ulps(1.0, expected)
}

/// Error of the footprint's stretch `(|o - d| |o + r| + |o + d| |o - r|) / (4 |dn|)` on a device,
/// for unit vectors, whose components are at most 1 (`r` at most 3, each sum or difference at
/// most 4 long): `dn` off by the dot product's rounding `e`; each component of `r = d + 2 dn n` by
/// 8 ULP of 1 and `2 e`, of a sum or difference of two vectors by 2 ULP more; a length by `sqrt 3`
/// times its components' error and 5 ULP of 4 (the dot product and the square root); each product
/// by 4 times each factor's error and 1 ULP of 16, the sum by both and 1 ULP of 32; the quotient
/// by the numerator's error over `4 |dn|`, and `stretch` times 3 ULP (the division) and
/// `e / |dn|`.
fn stretch_error(normal: Vec3, direction: Vec3, stretch: f32) -> f32 {
    let epsilon = f32::EPSILON;
    let facing_error = dot_error(normal, direction);
    let facing = clamped_cos(normal, direction);
    let component = 10.0 * epsilon + 2.0 * facing_error;
    let length = 3f32.sqrt() * component + 20.0 * epsilon;
    let numerator = 2.0 * (8.0 * length + 16.0 * epsilon) + 32.0 * epsilon;
    numerator / (4.0 * facing) + stretch.abs() * (3.0 * epsilon + facing_error / facing)
}

/// Error of the spread of [`rc::scatter_ray_cone`] returning `expected`. The normal's turn
/// `k w / dn` is half of [`rc::curvature_spread_angle`]'s `beta` for the same width, with its
/// relative error ([`curvature_spread_angle_error`], which also allows the other sign where the
/// dot product is within its rounding of 0), plus the width's own error times `|k / dn|`; where
/// the turn lies beyond `MAX_NORMAL_SPREAD` by more than that (or beyond the f32 range), both
/// clamp it to the same constant, and no two clamped turns differ by more than
/// `2 MAX_NORMAL_SPREAD`. A reflection doubles the turn (exactly) and adds the incoming
/// spread: one more rounding.
fn spread_error(
    cone: RayCone,
    t: f32,
    curvature: f32,
    normal: Vec3,
    direction: Vec3,
    lobe: u32,
    expected: f32,
) -> f32 {
    let width = rc::width_at(cone, t);
    let beta = rc::curvature_spread_angle(curvature, width, normal, direction);
    let beta_error = curvature_spread_angle_error(normal, direction, beta)
        + 2.0 * (curvature / clamped_cos(normal, direction)).abs() * width_at_error(cone, t);
    let turn = 0.5 * beta;
    let turn_error = 0.5 * beta_error;
    let clamped = !turn.is_finite() || turn.abs() - turn_error > MAX_NORMAL_SPREAD;
    let turn_error = if clamped {
        0.0
    } else {
        turn_error.min(2.0 * MAX_NORMAL_SPREAD)
    };
    if lobe == LOBE_DIFFUSE {
        turn_error
    } else {
        2.0 * turn_error + ulps(1.0, expected)
    }
}

/// The first order in the cone's size of the cone `(w, s)` meeting `surface` after `t` with the
/// central direction `d`, each boundary ray scattered by `scatter` (from its incoming direction
/// and its normal), measured across the scattered central ray with the sides in a reflection's
/// order: `(width, spread)` in the plane of incidence.
fn scattered_first_order(
    surface: Surface,
    d: DVec2,
    t: f64,
    (w, s): (f64, f64),
    scatter: impl Fn(DVec2, DVec2) -> Option<DVec2>,
) -> Derivative<DVec2> {
    let cosine = -d.y;
    let scattered = |h: f64| {
        scatter_cone(surface, d, t, (h * w, h * s), &scatter, |_, central| {
            rotate(central, -FRAC_PI_2)
        })
        .map_or(DVec2::NAN, |cone| DVec2::new(cone.width, cone.spread))
    };
    derivative(scattered, step((w, s), t, surface.curvature, cosine), 1.0)
}

/// A reference's case: the cone `(w, s)` meeting a surface of curvature `k` after `t` with
/// incidence cosine `cosine` and leaving in the plane of incidence along `leaving(d, n)` (from the
/// central direction and the normal there, 2-D), as the function's f32 arguments (normal `+z`,
/// the plane of incidence x-z, the ray towards `-z`), with the central direction in 2-D.
fn reference_arguments(
    (w, s, t, k, cosine): ReferenceCone,
    lobe: u32,
    leaving: impl Fn(DVec2, DVec2) -> DVec2,
) -> (Arguments, DVec2) {
    let sine = (1.0 - cosine * cosine).sqrt();
    let direction = Vec3::new(sine as f32, 0.0, -cosine as f32);
    let d = DVec2::new(f64::from(direction.x), f64::from(direction.z)).normalize();
    let out = leaving(d, DVec2::Y);
    let cone = RayCone {
        width: w as f32,
        spread_angle: s as f32,
    };
    let out3 = Vec3::new(out.x as f32, 0.0, out.y as f32);
    ((cone, t as f32, k as f32, Vec3::Z, direction, out3, lobe), d)
}

/// Whether the normal's turn `turn` lies where the function clamps it: the degenerate table's
/// rows, not a reference's, show what it does there.
fn beyond_the_clamp(turn: f64) -> bool {
    turn.abs() >= f64::from(MAX_NORMAL_SPREAD)
}

/// The deviation of `got` from the first order `expected` of a case whose leaving direction lies
/// in the plane of incidence, where the footprint's axes are the in-plane width and the width
/// across the plane, `width_at` itself: the longest of the two, with the width's sign.
///
/// Bounds of the f32 evaluation: the width at the hit ([`width_rounding`]) times the stretch; the
/// stretch's roundings, about 100 `U` of its numerator over `|dn|` and 4 `U` of itself, and the
/// f32 vectors' distance from unit length; the spread's ([`spread_bound`]).
fn deviation(
    arguments: Arguments,
    got: RayCone,
    expected: Derivative<DVec2>,
    turn: f64,
    factor: f64,
) -> Deviation {
    let (cone, t, k, normal, direction, leaving, _) = arguments;
    let (w, s) = (f64::from(cone.width), f64::from(cone.spread_angle));
    let at_hit = w + s * f64::from(t);
    let longest = expected.value.x.abs().max(at_hit.abs()).copysign(at_hit);
    let stretch = if at_hit == 0.0 {
        0.0
    } else {
        (longest / at_hit).abs()
    };
    let dn = f64::from(clamped_cos(normal, direction));
    let excess = unit_excess(normal, direction) + unit_excess(leaving, leaving);
    let stretch_bound = 100.0 * U / dn + stretch * (4.0 * U + 4.0 * excess / dn);
    let width_bound =
        stretch * width_rounding(w, s, f64::from(t)) + at_hit.abs() * stretch_bound + expected.error;
    let width = Deviation::within(f64::from(got.width), longest, width_bound);
    let spread_bound =
        spread_bound((cone, t, k, normal, direction), turn, factor, got.spread_angle) + expected.error;
    let spread = Deviation::within(f64::from(got.spread_angle), expected.value.y, spread_bound);
    width.and(spread)
}

/// The bound of a reference's spread for the normal's turn `turn` (exact), taken `factor` times
/// (2 for a reflection, 1 for a diffuse lobe), and the f32 result `got`: the width at the hit off
/// by its rounding ([`width_rounding`]) times `|k / dn|`; the turn's product and division
/// (`gamma(2)`) and the direction's distance from unit length in `dn` (the dot product with `+z`
/// is exact); a reflection's sum, one rounding of the result.
fn spread_bound(arguments: (RayCone, f32, f32, Vec3, Vec3), turn: f64, factor: f64, got: f32) -> f64 {
    let (cone, t, k, normal, direction) = arguments;
    let dn = f64::from(clamped_cos(normal, direction));
    let width = width_rounding(f64::from(cone.width), f64::from(cone.spread_angle), f64::from(t));
    let turn_error =
        (f64::from(k) / dn).abs() * width + turn.abs() * (gamma(2) + unit_excess(normal, direction));
    factor * turn_error + gamma(1) * f64::from(got).abs()
}

/// The strategy of a reference's `(w, s, t, k, cosine)` and one angle in `angles`.
fn reference_cases(angles: std::ops::Range<f64>) -> BoxedStrategy<(ReferenceCone, f64)> {
    let curvature = prop_oneof![1 => Just(0.0f64), 3 => signed_log(-2.0, 1.0)];
    let spread = prop_oneof![1 => Just(0.0f64), 3 => signed_log(-5.0, -2.0)];
    let cone = (
        signed_log(-4.0, -1.0),
        spread,
        log_uniform(-2.0, 2.0),
        curvature,
        0.2f64..1.0,
    );
    (cone, angles).boxed()
}

/// A reference of `rf_scatter_ray_cone`: a reflection lobe.
fn reflection_reference() -> Reference<Arguments, RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a planar or spherical surface, each boundary ray reflected exactly about its own microfacet normal, tilted from its shading normal by a fixed angle mu in the plane of incidence (a normal drawn in the shading frame with the random numbers fixed): the spread between the reflected boundary rays and the longest axis of the footprint seen from the reflected central ray (in the plane: the width between the reflected boundary rays; across it: the width at the hit), to first order (f64 central differences in the cone's size)",
        || reference_cases(-0.3f64..0.3),
        |&(case, tilt), scatter_ray_cone| {
            let microfacet = |normal: DVec2| rotate(normal, tilt);
            let (arguments, d) = reference_arguments(case, LOBE_REFLECTION, |d, n| reflect(d, microfacet(n)));
            // The reflected central ray must leave above the surface.
            if reflect(d, microfacet(DVec2::Y)).y <= 0.05 {
                return None;
            }
            let (cone, t, k, ..) = arguments;
            let surface = Surface {
                curvature: f64::from(k),
            };
            let (w, s) = (f64::from(cone.width), f64::from(cone.spread_angle));
            let expected = scattered_first_order(surface, d, f64::from(t), (w, s), |incoming, normal| {
                Some(reflect(incoming, microfacet(normal)))
            });
            let turn = 0.5 * (expected.value.y - s);
            if beyond_the_clamp(turn) {
                return None;
            }
            Some(deviation(arguments, scatter_ray_cone(arguments), expected, turn, 2.0))
        },
    )
}

/// A reference of `rf_scatter_ray_cone`: a diffuse lobe.
fn diffuse_reference() -> Reference<Arguments, RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a planar or spherical surface, each boundary ray leaving at a fixed angle phi from its own normal in the plane of incidence (a direction drawn in the shading frame with the random numbers fixed): the spread between the leaving boundary rays, whatever the incoming spread, and the longest axis of the footprint seen from the leaving central ray (in the plane: the width between the leaving boundary rays; across it: the width at the hit), to first order (f64 central differences in the cone's size)",
        || reference_cases(-1.4f64..1.4),
        |&(case, leaving_angle), scatter_ray_cone| {
            let (arguments, d) = reference_arguments(case, LOBE_DIFFUSE, |_, n| rotate(n, leaving_angle));
            let (cone, t, k, ..) = arguments;
            let surface = Surface {
                curvature: f64::from(k),
            };
            let (w, s) = (f64::from(cone.width), f64::from(cone.spread_angle));
            let expected = scattered_first_order(surface, d, f64::from(t), (w, s), |_, normal| {
                Some(rotate(normal, leaving_angle))
            });
            if beyond_the_clamp(expected.value.y) {
                return None;
            }
            Some(deviation(arguments, scatter_ray_cone(arguments), expected, expected.value.y, 1.0))
        },
    )
}
