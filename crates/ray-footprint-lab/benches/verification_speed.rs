//! How fast the whole agreement suite verifies: every check of every module in every language,
//! through the public API as `verify` runs them, at a fixed number of cases per check and
//! language, with 1, 2, 4, ... up to all processors generating cases (`RunConfig::threads`).
//! Prints, per thread count, the checks run and not run, the cases, the wall time (compiling
//! each kernel and making its pipeline included: every processor does it for the next checks
//! while one runs) and the verified evaluations per second. Then, per thread count, where the
//! time went ([`shader_proptest::Phase`]): each phase's seconds summed over the threads that
//! worked in it and over every check, its share of the summed work, its share of the wall time
//! (above 100% where threads overlap) and its nanoseconds per case; the two waits are the
//! dispatching threads', each shared among the shaders that ran the same cases.
//!
//! `cargo bench -p ray-footprint-lab --bench verification_speed [-- --cases N] [--batch N] [--threads N]`
//!
//! `--cases` sets the cases per check and language (100,000, as `verify`); `--batch` the cases per
//! batch (`RunConfig::batch`, 8,192); `--threads` measures one thread count only. With `SHADER_PROPTEST_SPIRV_CACHE` set, kernels compiled by an earlier
//! run come from that cache (`shader_proptest::compile::SPIRV_CACHE_ENV`); without it every pass
//! starts cold: the compiles the process keeps in memory are forgotten first
//! (`shader_proptest::compile::forget_compiles`).

use ray_footprint_cases::agreement::run_all_checks;
use ray_footprint_lab::cli::{command_options, options_or_exit, positive_count};
use shader_proptest::compile::{forget_compiles, SPIRV_CACHE_ENV};
use shader_proptest::{Gpu, Outcome, Phase, PhaseTimes, RunConfig};
use std::process::ExitCode;
use std::time::{Duration, Instant};

/// The seed of every pass, so that each pass runs the same cases.
const SEED: u64 = 1;

struct Options {
    cases: usize,
    batch: usize,
    threads: Option<usize>,
}

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        cases: RunConfig::default().cases,
        batch: RunConfig::default().batch,
        threads: None,
    };
    for (flag, value) in command_options(args)? {
        let number = positive_count(&flag, &value)?;
        match flag.as_str() {
            "--cases" => options.cases = number,
            "--batch" => options.batch = number,
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
    phases: PhaseTimes,
}

fn pass(gpu: &Gpu, config: &RunConfig) -> Result<Pass, String> {
    let mut totals = Pass::default();
    let mut error = None;
    run_all_checks(gpu, config, |_, check, language, result| match result {
        Ok(report) => {
            totals.cases += report.cases;
            totals.phases += report.phases;
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

/// The table of where the time of a pass with `threads` generating threads went, over its
/// `wall` time.
fn print_phases(threads: usize, totals: &Pass, wall: Duration) {
    let work = totals.phases.work().as_secs_f64();
    println!(
        "\nwhere the time goes, {threads} generating threads, seed {SEED}: {} cases in {:.1} s wall, {work:.1} s of work summed over the threads",
        totals.cases,
        wall.as_secs_f64()
    );
    println!("| phase | seconds, summed over threads | share of summed work | share of wall | ns per case |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    let row = |name: &str, seconds: f64, share_of_work: String| {
        println!(
            "| {name} | {seconds:.2} | {share_of_work} | {:.1}% | {:.0} |",
            100.0 * seconds / wall.as_secs_f64(),
            1e9 * seconds / totals.cases.max(1) as f64
        );
    };
    for phase in Phase::ALL.into_iter().filter(|phase| !phase.is_wait()) {
        let seconds = totals.phases.get(phase).as_secs_f64();
        row(phase.name(), seconds, format!("{:.1}%", 100.0 * seconds / work));
    }
    row("all work", work, String::from("100.0%"));
    for phase in Phase::ALL.into_iter().filter(|phase| phase.is_wait()) {
        row(
            phase.name(),
            totals.phases.get(phase).as_secs_f64(),
            String::from("-"),
        );
    }
}

fn main() -> ExitCode {
    let options = options_or_exit(
        parse_args(std::env::args().skip(1)),
        "usage: verification_speed [--cases N] [--batch N] [--threads N]",
    );
    let gpu = match Gpu::new() {
        Ok(gpu) => gpu,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    };
    let processors = std::thread::available_parallelism().map_or(1, usize::from);
    let cache = std::env::var(SPIRV_CACHE_ENV).unwrap_or_default();
    println!(
        "device: {} ({}); queues: {}; {processors} processors; {} cases per check and language in batches of {}; SPIR-V cache: {}",
        gpu.name(),
        gpu.driver(),
        gpu.queue_count(),
        options.cases,
        options.batch,
        if cache.is_empty() { "off" } else { &cache }
    );
    println!("| threads | checks run | not run | cases | seconds | verified evaluations/s |");
    println!("| ---: | ---: | ---: | ---: | ---: | ---: |");
    let counts = options
        .threads
        .map_or_else(|| thread_counts(processors), |n| vec![n]);
    let mut failed = 0;
    let mut passes = Vec::new();
    for threads in counts {
        let config = RunConfig {
            cases: options.cases,
            batch: options.batch,
            threads,
            seed: Some(SEED),
            ..RunConfig::default()
        };
        if cache.is_empty() {
            // Each pass starts cold, as a new process would.
            forget_compiles();
        }
        let started = Instant::now();
        let totals = match pass(&gpu, &config) {
            Ok(totals) => totals,
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::FAILURE;
            }
        };
        let wall = started.elapsed();
        let seconds = wall.as_secs_f64();
        failed += totals.failed;
        println!(
            "| {threads} | {} | {} | {} | {seconds:.1} | {:.0} |",
            totals.run,
            totals.not_run,
            totals.cases,
            totals.cases as f64 / seconds
        );
        passes.push((threads, totals, wall));
    }
    for (threads, totals, wall) in &passes {
        print_phases(*threads, totals, *wall);
    }
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        eprintln!("{failed} checks failed");
        ExitCode::FAILURE
    }
}
