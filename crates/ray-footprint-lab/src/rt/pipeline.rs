//! Shaders and pipelines: the ray-tracing pipelines with their shader binding tables (the
//! recording shaders, with a GLSL, a Slang or an HLSL closest hit, and the colour-only shaders),
//! and the WGSL ray-query compute pipeline, over one descriptor-set and pipeline layout.

use super::abi::{RtPushConstants, MAX_DEPTH};
use ash::vk;
use ray_footprint::shaders::{wgsl_prelude, Module, GLSL_INCLUDE_DIR, HLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
use shader_proptest::compile::{
    base_capabilities, compile_glsl as glslang, compile_hlsl_with_slangc as hlsl_slangc,
    compile_slang as slangc, compile_wgsl as naga, Stage, Target,
};
use shader_proptest::{vulkan, Buffer, Error, Feature, Object, Owner};
use std::path::Path;

/// Directory of the renderer's shaders (ray generation, miss, closest hit, ray query).
pub const SHADER_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/rt/shaders");

/// The library modules the renderer's shaders use.
const MODULES: [Module; 3] = [Module::RayCone, Module::RayDiff, Module::Wireframe];

/// The renderer's WGSL ray-query source, as compiled: the extension, the ray-cone, ray-differential
/// and wireframe modules, the shader.
pub fn ray_query_source() -> String {
    format!(
        "enable wgpu_ray_query;\n{}\n{}",
        wgsl_prelude(&MODULES),
        include_str!("shaders/ray_query.wgsl")
    )
}

/// Every stage that reads the descriptor set or the push constants: the ray-tracing stages, and
/// compute where the device has ray queries (the WGSL path).
fn stages(owner: &Owner<'_>) -> vk::ShaderStageFlags {
    let ray_tracing = vk::ShaderStageFlags::RAYGEN_KHR
        | vk::ShaderStageFlags::MISS_KHR
        | vk::ShaderStageFlags::CLOSEST_HIT_KHR;
    if owner.gpu.has(Feature::RayQuery) {
        ray_tracing | vk::ShaderStageFlags::COMPUTE
    } else {
        ray_tracing
    }
}

/// The descriptor types of bindings 0 to 7 (see `rt_common.glsl`) and their counts.
pub(super) const BINDINGS: [(vk::DescriptorType, u32); 8] = [
    (vk::DescriptorType::ACCELERATION_STRUCTURE_KHR, 1),
    (vk::DescriptorType::STORAGE_BUFFER, 1),
    (vk::DescriptorType::STORAGE_BUFFER, 1),
    (vk::DescriptorType::STORAGE_BUFFER, 1),
    (vk::DescriptorType::STORAGE_BUFFER, 1),
    (vk::DescriptorType::STORAGE_BUFFER, 1),
    (vk::DescriptorType::COMBINED_IMAGE_SAMPLER, 2),
    (vk::DescriptorType::UNIFORM_BUFFER, 1),
];

/// The descriptor-set layout of [`BINDINGS`] and a pipeline layout with it and the push constants.
pub(super) fn layouts(owner: &mut Owner<'_>) -> Result<(vk::DescriptorSetLayout, vk::PipelineLayout), Error> {
    let bindings: Vec<_> = BINDINGS
        .iter()
        .enumerate()
        .map(|(binding, &(ty, count))| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(binding as u32)
                .descriptor_type(ty)
                .descriptor_count(count)
                .stage_flags(stages(owner))
        })
        .collect();
    let ranges = [vk::PushConstantRange::default()
        .stage_flags(stages(owner))
        .size(std::mem::size_of::<RtPushConstants>() as u32)];
    owner.layouts(&bindings, &ranges)
}

/// Pushes `push` for every stage of the layout.
pub(super) fn push(
    owner: &Owner<'_>,
    command_buffer: vk::CommandBuffer,
    layout: vk::PipelineLayout,
    push: &RtPushConstants,
) {
    // SAFETY: the range matches the layout's single push-constant range.
    unsafe {
        owner
            .device()
            .cmd_push_constants(command_buffer, layout, stages(owner), 0, bytemuck::bytes_of(push))
    }
}

