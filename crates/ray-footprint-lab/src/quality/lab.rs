//! A run of the lab: the ground truths (from the cache or rendered), every method's drift
//! frames, and every metric per scene and method.

use super::footprint::{self, Footprints};
use super::image::Image;
use super::metrics::{self, FlipMap};
use super::scenes::{LabScene, Measure, Method};
use super::truth::{self, Truth, TruthSettings};
use super::LabError;
use crate::rt::{Frame, Renderer};
use shader_proptest::Gpu;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// How a run is made.
#[derive(Clone, Debug, PartialEq)]
pub struct LabSettings {
    /// Width and height of every image, in pixels.
    pub size: (u32, u32),
    /// N (ground-truth samples per axis) and K (drift frames).
    pub truth: TruthSettings,
    /// Where ground truths are cached.
    pub cache_dir: PathBuf,
    /// Render every ground truth again, ignoring (and replacing) the cache.
    pub rebuild: bool,
}

/// Receives a run's progress: the number of frames it will render, what it is doing, and one
/// tick per frame rendered.
pub trait Progress {
    /// The run will render `frames` frames in all.
    fn plan(&mut self, frames: u64);
    /// It starts on `what`.
    fn stage(&mut self, what: &str);
    /// It rendered one frame.
    fn tick(&mut self);
}

/// A progress that reports nothing.
pub struct Quiet;

impl Progress for Quiet {
    fn plan(&mut self, _: u64) {}
    fn stage(&mut self, _: &str) {}
    fn tick(&mut self) {}
}

/// What one method scored on one scene.
#[derive(Clone, Debug)]
pub struct MethodResult {
    /// The method.
    pub method: Method,
    /// PSNR of the still frame over the whole image, dB.
    pub psnr: f64,
    /// PSNR of the still frame over the scene's mask, dB.
    pub psnr_mask: f64,
    /// Mean SSIM of the still frame.
    pub ssim: f64,
    /// Mean FLIP error of the still frame.
    pub flip: f64,
    /// Share of the ground truth's fine detail the still frame keeps.
    pub detail: f64,
    /// Mean change from frame to frame over the drift, 8-bit levels.
    pub change: f64,
    /// `change` minus the ground truth's: the shimmer the reference does not have.
    pub shimmer: f64,
    /// Median trace time per frame over the drift, milliseconds.
    pub ms_per_frame: f64,
    /// The still frame.
    pub frame: Image,
    /// The still frame's FLIP error map.
    pub flip_map: FlipMap,
}

/// A scene's ground truth and every method's result.
#[derive(Clone, Debug)]
pub struct SceneResult {
    /// The scene.
    pub scene: LabScene,
    /// The ground truth's still image.
    pub truth: Image,
    /// The ground truth's mean change from frame to frame, 8-bit levels.
    pub truth_change: f64,
    /// Whether the ground truth came from the cache.
    pub truth_cached: bool,
    /// Time spent rendering the ground truth (0 when cached).
    pub truth_time: Duration,
    /// Per pixel: whether it is in the scene's mask.
    pub mask: Vec<bool>,
    /// On a texture scene, the cones' footprints against the ray differential's over the mask
    /// (still frame's records); `None` on the wireframe scene, or where no pixel could be
    /// compared.
    pub footprints: Option<Footprints>,
    /// The methods, the baseline first.
    pub methods: Vec<MethodResult>,
}

impl SceneResult {
    /// The baseline's result (mip 0; the hard lines on the wireframe scene).
    pub fn baseline(&self) -> &MethodResult {
        &self.methods[0]
    }

    /// The result of the method called `name`.
    pub fn method(&self, name: &str) -> Option<&MethodResult> {
        self.methods.iter().find(|m| m.method.name == name)
    }
}

/// A finished run.
#[derive(Clone, Debug)]
pub struct LabRun {
    /// The device's name.
    pub device: String,
    /// How it was made.
    pub settings: LabSettings,
    /// Per scene, in order.
    pub scenes: Vec<SceneResult>,
}

/// A scene's ground truth, where it is cached, and the cached copy if there is a valid one.
struct Planned {
    scene: LabScene,
    path: PathBuf,
    cached: Option<Truth>,
}

