//! The structs that cross the CPU/GPU boundary, as `#[repr(C)]` bytemuck `Pod` mirrors.
//!
//! Every shared struct has one byte layout in Rust, in WGSL (naga's layout for host-shareable
//! memory), in GLSL under `std430` (the default of push constants and storage buffers) and in GLSL
//! under `scalar` block layout (GL_EXT_scalar_block_layout, what Slang-generated Vulkan code uses).
//! Field order and explicit padding fields (always 0) make these coincide; no struct has implicit
//! padding. With the `validate` feature the crate does not compile unless each Rust mirror has
//! the offsets, size and alignment naga computes for its WGSL declaration; the tests compare the
//! GLSL layouts from glslang's SPIR-V too, and echo random values through the GPU.
//!
//! | Rust | shader | declared in | bytes |
//! | --- | --- | --- | --- |
//! | [`RayCone`] | `RfRayCone` | `ray_cone` | 8 |
//! | [`PackedRayCone`] | `u32` | `ray_cone` | 4 |
//! | [`HitPayload`] | `RfHitPayload` | `ray_cone` | 32 |
//! | [`RayConePushConstants`] | `RfRayConePushConstants` | `ray_cone` | 8 |
//! | [`RayDiff`] | `RfRayDiff` | `ray_diff` | 64 |
//! | [`WireframeSettingsIo`] | `RfWireframeSettingsIo` | `wireframe` | 32 |
//! | [`WireframePushConstants`] | `RfWireframePushConstants` | `wireframe` | 48 |
//!
//! # Why booleans become integers
//!
//! GLSL lays out a `bool` in a block as 4 bytes, Rust as 1 byte, and WGSL does not allow `bool` in
//! host-shareable memory at all. A Rust struct with a `bool` pushed to a GLSL block with a `bool`
//! puts every later field at the wrong offset. Such a struct is not even `Pod`:
//!
//! ```compile_fail,E0277
//! #[repr(C)]
//! #[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
//! struct Settings {
//!     thickness: f32,
//!     stipple: bool,
//! }
//! ```
//!
//! so every bool crosses the boundary as a 32-bit integer (0 = false, anything else = true).
//!
//! # Reading structs from bytes
//!
//! Bytes read back from the GPU or a file become structs through [`from_bytes`] (one struct, any
//! alignment), [`vec_from_bytes`] (an array, copied, any alignment) or [`slice_from_bytes`] (an
//! array in place; the bytes must be aligned for the struct). A wrong byte count or a misaligned
//! start is a [`BytesError`] naming the struct, the size or alignment it needs and what it got:
//!
//! ```
//! use ray_footprint::abi::{from_bytes, HitPayload};
//!
//! let error = from_bytes::<HitPayload>(&[0; 31]).unwrap_err();
//! assert_eq!(error.to_string(), "ray_footprint::abi::HitPayload: expected 32 bytes, got 31");
//! ```
//!
//! Every bit pattern is a valid value of these structs; what the values mean is checked elsewhere
//! (for settings, [`WireframeSettingsIo::unpack`] then [`crate::wireframe::WireframeSettings::validate`]).

use bytemuck::{Pod, Zeroable};
use glam::{Vec3, Vec4};

pub use crate::ray_cone::{PackedRayCone, RayCone};
pub use crate::ray_diff::RayDiff;
pub use crate::wireframe::WireframeSettingsIo;

/// The push-constant bytes every Vulkan device accepts (the minimum of `maxPushConstantsSize`).
pub const PUSH_CONSTANT_LIMIT: usize = 128;

/// A ray payload carrying a cone (`RfHitPayload`): accumulated colour, path weight, the cone at the
/// ray's origin, and the bounce depth. 32 bytes, 16-byte aligned like its vec3.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct HitPayload {
    /// Accumulated colour.
    pub colour: Vec3,
    /// Path weight (throughput).
    pub weight: f32,
    /// The ray cone at the ray's origin.
    pub cone: RayCone,
    /// Bounce depth, 0 for a primary ray.
    pub depth: u32,
    /// Always 0: makes the size a multiple of 16 explicitly.
    pub pad: u32,
}

