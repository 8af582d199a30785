//! Reflection chains through the Rust mirror (no GPU needed): the cone against the crate's ray
//! differentials along the same paths (`ray_footprint_lab::chains`). As many chains from the same
//! strategies run on the device in the GPU tests (`tests/gpu/chains.rs`). Also: the chain shader's
//! three sources and its mirror declare the same structs and functions in the same order.

use ray_footprint_lab::chains::{
    check_on_the_cpu, head_on_chain_with_one_saddle, in_plane_chain, Comparison, CHAIN_SHADER_DIR,
    HEAD_ON_CHAINS, IN_PLANE_CHAINS,
};

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

/// The structs (`struct Name`) and the chain's functions (`chain_*`, `reflection_chain`) a source
/// declares at the top level, in order. A function's name is the word before the first `(` of its
/// declaration's line.
fn chain_declarations(source: &str) -> Vec<String> {
    let top_level = source.lines().filter(|line| !line.starts_with([' ', '/', '#']));
    top_level
        .filter_map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            if let Some(at) = words.iter().position(|word| *word == "struct") {
                return words.get(at + 1).map(|name| format!("struct {name}"));
            }
            let name = line.split('(').next()?.split_whitespace().last()?;
            (name.starts_with("chain_") || name == "reflection_chain").then(|| format!("fn {name}"))
        })
        .collect()
}

/// `reflection_chain.wgsl`, `.glsl` and `.slang` declare the structs and functions of `mirror.rs`,
/// in its order; the mirror adds only `chain_shader`, which picks one of them.
#[test]
fn chain_shaders_declare_the_mirrors_functions_in_order() {
    let read = |file: &str| {
        let path = std::path::Path::new(CHAIN_SHADER_DIR).join(file);
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    };
    let mut mirror = chain_declarations(&read("mirror.rs"));
    assert_eq!(mirror.pop().as_deref(), Some("fn chain_shader"), "{mirror:?}");
    assert!(mirror.contains(&"fn reflection_chain".to_string()), "{mirror:?}");
    for language in ["wgsl", "glsl", "slang"] {
        let file = format!("reflection_chain.{language}");
        assert_eq!(chain_declarations(&read(&file)), mirror, "{file}");
    }
}
