//! Colour-only rendering, and its timing with GPU timestamps: the pixels a user's renderer would
//! produce in one mode, with no per-pixel records. The shaders (`colour_*` in `shaders/`) are
//! compiled once per mode, so each computes only what its mode needs, and their payload carries
//! only that ([`Mode::payload`]).

use super::super::abi::{RtPushConstants, RtUniforms};
use super::super::mode::Mode;
use super::super::pipeline::{self, RayTracing, COLOUR_STAGES, SHADER_DIR};
use super::{Error, Frame, Records, Renderer, Target};
use ash::vk;
use ray_footprint::shaders::GLSL_INCLUDE_DIR;
use shader_proptest::layout::{glsl_layout, GlslPacking};
use shader_proptest::{barrier_shader_writes_to_host, vulkan, Gpu, Object, Owner};
use std::path::Path;
use std::time::{Duration, Instant};

/// One mode's colour-only ray-tracing pipeline over a [`Renderer`]'s scene.
pub struct ColourPipeline<'r, 'g> {
    renderer: &'r Renderer<'g>,
    mode: Mode,
    owner: Owner<'g>,
    ray_tracing: RayTracing,
    closest_hit: Vec<u32>,
    payload_bytes: u32,
}

/// The device's timestamps: nanoseconds per tick and the bits that count.
#[derive(Clone, Copy, Debug)]
struct Timestamps {
    period_ns: f64,
    valid_bits: u32,
}

impl<'g> Renderer<'g> {
    /// Compiles the colour-only shaders of `mode` and makes their pipeline.
    pub fn colour_pipeline(&self, mode: Mode) -> Result<ColourPipeline<'_, 'g>, Error> {
        let defines = mode.colour_defines();
        let spirv = pipeline::compile_stages(COLOUR_STAGES, &defines)?;
        let mut owner = Owner::new(self.owner.gpu);
        let ray_tracing = pipeline::ray_tracing_pipeline(&mut owner, self.layout, &spirv)?;
        Ok(ColourPipeline {
            renderer: self,
            mode,
            owner,
            ray_tracing,
            closest_hit: spirv[2].clone(),
            payload_bytes: payload_bytes(&defines)?,
        })
    }
}

