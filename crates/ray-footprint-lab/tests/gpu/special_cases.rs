//! Special values for every function (each record's special-value check,
//! [`ray_footprint_cases::special`]): special floats, zero and axis-aligned vectors, vectors tied to
//! each other, in WGSL, GLSL, Slang and HLSL (glslang, slangc).
//!
//! Where a record declares its well-conditioned domain ([`ray_footprint_cases::Record::conditioned`]),
//! the cases inside it must agree with the mirror within the function's tolerance, and at most
//! [`MAX_VACUOUS`] of them may have a vacuous tolerance, as `verify` asks of the agreement checks.
//! The cases outside it are counted, printed with the reason, and run on the device,
//! where they must keep the record's promises: finite outputs for finite inputs, within the
//! documented range.

use super::gpu;
use ray_footprint::shaders::Module;
use ray_footprint_cases::{module_records, Function};
use shader_proptest::{Gpu, Language, RunConfig, Shader, MAX_VACUOUS};

/// Special-value cases drawn per function and language to run the ill-conditioned ones.
const ILL_CONDITIONED_DRAWN: usize = 20_000;

/// The failures of one function's special values in `language`, after printing its reports.
fn special_values_of(
    gpu: &Gpu,
    shader: &Shader,
    language: Language,
    record: &dyn Function,
    config: &RunConfig,
) -> Vec<String> {
    let name = record.name();
    let report = record
        .special_check()
        .run(gpu, shader, config)
        .unwrap_or_else(|error| panic!("{name} ({}): {error}", language.name()));
    println!("{report}");
    if !report.passed() {
        return vec![report.to_string()];
    }
    let mut failures = Vec::new();
    if report.vacuous > MAX_VACUOUS {
        failures.push(format!(
            "{name}: {:.2}% of the well-conditioned cases have a vacuous tolerance (at most {:.0}%)",
            100.0 * report.vacuous,
            100.0 * MAX_VACUOUS
        ));
    }
    let seed = report.seed;
    let ill = record
        .ill_conditioned_gpu(gpu, language, ILL_CONDITIONED_DRAWN, seed)
        .unwrap_or_else(|error| panic!("{name} ill-conditioned ({}): {error}", language.name()));
    if let Some(ill) = ill {
        println!(
            "    ill-conditioned: {} of {} special cases ({:.2}%), {} broken promises: {}",
            ill.run,
            ill.drawn,
            100.0 * ill.share(),
            ill.failures.len(),
            ill.reason
        );
        failures.extend(ill.failures.iter().take(5).map(|line| format!("{name}: {line}")));
    }
    failures
}

fn special_values_agree(module: Module, language: Language) {
    let gpu = gpu();
    let shader = module.shader(language);
    let config = RunConfig::default();
    let failures: Vec<String> = module_records(module)
        .flat_map(|record| special_values_of(&gpu, &shader, language, record, &config))
        .collect();
    assert!(
        failures.is_empty(),
        "{} failure(s) on special values:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

module_and_language_tests!(special_values_agree);
