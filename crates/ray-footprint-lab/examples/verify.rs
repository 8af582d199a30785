//! The main job: prints the layout of every struct shared between Rust and the shaders (Rust,
//! WGSL, GLSL std430 and scalar, Slang std430 and scalar), then runs the whole agreement suite on
//! the local Vulkan device (lavapipe unless `SHADER_PROPTEST_DEVICE` names another), one line per
//! function and language (WGSL, GLSL, Slang).
//!
//! A check fails when a case disagrees, or when more than [`MAX_VACUOUS`] of its cases have a
//! vacuous tolerance (one that no plausible output could exceed). A check the device cannot run
//! (no 64-bit floats) is reported as not run, with the reason, and never counted as passed.
//!
//! `cargo run --release -p ray-footprint-lab --example verify [-- --cases N] [--batch N]`

use ray_footprint_cases::agreement::run_all_checks;
use ray_footprint_lab::cli::{options_or_exit, positive_count};
use shader_proptest::{Gpu, Outcome, RunConfig, MAX_VACUOUS};
use std::process::ExitCode;

fn main() -> ExitCode {
    let config = options_or_exit(
        parse_args(std::env::args().skip(1)),
        "usage: verify [--cases N] [--batch N]",
    );
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
    println!("device: {} ({})", gpu.name(), gpu.driver());
    println!(
        "cases per function and language: at least {} (batches of up to {})",
        config.cases, config.batch
    );
    let started = std::time::Instant::now();
    let (mut failed, mut not_run, mut cases) = (0, 0, 0);
    let suite = run_all_checks(&gpu, &config, |module, check, language, result| match result {
        Ok(report) => {
            println!("{:<12} {report}", module.stem());
            cases += report.cases;
            match &report.outcome {
                Outcome::Passed if report.vacuous > MAX_VACUOUS => {
                    println!(
                        "    FAIL: {:.2}% of the cases have a vacuous tolerance (at most {:.0}%)",
                        100.0 * report.vacuous,
                        100.0 * MAX_VACUOUS
                    );
                    failed += 1;
                }
                Outcome::Passed => {}
                Outcome::Failed(_) => failed += 1,
                Outcome::NotRun(_) => not_run += 1,
            }
        }
        Err(error) => {
            println!(
                "{:<12} {:<38} {:<5} error: {error}",
                module.stem(),
                check.function(),
                language.name()
            );
            failed += 1;
        }
    });
    if let Err(error) = suite {
        eprintln!("error: {error}");
        return ExitCode::FAILURE;
    }
    let seconds = started.elapsed().as_secs_f64();
    println!(
        "{failed} checks failed, {not_run} not run; {cases} cases in {seconds:.1} s ({:.0} verified evaluations/s)",
        cases as f64 / seconds
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
        *target = positive_count(&flag, &value)?;
    }
    Ok(config)
}
