//! The image error of every path mode of the ray-tracing renderer, on the GPU: per scene of the
//! quality lab and path mode, the RMSE against a reference rendered by `path_mip0` with many
//! samples, at equal samples per pixel and at equal GPU time, split into bias and noise as
//! `ray_footprint_lab::paths::image` splits the CPU renders (two renders `A`, `B` of independent
//! seeds; the reference the mean of two renders `R1`, `R2`).
//!
//! A sample is one frame of the mode's colour-only pipeline at a sub-pixel offset drawn from the
//! seed's stream; the renderer draws every path's random numbers from the pixel and that offset,
//! so each stream is a different set of paths and every mode of one stream traces the same ones.
//! The frames' RGBA8 colours (gamma 2.2) are taken back to linear light and averaged. Equal time:
//! each path mode's frame is timed in interleaved rounds (`Renderer::time_colour_frames`, the
//! order reversed every other round, after warm-up rounds until two agree within 2%), and a mode
//! gets `floor(64 x path_mip0's frame / its frame)` samples where `path_mip0` gets 64.
//!
//! ```text
//! cargo run --release -p ray-footprint-lab --example path_image_gpu -- \
//!     [--seed N] [--size WxH] [--reference-spp N] [--texture-size N] [--scene NAME|all] [--crops DIR] \
//!     [--biases B,B,..] [--spread pixel|sample]
//! ```
//!
//! With `--crops DIR`, each scene's crop (the quality lab's) of the reference and of every mode's
//! render `A` at 64 samples per pixel, captioned with the mode and its RMSE at 64 samples, side by
//! side in `DIR/<scene>.png`.
//!
//! With `--biases`, `path_bias` is also rendered at each of the listed level-of-detail biases
//! (`RtPushConstants::lod_bias`, in mip levels, added past the first hit) at equal samples, and
//! the summary gives each bias' RMSE and noise over `path_mip0`'s RMSE, and per scene beside the
//! lowest mode's: the sweep that picks `ray_footprint_lab::rt::PATH_LOD_BIAS` (its doc names the
//! command). A bias of +20 reads the texture's mean past the first hit, and its noise estimates
//! the floor no rule for the later hits gets below.
//!
//! With `--spread sample`, every mode's render of `n` samples per pixel starts from the cone of
//! one sample instead of the pixel's: the pixel's spread angle over `sqrt(n)`, the side of the
//! pixel's share each of `n` samples stands for (pbrt scales its camera rays' differentials so:
//! `1 / sqrt(spp)`, floored at 1/8 in pbrt-v4). Each count is then a render of its own, the
//! frames are timed at the cone of one of 64 samples, and `--biases` renders follow it too.
//!
//! With `--offsets pixel`, each pixel of a frame samples a sub-pixel position of its own, drawn
//! from the frame's offset and the pixel (`FLAG_PIXEL_JITTER`), instead of every pixel sampling at
//! the frame's offset (`frame`, the default). One offset per frame makes a frame's texture error
//! the same function of it at every pixel, so that the bias and noise of a render of 64 frames do
//! not separate: `path_mip0`, unbiased, then reads a bias of up to 0.0096.

use glam::DVec3;
use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_lab::cli::{
    command_options, example_command, image_size, lod_biases, options_or_exit, positive_count, sample_spread,
    seed,
};
use ray_footprint_lab::figure::{grid, write_png, Panel, RgbaImage};
use ray_footprint_lab::paths::image::{error_split, mean_squared_difference, ErrorSplit};
use ray_footprint_lab::quality::{LabScene, Measure};
use ray_footprint_lab::rt::abi::{RtPushConstants, RtUniforms, FLAG_PIXEL_JITTER};
use ray_footprint_lab::rt::{enlarged, open_device, ColourPipeline, Mode, Renderer, Timed, PATH_LOD_BIAS};
use ray_footprint_lab::timing::{gpu_clocks, median, warm_up, Spread};
use std::path::PathBuf;
use std::time::Instant;

