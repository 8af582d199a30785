//! Compute kernels on the device: a pipeline over two storage buffers (binding 0 the input words,
//! binding 1 the output words) and an optional push-constant block, dispatched once per batch.
//! The buffers and their descriptor set are made by the first dispatch and reused by the next
//! ones while they are large enough.

use super::device::Gpu;
use super::error::Error;
use super::lock::lock;
use super::phases::{Phase, PhaseTimes};
use super::resources::{barrier_shader_writes_to_host, Buffer, Location, Owner};
use crate::back::WORKGROUP_SIZE;
use ash::vk;
use std::sync::Mutex;
use std::time::Instant;

/// A compiled kernel on a device that runs cases in batches: `invocations` invocations over the
/// `input` words, returning the first `output_words` output words, one dispatch per call,
/// waited for, its upload, dispatch and read-back timed into `times`. A check runs on any device
/// that gives it one ([`ComputeKernel`] on Vulkan through ash; the `wgpu` feature's kernels
/// through wgpu).
pub(crate) trait Dispatch: Send + Sync {
    /// Runs one batch; a validation message fails it.
    fn dispatch(&self, run: KernelRun<'_>, times: &mut PhaseTimes) -> Result<Vec<u32>, Error>;
}

/// One batch of a kernel: `invocations` invocations over the `input` words, returning the first
/// `output_words` output words.
#[derive(Clone, Copy)]
pub(crate) struct KernelRun<'a> {
    pub invocations: usize,
    pub input: &'a [u32],
    pub output_words: usize,
}

impl<'a> KernelRun<'a> {
    /// `invocations` cases over `input`, each returning `words` words.
    pub(crate) fn per_case(invocations: usize, input: &'a [u32], words: usize) -> KernelRun<'a> {
        KernelRun {
            invocations,
            input,
            output_words: invocations * words,
        }
    }

    /// The workgroups of [`WORKGROUP_SIZE`] invocations that cover the batch; an error where they
    /// are more than the device's `limit` per dispatch.
    pub(crate) fn groups(&self, limit: u32) -> Result<u32, Error> {
        let groups = self.invocations.div_ceil(WORKGROUP_SIZE as usize);
        u32::try_from(groups)
            .ok()
            .filter(|&groups| groups <= limit)
            .ok_or(Error::BatchTooLarge(self.invocations))
    }
}

impl Dispatch for ComputeKernel<'_> {
    fn dispatch(&self, run: KernelRun<'_>, times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
        self.dispatch_timed(run, &[], times)
    }
}

/// A compute pipeline for one kernel whose entry point is `main`; destroys itself when dropped.
pub struct ComputeKernel<'g> {
    owner: Owner<'g>,
    pipeline: vk::Pipeline,
    layout: vk::PipelineLayout,
    set_layout: vk::DescriptorSetLayout,
    push_constant_bytes: u32,
    /// The buffers of the last dispatch, kept for the next one.
    io: Mutex<Option<KernelIo<'g>>>,
}

/// A kernel's input and output buffers and the descriptor set that binds them.
struct KernelIo<'g> {
    /// Owns the buffers, their memory and the descriptor pool.
    owner: Owner<'g>,
    input: Buffer,
    output: Buffer,
    set: vk::DescriptorSet,
}

impl KernelIo<'_> {
    /// Whether the buffers hold `input_bytes` and `output_bytes`.
    fn holds(&self, input_bytes: u64, output_bytes: u64) -> bool {
        self.input.size >= input_bytes && self.output.size >= output_bytes
    }
}

