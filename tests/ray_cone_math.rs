//! The ray-cone math itself, checked against exact geometry computed in f64 and against the
//! crate's ray differentials on the same paths (no GPU needed).

use glam::{DVec2, DVec3, Mat4, Vec2, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{TestRng, TestRunner};
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::ray_diff::{self as rd, Derivatives3, RayDiff};

/// Rounding slack for a value computed in f32 through a handful of operations.
const F32_SLACK: f64 = 1.0e-5;

/// Width, on a plane perpendicular to the view axis at distance `t`, of the central pixel of a
/// pinhole camera: intersect the rays through the pixel's top and bottom edges (NDC y = +-1/H)
/// with the plane.
fn exact_central_pixel_width(fov_y: f64, height: f64, t: f64) -> f64 {
    let tan_half = (0.5 * fov_y).tan();
    let edge = |ndc_y: f64| DVec3::new(0.0, ndc_y * tan_half, -1.0) * t; // z = -t on the plane
    (edge(1.0 / height) - edge(-1.0 / height)).length()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    /// A primary cone's width at distance t matches the exact pixel footprint on a perpendicular
    /// plane: the small-angle spread exactly, the exact spread (RTG Eq. 30) within
    /// `1 - atan(x)/x <= x^2/3` with `x = 2 tan(fov/2) / H`.
    #[test]
    fn cone_width_matches_the_pixel_footprint_on_a_perpendicular_plane(
        fov_y in 0.1f32..2.8, height in 1u32..4096, t in 0.01f32..1.0e4,
    ) {
        let exact = exact_central_pixel_width(f64::from(fov_y), f64::from(height), f64::from(t));
        let x = 2.0 * (0.5 * f64::from(fov_y)).tan() / f64::from(height);
        let small = rc::width_at(rc::pinhole_ray_cone(rc::pixel_spread_angle_small(fov_y, height as f32)), t);
        let atan = rc::width_at(rc::pinhole_ray_cone(rc::pixel_spread_angle(fov_y, height as f32)), t);
        prop_assert!((f64::from(small) - exact).abs() <= F32_SLACK * exact, "small {small} exact {exact}");
        let bound = x * x / 3.0 + F32_SLACK;
        prop_assert!((f64::from(atan) - exact).abs() <= bound * exact, "atan {atan} exact {exact} x {x}");
    }

    /// The spread angle read from an inverse projection matrix (OpenGL or y-flipped Vulkan) equals
    /// the one from the field of view.
    #[test]
    fn spread_from_inverse_projection_matches_spread_from_fov(
        fov_y in 0.1f32..2.8, aspect in 0.3f32..4.0, height in 1u32..4096, vulkan in any::<bool>(),
    ) {
        let projection = if vulkan {
            glam::camera::rh::proj::vulkan::perspective(fov_y, aspect, 0.1, 100.0)
        } else {
            glam::camera::rh::proj::opengl::perspective(fov_y, aspect, 0.1, 100.0)
        };
        let from_matrix = rc::pixel_spread_angle_from_proj_inv(projection.inverse(), height as f32);
        let from_fov = rc::pixel_spread_angle(fov_y, height as f32);
        prop_assert!((from_matrix - from_fov).abs() <= 1.0e-5 * from_fov, "{from_matrix} vs {from_fov}");
    }

    /// SPEC 1.4: after a planar mirror (surface spread 0) at distance t0, the cone traced a further
    /// t1 is as wide as the chord between the two reflected pixel-edge rays, which is the chord of
    /// the mirror-image camera's primary rays at t0 + t1: `2 (t0 + t1) sin(alpha / 2)`. The cone's
    /// linear width `alpha (t0 + t1)` exceeds it by `alpha^2 / 24` relative, at any incidence angle.
    #[test]
    fn a_planar_mirror_acts_as_a_mirror_image_camera(
        alpha in 1.0e-4f64..0.05, t0 in 0.1f64..100.0, t1 in 0.0f64..100.0,
        incidence in 0.0f64..1.4, roll in 0.0f64..std::f64::consts::TAU,
    ) {
        let chord = reflected_chord(alpha, t0, t1, incidence, roll);
        let cone = rc::propagate(rc::pinhole_ray_cone(alpha as f32), t0 as f32, 0.0);
        let width = f64::from(rc::width_at(cone, t1 as f32));
        let bound = alpha * alpha / 24.0 + F32_SLACK;
        prop_assert!((width - chord).abs() <= bound * chord, "cone {width} chord {chord} (incidence {incidence})");
    }

    /// SPEC 1.9: for a square W x W texture, `lambda` (RTG Eq. 34) equals
    /// `log2(world_footprint * texel_density * W)`. Both sides are f32 sums of about ten rounded
    /// terms no larger than 64: 10 * 64 * 2^-24 < 4e-5, so 1e-4 bounds their difference.
    #[test]
    fn texture_lod_equals_the_log_of_the_uv_footprint_in_texels(
        p in prop::array::uniform3(prop::array::uniform3(-10.0f32..10.0)),
        uv in prop::array::uniform3(prop::array::uniform2(-2.0f32..2.0)),
        size in 1u32..8192, width in 0.0f32..1.0, spread in -0.01f32..0.01, t in 0.0f32..100.0,
        normal_angle in 0.0f32..1.4,
    ) {
        let p = p.map(Vec3::from_array);
        let uv = uv.map(Vec2::from_array);
        let world_area2 = rc::triangle_world_area2(p[0], p[1], p[2]);
        let uv_area2 = rc::triangle_uv_area2(uv[0], uv[1], uv[2]);
        prop_assume!(world_area2 > 1.0e-3 && uv_area2 > 1.0e-3);
        let cone = RayCone { width, spread_angle: spread };
        prop_assume!(rc::width_at(cone, t).abs() > 1.0e-4);
        let direction = Vec3::NEG_Z;
        let normal = Vec3::new(normal_angle.sin(), 0.0, normal_angle.cos());
        let w = size as f32;
        let lambda = rc::texture_lod(
            rc::triangle_base_lod(p[0], p[1], p[2], uv[0], uv[1], uv[2]),
            rc::width_at(cone, t),
            Vec2::splat(w),
            normal,
            direction,
        );
        let uv_footprint = rc::world_footprint(cone, t, normal, direction)
            * rc::texel_density(p[0], p[1], p[2], uv[0], uv[1], uv[2]);
        let expected = (uv_footprint * w).log2();
        prop_assert!((lambda - expected).abs() <= 1.0e-4, "lambda {lambda} expected {expected}");
    }

    /// Packing to f16 keeps about three decimal digits and clamps instead of overflowing.
    #[test]
    fn packed_cones_round_trip_within_half_precision(width in -1.0e6f32..1.0e6, spread in -4.0f32..4.0) {
        let unpacked = rc::unpack_ray_cone(rc::pack_ray_cone(RayCone { width, spread_angle: spread }));
        let expected_width = width.clamp(-rc::F16_MAX, rc::F16_MAX);
        prop_assert!((unpacked.width - expected_width).abs() <= expected_width.abs() / 2048.0 + 6.0e-8);
        prop_assert!((unpacked.spread_angle - spread).abs() <= spread.abs() / 2048.0 + 6.0e-8);
        prop_assert!(unpacked.width.is_finite());
    }
}

/// The footprint of pixel `pixel` of a pinhole camera at the origin looking down -z (vertical field
/// of view `fov_y`, image `size`, pixel y growing downwards) on the plane across its central ray at
/// distance 1: the vectors from its left to its right edge and from its top to its bottom edge,
/// between the points where the rays through the midpoints of the pixel's four edges cross that
/// plane. Also the central ray's unit direction. In f64.
fn exact_pixel_footprint(fov_y: f64, size: DVec2, pixel: DVec2) -> (DVec3, [DVec3; 2]) {
    let tan_half = (0.5 * fov_y).tan();
    let ray = |at: DVec2| {
        let ndc = at / size * 2.0 - 1.0;
        DVec3::new(ndc.x * size.x / size.y * tan_half, -ndc.y * tan_half, -1.0).normalize()
    };
    let centre = ray(pixel + 0.5);
    let on_plane = |at: DVec2| {
        let direction = ray(pixel + at);
        direction / direction.dot(centre)
    };
    let across = on_plane(DVec2::new(1.0, 0.5)) - on_plane(DVec2::new(0.0, 0.5));
    let down = on_plane(DVec2::new(0.5, 1.0)) - on_plane(DVec2::new(0.5, 0.0));
    (centre, [across, down])
}

/// LOD slack for the per-ray cone: the exact spread `atan(x)` instead of `x` (under 1e-4 LOD here),
/// terms of second order in the pixel's angular size, and f32 rounding.
const PER_RAY_LOD_SLACK: f64 = 1.0e-3;

/// SPEC 1.12, the per-ray pinhole cone, across 16:9 views with 60- and 160-degree vertical fields
/// of view: the width at distance 1 of the per-ray cone and of the constant one against the exact
/// footprint's longer side on the plane across the ray (the isotropic LOD's measure, RTG Eq. 2),
/// as LOD errors `log2(cone width / exact width)`.
///
/// A pixel `theta` off axis spans `alpha cos(theta)` across the radial direction and
/// `alpha cos^2(theta)` along it, to first order in its size. Its longer side, at whatever angle to
/// the radial direction, is at most the first and at least `alpha cos(theta) sqrt((1 + cos^2) / 2)`,
/// so the per-ray cone's error lies in `[0, 0.5 log2(2 / (1 + cos^2(theta)))]`, under half a level;
/// the constant cone's is `log2(1 / cos(theta))` larger.
#[test]
fn per_ray_pinhole_cones_fit_off_axis_pixels() {
    let size = DVec2::new(1920.0, 1080.0);
    let corner = size - 1.0;
    let grid = (0..=240).flat_map(|i| (0..=135).map(move |j| DVec2::new(f64::from(i), f64::from(j)) * 8.0));
    for fov_degrees in [60.0f64, 160.0] {
        let fov_y = fov_degrees.to_radians();
        let alpha = rc::pixel_spread_angle(fov_y as f32, size.y as f32);
        let lod_errors = |pixel: DVec2| {
            let (direction, sides) = exact_pixel_footprint(fov_y, size, pixel);
            let exact = sides[0].length().max(sides[1].length());
            let lod_error = |cone: RayCone| (f64::from(rc::width_at(cone, 1.0)) / exact).log2();
            let per_ray = rc::pinhole_ray_cone_for_ray(alpha, direction.as_vec3(), Vec3::NEG_Z);
            (
                -direction.z,
                lod_error(per_ray),
                lod_error(rc::pinhole_ray_cone(alpha)),
            )
        };
        let (mut worst_per_ray, mut worst_constant) = (0.0f64, 0.0f64);
        for pixel in grid.clone().map(|p| p.min(corner)).chain([corner]) {
            let (cos, per_ray, constant) = lod_errors(pixel);
            let bound = 0.5 * (2.0 / (1.0 + cos * cos)).log2();
            assert!(
                (-PER_RAY_LOD_SLACK..=bound + PER_RAY_LOD_SLACK).contains(&per_ray),
                "{fov_degrees} degrees, pixel {pixel}: per-ray LOD error {per_ray}, bound {bound}"
            );
            assert!(
                per_ray.abs() <= constant.abs(),
                "pixel {pixel}: {per_ray} vs {constant}"
            );
            worst_per_ray = worst_per_ray.max(per_ray.abs());
            worst_constant = worst_constant.max(constant.abs());
        }
        let (cos, per_ray, constant) = lod_errors(corner);
        println!(
            "{fov_degrees}-degree 16:9 view, corner pixel ({:.1} degrees off axis, log2(1 / cos) = \
             {:.3}): LOD error of the per-ray cone {per_ray:+.3}, of the constant cone \
             {constant:+.3}; largest over every 8th pixel: per-ray {worst_per_ray:.3}, constant \
             {worst_constant:.3}",
            cos.acos().to_degrees(),
            -cos.log2()
        );
    }
}

/// Chord between the two pixel-edge rays (angle `alpha` apart) of a pinhole camera at the origin
/// after a planar mirror hit at distance `t0` with the given incidence angle, once each edge ray has
/// travelled `t0 + t1` in all. Computed in f64 with explicit ray-plane intersections.
fn reflected_chord(alpha: f64, t0: f64, t1: f64, incidence: f64, roll: f64) -> f64 {
    let axis = DVec3::NEG_Z;
    // Mirror normal tilted by `incidence` from -axis, rolled about the axis.
    let tilt = DVec3::new(roll.cos(), roll.sin(), 0.0);
    let normal = -axis * incidence.cos() + tilt * incidence.sin();
    let plane_point = axis * t0;
    // Edge rays spread in the plane of incidence, where slant matters most.
    let spread_dir = (tilt - axis * tilt.dot(axis)).normalize();
    let edge = |sign: f64| {
        let direction = (axis * (0.5 * alpha).cos() + spread_dir * sign * (0.5 * alpha).sin()).normalize();
        let s = plane_point.dot(normal) / direction.dot(normal);
        let hit = direction * s;
        let reflected = direction - normal * 2.0 * direction.dot(normal);
        hit + reflected * (t0 + t1 - s)
    };
    (edge(1.0) - edge(-1.0)).length()
}

/// Vertices and outward normals of a latitude-longitude sphere of the given radius.
fn sphere(radius: f32, rings: usize, segments: usize) -> (Vec<Vec3>, Vec<Vec3>) {
    let mut normals = Vec::new();
    for ring in 0..=rings {
        let theta = std::f32::consts::PI * ring as f32 / rings as f32;
        for segment in 0..segments {
            let phi = std::f32::consts::TAU * segment as f32 / segments as f32;
            normals.push(Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            ));
        }
    }
    (normals.iter().map(|n| *n * radius).collect(), normals)
}

