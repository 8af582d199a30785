//! The ray-differential math itself, on the CPU: the differentials must be the derivatives of exact
//! ray hits (computed here in f64), the G-buffer variant must follow the exact one, ray
//! differentials and ray cones must give consistent LODs, and the f64 re-intersection must fix what
//! f32 gets wrong at large coordinates. (The planar mirror as a mirror-image camera is a reference
//! of `reflect_ray_diff` in the cases crate.)
//!
//! Each test prints what it measured.

mod common;

use common::Rng;
use glam::{DVec2, DVec3, Mat4, Vec2, Vec3};
use ray_footprint::ray_cone as rc;
use ray_footprint::ray_diff::{self as rd, Derivatives3, GBufferSample, RayDiff};
use ray_footprint::ray_diff_f64 as rd64;

/// A pinhole camera: position, orthonormal basis (`view` points towards the eye), vertical field of
/// view and image size.
#[derive(Clone, Copy, Debug)]
struct Camera {
    position: DVec3,
    right: DVec3,
    up: DVec3,
    view: DVec3,
    fov_y: f64,
    size: DVec2,
}

impl Camera {
    fn random(rng: &mut Rng, position: DVec3) -> Camera {
        let view = rng.unit();
        let right = view.any_orthonormal_vector();
        let right =
            (right * rng.range(-1.0, 1.0) + view.cross(right) * rng.range(-1.0, 1.0)).normalize_or(right);
        let up = view.cross(right);
        let size = [
            DVec2::new(640.0, 480.0),
            DVec2::new(1280.0, 720.0),
            DVec2::new(1920.0, 1080.0),
        ][(rng.next() * 3.0) as usize];
        Camera {
            position,
            right,
            up,
            view,
            fov_y: rng.range(0.4, 1.5),
            size,
        }
    }

    /// Unit direction through a (continuous) pixel position, exactly (RTG Eq. 8-9 in f64).
    fn direction(&self, pixel: DVec2) -> DVec3 {
        let c = (pixel + 0.5) / self.size * 2.0 - 1.0;
        let f = (0.5 * self.fov_y).tan();
        let a = self.size.x / self.size.y;
        (c.x * a * f * self.right - c.y * f * self.up - self.view).normalize()
    }

    /// The crate's differential for a pixel (f32).
    fn ray_diff(&self, pixel: DVec2) -> RayDiff {
        rd::eye_ray_diff(
            pixel.as_vec2(),
            self.size.as_vec2(),
            self.fov_y as f32,
            self.right.as_vec3(),
            self.up.as_vec3(),
            self.view.as_vec3(),
        )
    }
}

/// Exact hit of a ray on a triangle's plane: distance and barycentrics `(u, v)` (f64).
fn exact_hit(origin: DVec3, direction: DVec3, p: [DVec3; 3]) -> (f64, DVec2) {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let n = e1.cross(e2);
    let t = (p[0] - origin).dot(n) / direction.dot(n);
    let s = origin + t * direction - p[0];
    let k = n.dot(n);
    (t, DVec2::new(s.cross(e2).dot(n) / k, e1.cross(s).dot(n) / k))
}

/// A triangle that the ray through `pixel` hits at distance `t`, around the hit, with unit normal
/// `normal` and edges of about `size`; the hit lies inside.
fn triangle_around(
    camera: &Camera,
    pixel: DVec2,
    t: f64,
    normal: DVec3,
    size: f64,
    rng: &mut Rng,
) -> [DVec3; 3] {
    let hit = camera.position + t * camera.direction(pixel);
    let a = normal.any_orthonormal_vector();
    let b = normal.cross(a);
    let corner = |angle: f64, rng: &mut Rng| {
        let r = size * rng.range(0.6, 1.0);
        hit + r * (angle.cos() * a + angle.sin() * b)
    };
    let start = rng.range(0.0, std::f64::consts::TAU);
    let third = std::f64::consts::TAU / 3.0;
    [
        corner(start, rng),
        corner(start + third, rng),
        corner(start + 2.0 * third, rng),
    ]
}