/// Push constants of a ray-cone renderer (`RfRayConePushConstants`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RayConePushConstants {
    /// `textureGrad` scale: 0 samples mip 0, 1 the matching level, above 1 blurs.
    pub tex_grad_scale: f32,
    /// The camera's pixel spread angle ([`crate::ray_cone::pixel_spread_angle`]).
    pub pixel_spread_angle: f32,
}

/// Push constants of a wireframe overlay (`RfWireframePushConstants`): line colour and settings.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct WireframePushConstants {
    /// Line colour, RGBA.
    pub colour: Vec4,
    /// The wireframe settings, bools as integers.
    pub settings: WireframeSettingsIo,
}

const _: () = assert!(std::mem::size_of::<RayConePushConstants>() <= PUSH_CONSTANT_LIMIT);
const _: () = assert!(std::mem::size_of::<WireframePushConstants>() <= PUSH_CONSTANT_LIMIT);
const _: () = assert!(std::mem::size_of::<PackedRayCone>() == 4);

/// Bytes that do not hold the requested structs: the struct's Rust type, what it needs and what
/// the bytes are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BytesError {
    /// [`from_bytes`]: the byte count is not the struct's size.
    Length {
        /// The struct's Rust type.
        structure: &'static str,
        /// Its size in bytes.
        expected: usize,
        /// The byte count received.
        actual: usize,
    },
    /// [`vec_from_bytes`], [`slice_from_bytes`]: the byte count is not a multiple of the struct's
    /// size (or the struct has no size).
    NotWhole {
        /// The struct's Rust type.
        structure: &'static str,
        /// Its size in bytes.
        size: usize,
        /// The byte count received.
        actual: usize,
    },
    /// [`slice_from_bytes`]: the bytes start at an address that is not a multiple of the struct's
    /// alignment.
    Misaligned {
        /// The struct's Rust type.
        structure: &'static str,
        /// Its alignment in bytes.
        align: usize,
        /// The start address of the bytes modulo `align` (never 0).
        misalignment: usize,
    },
}

impl std::fmt::Display for BytesError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            BytesError::Length {
                structure,
                expected,
                actual,
            } => write!(f, "{structure}: expected {expected} bytes, got {actual}"),
            BytesError::NotWhole {
                structure,
                size,
                actual,
            } => write!(
                f,
                "{structure}: {actual} bytes are not a whole number of {size}-byte structs"
            ),
            BytesError::Misaligned {
                structure,
                align,
                misalignment,
            } => write!(
                f,
                "{structure}: the bytes start {misalignment} byte(s) past a multiple of the struct's \
                 alignment {align} (vec_from_bytes copies them from any address)"
            ),
        }
    }
}

impl std::error::Error for BytesError {}

/// One `T` from exactly `size_of::<T>()` bytes at any alignment (a copy).
///
/// # Examples
///
/// ```
/// use ray_footprint::abi::{from_bytes, RayCone};
///
/// // A cone read back from a GPU buffer: the width's f32, then the spread angle's.
/// let bytes = [0.5f32.to_ne_bytes(), 0.001f32.to_ne_bytes()].concat();
/// let cone: RayCone = from_bytes(&bytes)?;
/// assert_eq!(cone, RayCone { width: 0.5, spread_angle: 0.001 });
/// # Ok::<(), ray_footprint::abi::BytesError>(())
/// ```
pub fn from_bytes<T: Pod>(bytes: &[u8]) -> Result<T, BytesError> {
    bytemuck::try_pod_read_unaligned(bytes).map_err(|_| BytesError::Length {
        structure: std::any::type_name::<T>(),
        expected: std::mem::size_of::<T>(),
        actual: bytes.len(),
    })
}

