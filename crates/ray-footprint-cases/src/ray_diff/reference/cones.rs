//! References of the cones-with-differentials section: the cone as a cylinder cut by the surface
//! (its exact ellipse, and that ellipse under an affine texture map), the OptiX Toolkit's
//! projection, a vertex's height over its opposite edge, the rays of a cone's differential, and
//! the round trips and commutations of the conversions.

use super::super::{enclosure, ConeGradientArgs};
use super::{components, widths};
use crate::exact::{log_uniform, plane_hit, tangent, towards, unit};
use crate::reference::{Deviation, Kind, Reference, U};
use crate::strategy::triangle;
use glam::{DMat2, DMat3, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, RayDiff, DIFF_MAX_VALUE, DIFF_MIN_SINE,
};
use shader_proptest::interval::{interval3, Interval3};

/// Relative f32 error of a value computed through a few dozen roundings of well-conditioned
/// operations (about 40 x 6e-8, rounded up).
const F32_CHAIN: f64 = 1.0e-5;

/// `sign * 10^e` for `e` uniform in `[low, high)` and either sign.
fn signed_log(low: f64, high: f64) -> BoxedStrategy<f64> {
    (log_uniform(low, high), any::<bool>())
        .prop_map(|(m, negative)| if negative { -m } else { m })
        .boxed()
}

/// The symmetric matrix `sum_i a_i a_i^T` of an ellipse spanned by conjugate axes `a_i`: the same
/// for every conjugate pair of one ellipse, so it compares ellipses whatever their axes.
fn ellipse(axes: &[DVec3]) -> DMat3 {
    axes.iter()
        .map(|a| DMat3::from_cols(*a * a.x, *a * a.y, *a * a.z))
        .fold(DMat3::ZERO, |m, a| m + a)
}

/// The Frobenius norm.
fn frobenius(m: DMat3) -> f64 {
    m.to_cols_array().iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// How far [`ellipse`] of `axes` can move when each axis moves by up to `errors` (its length):
/// `sum 2 |a| e + e^2`.
fn ellipse_error(axes: &[DVec3], errors: &[f64]) -> f64 {
    axes.iter()
        .zip(errors)
        .map(|(a, e)| 2.0 * a.length() * e + e * e)
        .sum()
}

/// The length of an enclosure's widths, per vector.
fn vector_errors(vectors: &[Interval3]) -> Vec<f64> {
    vectors
        .iter()
        .map(|v| widths(&v.components()).iter().map(|w| w * w).sum::<f64>().sqrt())
        .collect()
}

/// Two conjugate full diameters of the ellipse in which the plane through the origin with unit
/// normal `n` cuts the cylinder of diameter `width` around the unit direction `d`: the images on
/// the plane, along `d`, of two perpendicular diameters of the cylinder's cross-section.
fn cut_cylinder(width: f64, n: DVec3, d: DVec3) -> [DVec3; 2] {
    let a = d.any_orthonormal_vector();
    let b = d.cross(a);
    [a, b].map(|radius| 2.0 * plane_hit(radius * (0.5 * width), d, DVec3::ZERO, n))
}

/// A unit direction meeting the unit normal `n` at `|cos|` from 1e-3 to 1 (exactly 1, and within
/// 1e-10 and 1e-7 of it, around `DIFF_MIN_SINE`), from either side.
fn incidence(n: DVec3) -> BoxedStrategy<DVec3> {
    let cosine = prop_oneof![6 => log_uniform(-3.0, 0.0), 1 => Just(1.0f64), 1 => Just(1.0 - 1.0e-10), 1 => Just(1.0 - 1.0e-7)];
    (cosine, 0.0f64..6.3, any::<bool>())
        .prop_map(move |(cosine, angle, behind)| towards(n, cosine, angle) * if behind { -1.0 } else { 1.0 })
        .boxed()
}

/// How far an ellipse's matrix may lie from the exact one besides the rounding: the inputs'
/// distance from unit length (the major axis scales with it, `3 eta |M|`), and, within twice
/// `DIFF_MIN_SINE` of normal incidence, the fixed tangent in place of the projected direction
/// (`1.5 w^2 (1 / cos^2 - 1)`, below 1e-7 w^2).
fn ellipse_assumptions(n: Vec3, d: Vec3, width: f64, exact: DMat3) -> f64 {
    let (n64, d64) = (n.as_dvec3(), d.as_dvec3());
    let eta = (n64.length() - 1.0).abs() + (d64.length() - 1.0).abs();
    let (n64, d64) = (n64.normalize(), d64.normalize());
    let cosine = n64.dot(d64).abs();
    let near_normal = if n64.cross(d64).length() < 2.0 * f64::from(DIFF_MIN_SINE) {
        1.5 * width * width * (1.0 / (cosine * cosine) - 1.0)
    } else {
        0.0
    };
    3.0 * eta * frobenius(exact) + near_normal
}

/// `rf_anisotropic_cone_axes`: the cut cylinder.
pub(in crate::ray_diff) fn anisotropic_cone_axes() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the cone as a cylinder of diameter |w| around d cut by the surface: two perpendicular diameters of its cross-section projected along d onto the plane span the same ellipse as the axes (JCGT 2021, with its errata's factor 2)",
        || (signed_log(-4.0, 2.0), unit()).prop_flat_map(|(w, n)| (Just(w), Just(n), incidence(n))).boxed(),
        |&(w, n, d), anisotropic_cone_axes| {
            let (w, n, d) = (w as f32, n.as_vec3(), d.as_vec3());
            let got = anisotropic_cone_axes((w, n, d));
            let axes = [got.dx.as_dvec3(), got.dy.as_dvec3()];
            let exact = ellipse(&cut_cylinder(f64::from(w).abs(), n.as_dvec3().normalize(), d.as_dvec3().normalize()));
            let (major, minor) = enclosure::anisotropic_cone_axes(w, interval3(n), interval3(d));
            let bound = ellipse_error(&axes, &vector_errors(&[major, minor]))
                + ellipse_assumptions(n, d, f64::from(w), exact)
                + 1.0e-12 * frobenius(exact);
            Some(Deviation::new(frobenius(ellipse(&axes) - exact), bound))
        },
    )
}

