//! The image error of each cone rule when its width picks the texture's level of detail.
//!
//! Every diffuse surface (and the Lambert base of a coat) reflects `DIFFUSE_ALBEDO` times the
//! procedural texture ([`super::texture`]), sampled trilinearly at the level
//! `texture_lod(log2(1 / TEXTURE_REPEAT_METRES), |width|, (1024, 1024), n, d)` of this crate, that
//! is `log2(|width| / |cos theta| x 512 texels per metre)` with the method's cone width at the
//! vertex; GGX conductors reflect the constant colour [`CONDUCTOR_COLOUR`]. Light comes from a
//! constant white environment of radiance 1 that paths leaving the scene see, and in the closed
//! room from one sphere light ([`scene_light`]). A path scatters at up to 4 vertices (the tracer's
//! 4, the last one sampled here from the numbers of vertex 5) and is worth its throughput, the
//! product of `f cos / pdf` over its vertices, times the radiance its last ray meets (Kajiya 1986;
//! no Russian roulette, no next-event estimation). The same paths serve every method of a render
//! (only the texture lookups differ), so differences between methods are not noise of the paths.
//!
//! The error of a method at `s` samples per pixel is measured with two renders `A` and `B` of
//! independent seeds against a reference `R`, the mean of two renders `R1`, `R2` at level 0 of
//! many samples, over the `n = 3 x pixels` linear RGB values:
//! `RMSE^2 = (mean((A - R)^2) + mean((B - R)^2)) / 2`, the variance of one render
//! `var = mean((A - B)^2) / 2`, the reference's variance `var_R = mean((R1 - R2)^2) / 4`, and
//! `bias^2 = mean(((A + B) / 2 - R)^2) - var / 2 - var_R` (the mean of two independent renders has
//! half the variance; the reference's own noise adds `var_R` to every squared difference).

use super::methods::{method_widths, Method, METHODS};
use super::sampling::vertex_numbers;
use super::sampling::{pdf_and_bsdf, sample_material, shading_frame, Stream, NUMBERS_PER_VERTEX};
use super::scene::{Camera, Material, Scene, DIFFUSE_ALBEDO, TEXTURE_REPEAT_METRES};
use super::texture::{Texture, TEXTURE_SIZE};
use super::tracer::{trace, Path, Vertex, MAX_VERTICES};
use crate::quality::plots::{scatter_plot, ScatterPanel, ScatterPoint};
use crate::quality::LabError;
use glam::{DVec3, Vec2};
use ray_footprint::ray_cone::texture_lod;
use std::f64::consts::PI;
use std::fmt::Write;

/// Radiance of the environment every ray that leaves the scene sees (white).
pub const ENVIRONMENT_RADIANCE: f64 = 1.0;

/// The constant colour (Fresnel) of every GGX conductor; a coat's lobe keeps Fresnel 1.
pub const CONDUCTOR_COLOUR: DVec3 = DVec3::new(0.95, 0.9, 0.8);

/// A sphere that emits `radiance` towards every direction from its surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// The centre.
    pub centre: DVec3,
    /// The radius.
    pub radius: f64,
    /// Emitted radiance (white).
    pub radiance: f64,
}

impl Light {
    /// Distance along the unit `direction` from `origin` (outside the sphere) to the sphere.
    pub fn distance(&self, origin: DVec3, direction: DVec3) -> Option<f64> {
        let offset = origin - self.centre;
        let half_b = offset.dot(direction);
        let discriminant = half_b * half_b - (offset.length_squared() - self.radius * self.radius);
        let t = -half_b - discriminant.max(0.0).sqrt();
        (discriminant >= 0.0 && t > 0.0).then_some(t)
    }
}

/// The light of a scene: a sphere of radius 0.6 and radiance 5 under the ceiling of the closed
/// `rough_room` (which the environment cannot reach), none elsewhere.
pub fn scene_light(scene: &Scene) -> Option<Light> {
    (scene.name == "rough_room").then_some(Light {
        centre: DVec3::new(0.5, 2.2, -3.0),
        radius: 0.6,
        radiance: 5.0,
    })
}

/// How a render picks the texture's level at a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageMethod {
    /// Level 0 everywhere (bilinear at level 0): what the reference renders.
    Mip0,
    /// The level of a cone rule's width.
    Cone(Method),
    /// The first vertex at the level of its cone's width (the cone every rule starts from, so
    /// every rule's first width), every later vertex at the texture's last level, its mean. Its
    /// noise (sd) is what no rule for the later vertices removes: the noise of the paths' light
    /// and of the first hit's lookups, which every rule shares. A floor, not a rule to ship.
    MeanPastFirstHit,
}

/// A cone width past every scene's size, whose level lies past the texture's last: a lookup
/// there reads the texture's mean.
const BEYOND_ANY_SCENE: f32 = 1.0e6;

impl ImageMethod {
    /// The name in the tables.
    pub fn name(self) -> &'static str {
        match self {
            ImageMethod::Mip0 => "mip 0",
            ImageMethod::Cone(method) => method.name(),
            ImageMethod::MeanPastFirstHit => "texture mean past the first hit (the floor)",
        }
    }

    /// Whether it is one of the peer renderers' rules that ship: JCGT's roughness, RTXPT's, the
    /// square root of the pdf and the OptiX Toolkit's.
    pub fn is_shipped(self) -> bool {
        matches!(
            self,
            ImageMethod::Cone(
                Method::JcgtRoughness | Method::Rtxpt | Method::PdfSquareRoot | Method::OptixToolkit
            )
        )
    }
}

