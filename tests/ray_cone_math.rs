//! The ray-cone math itself, checked against exact geometry computed in f64 (no GPU needed).

use glam::{DVec3, Mat4, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, RayCone};

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
/// curvature estimate is 1/R (to f32 rounding), and the reflection spread it gives is positive.
#[test]
fn sphere_curvature_is_one_over_the_radius() {
    for radius in [0.01f32, 1.0, 37.0, 1000.0] {
        let (positions, normals) = sphere(radius, 24, 48);
        let values = curvatures(&positions, &normals, &grid_triangles(24, 48));
        let worst = values
            .iter()
            .map(|k| (k * radius - 1.0).abs())
            .fold(0.0f32, f32::max);
        println!(
            "sphere R = {radius}: {} triangles, worst |k R - 1| = {worst:.2e}",
            values.len()
        );
        assert!(worst < 1.0e-3, "radius {radius}: worst relative error {worst}");
        let beta = rc::curvature_spread_angle(values[0], 0.01, Vec3::Y, -Vec3::Y);
        assert!((beta - 2.0 * 0.01 / radius).abs() <= 1.0e-3 * beta, "beta {beta}");
        // Seen from inside (normals flipped), the sphere is concave: negative curvature and spread.
        let inward: Vec<Vec3> = normals.iter().map(|n| -*n).collect();
        let concave = curvatures(&positions, &inward, &grid_triangles(24, 48));
        assert!(concave.iter().all(|k| (k * radius + 1.0).abs() < 1.0e-3));
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