/// The closest-hit shader of the recording pipeline; its ray generation and miss are GLSL.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClosestHit {
    /// `closest_hit.rchit`, compiled by glslang, `#include`-ing the GLSL modules.
    Glsl,
    /// `closest_hit.slang`, compiled by slangc, `import`-ing the Slang modules.
    Slang,
    /// `closest_hit.hlsl`, compiled by slangc reading HLSL, `#include`-ing the HLSL modules
    /// (glslang's HLSL front end, which the shader-proptest harness also uses for HLSL, parses no
    /// ray-tracing stage: `RaytracingAccelerationStructure`, `TraceRay` and the closest hit's
    /// `BuiltInTriangleIntersectionAttributes` are unknown to it).
    Hlsl,
}

impl ClosestHit {
    /// Every closest-hit shader.
    pub const ALL: [ClosestHit; 3] = [ClosestHit::Glsl, ClosestHit::Slang, ClosestHit::Hlsl];

    /// The closest-hit shader's file in [`SHADER_DIR`].
    fn file(self) -> &'static str {
        match self {
            ClosestHit::Glsl => "closest_hit.rchit",
            ClosestHit::Slang => "closest_hit.slang",
            ClosestHit::Hlsl => "closest_hit.hlsl",
        }
    }
}

/// A ray-tracing pipeline and its shader binding table regions (ray generation, miss, hit,
/// callable).
pub(super) struct RayTracing {
    pub pipeline: vk::Pipeline,
    pub regions: [vk::StridedDeviceAddressRegionKHR; 4],
    pub loader: ash::khr::ray_tracing_pipeline::Device,
}

impl RayTracing {
    /// Records the tracing of `width` x `height` rays into `command_buffer`, which is recording
    /// with the pipeline bound.
    pub(super) fn trace(&self, command_buffer: vk::CommandBuffer, width: u32, height: u32) {
        let [raygen, miss, hit, callable] = &self.regions;
        // SAFETY: the caller's command buffer is recording, with this pipeline bound.
        unsafe {
            self.loader
                .cmd_trace_rays(command_buffer, raygen, miss, hit, callable, width, height, 1)
        }
    }
}

/// The stages of the colour-only shaders, compiled once per mode.
pub(super) const COLOUR_STAGES: [&str; 3] = [
    "colour_raygen.rgen",
    "colour_miss.rmiss",
    "colour_closest_hit.rchit",
];

/// The shader stage of each of a pipeline's three files.
const STAGES: [(Stage, vk::ShaderStageFlags); 3] = [
    (Stage::RayGeneration, vk::ShaderStageFlags::RAYGEN_KHR),
    (Stage::Miss, vk::ShaderStageFlags::MISS_KHR),
    (Stage::ClosestHit, vk::ShaderStageFlags::CLOSEST_HIT_KHR),
];

/// The ray-generation, miss and `closest_hit` shaders of [`SHADER_DIR`] that record what they
/// measured, in one pipeline.
pub(super) fn ray_tracing(
    owner: &mut Owner<'_>,
    layout: vk::PipelineLayout,
    closest_hit: ClosestHit,
) -> Result<RayTracing, Error> {
    let files = ["raygen.rgen", "miss.rmiss", closest_hit.file()];
    ray_tracing_pipeline(owner, layout, &compile_stages(files, &[])?)
}

/// The ray-generation, miss and closest-hit `files` of [`SHADER_DIR`] compiled with `defines`
/// (name and value), as SPIR-V words in that order.
pub(super) fn compile_stages(files: [&str; 3], defines: &[(&str, String)]) -> Result<Vec<Vec<u32>>, Error> {
    files
        .iter()
        .zip(STAGES)
        .map(|(file, (stage, _))| compile_stage(&Path::new(SHADER_DIR).join(file), stage, defines))
        .collect()
}