/// The lowest RMSE of a method other than the floor ([`ImageMethod::MeanPastFirstHit`]) at
/// checkpoint `c` of scene `e`: the one the tables mark and count as a win.
fn lowest_rmse(e: &SceneErrors, c: usize) -> f64 {
    image_methods()
        .iter()
        .zip(&e.errors)
        .filter(|(method, _)| **method != ImageMethod::MeanPastFirstHit)
        .map(|(_, errors)| errors[c].rmse)
        .fold(f64::INFINITY, f64::min)
}

/// The methods in the order the tables print them: mip 0, [`METHODS`], then the floor.
pub fn image_methods() -> Vec<ImageMethod> {
    std::iter::once(ImageMethod::Mip0)
        .chain(METHODS.iter().map(|&m| ImageMethod::Cone(m)))
        .chain([ImageMethod::MeanPastFirstHit])
        .collect()
}

/// Where a diffuse albedo comes from.
#[derive(Clone, Copy, Debug)]
pub enum Albedo<'a> {
    /// `DIFFUSE_ALBEDO` times the texture at the method's level.
    Textured(&'a Texture),
    /// The same albedo everywhere (for checks against closed forms).
    Constant(f64),
}

impl Albedo<'_> {
    /// The diffuse albedo at `vertex` of `scene` for the cone width `width` (level 0 for `None`).
    fn at(&self, scene: &Scene, vertex: &Vertex, width: Option<f32>) -> DVec3 {
        let texture = match *self {
            Albedo::Constant(albedo) => return DVec3::splat(albedo),
            Albedo::Textured(texture) => texture,
        };
        let uv = scene.surfaces[vertex.surface].texture_coordinates(vertex.position);
        let lod = width.map_or(0.0, |width| level_of_detail(width, vertex));
        DIFFUSE_ALBEDO * texture.trilinear(uv, lod)
    }
}

/// `texture_lod(log2(1 / TEXTURE_REPEAT_METRES), width, (1024, 1024), n, d)`
/// (RTG Eq. 34): `log2(|width| / |n . d| x TEXTURE_SIZE / TEXTURE_REPEAT_METRES)`.
pub fn level_of_detail(width: f32, vertex: &Vertex) -> f64 {
    let base_lod = (1.0 / TEXTURE_REPEAT_METRES).log2() as f32;
    let size = Vec2::splat(TEXTURE_SIZE as f32);
    f64::from(texture_lod(
        base_lod,
        width,
        size,
        vertex.normal.as_vec3(),
        vertex.incoming.as_vec3(),
    ))
}

/// The normal at `vertex` turned to face the incoming ray.
fn facing_normal(vertex: &Vertex) -> DVec3 {
    if vertex.normal.dot(vertex.incoming) < 0.0 {
        vertex.normal
    } else {
        -vertex.normal
    }
}

/// A GGX conductor's `f cos_o / pdf` for the sampled `outgoing` (Fresnel 1): with `pdf_and_bsdf`'s
/// `f = D G1(i) G1(o) / (4 cos_i cos_o)` and `pdf = D cos_m / (4 |o . m|)` (Walter et al. 2007,
/// Eq. 20, 14, 35-36) it is `G1(i) G1(o) |o . m| / (cos_i cos_m)`; 1 for a mirror.
pub fn ggx_weight(roughness: f64, normal: DVec3, incoming: DVec3, outgoing: DVec3) -> f64 {
    let (pdf, bsdf) = pdf_and_bsdf(Material::Conductor { roughness }, normal, incoming, outgoing);
    if pdf.is_infinite() {
        return 1.0;
    }
    if pdf <= 0.0 {
        return 0.0;
    }
    bsdf * outgoing.dot(normal) / pdf
}

/// `f cos_o / pdf` of `material` for the sampled `outgoing`, per channel, with the diffuse albedo
/// `albedo`: Lambert `albedo`; a conductor [`CONDUCTOR_COLOUR`] times [`ggx_weight`]; a coat
/// `(c f_ggx + (1 - c) albedo / pi) cos_o / (c pdf_ggx + (1 - c) cos_o / pi)`, the one-sample
/// estimator of the mixture with the mixture's pdf, whichever lobe was sampled.
pub fn scatter_weight(
    material: Material,
    normal: DVec3,
    incoming: DVec3,
    outgoing: DVec3,
    albedo: DVec3,
) -> DVec3 {
    let cos_out = outgoing.dot(normal);
    match material {
        Material::Lambert => albedo,
        Material::Conductor { roughness } => {
            CONDUCTOR_COLOUR * ggx_weight(roughness, normal, incoming, outgoing)
        }
        Material::Coated {
            roughness,
            coat_weight,
        } => {
            let glossy = Material::Conductor { roughness };
            let (pdf_ggx, f_ggx) = pdf_and_bsdf(glossy, normal, incoming, outgoing);
            let base = 1.0 - coat_weight;
            let pdf = coat_weight * pdf_ggx + base * cos_out / PI;
            let bsdf = DVec3::splat(coat_weight * f_ggx) + base * albedo / PI;
            bsdf * cos_out / pdf
        }
    }
}

