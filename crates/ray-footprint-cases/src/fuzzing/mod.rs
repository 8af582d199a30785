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

/// Little-endian 32-bit words of a byte string, cycling: word `i` is made of the bytes
/// `4i .. 4i + 4` modulo the length. An empty string gives zeros.
#[derive(Clone, Debug)]
pub struct Words<'a> {
    data: &'a [u8],
    next: usize,
}

impl<'a> Words<'a> {
    /// Words of `data`, from the first.
    pub fn new(data: &'a [u8]) -> Self {
        Words { data, next: 0 }
    }

    /// The next word.
    pub fn u32(&mut self) -> u32 {
        if self.data.is_empty() {
            return 0;
        }
        let start = self.next * 4;
        self.next += 1;
        let byte = |k: usize| self.data[(start + k) % self.data.len()];
        u32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)])
    }

    /// The next word as the bits of an `f32`.
    pub fn f32(&mut self) -> f32 {
        f32::from_bits(self.u32())
    }

    /// The next `n` bytes (cycling), for structs read byte by byte.
    pub fn bytes(&mut self, n: usize) -> Vec<u8> {
        let words: Vec<u8> = (0..n.div_ceil(4))
            .flat_map(|_| self.u32().to_le_bytes())
            .collect();
        words[..n].to_vec()
    }
}
