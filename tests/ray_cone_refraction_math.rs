//! Refraction of ray cones and the spread from roughness, checked on the CPU against independent
//! constructions: the cone's two boundary rays traced exactly in f64 through flat and spherical
//! interfaces, the first-order formulas, the OptiX Toolkit's thin form, and the roughness mapping's
//! closed form. Each test prints the worst error it measured.

mod common;

use common::{worst_case, Rng};
use glam::{DVec2, Vec3};
use ray_footprint::ray_cone::{self as rc, RayCone};

/// The 2-D cross product `a.x b.y - a.y b.x`.
fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `v` turned counter-clockwise by `angle`.
fn rotate(v: DVec2, angle: f64) -> DVec2 {
    let (sin, cos) = angle.sin_cos();
    DVec2::new(v.x * cos - v.y * sin, v.x * sin + v.y * cos)
}

/// Snell's law for a unit direction `d` meeting a surface with unit normal `n` (facing the ray),
/// `eta = n_incident / n_transmitted`; `None` on total internal reflection.
fn snell(d: DVec2, n: DVec2, eta: f64) -> Option<DVec2> {
    let cos_i = -d.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| d * eta + n * (eta * cos_i - k.sqrt()))
}

/// An interface in the plane of incidence, through the origin with normal +y there: flat
/// (`curvature` 0) or a circle of radius `1 / |curvature|`, convex towards +y when `curvature > 0`.
#[derive(Clone, Copy)]
struct Interface {
    curvature: f64,
}

impl Interface {
    /// Where the ray `start + s * d` (s > 0) meets the interface nearest the origin, and the unit
    /// normal there (facing +y).
    fn hit(self, start: DVec2, d: DVec2) -> Option<(DVec2, DVec2)> {
        if self.curvature == 0.0 {
            let s = -start.y / d.y;
            return (s > 0.0).then(|| (start + d * s, DVec2::Y));
        }
        let radius = 1.0 / self.curvature;
        let centre = DVec2::new(0.0, -radius);
        let offset = start - centre;
        let b = offset.dot(d);
        let disc = b * b - (offset.length_squared() - radius * radius);
        if disc < 0.0 {
            return None;
        }
        let point = [-b - disc.sqrt(), -b + disc.sqrt()]
            .into_iter()
            .filter(|&s| s > 0.0)
            .map(|s| start + d * s)
            .min_by(|a, b| a.length().total_cmp(&b.length()))?;
        Some((point, (point - centre) / radius))
    }
}

/// The exact refraction of a cone at the origin, from its two boundary rays traced in f64.
struct Traced {
    width: f64,
    spread: f64,
    /// Angle by which the normal turns between the two boundary hits (positive where it spreads).
    normal_spread: f64,
    /// Smallest cosine at which a boundary ray meets the interface.
    min_landing_cos: f64,
    /// Smallest cosine between a refracted boundary ray and the normal at its hit.
    min_leaving_cos: f64,
}

/// Traces the cone of width `width` (> 0) and spread `spread` whose central ray meets `interface`
/// at the origin at incidence `incidence`: the boundary ray on side `s` starts `s * width / 2`
/// across the central ray, turned by `s * spread / 2`, is refracted exactly where it meets the
/// interface, and the refracted cone is measured across the exactly refracted central ray.
fn trace(interface: Interface, incidence: f64, width: f64, spread: f64, eta: f64) -> Option<Traced> {
    let d = DVec2::new(incidence.sin(), -incidence.cos());
    let across = rotate(d, std::f64::consts::FRAC_PI_2);
    let central = snell(d, DVec2::Y, eta)?;
    let boundary = |side: f64| {
        let direction = rotate(d, side * 0.5 * spread);
        let start = across * (side * 0.5 * width) - direction * 10.0 * width;
        let (point, normal) = interface.hit(start, direction)?;
        let refracted = snell(direction, normal, eta)?;
        let offset = cross(point, refracted) / cross(rotate(central, std::f64::consts::FRAC_PI_2), refracted);
        Some((
            refracted,
            normal,
            -direction.dot(normal),
            -refracted.dot(normal),
            offset,
        ))
    };
    let (upper, upper_normal, upper_landing, upper_leaving, upper_offset) = boundary(1.0)?;
    let (lower, lower_normal, lower_landing, lower_leaving, lower_offset) = boundary(-1.0)?;
    Some(Traced {
        width: upper_offset - lower_offset,
        spread: cross(lower, upper).atan2(lower.dot(upper)),
        normal_spread: -cross(lower_normal, upper_normal).atan2(lower_normal.dot(upper_normal)),
        min_landing_cos: upper_landing.min(lower_landing),
        min_leaving_cos: upper_leaving.min(lower_leaving),
    })
}

