//! Submitting recorded commands from several threads at once: a fixed set of command buffers, each
//! with its pool and fence, that threads take one each, over the queues the device was created
//! with.

use super::error::{vulkan, Error};
use super::lock::lock;
use ash::vk;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, MutexGuard};

/// How many command buffers a device keeps for submissions (threads beyond that many wait for
/// one), and the most queues it asks for. `run_checks` dispatches from ten threads at once.
pub(crate) const SUBMITTERS: usize = 16;

/// A command buffer, the pool it comes from and the fence its submission signals, made once and
/// reused, with the lock that gives them to one thread at a time, from recording to the fence's
/// signal.
struct Submitter {
    pool: vk::CommandPool,
    command_buffer: vk::CommandBuffer,
    fence: vk::Fence,
    /// The queue it submits to, an index into [`Submission::queues`].
    queue: usize,
    turn: Mutex<()>,
}

/// The queues of one family and the submitters that share them out (submitter `i` submits to
/// queue `i mod count`).
pub(crate) struct Submission {
    /// A queue is used by one `vkQueueSubmit` at a time.
    queues: Vec<Mutex<vk::Queue>>,
    submitters: Vec<Submitter>,
    /// Where the next search for a free submitter starts.
    next: AtomicUsize,
}

impl Submission {
    /// Submitters over the first `queue_count` queues of `family`, which `device` was created
    /// with. On failure, what was made is destroyed.
    pub(crate) fn new(device: &ash::Device, family: u32, queue_count: u32) -> Result<Submission, Error> {
        // SAFETY: queues of the family the device was created with, indices below its count.
        let queues = (0..queue_count)
            .map(|index| Mutex::new(unsafe { device.get_device_queue(family, index) }))
            .collect();
        let mut submission = Submission {
            queues,
            submitters: Vec::with_capacity(SUBMITTERS),
            next: AtomicUsize::new(0),
        };
        for index in 0..SUBMITTERS {
            match submitter(device, family, index % queue_count as usize) {
                Ok(submitter) => submission.submitters.push(submitter),
                Err(error) => {
                    // SAFETY: nothing made so far has been used.
                    unsafe { submission.destroy(device) };
                    return Err(error);
                }
            }
        }
        Ok(submission)
    }

    /// How many queues the submissions go to.
    pub(crate) fn queue_count(&self) -> usize {
        self.queues.len()
    }

    /// Records a command buffer with `record`, submits it and waits for it, on a free submitter.
    /// `check_messages` is called after the submission and after the wait, and fails the call
    /// with the validation messages it finds.
    pub(crate) fn submit(
        &self,
        device: &ash::Device,
        record: impl FnOnce(&ash::Device, vk::CommandBuffer),
        check_messages: impl Fn() -> Result<(), Error>,
    ) -> Result<(), Error> {
        let (submitter, _turn) = self.take();
        // SAFETY: the submitter's command buffer and fence are used by the holder of its turn
        // only, and the turn is held until the fence has signalled (or the wait failed, after
        // which the device is lost); its queue is used under the queue's lock.
        unsafe {
            device
                .reset_fences(&[submitter.fence])
                .map_err(vulkan("vkResetFences"))?;
            let command_buffer = submitter.command_buffer;
            device
                .reset_command_buffer(command_buffer, vk::CommandBufferResetFlags::empty())
                .map_err(vulkan("vkResetCommandBuffer"))?;
            let begin =
                vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            device
                .begin_command_buffer(command_buffer, &begin)
                .map_err(vulkan("vkBeginCommandBuffer"))?;
            record(device, command_buffer);
            device
                .end_command_buffer(command_buffer)
                .map_err(vulkan("vkEndCommandBuffer"))?;
            let buffers = [command_buffer];
            let submit = [vk::SubmitInfo::default().command_buffers(&buffers)];
            {
                let queue = lock(&self.queues[submitter.queue]);
                device
                    .queue_submit(*queue, &submit, submitter.fence)
                    .map_err(vulkan("vkQueueSubmit"))?;
            }
            let submitted = check_messages();
            let waited = device
                .wait_for_fences(&[submitter.fence], true, u64::MAX)
                .map_err(vulkan("vkWaitForFences"));
            submitted.and(waited).and(check_messages())
        }
    }

