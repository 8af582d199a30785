//! A Vulkan device with the validation layer on: any validation message fails the run.

use super::error::{vulkan, Error};
use super::lock::lock;
use super::submission::{Submission, SUBMITTERS};
use crate::shader::Feature;
use ash::vk;
use std::ffi::{c_void, CStr};
use std::sync::{Mutex, OnceLock};

/// Environment variable naming the device to use (a case-insensitive part of its name) instead of
/// lavapipe, for example `SHADER_PROPTEST_DEVICE=nvidia`.
pub const DEVICE_ENV: &str = "SHADER_PROPTEST_DEVICE";

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// A device error about what is missing, with what to install.
pub(crate) fn setup(problem: &str) -> Error {
    Error::Setup(format!(
        "{problem}. Checks need a Vulkan loader, a Vulkan device (Mesa's lavapipe, from the \
         mesa-vulkan-drivers package, runs anywhere) and the Khronos validation layer \
         (vulkan-validationlayers); GLSL needs glslangValidator (glslang-tools), Slang needs slangc"
    ))
}

/// Which optional device features to enable: the program fails to open a device without one of
/// `required`, and runs without any of `optional` it lacks (ask [`Gpu::has`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct DeviceRequest<'a> {
    /// Features the device must have.
    pub required: &'a [Feature],
    /// Features to enable where the device has them.
    pub optional: &'a [Feature],
}

/// A Vulkan device (lavapipe unless [`DEVICE_ENV`] names another) with the validation layer on.
///
/// Validation messages of severity warning or error are collected; any of them fails the dispatch
/// or submission during which it arrived ([`Error::Validation`]). Submissions from several threads
/// run at once: the device keeps sixteen command buffers for them and asks for as many queues of
/// the compute family as it offers, up to sixteen ([`Owner::submit`](super::Owner::submit)).
///
/// ```
/// use shader_proptest::{Feature, Gpu};
///
/// let gpu = Gpu::new()?;
/// println!("{}, {}", gpu.name(), gpu.driver());
/// if let Some(reason) = gpu.lacks(Feature::ShaderFloat64) {
///     println!("checks of f64 functions are reported as not run: {reason}");
/// }
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct Gpu {
    instance: ash::Instance,
    debug_utils: ash::ext::debug_utils::Instance,
    messenger: vk::DebugUtilsMessengerEXT,
    messages: Box<Mutex<Vec<String>>>,
    physical: vk::PhysicalDevice,
    device: ash::Device,
    family: u32,
    /// The queues of `family` this device was created with, and the command buffers submitted
    /// to them.
    submission: Submission,
    name: String,
    driver: String,
    enabled: Vec<Feature>,
    missing: Vec<(Feature, String)>,
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
        lock(messages).push(format!("{severity:?}: {text}"));
    }
    vk::FALSE
}

/// The physical device a run uses, and what it offers.
struct Candidate {
    physical: vk::PhysicalDevice,
    name: String,
    driver: String,
    family: u32,
    /// Queues the family has, capped at [`SUBMITTERS`] (more would go unused).
    queue_count: u32,
}

impl Gpu {
    /// Opens the device for compute checks, with 64-bit floats where the device has them.
    pub fn new() -> Result<Gpu, Error> {
        Gpu::open(DeviceRequest {
            required: &[],
            optional: &[Feature::ShaderFloat64],
        })
    }

    /// Opens the device with the features `request` names. Fails with [`Error::Setup`] when the
    /// loader, the validation layer, a matching device or a required feature is missing.
    pub fn open(request: DeviceRequest<'_>) -> Result<Gpu, Error> {
        let messages: Box<Mutex<Vec<String>>> = Box::default();
        let (instance, debug_utils, messenger) = instance(loader()?, &messages)?;
        let opened = open_device(&instance, request);
        let (candidate, device, enabled, missing) = match opened {
            Ok(opened) => opened,
            Err(error) => {
                // SAFETY: nothing was created from the instance but the messenger.
                unsafe {
                    debug_utils.destroy_debug_utils_messenger(messenger, None);
                    instance.destroy_instance(None);
                }
                return Err(error);
            }
        };
        let submission = match Submission::new(&device, candidate.family, candidate.queue_count) {
            Ok(submission) => submission,
            Err(error) => {
                // SAFETY: what `Submission::new` made before failing it destroyed; nothing else
                // was created from the device.
                unsafe {
                    device.destroy_device(None);
                    debug_utils.destroy_debug_utils_messenger(messenger, None);
                    instance.destroy_instance(None);
                }
                return Err(error);
            }
        };
        let gpu = Gpu {
            instance,
            debug_utils,
            messenger,
            messages,
            physical: candidate.physical,
            device,
            family: candidate.family,
            submission,
            name: candidate.name,
            driver: candidate.driver,
            enabled,
            missing,
        };
        gpu.check_messages()?;
        Ok(gpu)
    }