/// Triangles of a grid of `rows + 1` by `columns` vertices that wraps around in the column direction.
fn grid_triangles(rows: usize, columns: usize) -> Vec<[usize; 3]> {
    let index = |row: usize, column: usize| row * columns + column % columns;
    (0..rows)
        .flat_map(|r| {
            (0..columns).flat_map(move |c| {
                [
                    [index(r, c), index(r + 1, c), index(r, c + 1)],
                    [index(r, c + 1), index(r + 1, c), index(r + 1, c + 1)],
                ]
            })
        })
        .collect()
}

fn curvatures(positions: &[Vec3], normals: &[Vec3], triangles: &[[usize; 3]]) -> Vec<f32> {
    triangles
        .iter()
        .filter(|t| rc::triangle_world_area2(positions[t[0]], positions[t[1]], positions[t[2]]) > 0.0)
        .map(|t| {
            rc::triangle_curvature(
                positions[t[0]],
                positions[t[1]],
                positions[t[2]],
                normals[t[0]],
                normals[t[1]],
                normals[t[2]],
            )
        })
        .collect()
}

/// SPEC 1.6: on a tessellated sphere of radius R with exact vertex normals, every triangle's
/// curvature estimate is 1/R (to f32 rounding) with outward normals and -1/R with inward ones. With
/// the normals as the mesh stores them, in either orientation, the reflection spread near the pole
/// is `+2 width / R` for a ray from outside (a convex mirror) and `-2 width / R` for a ray from
/// inside (a concave one).
#[test]
fn sphere_curvature_is_one_over_the_radius() {
    let width = 0.01f32;
    for radius in [0.01f32, 1.0, 37.0, 1000.0] {
        let (positions, outward) = sphere(radius, 24, 48);
        let values = curvatures(&positions, &outward, &grid_triangles(24, 48));
        let worst = values
            .iter()
            .map(|k| (k * radius - 1.0).abs())
            .fold(0.0f32, f32::max);
        println!(
            "sphere R = {radius}: {} triangles, worst |k R - 1| = {worst:.2e}",
            values.len()
        );
        assert!(worst < 1.0e-3, "radius {radius}: worst relative error {worst}");
        let inward: Vec<Vec3> = outward.iter().map(|n| -*n).collect();
        let concave = curvatures(&positions, &inward, &grid_triangles(24, 48));
        assert!(concave.iter().all(|k| (k * radius + 1.0).abs() < 1.0e-3));
        // The first non-degenerate triangle touches the pole, where the stored normal is +-Y.
        for (curvature, pole_normal) in [(values[0], Vec3::Y), (concave[0], Vec3::NEG_Y)] {
            let expected = 2.0 * width / radius;
            let from_outside = rc::curvature_spread_angle(curvature, width, pole_normal, Vec3::NEG_Y);
            let from_inside = rc::curvature_spread_angle(curvature, width, pole_normal, Vec3::Y);
            assert!(
                (from_outside - expected).abs() <= 1.0e-3 * expected,
                "from outside {from_outside}"
            );
            assert!(
                (from_inside + expected).abs() <= 1.0e-3 * expected,
                "from inside {from_inside}"
            );
        }
    }
}