/// A unit normal facing the ray `direction` with `|cos|` in `[min_cos, 1]`.
fn facing_normal(direction: DVec3, min_cos: f64, rng: &mut Rng) -> DVec3 {
    loop {
        let n = rng.unit();
        let n = if n.dot(direction) > 0.0 { -n } else { n };
        if -n.dot(direction) >= min_cos {
            return n;
        }
    }
}

/// A random pixel away from the border.
fn random_pixel(camera: &Camera, rng: &mut Rng) -> DVec2 {
    DVec2::new(
        rng.range(2.0, camera.size.x - 3.0).floor(),
        rng.range(2.0, camera.size.y - 3.0).floor(),
    )
}

/// One random primary hit: camera, pixel, triangle, UVs.
struct PrimaryHit {
    camera: Camera,
    pixel: DVec2,
    triangle: [DVec3; 3],
    uvs: [DVec2; 3],
}

impl PrimaryHit {
    fn random(rng: &mut Rng) -> PrimaryHit {
        let position = DVec3::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let camera = Camera::random(rng, position);
        let pixel = random_pixel(&camera, rng);
        let t = rng.range(1.0, 50.0);
        let normal = facing_normal(camera.direction(pixel), 0.3, rng);
        let triangle = triangle_around(&camera, pixel, t, normal, t * rng.range(0.05, 0.5), rng);
        let uvs = [
            DVec2::new(rng.next(), rng.next()),
            DVec2::new(rng.next(), rng.next()),
            DVec2::new(rng.next(), rng.next()),
        ];
        PrimaryHit {
            camera,
            pixel,
            triangle,
            uvs,
        }
    }

    /// Exact barycentrics `(u, v)` of the ray through a continuous pixel position.
    fn barycentrics(&self, pixel: DVec2) -> DVec2 {
        exact_hit(self.camera.position, self.camera.direction(pixel), self.triangle).1
    }

    /// The crate's barycentric differentials (RTG Eq. 12-19) at the pixel centre, in f32.
    fn barycentric_derivatives(&self) -> rd::Derivatives2 {
        let direction = self.camera.direction(self.pixel);
        let (t, _) = exact_hit(self.camera.position, direction, self.triangle);
        let p = self.triangle.map(|p| (p - self.camera.position).as_vec3());
        rd::barycentric_derivatives(
            self.camera.ray_diff(self.pixel),
            direction.as_vec3(),
            t as f32,
            p[0],
            p[1],
            p[2],
        )
    }

    /// Texture coordinates at barycentrics `(u, v)`.
    fn uv(&self, b: DVec2) -> DVec2 {
        (1.0 - b.x - b.y) * self.uvs[0] + b.x * self.uvs[1] + b.y * self.uvs[2]
    }
}

/// `(d/dx, d/dy)` of `f` at the pixel by forward differences with step `h` pixels.
fn forward_difference(f: impl Fn(DVec2) -> DVec2, pixel: DVec2, h: f64) -> [DVec2; 2] {
    let centre = f(pixel);
    [
        (f(pixel + DVec2::new(h, 0.0)) - centre) / h,
        (f(pixel + DVec2::new(0.0, h)) - centre) / h,
    ]
}

/// How far a pair `(d/dx, d/dy)` is from a reference pair: the larger of `|got[0] - reference[0]|`
/// and `|got[1] - reference[1]|`, relative to the larger of `|reference[0]|` and `|reference[1]|`.
fn relative_error(got: [DVec3; 2], reference: [DVec3; 2]) -> f64 {
    let scale = reference[0].length().max(reference[1].length());
    (got[0] - reference[0])
        .length()
        .max((got[1] - reference[1]).length())
        / scale
}

/// A pair of 2D derivatives as 3-vectors with `z = 0`, for [`relative_error`].
fn flat(pair: [DVec2; 2]) -> [DVec3; 2] {
    pair.map(|v| v.extend(0.0))
}