/// `bytes.len() / size_of::<T>()` structs from a whole number of them at any alignment (a copy).
///
/// # Examples
///
/// ```
/// use ray_footprint::abi::{vec_from_bytes, HitPayload};
///
/// // Two 32-byte payloads one byte into a readback; `depth` is at byte 24 of each (after the
/// // 12-byte colour, the 4-byte weight and the 8-byte cone).
/// let mut bytes = vec![0u8; 1 + 64];
/// bytes[1 + 24..1 + 28].copy_from_slice(&3u32.to_ne_bytes());
/// bytes[1 + 32 + 24..1 + 32 + 28].copy_from_slice(&1u32.to_ne_bytes());
/// let payloads: Vec<HitPayload> = vec_from_bytes(&bytes[1..])?;
/// assert_eq!(payloads.iter().map(|payload| payload.depth).collect::<Vec<_>>(), [3, 1]);
/// // 40 bytes are not a whole number of payloads.
/// assert!(vec_from_bytes::<HitPayload>(&bytes[1..41]).is_err());
/// # Ok::<(), ray_footprint::abi::BytesError>(())
/// ```
pub fn vec_from_bytes<T: Pod>(bytes: &[u8]) -> Result<Vec<T>, BytesError> {
    let size = std::mem::size_of::<T>();
    if size == 0 || !bytes.len().is_multiple_of(size) {
        return Err(not_whole::<T>(bytes));
    }
    Ok(bytes
        .chunks_exact(size)
        .map(bytemuck::pod_read_unaligned)
        .collect())
}

/// The structs that a whole number of them occupy, in place: `bytes` must start at a multiple of
/// `align_of::<T>()`.
///
/// # Examples
///
/// ```
/// use ray_footprint::abi::{slice_from_bytes, BytesError, PackedRayCone, RayCone};
/// use ray_footprint::ray_cone::unpack_ray_cone;
///
/// // Packed cones in a u32 buffer, read in place. In binary16 0x3c00 is 1.0 and 0x3800 is 0.5.
/// let words: Vec<u32> = vec![0x3800_3c00, 0x3c00_3800];
/// let bytes: &[u8] = bytemuck::cast_slice(&words);
/// let cones = slice_from_bytes::<PackedRayCone>(bytes)?;
/// assert_eq!(unpack_ray_cone(cones[1]), RayCone { width: 0.5, spread_angle: 1.0 });
/// // One byte further the four bytes are not 4-byte aligned.
/// let misaligned = slice_from_bytes::<PackedRayCone>(&bytes[1..5]);
/// assert!(matches!(misaligned, Err(BytesError::Misaligned { align: 4, misalignment: 1, .. })));
/// # Ok::<(), BytesError>(())
/// ```
pub fn slice_from_bytes<T: Pod>(bytes: &[u8]) -> Result<&[T], BytesError> {
    let size = std::mem::size_of::<T>();
    if size == 0 || !bytes.len().is_multiple_of(size) {
        return Err(not_whole::<T>(bytes));
    }
    bytemuck::try_cast_slice(bytes).map_err(|_| BytesError::Misaligned {
        structure: std::any::type_name::<T>(),
        align: std::mem::align_of::<T>(),
        misalignment: bytes.as_ptr() as usize % std::mem::align_of::<T>(),
    })
}

fn not_whole<T>(bytes: &[u8]) -> BytesError {
    BytesError::NotWhole {
        structure: std::any::type_name::<T>(),
        size: std::mem::size_of::<T>(),
        actual: bytes.len(),
    }
}

// Generated by build.rs: offsets, sizes and alignments naga computes for the WGSL declarations.
#[cfg(feature = "validate")]
include!(concat!(env!("OUT_DIR"), "/layout_asserts.rs"));

/// Every shared struct: the module whose shader files declare it, and its Rust layout.
///
/// # Examples
///
/// ```
/// use ray_footprint::abi::shared_layouts;
///
/// // RfRayDiff: four vec3s, each followed by its f32 pad, 64 bytes in all.
/// let layouts = shared_layouts();
/// let (_, ray_diff) = layouts.iter().find(|(_, layout)| layout.name == "RfRayDiff").unwrap();
/// let offsets: Vec<u32> = ray_diff.fields.iter().map(|field| field.offset).collect();
/// assert_eq!(offsets, [0, 12, 16, 28, 32, 44, 48, 60]);
/// assert_eq!(ray_diff.size, 64);
/// ```
// generated by `cargo xtask codegen` from src/ray_cone.rs, src/abi.rs, src/ray_diff.rs, src/ray_diff_f64.rs, src/wireframe.rs: do not edit
#[cfg(feature = "validate")]
#[rustfmt::skip]
pub fn shared_layouts() -> Vec<(crate::shaders::Module, crate::layout::StructLayout)> {
    use crate::rust_layout;
    use crate::shaders::Module;
    vec![
        (Module::RayCone, rust_layout!(RayCone as "RfRayCone" { width, spread_angle })),
        (Module::RayCone, rust_layout!(HitPayload as "RfHitPayload" { colour, weight, cone, depth, pad })),
        (Module::RayCone, rust_layout!(RayConePushConstants as "RfRayConePushConstants" { tex_grad_scale, pixel_spread_angle })),
        (Module::RayDiff, rust_layout!(RayDiff as "RfRayDiff" { d_origin_dx, pad0, d_origin_dy, pad1, d_direction_dx, pad2, d_direction_dy, pad3 })),
        (Module::Wireframe, rust_layout!(WireframeSettingsIo as "RfWireframeSettingsIo" { thickness_var, thickness, smoothing, stipple, stipple_length, stipple_repeats, screen_space })),
        (Module::Wireframe, rust_layout!(WireframePushConstants as "RfWireframePushConstants" { colour, settings })),
    ]
}
// end of generated code

