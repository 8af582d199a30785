//! ray-footprint on a GPU: a Vulkan ray-tracing renderer
//! that uses the modules as a user's renderer would ([`rt`]), with its gallery, and the quality
//! lab that measures each level-of-detail method against a supersampled ground truth
//! ([`quality`]), with captioned figures ([`figure`]), and reflection chains that follow a ray
//! cone and a ray differential along the same paths, on the CPU and in both shader languages
//! ([`chains`]), the true footprints of path-traced vertices against the cone rules for
//! scattering ([`paths`]), and the GPU timing that the benches share ([`timing`]); with the
//! feature `browser`, the WebGPU demo page and its rendering through wgpu (`demo`).
#![deny(missing_docs)]

pub mod chains;
pub mod cli;
#[cfg(feature = "browser")]
pub mod demo;
pub mod figure;
pub mod paths;
pub mod quality;
/// The README's Rust examples, if any, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
mod readme_examples {}
pub mod rt;
pub mod timing;