/// Numbers in scientific notation.
fn list(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|v| format!("{v:.3e}")).collect();
    items.join(", ")
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// The barycentric and UV differentials are the derivatives of exact hits: forward differences with
/// step `h` converge to them, with an error that halves when `h` halves (first order).
#[test]
fn barycentric_and_uv_differentials_match_finite_differences() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let steps = [1.0, 0.5, 0.25, 0.125];
    let (mut bary_errors, mut uv_errors) = (vec![Vec::new(); 4], vec![Vec::new(); 4]);
    for _ in 0..200 {
        let hit = PrimaryHit::random(&mut rng);
        let b = hit.barycentric_derivatives();
        let analytic = [b.dx.as_dvec2(), b.dy.as_dvec2()];
        let g = rd::texture_derivatives(
            b,
            hit.uvs[0].as_vec2(),
            hit.uvs[1].as_vec2(),
            hit.uvs[2].as_vec2(),
        );
        let analytic_uv = [g.dx.as_dvec2(), g.dy.as_dvec2()];
        for (i, &h) in steps.iter().enumerate() {
            let fd = forward_difference(|p| hit.barycentrics(p), hit.pixel, h);
            bary_errors[i].push(relative_error(flat(fd), flat(analytic)));
            let fd_uv = forward_difference(|p| hit.uv(hit.barycentrics(p)), hit.pixel, h);
            uv_errors[i].push(relative_error(flat(fd_uv), flat(analytic_uv)));
        }
    }
    for (name, errors) in [("barycentric", &bary_errors), ("uv", &uv_errors)] {
        let medians: Vec<f64> = errors.iter().map(|e| median(e.clone())).collect();
        let worst: Vec<f64> = errors
            .iter()
            .map(|e| e.iter().copied().fold(0.0, f64::max))
            .collect();
        println!(
            "{name}: median relative error at h = 1, 1/2, 1/4, 1/8 px: {}; worst {}",
            list(&medians),
            list(&worst)
        );
        for i in 0..steps.len() - 1 {
            let ratios: Vec<f64> = errors[i].iter().zip(&errors[i + 1]).map(|(a, b)| a / b).collect();
            let ratio = median(ratios);
            println!(
                "{name}: median error ratio h = {} / h = {}: {ratio:.4}",
                steps[i],
                steps[i + 1]
            );
            assert!((1.8..2.2).contains(&ratio), "{name}: first-order ratio {ratio}");
        }
        // One-pixel forward differences of a perspective projection differ from the derivative by
        // about half a pixel's step times the relative change of the derivative across the pixel.
        assert!(medians[0] < 2.0e-2, "{name}: {medians:?}");
        assert!(worst[3] < 2.0e-2, "{name}: {worst:?}");
    }
}

/// The re-intersection deltas (`pixel_directions` + `barycentric_offsets`) are exact one-pixel
/// differences of the hit barycentrics, and agree with the analytic differentials to first order.
#[test]
fn barycentric_offsets_are_exact_one_pixel_differences() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let (mut exact_errors, mut analytic_gaps) = (Vec::new(), Vec::new());
    for _ in 0..200 {
        let hit = PrimaryHit::random(&mut rng);
        let cam = &hit.camera;
        let view_inv = Mat4::from_cols(
            cam.right.as_vec3().extend(0.0),
            cam.up.as_vec3().extend(0.0),
            cam.view.as_vec3().extend(0.0),
            cam.position.as_vec3().extend(1.0),
        );
        let tan = (0.5 * cam.fov_y).tan() as f32;
        let aspect = (cam.size.x / cam.size.y) as f32;
        // Inverse of an OpenGL-style projection, flipped in y so that NDC y = -1 is the top row.
        let proj_inv = Mat4::from_cols(
            glam::Vec4::new(aspect * tan, 0.0, 0.0, 0.0),
            glam::Vec4::new(0.0, -tan, 0.0, 0.0),
            glam::Vec4::new(0.0, 0.0, 0.0, -1.0),
            glam::Vec4::new(0.0, 0.0, -1.0, 1.0),
        );
        let directions = rd::pixel_directions(hit.pixel.as_vec2(), cam.size.as_vec2(), view_inv, proj_inv);
        let b = hit.barycentrics(hit.pixel);
        let b_right = hit.barycentrics(hit.pixel + DVec2::X);
        let b_below = hit.barycentrics(hit.pixel + DVec2::Y);
        let hit3 = |b: DVec2| DVec3::new(1.0 - b.x - b.y, b.x, b.y);
        let p = hit.triangle.map(|p| p.as_vec3());
        let offsets = rd::barycentric_offsets(
            Mat4::IDENTITY,
            cam.position.as_vec3(),
            p[0],
            p[1],
            p[2],
            directions.right,
            directions.below,
            hit3(b).as_vec3(),
        );
        let exact = [hit3(b_right) - hit3(b), hit3(b_below) - hit3(b)];
        let offsets = [offsets.dx.as_dvec3(), offsets.dy.as_dvec3()];
        exact_errors.push(relative_error(offsets, exact));
        let analytic = hit.barycentric_derivatives();
        let uv = |v: DVec3| DVec2::new(v.y, v.z);
        analytic_gaps.push(relative_error(
            flat(offsets.map(uv)),
            flat([analytic.dx.as_dvec2(), analytic.dy.as_dvec2()]),
        ));
    }
    let worst = exact_errors.iter().copied().fold(0.0, f64::max);
    println!(
        "re-intersection vs exact one-pixel differences: median {:.3e}, worst {worst:.3e}",
        median(exact_errors.clone())
    );
    println!(
        "re-intersection vs analytic differentials (one-pixel step): median {:.3e}",
        median(analytic_gaps.clone())
    );
    // f32 rounding of positions near 1..50 units: relative errors of a few 1e-4 at worst on the
    // difference of two barycentrics of a ~1/1000 pixel step.
    assert!(worst < 1.0e-2, "{worst}");
    assert!(median(exact_errors) < 1.0e-3);
    assert!(median(analytic_gaps) < 2.0e-2);
}