/// Runs the lab on `scenes`: loads or renders each ground truth (N x N samples per pixel over
/// K drift frames, caching what it renders), renders every method K times along the drift, and
/// computes every metric. Reports progress to `progress`.
pub fn run(
    gpu: &Gpu,
    scenes: &[LabScene],
    settings: &LabSettings,
    progress: &mut dyn Progress,
) -> Result<LabRun, LabError> {
    check(settings)?;
    let device = gpu.name().to_string();
    let mut plans = Vec::new();
    for scene in scenes {
        let key = truth::truth_key(scene, settings.size, settings.truth, &device)?;
        let path = truth::cache_path(&settings.cache_dir, scene, settings.size, settings.truth, key);
        let cached = (!settings.rebuild)
            .then(|| truth::load(&path, settings.size, settings.truth.frames))
            .flatten();
        plans.push(Planned {
            scene: scene.clone(),
            path,
            cached,
        });
    }
    let frames_per_method = u64::from(settings.truth.frames);
    let total = plans
        .iter()
        .map(|p| {
            let truth = if p.cached.is_some() {
                0
            } else {
                truth::sample_count(settings.truth)
            };
            truth + p.scene.methods().len() as u64 * frames_per_method
        })
        .sum();
    progress.plan(total);
    let mut results = Vec::new();
    for plan in plans {
        results.push(run_scene(gpu, plan, settings, progress)?);
    }
    Ok(LabRun {
        device,
        settings: settings.clone(),
        scenes: results,
    })
}

/// Fails with [`LabError::Settings`] unless N >= 1, K >= 2 (a change from frame to frame needs
/// two frames) and the image is at least the SSIM window in each direction.
fn check(settings: &LabSettings) -> Result<(), LabError> {
    let window = metrics::WINDOW as u32;
    let (n, k) = (settings.truth.samples_per_axis, settings.truth.frames);
    if n < 1 {
        return Err(LabError::Settings(format!(
            "samples_per_axis is {n}, at least 1 is needed"
        )));
    }
    if k < 2 {
        return Err(LabError::Settings(format!(
            "frames is {k}, at least 2 are needed"
        )));
    }
    if settings.size.0 < window || settings.size.1 < window {
        let (w, h) = settings.size;
        return Err(LabError::Settings(format!(
            "size is {w} x {h}, at least {window} x {window} is needed"
        )));
    }
    Ok(())
}

/// One scene: its renderer, ground truth and methods.
fn run_scene(
    gpu: &Gpu,
    plan: Planned,
    settings: &LabSettings,
    progress: &mut dyn Progress,
) -> Result<SceneResult, LabError> {
    let lab = plan.scene;
    let renderer = Renderer::with_texture(gpu, lab.scene.clone(), lab.texture.clone())?;
    let truth_cached = plan.cached.is_some();
    let started = Instant::now();
    let truth = match plan.cached {
        Some(truth) => truth,
        None => {
            let n = settings.truth.samples_per_axis;
            progress.stage(&format!(
                "{}: ground truth, {n} x {n} samples per pixel",
                lab.name
            ));
            let truth = truth::render_truth(&renderer, &lab, settings.size, settings.truth, &mut || {
                progress.tick()
            })?;
            truth::save(&plan.path, &truth)?;
            truth
        }
    };
    let truth_time = if truth_cached {
        Duration::ZERO
    } else {
        started.elapsed()
    };
    let truth_change = metrics::mean_change(&truth.frames)?;
    let still = &truth.frames[0];
    let mut mask = Vec::new();
    let mut footprints = None;
    let mut methods = Vec::new();
    for method in lab.methods() {
        progress.stage(&format!("{}: {}", lab.name, method.name));
        let frames = drift_frames(&renderer, &lab, &method, settings, progress)?;
        if mask.is_empty() {
            mask = frames[0].records.iter().map(|r| lab.mask.contains(r)).collect();
            if lab.measure == Measure::Texture {
                footprints = footprint::footprints(&frames[0].records, &mask);
            }
        }
        methods.push(score(method, still, &frames, &mask, truth_change)?);
    }
    Ok(SceneResult {
        truth: still.clone(),
        scene: lab,
        truth_change,
        truth_cached,
        truth_time,
        mask,
        footprints,
        methods,
    })
}

