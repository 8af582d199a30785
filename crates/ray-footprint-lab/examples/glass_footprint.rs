//! How large a pixel's footprint on the ground plane is when seen through the glass sphere of the
//! materials scene (`Camera::glass`), at the lab's two image sizes: the exact footprint against
//! the refracted ray cone alone (RTG II ch. 10, the section in the plane of incidence: the
//! `cone_refraction` mode), and against the two sections the `cone_sections` mode carries (that
//! cone and the section across the plane of incidence). It explains the quality lab's glass figures: an isotropic
//! `textureGrad` filters at the footprint's longer axis, so a cone wider than that axis blurs.
//!
//! ```text
//! cargo run --release -p ray-footprint-lab --example glass_footprint
//! ```
//!
//! Everything is on the CPU, on the analytic sphere the scene's mesh approximates (its curvature
//! exactly `1 / radius`, where the renderer fits one to each triangle's vertex normals):
//!
//! - *Exact*: each pixel's ray is traced in f64 into the sphere, out of it by Snell's law and down
//!   to the ground (`y = 0`); the rays 0.01 pixel to each side give the ground point's derivatives
//!   per pixel by central differences (`ray_footprint_cases::exact::derivative`, which also traces
//!   the rays 0.02 pixel away for its error estimate), and the footprint's longer axis is the
//!   larger singular value of that Jacobian.
//! - *Cone*: the library's f32 functions: the pinhole cone of the ray, refracted at both surfaces
//!   by `refract_ray_cone` with the normal's turn across the slanted footprint, its footprint on
//!   the ground `|width| / |n . d|`, as the `cone_refraction` mode carries it. `refract_ray_cone`
//!   carries the width in the plane of incidence (the tangential section of the beam).
//! - *Two widths*: the same cone, and beside it the section across the plane of incidence (the
//!   sagittal section), refracted at both surfaces by `refract_sagittal_cone` (Coddington's
//!   sagittal equation to first order), as the renderer's `cone_sections` mode carries it. For a
//!   sphere both surfaces share one plane of incidence, so the two sections stay the beam's axes;
//!   on the ground they span an ellipse whose longer axis is the footprint (`two_section_width`
//!   over `|n . d|`). *Larger width*: the larger of the two widths over `|n . d|` on the ground, a
//!   footprint that needs no direction for the sections.
//!
//! Each size prints, per 10-degree band of the incidence angle at the sphere's front, the mean of
//! `log2(footprint / exact longer axis)` in mip levels (positive: too wide, a blur), and over
//! all pixels the mean, the mean magnitude and the 95th percentile.

use glam::{DVec2, DVec3, Vec3};
use ray_footprint::ray_cone::{
    pinhole_ray_cone_for_ray, propagate, refract_ray_cone, refract_sagittal_cone, two_section_width,
    width_at, world_footprint, RayCone,
};
use ray_footprint_cases::exact::{derivative, snell};
use ray_footprint_lab::quality::footprint::singular_values;
use ray_footprint_lab::rt::abi::RtPushConstants;
use ray_footprint_lab::rt::{Camera, GLASS_CENTRE, GLASS_INDEX, GLASS_RADIUS};

/// The lab's two image sizes.
const SIZES: [(u32, u32); 2] = [(240, 160), (360, 240)];
/// The step of the central differences, in pixels.
const STEP: f64 = 0.01;
/// Bands of the incidence angle at the sphere's front, each `BAND_DEGREES` wide.
const BANDS: usize = 9;
const BAND_DEGREES: f64 = 10.0;

/// A ray's path through the sphere to the ground.
struct Path {
    direction: DVec3,
    /// Distance to the front surface, and the outward normal there.
    front: (f64, DVec3),
    /// Direction inside, distance to the back surface, and the outward normal there.
    inside: DVec3,
    back: (f64, DVec3),
    /// Direction leaving the sphere, and the distance from the back surface to the ground.
    leaving: DVec3,
    to_ground: f64,
    ground: DVec3,
}

/// What one pixel gives: the band of its incidence angle, and `log2(footprint / exact)` for the
/// cone, for the two widths, and for the larger of the two widths alone.
struct Sample {
    band: usize,
    cone: f64,
    two_widths: f64,
    larger_width: f64,
}

/// The two sections of a beam on the ground: the footprint their ellipse spans, and the larger
/// width slanted by the ground (`max |width| / |n . d|`), which needs no direction.
struct Sections {
    ellipse: f64,
    larger_width: f64,
}

fn main() {
    for (width, height) in SIZES {
        let camera = Camera::glass().push_constants(0, 1.0, (width, height), 1);
        let samples = sample_pixels(&camera);
        print_size(width, height, &samples);
    }
}