/// The default seed.
const DEFAULT_SEED: u64 = 1;
/// The default image size.
const DEFAULT_SIZE: (u32, u32) = (160, 90);
/// The default samples per pixel of each reference render.
const DEFAULT_REFERENCE_SAMPLES: usize = 256;
/// Samples per pixel measured at equal samples.
const SAMPLES: [usize; 3] = [4, 16, 64];
/// `path_mip0`'s samples per pixel at equal time.
const EQUAL_TIME_SAMPLES: usize = 64;
/// Timed rounds, frames of each mode per round, and the most warm-up rounds.
const ROUNDS: usize = 8;
const FRAMES_PER_ROUND: usize = 32;
const MAX_WARM_UP_ROUNDS: usize = 20;

/// The path modes, in `Mode::ALL`'s order: `path_mip0` first.
fn path_modes() -> Vec<Mode> {
    Mode::ALL.into_iter().filter(|mode| mode.traces_paths()).collect()
}

struct Options {
    seed: u64,
    size: (u32, u32),
    reference_samples: usize,
    texture_size: Option<u32>,
    scenes: Vec<LabScene>,
    /// Where the captioned crops go, if anywhere.
    crops: Option<PathBuf>,
    /// The biases `path_bias` is also rendered at, in mip levels (none by default).
    biases: Vec<f32>,
    /// Whether a render of `n` samples starts from one sample's cone (`--spread sample`) or from
    /// the pixel's (`pixel`).
    sample_spread: bool,
    /// Whether each pixel of a frame samples an offset of its own (`--offsets pixel`,
    /// [`FLAG_PIXEL_JITTER`]) or every pixel the frame's (`frame`).
    pixel_offsets: bool,
}