/// Exact hit of a ray on a sphere (nearest positive root).
fn sphere_hit(origin: DVec3, direction: DVec3, centre: DVec3, radius: f64) -> Option<f64> {
    let oc = origin - centre;
    let b = oc.dot(direction);
    let disc = b * b - (oc.dot(oc) - radius * radius);
    (disc >= 0.0).then(|| -b - disc.sqrt()).filter(|&t| t > 0.0)
}

/// A G-buffer texel of a scene made of a sphere in front of a far wall `z = wall`.
fn gbuffer_texel(
    camera: &Camera,
    pixel: DVec2,
    centre: DVec3,
    radius: f64,
    wall_distance: f64,
) -> GBufferSample {
    let e = camera.direction(pixel);
    let (t, normal) = match sphere_hit(camera.position, e, centre, radius) {
        Some(t) => (t, (camera.position + t * e - centre) / radius),
        None => (wall_distance / e.dot(-camera.view), camera.view),
    };
    GBufferSample {
        eye_direction: e.as_vec3(),
        distance: t as f32,
        normal: normal.as_vec3(),
    }
}

/// The G-buffer differential (RTG Eq. 23-24) follows the exact one (transfer + curvature of the
/// sphere + reflection) on a smooth surface, and the neighbour choice keeps it finite and close to
/// the exact one across a depth discontinuity, where the forward difference alone blows up.
#[test]
fn gbuffer_differentials_follow_the_exact_ones() {
    let mut rng = Rng(0x5151_aaaa_1234_0077);
    let camera = Camera {
        position: DVec3::ZERO,
        right: DVec3::X,
        up: DVec3::Y,
        view: DVec3::Z,
        fov_y: 0.8,
        size: DVec2::new(1280.0, 720.0),
    };
    let (centre, radius, wall) = (DVec3::new(0.0, 0.0, -10.0), 3.0, 40.0);
    let texel = |p: DVec2| gbuffer_texel(&camera, p, centre, radius, wall);
    let exact = |pixel: DVec2| {
        let e = camera.direction(pixel);
        let t = sphere_hit(camera.position, e, centre, radius).expect("on the sphere");
        let normal = (camera.position + t * e - centre) / radius;
        let hit = rd::transfer(camera.ray_diff(pixel), e.as_vec3(), t as f32, normal.as_vec3());
        // On a sphere N = (P - C) / R, so dN = dP / R.
        let d_normal = Derivatives3::new(hit.d_origin_dx / radius as f32, hit.d_origin_dy / radius as f32);
        rd::reflect_ray_diff(hit, e.as_vec3(), normal.as_vec3(), d_normal)
    };
    let gap = |a: RayDiff, b: RayDiff| {
        let rel = |x: Vec3, y: Vec3| f64::from((x - y).length() / y.length().max(1e-30));
        [
            rel(a.d_origin_dx, b.d_origin_dx).max(rel(a.d_origin_dy, b.d_origin_dy)),
            rel(a.d_direction_dx, b.d_direction_dx).max(rel(a.d_direction_dy, b.d_direction_dy)),
        ]
    };
    let neighbours = |p: DVec2| {
        (
            texel(p),
            texel(p + DVec2::X),
            texel(p - DVec2::X),
            texel(p + DVec2::Y),
            texel(p - DVec2::Y),
        )
    };
    // Smooth: pixels well inside the sphere's disc (up to 80% of its angular radius).
    let mut smooth: [f64; 2] = [0.0, 0.0];
    for _ in 0..200 {
        let angle = rng.range(0.0, std::f64::consts::TAU);
        let r = rng.range(0.0, 0.8) * 166.0;
        let pixel = (DVec2::new(640.0, 360.0) + r * DVec2::new(angle.cos(), angle.sin())).floor();
        let (c, right, left, below, above) = neighbours(pixel);
        let g = rd::gbuffer_ray_diff(c, right, left, below, above, 0.05);
        let [o, d] = gap(g, exact(pixel));
        smooth = [smooth[0].max(o), smooth[1].max(d)];
    }
    println!(
        "smooth sphere: G-buffer vs exact, worst relative gap: dO {:.3e}, dD {:.3e}",
        smooth[0], smooth[1]
    );
    // One-pixel forward differences of a curved surface: first-order error, a few per cent where the
    // sphere's normal turns fastest inside 80% of its radius.
    assert!(smooth[0] < 0.05 && smooth[1] < 0.1, "{smooth:?}");

    // Discontinuity: the right neighbour sees the wall, the left one the sphere.
    let row = 360.0;
    let edge = (640..1280)
        .map(f64::from)
        .find(|&x| {
            sphere_hit(
                camera.position,
                camera.direction(DVec2::new(x + 1.0, row)),
                centre,
                radius,
            )
            .is_none()
        })
        .expect("the sphere's right edge");
    let pixel = DVec2::new(edge - 2.0, row);
    let (c, _, left, below, above) = neighbours(pixel);
    let right = texel(pixel + DVec2::new(3.0, 0.0));
    let chosen = rd::gbuffer_ray_diff(c, right, left, below, above, 0.05);
    let forward_only = rd::gbuffer_ray_diff(c, right, left, below, above, f32::INFINITY);
    let exact_here = exact(pixel);
    let [chosen_gap, _] = gap(chosen, exact_here);
    let [forward_gap, _] = gap(forward_only, exact_here);
    println!(
        "depth discontinuity at x = {edge}: dO/dx relative gap with the neighbour choice {chosen_gap:.3e}, \
         forward difference only {forward_gap:.3e} (|dO/dx| {:.3e} vs exact {:.3e})",
        forward_only.d_origin_dx.length(),
        exact_here.d_origin_dx.length()
    );
    assert!(chosen.d_origin_dx.is_finite() && chosen.d_direction_dx.is_finite());
    assert!(chosen_gap < 0.5, "{chosen_gap}");
    assert!(forward_gap > 100.0, "{forward_gap}");
}

