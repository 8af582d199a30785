//! The browser demo (`web/`, feature `browser`): a static page that renders a textured ground and
//! a mirror sphere with WebGPU compute, calling the crate's WGSL modules as it ships them.
//!
//! [`serve`] serves the page and the modules on loopback. [`render_with_wgpu`] runs the page's own
//! shader (`web/render.wgsl` after the same modules, the same texture, camera and mode) through
//! wgpu on the local Vulkan device (naga and lavapipe, where the page has Tint and SwiftShader),
//! for the browser test that compares the two with FLIP.

use crate::quality::image::Image;
use ray_footprint::shaders::{wgsl_prelude, Module};
use shader_proptest::{LoopbackServer, Response};
use std::path::{Path, PathBuf};

/// The page's width and height in pixels (the canvas of `web/index.html`).
pub const IMAGE_SIZE: [u32; 2] = [480, 320];

/// The page's shader, after the modules.
pub const RENDER_WGSL: &str = include_str!("../web/render.wgsl");

/// The modules the page puts in front of `render.wgsl`, in its order.
pub const MODULES: [Module; 3] = [Module::RayCone, Module::RayDiff, Module::Wireframe];

/// The ground texture's side in texels (`TEXTURE_SIZE` in `web/demo.js`).
const TEXTURE_SIZE: u32 = 512;

/// Where the page is, from the repository's root.
pub const PAGE_PATH: &str = "/crates/ray-footprint-lab/web/index.html";

/// The folders the demo server serves, from the repository's root.
const SERVED: [&str; 2] = ["crates/ray-footprint-lab/web/", "shaders/wgsl/"];

/// A mode of the demo, as the page names it and as `render.wgsl` numbers it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DemoMode {
    /// Mip 0 everywhere.
    Mip0,
    /// The ray cone's LOD (`rf_texture_lod`).
    Cone,
    /// The cone's elliptical footprint as gradients (`rf_anisotropic_cone_gradients`).
    ConeAnisotropic,
    /// The cone's LOD with the ground's triangles drawn (`rf_process_wireframe`).
    Wireframe,
}

impl DemoMode {
    /// Every mode, in the page's order.
    pub const ALL: [DemoMode; 4] = [
        DemoMode::Mip0,
        DemoMode::Cone,
        DemoMode::ConeAnisotropic,
        DemoMode::Wireframe,
    ];

    /// The page's name of the mode (`demo.render(name)`).
    pub fn name(self) -> &'static str {
        match self {
            DemoMode::Mip0 => "mip0",
            DemoMode::Cone => "cone",
            DemoMode::ConeAnisotropic => "cone_anisotropic",
            DemoMode::Wireframe => "wireframe",
        }
    }

    /// `render.wgsl`'s number of the mode.
    fn number(self) -> u32 {
        self as u32
    }
}

/// The repository's root.
fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Serves the page and the WGSL modules on `127.0.0.1:port` (0: a free port): the files of
/// `crates/ray-footprint-lab/web/` and `shaders/wgsl/` at their paths from the repository's root,
/// nothing else; `/` leads to the page ([`PAGE_PATH`]).
pub fn serve(port: u16) -> Result<LoopbackServer, shader_proptest::Error> {
    let root = repository();
    LoopbackServer::start(port, move |request| match request.path.as_str() {
        "/" => Response::ok(
            "text/html",
            format!("<meta http-equiv=\"refresh\" content=\"0; url={PAGE_PATH}\">"),
        ),
        path => served_file(&root, path).unwrap_or_else(|| Response::not_found(path)),
    })
}

/// The file at `path` when it is a plain name in one of the [`SERVED`] folders.
fn served_file(root: &Path, path: &str) -> Option<Response> {
    let relative = path.strip_prefix('/')?;
    let (folder, name) = relative.rsplit_once('/')?;
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-.".contains(c);
    if !SERVED.contains(&format!("{folder}/").as_str()) || !name.chars().all(plain) || name.starts_with('.') {
        return None;
    }
    let content_type = match name.rsplit_once('.')?.1 {
        "html" => "text/html; charset=utf-8",
        "js" => "text/javascript; charset=utf-8",
        _ => "text/plain; charset=utf-8",
    };
    let body = std::fs::read(root.join(relative)).ok()?;
    Some(Response::ok(content_type, body))
}

