//! How fast the whole agreement suite verifies: every check of every module in every language,
//! through the public API as `verify` runs them, at a fixed number of cases per check and
//! language, with 1, 2, 4, ... up to all processors generating cases (`RunConfig::threads`).
//! Prints, per thread count, the checks run and not run, the cases, the wall time (compiling
//! each kernel and making its pipeline included: half the processors do it for the next checks
//! while one runs) and the verified evaluations per second.
//!
//! `cargo bench -p ray-footprint-lab --bench verification_speed [-- --cases N] [--threads N]`
//!
//! `--cases` sets the cases per check and language (100,000, as `verify`); `--threads` measures
//! one thread count only.

use ray_footprint_cases::agreement::run_all_checks;
use ray_footprint_lab::cli::{options_or_exit, positive_count};
use shader_proptest::{Gpu, Outcome, RunConfig};
use std::process::ExitCode;
use std::time::Instant;

struct Options {
    cases: usize,
    threads: Option<usize>,
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        cases: RunConfig::default().cases,
        threads: None,
    };
    while let Some(flag) = args.next() {
        if flag == "--bench" {
            continue;
        }
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        let number = positive_count(&flag, &value)?;
        match flag.as_str() {
            "--cases" => options.cases = number,
            "--threads" => options.threads = Some(number),
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(options)
}

/// 1, 2, 4, ... and the number of processors.
fn thread_counts(processors: usize) -> Vec<usize> {
    let mut counts: Vec<usize> = (0..usize::BITS)
        .map(|power| 1usize << power)
        .take_while(|&count| count < processors)
        .collect();
    counts.push(processors);
    counts
}

/// Totals of one pass over the suite.
#[derive(Default)]
struct Pass {
    run: usize,
    not_run: usize,
    failed: usize,
    cases: usize,
}

fn pass(gpu: &Gpu, config: &RunConfig) -> Result<Pass, String> {
    let mut totals = Pass::default();
    let mut error = None;
    run_all_checks(gpu, config, |_, check, language, result| match result {
        Ok(report) => {
            totals.cases += report.cases;
            match report.outcome {
                Outcome::Passed => totals.run += 1,
                Outcome::Failed(_) => {
                    totals.run += 1;
                    totals.failed += 1;
                    eprintln!("{report}");
                }
                Outcome::NotRun(_) => totals.not_run += 1,
            }
        }
        Err(e) => {
            error.get_or_insert(format!("{} ({language}): {e}", check.function()));
        }
    })
    .map_err(|e| e.to_string())?;
    error.map_or(Ok(totals), Err)
}

fn main() -> ExitCode {
    let options = options_or_exit(
        parse_args(std::env::args().skip(1)),
        "usage: verification_speed [--cases N] [--threads N]",
    );
    let gpu = match Gpu::new() {
        Ok(gpu) => gpu,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    };
    let processors = std::thread::available_parallelism().map_or(1, usize::from);
    println!(
        "device: {} ({}); {processors} processors; {} cases per check and language",
        gpu.name(),
        gpu.driver(),
        options.cases
    );
    println!("| threads | checks run | not run | cases | seconds | verified evaluations/s |");
    println!("| ---: | ---: | ---: | ---: | ---: | ---: |");
    let counts = options
        .threads
        .map_or_else(|| thread_counts(processors), |n| vec![n]);
    let mut failed = 0;
    for threads in counts {
        let config = RunConfig {
            cases: options.cases,
            threads,
            seed: Some(1),
            ..RunConfig::default()
        };
        let started = Instant::now();
        let totals = match pass(&gpu, &config) {
            Ok(totals) => totals,
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::FAILURE;
            }
        };
        let seconds = started.elapsed().as_secs_f64();
        failed += totals.failed;
        println!(
            "| {threads} | {} | {} | {} | {seconds:.1} | {:.0} |",
            totals.run,
            totals.not_run,
            totals.cases,
            totals.cases as f64 / seconds
        );
    }
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        eprintln!("{failed} checks failed");
        ExitCode::FAILURE
    }
}