/// The reflection of `v` off a plane with unit normal `normal`.
fn reflect(v: Vec3, normal: Vec3) -> Vec3 {
    v - 2.0 * v.dot(normal) * normal
}

/// Rounding of a few f32 operations on values below 1.
const REPRODUCTION_SLACK: f32 = 1.0e-6;

/// A thin-lens cone meets a convex mirror past its focus: aperture 0.05 focused at 5 (width 0.05,
/// spread -0.01), a mirror of radius 1 head-on at t = 10 (normal +z, ray -z), then one more unit.
///
/// The answer from the geometry (paraxial edge rays): the edge ray that leaves the lens at
/// x = +0.025 crosses the axis at z = 5 and meets the mirror at x = -0.025, moving away from the
/// axis by 0.005 per unit. The mirror's normal there is tilted by 0.025 / R = 0.025, which turns the
/// reflected ray by twice that, 0.05, further from the axis: 0.055 per unit. One unit later that
/// edge is 0.025 + 0.055 = 0.08 from the axis, so the footprint is 0.16 wide. In the cone's signed
/// terms the width at the hit is -0.05 and the mirror adds -0.1 to the spread (a change that widens
/// the cone has the width's sign). The crate's ray differentials on the same path agree.
#[test]
fn convex_mirror_past_the_focus_widens_the_inverted_cone() {
    const FOOTPRINT: f32 = 0.16;
    const BETA: f32 = -0.1;
    let (t, further, curvature) = (10.0f32, 1.0f32, 1.0f32);
    let (normal, direction) = (Vec3::Z, Vec3::NEG_Z);
    let cone = rc::thin_lens_ray_cone(0.0, 0.05, 5.0);
    let width = rc::width_at(cone, t);
    let beta = rc::curvature_spread_angle(curvature, width, normal, direction);
    let cone_footprint = rc::width_at(rc::propagate(cone, t, beta), further).abs();
    // The lens as a differential (origin 0.05 x, direction -0.01 x per pixel step); on a sphere the
    // stored normal changes by curvature * dP.
    let lens = RayDiff::new(0.05 * Vec3::X, Vec3::ZERO, -0.01 * Vec3::X, Vec3::ZERO);
    let at_hit = rd::transfer(lens, direction, t, normal);
    let normal_change = Derivatives3::new(curvature * at_hit.d_origin_dx, Vec3::ZERO);
    let reflected = rd::reflect_ray_diff(at_hit, direction, normal, normal_change);
    let outgoing = reflect(direction, normal);
    let diff_footprint = rd::transfer(reflected, outgoing, further, outgoing)
        .d_origin_dx
        .length();
    println!(
        "past the focus: width at the hit {width}, beta {beta}, footprint one unit later: cone \
         {cone_footprint}, ray differentials {diff_footprint} (geometry: {FOOTPRINT})"
    );
    assert!((beta - BETA).abs() <= REPRODUCTION_SLACK, "beta {beta}");
    assert!((cone_footprint - FOOTPRINT).abs() <= REPRODUCTION_SLACK);
    assert!((diff_footprint - FOOTPRINT).abs() <= REPRODUCTION_SLACK);
}

