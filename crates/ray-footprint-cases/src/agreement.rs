//! The agreement runner: every record's check ([`crate::Record::check`]) in every language, on one
//! device, in module order.

use crate::records::records;
use ray_footprint::shaders::Module;
use shader_proptest::{run_checks, Check, Error, Gpu, Language, Report, RunConfig};

/// Runs every agreement check in every language ([`Language::ALL`]), in module order, and hands
/// each result to `each` with the check's module and language. Every processor prepares the next
/// checks while one runs ([`shader_proptest::run_checks`]): with an empty SPIR-V cache, compiling
/// the kernels is most of the work, and the compilers are processes that keep a core each busy.
pub fn run_all_checks(
    gpu: &Gpu,
    config: &RunConfig,
    mut each: impl FnMut(Module, &dyn Check, Language, Result<Report, Error>),
) -> Result<(), Error> {
    let checks: Vec<(Module, Box<dyn Check>)> = records()
        .iter()
        .map(|record| (record.module(), record.agreement_check()))
        .collect();
    let runs: Vec<(Module, &dyn Check, Language)> = checks
        .iter()
        .flat_map(|(module, check)| Language::ALL.map(|language| (*module, check.as_ref(), language)))
        .collect();
    let shaders: Vec<(&dyn Check, shader_proptest::Shader)> = runs
        .iter()
        .map(|&(module, check, language)| (check, module.shader(language)))
        .collect();
    let preparers = std::thread::available_parallelism().map_or(1, usize::from);
    run_checks(gpu, &shaders, config, preparers, |index, result| {
        let (module, check, language) = runs[index];
        each(module, check, language, result);
    })
}
