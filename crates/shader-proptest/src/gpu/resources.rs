//! Vulkan objects and how they are owned: an [`Owner`] destroys what it made in reverse creation
//! order when dropped, so a construction failing halfway leaks nothing. Buffers (with device
//! addresses where the device has them), mip-mapped RGBA8 textures, and one-time command
//! submission that reports validation messages.

use super::device::Gpu;
use super::error::{vulkan, Error};
use crate::shader::Feature;
use ash::vk;

/// A Vulkan object an [`Owner`] destroys.
#[derive(Clone, Copy, Debug)]
pub enum Object {
    /// A buffer.
    Buffer(vk::Buffer),
    /// Device memory.
    Memory(vk::DeviceMemory),
    /// An image.
    Image(vk::Image),
    /// An image view.
    ImageView(vk::ImageView),
    /// A sampler.
    Sampler(vk::Sampler),
    /// An acceleration structure.
    AccelerationStructure(vk::AccelerationStructureKHR),
    /// A pipeline.
    Pipeline(vk::Pipeline),
    /// A pipeline layout.
    PipelineLayout(vk::PipelineLayout),
    /// A descriptor-set layout.
    SetLayout(vk::DescriptorSetLayout),
    /// A descriptor pool (its sets go with it).
    DescriptorPool(vk::DescriptorPool),
    /// A query pool.
    QueryPool(vk::QueryPool),
    /// A shader module (a pipeline needs it only while it is created).
    ShaderModule(vk::ShaderModule),
}

/// Where a buffer's memory lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// Host-visible and coherent: written and read by the CPU.
    Host,
    /// Device-local where the device has it: GPU-only data.
    Device,
}

/// A buffer bound to its own memory, usable by device address.
#[derive(Clone, Copy, Debug)]
pub struct Buffer {
    /// The buffer.
    pub buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    /// Bytes from the buffer's start to `address` (non-zero only when an alignment asked for it).
    offset: vk::DeviceSize,
    /// Usable bytes from `offset`.
    pub size: vk::DeviceSize,
    /// Device address of the first usable byte, aligned as asked.
    pub address: vk::DeviceAddress,
}

/// Vulkan objects created on `gpu`, destroyed in reverse creation order when dropped, so that a
/// construction failing halfway leaks nothing.
pub struct Owner<'g> {
    /// The device the objects belong to.
    pub gpu: &'g Gpu,
    /// The acceleration-structure functions, where the device has them enabled.
    pub acceleration: Option<ash::khr::acceleration_structure::Device>,
    objects: Vec<Object>,
}

