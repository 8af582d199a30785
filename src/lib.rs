//! Pixel-footprint math for GPU ray tracers and raymarchers: ray cones, ray differentials and
//! anti-aliased barycentric wireframe, as WGSL, GLSL, Slang and HLSL modules to include in your
//! shaders, with a Rust mirror of every function and of every struct that crosses the CPU/GPU
//! boundary.
//!
//! The WGSL, the GLSL, the Slang, the HLSL and the Rust give the same answers: the workspace's
//! `ray-footprint-lab` runs every shader function on a Vulkan device (Mesa's lavapipe in CI)
//! through the `shader-proptest` harness and compares the results with the mirror, function by
//! function.
#![deny(missing_docs)]

pub mod abi;
/// Bad input at the edges of the API: what each entry that takes outside data answers.
///
#[doc = include_str!("bad_input.md")]
pub mod bad_input {}
/// Degenerate inputs: the documented output of every function, in every implementation.
///
#[doc = include_str!("degenerate.md")]
pub mod degenerate {}
pub mod mip;
#[cfg(feature = "naga_oil")]
pub mod naga_oil;
/// How each function is proven: agreement, independent references, degenerate rows.
///
#[doc = include_str!("proven.md")]
pub mod proven {}
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
/// The README's Rust examples, compiled and run as doc tests; they use every feature.
#[cfg(all(
    doctest,
    feature = "validate",
    feature = "naga_oil",
    feature = "shader-proptest",
    feature = "wesl"
))]
#[doc = include_str!("../README.md")]
mod readme_examples {}
pub mod shaders;
#[cfg(feature = "shader-proptest")]
mod values;
#[cfg(feature = "wesl")]
::wesl::wesl_pkg!(
    /// The WGSL modules as the WESL package `ray_footprint` (feature `wesl`), made by wesl's
    /// `PkgBuilder` in the build script: add [`PACKAGE`](self::wesl::PACKAGE) to a wesl compiler and import the
    /// modules' items by path, `import ray_footprint::ray_cone::{RfRayCone, rf_world_footprint};`.
    /// Each module is a submodule named by its stem (`ray_cone`, `ray_diff`, `ray_diff_f64`,
    /// `wireframe`); wesl links only what a shader imports.
    ///
    /// ```
    /// let mut compiler = wesl::Wesl::new("shaders");
    /// compiler.add_package(&ray_footprint::wesl::PACKAGE);
    /// ```
    ///
    /// Its items (`PACKAGE`, `MODULE` and one submodule per shader module holding its source) are
    /// written by wesl and carry no documentation of their own.
    #[allow(missing_docs)]
    pub wesl,
    "ray_footprint.rs"
);
#[cfg(feature = "wgpu")]
pub mod wgpu;
pub mod wireframe;

/// Struct layout verification (feature `validate`), from the `shader-proptest` crate: compare a
/// Rust struct's layout with a shader struct's (naga's WGSL layout, glslang's and slangc's std140,
/// std430 and scalar). [`abi::verify_shared_layouts`] uses it for every shared struct of this crate.
#[cfg(feature = "validate")]
pub mod layout {
    pub use shader_proptest::layout::*;
}
#[cfg(feature = "validate")]
pub use shader_proptest::rust_layout;