/// What the last ray of a path meets: the light if it is nearer than any surface, the environment
/// if no surface is ahead, else nothing.
fn final_radiance(scene: &Scene, light: Option<Light>, origin: DVec3, direction: DVec3, from: usize) -> f64 {
    let surface = scene
        .closest_hit(origin, direction, Some(from))
        .map(|hit| hit.distance);
    let emitter = light.and_then(|l| l.distance(origin, direction).map(|t| (t, l.radiance)));
    match (surface, emitter) {
        (_, Some((t, radiance))) if surface.is_none_or(|s| t < s) => radiance,
        (None, _) => ENVIRONMENT_RADIANCE,
        _ => 0.0,
    }
}

/// The direction leaving the last of [`MAX_VERTICES`] vertices, sampled from `numbers`, or `None`
/// where it goes below the surface.
fn last_scatter(scene: &Scene, vertex: &Vertex, numbers: [f64; NUMBERS_PER_VERTEX]) -> Option<DVec3> {
    let surface = &scene.surfaces[vertex.surface];
    let frame = shading_frame(facing_normal(vertex), surface.frame_axis);
    sample_material(surface.material, &frame, vertex.incoming, numbers).map(|(_, d)| d)
}

/// A traced path with the numbers its last vertex scatters with.
pub struct PathSample {
    /// The camera.
    pub camera: Camera,
    /// The path (up to [`MAX_VERTICES`] vertices).
    pub path: Path,
    /// The numbers of a fifth vertex, read at the fourth to sample its direction.
    pub last_numbers: [f64; NUMBERS_PER_VERTEX],
}

/// The radiance `path` carries to the camera, the diffuse albedo of vertex `k` from `albedo` at
/// the cone width `widths[k]` (level 0 without widths).
pub fn path_radiance(
    scene: &Scene,
    light: Option<Light>,
    albedo: Albedo,
    sample: &PathSample,
    widths: Option<&[f32]>,
) -> DVec3 {
    let mut throughput = DVec3::ONE;
    let mut origin = sample.camera.position;
    let vertices = &sample.path.vertices;
    for (k, vertex) in vertices.iter().enumerate() {
        if let Some(emitter) = light {
            if emitter
                .distance(origin, vertex.incoming)
                .is_some_and(|t| t < vertex.distance)
            {
                return throughput * emitter.radiance;
            }
        }
        let outgoing = match vertex.scatter {
            Some(scatter) => scatter.direction,
            None if k + 1 == MAX_VERTICES => match last_scatter(scene, vertex, sample.last_numbers) {
                Some(direction) => direction,
                None => return DVec3::ZERO,
            },
            None => return DVec3::ZERO,
        };
        let material = scene.surfaces[vertex.surface].material;
        let diffuse = albedo.at(scene, vertex, widths.map(|w| w[k]));
        throughput *= scatter_weight(
            material,
            facing_normal(vertex),
            vertex.incoming,
            outgoing,
            diffuse,
        );
        if k + 1 == vertices.len() {
            return throughput * final_radiance(scene, light, vertex.position, outgoing, vertex.surface);
        }
        origin = vertex.position;
    }
    match light.and_then(|l| l.distance(origin, sample.path.primary)) {
        Some(_) => throughput * light.map_or(0.0, |l| l.radiance),
        None => throughput * ENVIRONMENT_RADIANCE,
    }
}

/// What a render does.
#[derive(Clone, Debug)]
pub struct RenderJob<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// Where diffuse albedos come from.
    pub albedo: Albedo<'a>,
    /// Image size `(width, height)`.
    pub size: (u32, u32),
    /// Seed of the render's random numbers.
    pub seed: u64,
    /// The methods rendered with the same paths.
    pub methods: Vec<ImageMethod>,
    /// Samples per pixel at which the running mean is kept, ascending; the last is the total.
    pub checkpoints: Vec<usize>,
    /// How many samples share the pixel's cone: every path starts from the cone of a pixel
    /// `sqrt(cone_share)` times smaller (the pixel of an image that many times taller). 1 starts
    /// from the pixel's cone; `n` from the cone of one of `n` samples.
    pub cone_share: usize,
    /// Threads to render on.
    pub threads: usize,
}

/// A render's images: `images[c][m]` is method `m` at checkpoint `c`, row by row, linear RGB.
pub type Images = Vec<Vec<Vec<DVec3>>>;

/// Sample `s` of pixel `(x, y)`: path `(y W + x) S + s` (`S` the total samples) of the seed, its
/// position uniform in the pixel and its vertex numbers from the path's streams.
fn path_sample(job: &RenderJob, camera: &Camera, (x, y): (u32, u32), s: usize) -> PathSample {
    let total = *job.checkpoints.last().unwrap_or(&1) as u64;
    let index = (u64::from(y) * u64::from(job.size.0) + u64::from(x)) * total + s as u64;
    let mut stream = Stream::new(job.seed, index, 0);
    let position = (f64::from(x) + stream.next_f64(), f64::from(y) + stream.next_f64());
    let numbers = std::array::from_fn(|k| vertex_numbers(job.seed, index, k as u32 + 1));
    PathSample {
        camera: *camera,
        path: trace(job.scene, camera, position, &numbers),
        last_numbers: vertex_numbers(job.seed, index, MAX_VERTICES as u32 + 1),
    }
}

