//! WGSL checks through wgpu (feature `wgpu`), on whatever adapter wgpu opens: the same
//! [`FunctionCheck`], its kernel handed to wgpu as WGSL, its batches run through wgpu's compute
//! passes.
//!
//! Before wgpu sees the kernel, the check compares layouts and signatures and compiles the kernel
//! with naga, as on the Vulkan path; then wgpu validates it again with its own rules for the
//! adapter. wgpu's validation errors (error scopes around every call) fail the run; the Vulkan
//! validation layer is not consulted on this path. Tested on lavapipe through wgpu's Vulkan
//! backend; Metal and DX12 are enabled and untested here.

use super::check::{FunctionCheck, PreparedCheck, Report, RunConfig};
use super::compute::{Dispatch, KernelRun};
use super::device::DEVICE_ENV;
use super::error::Error;
use super::phases::{Phase, PhaseTimes};
use super::wgsl_device::WgslDevice;
use crate::shader::{Feature, Shader};
use crate::value::{Args, Value};
use std::time::Instant;
use wgpu::util::DeviceExt;

/// A wgpu device and its queue, on the adapter whose name contains [`DEVICE_ENV`], else a CPU
/// adapter (lavapipe, WARP), else the first adapter wgpu finds.
///
/// ```
/// use shader_proptest::proptest::prelude::*;
/// use shader_proptest::{FunctionCheck, RunConfig, Shader, WgpuDevice};
///
/// let device = WgpuDevice::new()?;
/// let check = FunctionCheck::new("half", || (-1.0f32..1.0,), |(x,)| 0.5 * x);
/// let shader = Shader::wgsl("fn half(x: f32) -> f32 { return 0.5 * x; }");
/// check.run_wgpu(&device, &shader, &RunConfig::default())?.assert_passed();
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct WgpuDevice {
    device: wgpu::Device,
    queue: wgpu::Queue,
    description: String,
}

impl WgpuDevice {
    /// Opens the adapter and a device on it with the adapter's limits.
    pub fn new() -> Result<WgpuDevice, Error> {
        pollster::block_on(Self::open())
    }

    async fn open() -> Result<WgpuDevice, Error> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::PRIMARY,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapters = instance.enumerate_adapters(wgpu::Backends::PRIMARY).await;
        let wanted = std::env::var(DEVICE_ENV).ok().map(|name| name.to_lowercase());
        let named = |adapter: &&wgpu::Adapter| match &wanted {
            Some(wanted) => adapter.get_info().name.to_lowercase().contains(wanted.as_str()),
            None => adapter.get_info().device_type == wgpu::DeviceType::Cpu,
        };
        let adapter = adapters
            .iter()
            .find(named)
            .or(adapters.first().filter(|_| wanted.is_none()))
            .ok_or_else(|| {
                let names: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
                Error::Setup(format!(
                    "no wgpu adapter matches {DEVICE_ENV}={wanted:?} among {names:?}"
                ))
            })?;
        let info = adapter.get_info();
        let descriptor = wgpu::DeviceDescriptor {
            required_features: adapter.features() & wgpu::Features::SHADER_F64,
            required_limits: adapter.limits(),
            ..wgpu::DeviceDescriptor::default()
        };
        let (device, queue) = adapter
            .request_device(&descriptor)
            .await
            .map_err(|error| Error::Setup(format!("wgpu request_device: {error}")))?;
        Ok(WgpuDevice {
            device,
            queue,
            description: format!(
                "{} through wgpu's {:?} backend, driver {} ({})",
                info.name, info.backend, info.driver, info.driver_info
            ),
        })
    }

    /// Runs `call` inside an error scope: a validation error of wgpu fails it.
    fn validated<T>(&self, call: impl FnOnce() -> T) -> Result<T, Error> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let value = call();
        match pollster::block_on(scope.pop()) {
            Some(error) => Err(Error::Validation(vec![error.to_string()])),
            None => Ok(value),
        }
    }
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// Runs the check on the WGSL function of `shader` through wgpu (see [`FunctionCheck::run`]).
    /// GLSL and Slang shaders are refused ([`Error::Setup`]): wgpu takes WGSL.
    pub fn run_wgpu(
        &self,
        device: &WgpuDevice,
        shader: &Shader,
        config: &RunConfig,
    ) -> Result<Report, Error> {
        let prepared = self.prepare_wgpu(device, shader)?;
        self.run_prepared_one(prepared, config)
    }

    /// [`FunctionCheck::prepare`] through wgpu: layouts, signature, naga's compilation, then wgpu's
    /// shader module and pipeline.
    pub fn prepare_wgpu<'g>(
        &self,
        device: &'g WgpuDevice,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error> {
        self.prepare_wgsl(device, shader)
    }
}