/// `triangle_curvature` of a triangle around the +z pole of a sphere of radius `radius`, its
/// vertices 0.5 rad from the pole, with the normals stored outward (`orientation` 1) or inward (-1).
fn pole_triangle_curvature(radius: f32, orientation: f32) -> f32 {
    let vertex = |azimuth: f32| {
        let (sin, cos) = (0.5f32.sin(), 0.5f32.cos());
        Vec3::new(sin * azimuth.cos(), sin * azimuth.sin(), cos)
    };
    let units = [0.0f32, 2.1, 4.2].map(vertex);
    let p = units.map(|u| u * radius);
    let n = units.map(|u| u * orientation);
    rc::triangle_curvature(p[0], p[1], p[2], n[0], n[1], n[2])
}

/// A ray from the centre of a sphere of radius 2 meets the +z pole head-on from inside (d = +z),
/// carrying a cone of width 0.01 and spread 0.005 there (its apex at the centre); the mesh stores
/// outward normals (n = +z at the pole, curvature 0.5 from its triangles) or inward ones.
///
/// The answer from the geometry: a spherical mirror reflects every ray from its centre back to
/// its centre, so the reflected cone converges on the centre: spread -0.005 (beta = -0.01), and
/// width 0 after the 2 units back.
#[test]
fn concave_mirror_seen_from_inside_focuses_with_stored_normals() {
    const BETA: f32 = -0.01;
    const REFLECTED_SPREAD: f32 = -0.005;
    let (radius, direction) = (2.0f32, Vec3::Z);
    let cone = rc::pinhole_ray_cone(0.005);
    for orientation in [1.0f32, -1.0] {
        let curvature = pole_triangle_curvature(radius, orientation);
        let width = rc::width_at(cone, radius);
        let beta = rc::curvature_spread_angle(curvature, width, orientation * Vec3::Z, direction);
        let reflected = rc::propagate(cone, radius, beta);
        let back_at_centre = rc::width_at(reflected, radius);
        println!(
            "from inside, normals stored {}: curvature {curvature}, width {width}, beta {beta}, \
             reflected spread {}, width back at the centre {back_at_centre:e}",
            if orientation > 0.0 { "outward" } else { "inward" },
            reflected.spread_angle
        );
        // The curvature estimate's own rounding (differences of nearby unit normals) is below 1e-5.
        assert!((beta - BETA).abs() <= 1.0e-5 * BETA.abs(), "beta {beta}");
        assert!((reflected.spread_angle - REFLECTED_SPREAD).abs() <= 1.0e-5 * BETA.abs());
        assert!(back_at_centre.abs() <= REPRODUCTION_SLACK);
    }
}

/// A flat mesh has zero curvature; a cylinder's lies between 0 (along the axis) and 1/R (around it).
#[test]
fn flat_and_cylindrical_curvature() {
    let flat: Vec<Vec3> = (0..5)
        .flat_map(|r| (0..5).map(move |c| Vec3::new(c as f32, 0.0, r as f32 * 0.7)))
        .collect();
    let triangles: Vec<[usize; 3]> = grid_triangles(4, 5)
        .into_iter()
        .filter(|t| t.iter().all(|&i| i < 25))
        .collect();
    let flat_values = curvatures(&flat, &vec![Vec3::Y; flat.len()], &triangles);
    assert!(flat_values.iter().all(|&k| k == 0.0), "{flat_values:?}");
    let radius = 2.0f32;
    let normals: Vec<Vec3> = (0..=6)
        .flat_map(|_| {
            (0..32).map(|s| {
                let phi = std::f32::consts::TAU * s as f32 / 32.0;
                Vec3::new(phi.cos(), 0.0, phi.sin())
            })
        })
        .collect();
    let positions: Vec<Vec3> = normals
        .iter()
        .enumerate()
        .map(|(i, n)| *n * radius + Vec3::Y * (i / 32) as f32 * 0.3)
        .collect();
    let values = curvatures(&positions, &normals, &grid_triangles(6, 32));
    println!(
        "cylinder R = {radius}: curvature in [{:.4}, {:.4}], 1/R = {}",
        values.iter().cloned().fold(f32::MAX, f32::min),
        values.iter().cloned().fold(0.0, f32::max),
        1.0 / radius
    );
    assert!(values.iter().all(|&k| k > 0.0 && k < 1.0 / radius));
}

