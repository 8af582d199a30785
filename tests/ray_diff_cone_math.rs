//! The anisotropic cone footprint and the cone <-> ray differential conversions against the other
//! functions of the crate, on the CPU: the exact ray differential of a pinhole's central pixel, a
//! transferred cone differential and the pinhole cone. Each test prints the worst error it
//! measured. (The single-function properties, the isotropic gradient at normal incidence, the
//! `1 / |cos|` growth of the major axis, the OptiX Toolkit's projection and the conversions' round
//! trip and commutation with propagation, are references of the records in the cases crate.)

mod common;

use common::{worst_case, Rng};
use glam::{DMat3, DVec3, Mat3, Vec2, Vec3};
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, RayDiff};

impl Rng {
    /// A unit direction meeting the unit normal `normal` at `|cos| = cosine`, towards it.
    fn direction_at(&mut self, normal: DVec3, cosine: f64) -> DVec3 {
        let tangent = normal.cross(self.unit()).normalize();
        (tangent * (1.0 - cosine * cosine).sqrt() - normal * cosine).normalize()
    }
}

/// A triangle in the plane through `centre` with unit normal `normal` (vertices at distance `size`).
fn triangle_in_plane(rng: &mut Rng, centre: DVec3, normal: DVec3, size: f64) -> [Vec3; 3] {
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let vertex = |angle: f64| (centre + (u * angle.cos() + v * angle.sin()) * size).as_vec3();
    let start = rng.range(0.0, std::f64::consts::TAU);
    [vertex(start), vertex(start + 2.1), vertex(start + 4.2)]
}

/// The symmetric matrix `sum_i a_i a_i^T` of an ellipse spanned by conjugate semi-axes `a_i`: the
/// same for every conjugate pair of one ellipse, so it compares ellipses whatever their axes.
fn ellipse(axes: &[DVec3]) -> DMat3 {
    axes.iter()
        .map(|a| DMat3::from_cols(*a * a.x, *a * a.y, *a * a.z))
        .fold(DMat3::ZERO, |m, a| m + a)
}

/// `|a - b| / |b|` in the Frobenius norm.
fn matrix_error(a: DMat3, b: DMat3) -> f64 {
    let norm = |m: DMat3| m.to_cols_array().iter().map(|x| x * x).sum::<f64>().sqrt();
    norm(a - b) / norm(b)
}

fn axes(d: Derivatives3) -> [DVec3; 2] {
    [d.dx.as_dvec3(), d.dy.as_dvec3()]
}

/// UV gradients as 3-vectors (z = 0), for [`ellipse`].
fn uv_axes(g: Derivatives2) -> [DVec3; 2] {
    [g.dx.as_dvec2().extend(0.0), g.dy.as_dvec2().extend(0.0)]
}

/// Relative f32 error of a value computed through a few dozen roundings of well-conditioned
/// operations (about 40 x 6e-8, rounded up).
const F32_CHAIN: f64 = 1.0e-5;

/// The exact ray differential of a pinhole camera's central pixel (square pixels) is isotropic,
/// `|dD/dx| = |dD/dy| = 2 tan(fov / 2) / H`: transferred to a surface and taken to texture space
/// (RTG Eq. 12-21), it spans the same ellipse as the anisotropic cone footprint of the pinhole cone
/// (`pixel_spread_angle_small`) at that distance, at any incidence; the texture map is arbitrary
/// (sheared). Both are f32 chains; their relative difference grows as `1 / cos^2` (the ellipse
/// matrix squares the major axis).
#[test]
fn the_central_pixel_differential_spans_the_cone_footprint() {
    let worst = worst_case(0xa11_0003, 5_000, |rng| {
        let view = rng.unit();
        let right = view.any_orthonormal_vector();
        let up = view.cross(right);
        let (height, fov) = (rng.range(200.0, 2000.0).round(), rng.range(0.3, 1.5));
        let size = Vec2::new(height as f32 * 1.5, height as f32);
        let pixel = size * 0.5 - 0.5;
        let diff = rd::eye_ray_diff(
            pixel,
            size,
            fov as f32,
            right.as_vec3(),
            up.as_vec3(),
            view.as_vec3(),
        );
        let direction = -view;
        let t = rng.log_range(-1.0, 3.0);
        let cosine = rng.log_range(-2.0, 0.0);
        let normal = -rng.direction_at(-direction, cosine);
        let p = triangle_in_plane(rng, direction * t, normal, t * 0.1);
        let uv: [Vec2; 3] = std::array::from_fn(|_| Vec2::new(rng.next() as f32, rng.next() as f32));
        let (d, t32) = (direction.as_vec3(), t as f32);
        let at_hit = rd::transfer(diff, d, t32, normal.as_vec3());
        let barycentric = rd::barycentric_derivatives(at_hit, d, 0.0, p[0], p[1], p[2]);
        let differential = rd::texture_derivatives(barycentric, uv[0], uv[1], uv[2]);
        let width = rc::width_at(
            rc::pinhole_ray_cone(rc::pixel_spread_angle_small(fov as f32, size.y)),
            t32,
        );
        let cone = rd::anisotropic_cone_gradients(width, d, p[0], p[1], p[2], uv[0], uv[1], uv[2]);
        let error = matrix_error(ellipse(&uv_axes(cone)), ellipse(&uv_axes(differential)));
        assert!(
            error < F32_CHAIN / (cosine * cosine),
            "cos {cosine}: {cone:?} vs {differential:?}"
        );
        error * cosine * cosine
    });
    println!("central pixel: worst relative difference of the UV ellipses x cos^2 {worst:.2e}");
}