/// Isotropic LOD of a primary hit from ray differentials (RTG Eq. 1-2) and from a ray cone
/// (RTG Eq. 34), for a square texture mapped with a uniform texel density.
/// Also returns the LOD of the footprint's short axis, `log2(min(|ddx|, |ddy|))` in texels.
fn lods(camera: &Camera, pixel: DVec2, normal: DVec3, texture: f32) -> (f32, f32, f32) {
    let direction = camera.direction(pixel);
    let t = 10.0;
    let mut rng = Rng(7);
    let triangle = triangle_around(camera, pixel, t, normal, 3.0, &mut rng);
    // UVs: the plane's own coordinates, 1 UV unit per 4 world units.
    let a = normal.any_orthonormal_vector();
    let b = normal.cross(a);
    let uv = triangle.map(|p| (DVec2::new(p.dot(a), p.dot(b)) / 4.0).as_vec2());
    let p = triangle.map(|p| (p - camera.position).as_vec3());
    let (hit_t, _) = exact_hit(camera.position, direction, triangle);
    let bary = rd::barycentric_derivatives(
        camera.ray_diff(pixel),
        direction.as_vec3(),
        hit_t as f32,
        p[0],
        p[1],
        p[2],
    );
    let texels = rd::texel_derivatives(bary, uv[0], uv[1], uv[2], Vec2::splat(texture));
    let diff_lod = rd::lod_isotropic(texels);
    let short_axis_lod = texels.dx.length().min(texels.dy.length()).log2();
    let cone = rc::pinhole_ray_cone(rc::pixel_spread_angle(camera.fov_y as f32, camera.size.y as f32));
    let base = rc::triangle_base_lod(p[0], p[1], p[2], uv[0], uv[1], uv[2]);
    let cone_lod = rc::texture_lod(
        base,
        rc::width_at(cone, hit_t as f32),
        Vec2::splat(texture),
        normal.as_vec3(),
        direction.as_vec3(),
    );
    (diff_lod, cone_lod, short_axis_lod)
}

