//! The device side (feature `gpu`): a Vulkan device with the validation layer on, the objects made
//! on it, compute kernels, and the checks that run on them.

#[cfg(feature = "browser")]
mod browser;
mod call;
mod check;
mod compute;
mod device;
mod echo;
mod error;
mod lock;
mod phases;
mod resources;
mod submission;
mod suite;
#[cfg(feature = "wgpu")]
mod wgpu_device;
#[cfg(any(feature = "wgpu", feature = "browser"))]
mod wgsl_device;

#[cfg(feature = "browser")]
pub use browser::{
    BrowserDevice, BrowserPage, Chromium, ChromiumOptions, Handler, LoopbackServer, Request, Response,
    CHROMIUM_ENV,
};
pub use check::{
    case_seed, evaluate, Check, Failure, FunctionCheck, MetamorphicCheck, Outcome, PreparedCheck, Report,
    RunConfig, MAX_VACUOUS, SEED_ENV,
};
pub use compute::ComputeKernel;
pub use device::{DeviceRequest, Gpu, DEVICE_ENV};
pub use echo::echo;
pub use error::{vulkan, Error};
pub use phases::{Phase, PhaseTimes};
pub use resources::{barrier_shader_writes, barrier_shader_writes_to_host, Buffer, Location, Object, Owner};
pub use suite::run_checks;
#[cfg(feature = "wgpu")]
pub use wgpu_device::WgpuDevice;
