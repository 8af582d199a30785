//! The main job: prints the layout of every struct shared between Rust and the shaders (Rust,
//! WGSL, GLSL std430, GLSL scalar), then runs the whole agreement suite on the local Vulkan device
//! (lavapipe unless `RAY_FOOTPRINT_DEVICE` names another), one line per function and language.
//!
//! `cargo run --release --all-features --example verify [-- --cases N]`

use ray_footprint::gpu::{suite, Gpu, Language, RunConfig};
use std::process::ExitCode;

fn main() -> ExitCode {
    let config = match parse_args(std::env::args().skip(1)) {
        Ok(config) => config,
        Err(message) => {
            eprintln!("error: {message}\nusage: verify [--cases N] [--batch N]");
            return ExitCode::from(2);
        }
    };
    println!("layouts of the shared structs (offset/size in bytes):");
    match ray_footprint::abi::verify_shared_layouts() {
        Ok(tables) => println!("{tables}\nall layouts equal\n"),
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    }
    let gpu = match Gpu::new() {
        Ok(gpu) => gpu,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    };
    println!("device: {}", gpu.name());
    println!(
        "cases per function and language: at least {} (batches of up to {})",
        config.cases, config.batch
    );
    let started = std::time::Instant::now();
    let mut failed = 0;
    for check in suite::all_checks() {
        for language in Language::ALL {
            match check.run(&gpu, language, &config) {
                Ok(report) => {
                    println!("{report}");
                    if let Some(failure) = &report.failure {
                        println!("    {}", failure.replace('\n', "\n    "));
                        failed += 1;
                    }
                }
                Err(error) => {
                    println!(
                        "{:<10} {:<34} {:<5} error: {error}",
                        check.module().stem(),
                        check.function(),
                        language.name()
                    );
                    failed += 1;
                }
            }
        }
    }
    println!(
        "{} checks failed; {:.1} s",
        failed,
        started.elapsed().as_secs_f64()
    );
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<RunConfig, String> {
    let mut config = RunConfig::default();
    while let Some(flag) = args.next() {
        let target = match flag.as_str() {
            "--cases" => &mut config.cases,
            "--batch" => &mut config.batch,
            other => return Err(format!("unknown argument '{other}'")),
        };
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        *target = match value.parse::<usize>() {
            Ok(n) if n > 0 => n,
            _ => return Err(format!("{flag} must be a positive integer, got '{value}'")),
        };
    }
    Ok(config)
}
