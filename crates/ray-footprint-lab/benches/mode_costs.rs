//! What each render mode costs: the gallery's ground view traced by each mode's colour-only
//! pipeline (no per-pixel records; each mode computes only what it needs), timed with GPU
//! timestamps around the trace. Prints, per mode, the median over the timed frames (after
//! untimed warm-up frames) in milliseconds, its ratio to mip 0, the payload's size in bytes and
//! the closest-hit shader's SPIR-V after `spirv-opt -O` (instructions inside functions,
//! conditional branches + switches, extended calls); then the goals beside the numbers.
//!
//! `cargo bench -p ray-footprint-lab --bench mode_costs [-- --width N --height N --frames N --warm-up N]`
//!
//! The default size is 1920 x 1080, or the gallery's 480 x 270 on lavapipe (a CPU
//! implementation); the default is 50 timed frames after 5 warm-up frames per mode.

use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_lab::cli::options_or_exit;
use ray_footprint_lab::rt::{open_device, Camera, Error, Mode, Renderer, Scene};
use shader_proptest::spirv::{self, Statistics};
use std::process::ExitCode;
use std::time::Duration;

/// The goal for the ray-cone LOD: at most this share added to the mip-0 frame.
const CONE_GOAL: f64 = 0.05;
/// The goal for ray-differential LOD: at most this many times the ray cone's added time.
const DIFF_GOAL: f64 = 2.0;
/// Fewest timed frames a median is taken over.
const MIN_FRAMES: usize = 50;

struct Options {
    size: Option<(u32, u32)>,
    frames: usize,
    warm_up: usize,
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        size: None,
        frames: MIN_FRAMES,
        warm_up: 5,
    };
    let (mut width, mut height) = (None, None);
    while let Some(flag) = args.next() {
        if flag == "--bench" {
            continue;
        }
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        let number = value
            .parse::<u32>()
            .map_err(|_| format!("{flag} must be a non-negative integer, got '{value}'"))?;
        match flag.as_str() {
            "--width" if number > 0 => width = Some(number),
            "--height" if number > 0 => height = Some(number),
            "--frames" if number as usize >= MIN_FRAMES => options.frames = number as usize,
            "--warm-up" => options.warm_up = number as usize,
            "--width" | "--height" => return Err(format!("{flag} must be positive")),
            "--frames" => return Err(format!("--frames must be at least {MIN_FRAMES}")),
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

/// One mode's figures.
struct Row {
    mode: Mode,
    median: Duration,
    payload_bytes: u32,
    closest_hit: Statistics,
}

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    let middle = times.len() / 2;
    if times.len().is_multiple_of(2) {
        (times[middle - 1] + times[middle]) / 2
    } else {
        times[middle]
    }
}

/// Why a mode has no row.
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

fn measure(
    renderer: &Renderer<'_>,
    mode: Mode,
    (width, height): (u32, u32),
    options: &Options,
) -> Result<Row, Failure> {
    let pipeline = renderer.colour_pipeline(mode)?;
    let camera = Camera::ground();
    let push = renderer.push_constants(&camera, mode, 1.0, width, height);
    let uniforms = camera.uniforms((width, height), WireframeSettings::default());
    let times = pipeline.time(&push, &uniforms, options.warm_up, options.frames)?;
    let optimized =
        spirv::optimize(pipeline.closest_hit_spirv()).map_err(|e| Failure::Error(e.to_string()))?;
    Ok(Row {
        mode,
        median: median(times),
        payload_bytes: pipeline.payload_bytes(),
        closest_hit: Statistics::of(&optimized).map_err(|e| Failure::Error(e.to_string()))?,
    })
}

fn print_table(rows: &[Row]) {
    let mip0 = rows[0].median.as_secs_f64();
    println!("| mode | ms (median) | vs mip 0 | payload bytes | closest-hit instructions | branches | extended calls |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for row in rows {
        let ms = row.median.as_secs_f64();
        let hit = &row.closest_hit;
        println!(
            "| {} | {:.3} | {:.3} | {} | {} | {}+{} | {} |",
            row.mode,
            ms * 1e3,
            ms / mip0,
            row.payload_bytes,
            hit.instructions,
            hit.conditional_branches,
            hit.switches,
            hit.extended_calls
        );
    }
}

fn print_goals(rows: &[Row]) {
    let time = |mode: Mode| {
        rows.iter()
            .find(|row| row.mode == mode)
            .map(|row| row.median.as_secs_f64())
    };
    let (Some(mip0), Some(cone), Some(diff)) = (time(Mode::Mip0), time(Mode::Cone), time(Mode::RayDiff))
    else {
        return;
    };
    let verdict = |met: bool| if met { "met" } else { "MISSED" };
    let cone_added = cone - mip0;
    let diff_added = diff - mip0;
    println!(
        "\ngoal: ray-cone LOD adds <= {:.0}% to the mip-0 frame: adds {:+.1}% ({:+.3} ms): {}",
        100.0 * CONE_GOAL,
        100.0 * cone_added / mip0,
        1e3 * cone_added,
        verdict(cone_added <= CONE_GOAL * mip0)
    );
    let ratio = diff_added / cone_added;
    let ratio_text = if cone_added > 0.0 {
        format!("{ratio:.2}x")
    } else {
        String::from("no ratio: the cone adds no time over mip 0")
    };
    println!(
        "goal: ray-differential LOD costs <= {DIFF_GOAL}x the cone's added cost (RTG ch.20 reports 2-3x): \
         adds {:+.3} ms, {ratio_text}: {}",
        1e3 * diff_added,
        verdict(diff_added <= DIFF_GOAL * cone_added.max(0.0))
    );
}

fn run(options: &Options) -> Result<(), Failure> {
    let gpu = open_device().map_err(|e| Failure::Error(e.to_string()))?;
    let renderer = Renderer::new(&gpu, Scene::gallery())?;
    let lavapipe = gpu.driver().contains("llvmpipe");
    let size = options
        .size
        .unwrap_or(if lavapipe { (480, 270) } else { (1920, 1080) });
    println!("device: {} ({})", gpu.name(), gpu.driver());
    println!(
        "ground view, {} x {}; median of {} frames after {} warm-up frames per mode; GPU timestamps around the trace",
        size.0, size.1, options.frames, options.warm_up
    );
    let mut rows = Vec::new();
    for mode in Mode::ALL {
        rows.push(measure(&renderer, mode, size, options)?);
    }
    println!();
    print_table(&rows);
    print_goals(&rows);
    Ok(())
}

fn main() -> ExitCode {
    let options = options_or_exit(
        parse_args(std::env::args().skip(1)),
        "usage: mode_costs [--width N --height N] [--frames N] [--warm-up N]",
    );
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
