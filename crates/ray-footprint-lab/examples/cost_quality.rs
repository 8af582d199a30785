//! Which method to use: the quality each method gains over mip 0 against the frame time it adds,
//! per scene, from the quality lab's `table.csv` and the `mode_costs` bench's CSV (run both on the
//! device the answer is for). Prints the joined Markdown table and draws `cost_quality.png`.
//!
//! ```text
//! cargo run --release -p ray-footprint-lab --example quality -- --out quality
//! cargo bench -p ray-footprint-lab --bench mode_costs -- --csv mode_costs.csv
//! cargo run --release -p ray-footprint-lab --example cost_quality -- \
//!     --quality quality/table.csv --costs mode_costs.csv --out cost_quality.png
//! ```

use ray_footprint_lab::cli::{command_options, options_or_exit};
use ray_footprint_lab::quality::cost;
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage: cost_quality --quality TABLE_CSV --costs MODE_COSTS_CSV [--out PNG]\n\
                     default --out cost_quality.png";

struct Options {
    quality: PathBuf,
    costs: PathBuf,
    out: PathBuf,
}

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let (mut quality, mut costs, mut out) = (None, None, PathBuf::from("cost_quality.png"));
    for (flag, value) in command_options(args)? {
        match flag.as_str() {
            "--quality" => quality = Some(PathBuf::from(value)),
            "--costs" => costs = Some(PathBuf::from(value)),
            "--out" => out = PathBuf::from(value),
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(Options {
        quality: quality.ok_or("--quality is needed")?,
        costs: costs.ok_or("--costs is needed")?,
        out,
    })
}

fn run(options: &Options) -> Result<(), String> {
    let read = |path: &PathBuf| std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()));
    let rows = cost::join(&read(&options.quality)?, &read(&options.costs)?)?;
    if rows.is_empty() {
        return Err(String::from("no scene and method is in both tables"));
    }
    print!("{}", cost::markdown(&rows));
    let written = cost::plot(&rows, &options.out).map_err(|e| e.to_string())?;
    println!("wrote {}", written.display());
    Ok(())
}

fn main() -> ExitCode {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), USAGE);
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
