//! Every public function against its independent references ([`ray_footprint_cases::reference`]),
//! on the CPU: each function has one, each holds over its cases, and the root crate's
//! `src/proven.md` shows how each function is proven.
//!
//! `RAY_FOOTPRINT_REFERENCE_SEED=<seed>` runs the references on other cases;
//! `RAY_FOOTPRINT_REFERENCE_ONLY=<text>` runs only those of the functions whose `module::function`
//! contains the text.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::assert_generated_block;
use ray_footprint_cases::pages::proven_table;
use ray_footprint_cases::reference::{run_seed, ReferenceReport, CASES, SEED_ENV};
use ray_footprint_cases::{records, Function};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// Every public function has at least one independent reference; the first without one, in
/// module order, is named.
#[test]
fn every_function_has_a_reference() {
    for record in records() {
        assert!(
            !record.references().is_empty(),
            "{}::{} has no independent reference",
            record.module().stem(),
            record.name()
        );
    }
    let count: usize = records().iter().map(|record| record.references().len()).sum();
    println!("{} functions, {count} references", records().len());
}

/// Environment variable naming the functions to run the references of (a substring of
/// `module::function`).
const ONLY_ENV: &str = "RAY_FOOTPRINT_REFERENCE_ONLY";

/// Runs every reference of every function (or those `ONLY_ENV` selects) on every processor, and
/// prints one line per reference in module order: its cases, the largest deviation and its share of
/// the bound.
#[test]
fn every_reference_holds() {
    let seed = run_seed().unwrap_or_else(|error| panic!("{error}"));
    let only = std::env::var(ONLY_ENV).unwrap_or_default();
    let runs: Vec<(&dyn Function, usize)> = records()
        .iter()
        .filter(|record| format!("{}::{}", record.module().stem(), record.name()).contains(&only))
        .flat_map(|record| (0..record.references().len()).map(move |index| (record.as_ref(), index)))
        .collect();
    println!(
        "{} references, {CASES} cases each, seed {seed:#x} (set {SEED_ENV} for others)",
        runs.len()
    );
    let started = Instant::now();
    let next = AtomicUsize::new(0);
    let reports: Mutex<Vec<Option<ReferenceReport>>> = Mutex::new((0..runs.len()).map(|_| None).collect());
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(record, reference)) = runs.get(index) else {
                    break;
                };
                let report = record.run_reference(reference, seed);
                reports.lock().expect("no panic while holding it")[index] = Some(report);
            });
        }
    });
    let reports: Vec<ReferenceReport> = reports
        .into_inner()
        .expect("no panic while holding it")
        .into_iter()
        .map(|report| report.expect("every reference ran"))
        .collect();
    for report in &reports {
        println!("{report}");
    }
    println!(
        "{} references in {:.1} s",
        reports.len(),
        started.elapsed().as_secs_f64()
    );
    let failures: Vec<String> = reports
        .iter()
        .filter(|report| report.outcome.is_err())
        .map(ToString::to_string)
        .collect();
    assert!(
        failures.is_empty(),
        "{} reference(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

const START: &str = "<!-- proven table: generated from ray-footprint-cases' records, do not edit by hand -->";
/// The root crate's documentation page that shows the table.
const DOC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../src/proven.md");
const END: &str = "<!-- end of proven table -->";

#[test]
fn the_docs_show_how_each_function_is_proven() {
    let block = format!("\n{}\n", proven_table(records()));
    assert_generated_block(Path::new(DOC), START, END, &block, "src/proven.md");
}
