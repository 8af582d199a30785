//! References of the reflection and refraction section: the exact reflection and Snell
//! refraction of the moved ray at the moved unit normal, by central differences in f64; the
//! interpolated unit normal along a barycentric path; a planar mirror as a mirror-image camera.

use super::super::{enclosure, Camera};
use super::camera::image_plane_point;
use super::{components, listed, widths};
use crate::exact::{derivative, log_uniform, mirrored, snell, towards, unit};
use crate::reference::{Deviation, Kind, Reference};
use glam::{DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, RayDiff, RefractedRayDiff};

/// A vector perpendicular to the unit `v`, of random direction and a length `10^[low, high)`.
fn perpendicular(v: DVec3, low: f64, high: f64) -> BoxedStrategy<DVec3> {
    (0.0f64..6.3, log_uniform(low, high))
        .prop_map(move |(angle, length)| crate::exact::tangent(v, angle) * length)
        .boxed()
}

/// A unit direction and a unit normal at `|cos|` 0.05 to 1 from either side, a differential whose
/// direction changes are perpendicular to the direction, and normal changes perpendicular to the
/// normal (as the derivatives of unit vectors are), all rounded to f32.
fn surface_hit() -> BoxedStrategy<(RayDiff, Vec3, Vec3, Derivatives3)> {
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
fn non_unit(diff: &RayDiff, direction: Vec3, normal: Vec3, dn: Derivatives3) -> f64 {
    let (d, n) = (direction.as_dvec3(), normal.as_dvec3());
    let along =
        |v: Vec3, unit: DVec3| v.as_dvec3().dot(unit.normalize()).abs() / v.as_dvec3().length().max(1.0e-300);
    (d.length() - 1.0).abs()
        + (n.length() - 1.0).abs()
        + along(diff.d_direction_dx, d).max(along(diff.d_direction_dy, d))
        + along(dn.dx, n).max(along(dn.dy, n))
}

/// The changes of one axis: origin, direction, normal.
fn changes(diff: &RayDiff, dn: Derivatives3, axis: usize) -> (DVec3, DVec3, DVec3) {
    let pick = |x: Vec3, y: Vec3| if axis == 0 { x } else { y }.as_dvec3();
    (
        pick(diff.d_origin_dx, diff.d_origin_dy),
        pick(diff.d_direction_dx, diff.d_direction_dy),
        pick(dn.dx, dn.dy),
    )
}

/// `rf_normal_derivatives`.
pub(in crate::ray_diff) fn normal_derivatives(
) -> Reference<(Vec3, Vec3, Vec3, Vec2, Derivatives2), Derivatives3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the unit normal interpolated from the vertex normals of a smooth surface along the barycentric path (u + h du, v + h dv) (Igehy)",
        || {
            let normal = || (unit(), 0.0f64..0.5).prop_map(|(v, tilt)| v * tilt);
            let change = || (0.0f64..6.3, log_uniform(-4.0, 0.0)).prop_map(|(a, l)| DVec2::from_angle(a) * l);
            (unit(), (normal(), normal(), normal()), (-0.2f64..1.2, -0.2f64..1.2), (change(), change())).boxed()
        },
        |&(n, (a, b, c), (u, v), (dx, dy)), normal_derivatives| {
            let [n0, n1, n2] = [a, b, c].map(|tilt| (n + tilt).normalize().as_vec3());
            let uv = Vec2::new(u as f32, v as f32);
            let changes = Derivatives2::new(dx.as_vec2(), dy.as_vec2());
            let args = (n0, n1, n2, uv, changes);
            let got = normal_derivatives(args);
            let [m0, m1, m2] = [n0, n1, n2].map(Vec3::as_dvec3);
            let at = |b: DVec2| ((1.0 - b.x - b.y) * m0 + b.x * m1 + b.y * m2).normalize();
            let along = |step: Vec2| derivative(|h| at(uv.as_dvec2() + step.as_dvec2() * h), 1.0e-4 / f64::from(step.length()), 2.0);
            let (ex, ey) = (along(changes.dx), along(changes.dy));
            let bounds = widths(&enclosure::normal_derivatives(&args));
            let error = ex.error.max(ey.error);
            Some(components(got, &listed(&[ex.value, ey.value], 0), |i| bounds[i] + error))
        },
    )
}

