//! Property tests for shader functions: run a WGSL, GLSL, Slang or HLSL function on a real Vulkan device over
//! hundreds of thousands of generated inputs and compare every result with a Rust mirror of the
//! same function; and check that a Rust struct has exactly the byte layout of its shader twin.
//!
//! ```no_run
//! use glam::Vec3;
//! use proptest::prelude::*;
//! use shader_proptest::{FunctionCheck, Gpu, RunConfig, Shader, Tolerance};
//!
//! fn luminance(c: Vec3) -> f32 {
//!     c.dot(Vec3::new(0.2126, 0.7152, 0.0722))
//! }
//!
//! let gpu = Gpu::new()?;
//! let shader = Shader::wgsl("fn luminance(c: vec3<f32>) -> f32 { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }");
//! let colour = || (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0).prop_map(|(r, g, b)| (Vec3::new(r, g, b),));
//! let check = FunctionCheck::new("luminance", colour, |(c,)| luminance(c)).tolerance(Tolerance::Ulps(4.0));
//! check.run(&gpu, &shader, &RunConfig::default())?.assert_passed();
//! # Ok::<(), shader_proptest::Error>(())
//! ```
//!
//! How a check runs:
//!
//! 1. [`Gpu::new`] opens Mesa's lavapipe (any machine runs it), or the device whose name contains
//!    the value of [`DEVICE_ENV`], with the Khronos validation layer on: any validation message
//!    fails the run.
//! 2. A generated compute kernel ([`kernel_source`]) reads each case's arguments as 32-bit words,
//!    calls the function once per invocation and writes the result's words back. The [`Shader`]'s
//!    source comes first: a WGSL module (compiled by naga), GLSL that `#include`s yours (compiled
//!    by glslang, as Vulkan's GLSL users compile it), Slang that `import`s yours (compiled by
//!    slangc), or HLSL that `#include`s yours (compiled by glslang's HLSL front end or by slangc:
//!    two languages, [`Language::HlslGlslang`] and [`Language::HlslSlangc`]).
//! 3. Cases come from a proptest strategy, generated batch by batch from per-batch seeds on every
//!    processor while the device runs the previous batch (one dispatch per batch).
//! 4. Every output component is compared with the mirror's within a [`Tolerance`] (ULPs, absolute,
//!    relative, or a bound computed per case, for example by [`interval`] arithmetic with Vulkan's
//!    rounding allowances, [`tolerance`]); for finite inputs both results must be finite.
//! 5. A failure is shrunk by proptest to a small case and reported with the inputs, both outputs,
//!    the tolerance, the seed that replays it ([`SEED_ENV`]) and the kernel's source.
//!
//! A [`RunConfig`] of 0 cases, a batch of 0 or 0 threads, and a [`SEED_ENV`] that holds no seed
//! (neither decimal nor hexadecimal after `0x`) end the run before it starts with
//! [`Error::Config`], which names the field or variable and its value.
//!
//! Arguments and results are [`Value`]s: `f32`, `u32`, `i32`, `bool`, glam's vectors and matrices,
//! and structs declared with [`shader_struct!`]; with `pod`, a `#[repr(C)]` bytemuck struct's Rust
//! layout is compared with the shader's before the check runs. [`layout`] compares layouts on its
//! own (naga's WGSL layout, glslang's and slangc's std140, std430 and scalar), and [`echo`] proves
//! one on the device, bit for bit.
//!
//! The crate needs, at run time, a Vulkan loader, a device, the validation layer, and for GLSL
//! `glslangValidator`, for Slang `slangc`, for HLSL the one of them that compiles it. Without its default feature `gpu` it is the compilers, the value
//! descriptions and the layout reader only (no ash, no proptest).
#![deny(missing_docs)]

mod back;
pub mod compile;
pub mod interval;
mod kernel;
pub mod layout;
mod shader;
pub mod spirv;
#[cfg(feature = "gpu")]
pub mod strategy;
pub mod tolerance;
pub mod value;

#[cfg(feature = "gpu")]
mod gpu;

pub use back::Language;
pub use compile::CompileError;
pub use kernel::{echo_kernel_source, kernel_source, WORKGROUP_SIZE};
pub use shader::{Feature, Shader};
pub use tolerance::Tolerance;
pub use value::{Args, ShaderType, StructType, Value};

#[cfg(feature = "gpu")]
pub use gpu::{
    barrier_shader_writes_to_host, echo, evaluate, run_checks, vulkan, Buffer, Check, ComputeKernel,
    DeviceRequest, Error, Failure, FunctionCheck, Gpu, Location, Object, Outcome, Owner, PreparedCheck,
    Report, RunConfig, DEVICE_ENV, SEED_ENV,
};
#[cfg(feature = "gpu")]
pub use {ash, proptest};
