//! The properties the fuzz targets check, shared by `fuzz/fuzz_targets/*.rs` (cargo-fuzz, nightly)
//! and the corpus replay test `tests/fuzz_corpus.rs` of this crate (stable), so that both run the same code on the
//! same bytes.
//!
//! Each target is a function from arbitrary bytes to `Ok(())` or `Err(description)` of the violated
//! property; a panic is a failure too. The fuzz targets turn an `Err` into a panic ([`fuzz_one`]),
//! the replay test reports it with the corpus file's name.
//!
//! | target | what it checks |
//! | --- | --- |
//! | `abi_bytes` | [`abi::abi_bytes`]: checked casts of the bytes as every shared struct, byte round trips, settings and packed-cone conversions |
//! | `cpu_mirror` | [`mirror::cpu_mirror`]: every public function of every Rust mirror module |
//! | `compose` | [`compose::compose`]: user WGSL after [`ray_footprint::shaders::wgsl_prelude`] through naga, and through naga_oil |
//! | `include` | [`include::include`]: [`ray_footprint::shaders::resolve_glsl_include`] of an arbitrary name |
//!
//! Bytes become inputs without any extra dependency: [`Words`] reads them as little-endian 32-bit
//! words, cycling through the input when it runs out (an empty input gives zeros).

pub mod abi;
pub mod compose;
pub mod draw;
pub mod include;
pub mod mirror;
mod words;

pub use words::Words;

/// A fuzz target: `Err` names the violated property.
pub type Target = fn(&[u8]) -> Result<(), String>;

/// Every target, by the name of its fuzz binary and of its corpus directory `fuzz/corpus/<name>/`.
pub const TARGETS: &[(&str, Target)] = &[
    ("abi_bytes", abi::abi_bytes),
    ("cpu_mirror", mirror::cpu_mirror),
    ("compose", compose::compose),
    ("include", include::include),
];

/// Runs `target` on `data` and panics with the violated property, for libFuzzer (which records a
/// panic as a crash). Each fuzz binary passes its own target, so that it links only that target's
/// code: libFuzzer scans the coverage counters of everything linked after every input.
pub fn fuzz_one(target: Target, data: &[u8]) {
    if let Err(violation) = target(data) {
        panic!("{violation}");
    }
}