impl<'g> Owner<'g> {
    /// An owner of nothing yet.
    pub fn new(gpu: &'g Gpu) -> Owner<'g> {
        let acceleration = gpu
            .has(Feature::AccelerationStructure)
            .then(|| ash::khr::acceleration_structure::Device::new(gpu.instance(), gpu.device()));
        Owner {
            gpu,
            acceleration,
            objects: Vec::new(),
        }
    }

    /// The logical device.
    pub fn device(&self) -> &ash::Device {
        self.gpu.device()
    }

    /// Hands `object` to the owner; returns it for chaining.
    pub fn keep<T>(&mut self, handle: T, object: impl FnOnce(T) -> Object) -> T
    where
        T: Copy,
    {
        self.objects.push(object(handle));
        handle
    }

    /// A buffer of `size` usable bytes for `usage`. Where the device has buffer device addresses
    /// enabled (with [`Feature::AccelerationStructure`]), the buffer is addressable and its
    /// [`Buffer::address`] is a multiple of `alignment` (a power of two); elsewhere the address is 0.
    pub fn buffer(
        &mut self,
        size: vk::DeviceSize,
        usage: vk::BufferUsageFlags,
        location: Location,
        alignment: vk::DeviceSize,
    ) -> Result<Buffer, Error> {
        let addressable = self.acceleration.is_some();
        let (padded, usage) = if addressable {
            (
                size.max(4) + alignment - 1,
                usage | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS,
            )
        } else {
            (size.max(4), usage)
        };
        let info = vk::BufferCreateInfo::default().size(padded).usage(usage);
        // SAFETY: valid create-info structs; every object is handed to the owner at once.
        unsafe {
            let buffer = self
                .device()
                .create_buffer(&info, None)
                .map_err(vulkan("vkCreateBuffer"))?;
            self.keep(buffer, Object::Buffer);
            let requirements = self.device().get_buffer_memory_requirements(buffer);
            let mut flags = vk::MemoryAllocateFlagsInfo::default();
            if addressable {
                flags = flags.flags(vk::MemoryAllocateFlags::DEVICE_ADDRESS);
            }
            let memory = self.allocate(requirements, location, &mut flags)?;
            self.device()
                .bind_buffer_memory(buffer, memory, 0)
                .map_err(vulkan("vkBindBufferMemory"))?;
            let (raw, address) = if addressable {
                let raw = self
                    .device()
                    .get_buffer_device_address(&vk::BufferDeviceAddressInfo::default().buffer(buffer));
                (raw, raw.next_multiple_of(alignment))
            } else {
                (0, 0)
            };
            Ok(Buffer {
                buffer,
                memory,
                offset: address - raw,
                size,
                address,
            })
        }
    }

    /// Memory for `requirements` at `location`, allocated with `flags` chained.
    pub fn allocate(
        &mut self,
        requirements: vk::MemoryRequirements,
        location: Location,
        flags: &mut vk::MemoryAllocateFlagsInfo<'_>,
    ) -> Result<vk::DeviceMemory, Error> {
        let index = self
            .memory_type(requirements.memory_type_bits, location)
            .ok_or(Error::Vulkan(
                "finding a memory type",
                vk::Result::ERROR_FEATURE_NOT_PRESENT,
            ))?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(requirements.size)
            .memory_type_index(index)
            .push_next(flags);
        // SAFETY: a valid allocate-info; the memory is handed to the owner.
        let memory =
            unsafe { self.device().allocate_memory(&info, None) }.map_err(vulkan("vkAllocateMemory"))?;
        Ok(self.keep(memory, Object::Memory))
    }

    /// A memory type allowed by `bits`: host-visible and coherent for [`Location::Host`];
    /// device-local if possible for [`Location::Device`].
    fn memory_type(&self, bits: u32, location: Location) -> Option<u32> {
        // SAFETY: a plain query.
        let types = unsafe {
            self.gpu
                .instance()
                .get_physical_device_memory_properties(self.gpu.physical_device())
        };
        let flags = |i: u32| types.memory_types[i as usize].property_flags;
        let host = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
        let allowed =
            |i: &u32| bits & (1 << i) != 0 && (location == Location::Device || flags(*i).contains(host));
        let preferred =
            |i: &u32| location == Location::Host || flags(*i).contains(vk::MemoryPropertyFlags::DEVICE_LOCAL);
        let mut candidates = (0..types.memory_type_count).filter(allowed);
        candidates.clone().find(preferred).or_else(|| candidates.next())
    }

    /// Copies `bytes` to the start of a [`Location::Host`] buffer.
    pub fn write(&self, buffer: &Buffer, bytes: &[u8]) -> Result<(), Error> {
        assert!(
            bytes.len() as vk::DeviceSize <= buffer.size,
            "write past the end of a buffer"
        );
        self.mapped(buffer, |mapped| {
            // SAFETY: the mapping covers the buffer's usable range, which holds `bytes`.
            unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), mapped, bytes.len()) }
        })
    }

    /// The first `count` values of a [`Location::Host`] buffer.
    pub fn read<T: bytemuck::Pod>(&self, buffer: &Buffer, count: usize) -> Result<Vec<T>, Error> {
        let bytes = count * std::mem::size_of::<T>();
        assert!(
            bytes as vk::DeviceSize <= buffer.size,
            "read past the end of a buffer"
        );
        let mut values = vec![T::zeroed(); count];
        self.mapped(buffer, |mapped| {
            // SAFETY: the mapping covers the buffer's usable range, which holds `bytes` bytes; the
            // GPU work that wrote the buffer has been waited for.
            unsafe { std::ptr::copy_nonoverlapping(mapped, values.as_mut_ptr().cast::<u8>(), bytes) }
        })?;
        Ok(values)
    }

    /// Maps a [`Location::Host`] buffer's usable range, hands its start to `access`, and unmaps it.
    fn mapped<R>(&self, buffer: &Buffer, access: impl FnOnce(*mut u8) -> R) -> Result<R, Error> {
        // SAFETY: host-visible memory, not mapped elsewhere, mapped over the buffer's usable range.
        let start = unsafe {
            self.device().map_memory(
                buffer.memory,
                buffer.offset,
                buffer.size,
                vk::MemoryMapFlags::empty(),
            )
        }
        .map_err(vulkan("vkMapMemory"))?;
        let result = access(start.cast::<u8>());
        // SAFETY: mapped above; `access` has returned and kept no pointer into it.
        unsafe { self.device().unmap_memory(buffer.memory) };
        Ok(result)
    }

    /// A host buffer holding `bytes`, for `usage`, its address aligned to `alignment`.
    pub fn upload(
        &mut self,
        bytes: &[u8],
        usage: vk::BufferUsageFlags,
        alignment: u64,
    ) -> Result<Buffer, Error> {
        let buffer = self.buffer(bytes.len() as u64, usage, Location::Host, alignment)?;
        self.write(&buffer, bytes)?;
        Ok(buffer)
    }

    /// Records commands with `record`, submits them and waits; validation messages fail the call.
    /// Each submission takes one of the device's sixteen command buffers (with its pool and
    /// fence, reused) for its whole course, from recording to the fence's signal, and submits it
    /// to one of the family's queues (the device asks for up to sixteen): threads submit at once,
    /// and take turns only for a queue that several command buffers share. The validation
    /// messages are collected for the whole device: those the layer reports while another thread
    /// submits or waits are read, and fail, whichever submission reads them first.
    pub fn submit(&self, record: impl FnOnce(&ash::Device, vk::CommandBuffer)) -> Result<(), Error> {
        self.gpu.submit(record)
    }

    /// A sampled square RGBA8 image `size` texels wide holding `levels` (level `i` is
    /// `size >> i` texels wide, row by row), ready for shader reads.
    pub fn texture(&mut self, size: u32, levels: &[Vec<[u8; 4]>]) -> Result<vk::ImageView, Error> {
        let level_count = levels.len() as u32;
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(vk::Format::R8G8B8A8_UNORM)
            .extent(vk::Extent3D {
                width: size,
                height: size,
                depth: 1,
            })
            .mip_levels(level_count)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: valid create-info structs; objects are handed to the owner at once.
        let image = unsafe {
            let image = self
                .device()
                .create_image(&info, None)
                .map_err(vulkan("vkCreateImage"))?;
            self.keep(image, Object::Image);
            let requirements = self.device().get_image_memory_requirements(image);
            let memory = self.allocate(
                requirements,
                Location::Device,
                &mut vk::MemoryAllocateFlagsInfo::default(),
            )?;
            self.device()
                .bind_image_memory(image, memory, 0)
                .map_err(vulkan("vkBindImageMemory"))?;
            image
        };
        let texels: Vec<[u8; 4]> = levels.concat();
        let staging = self.upload(
            bytemuck::cast_slice(&texels),
            vk::BufferUsageFlags::TRANSFER_SRC,
            1,
        )?;
        let readers = self.shader_stages();
        self.submit(|device, command_buffer| {
            copy_levels(
                device,
                command_buffer,
                (size, levels),
                staging.buffer,
                image,
                readers,
            )
        })?;
        let range = color_range(level_count);
        let view_info = vk::ImageViewCreateInfo::default()
            .image(image)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(vk::Format::R8G8B8A8_UNORM)
            .subresource_range(range);
        // SAFETY: a valid create-info for the image above.
        let view = unsafe { self.device().create_image_view(&view_info, None) }
            .map_err(vulkan("vkCreateImageView"))?;
        Ok(self.keep(view, Object::ImageView))
    }
}