/// The camera whose pixel's cone is the cone of one of `cone_share` samples of a pixel of
/// `camera`: the same view with `sqrt(cone_share)` times as many rows, whose pixel spread angle
/// `atan(2 tan(fov_y / 2) / H)` (JCGT 2021, Eq. 30) is the pixel's over `sqrt(cone_share)` to
/// first order. Only the cones read it; the paths go through `camera`'s pixels.
fn cone_camera(camera: &Camera, cone_share: usize) -> Camera {
    Camera {
        height: camera.height * (cone_share.max(1) as f64).sqrt(),
        ..*camera
    }
}

/// Every method's radiance along one path.
fn method_radiances(job: &RenderJob, light: Option<Light>, sample: &PathSample) -> Vec<DVec3> {
    let cone_camera = cone_camera(&sample.camera, job.cone_share);
    job.methods
        .iter()
        .map(|&method| match method {
            ImageMethod::Mip0 => path_radiance(job.scene, light, job.albedo, sample, None),
            ImageMethod::Cone(rule) => {
                let widths = method_widths(rule, &sample.path, &cone_camera);
                path_radiance(job.scene, light, job.albedo, sample, Some(&widths))
            }
            ImageMethod::MeanPastFirstHit => {
                let mut widths = method_widths(Method::NoScatteringTerm, &sample.path, &cone_camera);
                widths
                    .iter_mut()
                    .skip(1)
                    .for_each(|width| *width = BEYOND_ANY_SCENE);
                path_radiance(job.scene, light, job.albedo, sample, Some(&widths))
            }
        })
        .collect()
}

/// A pixel's means: per checkpoint, per method.
type PixelMeans = Vec<Vec<DVec3>>;

/// One pixel: per checkpoint, per method, the mean of its first samples.
fn render_pixel(job: &RenderJob, camera: &Camera, light: Option<Light>, pixel: (u32, u32)) -> PixelMeans {
    let mut sums = vec![DVec3::ZERO; job.methods.len()];
    let mut means = Vec::with_capacity(job.checkpoints.len());
    let total = *job.checkpoints.last().unwrap_or(&0);
    for s in 0..total {
        let sample = path_sample(job, camera, pixel, s);
        for (sum, radiance) in sums.iter_mut().zip(method_radiances(job, light, &sample)) {
            *sum += radiance;
        }
        if job.checkpoints.contains(&(s + 1)) {
            means.push(sums.iter().map(|&sum| sum / (s + 1) as f64).collect());
        }
    }
    means
}

/// Renders `job`: rows shared among the threads by their index modulo the thread count.
pub fn render(job: &RenderJob) -> Images {
    let camera = job.scene.camera(job.size);
    let light = scene_light(job.scene);
    let threads = job.threads.max(1) as u32;
    let rows: Vec<Vec<(u32, Vec<PixelMeans>)>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|first| {
                let camera = &camera;
                scope.spawn(move || {
                    (first..job.size.1)
                        .step_by(threads as usize)
                        .map(|y| {
                            let row = (0..job.size.0).map(|x| render_pixel(job, camera, light, (x, y)));
                            (y, row.collect())
                        })
                        .collect()
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a render thread panicked"))
            .collect()
    });
    let mut images = vec![
        vec![vec![DVec3::ZERO; (job.size.0 * job.size.1) as usize]; job.methods.len()];
        job.checkpoints.len()
    ];
    for (y, row) in rows.into_iter().flatten() {
        for (x, pixel) in row.into_iter().enumerate() {
            for (c, per_method) in pixel.into_iter().enumerate() {
                for (m, value) in per_method.into_iter().enumerate() {
                    images[c][m][(y * job.size.0) as usize + x] = value;
                }
            }
        }
    }
    images
}

/// The mean over the pixels and channels of `|a_i - b_i|^2 / 3`.
pub fn mean_squared_difference(a: &[DVec3], b: &[DVec3]) -> f64 {
    let sum: f64 = a.iter().zip(b).map(|(x, y)| (*x - *y).length_squared()).sum();
    sum / (3 * a.len()) as f64
}

/// A method's error at one sample count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorSplit {
    /// `sqrt((mean((A - R)^2) + mean((B - R)^2)) / 2)`.
    pub rmse: f64,
    /// `sqrt(max(bias^2, 0))` with the module doc's `bias^2`.
    pub bias: f64,
    /// `sqrt(var)`, `var = mean((A - B)^2) / 2`.
    pub sd: f64,
}

impl ErrorSplit {
    /// The RMSE an unbiased render with this noise would have against a reference of noise
    /// `reference_noise`: `sqrt(sd^2 + reference_noise^2)` (every RMSE holds the reference's
    /// variance). Of the render that reads the texture's mean past the first hit, the floor.
    pub fn unbiased_rmse(&self, reference_noise: f64) -> f64 {
        self.sd.hypot(reference_noise)
    }
}

