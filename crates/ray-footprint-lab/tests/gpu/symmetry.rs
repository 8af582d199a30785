//! Every declared symmetry of every function on the device ([`ray_footprint_cases::symmetry`]):
//! the shader function against itself, its result for a transformed case restored to the case's
//! terms and held to its result for the case, within the bound derived from the record's
//! tolerance, as a metamorphic check ([`shader_proptest::MetamorphicCheck`]), in WGSL, GLSL,
//! Slang and HLSL (glslang, slangc).
//!
//! Each symmetry runs [`DEFAULT_CASES`] cases in each language, or as many as
//! `RAY_FOOTPRINT_SYMMETRY_CASES` says (the lab's full run takes 100,000);
//! `RAY_FOOTPRINT_SYMMETRIES=<text>` runs only the functions whose `module::function` name holds
//! the text, as on the mirror.

use super::{assert_all_pass, gpu};
use ray_footprint::shaders::Module;
use ray_footprint_cases::module_records;
use ray_footprint_cases::symmetry::picked;
use shader_proptest::{Language, RunConfig};

/// Cases per symmetry and language where `RAY_FOOTPRINT_SYMMETRY_CASES` is not set.
const DEFAULT_CASES: usize = 10_000;

/// The run's configuration: the default with [`DEFAULT_CASES`] cases, or those the variable asks.
fn config() -> RunConfig {
    let cases = match std::env::var("RAY_FOOTPRINT_SYMMETRY_CASES") {
        Ok(text) => text.parse().unwrap_or_else(|_| {
            panic!("RAY_FOOTPRINT_SYMMETRY_CASES = {text:?}: expected a number of cases, such as 100000")
        }),
        Err(_) => DEFAULT_CASES,
    };
    RunConfig {
        cases,
        ..RunConfig::default()
    }
}

fn symmetries_hold(module: Module, language: Language) {
    let gpu = gpu();
    let checks: Vec<_> = module_records(module)
        .filter(|&record| picked(record))
        .flat_map(|record| (0..record.symmetry_list().len()).map(|index| record.symmetry_check(index)))
        .collect();
    let shader = module.shader(language);
    assert_all_pass(
        &gpu,
        &shader,
        language,
        checks.iter().map(AsRef::as_ref),
        &config(),
        "break a symmetry",
    );
}

module_and_language_tests!(symmetries_hold);
