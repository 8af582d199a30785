//! The quality lab: measures what each level-of-detail method buys against a supersampled ground
//! truth rendered through the same ray-tracing pipeline, on the local Vulkan device (lavapipe
//! unless `SHADER_PROPTEST_DEVICE` names another), and publishes the table, the goals, the images
//! and the plots in a folder.
//!
//! Ground truths are cached in `<out>/truth/` under a hash of everything they depend on; a re-run
//! renders only the methods. `--rebuild` renders them again (or delete the folder).
//! `--convergence` also renders every still ground truth with twice the samples per axis and
//! reports how much each PSNR moves.
//!
//! `cargo run --release -p ray-footprint-lab --example quality -- [--width N] [--height N]
//! [--samples N] [--frames K] [--scene NAME] [--out DIR] [--rebuild] [--convergence]`

use indicatif::{ProgressBar, ProgressStyle};
use ray_footprint_lab::cli::options_or_exit;
use ray_footprint_lab::quality::{self, report, truth::TruthSettings, LabScene, LabSettings, Progress};
use ray_footprint_lab::rt::{open_device, Mode};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Largest accepted width or height.
const MAX_SIZE: u32 = 2048;
/// Largest accepted samples per axis or frame count.
const MAX_COUNT: u32 = 256;

/// What to run, from the command line.
struct Options {
    size: (u32, u32),
    truth: TruthSettings,
    scenes: Vec<LabScene>,
    out: PathBuf,
    rebuild: bool,
    convergence: bool,
}

fn usage() -> String {
    let names: Vec<_> = LabScene::all()
        .iter()
        .map(|s| format!("  {:<12}{}", s.name, s.description))
        .collect();
    format!(
        "usage: quality [--width N] [--height N] [--samples N] [--frames K] [--scene NAME|all] \
         [--out DIR] [--rebuild] [--convergence]\n\
         defaults: --width {} --height {} --samples {} --frames {} --scene all --out quality\n\
         --samples: ground-truth samples per pixel along each axis (N x N per pixel)\n\
         --frames: frames of the sub-pixel drift (1/N pixel per frame)\n\
         --rebuild: render the ground truths again instead of reading <out>/truth/\n\
         --convergence: also render each still ground truth with 2N x 2N samples and compare\n\
         scenes:\n{}",
        DEFAULT_SIZE.0,
        DEFAULT_SIZE.1,
        DEFAULT_TRUTH.samples_per_axis,
        DEFAULT_TRUTH.frames,
        names.join("\n")
    )
}

/// The default image size: small enough for the whole run to take under five minutes on
/// lavapipe with two cores.
const DEFAULT_SIZE: (u32, u32) = (240, 160);
/// The default N (16 x 16 samples per pixel) and K (16 frames).
const DEFAULT_TRUTH: TruthSettings = TruthSettings {
    samples_per_axis: 16,
    frames: 16,
};

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        size: DEFAULT_SIZE,
        truth: DEFAULT_TRUTH,
        scenes: LabScene::all(),
        out: PathBuf::from("quality"),
        rebuild: false,
        convergence: false,
    };
    while let Some(flag) = args.next() {
        match flag.as_str() {
            "--help" | "-h" => return Err(String::new()),
            "--rebuild" => options.rebuild = true,
            "--convergence" => options.convergence = true,
            "--width" | "--height" | "--samples" | "--frames" | "--scene" | "--out" => {
                let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
                match flag.as_str() {
                    "--width" => options.size.0 = count(&flag, &value, 1, MAX_SIZE)?,
                    "--height" => options.size.1 = count(&flag, &value, 1, MAX_SIZE)?,
                    "--samples" => options.truth.samples_per_axis = count(&flag, &value, 1, MAX_COUNT)?,
                    "--frames" => options.truth.frames = count(&flag, &value, 2, MAX_COUNT)?,
                    "--scene" if value == "all" => options.scenes = LabScene::all(),
                    "--scene" => {
                        let scene = LabScene::all().into_iter().find(|s| s.name == value);
                        options.scenes = vec![scene.ok_or_else(|| format!("unknown scene '{value}'"))?];
                    }
                    _ if value.is_empty() => return Err("--out needs a folder name".into()),
                    _ => options.out = PathBuf::from(value),
                }
            }
            _ => return Err(format!("unknown argument '{flag}'")),
        }
    }
    Ok(options)
}

fn count(flag: &str, value: &str, min: u32, max: u32) -> Result<u32, String> {
    match value.parse::<u32>() {
        Ok(n) if (min..=max).contains(&n) => Ok(n),
        _ => Err(format!(
            "{flag} must be an integer from {min} to {max}, got '{value}'"
        )),
    }
}

/// The progress bar: frames rendered out of those planned, the stage, the time left.
struct Bar(ProgressBar);

impl Progress for Bar {
    fn plan(&mut self, frames: u64) {
        self.0.set_length(frames);
        self.0.set_position(0);
    }

    fn stage(&mut self, what: &str) {
        self.0.set_message(what.to_string());
    }

    fn tick(&mut self) {
        self.0.inc(1);
    }
}

fn bar() -> Bar {
    let bar = ProgressBar::new(0);
    let template = "[{elapsed_precise}] {bar:30} {pos}/{len} frames, {eta} left  {msg}";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    Bar(bar)
}

fn main() -> ExitCode {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), &usage());
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

/// Runs the lab, prints the setup, the table, the footprints, the goals (and the convergence table) and the
/// files written, and writes the folder.
fn run(options: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let started = Instant::now();
    let gpu = open_device()?;
    let settings = LabSettings {
        size: options.size,
        truth: options.truth,
        cache_dir: options.out.join("truth"),
        rebuild: options.rebuild,
    };
    let n = settings.truth.samples_per_axis;
    println!(
        "device: {}; {} x {} pixels; ground truth {n} x {n} samples per pixel; {} drift frames",
        gpu.name(),
        settings.size.0,
        settings.size.1,
        settings.truth.frames
    );
    let mut progress = bar();
    let lab_run = quality::run(&gpu, &options.scenes, &settings, &mut progress)?;
    progress.0.finish_and_clear();
    let rows = if options.convergence {
        let mut progress = bar();
        let rows = quality::convergence(&gpu, &lab_run, &mut progress)?;
        progress.0.finish_and_clear();
        rows
    } else {
        Vec::new()
    };
    let goals = report::goals(&lab_run);
    println!("\n{}", report::setup_markdown(&lab_run));
    println!("{}", report::table_markdown(&lab_run));
    println!(
        "{}{}",
        report::FOOTPRINTS_CAPTION,
        report::footprints_markdown(&lab_run)
    );
    let met = goals.iter().filter(|g| g.met).count();
    println!(
        "goals ({met} of {} met):\n{}",
        goals.len(),
        report::goals_markdown(&goals)
    );
    if !rows.is_empty() {
        println!("{}", report::convergence_markdown(&rows, n));
        println!(
            "largest PSNR change from {n}x{n} to {m}x{m} samples: {:.3} dB\n",
            report::largest_convergence_change(&rows),
            m = 2 * n
        );
    }
    for mode in Mode::ALL {
        if let Some(reason) = quality::not_a_texture_method(mode) {
            println!("no row on the texture scenes for {mode}: it {reason}");
        }
    }
    let written = report::write(&lab_run, &goals, &rows, &options.out)?;
    println!("files written: {} in {}", written.len(), options.out.display());
    println!("total time: {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