/// Every pixel whose ray passes through the sphere (no total internal reflection) to the ground,
/// as do its neighbours at [`STEP`].
fn sample_pixels(camera: &RtPushConstants) -> Vec<Sample> {
    let mut samples = Vec::new();
    for y in 0..camera.height {
        for x in 0..camera.width {
            let centre = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            if let Some(sample) = sample_pixel(camera, centre) {
                samples.push(sample);
            }
        }
    }
    samples
}

fn sample_pixel(camera: &RtPushConstants, (x, y): (f64, f64)) -> Option<Sample> {
    let path = trace(camera, x, y)?;
    let exact = exact_longer_axis(camera, x, y, path.ground)?;
    let eye_cone = pinhole_ray_cone_for_ray(
        camera.cone.pixel_spread_angle,
        path.direction.as_vec3(),
        camera.forward,
    );
    let cone = refracted_cone(eye_cone, &path);
    let cone_footprint = f64::from(world_footprint(
        cone,
        path.to_ground as f32,
        Vec3::Y,
        path.leaving.as_vec3(),
    ));
    let incidence = (-path.front.1.dot(path.direction)).acos().to_degrees();
    let sections = two_width_footprint(eye_cone, &path, cone);
    Some(Sample {
        band: ((incidence / BAND_DEGREES) as usize).min(BANDS - 1),
        cone: (cone_footprint / exact).log2(),
        two_widths: (sections.ellipse / exact).log2(),
        larger_width: (sections.larger_width / exact).log2(),
    })
}

/// The unit direction of the ray through `(x, y)` (pixel units from the image's corner), as the
/// renderer's `rt_primary_direction` makes it.
fn pixel_direction(camera: &RtPushConstants, x: f64, y: f64) -> DVec3 {
    let across = 2.0 * x / f64::from(camera.width) - 1.0;
    let down = 2.0 * y / f64::from(camera.height) - 1.0;
    let tan_half = f64::from(camera.tan_half_fov_y);
    (camera.forward.as_dvec3() + across * f64::from(camera.aspect) * tan_half * camera.right.as_dvec3()
        - down * tan_half * camera.up.as_dvec3())
    .normalize()
}

/// Distance along the unit `direction` from `origin` to the sphere: its near side from outside,
/// its far side from inside.
fn sphere_distance(origin: DVec3, direction: DVec3, from_inside: bool) -> Option<f64> {
    let offset = origin - GLASS_CENTRE.as_dvec3();
    let half_b = offset.dot(direction);
    let radius = f64::from(GLASS_RADIUS);
    let discriminant = half_b * half_b - (offset.length_squared() - radius * radius);
    let root = discriminant.sqrt();
    let distance = if from_inside {
        -half_b + root
    } else {
        -half_b - root
    };
    (discriminant >= 0.0 && distance > 1e-9).then_some(distance)
}

/// The path of the ray through `(x, y)`: into the sphere, out of it, down to the ground.
fn trace(camera: &RtPushConstants, x: f64, y: f64) -> Option<Path> {
    let direction = pixel_direction(camera, x, y);
    let index = f64::from(GLASS_INDEX);
    let outward = |point: DVec3| (point - GLASS_CENTRE.as_dvec3()).normalize();
    let eye = camera.eye.as_dvec3();
    let front_distance = sphere_distance(eye, direction, false)?;
    let entry = eye + front_distance * direction;
    let front_normal = outward(entry);
    let inside = snell(direction, front_normal, 1.0 / index)?;
    let back_distance = sphere_distance(entry, inside, true)?;
    let exit = entry + back_distance * inside;
    let back_normal = outward(exit);
    let leaving = snell(inside, back_normal, index)?;
    let to_ground = -exit.y / leaving.y;
    (leaving.y < 0.0).then(|| Path {
        direction,
        front: (front_distance, front_normal),
        inside,
        back: (back_distance, back_normal),
        leaving,
        to_ground,
        ground: exit + to_ground * leaving,
    })
}

/// The longer axis of the exact footprint at the ground point `ground`: the larger singular value
/// of the ground point's derivatives per pixel (central differences of [`STEP`]), or `None` where
/// a neighbouring ray misses the glass or the ground.
fn exact_longer_axis(camera: &RtPushConstants, x: f64, y: f64, ground: DVec3) -> Option<f64> {
    let ground_at = |x: f64, y: f64| trace(camera, x, y).map_or(DVec3::NAN, |path| path.ground);
    let scale = ground.length();
    let along_x = derivative(|h| ground_at(x + h, y), STEP, scale).value;
    let along_y = derivative(|h| ground_at(x, y + h), STEP, scale).value;
    (along_x.is_finite() && along_y.is_finite()).then(|| longer_axis(along_x, along_y))
}

/// The longer semi-axis of the ellipse `a cos s + b sin s` that two vectors on the ground span:
/// the larger singular value of the matrix of their `(x, z)` components (the ground is `y = 0`,
/// so that is all of them).
fn longer_axis(a: DVec3, b: DVec3) -> f64 {
    let on_ground = |v: DVec3| DVec2::new(v.x, v.z);
    singular_values(on_ground(a), on_ground(b)).0
}