/// The ray-tracing pipelines' recursion depth: the primary ray's trace and one per bounce, up to
/// [`MAX_DEPTH`]: a reflection, or a refraction into glass, out of it and once more (a total
/// internal reflection inside).
const RECURSION_DEPTH: u32 = MAX_DEPTH + 1;

/// The compiled ray-generation, miss and closest-hit shaders `spirv` in one pipeline (groups: 0
/// ray generation, 1 miss, 2 triangle hit group), recursion depth [`RECURSION_DEPTH`].
pub(super) fn ray_tracing_pipeline(
    owner: &mut Owner<'_>,
    layout: vk::PipelineLayout,
    spirv: &[Vec<u32>],
) -> Result<RayTracing, Error> {
    let properties = ray_tracing_properties(owner);
    if properties.max_ray_recursion_depth < RECURSION_DEPTH {
        return Err(Error::Setup(format!(
            "the device's maxRayRecursionDepth is {}, below {RECURSION_DEPTH} (the renderer traces \
             reflections and refractions through glass)",
            properties.max_ray_recursion_depth
        )));
    }
    // The modules go once the pipeline exists.
    let mut modules = Owner::new(owner.gpu);
    let stage_infos = STAGES
        .iter()
        .zip(spirv)
        .map(|(&(_, stage), words)| {
            Ok(vk::PipelineShaderStageCreateInfo::default()
                .stage(stage)
                .module(modules.shader_module(words)?)
                .name(c"main"))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let general = |shader: u32| {
        vk::RayTracingShaderGroupCreateInfoKHR::default()
            .ty(vk::RayTracingShaderGroupTypeKHR::GENERAL)
            .general_shader(shader)
            .closest_hit_shader(vk::SHADER_UNUSED_KHR)
            .any_hit_shader(vk::SHADER_UNUSED_KHR)
            .intersection_shader(vk::SHADER_UNUSED_KHR)
    };
    let groups = [
        general(0),
        general(1),
        general(vk::SHADER_UNUSED_KHR)
            .ty(vk::RayTracingShaderGroupTypeKHR::TRIANGLES_HIT_GROUP)
            .closest_hit_shader(2),
    ];
    let info = vk::RayTracingPipelineCreateInfoKHR::default()
        .stages(&stage_infos)
        .groups(&groups)
        .max_pipeline_ray_recursion_depth(RECURSION_DEPTH)
        .layout(layout);
    let loader = ash::khr::ray_tracing_pipeline::Device::new(owner.gpu.instance(), owner.gpu.device());
    // SAFETY: a valid create-info; the pipeline is handed to the owner.
    let created = unsafe {
        loader.create_ray_tracing_pipelines(
            vk::DeferredOperationKHR::null(),
            vk::PipelineCache::null(),
            &[info],
            None,
        )
    };
    let pipeline = created.map_err(|(_, result)| Error::Vulkan("vkCreateRayTracingPipelinesKHR", result))?[0];
    owner.keep(pipeline, Object::Pipeline);
    let regions = binding_table(owner, &loader, pipeline, &properties, groups.len() as u32)?;
    owner.gpu.check_messages()?;
    Ok(RayTracing {
        pipeline,
        regions,
        loader,
    })
}

fn ray_tracing_properties(owner: &Owner<'_>) -> vk::PhysicalDeviceRayTracingPipelinePropertiesKHR<'static> {
    let mut ray_tracing = vk::PhysicalDeviceRayTracingPipelinePropertiesKHR::default();
    owner.gpu.extended_properties(&mut ray_tracing);
    ray_tracing
}

/// The shader binding table: one record per group, each region starting at a multiple of
/// `shaderGroupBaseAlignment`, with a stride of the handle size rounded up to
/// `shaderGroupHandleAlignment` (the ray-generation region's size must equal its stride).
fn binding_table(
    owner: &mut Owner<'_>,
    loader: &ash::khr::ray_tracing_pipeline::Device,
    pipeline: vk::Pipeline,
    properties: &vk::PhysicalDeviceRayTracingPipelinePropertiesKHR<'_>,
    groups: u32,
) -> Result<[vk::StridedDeviceAddressRegionKHR; 4], Error> {
    let handle_size = properties.shader_group_handle_size as usize;
    let stride = properties
        .shader_group_handle_size
        .next_multiple_of(properties.shader_group_handle_alignment);
    let region_bytes = stride.next_multiple_of(properties.shader_group_base_alignment) as usize;
    // SAFETY: a plain query on a pipeline with `groups` groups.
    let handles = unsafe {
        loader.get_ray_tracing_shader_group_handles(pipeline, 0, groups, groups as usize * handle_size)
    }
    .map_err(vulkan("vkGetRayTracingShaderGroupHandlesKHR"))?;
    let mut table = vec![0u8; region_bytes * groups as usize];
    for (group, handle) in handles.chunks_exact(handle_size).enumerate() {
        table[group * region_bytes..][..handle_size].copy_from_slice(handle);
    }
    let buffer: Buffer = owner.upload(
        &table,
        vk::BufferUsageFlags::SHADER_BINDING_TABLE_KHR,
        u64::from(properties.shader_group_base_alignment),
    )?;
    let region = |group: u64| {
        vk::StridedDeviceAddressRegionKHR::default()
            .device_address(buffer.address + group * region_bytes as u64)
            .stride(u64::from(stride))
            .size(u64::from(stride))
    };
    Ok([
        region(0),
        region(1),
        region(2),
        vk::StridedDeviceAddressRegionKHR::default(),
    ])
}

/// The WGSL ray-query compute pipeline ([`ray_query_source`]).
pub(super) fn ray_query(owner: &mut Owner<'_>, layout: vk::PipelineLayout) -> Result<vk::Pipeline, Error> {
    owner.compute_pipeline(&compile_wgsl(&ray_query_source())?, layout)
}

/// A compiler of slangc's: [`slangc`] (Slang) or [`hlsl_slangc`] (HLSL).
type SlangcCompiler = fn(&str, Stage, Target, &[&Path]) -> Result<Vec<u32>, shader_proptest::CompileError>;

/// Compiles a ray-tracing stage by its file's language: Slang (`.slang`) and HLSL (`.hlsl`) with
/// slangc, GLSL with glslang. Only GLSL stages take `defines`.
fn compile_stage(path: &Path, stage: Stage, defines: &[(&str, String)]) -> Result<Vec<u32>, Error> {
    let slangc_input: Option<(&str, SlangcCompiler)> = match path.extension().and_then(|e| e.to_str()) {
        Some("slang") => Some((SLANG_INCLUDE_DIR, slangc)),
        Some("hlsl") => Some((HLSL_INCLUDE_DIR, hlsl_slangc)),
        _ => None,
    };
    let Some((library_dir, compiler)) = slangc_input else {
        return compile_glsl(path, stage, defines);
    };
    if !defines.is_empty() {
        return Err(Error::Compile(format!(
            "{}: defines are for GLSL stages",
            path.display()
        )));
    }
    compile_with_slangc(path, stage, library_dir, compiler)
}

/// Compiles a ray-tracing stage with glslang for Vulkan 1.2 (SPIR-V 1.5), with the library's
/// GLSL directory and [`SHADER_DIR`] on the include path and `defines` after its `#version` line
/// (messages keep the file's line numbers).
fn compile_glsl(path: &Path, stage: Stage, defines: &[(&str, String)]) -> Result<Vec<u32>, Error> {
    let source =
        std::fs::read_to_string(path).map_err(|e| Error::Compile(format!("{}: {e}", path.display())))?;
    let source = with_defines(&source, defines);
    let includes = [Path::new(GLSL_INCLUDE_DIR), Path::new(SHADER_DIR)];
    glslang(&source, stage, Target::Vulkan1_2, &includes)
        .map_err(|error| Error::Compile(format!("{}:\n{error}", path.display())))
}

/// `source` with a `#define` per entry of `defines` after its `#version` line, and a `#line`
/// that gives the lines after it their own numbers again.
fn with_defines(source: &str, defines: &[(&str, String)]) -> String {
    if defines.is_empty() {
        return source.to_string();
    }
    let mut lines: Vec<String> = source.lines().map(str::to_string).collect();
    if let Some(version) = lines.iter().position(|line| line.starts_with("#version")) {
        let mut inserted: Vec<String> = defines
            .iter()
            .map(|(name, value)| format!("#define {name} {value}"))
            .collect();
        inserted.push(format!("#line {}", version + 2));
        lines.splice(version + 1..version + 1, inserted);
    }
    lines.join("\n")
}

/// Compiles a Slang or an HLSL ray-tracing stage with slangc's `compiler` for Vulkan 1.2 (SPIR-V
/// 1.5), with the library's directory of its language (`library_dir`) and [`SHADER_DIR`] on the
/// search path of `import` and `#include`.
fn compile_with_slangc(
    path: &Path,
    stage: Stage,
    library_dir: &str,
    compiler: SlangcCompiler,
) -> Result<Vec<u32>, Error> {
    let source =
        std::fs::read_to_string(path).map_err(|e| Error::Compile(format!("{}: {e}", path.display())))?;
    let search_dirs = [Path::new(library_dir), Path::new(SHADER_DIR)];
    compiler(&source, stage, Target::Vulkan1_2, &search_dirs)
        .map_err(|error| Error::Compile(format!("{}:\n{error}", path.display())))
}

/// Compiles the ray-query shader with naga: the library modules' capabilities plus ray queries
/// and push constants (`var<immediate>`).
fn compile_wgsl(source: &str) -> Result<Vec<u32>, Error> {
    let capabilities = MODULES.into_iter().fold(base_capabilities(), |all, module| {
        all | module.naga_capabilities()
    }) | naga::valid::Capabilities::RAY_QUERY
        | naga::valid::Capabilities::IMMEDIATES;
    naga(source, "ray_query.wgsl", capabilities, Target::Vulkan1_2)
        .map_err(|error| Error::Compile(error.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use shader_proptest::spirv;

    /// `OpEntryPoint` and the execution model `ClosestHitKHR` (SPIR-V specification, 3.6 and 3.52).
    const OP_ENTRY_POINT: u32 = 15;
    const CLOSEST_HIT_KHR: u32 = 5316;
    /// The version word of a SPIR-V 1.5 module.
    const SPIRV_1_5: u32 = 0x0001_0500;

    /// Every closest-hit shader compiles to one SPIR-V 1.5 closest-hit entry point that `spirv-val`
    /// accepts for Vulkan 1.2: what can be checked of them without a ray-tracing device.
    #[test]
    fn every_closest_hit_compiles_to_valid_spirv() {
        for closest_hit in ClosestHit::ALL {
            let path = Path::new(SHADER_DIR).join(closest_hit.file());
            let words = compile_stage(&path, Stage::ClosestHit, &[]).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(words[1], SPIRV_1_5, "{closest_hit:?}: the SPIR-V version");
            assert_eq!(
                execution_models(&words),
                [CLOSEST_HIT_KHR],
                "{closest_hit:?}: the entry points' execution models"
            );
            spirv::validate(&words, Target::Vulkan1_2).unwrap_or_else(|e| panic!("{closest_hit:?}: {e}"));
        }
    }

    /// The execution model of each `OpEntryPoint` in `words`.
    fn execution_models(words: &[u32]) -> Vec<u32> {
        let mut models = Vec::new();
        let mut at = 5; // after the header
        while at < words.len() {
            if words[at] & 0xffff == OP_ENTRY_POINT {
                models.push(words[at + 1]);
            }
            at += ((words[at] >> 16) as usize).max(1);
        }
        models
    }
}
