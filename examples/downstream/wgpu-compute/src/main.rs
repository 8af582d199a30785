//! A wgpu user's compute shader, the same kernel with ray-footprint's modules brought in two ways:
//! the WGSL modules pasted in front (`ray_footprint::wgpu::shader_with_modules`, where
//! `include_wgsl!` would be), and the WESL package imported by path (`src/shaders/lod.wesl`,
//! linked by wesl-rs in `build.rs`). Each is validated by wgpu, run through its Vulkan backend
//! (lavapipe unless `SHADER_PROPTEST_DEVICE` names another adapter) and checked against the Rust
//! mirror.

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone;
use ray_footprint::shaders::Module;
use std::process::ExitCode;

/// The same computation with the Rust mirror: world footprint and texture LOD.
fn mirror(case: [f32; 4]) -> [f32; 2] {
    let [t, fov_y, height, cos] = case;
    let cone = ray_cone::pinhole_ray_cone(ray_cone::pixel_spread_angle(fov_y, height));
    let direction = Vec3::new((1.0 - cos * cos).sqrt(), -cos, 0.0);
    let footprint = ray_cone::world_footprint(cone, t, Vec3::Y, direction);
    let lod = ray_cone::texture_lod(0.0, ray_cone::width_at(cone, t), Vec2::splat(1024.0), Vec3::Y, direction);
    [footprint, lod]
}

/// Largest allowed relative difference of the footprint. Vulkan allows `tan` an absolute error of
/// 2^-11 and `atan` 4096 ULP; at the narrowest field of view here (0.3 rad, tan(0.15) = 0.15) the
/// first is 3.2e-3 of the pixel's size, the second 2.4e-4; the division by |cos| adds 2.5 ULP.
const FOOTPRINT_TOLERANCE: f32 = 4.0e-3;

/// Largest allowed difference in mip levels: the same errors through `log2` move the LOD by less
/// than 2e-3 for the fields of view here, and `log2` itself adds at most 3 ULP. A mip level is 1.
const LOD_TOLERANCE: f32 = 2.0e-3;

fn cases() -> Vec<[f32; 4]> {
    (0..4096)
        .map(|i| {
            let u = i as f32 / 4096.0;
            [
                0.5 + 200.0 * u,
                0.3 + 1.2 * (u * 7.0).fract(),
                240.0 + 1200.0 * (u * 3.0).fract(),
                0.02 + 0.98 * (u * 13.0).fract(),
            ]
        })
        .collect()
}

fn main() -> ExitCode {
    match pollster::block_on(run()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

async fn adapter(instance: &wgpu::Instance) -> Result<wgpu::Adapter, String> {
    let wanted = std::env::var("SHADER_PROPTEST_DEVICE")
        .ok()
        .map(|name| name.to_lowercase());
    let adapters = instance.enumerate_adapters(wgpu::Backends::VULKAN).await;
    let names: Vec<String> = adapters.iter().map(|a| a.get_info().name).collect();
    adapters
        .into_iter()
        .find(|adapter| {
            let info = adapter.get_info();
            match &wanted {
                Some(wanted) => info.name.to_lowercase().contains(wanted.as_str()),
                None => info.device_type == wgpu::DeviceType::Cpu,
            }
        })
        .ok_or_else(|| format!("no matching Vulkan adapter among {names:?}; run scripts/setup.sh"))
}

async fn run() -> Result<(), String> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapter = adapter(&instance).await?;
    println!(
        "adapter: {} ({:?})",
        adapter.get_info().name,
        adapter.get_info().backend
    );
    let (device, queue) = adapter
        .request_device(&wgpu::DeviceDescriptor::default())
        .await
        .map_err(|e| format!("request_device: {e}"))?;
    let kernels = [
        (
            "WGSL modules pasted in front",
            ray_footprint::wgpu::shader_with_modules("lod.wgsl", include_str!("shaders/lod.wgsl"), &[Module::RayCone]),
        ),
        (
            "WESL package imported by path",
            wgpu::ShaderModuleDescriptor {
                label: Some("lod.wesl"),
                // What `wesl::include_wesl!("lod")` reads: the artifact `build.rs` wrote.
                source: wgpu::ShaderSource::Wgsl(include_str!(concat!(env!("OUT_DIR"), "/lod.wgsl")).into()),
            },
        ),
    ];
    let cases = cases();
    for (way, descriptor) in kernels {
        let pipeline = pipeline(&device, descriptor).await?;
        let results = compute(&device, &queue, &pipeline, &cases).await?;
        check(way, &cases, &results)?;
    }
    Ok(())
}

/// The compute pipeline of `descriptor`'s shader; wgpu's validation errors are returned.
async fn pipeline(device: &wgpu::Device, descriptor: wgpu::ShaderModuleDescriptor<'_>) -> Result<wgpu::ComputePipeline, String> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(descriptor);
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("lod"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    match scope.pop().await {
        Some(error) => Err(format!("wgpu rejected the shader: {error}")),
        None => Ok(pipeline),
    }
}

/// The largest differences of `results` from the mirror, printed; an error past a tolerance.
fn check(way: &str, cases: &[[f32; 4]], results: &[[f32; 2]]) -> Result<(), String> {
    let (mut footprint, mut lod) = (0.0f32, 0.0f32);
    for (&case, result) in cases.iter().zip(results) {
        let [want_footprint, want_lod] = mirror(case);
        footprint = footprint.max((result[0] - want_footprint).abs() / want_footprint);
        lod = lod.max((result[1] - want_lod).abs());
    }
    println!(
        "{way}: {} cases; largest difference from the Rust mirror: footprint {footprint:.3e} (relative), LOD {lod:.3e} mip levels",
        results.len()
    );
    if footprint <= FOOTPRINT_TOLERANCE && lod <= LOD_TOLERANCE {
        Ok(())
    } else {
        Err(format!(
            "{way}: wgpu and the mirror differ by {footprint} (relative footprint, tolerance {FOOTPRINT_TOLERANCE}) or {lod} mip levels (tolerance {LOD_TOLERANCE})"
        ))
    }
}

async fn compute(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    pipeline: &wgpu::ComputePipeline,
    cases: &[[f32; 4]],
) -> Result<Vec<[f32; 2]>, String> {
    use wgpu::util::DeviceExt;
    let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("cases"),
        contents: bytemuck::cast_slice(cases),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let size = (cases.len() * 8) as u64;
    let output = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("results"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: input.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: output.as_entire_binding(),
            },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups((cases.len() as u32).div_ceil(64), 1, 1);
    }
    encoder.copy_buffer_to_buffer(&output, 0, &readback, 0, size);
    queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |result| {
        result.expect("mapping the readback buffer")
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| format!("poll: {e}"))?;
    let view = slice
        .get_mapped_range()
        .map_err(|e| format!("reading the results: {e}"))?;
    Ok(bytemuck::cast_slice(&view).to_vec())
}
