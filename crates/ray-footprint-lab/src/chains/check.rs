//! Chains by the thousand: through the Rust mirror, through the shader on the device (both against
//! the rounding bound of [`super::bound`]), and the shader against the mirror
//! ([`reflection_chain_check`]).

use super::enclosure;
use super::mirror::{chain_shader, reflection_chain, ChainArgs, ChainSamples};
use super::{head_on_chain_with_one_saddle, in_plane_chain, Chain, ChainStats, Comparison};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRng, TestRunner};
use shader_proptest::{kernel_source, Args, ComputeKernel, FunctionCheck, Gpu, Language, Tolerance, Value};
use std::cell::RefCell;

/// Chains per dispatch on the device.
const BATCH: usize = 8192;

/// The configuration of a run of `cases` chains: no failure files.
fn config(cases: u32) -> Config {
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

/// A runner with a fixed seed, so that every run sees the same chains.
fn fixed_runner(cases: u32) -> TestRunner {
    let config = config(cases);
    let rng = TestRng::deterministic_rng(config.rng_algorithm);
    TestRunner::new_with_rng(config, rng)
}

/// Runs `cases` chains from `chains` through the Rust mirror (a fixed seed, so the printed numbers
/// repeat) and checks every sample against its rounding bound. `Err`: the first failure, shrunk to
/// a small chain, with its samples.
pub fn check_on_the_cpu(
    chains: BoxedStrategy<Chain>,
    comparison: Comparison,
    cases: u32,
) -> Result<ChainStats, String> {
    let stats = RefCell::new(ChainStats::default());
    let result = fixed_runner(cases).run(&chains, |chain| {
        let samples = chain.samples(comparison, &chain.trace(comparison));
        if let Some(sample) = samples.iter().find(|s| !s.within_bound()) {
            return Err(TestCaseError::fail(format!("{sample:?} in {samples:?}")));
        }
        stats.borrow_mut().add(&chain, &samples);
        Ok(())
    });
    result.map_err(|failure| format!("{comparison:?}: {failure}"))?;
    Ok(stats.into_inner())
}

/// Runs `cases` chains from `chains` (a fixed seed, as [`check_on_the_cpu`]) through the chain
/// shader in `language` on `gpu`, one dispatch per batch, and checks every sample the device returns
/// against its rounding bound. `Err`: the harness could not run, or the first chain with a sample
/// beyond its bound, with its samples.
pub fn check_on_the_device(
    gpu: &Gpu,
    language: Language,
    chains: BoxedStrategy<Chain>,
    comparison: Comparison,
    cases: u32,
) -> Result<ChainStats, String> {
    let mut runner = fixed_runner(cases);
    let chains = (0..cases)
        .map(|_| chains.new_tree(&mut runner).map(|tree| tree.current()))
        .collect::<Result<Vec<Chain>, _>>()
        .map_err(|reason| reason.to_string())?;
    let shader = chain_shader(language)?;
    let kernel = kernel_source(&shader, "reflection_chain", ChainArgs::TYPES, ChainSamples::TYPE);
    let spirv = shader
        .compile_kernel(&kernel)
        .map_err(|error| format!("{error}\n--- kernel ---\n{kernel}"))?;
    let pipeline = ComputeKernel::new(gpu, &spirv, 0).map_err(|error| error.to_string())?;
    let mut stats = ChainStats::default();
    for batch in chains.chunks(BATCH) {
        let mut input = Vec::new();
        batch
            .iter()
            .for_each(|chain| chain.args(comparison).write(&mut input));
        let output = pipeline
            .dispatch(batch.len(), &input, batch.len() * ChainSamples::TYPE.words())
            .map_err(|error| error.to_string())?;
        let mut words = &output[..];
        for chain in batch {
            let samples = chain.samples(comparison, &ChainSamples::read(&mut words));
            if let Some(sample) = samples.iter().find(|s| !s.within_bound()) {
                return Err(format!(
                    "{comparison:?} in {}: {sample:?} in {samples:?}\n{chain:?}",
                    language.name()
                ));
            }
            stats.add(chain, &samples);
        }
    }
    Ok(stats)
}

/// The check of the shader function `reflection_chain` against [`reflection_chain`]: in-plane
/// chains and (one in five) head-on chains with a saddle, each with the curvatures its comparison
/// gives the cone. The tolerance of every output is the width of its enclosure
/// (`shader_proptest::interval`): the chain re-evaluated in interval arithmetic on the same f32
/// inputs, in the mirror's order of operations, widened after every operation by the rounding that
/// Vulkan allows the device (and that the mirror makes), so that both results lie inside.
pub fn reflection_chain_check() -> FunctionCheck<ChainArgs, ChainSamples> {
    let chains = || {
        prop_oneof![
            4 => in_plane_chain().prop_map(|chain| chain.args(Comparison::InPlane)),
            1 => head_on_chain_with_one_saddle().prop_map(|chain| chain.args(Comparison::Mean)),
        ]
    };
    let mirror = |(camera, bounces, leg0, leg1, leg2, leg3, leg4): ChainArgs| {
        reflection_chain(camera, bounces, leg0, leg1, leg2, leg3, leg4)
    };
    let widths = |args: &ChainArgs, _: &[f32]| {
        enclosure::reflection_chain(args)
            .iter()
            .map(|i| i.tolerance())
            .collect()
    };
    FunctionCheck::new("reflection_chain", chains, mirror).tolerance(Tolerance::per_case(widths))
}
