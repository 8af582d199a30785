//! Ray tracing with the modules: acceleration structures, a ray-tracing pipeline (GLSL, with a GLSL,
//! a Slang or an HLSL closest-hit shader) and, where the device has ray queries, a WGSL ray-query compute
//! shader, on a shader-proptest device with the validation layer on.
//!
//! A [`Renderer`] uploads a [`Scene`] built in code (a large textured ground plane, a mirror sphere,
//! a dense torus; or glass and rough mirror spheres over the plane, [`Scene::materials`]), builds one bottom-level acceleration structure per mesh and a top-level one,
//! makes a checker texture and a mip-colour texture with full mip chains, a trilinear sampler with
//! `maxLod = VK_LOD_CLAMP_NONE` (anisotropic where the device allows), and its pipelines:
//!
//! - GLSL (`shaders/raygen.rgen`, `miss.rmiss`, `closest_hit.rchit`, compiled with glslang with the
//!   library's GLSL directory on the include path): the shaders `#include` `ray_cone.glsl`,
//!   `ray_diff.glsl` and `wireframe.glsl`, carry the cone in an `RfHitPayload` and an `RfRayDiff`
//!   beside it (the renderer's payload), read `RfRayConePushConstants` inside the renderer's push
//!   constants and the inverse camera matrices and `RfWireframePushConstants` from a uniform buffer
//!   ([`RtUniforms`]); on a primary hit the closest-hit shader measures every ray-cone value, the
//!   ray differentials, the re-intersected barycentric offsets, the wireframe coverage, the
//!   material's values (a mirror's roughness spread, glass's refracted cone) and the anisotropic
//!   cone gradients, and it shades in the chosen [`Mode`] with the shading code of
//!   `rt_shading.glsl` that the colour-only pipelines ([`ColourPipeline`]) share;
//! - Slang (`shaders/closest_hit.slang`, compiled with slangc with the library's Slang directory
//!   on the search path) and HLSL (`shaders/closest_hit.hlsl`, compiled with slangc reading HLSL,
//!   with the library's HLSL directory on the include path; glslang's HLSL front end has no
//!   ray-tracing stages): the recording closest-hit stage, the one first `import`-ing `ray_cone`,
//!   `ray_diff` and `wireframe`, the other `#include`-ing `ray_cone.hlsl`, `ray_diff.hlsl` and
//!   `wireframe.hlsl`, and both then the closest hit of `rt_closest_hit.hlsl`: the same bindings,
//!   push constants and payload as the GLSL stages, declared with `[[vk::binding]]` and
//!   `[[vk::push_constant]]` (the combined image samplers as slangc's `Sampler2D`), and the same
//!   `rt_shading.glsl` compiled through slangc's GLSL compatibility (`import glsl;`), so that every
//!   library call in it is a call of the Slang or of the HLSL modules. Each takes the GLSL closest
//!   hit's place in the recording pipeline, with the GLSL ray generation and miss
//!   ([`Renderer::with_closest_hit`], [`ClosestHit::Slang`] and [`ClosestHit::Hlsl`]);
//! - WGSL (`shaders/ray_query.wgsl`, compiled with naga): a compute shader tracing the primary rays
//!   with a ray query over the same acceleration structures and measuring the same values with
//!   `ray_cone.wgsl`, `ray_diff.wgsl` and `wireframe.wgsl`.
//!
//! All four record, per pixel, the primary hit and what was measured there ([`RtPixelRecord`]), so
//! the Rust mirror can recompute every value from the same hit data. The structs and constants the
//! shaders share with Rust are declared once, in [`abi`] (the structs, the flags, the shading
//! constants), [`Mode`] (the modes' discriminants) and the scene (the materials and the buffers'
//! layout), and written into `rt_abi.glsl`, `rt_abi.slang`, `rt_abi.hlsl` and `ray_query.wgsl` by
//! `cargo xtask codegen`.
//!
//! ```no_run
//! use ray_footprint::wireframe::WireframeSettings;
//! use ray_footprint_lab::rt::{open_device, Camera, Mode, Renderer, Scene};
//!
//! let gpu = open_device()?;
//! let renderer = Renderer::new(&gpu, Scene::gallery())?;
//! let camera = Camera::ground();
//! let push = renderer.push_constants(&camera, Mode::Cone, 1.0, 320, 180);
//! let uniforms = camera.uniforms((320, 180), WireframeSettings::default());
//! let frame = renderer.render(&push, &uniforms)?;
//! println!("{} pixels in {:?}", frame.pixels.len(), frame.trace_time);
//! # Ok::<(), ray_footprint_lab::rt::Error>(())
//! ```
//!
//! [`RtPixelRecord`]: abi::RtPixelRecord
//! [`RtUniforms`]: abi::RtUniforms

pub mod abi;
mod accel;
mod mode;
mod pipeline;
mod renderer;
mod scene;
mod texture;

pub use mode::{Mode, Payload, PATH_LOD_BIAS};
pub use pipeline::{ray_query_source, ClosestHit, SHADER_DIR};
pub use renderer::{open_device, ColourPipeline, Frame, Renderer, Timed, DEVICE_REQUEST};
pub use scene::{
    ground_plane, hyperbolic_paraboloid, room, torus, uv_sphere, Camera, Diagonals, Material, Mesh, Scene,
    Vertex, GLASS_CENTRE, GLASS_INDEX, GLASS_RADIUS, MATERIAL_GLASS, MATERIAL_MIRROR, MATERIAL_TEXTURED,
    MESH_TABLE_WORDS, ROUGHNESS, VERTEX_FLOATS, WIRE_COLOUR,
};
pub use texture::{
    checker, enlarged, mip_colours, two_scale_checker, MipChain, CHECKER_SQUARE, LEVEL_COLOURS, TEXTURE_SIZE,
};

use std::fmt;

/// Why a frame was not traced.
#[derive(Debug)]
pub enum Error {
    /// The device, a compiler or the validation layer failed.
    Gpu(shader_proptest::Error),
    /// The frame has more pixels than its per-pixel buffers can hold on this device.
    FrameTooLarge {
        /// Pixels asked for.
        pixels: u64,
        /// Pixels the device allows per frame.
        max: u64,
    },
    /// A frame without pixels was asked for.
    EmptyFrame {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// The device lacks what this way of tracing needs: the reason. Report it as not run.
    NotSupported(String),
    /// A texture given to [`Renderer::with_texture`] is not a full square mip chain: what is wrong.
    InvalidTexture(String),
    /// A mesh's material has a parameter the shaders cannot take: the mesh and what is wrong
    /// ([`Material::validate`]).
    InvalidMaterial(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Gpu(error) => write!(f, "{error}"),
            Error::FrameTooLarge { pixels, max } => write!(
                f,
                "a frame of {pixels} pixels is too large: this device's maxStorageBufferRange holds \
                 the per-pixel records of at most {max} pixels"
            ),
            Error::EmptyFrame { width, height } => {
                write!(f, "a frame of {width} x {height} pixels has no pixels")
            }
            Error::NotSupported(reason) => write!(f, "not supported: {reason}"),
            Error::InvalidTexture(reason) => write!(f, "invalid texture: {reason}"),
            Error::InvalidMaterial(reason) => write!(f, "invalid material: {reason}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<shader_proptest::Error> for Error {
    fn from(error: shader_proptest::Error) -> Error {
        Error::Gpu(error)
    }
}
