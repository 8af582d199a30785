//! The proof of [`reflect_ray_diff`](ray_footprint::ray_diff::reflect_ray_diff): its record, its
//! enclosure and its references, the exact reflection and a planar mirror as a mirror-image camera.

use crate::degenerate::{parts, value};
use crate::exact::{derivative, mirrored, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::pinhole::{image_plane_point, Camera};
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::reflection::shared::{changes, non_unit, surface_hit};
use crate::ray_diff::rows::direction_dx;
use crate::ray_diff::strategy::{derivatives3, ray_diff};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::normal_and_direction;
use glam::{DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives3, RayDiff};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_reflect_ray_diff`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let flat = Derivatives3::default();
    Record::new(
        Module::RayDiff,
        "reflect_ray_diff",
        |(diff, d, n, dn)| rd::reflect_ray_diff(diff, d, n, dn),
        || {
            (ray_diff(), normal_and_direction(), derivatives3())
                .prop_map(|(diff, (n, d), dn)| (diff, d, n, dn))
                .boxed()
        },
    )
    .enclosure(enclosure)
    .reference(reference())
    .reference(reflect_ray_diff_mirror_camera())
    .symmetry(Symmetry::rotation(
        "everything turned: the differential turned",
        |&(diff, d, n, dn): &(RayDiff, Vec3, Vec3, Derivatives3), r| {
            (turned(diff, r), r * d, r * n, turned3(dn, r))
        },
        |diff: RayDiff, r| turned(diff, r.transpose()),
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the x and y parts exchanged",
        |&(diff, d, n, dn): &(RayDiff, Vec3, Vec3, Derivatives3)| (swapped(diff), d, n, swapped3(dn)),
        swapped,
    ))
    .symmetry(Symmetry::exchange(
        "the normal and its derivatives flipped: the same",
        |&(diff, d, n, dn): &(RayDiff, Vec3, Vec3, Derivatives3)| {
            (diff, d, -n, Derivatives3::new(-dn.dx, -dn.dy))
        },
        |diff: RayDiff| diff,
    ))
    .fuzz(|d| (d.ray_diff(), d.unit(), d.unit(), d.derivatives3()))
    .degenerate(vec![
        value(
            "ray in the surface plane, flat surface",
            "dD - 2 dot(dD, N) N",
            (direction_dx(z), x, z, flat),
            parts(direction_dx(-z)),
        ),
        value(
            "zero direction differentials, flat surface",
            "zero direction differentials, origin differentials kept",
            (RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO), -z, z, flat),
            parts(RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "head-on (D = -N), normal turning by dN/dx = (1, 0, 0)",
            "dR/dx = 2 dN/dx",
            (RayDiff::ZERO, -z, z, Derivatives3::new(x, Vec3::ZERO)),
            parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, 2.0 * x, Vec3::ZERO)),
        ),
    ])
}

/// One direction differential reflected at a hit; the differentials come as intervals, the ray
/// and the normal are exact.
pub fn reflected_direction(dd: Interval3, direction: Vec3, normal: Vec3, dn: Interval3) -> Interval3 {
    let (d, n) = (interval3(direction), interval3(normal));
    let cosine = d.dot(n);
    dd - (dn * cosine + n * (dd.dot(n) + d.dot(dn))) * Interval::c(2.0)
}

type ReflectArgs = (RayDiff, Vec3, Vec3, Derivatives3);

/// `rf_reflect_ray_diff` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(&(diff, direction, normal, dn): &ReflectArgs) -> Vec<Interval> {
    intervals::ray_diff(
        interval3(diff.d_origin_dx),
        interval3(diff.d_origin_dy),
        reflected_direction(
            interval3(diff.d_direction_dx),
            direction,
            normal,
            interval3(dn.dx),
        ),
        reflected_direction(
            interval3(diff.d_direction_dy),
            direction,
            normal,
            interval3(dn.dy),
        ),
    )
}

/// A reference of `rf_reflect_ray_diff`: the exact reflection, differentiated.
fn reference() -> Reference<(RayDiff, Vec3, Vec3, Derivatives3), RayDiff> {
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
            let bounds = widths(&enclosure(&(diff, direction, normal, dn)));
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

/// A reference of `rf_reflect_ray_diff`: a planar mirror.
fn reflect_ray_diff_mirror_camera() -> Reference<(RayDiff, Vec3, Vec3, Derivatives3), RayDiff> {
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
