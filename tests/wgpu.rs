//! The wgpu helpers on lavapipe through wgpu's Vulkan backend (wgpu's validation errors, caught in
//! error scopes, fail a test): mip levels made on the GPU against the CPU's `ray_footprint::mip`
//! chain, every level, RGBA8 sRGB and RGBA16 float, even and odd sizes; a texture the levels
//! cannot be rendered into refused, naming the field; a shader with the modules in front accepted.
#![cfg(feature = "wgpu")]

use half::f16;
use ray_footprint::mip::{mip_chain_rgba16f, mip_chain_rgba8_srgb, mip_level_count, MipError};
use ray_footprint::shaders::Module;
use ray_footprint::wgpu::{generate_mipmaps, shader_with_modules};

/// lavapipe through wgpu (the adapter whose name contains `SHADER_PROPTEST_DEVICE`, else the CPU one).
fn device() -> (wgpu::Device, wgpu::Queue) {
    pollster::block_on(async {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let wanted = std::env::var("SHADER_PROPTEST_DEVICE")
            .ok()
            .map(|name| name.to_lowercase());
        let adapters = instance.enumerate_adapters(wgpu::Backends::VULKAN).await;
        let adapter = adapters
            .into_iter()
            .find(|adapter| match &wanted {
                Some(wanted) => adapter.get_info().name.to_lowercase().contains(wanted.as_str()),
                None => adapter.get_info().device_type == wgpu::DeviceType::Cpu,
            })
            .expect("a Vulkan adapter: run scripts/setup.sh");
        println!("adapter: {}", adapter.get_info().name);
        adapter
            .request_device(&wgpu::DeviceDescriptor::default())
            .await
            .expect("a device")
    })
}

/// Runs `call` in a validation error scope; wgpu's error fails the test.
fn validated<T>(device: &wgpu::Device, call: impl FnOnce() -> T) -> T {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = call();
    if let Some(error) = pollster::block_on(scope.pop()) {
        panic!("wgpu: {error}");
    }
    value
}

/// A texture of `format` with level 0 `bytes` (`width x height`, 4 channels of `channel` bytes)
/// and room for its full chain.
fn texture(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    format: wgpu::TextureFormat,
    size: (u32, u32),
    bytes: &[u8],
) -> wgpu::Texture {
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("albedo"),
        size: wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        },
        mip_level_count: mip_level_count(size.0, size.1),
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::COPY_DST
            | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let texel_bytes = bytes.len() as u32 / (size.0 * size.1);
    queue.write_texture(
        texture.as_image_copy(),
        bytes,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(size.0 * texel_bytes),
            rows_per_image: None,
        },
        wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        },
    );
    texture
}

/// Every level of `texture`, read back, `texel_bytes` per texel, rows packed.
fn read_levels(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
    texel_bytes: u32,
) -> Vec<Vec<u8>> {
    (0..texture.mip_level_count())
        .map(|level| {
            let (width, height) = (
                (texture.width() >> level).max(1),
                (texture.height() >> level).max(1),
            );
            let row = (width * texel_bytes).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: u64::from(row * height),
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            let mut encoder = device.create_command_encoder(&Default::default());
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture,
                    mip_level: level,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer: &buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(row),
                        rows_per_image: None,
                    },
                },
                wgpu::Extent3d {
                    width,
                    height,
                    depth_or_array_layers: 1,
                },
            );
            queue.submit([encoder.finish()]);
            buffer
                .slice(..)
                .map_async(wgpu::MapMode::Read, |result| result.expect("mapping"));
            device.poll(wgpu::PollType::wait_indefinitely()).expect("polling");
            let data = buffer.slice(..).get_mapped_range().expect("the mapped range");
            data.chunks(row as usize)
                .flat_map(|line| &line[..(width * texel_bytes) as usize])
                .copied()
                .collect()
        })
        .collect()
}

/// Texels of a pseudo-random texture, as bytes.
fn noise_bytes(count: usize, seed: u32) -> Vec<u8> {
    (0..count as u32)
        .map(|i| (i.wrapping_mul(2_654_435_761).wrapping_add(seed) >> 13) as u8)
        .collect()
}