/// The clamps keep every output finite at the degenerate inputs SPEC section 0 names.
#[test]
fn degenerate_inputs_give_finite_outputs() {
    let grazing = Vec3::new(1.0, 0.0, 0.0);
    let point = Vec3::ZERO;
    let zero_cone = RayCone::default();
    let outputs = [
        rc::pixel_spread_angle(std::f32::consts::PI, 0.0),
        rc::pixel_spread_angle_from_proj_inv(Mat4::ZERO, 0.0),
        rc::thin_lens_ray_cone(0.001, 0.05, 0.0).spread_angle,
        rc::world_footprint(zero_cone, 0.0, Vec3::Y, grazing),
        rc::curvature_spread_angle(1.0, 1.0, Vec3::Y, grazing),
        rc::edge_curvature(point, point, Vec3::Y, Vec3::X),
        rc::texel_density(point, point, point, Vec2::ZERO, Vec2::ONE, Vec2::X),
        rc::triangle_base_lod(point, point, point, Vec2::ZERO, Vec2::ZERO, Vec2::ZERO),
        rc::texture_lod(0.0, 0.0, Vec2::ZERO, Vec3::Y, grazing),
        rc::environment_lod(0.0, 0.0),
    ];
    assert!(outputs.iter().all(|x| x.is_finite()), "{outputs:?}");
}

// Reflection chains: the cone against the crate's ray differentials.
//
// A chain is a primary ray (pinhole, orthographic or thin lens) reflected by 1 to 4 curved mirrors.
// The same path is followed by the cone (`width_at`, `curvature_spread_angle`, `propagate`) and by
// the ray differential (`transfer`, then `reflect_ray_diff` with the derivative of the stored normal
// field), both in f32; the geometry between them (directions, normals, the pixel-step frame) is
// exact in f64 and rounded to f32 where the crate's functions take it.
//
// Both are first-order models of the same beam, but the cone is isotropic and the differential is
// not, so they can only be compared where the beam stays describable by one width:
// - In-plane chains: every ray and normal lies in one plane, and a pixel step right moves the
//   footprint within it. There the differential's in-plane footprint follows the cone exactly when
//   the cone is given the mirror's normal curvature in that plane (for a sphere 1/R, for a saddle
//   whose principal directions lie along and across the plane, the principal curvature along
//   it). The differential's other axis meets the curvature across the plane and, at oblique
//   incidence, `cos` instead of `1 / cos` (Coddington's sagittal and tangential foci): no isotropic
//   cone follows both.
// - Head-on chains with one saddle: a saddle's principal curvatures have opposite signs, and an
//   isotropic estimate (`triangle_curvature`, the mean of normal curvatures over three edge
//   directions) approaches its mean curvature. Given the mean curvature, the cone follows the mean
//   of the differential's two signed footprints (half the trace of the footprint's map), exactly,
//   as long as the beam meeting the saddle is isotropic (head-on hits, every other mirror a
//   sphere); after that the two axes stay apart and only their mean is a cone.

/// The first ray of a chain: its cone and its differential. The camera looks down -z from the
/// origin; a pixel step right moves along +x, a step down along -y.
#[derive(Clone, Copy, Debug)]
struct Primary {
    cone: RayCone,
    diff: RayDiff,
}

/// The unit vectors along which a pixel step right and a pixel step down move a primary footprint.
const PIXEL_STEPS: [DVec3; 2] = [DVec3::X, DVec3::NEG_Y];

impl Primary {
    /// The centre pixel of an odd-sized square pinhole image: the cone with the small-angle pixel
    /// spread `2 tan(fov_y / 2) / H`, and the eye-ray differential (RTG Eq. 8-11).
    fn pinhole(fov_y: f32, size: u32) -> Self {
        let image = Vec2::splat(size as f32);
        let centre = Vec2::splat((size / 2) as f32);
        Primary {
            cone: rc::pinhole_ray_cone(rc::pixel_spread_angle_small(fov_y, size as f32)),
            diff: rd::eye_ray_diff(centre, image, fov_y, Vec3::X, Vec3::Y, Vec3::Z),
        }
    }

    /// A pixel of an orthographic view `view_height` tall: parallel rays one pixel apart.
    fn orthographic(view_height: f32, size: u32) -> Self {
        let pixel = view_height / size as f32;
        Primary {
            cone: rc::orthographic_ray_cone(view_height, size as f32),
            diff: RayDiff::new(pixel * Vec3::X, pixel * Vec3::NEG_Y, Vec3::ZERO, Vec3::ZERO),
        }
    }

    /// A pixel of a thin-lens camera (aperture A, focus distance F) with the pinhole's spread
    /// alpha: rays leave the lens A apart and meet the pixel's footprint on the focal plane,
    /// `alpha * F` wide, so they spread by `alpha - A / F` per unit.
    fn thin_lens(fov_y: f32, size: u32, aperture: f32, focus_distance: f32) -> Self {
        let alpha = rc::pixel_spread_angle_small(fov_y, size as f32);
        let spread = alpha - aperture / focus_distance;
        Primary {
            cone: rc::thin_lens_ray_cone(alpha, aperture, focus_distance),
            diff: RayDiff::new(
                aperture * Vec3::X,
                aperture * Vec3::NEG_Y,
                spread * Vec3::X,
                spread * Vec3::NEG_Y,
            ),
        }
    }
}

/// A mirror as a ray meets it. Curvatures follow `edge_curvature`'s convention: how fast the normal
/// turns along a direction, positive where the normals spread apart.
#[derive(Clone, Copy, Debug)]
enum Surface {
    /// A sphere of radius `radius` met from outside (convex) or inside (concave); with outward
    /// normals its curvature is `1 / radius` in every direction.
    Sphere { radius: f64, inside: bool },
    /// A saddle met at its vertex from its "up" side or from below. With the up normal its
    /// principal curvatures are `along`, on the principal direction `axis_angle` from the chain's
    /// plane, and `across`, of opposite signs: locally the height `-(along x^2 + across y^2) / 2`
    /// above its tangent plane.
    Saddle {
        along: f64,
        across: f64,
        axis_angle: f64,
        from_below: bool,
    },
}

