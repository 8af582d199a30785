//! Ray tracing with the modules (feature `gpu`): acceleration structures, a GLSL ray-tracing
//! pipeline and a WGSL ray-query compute shader on the harness device, validation layer on.
//!
//! A [`Renderer`] uploads a [`Scene`] built in code (a large textured ground plane, a mirror sphere,
//! a dense torus), builds one bottom-level acceleration structure per mesh and a top-level one,
//! makes a checker texture and a mip-colour texture with full mip chains, a trilinear sampler with
//! `maxLod = VK_LOD_CLAMP_NONE` (anisotropic where the device allows), and two pipelines:
//!
//! - GLSL (`shaders/raygen.rgen`, `miss.rmiss`, `closest_hit.rchit`, compiled with glslang with the
//!   library's GLSL directory on the include path): the closest-hit shader `#include`s
//!   `ray_cone.glsl`, `ray_diff.glsl` and `wireframe.glsl`, carries the cone in an `RfHitPayload`,
//!   reads `RfRayConePushConstants` inside the renderer's push constants and the inverse camera
//!   matrices and `RfWireframePushConstants` from a uniform buffer ([`RtUniforms`]), measures every
//!   ray-cone value at the hit and, on primary hits, the ray differentials, the re-intersected
//!   barycentric offsets and the wireframe coverage, and shades in the chosen [`Mode`];
//! - WGSL (`shaders/ray_query.wgsl`, compiled with naga): a compute shader tracing the primary rays
//!   with a ray query over the same acceleration structures and measuring the same values with
//!   `ray_cone.wgsl`, `ray_diff.wgsl` and `wireframe.wgsl`.
//!
//! Both record, per pixel, the primary hit and what was measured there ([`RtPixelRecord`]), so the
//! Rust mirror can recompute every value from the same hit data.
//!
//! ```no_run
//! use ray_footprint::gpu::rt::{Camera, Mode, Renderer, Scene};
//! use ray_footprint::gpu::Gpu;
//! use ray_footprint::wireframe::WireframeSettings;
//!
//! let gpu = Gpu::new_ray_tracing()?;
//! let renderer = Renderer::new(&gpu, Scene::gallery())?;
//! let camera = Camera::ground();
//! let push = renderer.push_constants(&camera, Mode::Cone, 1.0, 320, 180);
//! let uniforms = camera.uniforms((320, 180), WireframeSettings::default());
//! let frame = renderer.render(&push, &uniforms)?;
//! println!("{} pixels in {:?}", frame.pixels.len(), frame.trace_time);
//! # Ok::<(), ray_footprint::gpu::GpuError>(())
//! ```
//!
//! [`RtPixelRecord`]: crate::abi::RtPixelRecord
//! [`RtUniforms`]: crate::abi::RtUniforms

mod accel;
mod memory;
mod mode;
mod pipeline;
mod renderer;
mod scene;
mod texture;

pub use mode::Mode;
pub use pipeline::{ray_query_source, SHADER_DIR};
pub use renderer::{Frame, Renderer};
pub use scene::{
    ground_plane, torus, uv_sphere, Camera, Material, Mesh, Scene, Vertex, VERTEX_FLOATS, WIRE_COLOUR,
};
pub use texture::{checker, mip_colours, MipChain, CHECKER_SQUARE, LEVEL_COLOURS, TEXTURE_SIZE};