/// `rf_anisotropic_cone_axes`: the axes' lengths and directions.
pub(in crate::ray_diff) fn anisotropic_cone_axes_growth() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::Identity,
        "the major axis is |w| / |cos| long and the minor one |w|, perpendicular to each other, to the normal and (the minor one) to the ray, from head-on down to |cos| = 1e-3 (JCGT 2021)",
        || (unit(), log_uniform(-3.0, 0.0), 0.0f64..6.3, log_uniform(-4.0, 2.0)).boxed(),
        |&(normal, cosine, angle, width), anisotropic_cone_axes| {
            let direction = towards(normal, cosine, angle);
            let width32 = width as f32;
            let a = anisotropic_cone_axes((width32, normal.as_vec3(), direction.as_vec3()));
            let (major, minor) = (a.dx.as_dvec3(), a.dy.as_dvec3());
            let w = f64::from(width32);
            let errors = [
                (major.length() * cosine - w).abs() / w,
                (minor.length() - w).abs() / w,
                major.dot(minor).abs() / (major.length() * minor.length()),
                major.dot(normal).abs() / major.length(),
                minor.dot(direction).abs() / minor.length(),
            ];
            // A chain of about 40 roundings, amplified by 1 / cos for the major axis.
            Some(Deviation::worst(errors.map(|e| Deviation::new(e, F32_CHAIN / cosine))))
        },
    )
}

/// The OptiX Toolkit's `projectToRayDifferentialsOnSurface`, in f64: `dPdx = normalize(d - dot(d, n)
/// n) * w / max(|dot(d, n)|, 1 / 16)` (a fixed tangent when `|dot| >= 0.999`), `dPdy =
/// normalize(cross(dPdx, n)) * w`.
fn optix_projection(width: f64, d: DVec3, n: DVec3) -> [DVec3; 2] {
    let cosine = d.dot(n);
    let dpdx = (d - n * cosine).normalize() * (width / cosine.abs().max(1.0 / 16.0));
    [dpdx, dpdx.cross(n).normalize() * width]
}

