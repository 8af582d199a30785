//! Runs the HLSL compute shader the build script compiled (`shaders/eye_rays.hlsl`, which
//! `#include`s ray-footprint's `ray_diff.hlsl`) on the Vulkan device (lavapipe unless
//! `SHADER_PROPTEST_DEVICE` names another) with the validation layer on, and checks the eye ray
//! of every pixel against the Rust mirror: the host's glam matrices and the HLSL float4x4 agree on
//! which element is which.

use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_diff;
use ray_footprint::shaders::HLSL_INCLUDE_DIR;
use shader_proptest::{spirv, ComputeKernel, Gpu};
use std::process::ExitCode;

const EYE_RAYS_SPIRV: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/eye_rays.spv"));

/// The image, one invocation per pixel.
const IMAGE_SIZE: Vec2 = Vec2::new(64.0, 48.0);

/// Largest difference per component between the shader's unit direction and the mirror's. Each
/// side rounds the far point (one product per component for a perspective projection, 2 ULP of the
/// component), its normalization (a 3-term dot product, a square root and a division: 8 ULP of 1 on
/// the device, whose division may be 2.5 ULP, 4 in Rust) and the rotation into the world (three
/// products and two sums of terms at most 1 in size: 5 ULP of 1): at most 15 ULP of 1 on the device
/// and 11 in Rust, 26 * 2^-24 = 1.6e-6 together.
const TOLERANCE: f32 = 1.6e-6;

/// The camera as the shader's `Camera` reads it: both matrices column by column, then the image
/// size and two words of padding (std430: 144 bytes).
fn camera_words(view_inv: Mat4, proj_inv: Mat4) -> Vec<u32> {
    let floats = view_inv
        .to_cols_array()
        .into_iter()
        .chain(proj_inv.to_cols_array())
        .chain([IMAGE_SIZE.x, IMAGE_SIZE.y, 0.0, 0.0]);
    floats.map(f32::to_bits).collect()
}

fn main() -> ExitCode {
    match run() {
        Ok(report) => {
            println!("{report}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<String, String> {
    // The include directory the build script was given (`DEP_RAY_FOOTPRINT_HLSL_INCLUDE`) is the
    // one the crate names.
    let exported = env!("RAY_FOOTPRINT_HLSL_INCLUDE");
    if exported != HLSL_INCLUDE_DIR {
        return Err(format!(
            "the build script got {exported}, the crate names {HLSL_INCLUDE_DIR}"
        ));
    }
    let spirv = spirv::from_bytes(EYE_RAYS_SPIRV).map_err(|e| format!("eye_rays.spv: {e}"))?;
    let view =
        glam::camera::rh::view::look_at_mat4(Vec3::new(3.0, 2.0, 5.0), Vec3::new(0.0, 0.5, 0.0), Vec3::Y);
    let projection =
        glam::camera::rh::proj::vulkan::perspective(1.0, IMAGE_SIZE.x / IMAGE_SIZE.y, 0.1, 100.0);
    let (view_inv, proj_inv) = (view.inverse(), projection.inverse());
    let gpu = Gpu::new().map_err(|e| format!("{e}; run scripts/setup.sh"))?;
    let kernel = ComputeKernel::new(&gpu, &spirv, 0).map_err(|e| e.to_string())?;
    let pixels = (IMAGE_SIZE.x * IMAGE_SIZE.y) as usize;
    let output = kernel
        .dispatch(pixels, &camera_words(view_inv, proj_inv), 4 * pixels)
        .map_err(|e| e.to_string())?;
    let mut largest = 0.0f32;
    for (index, words) in output.chunks_exact(4).enumerate() {
        let width = IMAGE_SIZE.x as usize;
        let pixel = Vec2::new((index % width) as f32, (index / width) as f32);
        let direction = Vec3::new(
            f32::from_bits(words[0]),
            f32::from_bits(words[1]),
            f32::from_bits(words[2]),
        );
        let expected = ray_diff::eye_ray_direction_from_matrices(pixel, IMAGE_SIZE, view_inv, proj_inv);
        let difference = (direction - expected).abs().max_element();
        if !(difference <= TOLERANCE) {
            return Err(format!(
                "pixel {pixel}: shader {direction}, mirror {expected} (differ by {difference:e})"
            ));
        }
        largest = largest.max(difference);
    }
    Ok(format!(
        "HLSL modules in {exported}\ndevice: {}\nHLSL shader from the build script (glslang): {pixels} eye rays agree with the mirror \
         (within {largest:.2e} of {TOLERANCE:e} per component)",
        gpu.name()
    ))
}