impl WgslDevice for WgpuDevice {
    const TAKER: &'static str = "wgpu";

    fn description(&self) -> String {
        self.description.clone()
    }

    /// Only 64-bit floats are available through wgpu's compute path.
    fn missing_feature(&self, features: &[Feature]) -> Option<String> {
        let has = |feature: Feature| match feature {
            Feature::ShaderFloat64 => self.device.features().contains(wgpu::Features::SHADER_F64),
            _ => false,
        };
        features
            .iter()
            .find(|&&feature| !has(feature))
            .map(|feature| format!("{} lacks {}", self.description, feature.name()))
    }

    fn pipeline<'g>(&'g self, kernel: &str) -> Result<Box<dyn Dispatch + 'g>, Error> {
        Ok(Box::new(WgpuKernel::new(self, kernel)?))
    }
}

/// A compute pipeline of a call kernel on a wgpu device.
struct WgpuKernel<'g> {
    device: &'g WgpuDevice,
    pipeline: wgpu::ComputePipeline,
}

impl<'g> WgpuKernel<'g> {
    /// wgpu's shader module of the WGSL `kernel` and a pipeline of its `main`.
    fn new(device: &'g WgpuDevice, kernel: &str) -> Result<WgpuKernel<'g>, Error> {
        let gpu = &device.device;
        let pipeline = device
            .validated(|| {
                let module = gpu.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("kernel"),
                    source: wgpu::ShaderSource::Wgsl(kernel.into()),
                });
                gpu.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("kernel"),
                    layout: None,
                    module: &module,
                    entry_point: Some("main"),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    cache: None,
                })
            })
            .map_err(|error| Error::Compile(format!("{error}\n--- kernel ---\n{kernel}")))?;
        Ok(WgpuKernel { device, pipeline })
    }

    /// A storage buffer holding `words`, with `usage` besides.
    fn storage(&self, label: &str, words: &[u32], usage: wgpu::BufferUsages) -> wgpu::Buffer {
        self.device
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(words),
                usage: wgpu::BufferUsages::STORAGE | usage,
            })
    }
}

impl Dispatch for WgpuKernel<'_> {
    fn dispatch(&self, run: KernelRun<'_>, times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
        let mut clock = Instant::now();
        let gpu = &self.device.device;
        let groups = run.groups(gpu.limits().max_compute_workgroups_per_dimension)?;
        let bytes = (run.output_words.max(1) * 4) as u64;
        let readback = self.device.validated(|| {
            let input = self.storage("kernel_inputs", run.input, wgpu::BufferUsages::empty());
            let output = self.storage(
                "kernel_outputs",
                &vec![0; run.output_words],
                wgpu::BufferUsages::COPY_SRC,
            );
            let readback = gpu.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind_group = gpu.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &self.pipeline.get_bind_group_layout(0),
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: input.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: output.as_entire_binding(),
                    },
                ],
            });
            times.lap(Phase::Upload, &mut clock);
            let mut encoder = gpu.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(groups, 1, 1);
            }
            encoder.copy_buffer_to_buffer(&output, 0, &readback, 0, bytes);
            self.device.queue.submit([encoder.finish()]);
            readback
        })?;
        let slice = readback.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        gpu.poll(wgpu::PollType::wait_indefinitely())
            .map_err(|error| Error::Setup(format!("wgpu poll: {error}")))?;
        times.lap(Phase::Dispatch, &mut clock);
        let view = slice
            .get_mapped_range()
            .map_err(|error| Error::Setup(format!("wgpu reading the results: {error}")))?;
        let output = bytemuck::cast_slice(&view)[..run.output_words].to_vec();
        times.lap(Phase::ReadBack, &mut clock);
        Ok(output)
    }
}
