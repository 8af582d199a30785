//! The renderer: the scene's buffers, acceleration structures and textures on the device, and the
//! ways of tracing it (the recording ray-tracing pipeline, with the GLSL or the Slang closest-hit
//! shader, the colour-only ray-tracing pipelines, and the WGSL ray-query compute shader).

use super::abi::{RtPixelRecord, RtPushConstants, RtUniforms};
use super::accel;
use super::mode::Mode;
use super::pipeline::{self, ClosestHit, RayTracing, BINDINGS};
use super::scene::{Camera, Scene};
use super::texture::{checker, mip_colours, MipChain, CHECKER_SQUARE, TEXTURE_SIZE};
use super::Error;
use ash::vk;
use shader_proptest::{
    barrier_shader_writes_to_host, vulkan, Buffer, DeviceRequest, Feature, Gpu, Location, Object, Owner,
};
use std::time::{Duration, Instant};

mod colour;

pub use colour::{ColourPipeline, Timed};

/// What the renderer asks of a device: acceleration structures and ray-tracing pipelines, and
/// where the device has them, ray queries (the WGSL path) and anisotropic filtering.
pub const DEVICE_REQUEST: DeviceRequest<'static> = DeviceRequest {
    required: &[Feature::AccelerationStructure, Feature::RayTracingPipeline],
    optional: &[Feature::RayQuery, Feature::SamplerAnisotropy],
};

/// Opens the device (lavapipe unless `SHADER_PROPTEST_DEVICE` names another) for the renderer.
pub fn open_device() -> Result<Gpu, shader_proptest::Error> {
    Gpu::open(DEVICE_REQUEST)
}

/// One traced image: colours (ray-tracing pipeline only) and what each pixel's primary hit
/// measured.
#[derive(Clone, Debug)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA8 colour per pixel, row by row from the top (gamma 2.2); zeros from the WGSL path.
    pub pixels: Vec<[u8; 4]>,
    /// Per pixel, row by row from the top.
    pub records: Vec<RtPixelRecord>,
    /// Wall time from submitting the trace to its completion (readback excluded).
    pub trace_time: Duration,
}

/// Which shaders trace a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Path {
    /// The recording ray-tracing pipeline.
    RayTracing,
    /// The WGSL ray-query compute shader.
    RayQuery,
}

/// A scene on the device, ready to trace. Owns every Vulkan object it made; dropping it destroys them.
pub struct Renderer<'g> {
    owner: Owner<'g>,
    scene: Scene,
    tlas: vk::AccelerationStructureKHR,
    /// Vertex, index and mesh-table buffers (bindings 1 to 3).
    inputs: [Buffer; 3],
    /// The colour texture and the mip-colour texture (binding 6).
    textures: [vk::ImageView; 2],
    /// Width and height of both textures, in texels.
    texture_size: u32,
    sampler: vk::Sampler,
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    /// The recording pipeline: GLSL ray generation and miss, and the closest hit the renderer was
    /// made with.
    ray_tracing: RayTracing,
    /// The WGSL ray-query pipeline, where the device has ray queries.
    ray_query: Option<vk::Pipeline>,
}

impl<'g> Renderer<'g> {
    /// Uploads `scene`, builds its acceleration structures, makes the textures (full mip chains:
    /// the [`checker`] of [`CHECKER_SQUARE`]-texel squares and the mip colours) and the trilinear
    /// sampler, and compiles the recording ray-tracing pipeline with the GLSL closest-hit shader
    /// and, where the device has ray queries, the WGSL ray-query pipeline. `gpu` must come from
    /// [`open_device`].
    pub fn new(gpu: &'g Gpu, scene: Scene) -> Result<Renderer<'g>, Error> {
        Renderer::with_texture(gpu, scene, checker(TEXTURE_SIZE, CHECKER_SQUARE))
    }

    /// [`Renderer::new`] with the closest-hit shader `closest_hit` in the recording pipeline.
    pub fn with_closest_hit(
        gpu: &'g Gpu,
        scene: Scene,
        closest_hit: ClosestHit,
    ) -> Result<Renderer<'g>, Error> {
        let texture = checker(TEXTURE_SIZE, CHECKER_SQUARE);
        Renderer::build(gpu, scene, texture, closest_hit)
    }