/// `rf_reflect_ray_diff`: the exact reflection, differentiated.
pub(in crate::ray_diff) fn reflect_ray_diff() -> Reference<(RayDiff, Vec3, Vec3, Derivatives3), RayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the exact reflection of D + h dD at the unit normal normalize(N + h dN) (Igehy); the origin changes pass unchanged",
        surface_hit,
        |&(diff, direction, normal, dn), reflect_ray_diff| {
            let got = reflect_ray_diff((diff, direction, normal, dn));
            let (d, n) = (direction.as_dvec3(), normal.as_dvec3());
            let reflected = |axis: usize| {
                let (_, dd, dnormal) = changes(&diff, dn, axis);
                let step = 1.0e-4 / (dd.length() + dnormal.length());
                derivative(|h| mirrored(d + dd * h, (n + dnormal * h).normalize()), step, 4.0)
            };
            let (rx, ry) = (reflected(0), reflected(1));
            let expected = listed(&[changes(&diff, dn, 0).0, changes(&diff, dn, 1).0, rx.value, ry.value], 1);
            // The formula takes N unit and dN perpendicular to it: each of its terms (at most
            // 2 |dD| + 4 |D| |dN| in all) is off by twice the inputs' relative distance from that.
            let assumption = 2.0 * non_unit(&diff, direction, normal, dn);
            let bounds = widths(&enclosure::reflect_ray_diff(&(diff, direction, normal, dn)));
            Some(components(got, &expected, |i| {
                let (_, dd, dnormal) = changes(&diff, dn, (i / 4) % 2);
                let extra = if i >= 8 {
                    rx.error.max(ry.error) + assumption * (2.0 * dd.length() + 4.0 * d.length() * dnormal.length())
                } else {
                    0.0
                };
                bounds[i] + extra
            }))
        },
    )
}

/// `rf_refract_ray_diff`.
pub(in crate::ray_diff) fn refract_ray_diff(
) -> Reference<(RayDiff, Vec3, Vec3, Derivatives3, f32), RefractedRayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of Snell's law (GLSL's refract, the normal turned to the ray) for normalize(D + h dD) at normalize(N + h dN), or of the reflection past the critical angle, with the flag (Igehy)",
        || (surface_hit(), 0.3f64..3.0).boxed(),
        |&((diff, direction, normal, dn), eta), refract_ray_diff| {
            let eta32 = eta as f32;
            let (d, n, eta) = (direction.as_dvec3(), normal.as_dvec3(), f64::from(eta32));
            let cosine = d.normalize().dot(n.normalize());
            let k = 1.0 - eta * eta * (1.0 - cosine * cosine);
            // Near the critical angle the map is singular (sqrt(k)): left to its own test.
            if k.abs() < 0.05 {
                return None;
            }
            let got = refract_ray_diff((diff, direction, normal, dn, eta32));
            let scattered = |dd: DVec3, dnormal: DVec3, h: f64| {
                let (d, n) = ((d + dd * h).normalize(), (n + dnormal * h).normalize());
                snell(d, n, eta).unwrap_or_else(|| mirrored(d, n))
            };
            let turned = |axis: usize| {
                let (_, dd, dnormal) = changes(&diff, dn, axis);
                let step = 1.0e-4 * k.abs() / (dd.length() + dnormal.length());
                derivative(|h| scattered(dd, dnormal, h), step, 4.0)
            };
            let (tx, ty) = (turned(0), turned(1));
            let mut expected = listed(&[changes(&diff, dn, 0).0, changes(&diff, dn, 1).0, tx.value, ty.value], 1);
            expected.push(if k < 0.0 { 1.0 } else { 0.0 });
            // The formula takes D and N unit and the changes perpendicular to them; its terms
            // (eta |dD|, mu |dN| and the rate times both, rate = eta - eta^2 cos / cos t) are off
            // by twice the inputs' relative distance from that.
            let transmitted = k.max(0.0).sqrt().max(f64::from(rd::DIFF_MIN_COS));
            let (rate, mu) = if k < 0.0 {
                (2.0, 2.0)
            } else {
                ((eta - eta * eta * cosine.abs() / transmitted).abs(), eta * cosine.abs() + k.sqrt())
            };
            let assumption = 2.0 * non_unit(&diff, direction, normal, dn);
            let bounds = widths(&enclosure::refract_ray_diff(&(diff, direction, normal, dn, eta32)));
            Some(components(got, &expected, |i| {
                let (_, dd, dnormal) = changes(&diff, dn, (i / 4) % 2);
                let terms = eta.max(1.0) * dd.length() + mu * dnormal.length() + rate * (dd.length() + dnormal.length());
                let extra = if (8..16).contains(&i) {
                    tx.error.max(ty.error) + assumption * terms
                } else {
                    0.0
                };
                bounds[i] + extra
            }))
        },
    )
}

