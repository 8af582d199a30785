//! Property tests for shader functions: run a WGSL, GLSL, Slang or HLSL function on a real Vulkan
//! device over hundreds of thousands of generated inputs and compare every result with a Rust twin
//! of the same function, or with the function's own result for a transformed input where it has
//! no twin ([`MetamorphicCheck`], with the `gpu` feature); and check that a Rust struct has
//! exactly the byte layout of its shader twin.
//!
//! The crate's README (`crates/shader-proptest/README.md`) walks through a first test, what a
//! failure says, checks of functions that use a library's shader modules, and which tolerance
//! suits which function.
#![cfg_attr(
    feature = "gpu",
    doc = r#"
```
use shader_proptest::proptest::prelude::*;
use shader_proptest::{FunctionCheck, Gpu, RunConfig, Shader, Tolerance};

fn falloff(d: f32, r0: f32, r1: f32) -> f32 {
    let t = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

let shader = Shader::wgsl("fn falloff(d: f32, r0: f32, r1: f32) -> f32 { return 1.0 - smoothstep(r0, r1, d); }");
let distances = || (0.0f32..10.0, 0.0f32..1.0, 1.5f32..5.0);
let check = FunctionCheck::new("falloff", distances, |(d, r0, r1)| falloff(d, r0, r1))
    .tolerance(Tolerance::Absolute(1e-6));
let report = check.run(&Gpu::new()?, &shader, &RunConfig::default())?;
println!("{report}");
report.assert_passed();
# Ok::<(), shader_proptest::Error>(())
```

How a check runs:

1. [`Gpu::new`] opens Mesa's lavapipe (any machine runs it), or the device whose name contains
   the value of [`DEVICE_ENV`], with the Khronos validation layer on: any validation message
   fails the run. With the feature `wgpu`, `WgpuDevice` runs WGSL checks through wgpu instead.
2. The Rust layout of every `pod` struct among the arguments and the result is compared with
   the shader's ([`layout`]); a difference is [`Error::Layout`].
3. A generated compute kernel ([`kernel_source`]) reads each case's arguments as 32-bit words,
   calls the function once per invocation and writes the result's words back. The [`Shader`]'s
   source comes first: a WGSL module (compiled by naga), GLSL that `#include`s yours (compiled
   by glslang, as Vulkan's GLSL users compile it), Slang that `import`s yours (compiled by
   slangc), or HLSL that `#include`s yours (compiled by glslang's HLSL front end or by slangc:
   two languages, [`Language::HlslGlslang`] and [`Language::HlslSlangc`]). The function's signature, as the compiler reads it, is held against the Rust
   types; a difference is [`Error::Signature`], in Rust and in shader terms.
4. Cases come from a proptest strategy, generated batch by batch from per-batch seeds on every
   processor while the device runs the previous batch (one dispatch per batch).
5. Every output component is compared with the mirror's within a [`Tolerance`] (ULPs, absolute,
   relative, or a bound computed per case, for example by [`interval`] arithmetic with Vulkan's
   rounding allowances, [`tolerance`]); for finite inputs both results must be finite.
6. A failure is shrunk through the random words its strategy drew, many candidates per
   dispatch, until no single word can move toward a simpler input and still fail; the
   [`Report`] gives the inputs, both outputs, the tolerance, the seed that replays the run
   ([`SEED_ENV`]), the device and the kernel's source.

A [`RunConfig`] of 0 cases, a batch of 0 or 0 threads, and a [`SEED_ENV`] that holds no seed
(neither decimal nor hexadecimal after `0x`) end the run before it starts with
[`Error::Config`], which names the field or variable and its value. [`echo`] proves a struct's
layout on the device, bit for bit.
"#
)]
#![cfg_attr(
    not(feature = "gpu"),
    doc = r#"
This build is without the default feature `gpu`, which holds the checks (`FunctionCheck`, `Gpu`,
`RunConfig`, `Report`) and is documented on docs.rs, which builds every feature: what is here is
the compilers, the value descriptions, the tolerances and the layout reader.
"#
)]
//!
//! Arguments and results are [`Value`]s: `f32`, `u32`, `i32`, `bool`, glam's vectors and matrices,
//! and structs declared with [`shader_struct!`]; with `pod`, a `#[repr(C)]` bytemuck struct's Rust
//! layout is compared with the shader's before a check runs. [`layout`] compares layouts on its
//! own (naga's WGSL layout, glslang's and slangc's std140, std430 and scalar).
//!
//! Features: `gpu` (default) is the Vulkan device (ash), the checks and proptest; `wgpu` adds WGSL
//! checks through wgpu. Without `gpu` the crate is the compilers, the value descriptions and the
//! layout reader only. The crate needs, at run time, a Vulkan loader, a device, the validation
//! layer, and for GLSL `glslangValidator`, for Slang `slangc` and the compiler library installed
//! with it (loaded into the process: `compile_slang`), for HLSL the one of them that compiles it.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![deny(missing_docs)]

mod back;
pub mod compile;
pub mod declarations;
#[cfg(feature = "gpu")]
pub mod draw;
pub mod interval;
mod kernel;
mod language;
pub mod layout;
mod reflect;
mod shader;
#[cfg(feature = "gpu")]
mod signature;
pub mod spirv;
#[cfg(feature = "gpu")]
pub mod strategy;
pub mod tolerance;
mod tool;
pub mod value;

#[cfg(feature = "gpu")]
mod gpu;

pub use back::WORKGROUP_SIZE;
pub use compile::CompileError;
pub use kernel::{echo_kernel_source, kernel_source};
pub use language::Language;
pub use shader::{Feature, Shader};
pub use tolerance::Tolerance;
pub use value::{Args, ShaderType, StructType, Value};

#[cfg(feature = "wgpu")]
pub use gpu::WgpuDevice;
#[cfg(feature = "gpu")]
pub use gpu::{
    barrier_shader_writes, barrier_shader_writes_to_host, case_seed, echo, evaluate, run_checks, vulkan,
    Buffer, Check, ComputeKernel, DeviceRequest, Error, Failure, FunctionCheck, Gpu, Location,
    MetamorphicCheck, Object, Outcome, Owner, Phase, PhaseTimes, PreparedCheck, Report, RunConfig,
    DEVICE_ENV, MAX_VACUOUS, SEED_ENV,
};
#[cfg(feature = "browser")]
pub use gpu::{
    BrowserDevice, BrowserPage, Chromium, ChromiumOptions, Handler, LoopbackServer, Request, Response,
    CHROMIUM_ENV,
};
#[cfg(feature = "gpu")]
pub use {ash, proptest};