    /// [`Renderer::new`] with `texture` on every textured mesh instead of the checker; the
    /// mip-colour texture takes its size. Fails with [`Error::InvalidTexture`] unless `texture`
    /// is square, a power of two wide, with every level down to 1 x 1, and with
    /// [`Error::InvalidMaterial`] unless every mesh's material is valid
    /// ([`Material::validate`](crate::rt::Material::validate)).
    pub fn with_texture(gpu: &'g Gpu, scene: Scene, texture: MipChain) -> Result<Renderer<'g>, Error> {
        Renderer::build(gpu, scene, texture, ClosestHit::Glsl)
    }

    /// A renderer of `scene` with `texture` and `closest_hit` (see [`Renderer::with_texture`]).
    fn build(
        gpu: &'g Gpu,
        scene: Scene,
        texture: MipChain,
        closest_hit: ClosestHit,
    ) -> Result<Renderer<'g>, Error> {
        texture.validate().map_err(Error::InvalidTexture)?;
        for mesh in &scene.meshes {
            mesh.material
                .validate()
                .map_err(|reason| Error::InvalidMaterial(format!("mesh '{}': {reason}", mesh.name)))?;
        }
        let mut owner = Owner::new(gpu);
        let input = vk::BufferUsageFlags::STORAGE_BUFFER
            | vk::BufferUsageFlags::ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_KHR;
        let vertices = owner.upload(bytemuck::cast_slice(&scene.vertex_floats()), input, 4)?;
        let indices = owner.upload(bytemuck::cast_slice(&scene.indices()), input, 4)?;
        let meshes = owner.upload(
            bytemuck::cast_slice(&scene.mesh_table()),
            vk::BufferUsageFlags::STORAGE_BUFFER,
            4,
        )?;
        let tlas = accel::build(&mut owner, &scene, &vertices, &indices)?;
        let texture_size = texture.size;
        let mut upload = |chain: MipChain| owner.texture(chain.size, &chain.levels);
        let textures = [upload(texture)?, upload(mip_colours(texture_size))?];
        let sampler = sampler(&mut owner, anisotropy(gpu))?;
        let (set_layout, layout) = pipeline::layouts(&mut owner)?;
        let ray_tracing = pipeline::ray_tracing(&mut owner, layout, closest_hit)?;
        let ray_query = if gpu.has(Feature::RayQuery) {
            Some(pipeline::ray_query(&mut owner, layout)?)
        } else {
            None
        };
        gpu.check_messages()?;
        Ok(Renderer {
            owner,
            scene,
            tlas,
            inputs: [vertices, indices, meshes],
            textures,
            texture_size,
            sampler,
            set_layout,
            layout,
            ray_tracing,
            ray_query,
        })
    }

    /// The scene being traced.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The push constants for `camera` in `mode` on a `width` x `height` image.
    pub fn push_constants(
        &self,
        camera: &Camera,
        mode: Mode,
        tex_grad_scale: f32,
        width: u32,
        height: u32,
    ) -> RtPushConstants {
        camera.push_constants(mode.id(), tex_grad_scale, (width, height), self.texture_size)
    }

    /// The maximum anisotropy of the texture sampler: `min(16, maxSamplerAnisotropy)` where the
    /// device has `samplerAnisotropy`, else `None` (plain trilinear filtering).
    pub fn anisotropy(&self) -> Option<f32> {
        anisotropy(self.owner.gpu)
    }

    /// Traces a frame with the recording ray-tracing pipeline: colours and records. Fails with
    /// [`Error::FrameTooLarge`] above [`Renderer::max_pixels`].
    pub fn render(&self, push: &RtPushConstants, uniforms: &RtUniforms) -> Result<Frame, Error> {
        self.trace(push, uniforms, Path::RayTracing)
    }

    /// Traces the primary rays of a frame with the WGSL ray-query compute shader: records only
    /// (the frame's pixels are zero). Fails as [`Renderer::render`] does, and with
    /// [`Error::NotSupported`] on a device without ray queries.
    pub fn trace_wgsl(&self, push: &RtPushConstants, uniforms: &RtUniforms) -> Result<Frame, Error> {
        self.trace(push, uniforms, Path::RayQuery)
    }

    /// The most pixels a frame may have: the device's `maxStorageBufferRange` over the size of a
    /// pixel record.
    pub fn max_pixels(&self) -> u64 {
        let limits = self.owner.gpu.properties().limits;
        u64::from(limits.max_storage_buffer_range) / std::mem::size_of::<RtPixelRecord>() as u64
    }

    fn trace(&self, push: &RtPushConstants, uniforms: &RtUniforms, path: Path) -> Result<Frame, Error> {
        let pipeline = match path {
            Path::RayTracing => self.ray_tracing.pipeline,
            Path::RayQuery => self.ray_query.ok_or_else(|| {
                let reason = self
                    .owner
                    .gpu
                    .lacks(Feature::RayQuery)
                    .unwrap_or("ray queries are not enabled");
                Error::NotSupported(format!("{}: {reason}", self.owner.gpu.name()))
            })?,
        };
        let target = self.target(push, uniforms, Records::PerPixel)?;
        target.render(push, |device, command_buffer| {
            self.record(device, command_buffer, target.set, push, (path, pipeline))
        })
    }

