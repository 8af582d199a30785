//! Reflection chains through the Rust mirror (no GPU needed): the cone against the crate's ray
//! differentials along the same paths (`ray_footprint_lab::chains`). As many chains from the same
//! strategies run on the device in the GPU tests (`tests/gpu/chains.rs`).

use ray_footprint_lab::chains::{
    check_on_the_cpu, head_on_chain_with_one_saddle, in_plane_chain, Comparison, HEAD_ON_CHAINS,
    IN_PLANE_CHAINS,
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