impl ColourPipeline<'_, '_> {
    /// The mode the shaders were compiled for (the push constants' `mode` is not read).
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Bytes of the ray payload (`RtColourPayload` in the scalar layout: its members' sizes).
    pub fn payload_bytes(&self) -> u32 {
        self.payload_bytes
    }

    /// The closest-hit shader as glslang compiled it, as SPIR-V words.
    pub fn closest_hit_spirv(&self) -> &[u32] {
        &self.closest_hit
    }

    /// Traces a frame: its colours only (`records` is empty); `trace_time` is the wall time from
    /// submission to completion.
    pub fn render(&self, push: &RtPushConstants, uniforms: &RtUniforms) -> Result<Frame, Error> {
        let target = self.renderer.target(push, uniforms, Records::StandIn)?;
        let started = Instant::now();
        target
            .owner
            .submit(|device, command_buffer| self.record(device, command_buffer, &target, push, None))?;
        let trace_time = started.elapsed();
        Ok(Frame {
            width: push.width,
            height: push.height,
            pixels: target.owner.read(&target.colours, target.pixels)?,
            records: Vec::new(),
            trace_time,
        })
    }

    /// Traces `warm_up` untimed frames, then `frames` frames each bracketed by GPU timestamps
    /// (one submission per frame, waited for); returns each timed frame's GPU time. Fails with
    /// [`Error::NotSupported`] on a queue without timestamps.
    pub fn time(
        &self,
        push: &RtPushConstants,
        uniforms: &RtUniforms,
        warm_up: usize,
        frames: usize,
    ) -> Result<Vec<Duration>, Error> {
        let timestamps = timestamps(self.owner.gpu)?;
        let mut target = self.renderer.target(push, uniforms, Records::StandIn)?;
        let pool = query_pool(&mut target.owner)?;
        let mut times = Vec::with_capacity(frames);
        for frame in 0..warm_up + frames {
            target.owner.submit(|device, command_buffer| {
                self.record(device, command_buffer, &target, push, Some(pool))
            })?;
            let mut ticks = [0u64; 2];
            // SAFETY: the submission that wrote both queries was waited for.
            unsafe {
                self.owner.device().get_query_pool_results(
                    pool,
                    0,
                    &mut ticks,
                    vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
                )
            }
            .map_err(|e| Error::Gpu(vulkan("vkGetQueryPoolResults")(e)))?;
            if frame >= warm_up {
                times.push(timestamps.elapsed(ticks));
            }
        }
        Ok(times)
    }

    /// Records one trace into `command_buffer`, between two timestamps in `timing` when given,
    /// then makes its writes visible to the host.
    fn record(
        &self,
        device: &ash::Device,
        command_buffer: vk::CommandBuffer,
        target: &Target<'_>,
        push: &RtPushConstants,
        timing: Option<vk::QueryPool>,
    ) {
        if let Some(pool) = timing {
            // SAFETY: recording into a command buffer in the recording state; the pool is alive.
            unsafe {
                device.cmd_reset_query_pool(command_buffer, pool, 0, 2);
                device.cmd_write_timestamp(command_buffer, vk::PipelineStageFlags::TOP_OF_PIPE, pool, 0);
            }
        }
        let bind_point = vk::PipelineBindPoint::RAY_TRACING_KHR;
        self.renderer.bind(
            command_buffer,
            (bind_point, self.ray_tracing.pipeline),
            target.set,
            push,
        );
        self.ray_tracing.trace(command_buffer, push.width, push.height);
        // SAFETY: recording into a command buffer in the recording state; the pool is alive.
        unsafe {
            if let Some(pool) = timing {
                device.cmd_write_timestamp(command_buffer, vk::PipelineStageFlags::BOTTOM_OF_PIPE, pool, 1);
            }
            barrier_shader_writes_to_host(device, command_buffer, self.owner.shader_stages());
        }
    }
}

/// The size of `RtColourPayload` compiled with `defines`, in the scalar layout (glslang's).
fn payload_bytes(defines: &[(&str, String)]) -> Result<u32, Error> {
    let source: String = defines
        .iter()
        .map(|(name, value)| format!("#define {name} {value}\n"))
        .chain([String::from("#include \"colour_payload.glsl\"")])
        .collect();
    let include_dirs = [Path::new(GLSL_INCLUDE_DIR), Path::new(SHADER_DIR)];
    glsl_layout(&source, "RtColourPayload", GlslPacking::Scalar, &include_dirs)
        .map(|layout| layout.size)
        .map_err(|error| Error::Gpu(shader_proptest::Error::Compile(error.to_string())))
}

/// The timestamps of `gpu`'s queue, or why it has none.
fn timestamps(gpu: &Gpu) -> Result<Timestamps, Error> {
    let limits = gpu.properties().limits;
    // SAFETY: a plain query.
    let families = unsafe {
        gpu.instance()
            .get_physical_device_queue_family_properties(gpu.physical_device())
    };
    let valid_bits = families
        .get(gpu.queue_family() as usize)
        .map_or(0, |family| family.timestamp_valid_bits);
    if valid_bits == 0 {
        let compute_and_graphics = limits.timestamp_compute_and_graphics == vk::TRUE;
        return Err(Error::NotSupported(format!(
            "{}: queue family {} has timestampValidBits 0 (timestampComputeAndGraphics {compute_and_graphics})",
            gpu.name(),
            gpu.queue_family()
        )));
    }
    Ok(Timestamps {
        period_ns: f64::from(limits.timestamp_period),
        valid_bits,
    })
}

impl Timestamps {
    /// The time between two timestamps, counting only the valid bits (which may wrap).
    fn elapsed(self, [start, end]: [u64; 2]) -> Duration {
        let mask = if self.valid_bits >= 64 {
            u64::MAX
        } else {
            (1u64 << self.valid_bits) - 1
        };
        let ticks = end.wrapping_sub(start) & mask;
        Duration::from_secs_f64(ticks as f64 * self.period_ns * 1e-9)
    }
}

/// A pool of two timestamp queries, kept by `owner`.
fn query_pool(owner: &mut Owner<'_>) -> Result<vk::QueryPool, Error> {
    let info = vk::QueryPoolCreateInfo::default()
        .query_type(vk::QueryType::TIMESTAMP)
        .query_count(2);
    // SAFETY: a valid create-info; the pool is handed to the owner.
    let pool = unsafe { owner.device().create_query_pool(&info, None) }
        .map_err(|e| Error::Gpu(vulkan("vkCreateQueryPool")(e)))?;
    Ok(owner.keep(pool, Object::QueryPool))
}