/// Reads every shared struct's layout from the WGSL module (naga), from the GLSL module in a
/// std430 and a scalar block (glslang), from the Slang module in a std430 and a scalar
/// structured buffer (slangc) and from the HLSL module in a structured buffer (std430, glslang's
/// HLSL front end and slangc), compares each with the Rust mirror, and renders one table per
/// struct (Rust / WGSL / std430 / scalar / Slang std430 / Slang scalar / HLSL glslang / HLSL
/// slangc). Fails on the first difference, naming the struct and field. Needs `glslangValidator`
/// and `slangc`.
///
/// # Examples
///
/// ```
/// use ray_footprint::abi::verify_shared_layouts;
///
/// // RayDiff's d_origin_dy is 12 bytes at byte 16 in Rust and in all seven shader layouts.
/// let tables = verify_shared_layouts()?;
/// let row = tables.lines().find(|line| line.trim_start().starts_with("d_origin_dy ")).unwrap();
/// assert_eq!(row.split_whitespace().skip(1).collect::<Vec<_>>(), ["16/12"; 8]);
/// # Ok::<(), ray_footprint::layout::LayoutError>(())
/// ```
#[cfg(feature = "validate")]
pub fn verify_shared_layouts() -> Result<String, crate::layout::LayoutError> {
    use crate::layout::{compare, glsl_layout, render_columns, slang_layout, wgsl_layout, GlslPacking};
    use crate::shaders::{GLSL_INCLUDE_DIR, HLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
    use shader_proptest::{Language, Shader};
    let glsl_dir = std::path::Path::new(GLSL_INCLUDE_DIR);
    let slang_dir = std::path::Path::new(SLANG_INCLUDE_DIR);
    let mut tables = Vec::new();
    for (module, rust) in shared_layouts() {
        let include = format!("#include \"{}.glsl\"", module.stem());
        let import = format!("import {};", module.stem());
        let name = &rust.name;
        let hlsl = |language| {
            Shader::new(language, format!("#include \"{}.hlsl\"", module.stem()))
                .include_dir(HLSL_INCLUDE_DIR)
                .struct_layout(name)
        };
        let columns = [
            ("WGSL", wgsl_layout(module.wgsl(), name)?),
            (
                "std430",
                glsl_layout(&include, name, GlslPacking::Std430, &[glsl_dir])?,
            ),
            (
                "scalar",
                glsl_layout(&include, name, GlslPacking::Scalar, &[glsl_dir])?,
            ),
            (
                "Slang std430",
                slang_layout(&import, name, GlslPacking::Std430, &[slang_dir])?,
            ),
            (
                "Slang scalar",
                slang_layout(&import, name, GlslPacking::Scalar, &[slang_dir])?,
            ),
            ("HLSL glslang", hlsl(Language::HlslGlslang)?),
            ("HLSL slangc", hlsl(Language::HlslSlangc)?),
        ];
        for (_, shader) in &columns {
            compare(&rust, shader)?;
        }
        let columns: Vec<_> = columns.iter().map(|(label, layout)| (*label, layout)).collect();
        tables.push(render_columns(&rust, &columns));
    }
    Ok(tables.join("\n"))
}