/// Why the wgpu rendering of the demo failed.
#[derive(Debug)]
pub struct DemoError(pub String);

impl std::fmt::Display for DemoError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl std::error::Error for DemoError {}

/// The page's shader source: the modules in the page's order, then `render.wgsl`.
pub fn shader_source() -> String {
    format!("{}\n{RENDER_WGSL}", wgsl_prelude(&MODULES))
}

/// The demo in `mode` rendered by the page's shader through wgpu on the local Vulkan device (a CPU
/// adapter, lavapipe here, where there is one), at [`IMAGE_SIZE`], with wgpu's validation on.
pub fn render_with_wgpu(mode: DemoMode) -> Result<Image, DemoError> {
    pollster::block_on(render(mode))
}

async fn render(mode: DemoMode) -> Result<Image, DemoError> {
    let (device, queue) = open().await?;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("demo"),
        source: wgpu::ShaderSource::Wgsl(shader_source().into()),
    });
    let texture = ground_texture(&device, &queue, &module);
    let image = render_image(&device, &queue, &module, &texture, mode);
    if let Some(error) = scope.pop().await {
        return Err(DemoError(format!("wgpu: {error}")));
    }
    read_image(&device, &queue, &image).await
}

/// A CPU adapter (lavapipe), else the first, and a device on it.
async fn open() -> Result<(wgpu::Device, wgpu::Queue), DemoError> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapters = instance.enumerate_adapters(wgpu::Backends::VULKAN).await;
    let adapter = adapters
        .iter()
        .find(|adapter| adapter.get_info().device_type == wgpu::DeviceType::Cpu)
        .or(adapters.first())
        .ok_or_else(|| DemoError("no Vulkan adapter for wgpu: run scripts/setup.sh".into()))?;
    adapter
        .request_device(&wgpu::DeviceDescriptor::default())
        .await
        .map_err(|error| DemoError(format!("wgpu request_device: {error}")))
}

/// A compute pipeline of `entry_point`.
fn pipeline(device: &wgpu::Device, module: &wgpu::ShaderModule, entry_point: &str) -> wgpu::ComputePipeline {
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry_point),
        layout: None,
        module,
        entry_point: Some(entry_point),
        compilation_options: wgpu::PipelineCompilationOptions::default(),
        cache: None,
    })
}

/// Records `pipeline` over `size` with `resources` bound (binding, resource).
fn dispatch(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    pipeline: &wgpu::ComputePipeline,
    resources: &[(u32, wgpu::BindingResource<'_>)],
    size: [u32; 2],
) {
    let entries: Vec<wgpu::BindGroupEntry<'_>> = resources
        .iter()
        .map(|(binding, resource)| wgpu::BindGroupEntry {
            binding: *binding,
            resource: resource.clone(),
        })
        .collect();
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    });
    let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
    pass.set_pipeline(pipeline);
    pass.set_bind_group(0, &bind_group, &[]);
    pass.dispatch_workgroups(size[0].div_ceil(8), size[1].div_ceil(8), 1);
}

/// The ground texture and its mip chain, made by `render.wgsl`'s texture entry points, as the
/// page makes them.
fn ground_texture(device: &wgpu::Device, queue: &wgpu::Queue, module: &wgpu::ShaderModule) -> wgpu::Texture {
    let levels = TEXTURE_SIZE.ilog2() + 1;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ground"),
        size: wgpu::Extent3d {
            width: TEXTURE_SIZE,
            height: TEXTURE_SIZE,
            depth_or_array_layers: 1,
        },
        mip_level_count: levels,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::STORAGE_BINDING,
        view_formats: &[],
    });
    let level = |mip: u32| {
        texture.create_view(&wgpu::TextureViewDescriptor {
            base_mip_level: mip,
            mip_level_count: Some(1),
            ..wgpu::TextureViewDescriptor::default()
        })
    };
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    let level0 = level(0);
    let first = pipeline(device, module, "texture_level0");
    dispatch(
        device,
        &mut encoder,
        &first,
        &[(4, wgpu::BindingResource::TextureView(&level0))],
        [TEXTURE_SIZE; 2],
    );
    let downsample = pipeline(device, module, "texture_downsample");
    for mip in 1..levels {
        let (below, above) = (level(mip), level(mip - 1));
        let resources = [
            (4, wgpu::BindingResource::TextureView(&below)),
            (5, wgpu::BindingResource::TextureView(&above)),
        ];
        dispatch(
            device,
            &mut encoder,
            &downsample,
            &resources,
            [TEXTURE_SIZE >> mip; 2],
        );
    }
    queue.submit([encoder.finish()]);
    texture
}

