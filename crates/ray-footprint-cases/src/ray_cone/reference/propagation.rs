//! References of the propagation and curvature section: boundary rays, planar and spherical
//! mirrors, normals across a pixel, quadric patches and chords of spheres and cylinders.

use super::{mirrored, reflect, rotate, scatter_cone, Surface};
use crate::exact::{angle_between, derivative, log_uniform, towards, unit, Derivative};
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use glam::{DQuat, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::RayCone;

/// `sign * 10^e` for `e` uniform in `[low, high)` and either sign.
pub(super) fn signed_log(low: f64, high: f64) -> BoxedStrategy<f64> {
    (log_uniform(low, high), any::<bool>())
        .prop_map(|(m, negative)| if negative { -m } else { m })
        .boxed()
}

/// `2 tan(s / 2) - s`, the excess of the boundary rays' separation rate over the linear width's,
/// is at most `|s|^3 / (12 cos^4(s / 2))` (from `tan x - x <= x^3 / (3 cos^4 x)`, which integrates
/// `tan^2 x <= x^2 / cos^4 x`).
fn tangent_excess_bound(spread: f64) -> f64 {
    spread.abs().powi(3) / (12.0 * (0.5 * spread).cos().powi(4))
}

/// Rounding of `width + spread * t` in f32 (possibly the mirror's `width_at`): a product and a sum,
/// `gamma(2) (|width| + 2 |spread t|)`.
pub(super) fn width_rounding(width: f64, spread: f64, t: f64) -> f64 {
    gamma(2) * (width.abs() + 2.0 * (spread * t).abs())
}

/// `rf_width_at`.
pub(in crate::ray_cone) fn width_at() -> Reference<(RayCone, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the two boundary rays (width w apart, spread s) intersected with the plane across the central ray at t: within t |s|^3 / (12 cos^4(s / 2)) of w + s t",
        || (signed_log(-6.0, 2.0), signed_log(-6.0, 0.17), log_uniform(-3.0, 4.0)).boxed(),
        |&(w, s, t), width_at| {
            let (w, s, t) = (w as f32, s as f32, t as f32);
            let got = width_at((RayCone { width: w, spread_angle: s }, t));
            let (w, s, t) = (f64::from(w), f64::from(s), f64::from(t));
            let crossing = |side: f64| {
                let start = DVec3::new(0.0, side * 0.5 * w, 0.0);
                let direction = DVec3::new((0.5 * s).cos(), side * (0.5 * s).sin(), 0.0);
                crate::exact::plane_hit(start, direction, DVec3::X * t, DVec3::X).y
            };
            let exact = crossing(1.0) - crossing(-1.0);
            let bound = t * tangent_excess_bound(s) + width_rounding(w, s, t);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}

/// Chord between the two pixel-edge rays (angle `alpha` apart) of a pinhole camera at the origin
/// after a planar mirror hit at distance `t0` with the given incidence angle (the mirror tilted by
/// `roll` about the axis), once each edge ray has travelled `t0 + t1` in all. Explicit ray-plane
/// intersections in f64.
fn reflected_chord(alpha: f64, t0: f64, t1: f64, incidence: f64, roll: f64) -> f64 {
    let axis = DVec3::NEG_Z;
    let tilt = DVec3::new(roll.cos(), roll.sin(), 0.0);
    let normal = -axis * incidence.cos() + tilt * incidence.sin();
    let plane_point = axis * t0;
    // The edge rays spread in the plane of incidence, where the slant matters most.
    let spread_direction = (tilt - axis * tilt.dot(axis)).normalize();
    let edge = |side: f64| {
        let direction =
            (axis * (0.5 * alpha).cos() + spread_direction * side * (0.5 * alpha).sin()).normalize();
        let hit = crate::exact::plane_hit(DVec3::ZERO, direction, plane_point, normal);
        let reflected = direction - normal * 2.0 * direction.dot(normal);
        hit + reflected * (t0 + t1 - hit.length())
    };
    (edge(1.0) - edge(-1.0)).length()
}

/// `rf_propagate`: a planar mirror.
pub(in crate::ray_cone) fn propagate_planar() -> Reference<(RayCone, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a planar mirror is a mirror-image camera (RTG Eq. 35): a pinhole cone reflected at t0 and traced t1 further is as wide as the chord between the reflected pixel-edge rays, 2 (t0 + t1) sin(alpha / 2), within alpha^2 / 24",
        || {
            (1.0e-4f64..0.05, 0.1f64..100.0, 0.0f64..100.0, 0.0f64..1.4, 0.0f64..std::f64::consts::TAU).boxed()
        },
        |&(alpha, t0, t1, incidence, roll), propagate| {
            let (alpha32, t0_32, t1_32) = (alpha as f32, t0 as f32, t1 as f32);
            let pinhole = RayCone {
                width: 0.0,
                spread_angle: alpha32,
            };
            let cone = propagate((pinhole, t0_32, 0.0));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * f64::from(t1_32);
            let chord = reflected_chord(alpha, t0, t1, incidence, roll);
            // The linear width alpha (t0 + t1) exceeds the chord by alpha / (2 sin(alpha / 2)) - 1
            // = alpha^2 / 24 + 7 alpha^4 / 5760 + ... relative; the fourth-order term (< 8e-9 here)
            // and the f32 rounding of alpha, t0, t1 and of alpha * t0 (4 u) lie within 8 u.
            let bound = (alpha * alpha / 24.0 + 8.0 * U) * chord;
            Some(Deviation::within(width, chord, bound))
        },
    )
}

/// The reflected cone's first order in its size: central differences of the cone `(h w, h s)`
/// scattered by `surface` (`h -> 0`), as `(width, spread)`, with step `step`.
fn reflected_first_order(
    surface: Surface,
    d: DVec2,
    t: f64,
    cone: (f64, f64),
    step: f64,
) -> Derivative<DVec2> {
    let reflected = |h: f64| {
        scatter_cone(
            surface,
            d,
            t,
            (h * cone.0, h * cone.1),
            |d, n| Some(reflect(d, n)),
            mirrored,
        )
        .map_or(DVec2::NAN, |s| DVec2::new(s.width, s.spread))
    };
    derivative(reflected, step, 1.0)
}

/// A step `h` that keeps the scaled cone `h * cone` at the hit within 1e-6 of a point: its
/// spread, its width (`|width| + |spread| t`) and that width's footprint over the radius of
/// curvature (`/ cos^2`) below 1e-6. Central differences are then exact to `O(1e-12)` relative.
fn step(cone: (f64, f64), t: f64, curvature: f64, cosine: f64) -> f64 {
    let size = cone.0.abs() + cone.1.abs() * t;
    let scale = cone
        .1
        .abs()
        .max(size)
        .max(size * curvature.abs() / (cosine * cosine));
    1.0e-6 / scale.max(1.0e-300)
}

/// `rf_propagate`: planar and spherical mirrors to first order.
pub(in crate::ray_cone) fn propagate_curved() -> Reference<(RayCone, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a cone's boundary rays traced t to a planar or spherical mirror and reflected exactly (f64 central differences in the cone's size): its width is w + s t and its spread s plus the spread beta the mirror gives a cone of zero spread",
        || {
            let curvature = prop_oneof![1 => Just(0.0f64), 2 => signed_log(-2.0, 2.0)];
            let spread = prop_oneof![1 => Just(0.0f64), 3 => signed_log(-5.0, -0.5)];
            (signed_log(-4.0, 1.0), spread, log_uniform(-2.0, 3.0), curvature, 0.05f64..1.0).boxed()
        },
        |&(w, s, t, curvature, cosine), propagate| {
            let (w, s, t) = (w as f32, s as f32, t as f32);
            let (w64, s64, t64) = (f64::from(w), f64::from(s), f64::from(t));
            let surface = Surface { curvature };
            let d = DVec2::new((1.0 - cosine * cosine).sqrt(), -cosine);
            let at_hit = w64 + s64 * t64;
            let beta = reflected_first_order(surface, d, 0.0, (at_hit, 0.0), step((at_hit, 0.0), 0.0, curvature, cosine));
            let expected = reflected_first_order(surface, d, t64, (w64, s64), step((w64, s64), t64, curvature, cosine));
            let beta32 = beta.value.y as f32;
            let got = propagate((RayCone { width: w, spread_angle: s }, t, beta32));
            // Width: the f32 width_at; spread: beta rounded to f32 and one sum in f32.
            let width = Deviation::within(
                f64::from(got.width),
                expected.value.x,
                width_rounding(w64, s64, t64) + expected.error,
            );
            let spread_bound = U * (beta.value.y.abs() + (s64 + f64::from(beta32)).abs())
                + beta.error
                + expected.error;
            let spread = Deviation::within(f64::from(got.spread_angle), expected.value.y, spread_bound);
            Some(width.and(spread))
        },
    )
}