/// One reflection of a chain.
#[derive(Clone, Copy, Debug)]
struct Bounce {
    surface: Surface,
    /// The mesh stores its normals flipped: inward on a sphere, down on a saddle.
    flipped_normals: bool,
    /// Distance travelled to the hit.
    distance: f64,
    /// Signed angle, in the chain's plane, between the reversed ray and the normal facing the ray.
    incidence: f64,
}

impl Bounce {
    /// Whether the stored normal points to the side the ray comes from.
    fn stored_normal_faces_the_ray(&self) -> bool {
        let outward_faces_the_ray = match self.surface {
            Surface::Sphere { inside, .. } => !inside,
            Surface::Saddle { from_below, .. } => !from_below,
        };
        outward_faces_the_ray != self.flipped_normals
    }

    /// The principal curvatures measured with the stored normals, and the angle of the first
    /// principal direction from the chain's plane.
    fn principal_curvatures(&self) -> (f64, f64, f64) {
        let sign = if self.flipped_normals { -1.0 } else { 1.0 };
        match self.surface {
            Surface::Sphere { radius, .. } => (sign / radius, sign / radius, 0.0),
            Surface::Saddle {
                along,
                across,
                axis_angle,
                ..
            } => (sign * along, sign * across, axis_angle),
        }
    }

    /// The normal curvature along the chain's plane (Euler: `k1 cos^2 + k2 sin^2`).
    fn in_plane_curvature(&self) -> f64 {
        let (k1, k2, angle) = self.principal_curvatures();
        k1 * angle.cos().powi(2) + k2 * angle.sin().powi(2)
    }

    fn mean_curvature(&self) -> f64 {
        let (k1, k2, _) = self.principal_curvatures();
        0.5 * (k1 + k2)
    }

    fn largest_curvature(&self) -> f64 {
        let (k1, k2, _) = self.principal_curvatures();
        k1.abs().max(k2.abs())
    }
}

/// The derivative of a mirror's stored unit normal at the hit: for a change `dp` of the hit point
/// in the tangent plane, `k1 (u1 . dp) u1 + k2 (u2 . dp) u2` with `u1`, `u2` the principal
/// directions (on a sphere simply `curvature * dp`).
struct NormalField {
    curvatures: [f32; 2],
    directions: [Vec3; 2],
}

impl NormalField {
    /// The field of `bounce` at a hit whose stored normal is `normal` (in the chain's plane).
    fn new(bounce: &Bounce, normal: DVec3) -> Self {
        let (k1, k2, angle) = bounce.principal_curvatures();
        let in_plane = DVec3::Y.cross(normal);
        let u1 = in_plane * angle.cos() + DVec3::Y * angle.sin();
        let u2 = DVec3::Y * angle.cos() - in_plane * angle.sin();
        NormalField {
            curvatures: [k1 as f32, k2 as f32],
            directions: [u1.as_vec3(), u2.as_vec3()],
        }
    }

    fn change(&self, dp: Vec3) -> Vec3 {
        let [k1, k2] = self.curvatures;
        let [u1, u2] = self.directions;
        k1 * u1.dot(dp) * u1 + k2 * u2.dot(dp) * u2
    }
}

/// What the cone is compared with, and which curvature it is given.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Comparison {
    /// The cone given the normal curvature in the chain's plane, against the differential's
    /// signed footprint along the in-plane pixel axis.
    InPlane,
    /// The cone given the mean curvature, against the mean of the differential's signed
    /// footprints along both pixel axes.
    Mean,
}

impl Comparison {
    fn curvature(self, bounce: &Bounce) -> f64 {
        match self {
            Comparison::InPlane => bounce.in_plane_curvature(),
            Comparison::Mean => bounce.mean_curvature(),
        }
    }

    /// The differential's signed footprint across the ray whose pixel-step frame is `frame`.
    fn footprint(self, diff: &RayDiff, frame: [DVec3; 2]) -> f64 {
        let along = |d_origin: Vec3, axis: DVec3| d_origin.as_dvec3().dot(axis);
        let right = along(diff.d_origin_dx, frame[0]);
        match self {
            Comparison::InPlane => right,
            Comparison::Mean => 0.5 * (right + along(diff.d_origin_dy, frame[1])),
        }
    }
}

/// Roundings (in f32 ULP) per leg of a chain, relative to the chain's scale (see [`Scale`]).
///
/// Per leg, `transfer` rounds about a dozen times on vectors no longer than the slanted footprint
/// (`scale / c`, c the cosine of incidence), and its division by the rounded `dot(D, N)` adds
/// `3 ULP / c` twice, so its error is below `12 ULP * scale / c^3`; `reflect_ray_diff` and the
/// normal field round about a dozen times on terms no larger than the spread scale; the cone
/// rounds 4 times. An error made on one leg grows on the later ones no faster than the scale
/// itself, which follows the same recurrence with absolute values. So after `n` legs the two
/// computations differ by less than `(12 + 12 + 4) * n` ULP of `scale / c_min^3`: 32 per leg.
const CHAIN_ULPS_PER_LEG: f64 = 32.0;

/// Bounds on the chain's widths and spreads: the cone's recurrences with absolute values (and the
/// larger principal curvature), which bound every term either computation rounds.
struct Scale {
    width: f64,
    spread: f64,
}

impl Scale {
    fn new(cone: RayCone) -> Self {
        Scale {
            width: f64::from(cone.width.abs()),
            spread: f64::from(cone.spread_angle.abs()),
        }
    }

    fn at(&self, t: f64) -> f64 {
        self.width + self.spread * t
    }

    fn reflect(&mut self, t: f64, curvature: f64, cos: f64) {
        self.width = self.at(t);
        self.spread += 2.0 * curvature * self.width / cos;
    }
}

