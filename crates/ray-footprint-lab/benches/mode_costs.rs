//! What each render mode costs, timed so that the numbers hold when measured again
//! ([`ray_footprint_lab::timing`]).
//!
//! Workloads: the quality lab's scenes ([`LabScene::all`]: the ground plane at grazing angles and
//! under a wide view, the mirror paraboloid in its room (both triangulations), the mirror sphere, the glass sphere that
//! refracts rays through up to three bounces, the rough mirror reflecting about normals drawn from
//! its GGX lobe, the torus under the wireframe), each with its texture and view, traced by every
//! mode's colour-only pipeline (no per-pixel records; each mode computes only what it needs) at
//! 3840 x 2160 with N x N sub-pixel samples per pixel (default 2 x 2: a 4-spp path), each sample
//! one trace of the whole image.
//!
//! Method, per scene: warm-up rounds until two successive round medians agree within 2%; then
//! `--rounds` rounds (at least 8), each timing `--frames` frames of every mode, the modes in
//! [`Mode::ALL`] order in even rounds and in reverse in odd ones, every frame of a round recorded
//! into one command buffer and submitted at once (one timestamp pair per frame, a barrier between
//! frames, no CPU wait); per mode the median of its round medians and their spread (smallest to
//! largest), its ratio to mip 0, the time it adds to mip 0 with the spread of that difference, and
//! a verdict only where the spreads do not overlap ("not separable at this load" otherwise); then
//! the payload's size and the closest-hit shader's SPIR-V after `spirv-opt -O`. The goals (the
//! ray cone adds at most 5% to mip 0's frame; the ray differential adds at most twice the cone's
//! added time) are met or MISSED only where the whole spread of the added time lies on one side
//! of the limit. The GPU's clocks
//! (nvidia-smi) are printed at the start and the end. On lavapipe, which runs on the CPU, the
//! default is a smoke run (160 x 90, one sample, 2 frames a round, at most 3 warm-up rounds) and
//! no verdict is given.
//!
//! `--csv FILE` writes one row per scene and mode, which `examples/cost_quality.rs` draws against
//! the quality lab's table. `--texture-size N` replaces each scene's texture by the same image at
//! N x N texels (`rt::enlarged`: a power of two, at least 1024), so that a level-0 fetch reads from
//! a large texture; `--modes a,b` times mip 0 and those modes only. The path tracers' goal
//! (`path_cone`'s frame at least 5% faster than `path_mip0`'s, JCGT 2021 reporting about 10% from
//! cone LOD in a GPU path tracer) is met or MISSED where the spreads allow, as the others.
//!
//! `--biases B,B,..` also times `path_bias` at each of those level-of-detail biases (mip levels
//! added past the first hit, `RtPushConstants::lod_bias`), interleaved with the modes. At -20 every
//! lookup past the first hit reads level 0, at +20 the last level, with the same cone computed at
//! every vertex: the difference of the two frames is what the lookups past the first hit cost
//! between their finest and their coarsest level, the most that any rule's choice of level there
//! can save; the bench prints it beside the path goal's share of `path_mip0`'s frame.
//!
//! `cargo bench -p ray-footprint-lab --bench mode_costs [-- --width N --height N
//! --samples-per-axis N --rounds N --frames N --scene NAME --texture-size N --modes LIST --biases LIST
//! --csv FILE]`

use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_lab::cli::{command_options, count_at_least, lod_biases, options_or_exit, positive_count};
use ray_footprint_lab::quality::{LabScene, Measure};
use ray_footprint_lab::rt::abi::RtPushConstants;
use ray_footprint_lab::rt::{enlarged, open_device, Error, Mode, Renderer, Timed, TEXTURE_SIZE};
use ray_footprint_lab::timing::{self, gpu_clocks, verdict, warm_up, Spread, Verdict};
use shader_proptest::spirv::{self, Statistics};
use std::fmt::Write as _;
use std::process::ExitCode;

/// The goal for the ray-cone LOD: at most this share added to the mip-0 frame.
const CONE_GOAL: f64 = 0.05;
/// The goal for ray-differential LOD: at most this many times the ray cone's added time.
const DIFF_GOAL: f64 = 2.0;
/// Fewest timed rounds.
const MIN_ROUNDS: usize = 8;
/// The goal for the path tracer's cone LOD: its frame at least this share faster than mip 0's.
const PATH_GOAL: f64 = 0.05;

