//! Every declared symmetry of every function on the mirror: the transformed case's result,
//! restored, against the case's, over `symmetry::CASES` cases each with scales drawn
//! log-uniformly over the documented range, within the bound derived from the record's; one
//! symmetry per processor at a time, the reports printed in module order.
//! `RAY_FOOTPRINT_SYMMETRIES=<text>` runs only the functions whose `module::function` name holds
//! the text; `SHADER_PROPTEST_SEED` draws other cases (the seed is printed).

use ray_footprint_cases::reference::env_seed;
use ray_footprint_cases::symmetry::{picked, SymmetryReport, CASES};
use ray_footprint_cases::{records, Function};
use shader_proptest::SEED_ENV;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

#[test]
fn every_symmetry_holds_on_the_mirror() {
    let records = records();
    let runs: Vec<(&dyn Function, usize)> = records
        .iter()
        .filter(|record| picked(record.as_ref()))
        .flat_map(|record| (0..record.symmetry_list().len()).map(move |index| (record.as_ref(), index)))
        .collect();
    // The first symmetry's seed; the next ones count up from it.
    let base_seed = env_seed(SEED_ENV, 0x5eed).unwrap_or_else(|error| panic!("{error}"));
    println!("{SEED_ENV}={base_seed:#x} replays this run");
    let next = AtomicUsize::new(0);
    let reports: Mutex<Vec<Option<SymmetryReport>>> = Mutex::new(vec![None; runs.len()]);
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let run = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(record, index)) = runs.get(run) else {
                    break;
                };
                let report = record.symmetry_cpu(index, CASES, base_seed + index as u64);
                reports.lock().expect("no panic while holding the lock")[run] = Some(report);
            });
        }
    });
    let reports = reports.into_inner().expect("every worker finished");
    let mut failures = Vec::new();
    for report in reports.into_iter().flatten() {
        println!("{report}");
        if !report.passed() {
            failures.push(report.to_string());
        }
    }
    println!("{} symmetries, {CASES} cases each", runs.len());
    assert!(
        failures.is_empty(),
        "{} symmetries broken:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