/// The scene in `mode`, rendered into a new storage texture of [`IMAGE_SIZE`].
fn render_image(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    module: &wgpu::ShaderModule,
    ground: &wgpu::Texture,
    mode: DemoMode,
) -> wgpu::Texture {
    use wgpu::util::DeviceExt;
    let params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("params"),
        contents: bytemuck::cast_slice(&[mode.number(), 0, 0, 0]),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        address_mode_u: wgpu::AddressMode::Repeat,
        address_mode_v: wgpu::AddressMode::Repeat,
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        mipmap_filter: wgpu::MipmapFilterMode::Linear,
        anisotropy_clamp: 16,
        ..wgpu::SamplerDescriptor::default()
    });
    let image = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("image"),
        size: wgpu::Extent3d {
            width: IMAGE_SIZE[0],
            height: IMAGE_SIZE[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let (ground_view, image_view) = (
        ground.create_view(&Default::default()),
        image.create_view(&Default::default()),
    );
    let resources = [
        (0, params.as_entire_binding()),
        (1, wgpu::BindingResource::TextureView(&ground_view)),
        (2, wgpu::BindingResource::Sampler(&sampler)),
        (3, wgpu::BindingResource::TextureView(&image_view)),
    ];
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    dispatch(
        device,
        &mut encoder,
        &pipeline(device, module, "render"),
        &resources,
        IMAGE_SIZE,
    );
    queue.submit([encoder.finish()]);
    image
}

/// The pixels of `image` (RGBA8), as an [`Image`] of display values.
async fn read_image(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    image: &wgpu::Texture,
) -> Result<Image, DemoError> {
    let [width, height] = IMAGE_SIZE;
    let row = (4 * width).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: u64::from(row * height),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    encoder.copy_texture_to_buffer(
        image.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: None,
            },
        },
        image.size(),
    );
    queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|error| DemoError(format!("wgpu poll: {error}")))?;
    let bytes = slice
        .get_mapped_range()
        .map_err(|error| DemoError(format!("wgpu reading the image: {error}")))?;
    let pixels = bytes
        .chunks_exact(row as usize)
        .flat_map(|line| line[..4 * width as usize].chunks_exact(4))
        .map(|p| [0, 1, 2].map(|c| f32::from(p[c]) / 255.0))
        .collect();
    Ok(Image {
        width,
        height,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The page's table quotes the README's method guide: every cell with a number is there word
    /// for word.
    #[test]
    fn the_page_quotes_the_method_guide() {
        let root = repository();
        let page = std::fs::read_to_string(root.join(PAGE_PATH.trim_start_matches('/'))).expect("the page");
        let readme = std::fs::read_to_string(root.join("README.md")).expect("the README");
        let cells: Vec<&str> = page
            .split("<td>")
            .skip(1)
            .filter_map(|cell| cell.split_once("</td>").map(|(text, _)| text))
            .filter(|text| text.contains(|c: char| c.is_ascii_digit()))
            .collect();
        assert!(cells.len() >= 4, "the page's table: {cells:?}");
        for cell in cells {
            assert!(
                readme.contains(cell),
                "the page says {cell:?}, the README does not"
            );
        }
    }

    /// Only plain names in the two folders are served.
    #[test]
    fn only_the_page_and_the_modules_are_served() {
        let root = repository();
        assert!(served_file(&root, "/shaders/wgsl/ray_cone.wgsl").is_some());
        assert!(served_file(&root, "/crates/ray-footprint-lab/web/index.html").is_some());
        for path in [
            "/Cargo.toml",
            "/shaders/wgsl/../../Cargo.toml",
            "/shaders/glsl/ray_cone.glsl",
            "/crates/ray-footprint-lab/web/.hidden",
        ] {
            assert!(served_file(&root, path).is_none(), "{path}");
        }
    }
}