/// `rf_anisotropic_cone_axes`: the OptiX Toolkit.
pub(in crate::ray_diff) fn anisotropic_cone_axes_optix() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::PeerOriginal,
        "the OptiX Toolkit's projectToRayDifferentialsOnSurface where it applies neither its anisotropy cap nor its fixed tangent (1/16 <= |cos| < 0.999): the same ellipse",
        || (unit(), 1.0f64 / 16.0..0.999, 0.0f64..6.3, log_uniform(-4.0, 2.0)).boxed(),
        |&(normal, cosine, angle, width), anisotropic_cone_axes| {
            let direction = towards(normal, cosine, angle);
            let ours = anisotropic_cone_axes((width as f32, normal.as_vec3(), direction.as_vec3()));
            let theirs = ellipse(&optix_projection(width, direction, normal));
            let error = frobenius(ellipse(&[ours.dx.as_dvec3(), ours.dy.as_dvec3()]) - theirs) / frobenius(theirs);
            // The f32 chain's error, squared by the ellipse matrix's major axis: 1 / cos^2.
            Some(Deviation::new(error, F32_CHAIN / (cosine * cosine)))
        },
    )
}

/// A triangle in a random plane with the UVs of an affine map of the plane, a width and a
/// direction meeting the plane from `|cos|` 1e-3 to head-on.
fn mapped_triangle() -> BoxedStrategy<ConeGradientArgs> {
    let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
    (
        (
            (corner(), corner(), corner()),
            unit(),
            0.0f64..6.3,
            log_uniform(-1.0, 1.0),
        ),
        (
            (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0),
            (-2.0f64..2.0, -2.0f64..2.0),
        ),
        signed_log(-4.0, 1.0),
    )
        .prop_flat_map(|(((a, b, c), normal, roll, size), (m, o), w)| {
            let u = tangent(normal, roll);
            let v = normal.cross(u);
            let p = [a, b, c].map(|q| (u * q.x + v * q.y) * size);
            let map = DMat2::from_cols(DVec2::new(m.0, m.2), DVec2::new(m.1, m.3));
            let uv = [a, b, c].map(|q| (map * q + DVec2::new(o.0, o.1)).as_vec2());
            incidence(normal).prop_map(move |d| {
                (
                    w as f32,
                    d.as_vec3(),
                    p[0].as_vec3(),
                    p[1].as_vec3(),
                    p[2].as_vec3(),
                    uv[0],
                    uv[1],
                    uv[2],
                )
            })
        })
        .prop_filter(
            "a sliver or a degenerate map",
            |&(_, _, p0, p1, p2, uv0, uv1, uv2)| {
                let (e1, e2) = ((p1 - p0).as_dvec3(), (p2 - p0).as_dvec3());
                let (g1, g2) = ((uv1 - uv0).as_dvec2(), (uv2 - uv0).as_dvec2());
                e1.cross(e2).length() > 0.1 * e1.length() * e2.length()
                    && (g1.perp_dot(g2)).abs() > 0.05 * g1.length() * g2.length()
            },
        )
        .boxed()
}

/// The exact UV ellipse of `anisotropic_cone_gradients`' arguments: the cut cylinder on the plane
/// of the corners, taken to UV by the affine map the corners' UVs define (in-plane coordinates
/// solved in f64), as 3-vectors with `z = 0`.
fn uv_ellipse(&(w, d, p0, p1, p2, uv0, uv1, uv2): &ConeGradientArgs) -> [DVec3; 2] {
    let (e1, e2) = ((p1 - p0).as_dvec3(), (p2 - p0).as_dvec3());
    let n = e1.cross(e2).normalize();
    let axes = [e1.normalize(), n.cross(e1.normalize())];
    let planar = |v: DVec3| DVec2::new(v.dot(axes[0]), v.dot(axes[1]));
    let corners = DMat2::from_cols(planar(e1), planar(e2));
    let uvs = DMat2::from_cols((uv1 - uv0).as_dvec2(), (uv2 - uv0).as_dvec2());
    let map = uvs * corners.inverse();
    cut_cylinder(f64::from(w).abs(), n, d.as_dvec3().normalize()).map(|a| (map * planar(a)).extend(0.0))
}