    /// The device name, as the driver reports it.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The driver's name, version information and the device's Vulkan version, for reports:
    /// for example `llvmpipe (Mesa 25.0.7), Vulkan 1.4.305`.
    pub fn driver(&self) -> &str {
        &self.driver
    }

    /// The device and its driver, for reports: `llvmpipe (LLVM 15.0.7, 256 bits), driver
    /// llvmpipe (Mesa 25.0.7), Vulkan 1.4.305`.
    pub(crate) fn description(&self) -> String {
        format!("{}, driver {}", self.name, self.driver)
    }

    /// Whether `feature` is enabled on this device.
    pub fn has(&self, feature: Feature) -> bool {
        self.enabled.contains(&feature)
    }

    /// The first of `features` this device lacks, as a reason: `"llvmpipe ... lacks shaderFloat64"`.
    pub(crate) fn missing_feature(&self, features: &[Feature]) -> Option<String> {
        features
            .iter()
            .find(|&&feature| !self.has(feature))
            .map(|feature| format!("{} lacks {}", self.name(), feature.name()))
    }

    /// Why an optional `feature` is not enabled, or `None` when it is (or was not asked for).
    pub fn lacks(&self, feature: Feature) -> Option<&str> {
        self.missing
            .iter()
            .find(|(missing, _)| *missing == feature)
            .map(|(_, reason)| reason.as_str())
    }

    /// The logical device.
    pub fn device(&self) -> &ash::Device {
        &self.device
    }

    /// The instance.
    pub fn instance(&self) -> &ash::Instance {
        &self.instance
    }

    /// The physical device.
    pub fn physical_device(&self) -> vk::PhysicalDevice {
        self.physical
    }

    /// The physical device's properties (limits included).
    pub fn properties(&self) -> vk::PhysicalDeviceProperties {
        // SAFETY: a plain query.
        unsafe { self.instance.get_physical_device_properties(self.physical) }
    }

    /// Fills `properties`, a structure that extends `VkPhysicalDeviceProperties2` (the
    /// acceleration structures' or the ray-tracing pipeline's properties, for example), from the
    /// physical device.
    pub fn extended_properties<T: vk::ExtendsPhysicalDeviceProperties2>(&self, properties: &mut T) {
        let mut chain = vk::PhysicalDeviceProperties2::default().push_next(properties);
        // SAFETY: a plain query into a chain of one structure the caller owns.
        unsafe {
            self.instance
                .get_physical_device_properties2(self.physical, &mut chain)
        }
    }

    /// The queue family of the queues submissions go to (its properties say, for example, how
    /// many bits its timestamps have).
    pub fn queue_family(&self) -> u32 {
        self.family
    }

    /// How many queues submissions go to.
    pub fn queue_count(&self) -> usize {
        self.submission.queue_count()
    }

    /// Records a command buffer with `record`, submits it and waits for it; validation messages
    /// fail the call (see [`Owner::submit`](super::Owner::submit)).
    pub(crate) fn submit(&self, record: impl FnOnce(&ash::Device, vk::CommandBuffer)) -> Result<(), Error> {
        self.submission
            .submit(&self.device, record, || self.check_messages())
    }

