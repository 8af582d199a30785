//! A small ray tracer, as a hobbyist writes one with wgpu: an image-plane camera ("Ray Tracing in
//! One Weekend"), triangles traced in one compute shader, a brick texture sampled where the rays
//! land. It renders each image twice, sampling mip 0 and sampling at the ray cone's level of
//! detail, and a reference with 8 x 8 rays per pixel at mip 0, on lavapipe (or the adapter named
//! by `SHADER_PROPTEST_DEVICE`), at two image sizes, and prints the PSNR of each against the
//! reference. It fails unless the cone's image is at least 6 dB closer to the reference than mip
//! 0's at both sizes, and unless the lines cone LOD needs (every line that differs from the mip-0
//! tracer ends with the marker `// cone LOD`) are at most 20.

use glam::Vec3;
use ray_footprint::mip::linear_to_srgb;
use ray_footprint::wgpu::{generate_mipmaps, shader_with_modules}; // cone LOD
use ray_footprint::{mip::mip_level_count, shaders::Module}; // cone LOD
use std::process::ExitCode;

/// The frame's uniform block, as `trace.wgsl` declares it.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Frame {
    origin: [f32; 4],
    lower_left: [f32; 4],
    horizontal: [f32; 4],
    vertical: [f32; 4],
    size: [u32; 2],
    samples: u32,
    cone_lod: u32,
}

/// The camera: where it is, where it looks, its vertical field of view.
const EYE: Vec3 = Vec3::new(0.0, 1.6, 6.0);
const LOOK_AT: Vec3 = Vec3::new(0.0, 0.8, -20.0);
const FIELD_OF_VIEW: f32 = 1.0;

/// The texture's side, texels, and its bricks: 64 x 32 texels with 4 of mortar.
const TEXTURE_SIDE: u32 = 1024;

/// The least PSNR gain of the cone's LOD over mip 0, dB, and the most lines it may take.
const GAIN_GOAL: f64 = 6.0;
const LINES_GOAL: usize = 20;

/// The marker that ends every line cone LOD adds or changes.
const MARKER: &str = concat!("// cone ", "LOD");