    /// The buffers of a frame of `push`'s size (`records`, the colours and `uniforms`) and the
    /// descriptor set binding them. Fails with [`Error::EmptyFrame`] on a frame without pixels and
    /// with [`Error::FrameTooLarge`] when one of its buffers would pass `maxStorageBufferRange`.
    fn target(
        &self,
        push: &RtPushConstants,
        uniforms: &RtUniforms,
        records_kind: Records,
    ) -> Result<Target<'g>, Error> {
        if push.width == 0 || push.height == 0 {
            return Err(Error::EmptyFrame {
                width: push.width,
                height: push.height,
            });
        }
        let pixels = push.width as usize * push.height as usize;
        let record_bytes = std::mem::size_of::<RtPixelRecord>();
        let (record_count, largest_pixel_bytes) = match records_kind {
            Records::PerPixel => (pixels, record_bytes),
            Records::StandIn => (1, 4),
        };
        let max = u64::from(self.owner.gpu.properties().limits.max_storage_buffer_range)
            / largest_pixel_bytes as u64;
        if pixels as u64 > max {
            return Err(Error::FrameTooLarge {
                pixels: pixels as u64,
                max,
            });
        }
        let mut owner = Owner::new(self.owner.gpu);
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let records = owner.buffer((record_count * record_bytes) as u64, storage, Location::Host, 1)?;
        let colours = owner.buffer((pixels * 4) as u64, storage, Location::Host, 1)?;
        let uniforms = owner.upload(
            bytemuck::bytes_of(uniforms),
            vk::BufferUsageFlags::UNIFORM_BUFFER,
            16,
        )?;
        let set = self.descriptor_set(&mut owner, [&records, &colours, &uniforms])?;
        let written_records = if records_kind == Records::PerPixel {
            pixels
        } else {
            0
        };
        Ok(Target {
            owner,
            records,
            colours,
            set,
            pixels,
            written_records,
        })
    }

    /// A descriptor set (from a pool `frame` owns) binding the scene, the per-frame buffers
    /// (records, colours, uniforms) and the textures as `rt_common.glsl` declares them.
    fn descriptor_set(
        &self,
        frame: &mut Owner<'_>,
        [records, colours, uniforms]: [&Buffer; 3],
    ) -> Result<vk::DescriptorSet, Error> {
        let sizes: Vec<_> = BINDINGS
            .iter()
            .map(|&(ty, count)| vk::DescriptorPoolSize::default().ty(ty).descriptor_count(count))
            .collect();
        let set = frame.descriptor_set(self.set_layout, &sizes)?;
        let structures = [self.tlas];
        let mut scene =
            vk::WriteDescriptorSetAccelerationStructureKHR::default().acceleration_structures(&structures);
        let buffers = [
            &self.inputs[0],
            &self.inputs[1],
            &self.inputs[2],
            records,
            colours,
            uniforms,
        ]
        .map(|b| {
            [vk::DescriptorBufferInfo::default()
                .buffer(b.buffer)
                .range(vk::WHOLE_SIZE)]
        });
        let images = self.textures.map(|view| {
            vk::DescriptorImageInfo::default()
                .sampler(self.sampler)
                .image_view(view)
                .image_layout(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL)
        });
        let write = |binding: usize| {
            vk::WriteDescriptorSet::default()
                .dst_set(set)
                .dst_binding(binding as u32)
                .descriptor_type(BINDINGS[binding].0)
        };
        let mut writes = vec![write(0).push_next(&mut scene)];
        writes[0].descriptor_count = 1;
        writes.extend((1..=5).map(|binding| write(binding).buffer_info(&buffers[binding - 1])));
        writes.push(write(6).image_info(&images));
        writes.push(write(7).buffer_info(&buffers[5]));
        // SAFETY: every write matches the layout's binding types and counts.
        unsafe { frame.device().update_descriptor_sets(&writes, &[]) };
        Ok(set)
    }

    /// Records one trace of `path` into `command_buffer`, then makes its writes visible to the host.
    fn record(
        &self,
        device: &ash::Device,
        command_buffer: vk::CommandBuffer,
        set: vk::DescriptorSet,
        push: &RtPushConstants,
        (path, pipeline): (Path, vk::Pipeline),
    ) {
        let bind_point = match path {
            Path::RayTracing => vk::PipelineBindPoint::RAY_TRACING_KHR,
            Path::RayQuery => vk::PipelineBindPoint::COMPUTE,
        };
        self.bind(command_buffer, (bind_point, pipeline), set, push);
        match path {
            Path::RayTracing => self.ray_tracing.trace(command_buffer, push.width, push.height),
            // SAFETY: recording into a command buffer in the recording state, the pipeline bound.
            Path::RayQuery => unsafe {
                device.cmd_dispatch(command_buffer, push.width.div_ceil(8), push.height.div_ceil(8), 1)
            },
        }
        // SAFETY: recording into a command buffer in the recording state.
        unsafe { barrier_shader_writes_to_host(device, command_buffer, self.owner.shader_stages()) };
    }

    /// Records, into `command_buffer` (recording), the binding of `pipeline` at `bind_point` with
    /// the frame's descriptor `set` and the push constants `push`.
    fn bind(
        &self,
        command_buffer: vk::CommandBuffer,
        (bind_point, pipeline): (vk::PipelineBindPoint, vk::Pipeline),
        set: vk::DescriptorSet,
        push: &RtPushConstants,
    ) {
        let device = self.owner.device();
        // SAFETY: recording into a command buffer in the recording state; every handle is alive.
        unsafe {
            device.cmd_bind_pipeline(command_buffer, bind_point, pipeline);
            device.cmd_bind_descriptor_sets(command_buffer, bind_point, self.layout, 0, &[set], &[]);
        }
        pipeline::push(&self.owner, command_buffer, self.layout, push);
    }
}