    /// Fails with every validation message collected since the last call.
    pub fn check_messages(&self) -> Result<(), Error> {
        let messages = std::mem::take(&mut *lock(&self.messages));
        if messages.is_empty() {
            Ok(())
        } else {
            Err(Error::Validation(messages))
        }
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: all work has been waited for; objects are destroyed in reverse creation order.
        unsafe {
            let _ = self.device.device_wait_idle();
            self.submission.destroy(&self.device);
            self.device.destroy_device(None);
            self.debug_utils
                .destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
    }
}

/// The Vulkan loader and one bare instance made from it, both kept for the life of the process.
/// Every [`Gpu`] makes its own instance (with the validation layer and its own messenger) from
/// this loader. The loader loads the driver's library when an instance is created and unloads it
/// when the last one is destroyed, so a process that opens one device at a time would load and
/// unload the driver once per device; NVIDIA's driver (580, on an H100) fails `vkCreateInstance`
/// ("Unable to find a Vulkan driver") after about 30 such cycles. The bare instance (no layer, no
/// extension, never destroyed) keeps the driver loaded. Where it cannot be created, each device's
/// own instance reports why.
fn loader() -> Result<&'static ash::Entry, Error> {
    struct Loader {
        entry: ash::Entry,
        _keeps_the_driver_loaded: Option<ash::Instance>,
    }
    static LOADER: OnceLock<Result<Loader, String>> = OnceLock::new();
    LOADER
        .get_or_init(|| {
            // SAFETY: loading the system Vulkan loader; a static is never dropped, so it stays
            // loaded while any instance made from it lives.
            let entry = unsafe { ash::Entry::load() }.map_err(|e| e.to_string())?;
            let application = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_3);
            let info = vk::InstanceCreateInfo::default().application_info(&application);
            // SAFETY: a valid create-info without layers or extensions; the instance is never
            // destroyed, so nothing can use it after destruction.
            let bare = unsafe { entry.create_instance(&info, None) }.ok();
            Ok(Loader {
                entry,
                _keeps_the_driver_loaded: bare,
            })
        })
        .as_ref()
        .map(|loader| &loader.entry)
        .map_err(|e| setup(&format!("cannot load the Vulkan loader (libvulkan.so.1): {e}")))
}

/// A Vulkan 1.3 instance with the validation layer, and a messenger collecting into `messages`.
fn instance(
    entry: &ash::Entry,
    messages: &Mutex<Vec<String>>,
) -> Result<
    (
        ash::Instance,
        ash::ext::debug_utils::Instance,
        vk::DebugUtilsMessengerEXT,
    ),
    Error,
> {
    // SAFETY: plain queries and object creation with valid create-info structs; `messages` outlives
    // the messenger (both belong to the `Gpu` being built, which destroys the messenger first).
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
            .application_name(c"shader-proptest")
            .api_version(vk::API_VERSION_1_3);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extension_names = [ash::ext::debug_utils::NAME.as_ptr()];
        let mut messenger_info = vk::DebugUtilsMessengerCreateInfoEXT::default()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                    | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                    | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
            )
            .pfn_user_callback(Some(collect_message))
            .user_data(messages as *const Mutex<Vec<String>> as *mut c_void);
        let instance_info = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layer_names)
            .enabled_extension_names(&extension_names)
            .push_next(&mut messenger_info);
        let instance = entry
            .create_instance(&instance_info, None)
            .map_err(vulkan("vkCreateInstance"))?;
        let debug_utils = ash::ext::debug_utils::Instance::new(entry, &instance);
        match debug_utils.create_debug_utils_messenger(&messenger_info, None) {
            Ok(messenger) => Ok((instance, debug_utils, messenger)),
            Err(e) => {
                instance.destroy_instance(None);
                Err(Error::Vulkan("vkCreateDebugUtilsMessengerEXT", e))
            }
        }
    }
}

type Opened = (Candidate, ash::Device, Vec<Feature>, Vec<(Feature, String)>);

/// Picks the device, decides which requested features it has, and creates the logical device.
fn open_device(instance: &ash::Instance, request: DeviceRequest<'_>) -> Result<Opened, Error> {
    let candidate = pick_device(instance)?;
    let support = Support::query(instance, candidate.physical);
    let mut enabled = Vec::new();
    let mut missing = Vec::new();
    for &feature in request.required {
        match support.lacks(feature) {
            Some(reason) => return Err(setup(&format!("{}: {reason}", candidate.name))),
            None => enabled.push(feature),
        }
    }
    for &feature in request.optional {
        match support.lacks(feature) {
            Some(reason) => missing.push((feature, reason)),
            None => enabled.push(feature),
        }
    }
    let device = create_device(instance, &candidate, &enabled)?;
    Ok((candidate, device, enabled, missing))
}

