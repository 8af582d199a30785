//! A Vulkan compute device with the validation layer on, and one-dispatch batch execution.

use ash::vk;
use std::ffi::{c_void, CStr};
use std::fmt;
use std::sync::Mutex;

/// The command that installs the Vulkan loader, lavapipe, the validation layer and glslang.
pub const SETUP_COMMAND: &str = "scripts/setup.sh";

/// Environment variable naming the device to use (a case-insensitive part of its name) instead of
/// lavapipe, for example `RAY_FOOTPRINT_DEVICE=nvidia`.
pub const DEVICE_ENV: &str = "RAY_FOOTPRINT_DEVICE";

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";
/// Invocations per workgroup in every generated kernel.
pub(crate) const WORKGROUP_SIZE: u32 = 64;

/// Everything that can go wrong while running shaders on the device.
#[derive(Debug)]
pub enum GpuError {
    /// No usable Vulkan loader, layer or device; the message says what to install.
    Setup(String),
    /// A Vulkan call failed.
    Vulkan(&'static str, vk::Result),
    /// A shader failed to compile.
    Compile(String),
    /// The validation layer reported messages (each one fails the run).
    Validation(Vec<String>),
    /// A batch is larger than one dispatch can hold.
    BatchTooLarge(usize),
    /// A traced frame has more pixels than its per-pixel buffers can hold on this device.
    FrameTooLarge {
        /// Pixels asked for.
        pixels: u64,
        /// Pixels the device allows per frame.
        max: u64,
    },
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::Setup(message) => write!(f, "{message}"),
            GpuError::Vulkan(call, result) => write!(f, "{call} failed: {result}"),
            GpuError::Compile(message) => write!(f, "shader compilation failed:\n{message}"),
            GpuError::Validation(messages) => {
                write!(
                    f,
                    "the Vulkan validation layer reported {} message(s):",
                    messages.len()
                )?;
                messages.iter().try_for_each(|m| write!(f, "\n  {m}"))
            }
            GpuError::BatchTooLarge(cases) => {
                write!(f, "a batch of {cases} cases does not fit in one dispatch")
            }
            GpuError::FrameTooLarge { pixels, max } => write!(
                f,
                "a frame of {pixels} pixels is too large: this device's maxStorageBufferRange holds \
                 the per-pixel records of at most {max} pixels"
            ),
        }
    }
}

impl std::error::Error for GpuError {}

pub(super) fn vulkan(call: &'static str) -> impl FnOnce(vk::Result) -> GpuError {
    move |result| GpuError::Vulkan(call, result)
}

/// A compute pipeline for one kernel: binding 0 the input buffer, binding 1 the output words, and
/// optionally a push-constant block.
pub struct Pipeline {
    pipeline: vk::Pipeline,
    layout: vk::PipelineLayout,
    set_layout: vk::DescriptorSetLayout,
    push_constant_bytes: u32,
}

/// A Vulkan device (lavapipe unless [`DEVICE_ENV`] names another) with the validation layer on.
///
/// Validation messages of severity warning or error are collected; any of them makes the current
/// dispatch fail with [`GpuError::Validation`].
pub struct Gpu {
    _entry: ash::Entry,
    pub(super) instance: ash::Instance,
    debug_utils: ash::ext::debug_utils::Instance,
    messenger: vk::DebugUtilsMessengerEXT,
    messages: Box<Mutex<Vec<String>>>,
    pub(super) physical: vk::PhysicalDevice,
    pub(super) device: ash::Device,
    pub(super) queue: vk::Queue,
    pub(super) pool: vk::CommandPool,
    name: String,
    max_groups: u32,
    max_anisotropy: Option<f32>,
}

unsafe extern "system" fn collect_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid callback data; `user` is the boxed Mutex owned by `Gpu`, which
    // outlives the messenger.
    unsafe {
        let text = if data.is_null() || (*data).p_message.is_null() {
            String::from("(no message text)")
        } else {
            CStr::from_ptr((*data).p_message).to_string_lossy().into_owned()
        };
        let messages = &*(user as *const Mutex<Vec<String>>);
        if let Ok(mut messages) = messages.lock() {
            messages.push(format!("{severity:?}: {text}"));
        }
    }
    vk::FALSE
}

