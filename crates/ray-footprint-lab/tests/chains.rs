//! Reflection chains through the Rust mirror (no GPU needed): the cone against the crate's ray
//! differentials along the same paths (`ray_footprint_lab::chains`). As many chains from the same
//! strategies run on the device in the GPU tests (`tests/gpu/chains.rs`). Also: the chain shader's
//! three sources and its mirror declare the same structs and functions in the same order.

use ray_footprint_lab::chains::{
    check_on_the_cpu, head_on_chain_with_one_saddle, in_plane_chain, Comparison, CHAIN_SHADER_DIR,
    HEAD_ON_CHAINS, IN_PLANE_CHAINS,
};
use shader_proptest::declarations::{declarations, Declaration};

/// Random in-plane chains (pinhole, orthographic and thin-lens primaries; convex and concave
/// spheres and saddles; hits from either side with the normals stored either way; foci crossed
/// anywhere): after every bounce and at the end, the cone's signed width equals the ray
/// differentials' in-plane footprint within the rounding bound (`CHAIN_PRIMARY_ULPS` and
/// `CHAIN_ULPS_PER_LEG` per leg).
#[test]
fn in_plane_chains_follow_the_ray_differentials() {
    let stats = check_on_the_cpu(in_plane_chain(), Comparison::InPlane, IN_PLANE_CHAINS)
        .unwrap_or_else(|e| panic!("{e}"));
    println!("in-plane chains: {stats}");
    // The chains exercise the signs: foci, back-side hits, saddles.
    assert!(stats.crossed_a_focus * 5 >= stats.chains);
    assert!(stats.back_side_hits * 5 >= stats.chains);
    assert!(stats.saddles * 5 >= stats.chains);
}

/// Random head-on chains with one saddle among spheres: the cone given the saddle's mean curvature
/// follows the mean of the ray differentials' two signed footprints, within the same bound.
#[test]
fn head_on_chains_with_a_saddle_follow_the_mean_footprint() {
    let stats = check_on_the_cpu(head_on_chain_with_one_saddle(), Comparison::Mean, HEAD_ON_CHAINS)
        .unwrap_or_else(|e| panic!("{e}"));
    println!("head-on chains with a saddle: {stats}");
    assert!(stats.crossed_a_focus * 5 >= stats.chains);
    assert!(stats.back_side_hits * 5 >= stats.chains);
}

/// The structs and the chain's functions (`chain_*`, `reflection_chain`) a source declares at the
/// top level, in order.
fn chain_declarations(source: &str) -> Vec<Declaration<'_>> {
    declarations(source)
        .into_iter()
        .filter(|declaration| match declaration {
            Declaration::Struct(_) => true,
            Declaration::Function(name) => name.starts_with("chain_") || *name == "reflection_chain",
            Declaration::Section(_) | Declaration::Constant(_) => false,
        })
        .collect()
}

/// `reflection_chain.wgsl` and `.glsl` (which Slang compiles too) declare the structs and
/// functions of `mirror.rs`, in its order; the mirror adds only `chain_shader`, which picks one of
/// them.
#[test]
fn chain_shaders_declare_the_mirrors_functions_in_order() {
    let read = |file: &str| {
        let path = std::path::Path::new(CHAIN_SHADER_DIR).join(file);
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    };
    let mirror_source = read("mirror.rs");
    let mut mirror = chain_declarations(&mirror_source);
    assert_eq!(
        mirror.pop(),
        Some(Declaration::Function("chain_shader")),
        "{mirror:?}"
    );
    assert!(
        mirror.contains(&Declaration::Function("reflection_chain")),
        "{mirror:?}"
    );
    for language in ["wgsl", "glsl"] {
        let file = format!("reflection_chain.{language}");
        assert_eq!(chain_declarations(&read(&file)), mirror, "{file}");
    }
}