/// The f32 inputs of a case: the direction at `incidence` in the xz plane (normal +Z), the cone,
/// the normal spread and eta.
#[derive(Clone, Copy, Debug)]
struct Case {
    direction: Vec3,
    cone: RayCone,
    normal_spread: f32,
    eta: f32,
}

impl Case {
    fn new(incidence: f64, width: f64, spread: f64, eta: f64) -> Case {
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
    fn incidence(&self) -> f64 {
        f64::from(self.direction.x).atan2(-f64::from(self.direction.z))
    }

    /// The case traced exactly through `interface`, from its f32 inputs.
    fn trace(&self, interface: Interface) -> Option<Traced> {
        trace(
            interface,
            self.incidence(),
            f64::from(self.cone.width),
            f64::from(self.cone.spread_angle),
            f64::from(self.eta),
        )
    }

    /// The crate's refraction.
    fn refract(&self) -> rc::RefractedRayCone {
        rc::refract_ray_cone(self.cone, Vec3::Z, self.direction, self.normal_spread, self.eta)
    }
}

/// `|a - b| / |b|`.
fn relative(a: f32, b: f64) -> f64 {
    (f64::from(a) - b).abs() / b.abs()
}

/// Accepted cases per test.
const CASES: usize = 20_000;

/// Each of `N` errors' largest value over [`CASES`] accepted cases: `check` draws one case from a
/// generator seeded with `seed` (one generator for all draws), given how many were accepted before,
/// and returns its errors, or `None` to reject the draw.
fn worst_accepted<const N: usize>(
    seed: u64,
    mut check: impl FnMut(&mut Rng, usize) -> Option<[f64; N]>,
) -> [f64; N] {
    let mut rng = Rng(seed);
    let mut worst = [0.0f64; N];
    let mut accepted = 0;
    while accepted < CASES {
        if let Some(errors) = check(&mut rng, accepted) {
            for (worst, error) in worst.iter_mut().zip(errors) {
                *worst = worst.max(error);
            }
            accepted += 1;
        }
    }
    worst
}

/// A case whose boundary rays land and leave at cosines of at least 0.05 (away from grazing and
/// from the critical angle, where the f32 inputs' rounding is amplified by up to 20 per cosine).
fn well_conditioned(traced: &Traced) -> bool {
    traced.min_landing_cos >= 0.05 && traced.min_leaving_cos >= 0.05
}

/// Flat interfaces: the construction is exact geometry, so on the same (f32) inputs the crate
/// agrees with the traced boundary rays to f32 rounding: about 30 operations, amplified by at most
/// 20 x 20 (the two cosines of [`well_conditioned`]), bound the relative error by
/// 30 * 400 * 6e-8 < 1e-3.
#[test]
fn flat_refraction_matches_the_traced_boundary_rays() {
    let [worst_width, worst_spread] = worst_accepted(0x5eed_0001, |rng, accepted| {
        let spread = rng.log_range(-7.0, 0.0) * if rng.next() < 0.2 { -1.0 } else { 1.0 };
        let eta = [rng.range(0.4, 0.95), rng.range(1.05, 2.5), 1.0 / 1.5, 1.5][accepted % 4];
        let case = Case::new(rng.range(0.0, 1.5), rng.log_range(-6.0, 3.0), spread, eta);
        let traced = case
            .trace(Interface { curvature: 0.0 })
            .filter(well_conditioned)?;
        let refracted = case.refract();
        assert!(!refracted.total_internal_reflection);
        let width_error = relative(refracted.cone.width, traced.width);
        let spread_error = relative(refracted.cone.spread_angle, traced.spread);
        assert!(
            width_error < 1.0e-3 && spread_error < 1.0e-3,
            "{case:?}: {:?} vs ({}, {})",
            refracted.cone,
            traced.width,
            traced.spread
        );
        Some([width_error, spread_error])
    });
    println!(
        "flat interface, {CASES} cones: worst relative error width {worst_width:.2e}, spread {worst_spread:.2e}"
    );
}

/// Spherical interfaces (convex and concave, radius 1): the crate refracts the boundary rays where
/// they meet the tangent plane, at normals tilted by -+beta/2 (beta from the traced hits); the
/// sphere's boundary hits differ from those by its sag, so the two agree to second order in the
/// footprint `x = width / cos i` measured in radii. The bound `4 x` (relative) holds with room for
/// the inputs' cosines (>= 0.05) and is far below the first-order effect `beta ~ x` it checks.
#[test]
fn curved_refraction_matches_the_traced_boundary_rays() {
    let [worst_width, worst_spread] = worst_accepted(0x5eed_0002, |rng, accepted| {
        let curvature = if rng.next() < 0.5 { 1.0 } else { -1.0 };
        let eta = [rng.range(0.4, 0.95), rng.range(1.05, 2.5)][accepted % 2];
        let mut case = Case::new(
            rng.range(0.0, 1.2),
            rng.log_range(-5.0, -2.0),
            rng.range(-0.02, 0.02),
            eta,
        );
        let traced = case.trace(Interface { curvature }).filter(well_conditioned)?;
        case.normal_spread = traced.normal_spread as f32;
        let footprint = f64::from(case.cone.width) / case.incidence().cos();
        let refracted = case.refract();
        let width_error = relative(refracted.cone.width, traced.width);
        let spread_error = (f64::from(refracted.cone.spread_angle) - traced.spread).abs()
            / (traced.spread.abs() + traced.normal_spread.abs());
        assert!(
            width_error < 4.0 * footprint + 1.0e-3 && spread_error < 4.0 * footprint + 1.0e-3,
            "k {curvature} {case:?}: {:?} vs ({}, {}), beta {}",
            refracted.cone,
            traced.width,
            traced.spread,
            traced.normal_spread
        );
        Some([width_error / footprint, spread_error / footprint])
    });
    println!(
        "unit spheres, {CASES} cones: worst relative error / footprint: width {worst_width:.3}, spread {worst_spread:.3}"
    );
}

/// Leading relative corrections to the first-order refraction of a cone of half spread `h` on a
/// flat interface (incidence `i`, index ratio `eta`), from the Taylor expansions of the exact maps:
/// with `tau(theta) = asin(eta sin theta)` and its derivatives `d1, d2, d3` at `i`, the spread
/// `tau(i + h) - tau(i - h)` is `2 h d1 (1 + (h^2 / 6) d3 / d1)`, and the width
/// `w cos(h) (f(i + h) + f(i - h)) / 2` with `f(theta) = cos tau / (cos theta cos(tau - t))` is
/// `w (cos t / cos i) (1 + (h^2 / 2) (f'' / f - 1))`. Returns the two corrections' magnitudes.
fn second_order_corrections(incidence: f64, eta: f64, h: f64) -> (f64, f64) {
    let sin_t = eta * incidence.sin();
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let tan_t = sin_t / cos_t;
    let d1 = eta * incidence.cos() / cos_t;
    let d2 = tan_t * (d1 * d1 - 1.0);
    let d3_over_d1 = (d1 * d1 - 1.0) * (1.0 / (cos_t * cos_t) + 2.0 * tan_t * tan_t);
    let g1 = -tan_t * d1 + incidence.tan();
    let g2 = -d1 * d1 / (cos_t * cos_t) - tan_t * d2 + 1.0 / incidence.cos().powi(2) + d1 * d1;
    (
        h * h / 6.0 * d3_over_d1.abs(),
        h * h / 2.0 * (g2 + g1 * g1 - 1.0).abs(),
    )
}

/// Cosines of at least 0.2 at the boundary rays' landing and leaving: the f32 evaluation's error is
/// then at most 30 operations x 5 x 5 x 6e-8 < 1e-4 relative.
fn comfortably_conditioned(traced: &Traced) -> bool {
    traced.min_landing_cos >= 0.2 && traced.min_leaving_cos >= 0.2
}

/// f32 error bound for [`comfortably_conditioned`] cases (see there).
const COMFORTABLE_F32_ERROR: f64 = 1.0e-4;

/// `eta = 1` on a flat surface changes nothing, at any incidence up to grazing (cones narrow enough
/// for both boundary rays to meet the surface within `MAX_INCIDENCE_ANGLE`), for diverging,
/// converging and negative-width cones. Every quantity is then a rotation of the inputs: 1e-3
/// relative bounds the f32 rounding (as in the flat test).
#[test]
fn index_one_leaves_the_cone_unchanged() {
    let worst = worst_case(0x5eed_0003, CASES, |rng| {
        let incidence = rng.range(0.0, f64::from(rc::MAX_INCIDENCE_ANGLE));
        let room = 1.8 * (f64::from(rc::MAX_INCIDENCE_ANGLE) - incidence);
        let case = Case::new(
            incidence,
            rng.sign() * rng.log_range(-6.0, 3.0),
            rng.sign() * rng.log_range(-9.0, -1.0).min(room),
            1.0,
        );
        let same = case.refract().cone;
        let error = relative(same.width, f64::from(case.cone.width))
            .max(relative(same.spread_angle, f64::from(case.cone.spread_angle)));
        assert!(error < 1.0e-3, "{case:?}: {same:?}");
        error
    });
    println!("eta = 1: worst relative change {worst:.2e}");
}

/// A small cone on a flat interface, with `m = eta cos i / cos t` and the half spread `h`: the
/// first order of RTG II ch. 10, `spread' = m spread`, `width' = width cos t / cos i`, within twice the
/// leading second-order correction ([`second_order_corrections`], kept below 1e-3 so that the
/// higher orders are negligible) plus the f32 error; and refracting into a flat slab of zero
/// thickness and straight back out (`eta`, then `1 / eta` along the refracted ray) restores the
/// cone within both passes' corrections (the first-order maps are each other's inverses).
#[test]
fn small_cones_follow_the_first_order_formulas_and_come_back_out_unchanged() {
    let [worst_spread, worst_width, worst_round_trip] = worst_accepted(0x5eed_0004, |rng, accepted| {
        let eta = [rng.range(0.4, 0.95), rng.range(1.05, 2.5)][accepted % 2];
        let case = Case::new(
            rng.range(0.0, 1.5),
            rng.log_range(-6.0, 3.0),
            rng.sign() * rng.log_range(-7.0, -2.0),
            eta,
        );
        case.trace(Interface { curvature: 0.0 })
            .filter(comfortably_conditioned)?;
        let (incidence, eta) = (case.incidence(), f64::from(case.eta));
        let h = 0.5 * f64::from(case.cone.spread_angle);
        let (spread_correction, width_correction) = second_order_corrections(incidence, eta, h);
        let sin_t = eta * incidence.sin();
        let cos_t = (1.0 - sin_t * sin_t).sqrt();
        let m = eta * incidence.cos() / cos_t;
        let inside = case.refract().cone;
        let back = Case {
            direction: Vec3::new(sin_t as f32, 0.0, -cos_t as f32),
            cone: inside,
            normal_spread: 0.0,
            eta: 1.0 / case.eta,
        };
        let back_h = 0.5 * f64::from(inside.spread_angle);
        let (back_spread, back_width) =
            second_order_corrections(back.incidence(), f64::from(back.eta), back_h);
        let corrections = [spread_correction, width_correction, back_spread, back_width];
        if corrections.iter().any(|&c| c > 1.0e-3) {
            return None;
        }
        back.trace(Interface { curvature: 0.0 })
            .filter(comfortably_conditioned)?;
        let spread_error = relative(inside.spread_angle, m * f64::from(case.cone.spread_angle));
        let width_error = relative(inside.width, f64::from(case.cone.width) * cos_t / incidence.cos());
        assert!(
            spread_error <= 2.0 * spread_correction + COMFORTABLE_F32_ERROR
                && width_error <= 2.0 * width_correction + COMFORTABLE_F32_ERROR,
            "{case:?}: {inside:?}, m {m}, corrections {spread_correction:e} {width_correction:e}"
        );
        let out = back.refract().cone;
        let round_trip_error = relative(out.width, f64::from(case.cone.width))
            .max(relative(out.spread_angle, f64::from(case.cone.spread_angle)));
        let round_trip_bound = 2.0 * corrections.iter().sum::<f64>() + 2.0 * COMFORTABLE_F32_ERROR;
        assert!(
            round_trip_error <= round_trip_bound,
            "{case:?}: in {inside:?}, out {out:?}"
        );
        Some([spread_error, width_error, round_trip_error])
    });
    println!(
        "first order, {CASES} cones: worst relative error spread {worst_spread:.2e} (vs eta gamma cos i / cos t), width {worst_width:.2e} (vs w cos t / cos i); in and back out: {worst_round_trip:.2e}"
    );
}

/// At normal incidence on a curved surface the OptiX Toolkit refracts a cone as
/// `(n_out / n_in) (angle + k |w|) - k |w|`, with `n_out / n_in = eta` and `k |w|` the normal's
/// turn across the footprint (our `beta`). The construction gives `2 asin(eta sin q) - beta` with
/// `q = (spread + beta) / 2`, which differs from that by `O(q^3)`: below `eta^3 q^3` here.
#[test]
fn normal_incidence_matches_the_optix_toolkit_thin_form() {
    let worst = worst_case(0x5eed_0005, CASES, |rng| {
        let eta = rng.range(0.4, 2.5) as f32;
        let curvature = rng.range(-10.0, 10.0);
        let width = rng.log_range(-6.0, -3.0) as f32;
        let spread = rng.range(-2.0e-3, 2.0e-3) as f32;
        let beta = (curvature * f64::from(width)) as f32;
        let refracted = rc::refract_ray_cone(
            RayCone {
                width,
                spread_angle: spread,
            },
            Vec3::Z,
            Vec3::NEG_Z,
            beta,
            eta,
        );
        let thin_form = f64::from(eta) * (f64::from(spread) + f64::from(beta)) - f64::from(beta);
        let q = 0.5 * (f64::from(spread) + f64::from(beta)).abs();
        let error = (f64::from(refracted.cone.spread_angle) - thin_form).abs();
        let bound = (f64::from(eta) * q).powi(3) + 1.0e-6 * (thin_form.abs() + f64::from(beta).abs());
        assert!(
            error <= bound,
            "eta {eta} k {curvature} w {width} spread {spread}: {refracted:?} vs {thin_form}"
        );
        assert_eq!(
            refracted.cone.width, width,
            "the width passes unchanged at normal incidence"
        );
        error / (thin_form.abs() + f64::from(beta).abs()).max(1.0e-30)
    });
    println!("normal incidence: worst |ours - OptiX thin form| / (|spread'| + |beta|) = {worst:.2e}");
}

/// Past the critical angle the central ray is reflected: the flag is set and the cone is the
/// reflected one, `(width, spread + 2 beta)` with beta as the ray sees the surface (negated when
/// the normal faces away from the ray).
#[test]
fn total_internal_reflection_gives_the_reflected_cone() {
    let cone = RayCone {
        width: 0.25,
        spread_angle: 0.125,
    };
    let direction = Vec3::new(0.8, 0.0, -0.6);
    let reflected = rc::refract_ray_cone(cone, Vec3::Z, direction, 0.0625, 1.5);
    assert!(reflected.total_internal_reflection);
    assert_eq!(
        reflected.cone,
        RayCone {
            width: 0.25,
            spread_angle: 0.25
        }
    );
    let from_behind = rc::refract_ray_cone(cone, Vec3::NEG_Z, direction, 0.0625, 1.5);
    assert_eq!(
        from_behind.cone,
        RayCone {
            width: 0.25,
            spread_angle: 0.0
        }
    );
    let below_critical = rc::refract_ray_cone(cone, Vec3::Z, direction, 0.0625, 1.2);
    assert!(!below_critical.total_internal_reflection);
}

/// `(w, spread)` and `(-w, -spread)` describe the same cone (the boundary rays swap sides): the
/// refracted cones are each other's negatives, on curved surfaces too.
#[test]
fn a_negated_cone_refracts_to_the_negated_cone() {
    let mut rng = Rng(0x5eed_0006);
    for _ in 0..20_000 {
        let case = Case {
            normal_spread: rng.range(-0.1, 0.1) as f32,
            ..Case::new(
                rng.range(0.0, 1.5),
                rng.log_range(-6.0, 3.0),
                rng.range(-1.0, 1.0),
                rng.range(0.3, 3.0),
            )
        };
        let negated = Case {
            cone: RayCone {
                width: -case.cone.width,
                spread_angle: -case.cone.spread_angle,
            },
            ..case
        };
        let (a, b) = (case.refract(), negated.refract());
        assert_eq!(a.total_internal_reflection, b.total_internal_reflection);
        if !a.total_internal_reflection {
            assert_eq!(
                (a.cone.width, a.cone.spread_angle),
                (-b.cone.width, -b.cone.spread_angle),
                "{case:?}"
            );
        }
    }
}

/// The roughness mapping (JCGT 2021 / Falcor): `2 sqrt(0.5 r^4 / (1 - r^4))` at a few roughness
/// values (closed form in f64; the f32 evaluation is five roundings and a square root, so 1e-6
/// relative), its small-roughness limit `sqrt(2) r^2` (relative difference `r^4 / 2` plus the same
/// rounding), 0 at roughness 0, the clamps outside `[0, 1]`, and growth with roughness.
#[test]
fn roughness_spread_follows_its_closed_form() {
    for r in [0.05f64, 0.1, 0.25, 0.5, 0.75, 0.9, 0.95] {
        let closed_form = 2.0 * (0.5 * r.powi(4) / (1.0 - r.powi(4))).sqrt();
        let spread = rc::roughness_spread_angle(r as f32);
        let r32 = f64::from(r as f32);
        let exact_at_r32 = 2.0 * (0.5 * r32.powi(4) / (1.0 - r32.powi(4))).sqrt();
        println!(
            "roughness {r}: spread {spread} (closed form {closed_form:.7}, relative error {:.1e})",
            relative(spread, exact_at_r32)
        );
        assert!(relative(spread, exact_at_r32) < 1.0e-6, "roughness {r}");
    }
    let mut worst = 0.0f64;
    for step in 1..=100 {
        let r = 0.001 * f64::from(step);
        let limit = std::f64::consts::SQRT_2 * r * r;
        let error = relative(rc::roughness_spread_angle(r as f32), limit);
        assert!(error < 0.5 * r.powi(4) + 1.0e-6, "roughness {r}: {error}");
        worst = worst.max(error);
    }
    println!("roughness <= 0.1: worst relative difference from sqrt(2) r^2: {worst:.2e}");
    assert_eq!(rc::roughness_spread_angle(0.0), 0.0);
    assert_eq!(rc::roughness_spread_angle(-0.5), 0.0);
    assert_eq!(rc::roughness_spread_angle(7.0), rc::roughness_spread_angle(1.0));
    let at_one = 2.0 * (0.5 / f64::from(rc::MIN_ROUGHNESS_DENOMINATOR)).sqrt();
    assert!(relative(rc::roughness_spread_angle(1.0), at_one) < 1.0e-6);
    let samples: Vec<f32> = (0..=1000)
        .map(|i| rc::roughness_spread_angle(i as f32 / 1000.0))
        .collect();
    assert!(
        samples.windows(2).all(|w| w[0] <= w[1]),
        "non-decreasing in roughness"
    );
}