impl<'g> ComputeKernel<'g> {
    /// A pipeline for the kernel `spirv`, with a push-constant range of `push_constant_bytes`
    /// (0 for none).
    pub fn new(gpu: &'g Gpu, spirv: &[u32], push_constant_bytes: u32) -> Result<ComputeKernel<'g>, Error> {
        let mut owner = Owner::new(gpu);
        let ranges = [vk::PushConstantRange::default()
            .stage_flags(vk::ShaderStageFlags::COMPUTE)
            .size(push_constant_bytes)];
        let ranges = if push_constant_bytes == 0 {
            &ranges[..0]
        } else {
            &ranges[..]
        };
        let (set_layout, layout) = owner.compute_storage_layouts(2, ranges)?;
        let pipeline = owner.compute_pipeline(spirv, layout)?;
        Ok(ComputeKernel {
            owner,
            pipeline,
            layout,
            set_layout,
            push_constant_bytes,
            io: Mutex::new(None),
        })
    }

    /// Runs `invocations` invocations over `input` and returns the first `output_words` words of
    /// the output buffer. One dispatch, waited for; validation messages fail the call.
    pub fn dispatch(
        &self,
        invocations: usize,
        input: &[u32],
        output_words: usize,
    ) -> Result<Vec<u32>, Error> {
        self.dispatch_with_push_constants(invocations, input, output_words, &[])
    }

    /// [`ComputeKernel::dispatch`] with `push_constants` (the range is filled from the start;
    /// missing bytes are zero).
    pub fn dispatch_with_push_constants(
        &self,
        invocations: usize,
        input: &[u32],
        output_words: usize,
        push_constants: &[u8],
    ) -> Result<Vec<u32>, Error> {
        let run = KernelRun {
            invocations,
            input,
            output_words,
        };
        self.dispatch_timed(run, push_constants, &mut PhaseTimes::default())
    }

    /// [`ComputeKernel::dispatch_with_push_constants`], its upload, dispatch and read-back timed
    /// into `times`.
    fn dispatch_timed(
        &self,
        run: KernelRun<'_>,
        push_constants: &[u8],
        times: &mut PhaseTimes,
    ) -> Result<Vec<u32>, Error> {
        let mut clock = Instant::now();
        let gpu = self.owner.gpu;
        let groups = run.groups(gpu.properties().limits.max_compute_work_group_count[0])?;
        let (input_bytes, output_bytes) = (
            (run.input.len().max(1) * 4) as u64,
            (run.output_words.max(1) * 4) as u64,
        );
        let mut io = lock(&self.io);
        if !io.as_ref().is_some_and(|io| io.holds(input_bytes, output_bytes)) {
            // The old buffers go first, so that only one set is alive at a time.
            *io = None;
            *io = Some(self.kernel_io(input_bytes, output_bytes)?);
        }
        let io = io.as_ref().expect("made above");
        io.owner.write(&io.input, bytemuck::cast_slice(run.input))?;
        let mut push = vec![0u8; self.push_constant_bytes as usize];
        let used = push_constants.len().min(push.len());
        push[..used].copy_from_slice(&push_constants[..used]);
        times.lap(Phase::Upload, &mut clock);
        let buffers = [(io.input.buffer, input_bytes), (io.output.buffer, output_bytes)];
        // Bound within the submission, so that its validation messages are the submission's.
        io.owner.submit(|device, command_buffer| {
            self.bind(io.set, buffers);
            self.record(device, command_buffer, io.set, &push, groups);
        })?;
        times.lap(Phase::Dispatch, &mut clock);
        let output = io.owner.read(&io.output, run.output_words);
        times.lap(Phase::ReadBack, &mut clock);
        output
    }

    /// Host buffers of `input_bytes` and `output_bytes` and a descriptor set binding them.
    fn kernel_io(&self, input_bytes: u64, output_bytes: u64) -> Result<KernelIo<'g>, Error> {
        let mut owner = Owner::new(self.owner.gpu);
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let input = owner.buffer(input_bytes, storage, Location::Host, 4)?;
        let output = owner.buffer(output_bytes, storage, Location::Host, 4)?;
        let set = self.descriptor_set(&mut owner)?;
        Ok(KernelIo {
            owner,
            input,
            output,
            set,
        })
    }

    /// A descriptor set of the kernel's layout, from a pool `owner` owns.
    fn descriptor_set(&self, owner: &mut Owner<'_>) -> Result<vk::DescriptorSet, Error> {
        let sizes = [vk::DescriptorPoolSize::default()
            .ty(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(2)];
        owner.descriptor_set(self.set_layout, &sizes)
    }

    /// Binds the first `bytes` of each of `buffers` as bindings 0 and 1 of `set` (the kernel sees
    /// exactly the dispatch's words, whatever the buffers' capacity). `set` is not in use.
    fn bind(&self, set: vk::DescriptorSet, buffers: [(vk::Buffer, u64); 2]) {
        let infos =
            buffers.map(|(buffer, bytes)| [vk::DescriptorBufferInfo::default().buffer(buffer).range(bytes)]);
        let writes = [0, 1].map(|binding| {
            vk::WriteDescriptorSet::default()
                .dst_set(set)
                .dst_binding(binding as u32)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&infos[binding])
        });
        // SAFETY: the writes match the set layout; every submission that used `set` was waited for.
        unsafe { self.owner.device().update_descriptor_sets(&writes, &[]) };
    }

    /// Records the dispatch and makes its writes visible to the host.
    fn record(
        &self,
        device: &ash::Device,
        command_buffer: vk::CommandBuffer,
        set: vk::DescriptorSet,
        push: &[u8],
        groups: u32,
    ) {
        // SAFETY: recording into a command buffer in the recording state; every handle is alive.
        unsafe {
            device.cmd_bind_pipeline(command_buffer, vk::PipelineBindPoint::COMPUTE, self.pipeline);
            device.cmd_bind_descriptor_sets(
                command_buffer,
                vk::PipelineBindPoint::COMPUTE,
                self.layout,
                0,
                &[set],
                &[],
            );
            if !push.is_empty() {
                device.cmd_push_constants(
                    command_buffer,
                    self.layout,
                    vk::ShaderStageFlags::COMPUTE,
                    0,
                    push,
                );
            }
            device.cmd_dispatch(command_buffer, groups, 1, 1);
            barrier_shader_writes_to_host(device, command_buffer, vk::PipelineStageFlags::COMPUTE_SHADER);
        }
    }
}