/// The camera `(pixel, size, fov_y, right, up, view)` mirrored at the plane with unit normal
/// `normal`: its basis mirrored (the position does not enter the eye-ray differential).
fn mirrored_camera(&(pixel, size, fov_y, right, up, view): &Camera, normal: DVec3) -> Camera {
    let mirror = |v: Vec3| mirrored(v.as_dvec3(), normal).as_vec3();
    (pixel, size, fov_y, mirror(right), mirror(up), mirror(view))
}

/// The crate's eye-ray differential of a camera (f32).
fn eye_ray_diff(&(pixel, size, fov_y, right, up, view): &Camera) -> RayDiff {
    rd::eye_ray_diff(pixel, size, fov_y, right, up, view)
}

/// `rf_reflect_ray_diff`: a planar mirror.
pub(in crate::ray_diff) fn reflect_ray_diff_mirror_camera(
) -> Reference<(RayDiff, Vec3, Vec3, Derivatives3), RayDiff> {
    Reference::new(
        Kind::ExactGeometry,
        "a planar mirror is a mirror-image camera: the reflected eye-ray differential has the mirrored camera's direction changes, and the same origin changes after any further distance to a second plane",
        || {
            (
                (unit(), 0.0f64..6.3, 0.4f64..1.5),
                (0.0f64..1.0, 0.0f64..1.0, 1.0f64..20.0, 0.2f64..1.0, 0.0f64..6.3),
                (0.5f64..20.0, 0.2f64..1.0, 0.0f64..6.3),
            )
                .boxed()
        },
        |&((view, roll, fov_y), (px, py, t, cosine, angle), (t1, cosine1, angle1)), reflect_ray_diff| {
            let right = crate::exact::tangent(view, roll);
            let size = DVec2::new(1280.0, 720.0);
            let pixel = (DVec2::new(px, py) * (size - 6.0)).floor() + 2.0;
            let camera = (
                pixel.as_vec2(),
                size.as_vec2(),
                fov_y as f32,
                right.as_vec3(),
                view.cross(right).as_vec3(),
                view.as_vec3(),
            );
            let direction = image_plane_point(&camera, pixel).normalize();
            let normal = towards(direction, cosine, angle);
            let transferred = rd::transfer(eye_ray_diff(&camera), direction.as_vec3(), t as f32, normal.as_vec3());
            let no_curvature = Derivatives3::new(Vec3::ZERO, Vec3::ZERO);
            let reflected = reflect_ray_diff((transferred, direction.as_vec3(), normal.as_vec3(), no_curvature));
            let reflected_direction = mirrored(direction, normal);
            // (A normal n = towards(d, c, a) has dot(n, d) = -c: it faces the ray.)
            // The mirror-image camera sees the same pixel along the reflected direction, from
            // behind the mirror, through the same point.
            let image_diff = eye_ray_diff(&mirrored_camera(&camera, normal));
            let second = towards(reflected_direction, cosine1, angle1);
            let after_mirror = rd::transfer(reflected, reflected_direction.as_vec3(), t1 as f32, second.as_vec3());
            let from_image = rd::transfer(image_diff, reflected_direction.as_vec3(), (t + t1) as f32, second.as_vec3());
            let relative = |a: [Vec3; 2], b: [Vec3; 2]| {
                let scale = b[0].as_dvec3().length().max(b[1].as_dvec3().length());
                (a[0].as_dvec3() - b[0].as_dvec3()).length().max((a[1].as_dvec3() - b[1].as_dvec3()).length()) / scale
            };
            let directions = relative(
                [reflected.d_direction_dx, reflected.d_direction_dy],
                [image_diff.d_direction_dx, image_diff.d_direction_dy],
            );
            let positions = relative(
                [after_mirror.d_origin_dx, after_mirror.d_origin_dy],
                [from_image.d_origin_dx, from_image.d_origin_dy],
            );
            // f32 arithmetic on unit vectors and distances up to 40: a few hundred ULP after two
            // transfers at cosines down to 0.2.
            Some(Deviation::new(directions.max(positions), 1.0e-4))
        },
    )
}
