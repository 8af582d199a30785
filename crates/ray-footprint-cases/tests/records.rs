//! The records on the CPU: one record per public function in module order, each complete, and
//! the degenerate table (the root crate's `src/degenerate.md`) as the records document it and as
//! the mirror computes it.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::assert_generated_block;
use ray_footprint::shaders::Module;
use ray_footprint_cases::order::check_order;
use ray_footprint_cases::pages::degenerate_table;
use ray_footprint_cases::sections::check_sections;
use ray_footprint_cases::{records, section_files};
use std::path::Path;

/// Every public function of every module has one record, in module order, whose checks call the
/// shader function of its name.
#[test]
fn every_function_has_a_record_in_module_order() {
    let names: Vec<_> = records()
        .iter()
        .map(|record| (record.module(), record.name()))
        .collect();
    check_order(&names).unwrap_or_else(|error| panic!("{error}"));
    for record in records() {
        let calls = format!("rf_{}", record.name());
        assert_eq!(record.agreement_check().function(), calls);
        assert_eq!(record.special_check().function(), calls);
    }
    println!("{} functions, each with one record", names.len());
}

/// Every section folder is named for its module's banner in its place, and every function's case
/// file lies in the folder of the section whose banner precedes the function (in the root crate's
/// `src/<module>.rs`); the first offender is named.
#[test]
fn every_case_file_is_in_its_sections_folder() {
    for &module in Module::ALL {
        let path = format!("{}/../../src/{}.rs", env!("CARGO_MANIFEST_DIR"), module.stem());
        let mirror = std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("{path}: {error}"));
        check_sections(module, &mirror, section_files(module)).unwrap_or_else(|error| panic!("{error}"));
        println!(
            "{}: {} files in section folders",
            module.stem(),
            section_files(module).len()
        );
    }
}

/// Every record says how the fuzzer draws its arguments, documents degenerate rows, and declares
/// at least one symmetry or says why it has none; the first incomplete record, in module order,
/// is named.
#[test]
fn every_record_is_complete() {
    for record in records() {
        let name = format!("{}::{}", record.module().stem(), record.name());
        assert!(record.has_fuzz_draw(), "{name} has no fuzz draw");
        assert!(record.degenerate_rows() > 0, "{name} has no degenerate rows");
        assert!(
            !record.symmetry_list().is_empty() || record.without_symmetry().is_some(),
            "{name} declares no symmetry and gives no reason"
        );
    }
}

const START: &str =
    "<!-- degenerate table: generated from ray-footprint-cases' records, do not edit by hand -->";
/// The root crate's documentation page that shows the table.
const DOC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../src/degenerate.md");
const END: &str = "<!-- end of degenerate table -->";

#[test]
fn the_docs_show_the_degenerate_table() {
    let block = format!("\n{}\n", degenerate_table(records()));
    assert_generated_block(Path::new(DOC), START, END, &block, "src/degenerate.md");
}

#[test]
fn the_mirror_follows_the_degenerate_table() {
    let rows: usize = records().iter().map(|record| record.degenerate_rows()).sum();
    let failures: Vec<String> = records()
        .iter()
        .flat_map(|record| record.degenerate_cpu())
        .collect();
    println!("{} functions, {rows} rows", records().len());
    assert!(rows > 0);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
