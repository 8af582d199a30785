//! Colour-only rendering, and its timing with GPU timestamps: the pixels a user's renderer would
//! produce in one mode, with no per-pixel records. The shaders (`colour_*` in `shaders/`) are
//! compiled once per mode, so each computes only what its mode needs, and their payload carries
//! only that ([`Mode::payload`]). [`Renderer::time_colour_frames`] times frames of several modes
//! back to back in one submission ([`crate::timing`]).

use super::super::abi::{RtPushConstants, RtUniforms};
use super::super::mode::Mode;
use super::super::pipeline::{self, RayTracing, COLOUR_STAGES, SHADER_DIR};
use super::{Error, Frame, Records, Renderer, Target};
use crate::timing::{median, query_pool, read_queries, round_order, write_timestamp, Timestamps};
use ash::vk;
use ray_footprint::shaders::GLSL_INCLUDE_DIR;
use shader_proptest::layout::{glsl_layout, GlslPacking};
use shader_proptest::{barrier_shader_writes, barrier_shader_writes_to_host, Owner};
use std::path::Path;
use std::time::Duration;

/// What one timed run of frames traces: a pipeline, and the push constants of each sub-pixel
/// sample of a frame.
pub type Timed<'a, 'r, 'g> = (&'a ColourPipeline<'r, 'g>, &'a [RtPushConstants]);

/// One mode's colour-only ray-tracing pipeline over a [`Renderer`]'s scene.
pub struct ColourPipeline<'r, 'g> {
    renderer: &'r Renderer<'g>,
    mode: Mode,
    owner: Owner<'g>,
    ray_tracing: RayTracing,
    closest_hit: Vec<u32>,
    payload_bytes: u32,
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
        target.render(push, |device, command_buffer| {
            self.trace(device, command_buffer, &target, push);
            // SAFETY: recording into a command buffer in the recording state.
            unsafe { barrier_shader_writes_to_host(device, command_buffer, self.owner.shader_stages()) };
        })
    }

    /// Records into `command_buffer` (recording) one trace with `push` into `target`, and a
    /// barrier after it: the next trace writes the same colours.
    fn trace(
        &self,
        device: &ash::Device,
        command_buffer: vk::CommandBuffer,
        target: &Target<'_>,
        push: &RtPushConstants,
    ) {
        let bind_point = vk::PipelineBindPoint::RAY_TRACING_KHR;
        self.renderer.bind(
            command_buffer,
            (bind_point, self.ray_tracing.pipeline),
            target.set,
            push,
        );
        self.ray_tracing.trace(command_buffer, push.width, push.height);
        let stage = vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR;
        let readers = (
            stage,
            vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE,
        );
        // SAFETY: recording into a command buffer in the recording state.
        unsafe { barrier_shader_writes(device, command_buffer, stage, readers) };
    }
}

impl<'g> Renderer<'g> {
    /// Times frames of colour-only pipelines in one submission: for each `((pipeline, samples),
    /// frames)` of `runs` in order, `frames` frames, each tracing every sample of `samples` (the
    /// push constants of one sub-pixel sample each, all of one image size in every run; their
    /// `mode` is not read), with a timestamp before and after each frame and nothing between two
    /// frames but a barrier (each trace writes the same colours, so each waits for the one
    /// before). Returns each run's frame times. The colours of a sample overwrite the last one's: the timing leaves out the sum a
    /// renderer would keep (a read and a write per pixel per sample). Fails with
    /// [`Error::NotSupported`] on a queue without timestamps.
    pub fn time_colour_frames(
        &self,
        runs: &[(Timed<'_, '_, 'g>, usize)],
        uniforms: &RtUniforms,
    ) -> Result<Vec<Vec<Duration>>, Error> {
        let first = runs
            .iter()
            .find_map(|((_, samples), _)| samples.first())
            .ok_or_else(|| Error::NotSupported(String::from("a frame needs a sample")))?;
        let timestamps = Timestamps::of(self.owner.gpu).map_err(Error::NotSupported)?;
        let mut target = self.target(first, uniforms, Records::StandIn)?;
        let queries: usize = 2 * runs.iter().map(|&(_, frames)| frames).sum::<usize>();
        let pool = query_pool(&mut target.owner, queries.max(2) as u32)?;
        target.owner.submit(|device, command_buffer| {
            // SAFETY: recording into a command buffer in the recording state; the pool is alive.
            unsafe { device.cmd_reset_query_pool(command_buffer, pool, 0, queries.max(2) as u32) };
            let mut query = 0;
            for &((pipeline, samples), frames) in runs {
                for _ in 0..frames {
                    // SAFETY: as above; each query was reset at the start.
                    unsafe { write_timestamp(device, command_buffer, pool, query) };
                    for sample in samples {
                        pipeline.trace(device, command_buffer, &target, sample);
                    }
                    // SAFETY: as above.
                    unsafe { write_timestamp(device, command_buffer, pool, query + 1) };
                    query += 2;
                }
            }
        })?;
        let times = timestamps.pairs(&read_queries(&target.owner, pool, queries)?);
        let mut runs_times = Vec::with_capacity(runs.len());
        let mut rest = &times[..];
        for &(_, frames) in runs {
            let (run, after) = rest.split_at(frames);
            runs_times.push(run.to_vec());
            rest = after;
        }
        Ok(runs_times)
    }
}

impl<'g> Renderer<'g> {
    /// Round `round` of an interleaved timing: `frames` frames of every entry of `timed` (a
    /// pipeline and its samples) in the round's order ([`round_order`]: reversed every other
    /// round), as [`Renderer::time_colour_frames`] times them; each entry's median frame time in
    /// ms, in the order of `timed`.
    pub fn time_colour_round(
        &self,
        timed: &[Timed<'_, '_, 'g>],
        uniforms: &RtUniforms,
        (frames, round): (usize, usize),
    ) -> Result<Vec<f64>, Error> {
        let order = round_order(timed.len(), round);
        let runs: Vec<_> = order.iter().map(|&index| (timed[index], frames)).collect();
        let times = self.time_colour_frames(&runs, uniforms)?;
        let mut medians = vec![0.0; timed.len()];
        for (&index, run_times) in order.iter().zip(&times) {
            let ms: Vec<f64> = run_times.iter().map(|t| t.as_secs_f64() * 1e3).collect();
            medians[index] = median(&ms);
        }
        Ok(medians)
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