impl Gpu {
    /// Opens the device. Fails with [`GpuError::Setup`], naming [`SETUP_COMMAND`], when the loader,
    /// the validation layer or a matching device is missing.
    pub fn new() -> Result<Gpu, GpuError> {
        Gpu::open(&[])
    }

    /// Opens the device with ray tracing on: the extensions in [`RAY_TRACING_EXTENSIONS`] and
    /// their features (acceleration structures, ray-tracing pipelines, ray queries), plus
    /// `bufferDeviceAddress` (Vulkan 1.2). Fails with [`GpuError::Setup`] when the device lacks
    /// one of them or is older than Vulkan 1.2 (ray-tracing shaders are SPIR-V 1.4).
    pub fn new_ray_tracing() -> Result<Gpu, GpuError> {
        Gpu::open(RAY_TRACING_EXTENSIONS)
    }

    fn open(extensions: &[&CStr]) -> Result<Gpu, GpuError> {
        // SAFETY: loading the system Vulkan loader; its functions are used per the Vulkan spec below.
        let entry = unsafe { ash::Entry::load() }
            .map_err(|e| setup(&format!("cannot load the Vulkan loader (libvulkan.so.1): {e}")))?;
        // SAFETY: plain queries and object creation with valid create-info structs; every object is
        // destroyed in `Drop` in reverse order.
        unsafe {
            let layers = entry
                .enumerate_instance_layer_properties()
                .map_err(vulkan("vkEnumerateInstanceLayerProperties"))?;
            if !layers
                .iter()
                .any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER))
            {
                return Err(setup(
                    "the Vulkan validation layer VK_LAYER_KHRONOS_validation is not installed",
                ));
            }
            let app = vk::ApplicationInfo::default()
                .application_name(c"ray-footprint")
                .api_version(vk::API_VERSION_1_3);
            let layer_names = [VALIDATION_LAYER.as_ptr()];
            let extension_names = [ash::ext::debug_utils::NAME.as_ptr()];
            let messages: Box<Mutex<Vec<String>>> = Box::default();
            let mut messenger_info = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                        | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                        | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
                )
                .pfn_user_callback(Some(collect_message))
                .user_data(&*messages as *const Mutex<Vec<String>> as *mut c_void);
            let instance_info = vk::InstanceCreateInfo::default()
                .application_info(&app)
                .enabled_layer_names(&layer_names)
                .enabled_extension_names(&extension_names)
                .push_next(&mut messenger_info);
            let instance = entry
                .create_instance(&instance_info, None)
                .map_err(vulkan("vkCreateInstance"))?;
            let debug_utils = ash::ext::debug_utils::Instance::new(&entry, &instance);
            let messenger = debug_utils
                .create_debug_utils_messenger(&messenger_info, None)
                .map_err(vulkan("vkCreateDebugUtilsMessengerEXT"))?;
            let (physical, name, family, max_groups) = match pick_device(&instance) {
                Ok(found) => found,
                Err(e) => {
                    debug_utils.destroy_debug_utils_messenger(messenger, None);
                    instance.destroy_instance(None);
                    return Err(e);
                }
            };
            if let Err(e) = check_extensions(&instance, physical, &name, extensions) {
                debug_utils.destroy_debug_utils_messenger(messenger, None);
                instance.destroy_instance(None);
                return Err(e);
            }
            let priorities = [1.0];
            let queue_info = [vk::DeviceQueueCreateInfo::default()
                .queue_family_index(family)
                .queue_priorities(&priorities)];
            // f64 for the `_f64` modules, where the device has it.
            let supported = instance.get_physical_device_features(physical);
            // Anisotropic filtering for textureGrad with anisotropic gradients, where the device has it.
            let anisotropic = supported.sampler_anisotropy == vk::TRUE;
            let features = vk::PhysicalDeviceFeatures::default()
                .shader_float64(supported.shader_float64 == vk::TRUE)
                .sampler_anisotropy(anisotropic);
            let max_anisotropy = anisotropic.then(|| {
                instance
                    .get_physical_device_properties(physical)
                    .limits
                    .max_sampler_anisotropy
            });
            let extension_names: Vec<_> = extensions.iter().map(|e| e.as_ptr()).collect();
            let mut vulkan12 = vk::PhysicalDeviceVulkan12Features::default().buffer_device_address(true);
            let mut acceleration =
                vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
            let mut ray_tracing =
                vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
            let mut ray_query = vk::PhysicalDeviceRayQueryFeaturesKHR::default().ray_query(true);
            let mut device_info = vk::DeviceCreateInfo::default()
                .queue_create_infos(&queue_info)
                .enabled_features(&features)
                .enabled_extension_names(&extension_names);
            if !extensions.is_empty() {
                device_info = device_info
                    .push_next(&mut vulkan12)
                    .push_next(&mut acceleration)
                    .push_next(&mut ray_tracing)
                    .push_next(&mut ray_query);
            }
            let device = instance
                .create_device(physical, &device_info, None)
                .map_err(vulkan("vkCreateDevice"))?;
            let queue = device.get_device_queue(family, 0);
            let pool_info = vk::CommandPoolCreateInfo::default()
                .queue_family_index(family)
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
            let pool = device
                .create_command_pool(&pool_info, None)
                .map_err(vulkan("vkCreateCommandPool"))?;
            let gpu = Gpu {
                _entry: entry,
                instance,
                debug_utils,
                messenger,
                messages,
                physical,
                device,
                queue,
                pool,
                name,
                max_groups,
                max_anisotropy,
            };
            gpu.check_messages()?;
            Ok(gpu)
        }
    }

    /// The device name, as the driver reports it.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// `maxSamplerAnisotropy` when the device has `samplerAnisotropy` (enabled), else `None`.
    pub fn max_sampler_anisotropy(&self) -> Option<f32> {
        self.max_anisotropy
    }

    /// Fails with every validation message collected since the last call.
    pub fn check_messages(&self) -> Result<(), GpuError> {
        let messages = std::mem::take(&mut *self.messages.lock().unwrap_or_else(|p| p.into_inner()));
        if messages.is_empty() {
            Ok(())
        } else {
            Err(GpuError::Validation(messages))
        }
    }

    /// Creates a compute pipeline from SPIR-V words whose entry point is `main`, with a
    /// push-constant range of `push_constant_bytes` (0 for none).
    pub fn pipeline(&self, spirv: &[u32], push_constant_bytes: u32) -> Result<Pipeline, GpuError> {
        // SAFETY: valid create-info structs; objects are destroyed by `destroy_pipeline`.
        unsafe {
            let module = self
                .device
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(spirv), None)
                .map_err(vulkan("vkCreateShaderModule"))?;
            let bindings = [0, 1].map(|binding| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(binding)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .descriptor_count(1)
                    .stage_flags(vk::ShaderStageFlags::COMPUTE)
            });
            let set_layout = self
                .device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                    None,
                )
                .map_err(vulkan("vkCreateDescriptorSetLayout"))?;
            let set_layouts = [set_layout];
            let ranges = [vk::PushConstantRange::default()
                .stage_flags(vk::ShaderStageFlags::COMPUTE)
                .size(push_constant_bytes)];
            let ranges = if push_constant_bytes == 0 {
                &ranges[..0]
            } else {
                &ranges[..]
            };
            let layout_info = vk::PipelineLayoutCreateInfo::default()
                .set_layouts(&set_layouts)
                .push_constant_ranges(ranges);
            let layout = self
                .device
                .create_pipeline_layout(&layout_info, None)
                .map_err(vulkan("vkCreatePipelineLayout"))?;
            let stage = vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::COMPUTE)
                .module(module)
                .name(c"main");
            let info = [vk::ComputePipelineCreateInfo::default()
                .stage(stage)
                .layout(layout)];
            let created = self
                .device
                .create_compute_pipelines(vk::PipelineCache::null(), &info, None);
            self.device.destroy_shader_module(module, None);
            let pipeline =
                created.map_err(|(_, result)| GpuError::Vulkan("vkCreateComputePipelines", result))?[0];
            let pipeline = Pipeline {
                pipeline,
                layout,
                set_layout,
                push_constant_bytes,
            };
            self.check_messages()?;
            Ok(pipeline)
        }
    }

    /// Destroys a pipeline made by [`Gpu::pipeline`].
    pub fn destroy_pipeline(&self, pipeline: Pipeline) {
        // SAFETY: the pipeline was made by this device and no dispatch is in flight (dispatches wait).
        unsafe {
            self.device.destroy_pipeline(pipeline.pipeline, None);
            self.device.destroy_pipeline_layout(pipeline.layout, None);
            self.device
                .destroy_descriptor_set_layout(pipeline.set_layout, None);
        }
    }

    /// Runs `cases` invocations of `pipeline` over `input` and returns `output_words` words.
    ///
    /// One dispatch, waited for; validation messages raised meanwhile fail the call.
    pub fn dispatch(
        &self,
        pipeline: &Pipeline,
        cases: usize,
        input: &[u32],
        output_words: usize,
    ) -> Result<Vec<u32>, GpuError> {
        self.dispatch_with_push_constants(pipeline, cases, input, output_words, &[])
    }

    /// [`Gpu::dispatch`] with `push_constants` (the pipeline's push-constant range is filled from
    /// the start; missing bytes are zero).
    pub fn dispatch_with_push_constants(
        &self,
        pipeline: &Pipeline,
        cases: usize,
        input: &[u32],
        output_words: usize,
        push_constants: &[u8],
    ) -> Result<Vec<u32>, GpuError> {
        let groups = cases.div_ceil(WORKGROUP_SIZE as usize);
        if groups > self.max_groups as usize {
            return Err(GpuError::BatchTooLarge(cases));
        }
        let input_buffer = self.buffer(input.len().max(1))?;
        let output_buffer = match self.buffer(output_words.max(1)) {
            Ok(buffer) => buffer,
            Err(e) => {
                self.free(input_buffer);
                return Err(e);
            }
        };
        let result = self.write(&input_buffer, input).and_then(|()| {
            self.record_and_submit(
                pipeline,
                groups as u32,
                &input_buffer,
                &output_buffer,
                push_constants,
            )
            .and_then(|()| self.read(&output_buffer, output_words))
        });
        self.free(input_buffer);
        self.free(output_buffer);
        let output = result?;
        self.check_messages()?;
        Ok(output)
    }

    fn buffer(&self, words: usize) -> Result<HostBuffer, GpuError> {
        let size = (words * 4) as vk::DeviceSize;
        // SAFETY: valid create-info structs; memory type chosen from the device's own list.
        unsafe {
            let buffer = self
                .device
                .create_buffer(
                    &vk::BufferCreateInfo::default()
                        .size(size)
                        .usage(vk::BufferUsageFlags::STORAGE_BUFFER),
                    None,
                )
                .map_err(vulkan("vkCreateBuffer"))?;
            let requirements = self.device.get_buffer_memory_requirements(buffer);
            let memory_types = self.instance.get_physical_device_memory_properties(self.physical);
            let wanted = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
            let Some(type_index) = (0..memory_types.memory_type_count).find(|&i| {
                requirements.memory_type_bits & (1 << i) != 0
                    && memory_types.memory_types[i as usize]
                        .property_flags
                        .contains(wanted)
            }) else {
                self.device.destroy_buffer(buffer, None);
                return Err(GpuError::Vulkan(
                    "finding host-visible memory",
                    vk::Result::ERROR_FEATURE_NOT_PRESENT,
                ));
            };
            let memory = match self.device.allocate_memory(
                &vk::MemoryAllocateInfo::default()
                    .allocation_size(requirements.size)
                    .memory_type_index(type_index),
                None,
            ) {
                Ok(memory) => memory,
                Err(e) => {
                    self.device.destroy_buffer(buffer, None);
                    return Err(GpuError::Vulkan("vkAllocateMemory", e));
                }
            };
            let host = HostBuffer { buffer, memory, size };
            if let Err(e) = self.device.bind_buffer_memory(buffer, memory, 0) {
                self.free(host);
                return Err(GpuError::Vulkan("vkBindBufferMemory", e));
            }
            Ok(host)
        }
    }

    fn free(&self, host: HostBuffer) {
        // SAFETY: the buffer belongs to this device and is no longer used by any submission.
        unsafe {
            self.device.destroy_buffer(host.buffer, None);
            self.device.free_memory(host.memory, None);
        }
    }

    fn write(&self, host: &HostBuffer, words: &[u32]) -> Result<(), GpuError> {
        // SAFETY: the mapping covers `host.size` bytes, at least `words.len() * 4`.
        unsafe {
            let ptr = self
                .device
                .map_memory(host.memory, 0, host.size, vk::MemoryMapFlags::empty())
                .map_err(vulkan("vkMapMemory"))?;
            std::ptr::copy_nonoverlapping(words.as_ptr(), ptr.cast::<u32>(), words.len());
            self.device.unmap_memory(host.memory);
        }
        Ok(())
    }

    fn read(&self, host: &HostBuffer, words: usize) -> Result<Vec<u32>, GpuError> {
        // SAFETY: the mapping covers `host.size` bytes, at least `words * 4`; the dispatch finished.
        unsafe {
            let ptr = self
                .device
                .map_memory(host.memory, 0, host.size, vk::MemoryMapFlags::empty())
                .map_err(vulkan("vkMapMemory"))?;
            let output = std::slice::from_raw_parts(ptr.cast::<u32>(), words).to_vec();
            self.device.unmap_memory(host.memory);
            Ok(output)
        }
    }

    fn record_and_submit(
        &self,
        pipeline: &Pipeline,
        groups: u32,
        input: &HostBuffer,
        output: &HostBuffer,
        push_constants: &[u8],
    ) -> Result<(), GpuError> {
        // SAFETY: every handle belongs to this device; the submission is waited for before return,
        // after which the descriptor pool, fence and command buffer are freed.
        unsafe {
            let sizes = [vk::DescriptorPoolSize::default()
                .ty(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(2)];
            let pool = self
                .device
                .create_descriptor_pool(
                    &vk::DescriptorPoolCreateInfo::default()
                        .max_sets(1)
                        .pool_sizes(&sizes),
                    None,
                )
                .map_err(vulkan("vkCreateDescriptorPool"))?;
            let fence = match self.device.create_fence(&vk::FenceCreateInfo::default(), None) {
                Ok(fence) => fence,
                Err(e) => {
                    self.device.destroy_descriptor_pool(pool, None);
                    return Err(GpuError::Vulkan("vkCreateFence", e));
                }
            };
            let command_buffers = self.device.allocate_command_buffers(
                &vk::CommandBufferAllocateInfo::default()
                    .command_pool(self.pool)
                    .command_buffer_count(1),
            );
            let result = command_buffers
                .map_err(vulkan("vkAllocateCommandBuffers"))
                .and_then(|buffers| {
                    let submitted = self.submit(
                        pipeline,
                        pool,
                        buffers[0],
                        fence,
                        groups,
                        [input, output],
                        push_constants,
                    );
                    self.device.free_command_buffers(self.pool, &buffers);
                    submitted
                });
            self.device.destroy_fence(fence, None);
            self.device.destroy_descriptor_pool(pool, None);
            result
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn submit(
        &self,
        pipeline: &Pipeline,
        pool: vk::DescriptorPool,
        command_buffer: vk::CommandBuffer,
        fence: vk::Fence,
        groups: u32,
        buffers: [&HostBuffer; 2],
        push_constants: &[u8],
    ) -> Result<(), GpuError> {
        // SAFETY: see `record_and_submit`.
        unsafe {
            let set_layouts = [pipeline.set_layout];
            let set = self
                .device
                .allocate_descriptor_sets(
                    &vk::DescriptorSetAllocateInfo::default()
                        .descriptor_pool(pool)
                        .set_layouts(&set_layouts),
                )
                .map_err(vulkan("vkAllocateDescriptorSets"))?[0];
            let infos = buffers.map(|host| {
                [vk::DescriptorBufferInfo::default()
                    .buffer(host.buffer)
                    .range(host.size)]
            });
            let writes = [0, 1].map(|binding| {
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(binding)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(&infos[binding as usize])
            });
            self.device.update_descriptor_sets(&writes, &[]);
            let begin =
                vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            self.device
                .begin_command_buffer(command_buffer, &begin)
                .map_err(vulkan("vkBeginCommandBuffer"))?;
            self.device
                .cmd_bind_pipeline(command_buffer, vk::PipelineBindPoint::COMPUTE, pipeline.pipeline);
            self.device.cmd_bind_descriptor_sets(
                command_buffer,
                vk::PipelineBindPoint::COMPUTE,
                pipeline.layout,
                0,
                &[set],
                &[],
            );
            if pipeline.push_constant_bytes > 0 {
                let mut bytes = vec![0u8; pipeline.push_constant_bytes as usize];
                let used = push_constants.len().min(bytes.len());
                bytes[..used].copy_from_slice(&push_constants[..used]);
                self.device.cmd_push_constants(
                    command_buffer,
                    pipeline.layout,
                    vk::ShaderStageFlags::COMPUTE,
                    0,
                    &bytes,
                );
            }
            self.device.cmd_dispatch(command_buffer, groups, 1, 1);
            let barrier = vk::MemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::SHADER_WRITE)
                .dst_access_mask(vk::AccessFlags::HOST_READ);
            self.device.cmd_pipeline_barrier(
                command_buffer,
                vk::PipelineStageFlags::COMPUTE_SHADER,
                vk::PipelineStageFlags::HOST,
                vk::DependencyFlags::empty(),
                &[barrier],
                &[],
                &[],
            );
            self.device
                .end_command_buffer(command_buffer)
                .map_err(vulkan("vkEndCommandBuffer"))?;
            let command_buffers = [command_buffer];
            let submit = [vk::SubmitInfo::default().command_buffers(&command_buffers)];
            self.device
                .queue_submit(self.queue, &submit, fence)
                .map_err(vulkan("vkQueueSubmit"))?;
            self.device
                .wait_for_fences(&[fence], true, u64::MAX)
                .map_err(vulkan("vkWaitForFences"))
        }
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: all work has been waited for; objects are destroyed in reverse creation order.
        unsafe {
            let _ = self.device.device_wait_idle();
            self.device.destroy_command_pool(self.pool, None);
            self.device.destroy_device(None);
            self.debug_utils
                .destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
    }
}

struct HostBuffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    size: vk::DeviceSize,
}

/// The device extensions [`Gpu::new_ray_tracing`] enables.
pub const RAY_TRACING_EXTENSIONS: &[&CStr] = &[
    ash::khr::acceleration_structure::NAME,
    ash::khr::ray_tracing_pipeline::NAME,
    ash::khr::ray_query::NAME,
    ash::khr::deferred_host_operations::NAME,
];

/// Fails with [`GpuError::Setup`] unless `physical` is Vulkan 1.2 or newer (when extensions are
/// wanted) and supports every extension in `wanted`.
fn check_extensions(
    instance: &ash::Instance,
    physical: vk::PhysicalDevice,
    name: &str,
    wanted: &[&CStr],
) -> Result<(), GpuError> {
    if wanted.is_empty() {
        return Ok(());
    }
    // SAFETY: plain queries on a valid instance and device.
    let (version, available) = unsafe {
        let version = instance.get_physical_device_properties(physical).api_version;
        let available = instance
            .enumerate_device_extension_properties(physical)
            .map_err(vulkan("vkEnumerateDeviceExtensionProperties"))?;
        (version, available)
    };
    let missing: Vec<String> = wanted
        .iter()
        .filter(|&&w| !available.iter().any(|a| a.extension_name_as_c_str() == Ok(w)))
        .map(|w| w.to_string_lossy().into_owned())
        .collect();
    if vk::api_version_minor(version) < 2 && vk::api_version_major(version) == 1 {
        return Err(setup(&format!(
            "{name} is Vulkan 1.{}; ray tracing needs 1.2",
            vk::api_version_minor(version)
        )));
    }
    if missing.is_empty() {
        Ok(())
    } else {
        Err(setup(&format!(
            "{name} lacks {} (ray tracing needs Mesa lavapipe >= 24.1 or a ray-tracing GPU)",
            missing.join(", ")
        )))
    }
}

pub(super) fn setup(problem: &str) -> GpuError {
    GpuError::Setup(format!(
        "{problem}. The GPU tests need a Vulkan device with the validation layer; on Debian 12 run \
         `{SETUP_COMMAND}` (it installs the Vulkan loader, Mesa lavapipe from bookworm-backports, \
         vulkan-validationlayers and glslang-tools)"
    ))
}

/// Picks lavapipe (driver id MESA_LLVMPIPE), or the device whose name contains [`DEVICE_ENV`].
/// Returns the device, its name, a compute queue family and the largest workgroup count in x.
fn pick_device(instance: &ash::Instance) -> Result<(vk::PhysicalDevice, String, u32, u32), GpuError> {
    let wanted = std::env::var(DEVICE_ENV).ok().map(|name| name.to_lowercase());
    // SAFETY: plain queries on a valid instance.
    unsafe {
        let devices = instance
            .enumerate_physical_devices()
            .map_err(vulkan("vkEnumeratePhysicalDevices"))?;
        let mut seen = Vec::new();
        for physical in devices {
            let mut driver = vk::PhysicalDeviceDriverProperties::default();
            let mut properties = vk::PhysicalDeviceProperties2::default().push_next(&mut driver);
            instance.get_physical_device_properties2(physical, &mut properties);
            let limits = properties.properties.limits;
            let name = properties
                .properties
                .device_name_as_c_str()
                .unwrap_or(c"?")
                .to_string_lossy()
                .into_owned();
            let chosen = match &wanted {
                Some(wanted) => name.to_lowercase().contains(wanted.as_str()),
                None => driver.driver_id == vk::DriverId::MESA_LLVMPIPE,
            };
            let family = instance
                .get_physical_device_queue_family_properties(physical)
                .iter()
                .position(|family| family.queue_flags.contains(vk::QueueFlags::COMPUTE));
            match (chosen, family) {
                (true, Some(family)) => {
                    let max_groups = limits.max_compute_work_group_count[0];
                    return Ok((physical, name, family as u32, max_groups));
                }
                _ => seen.push(name),
            }
        }
        let asked = match &wanted {
            Some(wanted) => format!("no Vulkan device named like '{wanted}' ({DEVICE_ENV})"),
            None => String::from("no lavapipe device (Mesa llvmpipe Vulkan driver)"),
        };
        Err(setup(&format!("{asked}; devices found: [{}]", seen.join(", "))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A call that breaks a valid-usage rule (a zero-sized buffer) is reported, and fails the run.
    #[test]
    fn validation_messages_fail_the_run() {
        let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
        gpu.check_messages().expect("a fresh device has no messages");
        // SAFETY: an invalid create-info on purpose; lavapipe tolerates it, the layer reports it.
        unsafe {
            let info = vk::BufferCreateInfo::default()
                .size(0)
                .usage(vk::BufferUsageFlags::STORAGE_BUFFER);
            if let Ok(buffer) = gpu.device.create_buffer(&info, None) {
                gpu.device.destroy_buffer(buffer, None);
            }
        }
        match gpu.check_messages() {
            Err(GpuError::Validation(messages)) => assert!(messages.iter().any(|m| m.contains("size"))),
            other => panic!("expected a validation error, got {other:?}"),
        }
    }
}