impl Owner<'_> {
    /// [`Owner::layouts`] of bindings 0 to `count - 1`, each one storage buffer of the compute
    /// stage.
    pub fn compute_storage_layouts(
        &mut self,
        count: u32,
        push_constants: &[vk::PushConstantRange],
    ) -> Result<(vk::DescriptorSetLayout, vk::PipelineLayout), Error> {
        let bindings: Vec<_> = (0..count)
            .map(|binding| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(binding)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .descriptor_count(1)
                    .stage_flags(vk::ShaderStageFlags::COMPUTE)
            })
            .collect();
        self.layouts(&bindings, push_constants)
    }

    /// A descriptor-set layout of `bindings`, and a pipeline layout of it and `push_constants`.
    pub fn layouts(
        &mut self,
        bindings: &[vk::DescriptorSetLayoutBinding<'_>],
        push_constants: &[vk::PushConstantRange],
    ) -> Result<(vk::DescriptorSetLayout, vk::PipelineLayout), Error> {
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(bindings);
        // SAFETY: a valid create-info; the layout is handed to the owner.
        let set_layout = unsafe { self.device().create_descriptor_set_layout(&info, None) }
            .map_err(vulkan("vkCreateDescriptorSetLayout"))?;
        self.keep(set_layout, Object::SetLayout);
        let set_layouts = [set_layout];
        let info = vk::PipelineLayoutCreateInfo::default()
            .set_layouts(&set_layouts)
            .push_constant_ranges(push_constants);
        // SAFETY: a valid create-info; the layout is handed to the owner.
        let layout = unsafe { self.device().create_pipeline_layout(&info, None) }
            .map_err(vulkan("vkCreatePipelineLayout"))?;
        Ok((set_layout, self.keep(layout, Object::PipelineLayout)))
    }

    /// A descriptor set of `set_layout`, from a pool of its own holding `sizes` (which the owner
    /// keeps).
    pub fn descriptor_set(
        &mut self,
        set_layout: vk::DescriptorSetLayout,
        sizes: &[vk::DescriptorPoolSize],
    ) -> Result<vk::DescriptorSet, Error> {
        let info = vk::DescriptorPoolCreateInfo::default()
            .max_sets(1)
            .pool_sizes(sizes);
        // SAFETY: a valid create-info; the pool is handed to the owner.
        let pool = unsafe { self.device().create_descriptor_pool(&info, None) }
            .map_err(vulkan("vkCreateDescriptorPool"))?;
        self.keep(pool, Object::DescriptorPool);
        let set_layouts = [set_layout];
        let info = vk::DescriptorSetAllocateInfo::default()
            .descriptor_pool(pool)
            .set_layouts(&set_layouts);
        // SAFETY: a valid allocate-info; the set goes with its pool.
        let sets = unsafe { self.device().allocate_descriptor_sets(&info) }
            .map_err(vulkan("vkAllocateDescriptorSets"))?;
        Ok(sets[0])
    }

    /// A shader module of the SPIR-V words `spirv` (a compiler's output). A pipeline needs its
    /// modules only while it is created: keep them in an owner that goes when the pipeline exists.
    pub fn shader_module(&mut self, spirv: &[u32]) -> Result<vk::ShaderModule, Error> {
        let info = vk::ShaderModuleCreateInfo::default().code(spirv);
        // SAFETY: a valid create-info; the module is handed to the owner.
        let module = unsafe { self.device().create_shader_module(&info, None) }
            .map_err(vulkan("vkCreateShaderModule"))?;
        Ok(self.keep(module, Object::ShaderModule))
    }

    /// A compute pipeline of `spirv` (entry point `main`) with `layout`; validation messages fail
    /// the call.
    pub fn compute_pipeline(
        &mut self,
        spirv: &[u32],
        layout: vk::PipelineLayout,
    ) -> Result<vk::Pipeline, Error> {
        let mut modules = Owner::new(self.gpu);
        let stage = vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::COMPUTE)
            .module(modules.shader_module(spirv)?)
            .name(c"main");
        let info = [vk::ComputePipelineCreateInfo::default()
            .stage(stage)
            .layout(layout)];
        // SAFETY: a valid create-info; the pipeline is handed to the owner.
        let created = unsafe {
            self.device()
                .create_compute_pipelines(vk::PipelineCache::null(), &info, None)
        };
        let pipeline = created.map_err(|(_, result)| Error::Vulkan("vkCreateComputePipelines", result))?[0];
        self.keep(pipeline, Object::Pipeline);
        self.gpu.check_messages()?;
        Ok(pipeline)
    }
}