/// What a physical device supports of the [`Feature`]s.
struct Support {
    api_version: u32,
    extensions: Vec<String>,
    float64: bool,
    anisotropy: bool,
    acceleration_structure: bool,
    ray_tracing_pipeline: bool,
    ray_query: bool,
    buffer_device_address: bool,
}

impl Support {
    fn query(instance: &ash::Instance, physical: vk::PhysicalDevice) -> Support {
        let mut vulkan12 = vk::PhysicalDeviceVulkan12Features::default();
        let mut acceleration = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default();
        let mut ray_tracing = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default();
        let mut ray_query = vk::PhysicalDeviceRayQueryFeaturesKHR::default();
        // SAFETY: plain queries; the chained structs are known to the loader (unknown ones are
        // skipped by the implementation, leaving them false).
        unsafe {
            let api_version = instance.get_physical_device_properties(physical).api_version;
            let extensions = instance
                .enumerate_device_extension_properties(physical)
                .unwrap_or_default()
                .iter()
                .filter_map(|e| e.extension_name_as_c_str().ok())
                .map(|name| name.to_string_lossy().into_owned())
                .collect();
            let mut features = vk::PhysicalDeviceFeatures2::default()
                .push_next(&mut vulkan12)
                .push_next(&mut acceleration)
                .push_next(&mut ray_tracing)
                .push_next(&mut ray_query);
            instance.get_physical_device_features2(physical, &mut features);
            let core = features.features;
            Support {
                api_version,
                extensions,
                float64: core.shader_float64 == vk::TRUE,
                anisotropy: core.sampler_anisotropy == vk::TRUE,
                acceleration_structure: acceleration.acceleration_structure == vk::TRUE,
                ray_tracing_pipeline: ray_tracing.ray_tracing_pipeline == vk::TRUE,
                ray_query: ray_query.ray_query == vk::TRUE,
                buffer_device_address: vulkan12.buffer_device_address == vk::TRUE,
            }
        }
    }

    fn has_extension(&self, name: &CStr) -> bool {
        self.extensions.iter().any(|e| e.as_bytes() == name.to_bytes())
    }

    /// Why `feature` cannot be enabled, or `None`.
    fn lacks(&self, feature: Feature) -> Option<String> {
        let extension = |name: &CStr, supported: bool| {
            if vk::api_version_major(self.api_version) == 1 && vk::api_version_minor(self.api_version) < 2 {
                Some(format!(
                    "Vulkan 1.{} (ray tracing needs 1.2)",
                    vk::api_version_minor(self.api_version)
                ))
            } else if !self.has_extension(name) {
                Some(format!("no {}", name.to_string_lossy()))
            } else if !supported || !self.buffer_device_address {
                Some(format!("{} without its feature bits", name.to_string_lossy()))
            } else {
                None
            }
        };
        let acceleration = || {
            extension(
                ash::khr::acceleration_structure::NAME,
                self.acceleration_structure,
            )
            .or_else(|| {
                (!self.has_extension(ash::khr::deferred_host_operations::NAME))
                    .then(|| String::from("no VK_KHR_deferred_host_operations"))
            })
        };
        match feature {
            Feature::ShaderFloat64 => (!self.float64).then(|| String::from("no shaderFloat64")),
            Feature::SamplerAnisotropy => (!self.anisotropy).then(|| String::from("no samplerAnisotropy")),
            Feature::AccelerationStructure => acceleration(),
            Feature::RayTracingPipeline => acceleration()
                .or_else(|| extension(ash::khr::ray_tracing_pipeline::NAME, self.ray_tracing_pipeline)),
            Feature::RayQuery => {
                acceleration().or_else(|| extension(ash::khr::ray_query::NAME, self.ray_query))
            }
        }
    }
}