/// `method` rendered at one sample per pixel in every frame of the drift.
fn drift_frames(
    renderer: &Renderer<'_>,
    lab: &LabScene,
    method: &Method,
    settings: &LabSettings,
    progress: &mut dyn Progress,
) -> Result<Vec<Frame>, LabError> {
    (0..settings.truth.frames)
        .map(|k| {
            let frame = truth::render(
                renderer,
                lab,
                method,
                settings.size,
                truth::drift(settings.truth, k),
            );
            progress.tick();
            frame
        })
        .collect()
}

/// Every metric of `method`'s drift frames against the ground truth's still image (`truth`).
fn score(
    method: Method,
    truth: &Image,
    frames: &[Frame],
    mask: &[bool],
    truth_change: f64,
) -> Result<MethodResult, LabError> {
    let images: Vec<Image> = frames.iter().map(Image::from_frame).collect();
    let still = &images[0];
    let change = metrics::mean_change(&images)?;
    let flip_map = metrics::flip(truth, still)?;
    let mut times: Vec<Duration> = frames.iter().map(|f| f.trace_time).collect();
    times.sort();
    Ok(MethodResult {
        method,
        psnr: metrics::psnr(truth, still, None)?,
        psnr_mask: metrics::psnr(truth, still, Some(mask))?,
        ssim: metrics::ssim(truth, still)?,
        flip: flip_map.mean(),
        detail: metrics::detail_kept(truth, still)?,
        change,
        shimmer: change - truth_change,
        ms_per_frame: times[times.len() / 2].as_secs_f64() * 1e3,
        frame: still.clone(),
        flip_map,
    })
}

/// PSNR of each method's still frame against the ground truth with N and with 2N samples per
/// axis, to show the truth has converged.
#[derive(Clone, Debug)]
pub struct Convergence {
    /// Scene name.
    pub scene: &'static str,
    /// Method name.
    pub method: String,
    /// Against N x N samples: whole image and mask, dB.
    pub psnr_n: (f64, f64),
    /// Against 2N x 2N samples: whole image and mask, dB.
    pub psnr_2n: (f64, f64),
}

/// Renders (or loads) the still ground truth of every scene of `run` with twice its N per axis
/// and scores each method's still frame against both truths.
pub fn convergence(
    gpu: &Gpu,
    run: &LabRun,
    progress: &mut dyn Progress,
) -> Result<Vec<Convergence>, LabError> {
    let doubled = TruthSettings {
        samples_per_axis: 2 * run.settings.truth.samples_per_axis,
        frames: 1,
    };
    let settings = &run.settings;
    let mut plans = Vec::new();
    for result in &run.scenes {
        let key = truth::truth_key(&result.scene, settings.size, doubled, &run.device)?;
        let path = truth::cache_path(&settings.cache_dir, &result.scene, settings.size, doubled, key);
        let cached = (!settings.rebuild)
            .then(|| truth::load(&path, settings.size, 1))
            .flatten();
        plans.push((path, cached));
    }
    let missing = plans.iter().filter(|(_, cached)| cached.is_none()).count() as u64;
    progress.plan(missing * truth::sample_count(doubled));
    let mut rows = Vec::new();
    for (result, (path, cached)) in run.scenes.iter().zip(plans) {
        let fine = match cached {
            Some(truth) => truth,
            None => {
                let lab = &result.scene;
                let n = doubled.samples_per_axis;
                progress.stage(&format!(
                    "{}: ground truth, {n} x {n} samples per pixel",
                    lab.name
                ));
                let renderer = Renderer::with_texture(gpu, lab.scene.clone(), lab.texture.clone())?;
                let truth =
                    truth::render_truth(&renderer, lab, settings.size, doubled, &mut || progress.tick())?;
                truth::save(&path, &truth)?;
                truth
            }
        };
        for method in &result.methods {
            let score = |truth: &Image| -> Result<(f64, f64), LabError> {
                Ok((
                    metrics::psnr(truth, &method.frame, None)?,
                    metrics::psnr(truth, &method.frame, Some(&result.mask))?,
                ))
            };
            rows.push(Convergence {
                scene: result.scene.name,
                method: method.method.name.clone(),
                psnr_n: score(&result.truth)?,
                psnr_2n: score(&fine.frames[0])?,
            });
        }
    }
    Ok(rows)
}