/// Ray differentials and ray cones agree on the LOD of surfaces facing the camera, within the
/// off-axis shrinking of the pixel footprint that a cone ignores; at grazing angles the cone's
/// isotropic `1/|cos|` stretch and the differentials' anisotropic one are compared and printed.
#[test]
fn lod_from_differentials_and_cones_agree_on_facing_surfaces() {
    let mut rng = Rng(0x4242_4242_1717_2323);
    let mut worst_excess: f32 = f32::NEG_INFINITY;
    let mut centre_gap: f32 = 0.0;
    let (mut gap_range, mut min_cos) = ((f32::INFINITY, f32::NEG_INFINITY), 1.0f32);
    for i in 0..300 {
        let camera = Camera::random(&mut rng, DVec3::ZERO);
        let pixel = if i % 3 == 0 {
            (camera.size / 2.0).floor()
        } else {
            random_pixel(&camera, &mut rng)
        };
        let direction = camera.direction(pixel);
        let (diff_lod, cone_lod, _) = lods(&camera, pixel, -direction, 512.0);
        // Bound: a cone spreads by the same angle for every pixel, while the pixel's true angular
        // size shrinks off axis by cos(theta) across and cos^2(theta) along the radial direction
        // (theta: angle to the optical axis); the isotropic LOD takes the larger axis, so the
        // differential LOD lies between log2(cos^2) and log2(cos) below the cone's, and the
        // pixel-centre discretisation of the exact/small-angle spread adds < 0.01.
        let cos_theta = direction.dot(-camera.view) as f32;
        let gap = diff_lod - cone_lod;
        gap_range = (gap_range.0.min(gap), gap_range.1.max(gap));
        min_cos = min_cos.min(cos_theta);
        let excess = gap.abs() - (-2.0 * cos_theta.log2() + 0.01);
        worst_excess = worst_excess.max(excess);
        if i % 3 == 0 {
            centre_gap = centre_gap.max(gap.abs());
        }
        assert!(excess <= 0.0, "LOD gap {gap} at cos(theta) {cos_theta}");
    }
    println!(
        "facing surfaces: |lod_diff - lod_cone| at the image centre <= {centre_gap:.4}; off axis \
         lod_diff - lod_cone in [{:.4}, {:.4}] for cos(theta) >= {min_cos:.3} (bound -2 log2 cos = {:.4}); \
         worst excess over the bound {worst_excess:.4}",
        gap_range.0,
        gap_range.1,
        -2.0 * min_cos.log2()
    );
    // A cone never sees less than the differentials on a facing surface.
    assert!(gap_range.1 <= 0.01, "{gap_range:?}");
    assert!(centre_gap < 0.01, "{centre_gap}");

    // Grazing angles at the image centre: print how the two differ.
    let camera = Camera {
        position: DVec3::ZERO,
        right: DVec3::X,
        up: DVec3::Y,
        view: DVec3::Z,
        fov_y: 1.0,
        size: DVec2::new(1920.0, 1080.0),
    };
    let pixel = DVec2::new(960.0, 540.0);
    let direction = camera.direction(pixel);
    for cos in [1.0f64, 0.5, 0.2, 0.1, 0.01] {
        let sin = (1.0 - cos * cos).sqrt();
        let normal = -cos * direction + sin * DVec3::Y;
        let (diff_lod, cone_lod, short_axis_lod) = lods(&camera, pixel, normal.normalize(), 512.0);
        println!(
            "grazing cos = {cos:<5}: lod from differentials {diff_lod:7.3}, from the cone {cone_lod:7.3}, \
             difference {:+.3}; the differentials' short axis stays at {short_axis_lod:7.3} \
             (anisotropy {:.1}:1, which a cone cannot express)",
            diff_lod - cone_lod,
            (diff_lod - short_axis_lod).exp2()
        );
        // The footprint's long axis grows as 1/cos for both; the isotropic LOD follows it in both.
        assert!((diff_lod - cone_lod).abs() < 0.05, "cos {cos}");
    }
}