/// `|1 - |a| |b||`: how far the f32 "unit" vectors `a` and `b` make a dot product from the cosine
/// of their angle, relatively.
pub(super) fn unit_excess(a: Vec3, b: Vec3) -> f64 {
    (1.0 - a.as_dvec3().length() * b.as_dvec3().length()).abs()
}

/// `rf_curvature_spread_angle`.
pub(in crate::ray_cone) fn curvature_spread_angle() -> Reference<(f32, f32, Vec3, Vec3), f32> {
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

/// Normal derivatives: each component small, ordinary or tiny (lengths down to about 1e-12).
fn normal_derivatives() -> BoxedStrategy<(Vec3, Vec3)> {
    let component = || prop_oneof![3 => -2.0f32..2.0, 1 => (-12.0f32..0.0).prop_map(|e| 10f32.powf(e))];
    let vector = || (component(), component(), component()).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    (vector(), vector()).boxed()
}

/// The angle between the unit normals at the two ends of a pixel across which the normal turns
/// by the combined length `length` of its derivatives (RTG Eq. 31): the normals `n +- g / 2`, `g`
/// perpendicular to the unit `n` with `|g| = length`, normalised.
fn normals_across_a_pixel(length: f64) -> f64 {
    let n = DVec3::new(0.36, 0.48, 0.8);
    let g = n.any_orthonormal_vector() * length;
    angle_between((n + 0.5 * g).normalize(), (n - 0.5 * g).normalize())
}

/// `sqrt(|dn_dx|^2 + |dn_dy|^2)` in f64.
fn derivative_length(dn_dx: Vec3, dn_dy: Vec3) -> f64 {
    (dn_dx.as_dvec3().length_squared() + dn_dy.as_dvec3().length_squared()).sqrt()
}

/// `rf_normal_spread_angle`.
pub(in crate::ray_cone) fn normal_spread_angle() -> Reference<(Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle between the unit normals at the two ends of a pixel across which the normal changes by sqrt(|dn_dx|^2 + |dn_dy|^2) (RTG Eq. 31)",
        normal_derivatives,
        |&(dn_dx, dn_dy), normal_spread_angle| {
            let got = normal_spread_angle((dn_dx, dn_dy));
            let exact = normals_across_a_pixel(derivative_length(dn_dx, dn_dy));
            // The length: six products summed (gamma(6) of the square), a square root (u): 4 u;
            // atan: 2 ULP (4 u) and at most the argument's relative error; halving and doubling
            // are exact.
            Some(Deviation::within(f64::from(got), exact, gamma(8) * exact))
        },
    )
}