/// The cone's width and the differential's footprint at one point of a chain, with the bound on
/// their rounding and the chain's scale there.
#[derive(Clone, Copy, Debug)]
struct Sample {
    cone: f64,
    diff: f64,
    bound: f64,
    scale: f64,
}

impl Sample {
    /// A sample after `legs` legs, where the chain's scale is `scale` and its smallest cosine of
    /// incidence so far `min_cos`.
    fn new(legs: usize, cone: f32, diff: f64, scale: f64, min_cos: f64) -> Self {
        let ulps = CHAIN_ULPS_PER_LEG * legs as f64;
        Sample {
            cone: f64::from(cone),
            diff,
            bound: ulps * f64::from(f32::EPSILON) * scale / min_cos.powi(3),
            scale,
        }
    }
}

/// A chain: the primary ray, its bounces and the distance travelled after the last one.
#[derive(Clone, Debug)]
struct Chain {
    primary: Primary,
    bounces: Vec<Bounce>,
    final_distance: f64,
}

/// The reflection of `v` off a plane with unit normal `normal`, in f64.
fn reflect_exact(v: DVec3, normal: DVec3) -> DVec3 {
    v - 2.0 * v.dot(normal) * normal
}

impl Chain {
    /// Follows the chain with the cone and the differential; one sample at every hit and one at
    /// the end, on a plane across the last ray.
    fn trace(&self, comparison: Comparison) -> Vec<Sample> {
        let (mut cone, mut diff) = (self.primary.cone, self.primary.diff);
        let (mut direction, mut frame) = (DVec3::NEG_Z, PIXEL_STEPS);
        let mut scale = Scale::new(cone);
        let mut min_cos = 1.0f64;
        let mut samples = Vec::new();
        for (index, bounce) in self.bounces.iter().enumerate() {
            let facing = -direction * bounce.incidence.cos() + frame[0] * bounce.incidence.sin();
            let normal = if bounce.stored_normal_faces_the_ray() {
                facing
            } else {
                -facing
            };
            let (d, n, t) = (direction.as_vec3(), normal.as_vec3(), bounce.distance as f32);
            min_cos = min_cos.min(bounce.incidence.cos());
            let width = rc::width_at(cone, t);
            let at_hit = rd::transfer(diff, d, t, n);
            let footprint = comparison.footprint(&at_hit, frame);
            samples.push(Sample::new(
                index + 1,
                width,
                footprint,
                scale.at(bounce.distance),
                min_cos,
            ));
            let field = NormalField::new(bounce, normal);
            let normal_change =
                Derivatives3::new(field.change(at_hit.d_origin_dx), field.change(at_hit.d_origin_dy));
            diff = rd::reflect_ray_diff(at_hit, d, n, normal_change);
            let curvature = comparison.curvature(bounce) as f32;
            cone = rc::propagate(cone, t, rc::curvature_spread_angle(curvature, width, n, d));
            scale.reflect(
                bounce.distance,
                bounce.largest_curvature(),
                bounce.incidence.cos(),
            );
            direction = reflect_exact(direction, facing);
            frame = frame.map(|axis| reflect_exact(axis, facing));
        }
        let (d, t) = (direction.as_vec3(), self.final_distance as f32);
        let across = rd::transfer(diff, d, t, d);
        let legs = self.bounces.len() + 1;
        samples.push(Sample::new(
            legs,
            rc::width_at(cone, t),
            comparison.footprint(&across, frame),
            scale.at(self.final_distance),
            min_cos,
        ));
        samples
    }
}

/// Largest angle of incidence in the in-plane chains (`cos >= 0.5`).
const MAX_INCIDENCE: f64 = std::f64::consts::FRAC_PI_3;

/// Samples whose differential footprint is at least this fraction of the chain's scale count for
/// the relative and LOD discrepancies; nearer a focus the width is the difference of larger terms,
/// and only the absolute rounding bound means anything there.
const AWAY_FROM_A_FOCUS: f64 = 0.1;

fn log_uniform(lo: f64, hi: f64) -> BoxedStrategy<f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp).boxed()
}

/// A pinhole, orthographic or thin-lens primary with pixel spreads from 2e-4 to 0.03.
fn primary() -> BoxedStrategy<Primary> {
    let size = (50u32..1000).prop_map(|half| 2 * half + 1);
    let fov_y = 0.2f32..2.0;
    prop_oneof![
        (fov_y.clone(), size.clone()).prop_map(|(fov_y, size)| Primary::pinhole(fov_y, size)),
        (0.1f32..10.0, size.clone()).prop_map(|(height, size)| Primary::orthographic(height, size)),
        (fov_y, size, 0.001f32..0.2, 0.5f32..20.0)
            .prop_map(|(fov_y, size, aperture, focus)| { Primary::thin_lens(fov_y, size, aperture, focus) }),
    ]
    .boxed()
}

/// A sphere of radius 0.2 to 20, met from outside or inside.
fn sphere_mirror() -> BoxedStrategy<Surface> {
    (log_uniform(0.2, 20.0), any::<bool>())
        .prop_map(|(radius, inside)| Surface::Sphere { radius, inside })
        .boxed()
}

/// A saddle with principal curvatures of 0.05 to 5 in magnitude, of opposite signs, met from
/// either side.
fn saddle_mirror(axis_angle: BoxedStrategy<f64>) -> BoxedStrategy<Surface> {
    let magnitude = || log_uniform(0.05, 5.0);
    (magnitude(), magnitude(), any::<bool>(), axis_angle, any::<bool>())
        .prop_map(|(along, across, positive_along, axis_angle, from_below)| {
            let sign = if positive_along { 1.0 } else { -1.0 };
            Surface::Saddle {
                along: sign * along,
                across: -sign * across,
                axis_angle,
                from_below,
            }
        })
        .boxed()
}

/// A bounce off `surface`, its normals stored either way, 0.1 to 20 units from the last one.
fn bounce(surface: BoxedStrategy<Surface>, incidence: BoxedStrategy<f64>) -> BoxedStrategy<Bounce> {
    (surface, any::<bool>(), log_uniform(0.1, 20.0), incidence)
        .prop_map(|(surface, flipped_normals, distance, incidence)| Bounce {
            surface,
            flipped_normals,
            distance,
            incidence,
        })
        .boxed()
}

