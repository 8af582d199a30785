//! Reflection chains in WGSL, GLSL and Slang (`ray_footprint_lab::chains`): the chain shader, which
//! follows a ray cone and a ray differential side by side with the library modules, against its
//! Rust mirror; then the device's cone against the device's ray differentials along the same
//! paths, within the rounding bound the CPU test (`tests/chains.rs`) uses.

use super::gpu;
use ray_footprint_lab::chains::{
    chain_shader, check_on_the_device, head_on_chain_with_one_saddle, in_plane_chain, reflection_chain_check,
    Comparison, HEAD_ON_CHAINS, IN_PLANE_CHAINS,
};
use shader_proptest::{Language, RunConfig, MAX_VACUOUS};
use std::time::Instant;

/// The chain shader in `language` against its mirror (100,000 chains, tolerances from the interval
/// enclosure), then [`IN_PLANE_CHAINS`] and [`HEAD_ON_CHAINS`] chains on the device, each sample
/// of the device's cone against the device's differential within the rounding bound.
fn chains_agree(language: Language) {
    let gpu = gpu();
    println!("device: {} ({})", gpu.name(), gpu.driver());
    let shader = chain_shader(language).unwrap_or_else(|reason| panic!("{}: {reason}", language.name()));
    let report = reflection_chain_check()
        .run(&gpu, &shader, &RunConfig::default())
        .unwrap_or_else(|error| panic!("reflection_chain ({}): {error}", language.name()));
    println!("{report} in {:.1} s", report.elapsed.as_secs_f64());
    report.assert_passed();
    assert!(
        report.vacuous <= MAX_VACUOUS,
        "{:.2}% of the cases have a vacuous tolerance",
        100.0 * report.vacuous
    );
    let families = [
        (
            "in-plane chains",
            in_plane_chain(),
            Comparison::InPlane,
            IN_PLANE_CHAINS,
        ),
        (
            "head-on chains with a saddle",
            head_on_chain_with_one_saddle(),
            Comparison::Mean,
            HEAD_ON_CHAINS,
        ),
    ];
    for (name, chains, comparison, cases) in families {
        let started = Instant::now();
        let stats = check_on_the_device(&gpu, language, chains, comparison, cases)
            .unwrap_or_else(|failure| panic!("{name}: {failure}"));
        println!(
            "{name} on the device ({}): {stats}; {:.1} s",
            language.name(),
            started.elapsed().as_secs_f64()
        );
    }
}

language_tests!(chains_agree:
    reflection_chain_wgsl => Wgsl,
    reflection_chain_glsl => Glsl,
    reflection_chain_slang => Slang,
);