    /// Destroys the fences and pools (their command buffers with them).
    ///
    /// # Safety
    /// No submission is pending, and none is made afterwards.
    pub(crate) unsafe fn destroy(&self, device: &ash::Device) {
        for submitter in &self.submitters {
            // SAFETY: the caller's promise; each object was made by `device`.
            unsafe {
                device.destroy_fence(submitter.fence, None);
                device.destroy_command_pool(submitter.pool, None);
            }
        }
    }

    /// A submitter and its turn: the first free one from where the last search started, or, when
    /// every one is busy, the starting one's turn once its holder lets go.
    fn take(&self) -> (&Submitter, MutexGuard<'_, ()>) {
        let count = self.submitters.len();
        let start = self.next.fetch_add(1, Ordering::Relaxed) % count;
        let order = (start..count)
            .chain(0..start)
            .map(|index| &self.submitters[index]);
        for submitter in order {
            if let Ok(turn) = submitter.turn.try_lock() {
                return (submitter, turn);
            }
        }
        let submitter = &self.submitters[start];
        (submitter, lock(&submitter.turn))
    }
}

/// A pool of `family`, one command buffer from it and an unsignalled fence; on failure, what was
/// made is destroyed.
fn submitter(device: &ash::Device, family: u32, queue: usize) -> Result<Submitter, Error> {
    let info = vk::CommandPoolCreateInfo::default()
        .queue_family_index(family)
        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
    // SAFETY: valid create-infos; the pool is destroyed here if the rest cannot be made.
    unsafe {
        let pool = device
            .create_command_pool(&info, None)
            .map_err(vulkan("vkCreateCommandPool"))?;
        let allocate = vk::CommandBufferAllocateInfo::default()
            .command_pool(pool)
            .command_buffer_count(1);
        let made = device
            .allocate_command_buffers(&allocate)
            .map_err(vulkan("vkAllocateCommandBuffers"))
            .and_then(|buffers| {
                let fence = device
                    .create_fence(&vk::FenceCreateInfo::default(), None)
                    .map_err(vulkan("vkCreateFence"))?;
                Ok((buffers[0], fence))
            });
        match made {
            Ok((command_buffer, fence)) => Ok(Submitter {
                pool,
                command_buffer,
                fence,
                queue,
                turn: Mutex::new(()),
            }),
            Err(error) => {
                device.destroy_command_pool(pool, None);
                Err(error)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::gpu::{Gpu, Location, Owner};
    use ash::vk;

    /// More threads than command buffers submit at once, each filling a buffer of its own again
    /// and again with a value no other thread writes: every submission ran its own commands, and
    /// its thread reads its own value back.
    #[test]
    fn more_threads_than_command_buffers_each_run_their_own_commands() {
        let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
        let threads = super::SUBMITTERS as u32 + 4;
        std::thread::scope(|scope| {
            for thread in 0..threads {
                let gpu = &gpu;
                scope.spawn(move || fill_and_read(gpu, thread));
            }
        });
    }

    /// Fills a 16-word buffer with `thread * 256 + round` for eight rounds, reading each back.
    fn fill_and_read(gpu: &Gpu, thread: u32) {
        let mut owner = Owner::new(gpu);
        let usage = vk::BufferUsageFlags::TRANSFER_DST;
        let buffer = owner
            .buffer(64, usage, Location::Host, 4)
            .unwrap_or_else(|error| panic!("{error}"));
        for round in 0..8 {
            let value = thread * 256 + round;
            let to_host = vk::MemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .dst_access_mask(vk::AccessFlags::HOST_READ);
            owner
                .submit(|device, command_buffer| {
                    // SAFETY: a recording command buffer and a live buffer of this device.
                    unsafe {
                        device.cmd_fill_buffer(command_buffer, buffer.buffer, 0, vk::WHOLE_SIZE, value);
                        device.cmd_pipeline_barrier(
                            command_buffer,
                            vk::PipelineStageFlags::TRANSFER,
                            vk::PipelineStageFlags::HOST,
                            vk::DependencyFlags::empty(),
                            &[to_host],
                            &[],
                            &[],
                        );
                    }
                })
                .unwrap_or_else(|error| panic!("thread {thread}, round {round}: {error}"));
            let words: Vec<u32> = owner.read(&buffer, 16).unwrap_or_else(|error| panic!("{error}"));
            assert_eq!(words, vec![value; 16], "thread {thread}, round {round}");
        }
    }
}