/// The differential of a cone, transferred to a surface, spans the ellipse of the anisotropic
/// footprint of the propagated cone there (the OptiX Toolkit's projection onto the surface: projected
/// this way, the cone gives the same ellipse), at any incidence down to `|cos| = 0.01`.
#[test]
fn a_transferred_cone_differential_spans_the_anisotropic_footprint() {
    let worst = worst_case(0xa11_0006, 20_000, |rng| {
        let cone = RayCone {
            width: rng.log_range(-6.0, 0.0) as f32,
            spread_angle: rng.log_range(-5.0, -1.0) as f32,
        };
        let direction = rng.unit();
        let t = rng.log_range(-2.0, 3.0) as f32;
        let cosine = rng.log_range(-2.0, 0.0);
        let normal = -rng.direction_at(-direction, cosine);
        let (d, n) = (direction.as_vec3(), normal.as_vec3());
        let diff = rd::ray_diff_from_cone(Vec2::new(cone.width, cone.spread_angle), d);
        let at_hit = rd::transfer(diff, d, t, n);
        let projected = [at_hit.d_origin_dx.as_dvec3(), at_hit.d_origin_dy.as_dvec3()];
        let footprint = rd::anisotropic_cone_axes(rc::width_at(cone, t), n, d);
        let error = matrix_error(ellipse(&projected), ellipse(&axes(footprint)));
        assert!(
            error < F32_CHAIN / (cosine * cosine),
            "cos {cosine}: {at_hit:?} vs {footprint:?}"
        );
        error * cosine * cosine
    });
    println!("transferred cone differential vs anisotropic footprint: worst relative ellipse difference x cos^2 {worst:.2e}");
}

/// A pinhole's eye-ray differential (`dO = 0`) converts to a cone of width 0 whose spread is the
/// mean of the pixel's two angular sizes: at the central pixel with square pixels, the pixel spread
/// angle `2 tan(fov / 2) / H`.
#[test]
fn a_pinhole_differential_is_the_pixel_cone() {
    let mut worst = 0.0f64;
    for (height, fov) in [(480.0f32, 0.8f32), (1080.0, 1.2), (2160.0, 0.3)] {
        let size = Vec2::new(height * 16.0 / 9.0, height);
        let camera = Mat3::from_rotation_y(0.3) * Mat3::from_rotation_x(-0.2);
        let (right, up, view) = (camera.x_axis, camera.y_axis, camera.z_axis);
        let diff: RayDiff = rd::eye_ray_diff(size * 0.5 - 0.5, size, fov, right, up, view);
        let cone = rd::cone_from_ray_diff(diff, -view);
        let pixel = rc::pixel_spread_angle_small(fov, height);
        let error = f64::from((cone.y - pixel).abs() / pixel);
        assert!(cone.x == 0.0 && error < F32_CHAIN, "{cone} vs {pixel}");
        worst = worst.max(error);
    }
    println!("central pixel differential -> cone: worst relative spread error {worst:.2e}");
}
