//! The GPU harness (feature `gpu`): runs the shader modules on a Vulkan device and compares every
//! function with its Rust mirror.
//!
//! [`Gpu`] opens lavapipe (or the device named by `RAY_FOOTPRINT_DEVICE`) with the Khronos validation
//! layer on; any validation message fails the run. A [`FunctionCheck`] wraps one shader function in a
//! generated compute kernel ([`kernel_source`]), compiled by naga (WGSL) or glslang (GLSL), generates
//! batches of inputs with proptest, dispatches each batch once, and compares the read-back words with
//! the mirror within a tolerance derived from Vulkan's precision rules ([`tolerance`]).
//!
//! ```no_run
//! use ray_footprint::gpu::{suite, Gpu, Language, RunConfig};
//!
//! let gpu = Gpu::new()?;
//! for check in suite::all_checks() {
//!     for language in Language::ALL {
//!         println!("{}", check.run(&gpu, language, &RunConfig::default())?);
//!     }
//! }
//! # Ok::<(), ray_footprint::gpu::GpuError>(())
//! ```

mod check;
mod device;
mod kernel;
pub mod rt;
pub mod strategy;
pub mod suite;
pub mod tolerance;
mod value;

pub use check::{Check, FunctionCheck, Report, RunConfig};
pub use device::{Gpu, GpuError, Pipeline, DEVICE_ENV, RAY_TRACING_EXTENSIONS, SETUP_COMMAND};
pub use kernel::{compile, echo_kernel_source, kernel_source, naga_capabilities, Language};
pub use value::{GpuArgs, GpuValue, ShaderType, StructType, HIT_PAYLOAD, RAY_CONE, RAY_CONE_PUSH_CONSTANTS};