/// Barycentric deltas of a triangle far from the world origin, by re-intersection in f32 and in
/// f64, against an f64 reference computed from the same inputs.
fn far_deltas(distance_from_origin: f64) -> (Vec3, Vec3, DVec3) {
    let mut rng = Rng(0x00f6_4f64_f64f_64f6);
    let offset = DVec3::new(1.0, 0.37, -0.61).normalize() * distance_from_origin;
    let camera = Camera {
        position: offset,
        right: DVec3::X,
        up: DVec3::Y,
        view: DVec3::Z,
        fov_y: 1.0,
        size: DVec2::new(1920.0, 1080.0),
    };
    // Snap the camera to f32, as a renderer stores it.
    let camera = Camera {
        position: camera.position.as_vec3().as_dvec3(),
        ..camera
    };
    let pixel = DVec2::new(700.0, 400.0);
    let normal = facing_normal(camera.direction(pixel), 0.7, &mut rng);
    let world = triangle_around(&camera, pixel, 5.0, normal, 4.0, &mut rng);
    // Object space: the instance is translated to the origin (a typical BLAS instance).
    let centre = (world[0] + world[1] + world[2]) / 3.0;
    let translation = -centre.as_vec3();
    let world_to_object = Mat4::from_translation(translation);
    let object = world.map(|p| (p - centre).as_vec3());
    let directions = [
        camera.direction(pixel + DVec2::X).as_vec3(),
        camera.direction(pixel + DVec2::Y).as_vec3(),
    ];
    let origin = camera.position.as_vec3();
    // Reference: the same f32 inputs, in f64.
    let object_origin = origin.as_dvec3() + translation.as_dvec3();
    let object_d = object.map(|p| p.as_dvec3());
    let bary3 = |dir: DVec3| {
        let (_, b) = exact_hit(object_origin, dir, object_d);
        DVec3::new(1.0 - b.x - b.y, b.x, b.y)
    };
    let hit = bary3(camera.direction(pixel)).as_vec3();
    let reference = (bary3(directions[0].as_dvec3()) - hit.as_dvec3()).abs()
        + (bary3(directions[1].as_dvec3()) - hit.as_dvec3()).abs();
    let args = (
        world_to_object,
        origin,
        object[0],
        object[1],
        object[2],
        directions[0],
        directions[1],
        hit,
    );
    let f32_deltas = rd::barycentric_deltas(args.0, args.1, args.2, args.3, args.4, args.5, args.6, args.7);
    let f64_deltas =
        rd64::barycentric_deltas_f64(args.0, args.1, args.2, args.3, args.4, args.5, args.6, args.7);
    (f32_deltas, f64_deltas, reference)
}

/// Why the f64 variant exists: at 1e4 units from the origin the f32 re-intersection loses the
/// neighbour direction in `O + direction` and its barycentric deltas are wrong by tens of per cent or
/// more, while the f64 variant stays within the f32 rounding of its inputs.
#[test]
fn f64_reintersection_fixes_far_from_origin_deltas() {
    let relative = |a: Vec3, reference: DVec3| (a.as_dvec3() - reference).length() / reference.length();
    let mut rows = Vec::new();
    for distance in [1.0e1, 1.0e2, 1.0e3, 1.0e4, 3.0e4, 1.0e5] {
        let (f32_deltas, f64_deltas, reference) = far_deltas(distance);
        let (e32, e64) = (relative(f32_deltas, reference), relative(f64_deltas, reference));
        println!(
            "|O| = {distance:8.0e}: deltas ({:.3e}, {:.3e}, {:.3e}); relative error f32 {e32:.3e}, f64 {e64:.3e}",
            reference.x, reference.y, reference.z
        );
        rows.push((distance, e32, e64));
    }
    for &(distance, e32, e64) in &rows {
        // The f64 variant: only the f32 rounding of its inputs and result (hit barycentrics and
        // directions are f32: ~1e-7 absolute on deltas of ~1e-3).
        assert!(e64 < 1.0e-3, "f64 at {distance}: {e64}");
        if distance >= 1.0e4 {
            // ulp(1e4) = 2^-10 ~ 1e-3 on a unit direction: as large as one pixel's angular step.
            assert!(e32 > 0.1, "f32 at {distance} should be visibly wrong: {e32}");
        }
        if distance <= 1.0e1 {
            assert!(e32 < 1.0e-2, "f32 at {distance}: {e32}");
        }
    }
}