/// The split of the module doc for renders `a` and `b` against `reference`, whose own variance
/// is `reference_variance`.
pub fn error_split(a: &[DVec3], b: &[DVec3], reference: &[DVec3], reference_variance: f64) -> ErrorSplit {
    let mse = 0.5 * (mean_squared_difference(a, reference) + mean_squared_difference(b, reference));
    let variance = 0.5 * mean_squared_difference(a, b);
    let average: Vec<DVec3> = a.iter().zip(b).map(|(x, y)| 0.5 * (*x + *y)).collect();
    let bias2 = mean_squared_difference(&average, reference) - 0.5 * variance - reference_variance;
    ErrorSplit {
        rmse: mse.sqrt(),
        bias: bias2.max(0.0).sqrt(),
        sd: variance.sqrt(),
    }
}

/// One scene's errors: `errors[m][c]` for method `m` at checkpoint `c`.
#[derive(Clone, Debug)]
pub struct SceneErrors {
    /// The scene's name.
    pub scene: &'static str,
    /// Its description.
    pub description: &'static str,
    /// The reference's noise `sqrt(var_R)` (RMS over pixels and channels).
    pub reference_noise: f64,
    /// The reference's RMS value, for scale.
    pub reference_rms: f64,
    /// Per method, per checkpoint.
    pub errors: Vec<Vec<ErrorSplit>>,
    /// Seconds the scene took.
    pub seconds: f64,
}

/// What an image run does.
#[derive(Clone, Debug)]
pub struct ImageSettings {
    /// The seed: renders A, B, R1 and R2 use `4 seed`, `4 seed + 1`, `+ 2` and `+ 3`.
    pub seed: u64,
    /// Image size.
    pub size: (u32, u32),
    /// Samples per pixel measured, ascending.
    pub samples: Vec<usize>,
    /// Samples per pixel of each of the two reference renders.
    pub reference_samples: usize,
    /// Whether a render of `n` samples per pixel starts every path from the cone of one of `n`
    /// samples (each count then a render of its own) instead of the pixel's.
    pub sample_spread: bool,
    /// Threads.
    pub threads: usize,
}

/// Renders `scene` with every method twice and the reference twice, and splits the errors.
pub fn measure_image(scene: &Scene, texture: &Texture, settings: &ImageSettings) -> SceneErrors {
    let started = std::time::Instant::now();
    let job = |seed_offset: u64, methods: Vec<ImageMethod>, checkpoints: Vec<usize>| RenderJob {
        scene,
        albedo: Albedo::Textured(texture),
        size: settings.size,
        seed: settings.seed.wrapping_mul(4).wrapping_add(seed_offset),
        methods,
        checkpoints,
        cone_share: 1,
        threads: settings.threads,
    };
    let reference_of = |offset| {
        render(&job(
            offset,
            vec![ImageMethod::Mip0],
            vec![settings.reference_samples],
        ))
        .remove(0)
        .remove(0)
    };
    let (first, second) = (reference_of(2), reference_of(3));
    let reference_variance = 0.25 * mean_squared_difference(&first, &second);
    let reference: Vec<DVec3> = first.iter().zip(&second).map(|(x, y)| 0.5 * (*x + *y)).collect();
    let methods_rendered = |seed_offset: u64| -> Images {
        if !settings.sample_spread {
            return render(&job(seed_offset, image_methods(), settings.samples.clone()));
        }
        settings
            .samples
            .iter()
            .map(|&count| {
                let one = RenderJob {
                    cone_share: count,
                    ..job(seed_offset, image_methods(), vec![count])
                };
                render(&one).remove(0)
            })
            .collect()
    };
    let (a, b) = (methods_rendered(0), methods_rendered(1));
    let errors = (0..image_methods().len())
        .map(|m| {
            (0..settings.samples.len())
                .map(|c| error_split(&a[c][m], &b[c][m], &reference, reference_variance))
                .collect()
        })
        .collect();
    SceneErrors {
        scene: scene.name,
        description: scene.description,
        reference_noise: reference_variance.sqrt(),
        reference_rms: mean_squared_difference(&reference, &vec![DVec3::ZERO; reference.len()]).sqrt(),
        errors,
        seconds: started.elapsed().as_secs_f64(),
    }
}

/// The scene's table: a row per method, a column per sample count, each cell
/// `RMSE (bias / sd)`, the lowest RMSE of a column in bold.
pub fn image_scene_table(errors: &SceneErrors, samples: &[usize]) -> String {
    let mut table = format!(
        "### {}: {}\n\nreference RMS value {:.4}, reference noise {:.5} ({:.1} s)\n\n| method |",
        errors.scene, errors.description, errors.reference_rms, errors.reference_noise, errors.seconds
    );
    for s in samples {
        write!(table, " {s} spp: RMSE (bias / sd) |").unwrap();
    }
    table.push_str("\n|---|");
    table.push_str(&"---:|".repeat(samples.len()));
    for (m, method) in image_methods().iter().enumerate() {
        write!(table, "\n| {} |", method.name()).unwrap();
        for c in 0..samples.len() {
            let best = lowest_rmse(errors, c);
            let cell = errors.errors[m][c];
            let rmse = if cell.rmse == best {
                format!("**{:.5}**", cell.rmse)
            } else {
                format!("{:.5}", cell.rmse)
            };
            write!(table, " {rmse} ({:.5} / {:.5}) |", cell.bias, cell.sd).unwrap();
        }
    }
    table.push('\n');
    table
}

