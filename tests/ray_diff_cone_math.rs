//! The anisotropic cone footprint and the cone <-> ray differential conversions, checked on the CPU
//! against independent constructions: the isotropic cone's gradient, the `1 / |cos|` growth of the
//! major axis, the crate's exact ray differentials of a pinhole's central pixel, the OptiX Toolkit's
//! projection of a cone onto a surface, and the conversions' round trip and commutation with
//! propagation. Each test prints the worst error it measured.

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

/// A texture mapping without shear: UV = rotation by `angle` and uniform scale `scale` of the
/// triangle's in-plane coordinates.
fn similar_uvs(p: [Vec3; 3], normal: DVec3, angle: f64, scale: f64) -> [Vec2; 3] {
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let (sin, cos) = angle.sin_cos();
    p.map(|point| {
        let (x, y) = (point.as_dvec3().dot(u), point.as_dvec3().dot(v));
        (glam::DVec2::new(cos * x - sin * y, sin * x + cos * y) * scale).as_vec2()
    })
}

/// Relative f32 error of a value computed through a few dozen roundings of well-conditioned
/// operations (about 40 x 6e-8, rounded up).
const F32_CHAIN: f64 = 1.0e-5;

/// JCGT 2021's anisotropic footprint: at normal incidence (exactly, and 1.4e-5 and 4.5e-4 radians off it, on either side
/// of `DIFF_MIN_SINE`), both gradients have the isotropic
/// cone's length `texture_gradient(world_footprint * texel_density)` for a texture mapped without
/// shear, and they are perpendicular. The normals include (1, -1, 1) / sqrt(3), for which the
/// OptiX Toolkit's fallback tangent `(N.y, N.z, -N.x)` is parallel to N.
#[test]
fn normal_incidence_gives_the_isotropic_gradient() {
    let mut rng = Rng(0xa11_0001);
    let mut worst = 0.0f64;
    for case in 0..10_000 {
        let normal = if case % 100 == 0 {
            DVec3::new(1.0, -1.0, 1.0).normalize()
        } else {
            rng.unit()
        };
        let off_normal = [0.0, 1.0e-10, 1.0e-7][case % 3];
        let direction = rng.direction_at(normal, 1.0 - off_normal);
        let size = rng.log_range(-2.0, 1.0);
        let centre = rng.unit() * rng.range(0.0, 3.0) * size;
        let p = triangle_in_plane(&mut rng, centre, normal, size);
        let uv = similar_uvs(p, normal, rng.range(0.0, 6.3), rng.log_range(-2.0, 2.0));
        let width = rng.log_range(-4.0, 0.0) as f32;
        let cone = RayCone {
            width,
            spread_angle: 0.0,
        };
        let isotropic = rc::texture_gradient(
            rc::world_footprint(cone, 0.0, normal.as_vec3(), direction.as_vec3())
                * rc::texel_density(p[0], p[1], p[2], uv[0], uv[1], uv[2]),
            1.0,
        );
        let g =
            rd::anisotropic_cone_gradients(width, direction.as_vec3(), p[0], p[1], p[2], uv[0], uv[1], uv[2]);
        let lengths = [g.dx.length(), g.dy.length()];
        let error = lengths
            .iter()
            .map(|&l| (f64::from(l) - f64::from(isotropic)).abs() / f64::from(isotropic))
            .fold(0.0, f64::max)
            .max(f64::from(g.dx.dot(g.dy).abs() / (lengths[0] * lengths[1])));
        assert!(
            error < F32_CHAIN,
            "normal {normal} width {width}: {g:?} vs {isotropic}"
        );
        worst = worst.max(error);
    }
    println!("normal incidence: worst relative difference from the isotropic gradient {worst:.2e}");
}

/// JCGT 2021's anisotropic footprint: the major axis is `|width| / |cos|` long and the minor one `|width|`, perpendicular to
/// each other, to the normal and (the minor one) to the ray, from head-on down to `|cos| = 1e-3`;
/// the gradients of a shear-free texture follow with the texture's scale.
#[test]
fn the_major_axis_grows_as_one_over_the_cosine() {
    let worst = worst_case(0xa11_0002, 10_000, |rng| {
        let normal = rng.unit();
        let cosine = rng.log_range(-3.0, 0.0);
        let direction = rng.direction_at(normal, cosine);
        let width = rng.log_range(-4.0, 2.0) as f32;
        let a = rd::anisotropic_cone_axes(width, normal.as_vec3(), direction.as_vec3());
        let (major, minor) = (a.dx.as_dvec3(), a.dy.as_dvec3());
        let w = f64::from(width);
        let errors = [
            (major.length() * cosine - w).abs() / w,
            (minor.length() - w).abs() / w,
            major.dot(minor).abs() / (major.length() * minor.length()),
            major.dot(normal).abs() / major.length(),
            minor.dot(direction).abs() / minor.length(),
        ];
        let bound = F32_CHAIN / cosine;
        assert!(errors.iter().all(|&e| e < bound), "cos {cosine}: {errors:?}");

        let p = triangle_in_plane(rng, DVec3::ZERO, normal, 1.0);
        let scale = rng.log_range(-1.0, 1.0);
        let uv = similar_uvs(p, normal, rng.range(0.0, 6.3), scale);
        let g =
            rd::anisotropic_cone_gradients(width, direction.as_vec3(), p[0], p[1], p[2], uv[0], uv[1], uv[2]);
        let gradient_errors = [
            (f64::from(g.dx.length()) * cosine - w * scale).abs() / (w * scale),
            (f64::from(g.dy.length()) - w * scale).abs() / (w * scale),
        ];
        assert!(
            gradient_errors.iter().all(|&e| e < bound),
            "cos {cosine}: {gradient_errors:?}"
        );
        errors
            .iter()
            .chain(&gradient_errors)
            .fold(0.0, |m, &e| m.max(e * cosine))
    });
    println!("1 / cos growth down to cos = 1e-3: worst relative error x cos {worst:.2e}");
}

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

