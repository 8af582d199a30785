//! wgpu helpers (feature `wgpu`): a shader with this crate's WGSL modules in front of it, in the
//! line where `include_wgsl!` was, and the mip levels of a texture made on the GPU.
//!
//! ```no_run
//! # fn demo(device: &wgpu::Device, queue: &wgpu::Queue, albedo: &wgpu::Texture) -> Result<(), ray_footprint::mip::MipError> {
//! use ray_footprint::shaders::Module;
//!
//! // Your shader, which calls the modules' functions.
//! const TRACE: &str = "@group(0) @binding(0) var<storage, read_write> lods: array<f32>;
//! @compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {
//!     lods[id.x] = rf_texture_lod(0.0, 0.01, vec2<f32>(1024.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, -1.0, 0.0));
//! }";
//! // Where `device.create_shader_module(wgpu::include_wgsl!("trace.wgsl"))` was:
//! let module = device.create_shader_module(ray_footprint::wgpu::shader_with_modules("trace.wgsl", TRACE, &[Module::RayCone]));
//! // Every level below the one you uploaded, box-filtered as light.
//! ray_footprint::wgpu::generate_mipmaps(device, queue, albedo)?;
//! # Ok(()) }
//! ```

use crate::mip::MipError;
use crate::shaders::{wgsl_prelude, Module};

/// A shader module descriptor of `source` with `modules` in front of it ([`wgsl_prelude`]),
/// labelled `label`: `device.create_shader_module(shader_with_modules("trace.wgsl",
/// include_str!("trace.wgsl"), &[Module::RayCone]))` where `include_wgsl!("trace.wgsl")` was.
pub fn shader_with_modules(
    label: &'static str,
    source: &str,
    modules: &[Module],
) -> wgpu::ShaderModuleDescriptor<'static> {
    wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(format!("{}{source}", wgsl_prelude(modules)).into()),
    }
}

/// The formats [`generate_mipmaps`] fills.
const FORMATS: [wgpu::TextureFormat; 3] = [
    wgpu::TextureFormat::Rgba8UnormSrgb,
    wgpu::TextureFormat::Rgba8Unorm,
    wgpu::TextureFormat::Rgba16Float,
];

/// Fills mip levels 1 and below of `texture` from level 0, each the box filter of the level above
/// over the exact area each texel covers, as [`crate::mip`] does on the CPU (sRGB textures are
/// averaged as light: the view decodes, the target encodes). One render pass per level, submitted
/// to `queue`; the caller's later submissions see the levels.
///
/// The texture must be a single 2-D layer of an RGBA8 (sRGB or not) or RGBA16 float format with
/// `TEXTURE_BINDING | RENDER_ATTACHMENT` usage; otherwise the error names the descriptor's field,
/// its value and what it must be. A texture of one level has nothing to fill.
pub fn generate_mipmaps(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<(), MipError> {
    check_texture(texture)?;
    if texture.mip_level_count() == 1 {
        return Ok(());
    }
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ray_footprint mip level"),
        source: wgpu::ShaderSource::Wgsl(include_str!("mip.wgsl").into()),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("ray_footprint mip level"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("covering_triangle"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("box_filter"),
            compilation_options: Default::default(),
            targets: &[Some(texture.format().into())],
        }),
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: wgpu::MultisampleState::default(),
        multiview_mask: None,
        cache: None,
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("ray_footprint mip levels"),
    });
    for level in 1..texture.mip_level_count() {
        let view = |mip: u32| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                base_mip_level: mip,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(&view(level - 1)),
            }],
        });
        let target = view(level);
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("ray_footprint mip level"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })],
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
    queue.submit([encoder.finish()]);
    Ok(())
}

/// The first property of `texture` that [`generate_mipmaps`] cannot fill, as an error.
fn check_texture(texture: &wgpu::Texture) -> Result<(), MipError> {
    let refuse = |field, value: String, expected| {
        Err(MipError::Texture {
            field,
            value,
            expected,
        })
    };
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT;
    if !FORMATS.contains(&texture.format()) {
        refuse(
            "format",
            format!("{:?}", texture.format()),
            "Rgba8UnormSrgb, Rgba8Unorm or Rgba16Float",
        )
    } else if texture.dimension() != wgpu::TextureDimension::D2 {
        refuse("dimension", format!("{:?}", texture.dimension()), "D2")
    } else if texture.depth_or_array_layers() != 1 {
        refuse(
            "depth_or_array_layers",
            texture.depth_or_array_layers().to_string(),
            "1",
        )
    } else if !texture.usage().contains(usage) {
        refuse(
            "usage",
            format!("{:?}", texture.usage()),
            "TEXTURE_BINDING | RENDER_ATTACHMENT",
        )
    } else {
        Ok(())
    }
}