#[test]
fn srgb_levels_on_the_gpu_match_the_cpu_chain() {
    let (device, queue) = device();
    for size in [(64, 48), (7, 5), (1, 13)] {
        let bytes = noise_bytes((size.0 * size.1 * 4) as usize, size.0);
        let albedo = texture(&device, &queue, wgpu::TextureFormat::Rgba8UnormSrgb, size, &bytes);
        validated(&device, || generate_mipmaps(&device, &queue, &albedo)).expect("an RGBA8 sRGB texture");
        let gpu = read_levels(&device, &queue, &albedo, 4);
        assert_eq!(gpu[0], bytes);
        let mut worst = 0;
        for level in 1..gpu.len() {
            let above: Vec<[u8; 4]> = gpu[level - 1]
                .chunks(4)
                .map(|c| [c[0], c[1], c[2], c[3]])
                .collect();
            let (width, height) = level_size(size, level - 1);
            let cpu = &mip_chain_rgba8_srgb(width, height, &above).expect("a valid level")[1];
            for (g, c) in gpu[level].iter().zip(cpu.texels.iter().flatten()) {
                worst = worst.max(g.abs_diff(*c));
                // The GPU's sRGB encoding and f32 sums may round the other way: one step.
                assert!(
                    g.abs_diff(*c) <= 1,
                    "{size:?}, level {level}: GPU {g} against CPU {c}"
                );
            }
        }
        println!(
            "RGBA8 sRGB {size:?}: {} levels, largest difference {worst} of an 8-bit step",
            gpu.len()
        );
    }
}

/// The size of level `level` of a texture of `size`.
fn level_size(size: (u32, u32), level: usize) -> (u32, u32) {
    ((size.0 >> level).max(1), (size.1 >> level).max(1))
}

#[test]
fn half_float_levels_on_the_gpu_match_the_cpu_chain() {
    let (device, queue) = device();
    let size = (130, 3);
    let values: Vec<u16> = noise_bytes((size.0 * size.1 * 4) as usize, 7)
        .iter()
        .map(|&b| f16::from_f32(f32::from(b) / 32.0 - 2.0).to_bits())
        .collect();
    let albedo = texture(
        &device,
        &queue,
        wgpu::TextureFormat::Rgba16Float,
        size,
        bytemuck::cast_slice(&values),
    );
    validated(&device, || generate_mipmaps(&device, &queue, &albedo)).expect("an RGBA16 float texture");
    let gpu: Vec<Vec<u16>> = read_levels(&device, &queue, &albedo, 8)
        .iter()
        .map(|level| bytemuck::cast_slice(level).to_vec())
        .collect();
    let mut worst = 0.0f32;
    for level in 1..gpu.len() {
        let above: Vec<[u16; 4]> = gpu[level - 1]
            .chunks(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect();
        let (width, height) = level_size(size, level - 1);
        let cpu = &mip_chain_rgba16f(width, height, &above).expect("a valid level")[1];
        for (g, c) in gpu[level].iter().zip(cpu.texels.iter().flatten()) {
            let (g, c) = (f16::from_bits(*g).to_f32(), f16::from_bits(*c).to_f32());
            // One half-float step (2^-10 relative): the GPU sums in f32 too, and rounds once.
            let step = f32::from(f16::EPSILON) * c.abs().max(1e-4);
            worst = worst.max((g - c).abs() / step);
            assert!((g - c).abs() <= step, "level {level}: GPU {g} against CPU {c}");
        }
    }
    println!(
        "RGBA16 float {size:?}: {} levels, largest difference {worst:.3} of a half-float step",
        gpu.len()
    );
}

#[test]
fn a_texture_the_levels_cannot_be_rendered_into_is_refused() {
    let (device, queue) = device();
    let sampled_only = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: 8,
            height: 8,
            depth_or_array_layers: 1,
        },
        mip_level_count: 4,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8UnormSrgb,
        usage: wgpu::TextureUsages::TEXTURE_BINDING,
        view_formats: &[],
    });
    let error = generate_mipmaps(&device, &queue, &sampled_only).expect_err("no RENDER_ATTACHMENT");
    assert!(
        matches!(error, MipError::Texture { field: "usage", .. }),
        "{error}"
    );
    println!("{error}");
}

#[test]
fn a_shader_with_the_modules_in_front_is_accepted() {
    let (device, _) = device();
    let source = "@group(0) @binding(0) var<storage, read_write> lods: array<f32>;
@compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    lods[id.x] = rf_texture_lod(0.0, 0.01, vec2<f32>(1024.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, -1.0, 0.0));
}";
    let module = validated(&device, || {
        device.create_shader_module(shader_with_modules("trace.wgsl", source, &[Module::RayCone]))
    });
    let pipeline = validated(&device, || {
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: None,
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        })
    });
    let _ = pipeline.get_bind_group_layout(0);
}