fn usage() -> String {
    format!(
        "usage: path_image_gpu [--seed N] [--size WxH] [--reference-spp N] [--texture-size N] [--scene NAME|all] \
         [--crops DIR] [--biases B,B,..] [--spread pixel|sample] [--offsets frame|pixel]\n\
         defaults: --seed {DEFAULT_SEED} --size {}x{} --reference-spp {DEFAULT_REFERENCE_SAMPLES} --scene all --spread pixel \
         --offsets frame, \
         each scene's own texture",
        DEFAULT_SIZE.0, DEFAULT_SIZE.1
    )
}

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        seed: DEFAULT_SEED,
        size: DEFAULT_SIZE,
        reference_samples: DEFAULT_REFERENCE_SAMPLES,
        texture_size: None,
        scenes: texture_scenes(LabScene::all()),
        crops: None,
        biases: Vec::new(),
        sample_spread: false,
        pixel_offsets: false,
    };
    for (flag, value) in command_options(args)? {
        match flag.as_str() {
            "--seed" => options.seed = seed(&flag, &value)?,
            "--size" => options.size = image_size(&flag, &value)?,
            "--reference-spp" => options.reference_samples = positive_count(&flag, &value)?,
            "--texture-size" => {
                let size = positive_count(&flag, &value)?;
                if !size.is_power_of_two() || size > 1 << 15 {
                    return Err(format!("{flag} {value}: expected a power of two up to 32768"));
                }
                options.texture_size = Some(size as u32);
            }
            "--crops" => options.crops = Some(PathBuf::from(value)),
            "--biases" => options.biases = lod_biases(&flag, &value)?,
            "--spread" => options.sample_spread = sample_spread(&flag, &value)?,
            "--offsets" => options.pixel_offsets = pixel_offsets(&flag, &value)?,
            "--scene" if value == "all" => options.scenes = texture_scenes(LabScene::all()),
            "--scene" => {
                options.scenes = texture_scenes(LabScene::all())
                    .into_iter()
                    .filter(|scene| scene.name == value)
                    .collect();
                if options.scenes.is_empty() {
                    return Err(format!("--scene {value}: no such scene with a texture"));
                }
            }
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(options)
}

/// `value` of the option `flag` (`--offsets`) as whether each pixel samples an offset of its own.
fn pixel_offsets(flag: &str, value: &str) -> Result<bool, String> {
    match value {
        "frame" => Ok(false),
        "pixel" => Ok(true),
        _ => Err(format!("{flag} must be frame or pixel, got '{value}'")),
    }
}

/// The scenes that measure a texture (the wireframe's torus draws lines).
fn texture_scenes(scenes: Vec<LabScene>) -> Vec<LabScene> {
    scenes
        .into_iter()
        .filter(|scene| matches!(scene.measure, Measure::Texture))
        .collect()
}

/// SplitMix64: the `index`-th number of stream `stream`.
fn splitmix(stream: u64, index: u64) -> u64 {
    let mut z = stream.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ index.wrapping_add(0x632b_e59b_d9b4_e8f5);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The push constants of sample `index` of stream `stream`: a sub-pixel offset in [-0.5, 0.5)^2.
fn sample_push(base: &RtPushConstants, stream: u64, index: usize) -> RtPushConstants {
    let bits = splitmix(stream, index as u64);
    let unit = |word: u64| (word & 0xff_ffff) as f32 / 16_777_216.0 - 0.5;
    let mut push = *base;
    push.pixel_offset = glam::Vec2::new(unit(bits), unit(bits >> 32));
    push
}

/// The mean of `checkpoints.last()` samples of `pipeline` from stream `stream`, in linear light,
/// taken at every count of `checkpoints` (ascending).
fn render_means(
    pipeline: &ColourPipeline<'_, '_>,
    base: &RtPushConstants,
    uniforms: &RtUniforms,
    stream: u64,
    checkpoints: &[usize],
) -> Result<Vec<Vec<DVec3>>, String> {
    let linear: Vec<f64> = (0..256).map(|v| (f64::from(v) / 255.0).powf(2.2)).collect();
    let pixels = (base.width * base.height) as usize;
    let mut sum = vec![DVec3::ZERO; pixels];
    let mut means = Vec::with_capacity(checkpoints.len());
    let last = checkpoints.last().copied().unwrap_or(0);
    for index in 0..last {
        let frame = pipeline
            .render(&sample_push(base, stream, index), uniforms)
            .map_err(|error| error.to_string())?;
        for (total, pixel) in sum.iter_mut().zip(&frame.pixels) {
            *total += DVec3::new(
                linear[pixel[0] as usize],
                linear[pixel[1] as usize],
                linear[pixel[2] as usize],
            );
        }
        let count = index + 1;
        if checkpoints.contains(&count) {
            means.push(sum.iter().map(|total| *total / count as f64).collect());
        }
    }
    Ok(means)
}

/// Each pipeline's frame time in ms, the spread of its [`ROUNDS`] round medians, after warm-up
/// rounds until two successive ones agree within 2% (at most [`MAX_WARM_UP_ROUNDS`]).
fn frame_times(
    renderer: &Renderer<'_>,
    pipelines: &[ColourPipeline<'_, '_>],
    base: &RtPushConstants,
    uniforms: &RtUniforms,
) -> Result<Vec<Spread>, String> {
    let samples = std::slice::from_ref(base);
    let timed: Vec<Timed<'_, '_, '_>> = pipelines.iter().map(|pipeline| (pipeline, samples)).collect();
    let round = |number: usize| {
        renderer
            .time_colour_round(&timed, uniforms, (FRAMES_PER_ROUND, number))
            .map_err(|error| error.to_string())
    };
    warm_up(MAX_WARM_UP_ROUNDS, || round(0).map(|medians| median(&medians)))?;
    let mut medians = vec![Vec::with_capacity(ROUNDS); pipelines.len()];
    for number in 0..ROUNDS {
        for (mode_medians, value) in medians.iter_mut().zip(round(number)?) {
            mode_medians.push(value);
        }
    }
    Ok(medians.iter().map(|m| Spread::of(m)).collect())
}

/// The reference: the mean of two renders of independent streams, and its variance per value.
struct Reference {
    mean: Vec<DVec3>,
    variance: f64,
}

/// `push` with the primary cone of one of `count` samples: the pixel's spread angle over
/// `sqrt(count)`.
fn one_sample_cone(push: &RtPushConstants, count: usize) -> RtPushConstants {
    let mut sample = *push;
    sample.cone.pixel_spread_angle /= (count as f32).sqrt();
    sample
}

/// [`split_renders`] with each count of `checkpoints` rendered on its own, its primary cone's
/// spread angle the pixel's over `sqrt(count)`: the cone of one of `count` samples.
fn split_renders_at_sample_spread(
    pipeline: &ColourPipeline<'_, '_>,
    (push, uniforms): (&RtPushConstants, &RtUniforms),
    streams: [u64; 2],
    checkpoints: &[usize],
    reference: &Reference,
) -> Result<(Vec<Vec<DVec3>>, Vec<ErrorSplit>), String> {
    let mut means = Vec::with_capacity(checkpoints.len());
    let mut splits = Vec::with_capacity(checkpoints.len());
    for &count in checkpoints {
        let sample = one_sample_cone(push, count);
        let (a, split) = split_renders(pipeline, (&sample, uniforms), streams, &[count], reference)?;
        means.extend(a);
        splits.extend(split);
    }
    Ok((means, splits))
}

/// Renders `A` and `B` of `pipeline` (streams `streams`) at every count of `checkpoints`
/// (ascending) and splits each pair's error against `reference`: render `A`'s means and the
/// splits, in the order of `checkpoints`.
fn split_renders(
    pipeline: &ColourPipeline<'_, '_>,
    (push, uniforms): (&RtPushConstants, &RtUniforms),
    streams: [u64; 2],
    checkpoints: &[usize],
    reference: &Reference,
) -> Result<(Vec<Vec<DVec3>>, Vec<ErrorSplit>), String> {
    let a = render_means(pipeline, push, uniforms, streams[0], checkpoints)?;
    let b = render_means(pipeline, push, uniforms, streams[1], checkpoints)?;
    let splits = a
        .iter()
        .zip(&b)
        .map(|(a, b)| error_split(a, b, &reference.mean, reference.variance))
        .collect();
    Ok((a, splits))
}

/// One scene's results: every path mode's, and `path_bias`' at each bias of `--biases` at
/// [`SAMPLES`].
struct SceneResult {
    name: &'static str,
    /// The averaged reference's noise, inside every RMSE.
    reference_noise: f64,
    modes: Vec<ModeResult>,
    sweep: Vec<Vec<ErrorSplit>>,
}

/// One mode's results on one scene.
struct ModeResult {
    mode: Mode,
    frame: Spread,
    /// At each count of [`SAMPLES`].
    equal_samples: Vec<ErrorSplit>,
    equal_time_samples: usize,
    equal_time: ErrorSplit,
}

/// Measures every path mode on `scene`, and `path_bias` at each of `options.biases`; prints its
/// table and returns the results.
fn measure_scene(
    gpu: &shader_proptest::Gpu,
    scene: &LabScene,
    options: &Options,
) -> Result<SceneResult, String> {
    let started = Instant::now();
    let texture = match options.texture_size {
        Some(size) => enlarged(&scene.texture, size),
        None => scene.texture.clone(),
    };
    let renderer = Renderer::with_texture(gpu, scene.scene.clone(), texture).map_err(|e| e.to_string())?;
    let pipelines = path_modes()
        .into_iter()
        .map(|mode| renderer.colour_pipeline(mode))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    let (width, height) = options.size;
    let mut base = renderer.push_constants(&scene.camera, Mode::PathMip0, 1.0, width, height);
    base.flags = scene.truth_flags
        | if options.pixel_offsets {
            FLAG_PIXEL_JITTER
        } else {
            0
        };
    let uniforms = scene.camera.uniforms(options.size, WireframeSettings::default());
    let timed = if options.sample_spread {
        one_sample_cone(&base, EQUAL_TIME_SAMPLES)
    } else {
        base
    };
    let frames = frame_times(&renderer, &pipelines, &timed, &uniforms)?;
    let renders = [4 * options.seed, 4 * options.seed + 1];
    let reference_count = [options.reference_samples];
    let r1 = render_means(
        &pipelines[0],
        &base,
        &uniforms,
        4 * options.seed + 2,
        &reference_count,
    )?
    .remove(0);
    let r2 = render_means(
        &pipelines[0],
        &base,
        &uniforms,
        4 * options.seed + 3,
        &reference_count,
    )?
    .remove(0);
    let reference = Reference {
        mean: r1.iter().zip(&r2).map(|(a, b)| 0.5 * (*a + *b)).collect(),
        variance: mean_squared_difference(&r1, &r2) / 4.0,
    };
    let render = if options.sample_spread {
        split_renders_at_sample_spread
    } else {
        split_renders
    };
    let mut results = Vec::new();
    let crop = |image: &[DVec3]| crop_of(image, options.size, scene.crop);
    let mut panels = vec![Panel::new(
        format!("reference (path_mip0, 2 x {} spp)", options.reference_samples),
        crop(&reference.mean),
    )];
    for (pipeline, frame) in pipelines.iter().zip(&frames) {
        let equal_time_samples =
            ((EQUAL_TIME_SAMPLES as f64 * frames[0].median / frame.median) as usize).max(1);
        let mut checkpoints: Vec<usize> = SAMPLES.iter().copied().chain([equal_time_samples]).collect();
        checkpoints.sort_unstable();
        checkpoints.dedup();
        let (a, splits) = render(pipeline, (&base, &uniforms), renders, &checkpoints, &reference)?;
        let at = |count: usize| {
            checkpoints
                .iter()
                .position(|&c| c == count)
                .expect("a checkpoint")
        };
        let split_at = |count: usize| splits[at(count)];
        let most = SAMPLES[SAMPLES.len() - 1];
        panels.push(Panel::new(
            format!("{}, 64 spp: RMSE {:.4}", pipeline.mode(), split_at(most).rmse),
            crop(&a[at(most)]),
        ));
        results.push(ModeResult {
            mode: pipeline.mode(),
            frame: *frame,
            equal_samples: SAMPLES.iter().map(|&count| split_at(count)).collect(),
            equal_time_samples,
            equal_time: split_at(equal_time_samples),
        });
    }
    if let Some(dir) = &options.crops {
        write_crops(dir, scene.name, panels)?;
    }
    let biased = pipelines
        .iter()
        .find(|pipeline| pipeline.mode() == Mode::PathBias)
        .expect("path_bias is a path mode");
    let mut sweep = Vec::with_capacity(options.biases.len());
    for &lod_bias in &options.biases {
        let push = RtPushConstants { lod_bias, ..base };
        sweep.push(render(biased, (&push, &uniforms), renders, &SAMPLES, &reference)?.1);
    }
    print_scene(
        scene,
        &results,
        reference.variance.sqrt(),
        started.elapsed().as_secs_f64(),
    );
    Ok(SceneResult {
        name: scene.name,
        reference_noise: reference.variance.sqrt(),
        modes: results,
        sweep,
    })
}

/// The part `fraction` (left, top, width, height of the image) of the linear image `image` of
/// `size`, as RGBA8 at gamma 2.2.
fn crop_of(image: &[DVec3], (width, height): (u32, u32), fraction: [f32; 4]) -> RgbaImage {
    let encode = |value: f64| (value.clamp(0.0, 1.0).powf(1.0 / 2.2) * 255.0).round() as u8;
    let full = RgbaImage {
        width,
        height,
        pixels: image
            .iter()
            .map(|c| [encode(c.x), encode(c.y), encode(c.z), 255])
            .collect(),
    };
    full.crop_part(fraction, 1)
}

/// The panels in rows of four, to `dir/<scene>.png`.
fn write_crops(dir: &std::path::Path, scene: &str, panels: Vec<Panel>) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|error| format!("creating {}: {error}", dir.display()))?;
    let rows: Vec<Vec<Panel>> = panels.chunks(4).map(<[Panel]>::to_vec).collect();
    let figure = grid(&rows).map_err(|error| error.to_string())?;
    let path = dir.join(format!("{scene}.png"));
    write_png(&path, &figure).map_err(|error| error.to_string())?;
    println!("wrote {}", path.display());
    Ok(())
}