/// The tangential section leaving the sphere, as the renderer's `cone_refraction` and
/// `cone_sections` modes carry it: `eye_cone`, the ray's pinhole cone, refracted at the front and
/// at the back, each time with the normal's turn across the slanted footprint (`rt_normal_spread`,
/// curvature `1 / radius` on the outward normal's side).
fn refracted_cone(eye_cone: RayCone, path: &Path) -> RayCone {
    let index = GLASS_INDEX;
    let curvature = 1.0 / GLASS_RADIUS;
    let refract_at = |cone: RayCone, (distance, normal): (f64, DVec3), direction: DVec3, eta: f32| {
        let (distance, normal, direction) = (distance as f32, normal.as_vec3(), direction.as_vec3());
        let normal_spread = curvature * world_footprint(cone, distance, normal, direction);
        refract_ray_cone(
            propagate(cone, distance, 0.0),
            normal,
            direction,
            normal_spread,
            eta,
        )
        .cone
    };
    let inside = refract_at(eye_cone, path.front, path.direction, 1.0 / index);
    refract_at(inside, path.back, path.inside, index)
}

/// The footprint of a beam with the tangential section `cone` (leaving the sphere) and the
/// sagittal section carried from `eye_cone` (a pinhole cone: the two sections start equal) by
/// `refract_sagittal_cone` at both surfaces, each with the normal's turn `curvature * |width|`
/// across it: `two_section_width` of the two sections on the ground, over `|n . d|`, the longer axis
/// of their ellipse there; and the larger width slanted.
fn two_width_footprint(eye_cone: RayCone, path: &Path, cone: RayCone) -> Sections {
    let curvature = 1.0 / GLASS_RADIUS;
    let refract_at = |section: RayCone, (distance, normal): (f64, DVec3), direction: DVec3, eta: f32| {
        let at_hit = propagate(section, distance as f32, 0.0);
        let normal_spread = curvature * at_hit.width.abs();
        refract_sagittal_cone(at_hit, normal.as_vec3(), direction.as_vec3(), normal_spread, eta)
    };
    let inside = refract_at(eye_cone, path.front, path.direction, 1.0 / GLASS_INDEX);
    let leaving = refract_at(inside, path.back, path.inside, GLASS_INDEX);
    let axis = path.direction.cross(path.front.1).as_vec3();
    let to_ground = path.to_ground as f32;
    let (tangential_width, sagittal_width) = (width_at(cone, to_ground), width_at(leaving, to_ground));
    let slant = path.leaving.y.abs();
    let width = two_section_width(
        tangential_width,
        sagittal_width,
        axis,
        Vec3::Y,
        path.leaving.as_vec3(),
    );
    Sections {
        ellipse: f64::from(width) / slant,
        larger_width: f64::from(tangential_width.abs().max(sagittal_width.abs())) / slant,
    }
}

/// One size's table: per band, then over all pixels.
fn print_size(width: u32, height: u32, samples: &[Sample]) {
    println!(
        "glass sphere, {width} x {height}, {} pixels through the glass to the ground",
        samples.len()
    );
    println!("log2(footprint / exact longer axis), mip levels (positive: wider than exact)");
    println!("| incidence at the front | pixels | cone | two widths | larger width |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    for band in 0..BANDS {
        let in_band: Vec<&Sample> = samples.iter().filter(|sample| sample.band == band).collect();
        if in_band.is_empty() {
            continue;
        }
        let mean =
            |value: fn(&Sample) -> f64| in_band.iter().map(|s| value(s)).sum::<f64>() / in_band.len() as f64;
        println!(
            "| {}-{} degrees | {} | {:.3} | {:.3} | {:.3} |",
            band as f64 * BAND_DEGREES,
            (band + 1) as f64 * BAND_DEGREES,
            in_band.len(),
            mean(|s| s.cone),
            mean(|s| s.two_widths),
            mean(|s| s.larger_width)
        );
    }
    print_summary("cone", samples.iter().map(|sample| sample.cone).collect());
    print_summary(
        "two widths",
        samples.iter().map(|sample| sample.two_widths).collect(),
    );
    print_summary(
        "larger width",
        samples.iter().map(|sample| sample.larger_width).collect(),
    );
    println!();
}

/// The mean, mean magnitude and 95th percentile of `values`, named `name`.
fn print_summary(name: &str, mut values: Vec<f64>) {
    values.sort_by(f64::total_cmp);
    let count = values.len().max(1) as f64;
    let mean = values.iter().sum::<f64>() / count;
    let magnitude = values.iter().map(|value| value.abs()).sum::<f64>() / count;
    let p95 = values.get(values.len() * 19 / 20).copied().unwrap_or(f64::NAN);
    println!("{name}: mean {mean:.3}, mean magnitude {magnitude:.3}, 95th percentile {p95:.3}");
}
