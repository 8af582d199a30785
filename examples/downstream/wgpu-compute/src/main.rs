//! A wgpu user's compute shader: the WGSL ray-cone module pasted in front of the user's kernel,
//! validated by wgpu's own shader validation and run through wgpu's Vulkan backend (lavapipe unless
//! `SHADER_PROPTEST_DEVICE` names another adapter), checked against the Rust mirror.

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone;
use ray_footprint::shaders::{wgsl_prelude, Module};
use std::process::ExitCode;

/// The user's kernel: texture LOD of a pinhole camera's ray cone hitting a ground plane.
const KERNEL: &str = "
@group(0) @binding(0) var<storage, read> cases: array<vec4<f32>>; // t, fov_y, image height, |cos|
@group(0) @binding(1) var<storage, read_write> lods: array<f32>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x >= arrayLength(&lods) {
        return;
    }
    let input = cases[id.x];
    let cone = rf_pinhole_ray_cone(rf_pixel_spread_angle(input.y, input.z));
    let direction = vec3<f32>(sqrt(1.0 - input.w * input.w), -input.w, 0.0);
    lods[id.x] = rf_texture_lod(0.0, rf_width_at(cone, input.x), vec2<f32>(1024.0), vec3<f32>(0.0, 1.0, 0.0), direction);
}
";

/// The same computation with the Rust mirror.
fn mirror(case: [f32; 4]) -> f32 {
    let [t, fov_y, height, cos] = case;
    let cone = ray_cone::pinhole_ray_cone(ray_cone::pixel_spread_angle(fov_y, height));
    let direction = Vec3::new((1.0 - cos * cos).sqrt(), -cos, 0.0);
    ray_cone::texture_lod(
        0.0,
        ray_cone::width_at(cone, t),
        Vec2::splat(1024.0),
        Vec3::Y,
        direction,
    )
}

/// Largest allowed difference in mip levels. Vulkan allows `tan` an absolute error of 2^-11 and
/// `atan` 4096 ULP; through `log2` these move the LOD by less than 2e-3 for the fields of view here
/// (0.3 to 1.5 rad), and `log2` itself adds at most 3 ULP. A mip level is 1.
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
    let source = format!("{}{KERNEL}", wgsl_prelude(&[Module::RayCone]));
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("lod"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("lod"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    if let Some(error) = scope.pop().await {
        return Err(format!("wgpu rejected the shader: {error}"));
    }
    let cases = cases();
    let lods = compute(&device, &queue, &pipeline, &cases).await?;
    let worst = cases
        .iter()
        .zip(&lods)
        .map(|(&case, &lod)| (lod - mirror(case)).abs())
        .fold(0.0f32, f32::max);
    println!(
        "{} LODs computed by wgpu; largest difference from the Rust mirror: {worst:.3e} mip levels",
        lods.len()
    );
    if worst <= LOD_TOLERANCE {
        Ok(())
    } else {
        Err(format!(
            "wgpu and the mirror differ by {worst} mip levels (tolerance {LOD_TOLERANCE})"
        ))
    }
}

async fn compute(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    pipeline: &wgpu::ComputePipeline,
    cases: &[[f32; 4]],
) -> Result<Vec<f32>, String> {
    use wgpu::util::DeviceExt;
    let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("cases"),
        contents: bytemuck::cast_slice(cases),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let size = (cases.len() * 4) as u64;
    let output = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("lods"),
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
    let lods = bytemuck::cast_slice(&view).to_vec();
    Ok(lods)
}