fn print_scene(scene: &LabScene, results: &[ModeResult], reference_noise: f64, seconds: f64) {
    println!("\n### {}: {}\n", scene.name, scene.description);
    println!("reference noise {reference_noise:.5}; {seconds:.1} s\n");
    println!(
        "| mode | frame ms (rounds) | 4 / 16 / 64 spp: RMSE | 64 spp: bias / sd | equal time: spp, RMSE |"
    );
    println!("| --- | ---: | ---: | ---: | ---: |");
    for result in results {
        let rmse: Vec<String> = result
            .equal_samples
            .iter()
            .map(|e| format!("{:.5}", e.rmse))
            .collect();
        let at_64 = result.equal_samples[SAMPLES.len() - 1];
        println!(
            "| {} | {:.3} ({:.3} to {:.3}) | {} | {:.5} / {:.5} | {}, {:.5} |",
            result.mode,
            result.frame.median,
            result.frame.min,
            result.frame.max,
            rmse.join(" / "),
            at_64.bias,
            at_64.sd,
            result.equal_time_samples,
            result.equal_time.rmse
        );
    }
}

/// The mean over the scenes of each mode's RMSE over `path_mip0`'s, at each sample count and at
/// equal time, and the scenes where the mode's RMSE is the lowest at 64 samples and at equal time.
fn print_summary(all: &[SceneResult]) {
    println!("\n## Over the scenes\n");
    println!("| mode | RMSE / path_mip0's: 4 / 16 / 64 spp | equal time | lowest at 64 spp | lowest at equal time |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    let count = all.len() as f64;
    for (m, mode) in path_modes().iter().enumerate() {
        let ratio = |value: &dyn Fn(&ModeResult) -> f64| {
            all.iter()
                .map(|scene| value(&scene.modes[m]) / value(&scene.modes[0]))
                .sum::<f64>()
                / count
        };
        let ratios: Vec<String> = (0..SAMPLES.len())
            .map(|c| format!("{:.3}", ratio(&|r: &ModeResult| r.equal_samples[c].rmse)))
            .collect();
        let lowest = |value: &dyn Fn(&ModeResult) -> f64| {
            all.iter()
                .filter(|scene| {
                    scene
                        .modes
                        .iter()
                        .all(|other| value(&scene.modes[m]) <= value(other))
                })
                .count()
        };
        println!(
            "| {mode} | {} | {:.3} | {} of {} | {} of {} |",
            ratios.join(" / "),
            ratio(&|r: &ModeResult| r.equal_time.rmse),
            lowest(&|r: &ModeResult| r.equal_samples[SAMPLES.len() - 1].rmse),
            all.len(),
            lowest(&|r: &ModeResult| r.equal_time.rmse),
            all.len()
        );
    }
}

/// The sweep of `path_bias`' bias: per bias, the mean over the scenes of its RMSE and of its
/// noise over `path_mip0`'s RMSE at each sample count, and the bias with the lowest mean RMSE at
/// 64 samples; then per scene each bias' RMSE and sd at each count beside the reference's noise
/// and the lowest RMSE of the path modes. The noise is `sqrt(sd^2 + reference noise^2)`, the RMSE
/// of an unbiased render with that sd (every RMSE holds the reference's noise).
///
/// A bias beyond the texture's levels (+20) reads every lookup past the first hit at the last
/// level, the texture's mean: what remains is the noise of the light's paths and of the first
/// hit's lookups, which every mode shares. Its noise estimates the floor below which no rule for
/// the later hits can bring the RMSE.
fn print_sweep(all: &[SceneResult], biases: &[f32]) {
    if biases.is_empty() {
        return;
    }
    println!("\n## path_bias' bias, swept\n");
    println!(
        "| bias (mip levels, past the first hit) | RMSE / path_mip0's: 4 / 16 / 64 spp | sqrt(sd^2 + reference noise^2) / path_mip0's RMSE |"
    );
    println!("| ---: | ---: | ---: |");
    let mean_over_mip0 = |b: usize, c: usize, value: fn(&SceneResult, &ErrorSplit) -> f64| {
        all.iter()
            .map(|scene| value(scene, &scene.sweep[b][c]) / scene.modes[0].equal_samples[c].rmse)
            .sum::<f64>()
            / all.len() as f64
    };
    let ratio = |b: usize, c: usize| mean_over_mip0(b, c, |_, split| split.rmse);
    let most = SAMPLES.len() - 1;
    for (b, bias) in biases.iter().enumerate() {
        let cells = |value: fn(&SceneResult, &ErrorSplit) -> f64| {
            let cells: Vec<String> = (0..SAMPLES.len())
                .map(|c| format!("{:.3}", mean_over_mip0(b, c, value)))
                .collect();
            cells.join(" / ")
        };
        println!(
            "| {bias:+.2} | {} | {} |",
            cells(|_, split| split.rmse),
            cells(|scene, split| split.unbiased_rmse(scene.reference_noise))
        );
    }
    let best = (0..biases.len())
        .min_by(|&x, &y| ratio(x, most).total_cmp(&ratio(y, most)))
        .expect("a bias");
    println!(
        "\nlowest at {} spp: bias {:+.2} ({:.3} of path_mip0's RMSE)",
        SAMPLES[most],
        biases[best],
        ratio(best, most)
    );
    print_sweep_scenes(all, biases);
}

/// Per scene: the reference's noise, the lowest RMSE of the path modes, and each bias' RMSE (sd)
/// and its noise `sqrt(sd^2 + reference noise^2)` over that lowest RMSE, at 4 / 16 / 64 samples.
fn print_sweep_scenes(all: &[SceneResult], biases: &[f32]) {
    print!("\n| scene | reference noise | lowest mode's RMSE: 4 / 16 / 64 spp |");
    for bias in biases {
        print!(" bias {bias:+.2}: RMSE (sd) | its noise / the lowest RMSE |");
    }
    println!("\n| --- | ---: | ---: |{}", " ---: | ---: |".repeat(biases.len()));
    let joined = |cells: Vec<String>| cells.join(" / ");
    for scene in all {
        let lowest: Vec<f64> = (0..SAMPLES.len())
            .map(|c| {
                scene
                    .modes
                    .iter()
                    .map(|mode| mode.equal_samples[c].rmse)
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        print!(
            "| {} | {:.5} | {} |",
            scene.name,
            scene.reference_noise,
            joined(lowest.iter().map(|rmse| format!("{rmse:.5}")).collect())
        );
        for splits in &scene.sweep {
            let cells = splits
                .iter()
                .map(|split| format!("{:.5} ({:.5})", split.rmse, split.sd))
                .collect();
            let ratios = splits
                .iter()
                .zip(&lowest)
                .map(|(split, lowest)| format!("{:.3}", split.unbiased_rmse(scene.reference_noise) / lowest))
                .collect();
            print!(" {} | {} |", joined(cells), joined(ratios));
        }
        println!();
    }
}

fn main() {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), &usage());
    let started = Instant::now();
    let gpu = open_device().unwrap_or_else(|error| {
        eprintln!("path_image_gpu: {error}");
        std::process::exit(1);
    });
    println!("# Path modes' image error on the GPU\n");
    println!("GPU clocks at the start: {}\n", gpu_clocks());
    println!("command: `{}`\n", example_command("path_image_gpu"));
    println!(
        "device {}, driver {}; seed {}, image {}x{}, texture {}; path_bias at bias {PATH_LOD_BIAS:+.2}; samples per \
         pixel {:?} (renders A and B: streams 4 seed and 4 seed + 1); reference: path_mip0, two renders of {} spp (streams 4 seed + 2 and + 3), averaged; equal \
         time: path_mip0 at {EQUAL_TIME_SAMPLES} spp, frame times from {ROUNDS} interleaved rounds of \
         {FRAMES_PER_ROUND} frames after warm-up rounds; a render of n spp starts from {}; a frame's pixels sample {}.\n",
        gpu.name(),
        gpu.driver(),
        options.seed,
        options.size.0,
        options.size.1,
        options.texture_size.map_or("each scene's own".to_string(), |n| format!("{n} x {n}")),
        SAMPLES,
        options.reference_samples,
        if options.sample_spread {
            "one sample's cone (the pixel's spread angle / sqrt(n))"
        } else {
            "the pixel's cone"
        },
        if options.pixel_offsets {
            "each an offset of its own"
        } else {
            "the frame's one offset"
        }
    );
    println!(
        "RMSE over pixels and linear RGB channels (frames' RGBA8 at gamma 2.2 taken to linear), split as the CPU \
         path_image splits it: sd^2 = mean((A - B)^2) / 2, bias^2 = mean(((A + B) / 2 - R)^2) - sd^2 / 2 - \
         noise^2, clamped at 0; reference noise = sqrt(mean((R1 - R2)^2) / 4)."
    );
    let mut all = Vec::new();
    for scene in &options.scenes {
        match measure_scene(&gpu, scene, &options) {
            Ok(results) => all.push(results),
            Err(error) => {
                eprintln!("path_image_gpu: {}: {error}", scene.name);
                std::process::exit(1);
            }
        }
    }
    print_summary(&all);
    print_sweep(&all, &options.biases);
    println!("\nGPU clocks at the end: {}", gpu_clocks());
    println!("\nwall time {:.1} s", started.elapsed().as_secs_f64());
}