/// The OptiX Toolkit's `projectToRayDifferentialsOnSurface`, in f64: `dPdx = normalize(d - dot(d, n) n)
/// * w / max(|dot(d, n)|, 1 / 16)` (a fixed tangent when `|dot| >= 0.999`), `dPdy = normalize(cross(dPdx, n)) * w`.
fn optix_projection(width: f64, d: DVec3, n: DVec3) -> [DVec3; 2] {
    let cosine = d.dot(n);
    let dpdx = (d - n * cosine).normalize() * (width / cosine.abs().max(1.0 / 16.0));
    [dpdx, dpdx.cross(n).normalize() * width]
}

/// Where the OptiX Toolkit's projection applies neither its anisotropy cap nor its fixed tangent
/// (`1/16 <= |cos| < 0.999`), it spans the same ellipse as `anisotropic_cone_axes`; below 1/16 the
/// crate's major axis is longer by `1 / (16 |cos|)` (no cap but `DIFF_MIN_COS`).
#[test]
fn the_optix_toolkit_projection_spans_the_same_ellipse() {
    let worst = worst_case(0xa11_0004, 10_000, |rng| {
        let normal = rng.unit();
        let cosine = rng.range(1.0 / 16.0, 0.999);
        let direction = rng.direction_at(normal, cosine);
        let width = rng.log_range(-4.0, 2.0);
        let ours = rd::anisotropic_cone_axes(width as f32, normal.as_vec3(), direction.as_vec3());
        let error = matrix_error(
            ellipse(&axes(ours)),
            ellipse(&optix_projection(width, direction, normal)),
        );
        assert!(error < F32_CHAIN / (cosine * cosine), "cos {cosine}: {error}");
        error
    });
    let (normal, direction) = (DVec3::Z, DVec3::new(0.999_8, 0.0, -0.02).normalize());
    let ours = rd::anisotropic_cone_axes(1.0, normal.as_vec3(), direction.as_vec3());
    let capped = optix_projection(1.0, direction, normal)[0].length();
    let ratio = f64::from(ours.dx.length()) / capped;
    assert!((ratio - 1.0 / (16.0 * 0.02)).abs() < 1.0e-3 * ratio, "{ratio}");
    println!("OptiX projection, 1/16 <= |cos| < 0.999: worst relative ellipse difference {worst:.2e}; at |cos| = 0.02 our major axis is {ratio:.3} x theirs");
}

/// `(w, s)` and `(-w, -s)` are the same cone; the form with `w >= 0` (and `s >= 0` when `w = 0`).
fn canonical(width: f32, spread: f32) -> (f32, f32) {
    if width < 0.0 || (width == 0.0 && spread < 0.0) {
        (-width, -spread)
    } else {
        (width, spread)
    }
}

/// `|a - b|` relative to the larger of the two cone values' magnitudes.
fn cone_error(got: Vec2, expected: (f32, f32)) -> f64 {
    let scale = f64::from(expected.0.abs().max(expected.1.abs()));
    (f64::from(got.x) - f64::from(expected.0))
        .abs()
        .max((f64::from(got.y) - f64::from(expected.1)).abs())
        / scale
}

/// cone -> differential -> cone returns the cone (in its canonical form), and converting commutes
/// with propagation: the cone of a transferred differential ([`rd::transfer`] to a plane at
/// `|cos| >= 0.01`) is the propagated cone. The transfer adds `dt D` with `|dt| ~ |dO| / |cos|`,
/// which the conversion removes again across `D`: the f32 error grows as `1 / |cos|`.
#[test]
fn conversions_round_trip_and_commute_with_propagation() {
    let mut rng = Rng(0xa11_0005);
    let (mut worst_round_trip, mut worst_commute) = (0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let sign = if rng.next() < 0.5 { -1.0 } else { 1.0 };
        let width = (sign * rng.log_range(-6.0, 3.0)) as f32;
        let spread = (rng.range(-1.0, 1.0) * rng.log_range(-6.0, 0.0)) as f32;
        let direction = rng.unit();
        let d = direction.as_vec3();
        let diff = rd::ray_diff_from_cone(Vec2::new(width, spread), d);
        let back = rd::cone_from_ray_diff(diff, d);
        let round_trip = cone_error(back, canonical(width, spread));
        assert!(round_trip < F32_CHAIN, "({width}, {spread}) along {d}: {back}");
        worst_round_trip = worst_round_trip.max(round_trip);

        let t = rng.log_range(-3.0, 3.0) as f32;
        let cosine = rng.log_range(-2.0, 0.0);
        let normal = -rng.direction_at(-direction, cosine).as_vec3();
        let transferred = rd::cone_from_ray_diff(rd::transfer(diff, d, t, normal), d);
        let propagated = rc::propagate(
            RayCone {
                width,
                spread_angle: spread,
            },
            t,
            0.0,
        );
        let expected = canonical(propagated.width, propagated.spread_angle);
        let commute = cone_error(transferred, expected);
        assert!(
            commute < F32_CHAIN / cosine,
            "cos {cosine} t {t}: {transferred} vs {expected:?}"
        );
        worst_commute = worst_commute.max(commute * cosine);
    }
    println!(
        "round trip: worst relative error {worst_round_trip:.2e}; transfer vs propagate: worst relative error x cos {worst_commute:.2e}"
    );
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