fn main() -> ExitCode {
    match pollster::block_on(run()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

async fn run() -> Result<(), String> {
    let lines = [include_str!("main.rs"), include_str!("trace.wgsl")]
        .iter()
        .flat_map(|source| source.lines())
        .filter(|line| line.trim_end().ends_with(MARKER))
        .count();
    println!("cone LOD takes {lines} lines (at most {LINES_GOAL})");
    let (device, queue) = device().await?;
    let tracer = Tracer::new(&device, &queue);
    for size in [[320, 240], [480, 360]] {
        let reference = tracer.render(&device, &queue, size, 8, false).await?;
        let mip0 = psnr(&tracer.render(&device, &queue, size, 1, false).await?, &reference);
        let cone = psnr(&tracer.render(&device, &queue, size, 1, true).await?, &reference);
        println!(
            "{} x {}: PSNR against 8 x 8 rays per pixel: mip 0 {mip0:.2} dB, cone LOD {cone:.2} dB (+{:.2} dB)",
            size[0],
            size[1],
            cone - mip0
        );
        if cone - mip0 < GAIN_GOAL {
            return Err(format!(
                "cone LOD gains {:.2} dB over mip 0, less than {GAIN_GOAL}",
                cone - mip0
            ));
        }
    }
    if lines > LINES_GOAL {
        return Err(format!("cone LOD takes {lines} lines, more than {LINES_GOAL}"));
    }
    Ok(())
}

/// lavapipe, or the Vulkan adapter whose name contains `SHADER_PROPTEST_DEVICE`.
async fn device() -> Result<(wgpu::Device, wgpu::Queue), String> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let wanted = std::env::var("SHADER_PROPTEST_DEVICE")
        .ok()
        .map(|name| name.to_lowercase());
    let adapter = instance
        .enumerate_adapters(wgpu::Backends::VULKAN)
        .await
        .into_iter()
        .find(|adapter| match &wanted {
            Some(wanted) => adapter.get_info().name.to_lowercase().contains(wanted.as_str()),
            None => adapter.get_info().device_type == wgpu::DeviceType::Cpu,
        })
        .ok_or("no matching Vulkan adapter; run scripts/setup.sh")?;
    println!("adapter: {}", adapter.get_info().name);
    adapter
        .request_device(&wgpu::DeviceDescriptor::default())
        .await
        .map_err(|e| format!("request_device: {e}"))
}

/// The scene's triangles: positions (xyz, w unused) and texture coordinates, three per triangle.
fn scene() -> (Vec<[f32; 4]>, Vec<[f32; 2]>) {
    // A ground 100 m wide running 200 m away, and a wall 20 m wide and 6 m high, 30 m ahead; the
    // texture spans 2 m by 1 m, repeated.
    let ground = [
        [-50.0, 0.0, 10.0],
        [50.0, 0.0, 10.0],
        [50.0, 0.0, -190.0],
        [-50.0, 0.0, -190.0],
    ];
    let wall = [
        [-10.0, 0.0, -30.0],
        [10.0, 0.0, -30.0],
        [10.0, 6.0, -30.0],
        [-10.0, 6.0, -30.0],
    ];
    let mut positions = Vec::new();
    let mut uvs = Vec::new();
    for (quad, uv) in [
        (
            ground,
            (|p: [f32; 3]| [p[0] / 2.0, p[2]]) as fn([f32; 3]) -> [f32; 2],
        ),
        (wall, |p: [f32; 3]| [p[0] / 2.0, -p[1]]),
    ] {
        for corner in [0, 1, 2, 0, 2, 3] {
            positions.push([quad[corner][0], quad[corner][1], quad[corner][2], 1.0]);
            uvs.push(uv(quad[corner]));
        }
    }
    (positions, uvs)
}

/// A brick texture, sRGB: bricks 64 x 32 texels, rows offset by half a brick, 4 texels of mortar,
/// each brick its own shade, and grain in every texel.
fn bricks() -> Vec<u8> {
    let hash = |x: u32, y: u32| {
        let mut h = x.wrapping_mul(0x9e37_79b1) ^ y.wrapping_mul(0x85eb_ca77);
        h ^= h >> 15;
        h = h.wrapping_mul(0x2c1b_3c6d);
        (h ^ (h >> 13)) as f32 / u32::MAX as f32
    };
    let mut texels = Vec::with_capacity((TEXTURE_SIDE * TEXTURE_SIDE * 4) as usize);
    for y in 0..TEXTURE_SIDE {
        for x in 0..TEXTURE_SIDE {
            let row = y / 32;
            let shifted = x + (row % 2) * 32;
            let mortar = y % 32 < 4 || shifted % 64 < 4;
            let grain = 0.75 + 0.5 * hash(x, y);
            let [r, g, b] = if mortar {
                [0.8, 0.78, 0.72]
            } else {
                let shade = 0.6 + 0.4 * hash(shifted / 64, row + 7);
                [0.62 * shade, 0.22 * shade, 0.12 * shade]
            };
            texels.extend([r, g, b].map(|c| linear_to_srgb(c * grain)));
            texels.push(255);
        }
    }
    texels
}

/// The pipeline and what it reads, made once.
struct Tracer {
    pipeline: wgpu::ComputePipeline,
    positions: wgpu::Buffer,
    uvs: wgpu::Buffer,
    albedo: wgpu::TextureView,
    sampler: wgpu::Sampler,
}

impl Tracer {
    fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Tracer {
        use wgpu::util::DeviceExt;
        let shader = shader_with_modules("trace", include_str!("trace.wgsl"), &[Module::RayCone]); // cone LOD
        let module = device.create_shader_module(shader); // cone LOD
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("trace"),
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        let (positions, uvs) = scene();
        let storage = |label, contents: &[u8]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::STORAGE,
            })
        };
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let usage = usage | wgpu::TextureUsages::RENDER_ATTACHMENT; // cone LOD
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("bricks"),
            size: wgpu::Extent3d {
                width: TEXTURE_SIDE,
                height: TEXTURE_SIDE,
                depth_or_array_layers: 1,
            },
            mip_level_count: mip_level_count(TEXTURE_SIDE, TEXTURE_SIDE), // cone LOD
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8UnormSrgb,
            usage,
            view_formats: &[],
        });
        queue.write_texture(
            texture.as_image_copy(),
            &bricks(),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(TEXTURE_SIDE * 4),
                rows_per_image: None,
            },
            wgpu::Extent3d {
                width: TEXTURE_SIDE,
                height: TEXTURE_SIDE,
                depth_or_array_layers: 1,
            },
        );
        generate_mipmaps(device, queue, &texture).expect("an RGBA8 sRGB texture"); // cone LOD
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,          // cone LOD
            mipmap_filter: wgpu::MipmapFilterMode::Linear, // cone LOD
            ..Default::default()
        });
        Tracer {
            pipeline,
            positions: storage("positions", bytemuck::cast_slice(&positions)),
            uvs: storage("uvs", bytemuck::cast_slice(&uvs)),
            albedo: texture.create_view(&Default::default()),
            sampler,
        }
    }

    /// The image of `size` pixels, `samples x samples` rays per pixel, linear RGB, row by row.
    async fn render(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        size: [u32; 2],
        samples: u32,
        cone_lod: bool,
    ) -> Result<Vec<[f32; 4]>, String> {
        use wgpu::util::DeviceExt;
        let forward = (LOOK_AT - EYE).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        let height = 2.0 * (0.5 * FIELD_OF_VIEW).tan();
        let width = height * size[0] as f32 / size[1] as f32;
        let lower_left = EYE + forward - 0.5 * width * right - 0.5 * height * up;
        let frame = Frame {
            origin: EYE.extend(1.0).into(),
            lower_left: lower_left.extend(1.0).into(),
            horizontal: (width * right).extend(0.0).into(),
            vertical: (height * up).extend(0.0).into(),
            size,
            samples,
            cone_lod: u32::from(cone_lod),
        };
        let frame = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("frame"),
            contents: bytemuck::bytes_of(&frame),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bytes = u64::from(size[0] * size[1]) * 16;
        let colours = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("colours"),
            size: bytes,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: bytes,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let entries = [
            wgpu::BindGroupEntry {
                binding: 0,
                resource: frame.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: self.positions.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: self.uvs.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: wgpu::BindingResource::TextureView(&self.albedo),
            },
            wgpu::BindGroupEntry {
                binding: 4,
                resource: wgpu::BindingResource::Sampler(&self.sampler),
            },
            wgpu::BindGroupEntry {
                binding: 5,
                resource: colours.as_entire_binding(),
            },
        ];
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(size[0].div_ceil(8), size[1].div_ceil(8), 1);
        }
        encoder.copy_buffer_to_buffer(&colours, 0, &readback, 0, bytes);
        queue.submit([encoder.finish()]);
        if let Some(error) = scope.pop().await {
            return Err(format!("wgpu: {error}"));
        }
        readback
            .slice(..)
            .map_async(wgpu::MapMode::Read, |result| result.expect("mapping"));
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| format!("poll: {e}"))?;
        let view = readback
            .slice(..)
            .get_mapped_range()
            .map_err(|e| format!("reading back: {e}"))?;
        Ok(bytemuck::cast_slice(&view).to_vec())
    }
}

/// PSNR of `image` against `reference`, dB, over the 8-bit sRGB values of their RGB channels.
fn psnr(image: &[[f32; 4]], reference: &[[f32; 4]]) -> f64 {
    let squared: f64 = image
        .iter()
        .zip(reference)
        .flat_map(|(a, b)| {
            (0..3).map(move |c| f64::from(linear_to_srgb(a[c])) - f64::from(linear_to_srgb(b[c])))
        })
        .map(|difference| difference * difference)
        .sum();
    let mean = squared / (3 * image.len()) as f64;
    10.0 * (255.0f64 * 255.0 / mean.max(1e-12)).log10()
}