/// `RayDiff` is 64 bytes with explicit pads after each vec3, as WGSL and std430 / scalar lay it out.
#[test]
fn ray_diff_layout() {
    assert_layout!(RayDiff, 64, {
        d_origin_dx: 0,
        pad0: 12,
        d_origin_dy: 16,
        pad1: 28,
        d_direction_dx: 32,
        pad2: 44,
        d_direction_dy: 48,
        pad3: 60,
    });
    let diff = RayDiff::new(Vec3::ONE, Vec3::ONE, Vec3::ONE, Vec3::ONE);
    let words: &[f32] = bytemuck::cast_slice(std::slice::from_ref(&diff));
    assert_eq!([words[3], words[7], words[11], words[15]], [0.0; 4]);
}

/// At exactly the critical angle (`k = 0`) refraction continues the angles just short of it:
/// `dot(T, N)` is `-sqrt(k)`, which at `k = 0` is `-0`, and keeping it `DIFF_MIN_COS` away from 0
/// must keep that sign. With `eta = 2` the critical cosine is `-sqrt(3) / 2`: `cos^2` rounds to
/// exactly 0.75 in f32, so `k = 1 - 4 (1 - 0.75)` is exactly 0; one ULP more head-on, `k` is
/// 2.4e-7 and `dot(T, N) = -4.9e-4`. A change of direction along the normal is amplified by
/// `rate = 2 - 4 cos / dot(T, N)`: about `2 - 7094` there and `2 - 3.46 / DIFF_MIN_COS` at the
/// critical angle, the same sign and larger; a clamp to `+DIFF_MIN_COS` would flip it.
#[test]
fn refraction_keeps_its_sign_at_the_critical_angle() {
    let normal = Vec3::Z;
    let d_normal = Derivatives3 {
        dx: Vec3::ZERO,
        dy: Vec3::ZERO,
    };
    let diff = RayDiff::new(Vec3::ZERO, Vec3::ZERO, Vec3::Z, Vec3::Z);
    let refracted_at = |cosine: f32| {
        let direction = Vec3::new((1.0 - cosine * cosine).sqrt(), 0.0, cosine);
        let k = 1.0 - 4.0 * (1.0 - cosine * cosine);
        (k, rd::refract_ray_diff(diff, direction, normal, d_normal, 2.0))
    };
    let critical = -0.866_025_4f32;
    let (k_critical, at) = refracted_at(critical);
    let (k_short, short) = refracted_at(f32::from_bits(critical.to_bits() + 1));
    println!(
        "k = {k_critical:e}: dT/dx = {:?}; k = {k_short:e}: dT/dx = {:?}",
        at.diff.d_direction_dx, short.diff.d_direction_dx
    );
    assert_eq!(k_critical, 0.0, "the test's angle is not the critical one");
    assert!(k_short > 0.0 && !short.total_internal_reflection && !at.total_internal_reflection);
    let (at_z, short_z) = (at.diff.d_direction_dx.z, short.diff.d_direction_dx.z);
    assert!(
        short_z > 1.0e3,
        "the change of direction is not amplified: {short_z}"
    );
    assert!(
        at_z >= short_z,
        "at the critical angle the change turns or shrinks: {at_z} against {short_z} just short of it"
    );
    let clamp_bound = 2.0 + 4.0 * critical.abs() / rd::DIFF_MIN_COS;
    assert!(
        at_z <= clamp_bound * 1.0001,
        "beyond the clamp: {at_z} > {clamp_bound}"
    );
}
