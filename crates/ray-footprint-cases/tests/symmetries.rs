//! Every declared symmetry of every function on the mirror: the transformed case's result,
//! restored, against the case's, over `symmetry::CASES` cases each with scales drawn
//! log-uniformly over the documented range, within the bound derived from the record's.
//! `RAY_FOOTPRINT_SYMMETRIES=<text>` runs only the functions whose `module::function` name holds
//! the text.

use ray_footprint_cases::records;
use ray_footprint_cases::symmetry::CASES;

#[test]
fn every_symmetry_holds_on_the_mirror() {
    let only = std::env::var("RAY_FOOTPRINT_SYMMETRIES").unwrap_or_default();
    let mut failures = Vec::new();
    for record in records() {
        if !format!("{}::{}", record.module().stem(), record.name()).contains(&only) {
            continue;
        }
        for index in 0..record.symmetry_list().len() {
            let report = record.symmetry_cpu(index, CASES, 0x5eed + index as u64);
            println!("{report}");
            if !report.passed() {
                failures.push(report.to_string());
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} symmetries broken:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