/// What to time, from the command line; `None` takes the device's default.
struct Options {
    size: Option<(u32, u32)>,
    samples_per_axis: Option<u32>,
    frames: Option<usize>,
    rounds: usize,
    scenes: Vec<LabScene>,
    csv: Option<String>,
    texture_size: Option<u32>,
    modes: Vec<Mode>,
    /// The biases `path_bias` is also timed at, in mip levels (none by default).
    biases: Vec<f32>,
}

/// The defaults on a GPU and on lavapipe (a CPU implementation: a smoke run), and the most
/// warm-up rounds before the timing goes on with the device unsettled (said in the output).
struct Defaults {
    size: (u32, u32),
    samples_per_axis: u32,
    frames: usize,
    max_warm_up_rounds: usize,
}

const GPU_DEFAULTS: Defaults = Defaults {
    size: (3840, 2160),
    samples_per_axis: 2,
    frames: 10,
    max_warm_up_rounds: 20,
};

const LAVAPIPE_DEFAULTS: Defaults = Defaults {
    size: (160, 90),
    samples_per_axis: 1,
    frames: 2,
    max_warm_up_rounds: 3,
};

const USAGE: &str = "usage: mode_costs [--width N --height N] [--samples-per-axis N] [--rounds N (>= 8)] \
                     [--frames N] [--scene NAME] [--texture-size N] [--modes a,b,...] [--biases B,B,...] \
                     [--csv FILE]";

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        size: None,
        samples_per_axis: None,
        frames: None,
        rounds: MIN_ROUNDS,
        scenes: LabScene::all(),
        csv: None,
        texture_size: None,
        modes: Mode::ALL.to_vec(),
        biases: Vec::new(),
    };
    let (mut width, mut height) = (None, None);
    for (flag, value) in command_options(args)? {
        let count = || positive_count(&flag, &value);
        match flag.as_str() {
            "--width" => width = Some(count()? as u32),
            "--height" => height = Some(count()? as u32),
            "--samples-per-axis" => options.samples_per_axis = Some(count()? as u32),
            "--frames" => options.frames = Some(count()?),
            "--rounds" => options.rounds = count_at_least(&flag, &value, MIN_ROUNDS)?,
            "--scene" => {
                options.scenes.retain(|scene| scene.name == value);
                if options.scenes.is_empty() {
                    let names: Vec<_> = LabScene::all().iter().map(|s| s.name).collect();
                    return Err(format!("no scene '{value}'; the scenes: {}", names.join(", ")));
                }
            }
            "--csv" => options.csv = Some(value),
            "--texture-size" => options.texture_size = Some(texture_size(&value)?),
            "--modes" => options.modes = modes(&value)?,
            "--biases" => options.biases = lod_biases(&flag, &value)?,
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    options.size = match (width, height) {
        (Some(w), Some(h)) => Some((w, h)),
        (None, None) => None,
        _ => return Err(String::from("give both --width and --height")),
    };
    Ok(options)
}

/// A `--texture-size`: a power of two from 1024 (the scenes' own) to 16384.
fn texture_size(value: &str) -> Result<u32, String> {
    match value.parse::<u32>() {
        Ok(size) if size.is_power_of_two() && (TEXTURE_SIZE..=16384).contains(&size) => Ok(size),
        _ => Err(format!(
            "--texture-size must be a power of two from {TEXTURE_SIZE} to 16384, got '{value}'"
        )),
    }
}

/// The modes of a `--modes` list, mip 0 first (the baseline) whether named or not, the others in
/// [`Mode::ALL`] order.
fn modes(value: &str) -> Result<Vec<Mode>, String> {
    let mut named = Vec::new();
    for name in value.split(',') {
        named.push(Mode::from_name(name).ok_or_else(|| format!("--modes: no mode '{name}'"))?);
    }
    Ok(Mode::ALL
        .into_iter()
        .filter(|&mode| mode == Mode::Mip0 || named.contains(&mode))
        .collect())
}

/// Why the bench stopped.
enum Failure {
    /// The device cannot time it: the reason.
    NotRun(String),
    /// Something broke.
    Error(String),
}

impl From<Error> for Failure {
    fn from(error: Error) -> Failure {
        match error {
            Error::NotSupported(reason) => Failure::NotRun(reason),
            other => Failure::Error(other.to_string()),
        }
    }
}

/// What a run is: the texture size, the modes and `path_bias`' biases, the image, the samples, the
/// frames per round, and whether verdicts are given.
struct Run {
    texture_size: Option<u32>,
    modes: Vec<Mode>,
    biases: Vec<f32>,
    size: (u32, u32),
    samples_per_axis: u32,
    frames: usize,
    rounds: usize,
    max_warm_up_rounds: usize,
    verdicts: bool,
}

/// One mode's figures in one scene.
struct Row {
    mode: Mode,
    /// The level-of-detail bias of a row of `--biases` (`path_bias` at that bias).
    lod_bias: Option<f32>,
    /// Round medians of the frame time, in ms.
    time: Spread,
    payload_bytes: u32,
    closest_hit: Statistics,
}

impl Row {
    /// Whether the row times `mode` itself, not `path_bias` at a bias of `--biases`.
    fn is_mode(&self, mode: Mode) -> bool {
        self.mode == mode && self.lod_bias.is_none()
    }

    /// The mode's name, with the bias of a row of `--biases`.
    fn label(&self) -> String {
        match self.lod_bias {
            Some(bias) => format!("{} at {bias:+.2}", self.mode),
            None => self.mode.to_string(),
        }
    }
}

/// The frame time of `mode`'s own row of `rows`, where it was timed.
fn mode_time(rows: &[Row], mode: Mode) -> Option<Spread> {
    rows.iter().find(|row| row.is_mode(mode)).map(|row| row.time)
}

/// The push constants of each sub-pixel sample of a frame of `scene`: an N x N grid of offsets,
/// each at the centre of its cell, under the scene's ground-truth flags (the rough mirror
/// reflecting about normals drawn from its GGX lobe).
fn samples(renderer: &Renderer<'_>, scene: &LabScene, run: &Run) -> Vec<RtPushConstants> {
    let n = run.samples_per_axis;
    let cell = 1.0 / n as f32;
    let (width, height) = run.size;
    (0..n * n)
        .map(|k| {
            let mut push = renderer.push_constants(&scene.camera, Mode::Mip0, 1.0, width, height);
            let (i, j) = (k % n, k / n);
            push.pixel_offset = glam::Vec2::new((i as f32 + 0.5) * cell - 0.5, (j as f32 + 0.5) * cell - 0.5);
            push.flags = scene.truth_flags;
            push
        })
        .collect()
}

/// `samples` with each of `biases` in turn as their level-of-detail bias: `path_bias`' samples at
/// each bias of `--biases`.
fn biased_samples(samples: &[RtPushConstants], biases: &[f32]) -> Vec<Vec<RtPushConstants>> {
    biases
        .iter()
        .map(|&lod_bias| {
            samples
                .iter()
                .map(|&push| RtPushConstants { lod_bias, ..push })
                .collect()
        })
        .collect()
}

/// The wireframe settings of `scene`'s uniforms: its preset where it measures the wireframe.
fn wireframe_settings(scene: &LabScene) -> WireframeSettings {
    match scene.measure {
        Measure::Wireframe { settings, .. } => settings,
        Measure::Texture => WireframeSettings::default(),
    }
}

/// Times every mode on `scene` and prints its table; returns its rows.
fn measure_scene(gpu: &shader_proptest::Gpu, scene: &LabScene, run: &Run) -> Result<Vec<Row>, Failure> {
    let texture = match run.texture_size {
        Some(size) => enlarged(&scene.texture, size),
        None => scene.texture.clone(),
    };
    let renderer = Renderer::with_texture(gpu, scene.scene.clone(), texture)?;
    let pipelines = run
        .modes
        .iter()
        .copied()
        .map(|mode| renderer.colour_pipeline(mode))
        .collect::<Result<Vec<_>, _>>()?;
    let biased = if run.biases.is_empty() {
        None
    } else {
        Some(renderer.colour_pipeline(Mode::PathBias)?)
    };
    let samples = samples(&renderer, scene, run);
    let biased_samples = biased_samples(&samples, &run.biases);
    let mut timed: Vec<Timed<'_, '_, '_>> = pipelines
        .iter()
        .map(|pipeline| (pipeline, &samples[..]))
        .collect();
    let mut row_biases: Vec<Option<f32>> = vec![None; pipelines.len()];
    if let Some(biased) = &biased {
        timed.extend(biased_samples.iter().map(|samples| (biased, &samples[..])));
        row_biases.extend(run.biases.iter().copied().map(Some));
    }
    let uniforms = scene.camera.uniforms(run.size, wireframe_settings(scene));
    let warm = warm_up(run.max_warm_up_rounds, || {
        renderer
            .time_colour_round(&timed, &uniforms, (run.frames, 0))
            .map(|medians| timing::median(&medians))
    })?;
    let mut round_medians = vec![Vec::with_capacity(run.rounds); timed.len()];
    for number in 0..run.rounds {
        let medians = renderer.time_colour_round(&timed, &uniforms, (run.frames, number))?;
        for (mode_medians, median) in round_medians.iter_mut().zip(medians) {
            mode_medians.push(median);
        }
    }
    let warm_medians: Vec<String> = warm.medians.iter().map(|m| format!("{m:.3}")).collect();
    println!(
        "\n### {}: {}\n\nwarm-up round medians (ms): {}{}\n",
        scene.name,
        scene.description,
        warm_medians.join(", "),
        if warm.settled {
            String::new()
        } else {
            format!(" (NOT settled within 2% after {} rounds)", run.max_warm_up_rounds)
        }
    );
    let rows = timed
        .iter()
        .zip(&round_medians)
        .zip(row_biases)
        .map(|((&(pipeline, _), medians), lod_bias)| {
            let optimized =
                spirv::optimize(pipeline.closest_hit_spirv()).map_err(|e| Failure::Error(e.to_string()))?;
            Ok(Row {
                mode: pipeline.mode(),
                lod_bias,
                time: Spread::of(medians),
                payload_bytes: pipeline.payload_bytes(),
                closest_hit: Statistics::of(&optimized).map_err(|e| Failure::Error(e.to_string()))?,
            })
        })
        .collect::<Result<Vec<_>, Failure>>()?;
    print_table(&rows, run);
    print_goals(&rows, run);
    Ok(rows)
}

/// The verdict on `row` against mip 0 (`baseline`), in words.
fn verdict_text(row: &Row, baseline: &Spread, run: &Run) -> String {
    if !run.verdicts {
        return String::from("no verdict (lavapipe)");
    }
    if row.is_mode(Mode::Mip0) {
        return String::from("baseline");
    }
    let percent = 100.0 * (row.time.median / baseline.median - 1.0);
    match verdict(&row.time, baseline) {
        Verdict::Slower => format!("slower, {percent:+.1}%"),
        Verdict::Faster => format!("faster, {percent:+.1}%"),
        Verdict::NotSeparable => String::from("not separable at this load"),
    }
}

fn print_table(rows: &[Row], run: &Run) {
    let baseline = rows[0].time;
    println!(
        "| mode | ms (median of {} round medians) | round medians min-max | vs mip 0 | added ms (min-max) | verdict | payload bytes | closest-hit instructions | branches | extended calls |",
        run.rounds
    );
    println!("| --- | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: |");
    for row in rows {
        let added = row.time.minus(&baseline);
        let added = if row.is_mode(Mode::Mip0) {
            String::from("-")
        } else {
            format!("{:+.3} ({:+.3} to {:+.3})", added.median, added.min, added.max)
        };
        let hit = &row.closest_hit;
        println!(
            "| {} | {:.3} | {:.3}-{:.3} | {:.3} | {added} | {} | {} | {} | {}+{} | {} |",
            row.label(),
            row.time.median,
            row.time.min,
            row.time.max,
            row.time.median / baseline.median,
            verdict_text(row, &baseline, run),
            row.payload_bytes,
            hit.instructions,
            hit.conditional_branches,
            hit.switches,
            hit.extended_calls
        );
    }
}

fn print_goals(rows: &[Row], run: &Run) {
    if !run.verdicts {
        println!("\ngoals: no verdict on lavapipe, which runs on the CPU");
        return;
    }
    print_path_goal(rows);
    let time = |mode: Mode| mode_time(rows, mode);
    let (Some(mip0), Some(cone), Some(diff)) = (time(Mode::Mip0), time(Mode::Cone), time(Mode::RayDiff))
    else {
        return;
    };
    let cone_added = cone.minus(&mip0);
    let cone_goal = format!(
        "adds {:+.1}% ({:+.3} ms, {:+.3} to {:+.3}): {}",
        100.0 * cone_added.median / mip0.median,
        cone_added.median,
        cone_added.min,
        cone_added.max,
        against_goal(&cone_added, CONE_GOAL * mip0.median, CONE_GOAL * mip0.median)
    );
    println!(
        "\ngoal: ray-cone LOD adds <= {:.0}% to the mip-0 frame: {cone_goal}",
        100.0 * CONE_GOAL
    );
    let diff_added = diff.minus(&mip0);
    let diff_goal = if cone_added.min <= 0.0 {
        format!(
            "no ratio: the cone adds no time beyond mip 0's spread ({:+.3} ms, {:+.3} to {:+.3}); the \
             differential adds {:+.3} ms ({:+.3} to {:+.3})",
            cone_added.median,
            cone_added.min,
            cone_added.max,
            diff_added.median,
            diff_added.min,
            diff_added.max
        )
    } else {
        let ratio = diff_added.median / cone_added.median;
        let verdict = against_goal(
            &diff_added,
            DIFF_GOAL * cone_added.min,
            DIFF_GOAL * cone_added.max,
        );
        format!(
            "adds {:+.3} ms ({:+.3} to {:+.3}) against the cone's {:+.3} ms ({:+.3} to {:+.3}), {ratio:.2}x: {verdict}",
            diff_added.median, diff_added.min, diff_added.max, cone_added.median, cone_added.min, cone_added.max
        )
    };
    println!("goal: ray-differential LOD costs <= {DIFF_GOAL}x the cone's added time (RTG ch.20 reports 2-3x): {diff_goal}");
}

/// The path tracers' goal, where both were timed: `path_cone`'s frame at least [`PATH_GOAL`] faster
/// than `path_mip0`'s, met where the whole spread of the time saved is above it; and every other
/// path mode's frame against `path_mip0`'s.
fn print_path_goal(rows: &[Row]) {
    let time = |mode: Mode| mode_time(rows, mode);
    let Some(mip0) = time(Mode::PathMip0) else {
        return;
    };
    for row in rows
        .iter()
        .filter(|row| row.mode.traces_paths() && row.mode != Mode::PathMip0)
    {
        let added = row.time.minus(&mip0);
        println!(
            "{} against path_mip0: {:+.1}% ({:+.3} ms, {:+.3} to {:+.3})",
            row.label(),
            100.0 * added.median / mip0.median,
            added.median,
            added.min,
            added.max
        );
    }
    print_lookup_cost(rows, &mip0);
    let Some(cone) = time(Mode::PathCone) else {
        return;
    };
    let added = cone.minus(&mip0);
    let limit = -PATH_GOAL * mip0.median;
    let verdict = against_goal(&added, limit, limit);
    println!(
        "\ngoal: path_cone's frame at least {:.0}% faster than path_mip0's: {:+.1}% ({:+.3} ms, {:+.3} to {:+.3}): {verdict}",
        100.0 * PATH_GOAL,
        100.0 * added.median / mip0.median,
        added.median,
        added.min,
        added.max
    );
}

/// Where `--biases` timed two or more biases: the frame of `path_bias` at the lowest bias less its
/// frame at the highest, as a share of `path_mip0`'s frame (`mip0`), beside the path goal's share.
/// At -20 and +20 that is what the lookups past the first hit cost at level 0 over the last level.
fn print_lookup_cost(rows: &[Row], mip0: &Spread) {
    let mut biased: Vec<&Row> = rows.iter().filter(|row| row.lod_bias.is_some()).collect();
    biased.sort_by(|a, b| a.lod_bias.partial_cmp(&b.lod_bias).expect("finite biases"));
    let [finest, .., coarsest] = biased[..] else {
        return;
    };
    let saved = finest.time.minus(&coarsest.time);
    println!(
        "{} less {}: {:+.1}% of path_mip0's frame ({:+.3} ms, {:+.3} to {:+.3}); the path goal's {:.0}% is {:.3} ms",
        finest.label(),
        coarsest.label(),
        100.0 * saved.median / mip0.median,
        saved.median,
        saved.min,
        saved.max,
        100.0 * PATH_GOAL,
        PATH_GOAL * mip0.median
    );
}

/// Whether the time `added` keeps within a limit that is somewhere from `low` to `high` (a
/// multiple of another measured spread, or one number twice): met where all of its spread is at
/// most `low`, MISSED where all of it is above `high`, otherwise not separable at this load.
fn against_goal(added: &Spread, low: f64, high: f64) -> &'static str {
    if added.max <= low {
        "met"
    } else if added.min > high {
        "MISSED"
    } else {
        "not separable at this load"
    }
}