/// `rf_anisotropic_cone_gradients`: the exact UV ellipse.
pub(in crate::ray_diff) fn anisotropic_cone_gradients() -> Reference<ConeGradientArgs, Derivatives2> {
    Reference::new(
        Kind::ExactGeometry,
        "the cylinder of diameter |w| around d cut by the triangle's plane, taken to UV by the affine map its corners' UVs define: the gradients span that UV ellipse (JCGT 2021's anisotropic filter)",
        mapped_triangle,
        |args, anisotropic_cone_gradients| {
            let got = anisotropic_cone_gradients(*args);
            let gradients = [got.dx.as_dvec2().extend(0.0), got.dy.as_dvec2().extend(0.0)];
            let exact = ellipse(&uv_ellipse(args));
            let rounding = widths(&enclosure::anisotropic_cone_gradients(args));
            let errors = [rounding[0].hypot(rounding[1]), rounding[2].hypot(rounding[3])];
            let (w, d, p0, p1, p2, ..) = *args;
            let normal = (p1 - p0).cross(p2 - p0).normalize();
            let bound = ellipse_error(&gradients, &errors)
                + ellipse_assumptions(normal, d, f64::from(w), exact)
                + 1.0e-9 * frobenius(exact);
            Some(Deviation::new(frobenius(ellipse(&gradients) - exact), bound))
        },
    )
}

/// `rf_anisotropic_cone_gradients`: head-on.
pub(in crate::ray_diff) fn anisotropic_cone_gradients_isotropic() -> Reference<ConeGradientArgs, Derivatives2>
{
    Reference::new(
        Kind::Identity,
        "at normal incidence (exactly, and 1.4e-5 and 4.5e-4 radians off it, either side of DIFF_MIN_SINE) both gradients of a shear-free texture have the isotropic cone's length texture_gradient(world_footprint * texel_density), and are perpendicular",
        || (unit(), 0usize..3, log_uniform(-2.0, 1.0), unit(), 0.0f64..3.0, 0.0f64..6.3, 0.0f64..6.3, log_uniform(-2.0, 2.0), log_uniform(-4.0, 0.0)).boxed(),
        |&(normal, off, size, centre, distance, start, angle, scale, width), anisotropic_cone_gradients| {
            let direction = towards(normal, 1.0 - [0.0, 1.0e-10, 1.0e-7][off], start);
            let (u, v) = (tangent(normal, 0.0), normal.cross(tangent(normal, 0.0)));
            let centre = centre * distance * size;
            let p = [start, start + 2.1, start + 4.2].map(|a| (centre + (u * a.cos() + v * a.sin()) * size).as_vec3());
            let (sin, cos) = angle.sin_cos();
            let uv = p.map(|point| {
                let (x, y) = (point.as_dvec3().dot(u), point.as_dvec3().dot(v));
                (DVec2::new(cos * x - sin * y, sin * x + cos * y) * scale).as_vec2()
            });
            let width = width as f32;
            let cone = RayCone { width, spread_angle: 0.0 };
            let isotropic = rc::texture_gradient(
                rc::world_footprint(cone, 0.0, normal.as_vec3(), direction.as_vec3())
                    * rc::texel_density(p[0], p[1], p[2], uv[0], uv[1], uv[2]),
                1.0,
            );
            let g = anisotropic_cone_gradients((width, direction.as_vec3(), p[0], p[1], p[2], uv[0], uv[1], uv[2]));
            let lengths = [g.dx.length(), g.dy.length()].map(f64::from);
            let iso = f64::from(isotropic);
            let errors = [
                (lengths[0] - iso).abs() / iso,
                (lengths[1] - iso).abs() / iso,
                f64::from(g.dx.dot(g.dy).abs()) / (lengths[0] * lengths[1]),
            ];
            Some(Deviation::worst(errors.map(|e| Deviation::new(e, F32_CHAIN))))
        },
    )
}

/// The height of `vertex` over the line through `a` and `b`: its distance from the foot of the
/// perpendicular.
fn height(vertex: DVec3, a: DVec3, b: DVec3) -> f64 {
    let edge = b - a;
    let foot = a + edge * ((vertex - a).dot(edge) / edge.dot(edge));
    (vertex - foot).length()
}