/// `rf_normal_spread_angle_small`: the approximation's bound.
pub(in crate::ray_cone) fn normal_spread_angle_small() -> Reference<(Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the small-angle form L against the angle between the normals at the pixel's ends, 2 atan(L / 2): within L^3 / 12 (RTG Eq. 32)",
        normal_derivatives,
        |&(dn_dx, dn_dy), normal_spread_angle_small| {
            let got = normal_spread_angle_small((dn_dx, dn_dy));
            let length = derivative_length(dn_dx, dn_dy);
            let exact = normals_across_a_pixel(length);
            // L - 2 atan(L / 2) <= L^3 / 12 (the alternating series of atan); the length's
            // rounding is 4 u.
            let bound = length.powi(3) / 12.0 + gamma(4) * length;
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
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

/// `rf_curvature_sign`.
pub(in crate::ray_cone) fn curvature_sign() -> Reference<(Vec3, Vec3, Vec3, Vec3), f32> {
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

/// `rf_surface_spread_angle`.
pub(in crate::ray_cone) fn surface_spread_angle() -> Reference<(f32, f32, f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "parallel rays reflected at the two ends of a pixel whose normals are phi apart, spreading (s = 1) or converging (s = -1): the reflected rays are 2 s phi apart at any incidence; beta = k1 times that plus k2 (RTG Eq. 32-34)",
        || (0.0f64..1.4, any::<bool>(), -4.0f64..4.0, prop_oneof![Just(0.0f64), -0.5f64..0.5], 0.0f64..1.5).boxed(),
        |&(phi, concave, k1, k2, incidence), surface_spread_angle| {
            let (phi, sign, k1, k2) = (phi as f32, if concave { -1.0f32 } else { 1.0 }, k1 as f32, k2 as f32);
            let got = surface_spread_angle((phi, sign, k1, k2));
            let d = DVec2::new(incidence.sin(), -incidence.cos());
            let central = reflect(d, DVec2::Y);
            let across = super::mirrored(rotate(d, std::f64::consts::FRAC_PI_2), central);
            // At the upper end (along +across) a spreading surface's normal tilts towards it.
            let reflected_angle = |side: f64| {
                let normal = rotate(DVec2::Y, -side * f64::from(sign) * 0.5 * f64::from(phi));
                let r = reflect(d, normal);
                r.dot(across).atan2(r.dot(central))
            };
            let geometric = reflected_angle(1.0) - reflected_angle(-1.0);
            let expected = f64::from(k1) * geometric + f64::from(k2);
            // 2 k1 and the product with the sign are exact; the product with phi and the sum
            // round once each.
            let bound = gamma(2) * (2.0 * f64::from(k1 * phi).abs() + f64::from(k2).abs()) + 1.0e-14;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}

/// Points and unit normals of a sphere or a cylinder, the normals stored outward or inward, and
/// the exact normal curvature of each chord.
#[derive(Clone, Debug)]
pub(super) struct Curved {
    pub(super) points: Vec<DVec3>,
    pub(super) normals: Vec<DVec3>,
    /// Unit axis of a cylinder, `None` for a sphere.
    pub(super) axis: Option<DVec3>,
    pub(super) radius: f64,
    /// 1 for outward normals, -1 for inward ones.
    pub(super) orientation: f64,
}

impl Curved {
    /// `count` points of a sphere or cylinder of radius `10^[-2, 2]` around a centre within 10.
    pub(super) fn strategy(count: usize) -> BoxedStrategy<Curved> {
        let place = (unit(), -1.0f64..1.0);
        (
            any::<bool>(),
            (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
            log_uniform(-2.0, 2.0),
            unit(),
            any::<bool>(),
            prop::collection::vec(place, count),
        )
            .prop_map(|(cylinder, (x, y, z), radius, axis, inward, places)| {
                let centre = DVec3::new(x, y, z);
                let orientation = if inward { -1.0 } else { 1.0 };
                let (points, normals) = places
                    .iter()
                    .map(|&(u, height)| {
                        let radial = if cylinder {
                            (u - axis * u.dot(axis)).normalize_or(axis.any_orthonormal_vector())
                        } else {
                            u
                        };
                        let along = if cylinder {
                            axis * (2.0 * radius * height)
                        } else {
                            DVec3::ZERO
                        };
                        (centre + radial * radius + along, radial * orientation)
                    })
                    .unzip();
                Curved {
                    points,
                    normals,
                    axis: cylinder.then_some(axis),
                    radius,
                    orientation,
                }
            })
            .boxed()
    }

    /// The curvature of the chord from point `i` to point `j`: `1 / R` on a sphere, `(1 - (a . e)^2)
    /// / R` on a cylinder of axis `a` for the chord's unit direction `e` (Euler's formula), signed
    /// by the normals' orientation.
    fn chord_curvature(&self, i: usize, j: usize) -> f64 {
        let along = self.axis.map_or(0.0, |axis| {
            axis.dot((self.points[j] - self.points[i]).normalize())
        });
        self.orientation * (1.0 - along * along) / self.radius
    }
}

/// How far `edge_curvature` of f32 inputs may be from the exact chord curvature `k` of the points
/// the inputs round: each input is off by up to `u` relative (its rounding), each difference
/// rounds once more, the dot product and the squared length by `gamma(3)` of their terms, the
/// quotient once:
/// `dN <= d(dn) |dp| + |dn| d(dp) + gamma(3) |dn| |dp|`, `dD <= 2 |dp| d(dp) + gamma(3) |dp|^2`,
/// `dk <= dN / D + |k| dD / D + u |k|`.
fn chord_error(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3, k: f64) -> f64 {
    let (p_i, p_j, n_i, n_j) = (p_i.as_dvec3(), p_j.as_dvec3(), n_i.as_dvec3(), n_j.as_dvec3());
    let (dp, dn) = ((p_j - p_i).length(), (n_j - n_i).length());
    let dp_error = U * (p_i.length() + p_j.length() + dp);
    let dn_error = U * (n_i.length() + n_j.length() + dn);
    let numerator = dn_error * dp + dn * dp_error + gamma(3) * dn * dp;
    let denominator = 2.0 * dp * dp_error + gamma(3) * dp * dp;
    (numerator + k.abs() * denominator) / (dp * dp) + U * k.abs()
}

/// `rf_edge_curvature`.
pub(in crate::ray_cone) fn edge_curvature() -> Reference<(Vec3, Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "chords of spheres and cylinders with exact vertex normals (outward or inward): 1 / R on a sphere, (1 - (axis . chord)^2) / R on a cylinder (JCGT 2021 Sec. 3; Euler's formula), negated for inward normals",
        || Curved::strategy(2),
        |curved, edge_curvature| {
            let [p_i, p_j] = [0, 1].map(|i| curved.points[i].as_vec3());
            let [n_i, n_j] = [0, 1].map(|i| curved.normals[i].as_vec3());
            let got = edge_curvature((p_i, p_j, n_i, n_j));
            let expected = curved.chord_curvature(0, 1);
            Some(Deviation::within(f64::from(got), expected, chord_error(p_i, p_j, n_i, n_j, expected)))
        },
    )
}

/// `rf_triangle_curvature`.
pub(in crate::ray_cone) fn triangle_curvature() -> Reference<(Vec3, Vec3, Vec3, Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles inscribed in spheres and cylinders with exact vertex normals: the mean of the three chords' exact curvatures (1 / R on a sphere, JCGT 2021)",
        || Curved::strategy(3),
        |curved, triangle_curvature| {
            let p = [0, 1, 2].map(|i| curved.points[i].as_vec3());
            let n = [0, 1, 2].map(|i| curved.normals[i].as_vec3());
            let got = triangle_curvature((p[0], p[1], p[2], n[0], n[1], n[2]));
            let edges = [(0, 1), (1, 2), (2, 0)];
            let expected = edges.iter().map(|&(i, j)| curved.chord_curvature(i, j)).sum::<f64>() / 3.0;
            // The three edges' errors, then two sums and a division by 3 (gamma(3) of the sum of
            // their magnitudes).
            let errors: f64 = edges
                .iter()
                .map(|&(i, j)| chord_error(p[i], p[j], n[i], n[j], curved.chord_curvature(i, j)))
                .sum();
            let sizes: f64 = edges.iter().map(|&(i, j)| curved.chord_curvature(i, j).abs()).sum();
            let bound = (errors + gamma(3) * sizes) / 3.0;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