/// Records a barrier after which the host may read back what the `writers` stages wrote to memory
/// (once the submission's fence has signalled).
///
/// # Safety
/// `command_buffer` was allocated from `device` and is recording.
pub unsafe fn barrier_shader_writes_to_host(
    device: &ash::Device,
    command_buffer: vk::CommandBuffer,
    writers: vk::PipelineStageFlags,
) {
    let readers = (vk::PipelineStageFlags::HOST, vk::AccessFlags::HOST_READ);
    // SAFETY: the caller's promise.
    unsafe { barrier_shader_writes(device, command_buffer, writers, readers) }
}

/// Records a barrier after which the `readers` stages, with the accesses they name, see what the
/// shaders of the `writers` stages wrote to memory: `(COMPUTE_SHADER, SHADER_WRITE)` for a
/// compute shader that overwrites its predecessor's results.
///
/// # Safety
/// `command_buffer` was allocated from `device` and is recording.
pub unsafe fn barrier_shader_writes(
    device: &ash::Device,
    command_buffer: vk::CommandBuffer,
    writers: vk::PipelineStageFlags,
    readers: (vk::PipelineStageFlags, vk::AccessFlags),
) {
    let written = vk::MemoryBarrier::default()
        .src_access_mask(vk::AccessFlags::SHADER_WRITE)
        .dst_access_mask(readers.1);
    // SAFETY: the caller's promise.
    unsafe {
        device.cmd_pipeline_barrier(
            command_buffer,
            writers,
            readers.0,
            vk::DependencyFlags::empty(),
            &[written],
            &[],
            &[],
        );
    }
}