/// `rf_cone_barycentric_deltas`.
pub(in crate::ray_diff) fn cone_barycentric_deltas() -> Reference<(f32, Vec3, Vec3, Vec3), Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "|footprint| over each vertex's height above its opposite edge, the height measured to the foot of the perpendicular in f64",
        || {
            (signed_log(-6.0, 2.0), triangle())
                .prop_filter("a sliver", |(_, p)| {
                    let (e1, e2) = ((p[1] - p[0]).as_dvec3(), (p[2] - p[0]).as_dvec3());
                    e1.cross(e2).length() > 1.0e-3 * e1.length() * e2.length()
                })
                .boxed()
        },
        |&(footprint, p), cone_barycentric_deltas| {
            let footprint = footprint as f32;
            let q = p.map(Vec3::as_dvec3);
            let f = f64::from(footprint).abs();
            let expected = [f / height(q[0], q[1], q[2]), f / height(q[1], q[2], q[0]), f / height(q[2], q[0], q[1])];
            if expected.iter().any(|&delta| delta > 0.99 * f64::from(DIFF_MAX_VALUE)) {
                return None;
            }
            let got = cone_barycentric_deltas((footprint, p[0], p[1], p[2]));
            let bounds = widths(&enclosure::cone_barycentric_deltas(&(footprint, p[0], p[1], p[2])));
            Some(components(got, &expected, |i| bounds[i] + 1.0e-12 * expected[i]))
        },
    )
}

/// A cone `(width, spread)`, a unit direction and a distance.
fn cone_and_distance() -> BoxedStrategy<(f64, f64, DVec3, f64)> {
    let spread = prop_oneof![1 => Just(0.0f64), 4 => signed_log(-6.0, 0.0)];
    (signed_log(-6.0, 3.0), spread, unit(), log_uniform(-3.0, 3.0)).boxed()
}

/// `rf_ray_diff_from_cone`: the differential's rays.
pub(in crate::ray_diff) fn ray_diff_from_cone() -> Reference<(Vec2, Vec3), RayDiff> {
    Reference::new(
        Kind::ExactGeometry,
        "the differential's neighbour rays (O + dO, D + dD) per axis: after any distance t they lie |w + s t| from the central ray, across d, in two perpendicular directions",
        cone_and_distance,
        |&(w, s, d, t), ray_diff_from_cone| {
            let (cone, direction) = (Vec2::new(w as f32, s as f32), d.as_vec3());
            let diff = ray_diff_from_cone((cone, direction));
            let (w, s) = (f64::from(cone.x), f64::from(cone.y));
            let across = (w + s * t).abs();
            let d = direction.as_dvec3().normalize();
            let at = |o: Vec3, turn: Vec3| o.as_dvec3() + turn.as_dvec3() * t;
            let (x, y) = (at(diff.d_origin_dx, diff.d_direction_dx), at(diff.d_origin_dy, diff.d_direction_dy));
            let rounding = widths(&enclosure::ray_diff_from_cone(&(cone, direction)));
            let vector = |i: usize| rounding[i..i + 3].iter().map(|r| r * r).sum::<f64>().sqrt();
            let (ex, ey) = (vector(0) + t * vector(8), vector(4) + t * vector(12));
            // Duff et al.'s tangent of a direction that is unit only to rounding is unit and
            // perpendicular to it within a few times that.
            let eta = 8.0 * ((direction.as_dvec3().length() - 1.0).abs() + U);
            let deviations = [
                Deviation::new((x.length() - across).abs(), ex + eta * across),
                Deviation::new((y.length() - across).abs(), ey + eta * across),
                Deviation::new(x.dot(y).abs(), ex * y.length() + ey * x.length() + ex * ey + eta * across * across),
                Deviation::new(x.dot(d).abs(), ex + eta * across),
                Deviation::new(y.dot(d).abs(), ey + eta * across),
            ];
            Some(Deviation::worst(deviations))
        },
    )
}

/// `(w, s)` and `(-w, -s)` are the same cone; the form with `w >= 0` (and `s >= 0` when `w = 0`).
fn canonical(width: f64, spread: f64) -> DVec2 {
    if width < 0.0 || (width == 0.0 && spread < 0.0) {
        DVec2::new(-width, -spread)
    } else {
        DVec2::new(width, spread)
    }
}

/// `|got - expected|` relative to the larger of the cone's two magnitudes.
fn cone_error(got: Vec2, expected: DVec2) -> f64 {
    (got.as_dvec2() - expected).abs().max_element() / expected.abs().max_element()
}