/// Method `m`'s RMSE at checkpoint `c` over mip 0's, averaged over the scenes (each scene counts
/// the same whatever its brightness).
fn mean_ratio_to_mip0(all: &[SceneErrors], m: usize, c: usize) -> f64 {
    let ratios = all.iter().map(|e| e.errors[m][c].rmse / e.errors[0][c].rmse);
    ratios.sum::<f64>() / all.len() as f64
}

/// Whether method `m` has the lowest RMSE of scene `e` at checkpoint `c` ([`lowest_rmse`]).
fn wins(e: &SceneErrors, m: usize, c: usize) -> bool {
    e.errors[m][c].rmse == lowest_rmse(e, c)
}

/// The summary: per sample count, on how many scenes each method has the lowest RMSE (ties count
/// for each), and its RMSE relative to mip 0's averaged over the scenes (`mean_s RMSE_m / RMSE_mip0`),
/// also divided by the lowest such mean among the shipped rules.
pub fn image_summary_table(all: &[SceneErrors], samples: &[usize]) -> String {
    let methods = image_methods();
    let mut table = String::from("### summary over the scenes\n\n| method |");
    for s in samples {
        write!(table, " {s} spp: wins | / best shipped | / mip 0 |").unwrap();
    }
    table.push_str("\n|---|");
    table.push_str(&"---:|---:|---:|".repeat(samples.len()));
    for (m, method) in methods.iter().enumerate() {
        write!(table, "\n| {} |", method.name()).unwrap();
        for c in 0..samples.len() {
            let count = all.iter().filter(|e| wins(e, m, c)).count();
            let best_shipped = (0..methods.len())
                .filter(|&i| methods[i].is_shipped())
                .map(|i| mean_ratio_to_mip0(all, i, c))
                .fold(f64::INFINITY, f64::min);
            let ratio = mean_ratio_to_mip0(all, m, c);
            write!(table, " {count} | {:.3} | {:.3} |", ratio / best_shipped, ratio).unwrap();
        }
    }
    table.push('\n');
    table
}

/// The floor against the shipped rules. The floor of a scene is the RMSE an unbiased render
/// with [`ImageMethod::MeanPastFirstHit`]'s noise would have, `sqrt(sd^2 + var_R)` (every RMSE
/// holds the reference's variance `var_R`). Per sample count: the mean over the scenes of the
/// floor over mip 0's RMSE, the lowest shipped rule's mean RMSE over mip 0's (the summary's), and
/// per scene the floor over the lowest RMSE of a shipped rule there, its mean and its smallest
/// over the scenes. A rule for the later vertices that lowers the error by a fraction `f` from
/// the best shipped one needs that ratio below `1 - f` on the scene.
pub fn noise_floor_table(all: &[SceneErrors], samples: &[usize]) -> String {
    let methods = image_methods();
    let floor = methods
        .iter()
        .position(|&m| m == ImageMethod::MeanPastFirstHit)
        .expect("the floor is measured");
    let shipped: Vec<usize> = (0..methods.len()).filter(|&m| methods[m].is_shipped()).collect();
    let mut rows = [
        String::from("| floor: sqrt(its sd^2 + reference noise^2) / mip 0's RMSE, mean over the scenes |"),
        String::from("| lowest shipped rule: RMSE / mip 0's, mean over the scenes |"),
        String::from("| floor / the scene's lowest shipped RMSE: mean (smallest) |"),
    ];
    let floor_of = |e: &SceneErrors, c: usize| e.errors[floor][c].unbiased_rmse(e.reference_noise);
    for c in 0..samples.len() {
        let floor_over_mip0 = all
            .iter()
            .map(|e| floor_of(e, c) / e.errors[0][c].rmse)
            .sum::<f64>()
            / all.len() as f64;
        let best_shipped = shipped
            .iter()
            .map(|&m| mean_ratio_to_mip0(all, m, c))
            .fold(f64::INFINITY, f64::min);
        let per_scene: Vec<f64> = all
            .iter()
            .map(|e| {
                let lowest = shipped
                    .iter()
                    .map(|&m| e.errors[m][c].rmse)
                    .fold(f64::INFINITY, f64::min);
                floor_of(e, c) / lowest
            })
            .collect();
        let mean = per_scene.iter().sum::<f64>() / per_scene.len() as f64;
        let smallest = per_scene.iter().copied().fold(f64::INFINITY, f64::min);
        write!(rows[0], " {floor_over_mip0:.3} |").unwrap();
        write!(rows[1], " {best_shipped:.3} |").unwrap();
        write!(rows[2], " {mean:.3} ({smallest:.3}) |").unwrap();
    }
    let mut table = String::from("### the floor: the noise no rule past the first hit removes\n\n|  |");
    for s in samples {
        write!(table, " {s} spp |").unwrap();
    }
    table.push_str("\n|---|");
    table.push_str(&"---:|".repeat(samples.len()));
    for row in rows {
        table.push('\n');
        table.push_str(&row);
    }
    table.push('\n');
    table
}