/// 1 to 4 bounces in one plane, off spheres and off saddles whose principal directions lie along
/// and across the plane, at incidences up to [`MAX_INCIDENCE`].
fn in_plane_chain() -> BoxedStrategy<Chain> {
    let axis_angle = prop_oneof![Just(0.0), Just(std::f64::consts::FRAC_PI_2)].boxed();
    let surface = prop_oneof![2 => sphere_mirror(), 1 => saddle_mirror(axis_angle)].boxed();
    let incidence = (-MAX_INCIDENCE..MAX_INCIDENCE).boxed();
    let bounces = prop::collection::vec(bounce(surface, incidence), 1..=4);
    (primary(), bounces, log_uniform(0.1, 20.0))
        .prop_map(|(primary, bounces, final_distance)| Chain {
            primary,
            bounces,
            final_distance,
        })
        .boxed()
}

/// 1 to 4 head-on bounces: one saddle (principal directions at any angle) among up to 3 spheres.
fn head_on_chain_with_one_saddle() -> BoxedStrategy<Chain> {
    let head_on = || Just(0.0).boxed();
    let spheres = prop::collection::vec(bounce(sphere_mirror(), head_on()), 0..=3);
    let one_saddle = bounce(saddle_mirror((0.0..std::f64::consts::PI).boxed()), head_on());
    (primary(), spheres, one_saddle, 0usize..4, log_uniform(0.1, 20.0))
        .prop_map(|(primary, mut bounces, one_saddle, position, final_distance)| {
            bounces.insert(position % (bounces.len() + 1), one_saddle);
            Chain {
                primary,
                bounces,
                final_distance,
            }
        })
        .boxed()
}

/// What the chains covered and how far the cone and the differential were apart.
#[derive(Default)]
struct ChainStats {
    chains: usize,
    samples: usize,
    crossed_a_focus: usize,
    back_side_hits: usize,
    saddles: usize,
    worst_ratio: f64,
    away_from_a_focus: usize,
    worst_relative: f64,
    worst_lod: f64,
}

impl ChainStats {
    fn add(&mut self, chain: &Chain, samples: &[Sample]) {
        let count = |yes: bool| usize::from(yes);
        self.chains += 1;
        self.samples += samples.len();
        self.crossed_a_focus += count(samples.iter().any(|s| s.cone < 0.0));
        self.back_side_hits += count(chain.bounces.iter().any(|b| !b.stored_normal_faces_the_ray()));
        self.saddles += count(
            chain
                .bounces
                .iter()
                .any(|b| matches!(b.surface, Surface::Saddle { .. })),
        );
        for sample in samples {
            self.worst_ratio = self
                .worst_ratio
                .max((sample.cone - sample.diff).abs() / sample.bound);
            if sample.diff.abs() >= AWAY_FROM_A_FOCUS * sample.scale {
                self.away_from_a_focus += 1;
                let relative = (sample.cone - sample.diff).abs() / sample.diff.abs();
                self.worst_relative = self.worst_relative.max(relative);
                self.worst_lod = self.worst_lod.max((sample.cone / sample.diff).abs().log2().abs());
            }
        }
    }

    fn print(&self, name: &str) {
        println!(
            "{name}: {} chains ({} crossed a focus, {} met a mirror from behind its stored normals, \
             {} met a saddle), {} samples; largest |cone - differential| {:.4} of the rounding \
             bound; away from a focus ({} samples): largest relative discrepancy {:.2e}, largest \
             LOD difference {:.2e}",
            self.chains,
            self.crossed_a_focus,
            self.back_side_hits,
            self.saddles,
            self.samples,
            self.worst_ratio,
            self.away_from_a_focus,
            self.worst_relative,
            self.worst_lod
        );
    }
}

/// Runs `cases` chains (a fixed seed, so the printed numbers repeat) and checks every sample
/// against its rounding bound; a failure is shrunk to a small chain and reported.
fn check_chains(chains: BoxedStrategy<Chain>, comparison: Comparison, cases: u32) -> ChainStats {
    let stats = std::cell::RefCell::new(ChainStats::default());
    let config = ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    let rng = TestRng::deterministic_rng(config.rng_algorithm);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let result = runner.run(&chains, |chain| {
        let samples = chain.trace(comparison);
        if let Some(sample) = samples
            .iter()
            .find(|s| (s.cone - s.diff).abs() > s.bound || !s.cone.is_finite())
        {
            return Err(TestCaseError::fail(format!("{sample:?} in {samples:?}")));
        }
        stats.borrow_mut().add(&chain, &samples);
        Ok(())
    });
    if let Err(failure) = result {
        panic!("{comparison:?}: {failure}");
    }
    stats.into_inner()
}

/// Random in-plane chains (pinhole, orthographic and thin-lens primaries; convex and concave
/// spheres and saddles; hits from either side with the normals stored either way; foci crossed
/// anywhere): after every bounce and at the end, the cone's signed width equals the ray
/// differentials' in-plane footprint within [`CHAIN_ULPS_PER_LEG`] per leg.
#[test]
fn in_plane_chains_follow_the_ray_differentials() {
    let stats = check_chains(in_plane_chain(), Comparison::InPlane, 20_000);
    stats.print("in-plane chains");
    // The chains exercise the signs: foci, back-side hits, saddles.
    assert!(stats.crossed_a_focus * 5 >= stats.chains);
    assert!(stats.back_side_hits * 5 >= stats.chains);
    assert!(stats.saddles * 5 >= stats.chains);
}

/// Random head-on chains with one saddle among spheres: the cone given the saddle's mean curvature
/// follows the mean of the ray differentials' two signed footprints, within the same bound.
#[test]
fn head_on_chains_with_a_saddle_follow_the_mean_footprint() {
    let stats = check_chains(head_on_chain_with_one_saddle(), Comparison::Mean, 5_000);
    stats.print("head-on chains with a saddle");
    assert!(stats.crossed_a_focus * 5 >= stats.chains);
    assert!(stats.back_side_hits * 5 >= stats.chains);
}