/// `rf_ray_diff_from_cone`: the round trip.
pub(in crate::ray_diff) fn ray_diff_from_cone_round_trip() -> Reference<(Vec2, Vec3), RayDiff> {
    Reference::new(
        Kind::Identity,
        "cone -> differential -> cone (cone_from_ray_diff) returns the cone in its canonical form, (w, s) or (-w, -s) with w >= 0",
        cone_and_distance,
        |&(w, s, d, _), ray_diff_from_cone| {
            let (cone, direction) = (Vec2::new(w as f32, s as f32), d.as_vec3());
            let back = rd::cone_from_ray_diff(ray_diff_from_cone((cone, direction)), direction);
            let expected = canonical(f64::from(cone.x), f64::from(cone.y));
            Some(Deviation::new(cone_error(back, expected), F32_CHAIN))
        },
    )
}

/// `rf_cone_from_ray_diff`: a differential built from two cones.
pub(in crate::ray_diff) fn cone_from_ray_diff() -> Reference<(RayDiff, Vec3), Vec2> {
    Reference::new(
        Kind::Identity,
        "a differential built from one cone per axis (origin change w a, direction change s a across d, plus changes along d that the conversion drops) converts to the mean of the two cones' canonical forms",
        || {
            let axis = || (0.0f64..6.3, signed_log(-6.0, 2.0), signed_log(-6.0, 0.0), -10.0f64..10.0, -1.0f64..1.0);
            (unit(), axis(), axis()).boxed()
        },
        |&(d, x, y), cone_from_ray_diff| {
            let build = |(angle, w, s, along_o, along_d): (f64, f64, f64, f64, f64)| {
                let a = tangent(d, angle);
                (a * w + d * (along_o * w.abs()), a * s + d * along_d)
            };
            let ((ox, dx), (oy, dy)) = (build(x), build(y));
            let diff = RayDiff::new(ox.as_vec3(), oy.as_vec3(), dx.as_vec3(), dy.as_vec3());
            let direction = d.as_vec3();
            let got = cone_from_ray_diff((diff, direction));
            let expected = 0.5 * (canonical(x.1, x.2) + canonical(y.1, y.2));
            // The conversion's rounding (the enclosure), the inputs' rounding (u of each change)
            // and the direction's distance from unit length (the changes along d leave that much
            // across it), halved by the mean.
            let eta = (direction.as_dvec3().length() - 1.0).abs() + U;
            let rounding = widths(&enclosure::cone_from_ray_diff(&(diff, direction)));
            let input = |a: DVec3, b: DVec3| 0.5 * (U + 3.0 * eta) * (a.length() + b.length());
            let bounds = [rounding[0] + input(ox, oy), rounding[1] + input(dx, dy)];
            Some(components(got, &expected.to_array(), |i| bounds[i]))
        },
    )
}

/// `rf_cone_from_ray_diff`: propagation.
pub(in crate::ray_diff) fn cone_from_ray_diff_propagation() -> Reference<(RayDiff, Vec3), Vec2> {
    Reference::new(
        Kind::Identity,
        "converting commutes with propagation: the cone of a cone's differential transferred to a plane at |cos| >= 0.01 is the propagated cone (ray_cone::propagate), within an f32 error that grows as 1 / |cos|",
        || (cone_and_distance(), log_uniform(-2.0, 0.0), 0.0f64..6.3).boxed(),
        |&((w, s, d, t), cosine, angle), cone_from_ray_diff| {
            let (cone, direction, t) = (Vec2::new(w as f32, s as f32), d.as_vec3(), t as f32);
            let normal = towards(d, cosine, angle).as_vec3();
            let diff = rd::ray_diff_from_cone(cone, direction);
            let transferred = cone_from_ray_diff((rd::transfer(diff, direction, t, normal), direction));
            let propagated = rc::propagate(RayCone { width: cone.x, spread_angle: cone.y }, t, 0.0);
            let expected = canonical(f64::from(propagated.width), f64::from(propagated.spread_angle));
            // The transfer adds dt D with |dt| ~ |dO| / |cos|, which the conversion removes again.
            Some(Deviation::new(cone_error(transferred, expected), F32_CHAIN / cosine))
        },
    )
}