impl Owner<'_> {
    /// The shader stages this crate's users read resources from: compute, and the ray-tracing
    /// stages where ray-tracing pipelines are enabled.
    pub fn shader_stages(&self) -> vk::PipelineStageFlags {
        if self.gpu.has(Feature::RayTracingPipeline) {
            vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR
        } else {
            vk::PipelineStageFlags::COMPUTE_SHADER
        }
    }
}

impl Drop for Owner<'_> {
    fn drop(&mut self) {
        let device = self.gpu.device();
        // SAFETY: every submission was waited for; objects are destroyed newest first.
        unsafe {
            for object in self.objects.drain(..).rev() {
                match object {
                    Object::Buffer(b) => device.destroy_buffer(b, None),
                    Object::Memory(m) => device.free_memory(m, None),
                    Object::Image(i) => device.destroy_image(i, None),
                    Object::ImageView(v) => device.destroy_image_view(v, None),
                    Object::Sampler(s) => device.destroy_sampler(s, None),
                    Object::AccelerationStructure(a) => {
                        if let Some(acceleration) = &self.acceleration {
                            acceleration.destroy_acceleration_structure(a, None)
                        }
                    }
                    Object::Pipeline(p) => device.destroy_pipeline(p, None),
                    Object::PipelineLayout(l) => device.destroy_pipeline_layout(l, None),
                    Object::SetLayout(l) => device.destroy_descriptor_set_layout(l, None),
                    Object::DescriptorPool(p) => device.destroy_descriptor_pool(p, None),
                    Object::QueryPool(p) => device.destroy_query_pool(p, None),
                    Object::ShaderModule(m) => device.destroy_shader_module(m, None),
                }
            }
        }
    }
}

/// All mip levels of the colour aspect.
fn color_range(levels: u32) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange::default()
        .aspect_mask(vk::ImageAspectFlags::COLOR)
        .level_count(levels)
        .layer_count(1)
}

/// Records: every level of a `(size, levels)` chain from `staging` (levels back to back) into
/// `image`, then the image's transition to shader reads by the `readers` stages.
fn copy_levels(
    device: &ash::Device,
    command_buffer: vk::CommandBuffer,
    (size, levels): (u32, &[Vec<[u8; 4]>]),
    staging: vk::Buffer,
    image: vk::Image,
    readers: vk::PipelineStageFlags,
) {
    let range = color_range(levels.len() as u32);
    let to_transfer = vk::ImageMemoryBarrier::default()
        .dst_access_mask(vk::AccessFlags::TRANSFER_WRITE)
        .old_layout(vk::ImageLayout::UNDEFINED)
        .new_layout(vk::ImageLayout::TRANSFER_DST_OPTIMAL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image)
        .subresource_range(range);
    let mut offset = 0;
    let regions: Vec<vk::BufferImageCopy> = levels
        .iter()
        .enumerate()
        .map(|(level, texels)| {
            let size = size >> level;
            let region = vk::BufferImageCopy::default()
                .buffer_offset(offset)
                .image_subresource(
                    vk::ImageSubresourceLayers::default()
                        .aspect_mask(vk::ImageAspectFlags::COLOR)
                        .mip_level(level as u32)
                        .layer_count(1),
                )
                .image_extent(vk::Extent3D {
                    width: size,
                    height: size,
                    depth: 1,
                });
            offset += 4 * texels.len() as u64;
            region
        })
        .collect();
    let to_shaders = vk::ImageMemoryBarrier {
        src_access_mask: vk::AccessFlags::TRANSFER_WRITE,
        dst_access_mask: vk::AccessFlags::SHADER_READ,
        old_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
        new_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        ..to_transfer
    };
    // SAFETY: recording into a command buffer in the recording state.
    unsafe {
        device.cmd_pipeline_barrier(
            command_buffer,
            vk::PipelineStageFlags::TOP_OF_PIPE,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_transfer],
        );
        device.cmd_copy_buffer_to_image(
            command_buffer,
            staging,
            image,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            &regions,
        );
        device.cmd_pipeline_barrier(
            command_buffer,
            vk::PipelineStageFlags::TRANSFER,
            readers,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_shaders],
        );
    }
}