/// The error against samples per pixel, drawn to `path` (PNG): a point per method and sample
/// count at `log2(spp)` across and its RMSE over mip 0's, averaged over the scenes, up (the
/// summary table's "/ mip 0"); the legend names each method without its parenthesis.
pub fn image_error_plot(
    all: &[SceneErrors],
    samples: &[usize],
    path: &std::path::Path,
) -> Result<std::path::PathBuf, LabError> {
    let points = image_methods()
        .iter()
        .enumerate()
        .flat_map(|(m, method)| {
            let name = method.name().split(" (").next().unwrap_or_default().to_string();
            samples.iter().enumerate().map(move |(c, &spp)| ScatterPoint {
                x: (spp as f64).log2(),
                x_spread: None,
                y: mean_ratio_to_mip0(all, m, c),
                method: name.clone(),
                separable: true,
            })
        })
        .collect();
    let panel = ScatterPanel {
        title: format!("RMSE over mip 0's, mean over {} scenes", all.len()),
        points,
    };
    scatter_plot(path, &[panel], ("log2 samples per pixel", "RMSE over mip 0's"))
}

/// A standard normal number from two of `stream`'s (Box-Muller).
#[cfg(test)]
fn normal(stream: &mut Stream) -> f64 {
    let (u1, u2) = (1.0 - stream.next_f64(), stream.next_f64());
    (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paths::sampling::smith_g1;
    use crate::paths::scene::Surface;

    /// A white Lambert floor seen from 2 m above, alone under the environment.
    fn lone_floor() -> Scene {
        Scene {
            name: "lone_floor",
            description: "one diffuse plane under the environment",
            eye: DVec3::new(0.0, 2.0, 0.0),
            target: DVec3::new(0.0, 0.0, -1.0),
            up_hint: DVec3::Y,
            surfaces: vec![Surface::plane(DVec3::ZERO, DVec3::Y, Material::Lambert)],
        }
    }

    /// A Lambert plane of albedo `a` under radiance 1 reflects `L = int (a / pi) 1 cos dw = a`
    /// over the hemisphere, and a path from it escapes after one bounce (a plane cannot meet its
    /// own reflection), with weight `f cos / pdf = (a / pi) cos / (cos / pi) = a` every time:
    /// every sample of a pixel that sees the floor is `a` exactly, one that misses it 1.
    #[test]
    fn lambert_plane_under_constant_environment_renders_its_albedo() {
        let scene = lone_floor();
        let job = RenderJob {
            scene: &scene,
            albedo: Albedo::Constant(0.6),
            size: (24, 16),
            seed: 7,
            methods: image_methods(),
            checkpoints: vec![1, 4],
            cone_share: 1,
            threads: 2,
        };
        let images = render(&job);
        let camera = scene.camera(job.size);
        for (m, image) in images[1].iter().enumerate() {
            for (i, value) in image.iter().enumerate() {
                let (x, y) = ((i as u32 % job.size.0) as f64, (i as u32 / job.size.0) as f64);
                let sees_floor = camera.direction(x, y).y < 0.0 && camera.direction(x + 1.0, y + 1.0).y < 0.0;
                let sees_sky = camera.direction(x, y).y > 0.0 && camera.direction(x + 1.0, y + 1.0).y > 0.0;
                if sees_floor {
                    assert!(
                        (*value - DVec3::splat(0.6)).abs().max_element() < 1e-12,
                        "method {m} pixel {i}: {value}"
                    );
                } else if sees_sky {
                    assert_eq!(*value, DVec3::ONE);
                }
            }
        }
    }

    /// A path started from the cone of one of 16 samples has every vertex's cone width a quarter
    /// of the pixel's cone's, for a rule linear in the width (every vertex a curved mirror): the
    /// spread angles differ by `atan(x) / (4 atan(x / 4)) - 1`, at most `x^2 / 3` in magnitude for
    /// the pixel's `x = 2 tan(fov_y / 2) / H`, plus f32 rounding.
    #[test]
    fn a_sample_cone_is_the_pixel_cone_over_the_root_of_the_samples() {
        let scene = crate::paths::scenes()
            .into_iter()
            .find(|scene| scene.name == "glossy_sphere")
            .expect("the glossy sphere scene");
        let camera = scene.camera((640, 360));
        let pixel = 2.0 * camera.tan_half_fov_y / camera.height;
        let tolerance = pixel * pixel / 3.0 + 1e-5;
        let mut vertices = 0;
        for index in 0..64u64 {
            let numbers = std::array::from_fn(|k| vertex_numbers(11, index, k as u32 + 1));
            let position = (10.0 * index as f64, 5.0 * index as f64 + 0.5);
            let path = trace(&scene, &camera, position, &numbers);
            let whole = method_widths(Method::NoScatteringTerm, &path, &camera);
            let share = method_widths(Method::NoScatteringTerm, &path, &cone_camera(&camera, 16));
            for (k, (whole, share)) in whole.iter().zip(&share).enumerate() {
                let ratio = f64::from(*share) / f64::from(*whole);
                assert!(
                    (4.0 * ratio - 1.0).abs() <= tolerance,
                    "path {index} vertex {k}: {share} against {whole}"
                );
                vertices += 1;
            }
        }
        assert!(vertices > 64, "only {vertices} vertices");
    }

    /// The floor looks the first vertex up at the width every rule gives it, and every later
    /// vertex at the texture's last level, its mean, however grazing the hit.
    #[test]
    fn the_floor_reads_every_rules_first_width_then_the_textures_mean() {
        // A chain of TEXTURE_SIZE^2 texels down to 1 x 1.
        let last_level = f64::from(TEXTURE_SIZE.ilog2());
        let mut later = 0;
        for scene in crate::paths::scenes() {
            let camera = scene.camera((160, 90));
            for index in 0..16u64 {
                let numbers = std::array::from_fn(|k| vertex_numbers(5, index, k as u32 + 1));
                let position = (10.0 * index as f64 + 0.5, 5.0 * index as f64 + 0.5);
                let path = trace(&scene, &camera, position, &numbers);
                let Some(first) = method_widths(Method::NoScatteringTerm, &path, &camera)
                    .first()
                    .copied()
                else {
                    continue;
                };
                for method in METHODS {
                    assert_eq!(
                        method_widths(method, &path, &camera)[0],
                        first,
                        "{}: {method:?}",
                        scene.name
                    );
                }
                for vertex in path.vertices.iter().skip(1) {
                    let level = level_of_detail(BEYOND_ANY_SCENE, vertex);
                    assert!(
                        level >= last_level,
                        "{}: level {level} below the last, {last_level}",
                        scene.name
                    );
                    later += 1;
                }
            }
        }
        assert!(later > 100, "only {later} vertices past the first");
    }

    /// Every measured scene lets light reach the camera: a small render of each, white albedo, has
    /// a mean above 0.05 (a scene closed by two parallel infinite planes renders black, and its
    /// image error would be 0 for every rule).
    #[test]
    fn every_scene_is_lit() {
        for scene in crate::paths::scenes() {
            let job = RenderJob {
                scene: &scene,
                albedo: Albedo::Constant(0.8),
                size: (16, 9),
                seed: 3,
                methods: vec![ImageMethod::Mip0],
                checkpoints: vec![4],
                cone_share: 1,
                threads: 2,
            };
            let image = &render(&job)[0][0];
            let mean = image.iter().map(|value| value.x).sum::<f64>() / image.len() as f64;
            assert!(mean > 0.05, "{}: mean radiance {mean}", scene.name);
        }
    }

    /// The GGX weight against its closed form `G1(i) G1(o) |o . m| / (cos_i cos_m)`, for sampled
    /// directions.
    #[test]
    fn ggx_weight_is_the_masking_over_the_half_vector_terms() {
        let normal = DVec3::Z;
        let incoming = DVec3::new(0.6, 0.0, -0.8);
        let frame = shading_frame(normal, DVec3::X);
        let roughness = 0.4;
        let alpha = roughness * roughness;
        let mut checked = 0;
        for path in 0..200 {
            let numbers = vertex_numbers(3, path, 1);
            let material = Material::Conductor { roughness };
            let Some((_, outgoing)) = sample_material(material, &frame, incoming, numbers) else {
                continue;
            };
            let half = (outgoing - incoming).normalize();
            let (cos_in, cos_out, cos_m) = (-incoming.dot(normal), outgoing.dot(normal), half.dot(normal));
            let expected = smith_g1(alpha, cos_in) * smith_g1(alpha, cos_out) * outgoing.dot(half).abs()
                / (cos_in * cos_m);
            let weight = ggx_weight(roughness, normal, incoming, outgoing);
            assert!(
                (weight - expected).abs() < 1e-12 * expected.max(1.0),
                "{weight} against {expected}"
            );
            checked += 1;
        }
        assert!(checked > 150);
    }

    /// Renders drawn as truth + bias + sd x normal, A and B independent, against the exact truth:
    /// the split recovers the bias and the sd to 2 %.
    #[test]
    fn error_split_recovers_a_known_bias_and_deviation() {
        let (bias, sd) = (0.03, 0.05);
        let mut stream = Stream::new(11, 0, 0);
        let truth: Vec<DVec3> = (0..40_000)
            .map(|_| DVec3::new(stream.next_f64(), stream.next_f64(), stream.next_f64()))
            .collect();
        let noisy = |stream: &mut Stream| -> Vec<DVec3> {
            truth
                .iter()
                .map(|t| {
                    *t + DVec3::splat(bias) + sd * DVec3::new(normal(stream), normal(stream), normal(stream))
                })
                .collect()
        };
        let (a, b) = (noisy(&mut stream), noisy(&mut stream));
        let split = error_split(&a, &b, &truth, 0.0);
        assert!((split.bias / bias - 1.0).abs() < 0.02, "{split:?}");
        assert!((split.sd / sd - 1.0).abs() < 0.02, "{split:?}");
        let expected_rmse = (bias * bias + sd * sd).sqrt();
        assert!((split.rmse / expected_rmse - 1.0).abs() < 0.02, "{split:?}");
        // A noisy reference of known variance: subtracting it recovers the bias again.
        let reference_sd = 0.02;
        let noisy_reference: Vec<DVec3> = truth
            .iter()
            .map(|t| {
                *t + reference_sd * DVec3::new(normal(&mut stream), normal(&mut stream), normal(&mut stream))
            })
            .collect();
        let split = error_split(&a, &b, &noisy_reference, reference_sd * reference_sd);
        assert!((split.bias / bias - 1.0).abs() < 0.03, "{split:?}");
    }
}