/// The CSV of every scene's rows: the columns `examples/cost_quality.rs` reads.
fn csv(scenes: &[(&str, Vec<Row>)], run: &Run) -> String {
    let mut text = String::from(
        "scene,mode,median_ms,round_min_ms,round_max_ms,added_ms,added_min_ms,added_max_ms,verdict\n",
    );
    for (scene, rows) in scenes {
        let baseline = rows[0].time;
        for row in rows {
            let added = row.time.minus(&baseline);
            let _ = writeln!(
                text,
                "{scene},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{}",
                row.label(),
                row.time.median,
                row.time.min,
                row.time.max,
                added.median,
                added.min,
                added.max,
                verdict_text(row, &baseline, run)
            );
        }
    }
    text
}

fn run(options: &Options) -> Result<(), Failure> {
    let gpu = open_device().map_err(|e| Failure::Error(e.to_string()))?;
    let lavapipe = gpu.driver().contains("llvmpipe");
    let defaults = if lavapipe {
        &LAVAPIPE_DEFAULTS
    } else {
        &GPU_DEFAULTS
    };
    let run = Run {
        texture_size: options.texture_size,
        modes: options.modes.clone(),
        biases: options.biases.clone(),
        size: options.size.unwrap_or(defaults.size),
        samples_per_axis: options.samples_per_axis.unwrap_or(defaults.samples_per_axis),
        frames: options.frames.unwrap_or(defaults.frames),
        rounds: options.rounds,
        max_warm_up_rounds: defaults.max_warm_up_rounds,
        verdicts: !lavapipe,
    };
    println!("device: {} ({})", gpu.name(), gpu.driver());
    println!("GPU clocks at the start: {}", gpu_clocks());
    if lavapipe {
        println!(
            "lavapipe runs on the CPU: a smoke run of the method; its times say nothing of a GPU, and no verdict is given"
        );
    }
    let n = run.samples_per_axis;
    println!(
        "{} x {}, {n} x {n} samples per pixel (one trace of the image each), {} frames per mode per round, {} rounds \
         after warm-up rounds until two successive round medians agree within {:.0}%",
        run.size.0,
        run.size.1,
        run.frames,
        run.rounds,
        100.0 * timing::SETTLED
    );
    match run.texture_size {
        Some(size) => println!("textures: each scene's enlarged to {size} x {size} texels (rt::enlarged)"),
        None => println!("textures: each scene's own, {TEXTURE_SIZE} x {TEXTURE_SIZE} texels"),
    }
    let mut scenes = Vec::new();
    for scene in &options.scenes {
        scenes.push((scene.name, measure_scene(&gpu, scene, &run)?));
    }
    println!("\nGPU clocks at the end: {}", gpu_clocks());
    if let Some(path) = &options.csv {
        std::fs::write(path, csv(&scenes, &run))
            .map_err(|e| Failure::Error(format!("writing {path}: {e}")))?;
        println!("wrote {path}");
    }
    Ok(())
}

fn main() -> ExitCode {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), USAGE);
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::NotRun(reason)) => {
            println!("not run: {reason}");
            ExitCode::SUCCESS
        }
        Err(Failure::Error(message)) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
