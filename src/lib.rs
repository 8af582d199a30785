//! Pixel-footprint math for GPU ray tracers and raymarchers: ray cones, ray differentials and
//! anti-aliased barycentric wireframe, as WGSL and GLSL modules to include in your shaders, with a
//! Rust mirror of every function and of every struct that crosses the CPU/GPU boundary.
//!
//! The WGSL, the GLSL and the Rust give the same answers: the `gpu` feature's harness runs the
//! shader modules on a Vulkan device (Mesa's lavapipe in CI) and compares the results with the
//! mirror, function by function.
#![deny(missing_docs)]

pub mod abi;
/// Degenerate inputs: the documented output of every function, in all three implementations.
///
#[doc = include_str!("degenerate.md")]
pub mod degenerate {}
#[doc(hidden)]
pub mod fuzzing;
#[cfg(feature = "validate")]
mod glslang;
#[cfg(feature = "validate")]
pub mod layout;
#[cfg(feature = "naga_oil")]
pub mod naga_oil;
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
pub mod shaders;
pub mod wireframe;

#[cfg(feature = "gpu")]
pub mod gpu;
