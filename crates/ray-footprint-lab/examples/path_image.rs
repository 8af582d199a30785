//! The image error each cone rule gives when its width picks the level of a mip-mapped texture in
//! a path tracer: per scene, rule and samples per pixel, the RMSE against a reference rendered at
//! level 0 with many samples, split into bias and noise (`ray_footprint_lab::paths::image` says
//! how), and the error against the samples per pixel drawn to `--plot FILE` (default
//! `path_image.png`). Everything runs on the CPU.
//!
//! ```text
//! cargo run --release -p ray-footprint-lab --example path_image -- \
//!     [--seed N] [--size WxH] [--reference-spp N] [--scene NAME] [--threads N] [--plot FILE] \
//!     [--spread pixel|sample]
//! ```
//!
//! With `--spread sample`, a render of `n` samples per pixel starts every path from the cone of
//! one of `n` samples: the pixel's of an image `sqrt(n)` times taller, whose spread angle is the
//! pixel's over `sqrt(n)` to first order (pbrt scales its camera rays' differentials by
//! `1 / sqrt(spp)`). Each count is then a render of its own.

use ray_footprint_lab::cli::{
    command_options, example_command, image_size, options_or_exit, positive_count, sample_spread, seed,
};
use ray_footprint_lab::paths::{
    image_error_plot, image_scene_table, image_summary_table, measure_image, noise_floor_table, scenes,
    scenes_named, ImageSettings, Scene, Texture,
};
use std::path::PathBuf;
use std::time::Instant;

/// The default seed.
const DEFAULT_SEED: u64 = 1;
/// The default image size.
const DEFAULT_SIZE: (u32, u32) = (160, 90);
/// Samples per pixel measured.
const SAMPLES: [usize; 3] = [4, 16, 64];
/// The default samples per pixel of each of the two reference renders.
const DEFAULT_REFERENCE_SAMPLES: usize = 1024;

/// What to run, from the command line.
struct Options {
    settings: ImageSettings,
    scenes: Vec<Scene>,
    plot: PathBuf,
}

fn usage() -> String {
    format!(
        "usage: path_image [--seed N] [--size WxH] [--reference-spp N] [--scene NAME|all] [--threads N] \
         [--plot FILE] [--spread pixel|sample]\n\
         defaults: --seed {DEFAULT_SEED} --size {}x{} --reference-spp {DEFAULT_REFERENCE_SAMPLES} \
         --scene all --threads (all cores) --plot path_image.png --spread pixel",
        DEFAULT_SIZE.0, DEFAULT_SIZE.1
    )
}

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut options = Options {
        settings: ImageSettings {
            seed: DEFAULT_SEED,
            size: DEFAULT_SIZE,
            samples: SAMPLES.to_vec(),
            reference_samples: DEFAULT_REFERENCE_SAMPLES,
            sample_spread: false,
            threads,
        },
        scenes: scenes(),
        plot: PathBuf::from("path_image.png"),
    };
    for (flag, value) in command_options(args)? {
        match flag.as_str() {
            "--seed" => options.settings.seed = seed(&flag, &value)?,
            "--size" => options.settings.size = image_size(&flag, &value)?,
            "--reference-spp" => options.settings.reference_samples = positive_count(&flag, &value)?,
            "--threads" => options.settings.threads = positive_count(&flag, &value)?,
            "--scene" => options.scenes = scenes_named(&value)?,
            "--plot" => options.plot = PathBuf::from(value),
            "--spread" => options.settings.sample_spread = sample_spread(&flag, &value)?,
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(options)
}

fn main() {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), &usage());
    let settings = options.settings;
    let started = Instant::now();
    let texture = Texture::procedural();
    let results: Vec<_> = options
        .scenes
        .iter()
        .map(|scene| measure_image(scene, &texture, &settings))
        .collect();
    println!("# Path tracer image error of texture LOD from each cone rule\n");
    println!("command: `{}`\n", example_command("path_image"));
    println!(
        "seed {}, image {}x{} (vertical field of view 60 degrees), samples per pixel {:?} (renders A and \
         B, seeds 4 seed and 4 seed + 1), reference: two renders of {} spp at level 0 (bilinear), seeds \
         4 seed + 2 and + 3, averaged; a render of n spp starts its paths from {}; {} threads; wall time \
         {:.1} s\n",
        settings.seed,
        settings.size.0,
        settings.size.1,
        settings.samples,
        settings.reference_samples,
        if settings.sample_spread {
            "one sample's cone (the pixel's of an image sqrt(n) times taller)"
        } else {
            "the pixel's cone"
        },
        settings.threads,
        started.elapsed().as_secs_f64()
    );
    println!(
        "Texture 1024 x 1024 (two colours mixed by ten checkers of squares 1 to 512 texels), 512 \
         texels per metre, trilinear; LOD = texture_lod(log2(1/2), |width|, 1024^2, n, d) = \
         log2(|width| / |cos| x 512). Diffuse albedo 0.8 x texture; GGX conductors colour (0.95, 0.9, \
         0.8); white environment of radiance 1, a sphere light (radiance 5) in rough_room; up to 4 \
         scattering vertices, no Russian roulette, no NEE.\n"
    );
    println!(
        "Each cell: RMSE over pixels and linear RGB channels, (A and B mean squared), (bias / sd): \
         sd^2 = mean((A - B)^2) / 2, bias^2 = mean(((A + B) / 2 - R)^2) - sd^2 / 2 - noise^2, clamped \
         at 0. Reference noise = sqrt(mean((R1 - R2)^2) / 4), the noise of the averaged reference; it is \
         inside every RMSE (RMSE^2 = bias^2 + sd^2 + noise^2). Bold: lowest RMSE of the column but the floor's.\n"
    );
    for result in &results {
        println!("{}", image_scene_table(result, &settings.samples));
    }
    println!("{}", image_summary_table(&results, &settings.samples));
    println!(
        "wins: scenes where the method has the lowest RMSE of all but the floor (ties count for each; a scene without texture, \
         rough_room, is a tie of all); / mip 0: mean over the scenes of RMSE / mip 0's RMSE; / best \
         shipped: that mean divided by the lowest such mean among the shipped rules (JCGT roughness, \
         RTXPT, sqrt-pdf, OptiX Toolkit).\n"
    );
    println!("{}", noise_floor_table(&results, &settings.samples));
    match image_error_plot(&results, &settings.samples, &options.plot) {
        Ok(path) => println!("wrote {}", path.display()),
        Err(error) => {
            eprintln!("path_image: {error}");
            std::process::exit(1);
        }
    }
    println!("wall time {:.1} s", started.elapsed().as_secs_f64());
}