/// Which pixel records a frame's buffers hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Records {
    /// One per pixel: the recording shaders write them.
    PerPixel,
    /// One standing in: the colour-only shaders declare the buffer but never write it.
    StandIn,
}

/// A frame's buffers (and the uniforms, which `owner` keeps alive) and the descriptor set that
/// binds them with the scene.
struct Target<'g> {
    owner: Owner<'g>,
    records: Buffer,
    colours: Buffer,
    set: vk::DescriptorSet,
    pixels: usize,
    /// The records the shaders write: one per pixel, or none.
    written_records: usize,
}

impl Target<'_> {
    /// Submits what `record` records into a command buffer and reads the frame back: its colours,
    /// and its pixel records where the shaders write them; `trace_time` is the wall time from
    /// submission to completion.
    fn render(
        &self,
        push: &RtPushConstants,
        record: impl FnOnce(&ash::Device, vk::CommandBuffer),
    ) -> Result<Frame, Error> {
        let started = Instant::now();
        self.owner.submit(record)?;
        let trace_time = started.elapsed();
        Ok(Frame {
            width: push.width,
            height: push.height,
            pixels: self.owner.read(&self.colours, self.pixels)?,
            records: self.owner.read(&self.records, self.written_records)?,
            trace_time,
        })
    }
}

/// Largest anisotropy the renderer asks for: 16 samples along the footprint's long axis.
const MAX_ANISOTROPY: f32 = 16.0;

/// The sampler's maximum anisotropy on `gpu` (see [`Renderer::anisotropy`]).
fn anisotropy(gpu: &Gpu) -> Option<f32> {
    gpu.has(Feature::SamplerAnisotropy)
        .then(|| gpu.properties().limits.max_sampler_anisotropy.min(MAX_ANISOTROPY))
}

/// Trilinear filtering, anisotropic up to `anisotropy` when given, repeating, every level
/// reachable: `maxLod = VK_LOD_CLAMP_NONE`. With the default `maxLod = 0` every level of detail
/// silently samples mip 0. Anisotropy only changes `textureGrad` with anisotropic gradients: an
/// explicit LOD (`textureLod`) and isotropic gradients sample as plain trilinear.
fn sampler(owner: &mut Owner<'_>, anisotropy: Option<f32>) -> Result<vk::Sampler, Error> {
    let info = vk::SamplerCreateInfo::default()
        .anisotropy_enable(anisotropy.is_some())
        .max_anisotropy(anisotropy.unwrap_or(1.0))
        .mag_filter(vk::Filter::LINEAR)
        .min_filter(vk::Filter::LINEAR)
        .mipmap_mode(vk::SamplerMipmapMode::LINEAR)
        .address_mode_u(vk::SamplerAddressMode::REPEAT)
        .address_mode_v(vk::SamplerAddressMode::REPEAT)
        .address_mode_w(vk::SamplerAddressMode::REPEAT)
        .min_lod(0.0)
        .max_lod(vk::LOD_CLAMP_NONE);
    // SAFETY: a valid create-info; the sampler is handed to the owner.
    let sampler = unsafe { owner.device().create_sampler(&info, None) }.map_err(vulkan("vkCreateSampler"))?;
    Ok(owner.keep(sampler, Object::Sampler))
}
