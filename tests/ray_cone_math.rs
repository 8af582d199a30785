//! The ray-cone math itself, checked against exact geometry computed in f64 and against the
//! crate's ray differentials on the same paths (no GPU needed). Random reflection chains against
//! the ray differentials are the lab's (`crates/ray-footprint-lab/tests/chains.rs`), which runs
//! them on the CPU and, in WGSL and GLSL, on the device.

use glam::{DVec2, DVec3, Mat4, Vec2, Vec3};
use proptest::prelude::*;
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

    /// RTG Eq. 35: after a planar mirror (surface spread 0) at distance t0, the cone traced a further
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

    /// For a square W x W texture, `lambda` (RTG Eq. 34) equals
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

/// The per-ray pinhole cone (the OptiX Toolkit's), across 16:9 views with 60- and 160-degree vertical fields
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

/// JCGT 2021's curvature from vertex normals: on a tessellated sphere of radius R with exact vertex normals, every triangle's
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

/// The clamps keep every output finite at the degenerate inputs the README's Conventions name.
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
