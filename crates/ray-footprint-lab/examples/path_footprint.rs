//! How wide each cone rule makes a path tracer's footprints against the true ones: per scene,
//! bounce (1 to 4) and rule, the mean and 95th percentile of `|log2(cone width / true width)|` in
//! mip levels over the paths' vertices, and a summary by the lobe sampled before the vertex
//! (`ray_footprint_lab::paths` says how each is measured), with the sweep of one global bias added
//! to the cone without a scattering term past the first hit. Everything runs on the CPU.
//!
//! ```text
//! cargo run --release -p ray-footprint-lab --example path_footprint -- \
//!     [--seed N] [--size WxH] [--paths N] [--step PIXELS] [--scene NAME] [--threads N]
//! ```

use ray_footprint_lab::cli::{
    command_options, example_command, image_size, options_or_exit, positive_count, seed,
};
use ray_footprint_lab::paths::{
    bias_sweep_table, measure, scene_table, scenes, scenes_named, summary_table, Scene, Settings,
    DEFAULT_STEP,
};
use std::time::Instant;

/// The default seed.
const DEFAULT_SEED: u64 = 1;
/// The default image size.
const DEFAULT_SIZE: (u32, u32) = (640, 360);
/// The default number of paths per scene.
const DEFAULT_PATHS: usize = 100_000;

/// What to run, from the command line.
struct Options {
    settings: Settings,
    scenes: Vec<Scene>,
}

fn usage() -> String {
    let names: Vec<_> = scenes()
        .iter()
        .map(|s| format!("  {:<16}{}", s.name, s.description))
        .collect();
    format!(
        "usage: path_footprint [--seed N] [--size WxH] [--paths N] [--step PIXELS] [--scene NAME|all] \
         [--threads N]\n\
         defaults: --seed {DEFAULT_SEED} --size {}x{} --paths {DEFAULT_PATHS} --step {DEFAULT_STEP:e} \
         --scene all --threads (all cores)\n\
         scenes:\n{}",
        DEFAULT_SIZE.0,
        DEFAULT_SIZE.1,
        names.join("\n")
    )
}

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut options = Options {
        settings: Settings {
            seed: DEFAULT_SEED,
            size: DEFAULT_SIZE,
            paths: DEFAULT_PATHS,
            step: DEFAULT_STEP,
            threads,
        },
        scenes: scenes(),
    };
    for (flag, value) in command_options(args)? {
        match flag.as_str() {
            "--seed" => options.settings.seed = seed(&flag, &value)?,
            "--size" => options.settings.size = image_size(&flag, &value)?,
            "--paths" => options.settings.paths = positive_count(&flag, &value)?,
            "--step" => options.settings.step = parse_step(&value)?,
            "--threads" => options.settings.threads = positive_count(&flag, &value)?,
            "--scene" => options.scenes = scenes_named(&value)?,
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(options)
}

/// A step in pixels, positive and below 0.1.
fn parse_step(value: &str) -> Result<f64, String> {
    match value.parse::<f64>() {
        Ok(step) if step > 0.0 && step < 0.1 => Ok(step),
        _ => Err(format!(
            "--step must be a number of pixels in (0, 0.1), got '{value}'"
        )),
    }
}

fn main() {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), &usage());
    let settings = options.settings;
    println!("# Path footprints: cone rules against the true footprint\n");
    println!("command: `{}`\n", example_command("path_footprint"));
    println!(
        "seed {}, image {}x{} (vertical field of view 60 degrees), {} paths per scene at random image \
         positions, central differences of step h = {:e} px, {} threads\n",
        settings.seed, settings.size.0, settings.size.1, settings.paths, settings.step, settings.threads
    );
    println!(
        "Each cell: mean / p95 of |log2(cone width / true width)| in mip levels over the vertices at that \
         bounce that have a true footprint (the paths at x +- h and y +- h met the same surfaces and \
         sampled the same lobes up to the vertex).\n"
    );
    let started = Instant::now();
    let measurements: Vec<_> = options
        .scenes
        .iter()
        .map(|scene| measure(scene, &settings))
        .collect();
    for measurement in &measurements {
        println!("{}", scene_table(measurement));
    }
    println!("{}", bias_sweep_table(&measurements));
    println!("{}", summary_table(&measurements));
    println!(
        "signed: mean of log2(cone width / true width); positive is too wide (blur), negative too narrow.\n"
    );
    println!("measured in {:.1} s", started.elapsed().as_secs_f64());
}