/// The logical device with `candidate.queue_count` queues of `candidate.family` and the `enabled`
/// features.
fn create_device(
    instance: &ash::Instance,
    candidate: &Candidate,
    enabled: &[Feature],
) -> Result<ash::Device, Error> {
    let on = |feature| enabled.contains(&feature);
    let acceleration_on =
        on(Feature::AccelerationStructure) || on(Feature::RayTracingPipeline) || on(Feature::RayQuery);
    let mut extensions = Vec::new();
    if acceleration_on {
        extensions.extend([
            ash::khr::acceleration_structure::NAME.as_ptr(),
            ash::khr::deferred_host_operations::NAME.as_ptr(),
        ]);
    }
    if on(Feature::RayTracingPipeline) {
        extensions.push(ash::khr::ray_tracing_pipeline::NAME.as_ptr());
    }
    if on(Feature::RayQuery) {
        extensions.push(ash::khr::ray_query::NAME.as_ptr());
    }
    let priorities = vec![1.0; candidate.queue_count as usize];
    let queue_info = [vk::DeviceQueueCreateInfo::default()
        .queue_family_index(candidate.family)
        .queue_priorities(&priorities)];
    let features = vk::PhysicalDeviceFeatures::default()
        .shader_float64(on(Feature::ShaderFloat64))
        .sampler_anisotropy(on(Feature::SamplerAnisotropy));
    let mut vulkan12 = vk::PhysicalDeviceVulkan12Features::default().buffer_device_address(true);
    let mut acceleration =
        vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
    let mut ray_tracing =
        vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
    let mut ray_query = vk::PhysicalDeviceRayQueryFeaturesKHR::default().ray_query(true);
    let mut info = vk::DeviceCreateInfo::default()
        .queue_create_infos(&queue_info)
        .enabled_features(&features)
        .enabled_extension_names(&extensions);
    if acceleration_on {
        info = info.push_next(&mut vulkan12).push_next(&mut acceleration);
    }
    if on(Feature::RayTracingPipeline) {
        info = info.push_next(&mut ray_tracing);
    }
    if on(Feature::RayQuery) {
        info = info.push_next(&mut ray_query);
    }
    // SAFETY: a valid create-info whose extensions and features the device supports.
    unsafe { instance.create_device(candidate.physical, &info, None) }.map_err(vulkan("vkCreateDevice"))
}

/// Picks lavapipe (driver id MESA_LLVMPIPE), or the device whose name contains [`DEVICE_ENV`].
fn pick_device(instance: &ash::Instance) -> Result<Candidate, Error> {
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
            let version = properties.properties.api_version;
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
            let families = instance.get_physical_device_queue_family_properties(physical);
            let family = families
                .iter()
                .position(|family| family.queue_flags.contains(vk::QueueFlags::COMPUTE));
            match (chosen, family) {
                (true, Some(family)) => {
                    let text = |name: Result<&CStr, _>| name.unwrap_or(c"?").to_string_lossy().into_owned();
                    let driver = format!(
                        "{} ({}), Vulkan {}.{}.{}",
                        text(driver.driver_name_as_c_str()),
                        text(driver.driver_info_as_c_str()),
                        vk::api_version_major(version),
                        vk::api_version_minor(version),
                        vk::api_version_patch(version)
                    );
                    return Ok(Candidate {
                        physical,
                        name,
                        driver,
                        family: family as u32,
                        queue_count: families[family].queue_count.clamp(1, SUBMITTERS as u32),
                    });
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

    /// Devices opened and dropped one after another all open, each with its own instance made from
    /// the one loader of the process (whose bare instance keeps the driver loaded in between).
    #[test]
    fn devices_opened_in_a_row_share_one_loader() {
        let first = loader().unwrap_or_else(|error| panic!("{error}"));
        for opened in 1..=50 {
            let gpu = Gpu::new().unwrap_or_else(|error| panic!("device {opened} of 50: {error}"));
            drop(gpu);
            let again = loader().unwrap_or_else(|error| panic!("{error}"));
            assert!(
                std::ptr::eq(first, again),
                "device {opened} loaded the loader again"
            );
        }
    }

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
            Err(Error::Validation(messages)) => assert!(messages.iter().any(|m| m.contains("size"))),
            other => panic!("expected a validation error, got {other:?}"),
        }
    }
}
