//! ABI: every shared struct has one layout in Rust, WGSL, GLSL std430 and scalar, and Slang std430
//! and scalar, and every
//! push-constant block fits the minimum every device accepts. (The values are echoed through the
//! GPU bit for bit by `crates/ray-footprint-lab/tests/gpu/abi.rs`.)

use ray_footprint::abi::{self, PUSH_CONSTANT_LIMIT};

/// Rust, WGSL, GLSL std430 and scalar, Slang std430 and scalar agree for every shared struct;
/// prints the table.
#[test]
fn every_shared_struct_has_one_layout() {
    let tables = abi::verify_shared_layouts().unwrap_or_else(|error| panic!("{error}"));
    println!("{tables}");
}

/// Every push-constant block fits the 128 bytes every Vulkan device accepts.
#[test]
fn push_constant_blocks_fit_the_vulkan_minimum() {
    let blocks: Vec<_> = abi::shared_layouts()
        .into_iter()
        .filter(|(_, layout)| layout.name.ends_with("PushConstants"))
        .collect();
    assert!(!blocks.is_empty());
    for (_, layout) in blocks {
        println!("{}: {} of {PUSH_CONSTANT_LIMIT} bytes", layout.name, layout.size);
        assert!(
            layout.size as usize <= PUSH_CONSTANT_LIMIT,
            "{} is {} bytes",
            layout.name,
            layout.size
        );
    }
}
