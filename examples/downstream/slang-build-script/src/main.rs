//! Runs the Slang compute shader the build script compiled (`shaders/footprint.slang`, which
//! imports ray-footprint's `ray_cone` module) on the Vulkan device (lavapipe unless
//! `SHADER_PROPTEST_DEVICE` names another) with the validation layer on, and checks every result
//! against the Rust mirror.

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::{self, RayCone};
use ray_footprint::shaders::SLANG_INCLUDE_DIR;
use shader_proptest::{spirv, ComputeKernel, Gpu};
use std::process::ExitCode;

const FOOTPRINT_SPIRV: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/footprint.spv"));

/// Cases run, one invocation each.
const CASES: usize = 4096;

/// One case as the shader's `GroundHit` reads it: the cone, the hit distance, the cosine between
/// the ray and the ground.
struct GroundHit {
    cone: RayCone,
    t: f32,
    cosine: f32,
}

/// Widths from 0 to 0.01, spreads from 1e-4 to 1e-2, distances from 0.5 to 200 and cosines from
/// 0.02 (grazing) to 1, stepped through their ranges at different rates.
fn hits() -> Vec<GroundHit> {
    (0..CASES)
        .map(|i| {
            let u = i as f32 / CASES as f32;
            GroundHit {
                cone: RayCone {
                    width: 0.01 * (u * 5.0).fract(),
                    spread_angle: 1.0e-4 + 0.0099 * (u * 11.0).fract(),
                },
                t: 0.5 + 199.5 * u,
                cosine: 0.02 + 0.98 * (u * 13.0).fract(),
            }
        })
        .collect()
}

/// The shader's computation with the Rust mirror: (footprint, LOD).
fn mirror(hit: &GroundHit) -> (f32, f32) {
    let direction = Vec3::new((1.0 - hit.cosine * hit.cosine).sqrt(), -hit.cosine, 0.0);
    let footprint = ray_cone::world_footprint(hit.cone, hit.t, Vec3::Y, direction);
    let width = ray_cone::width_at(hit.cone, hit.t);
    let lod = ray_cone::texture_lod(0.0, width, Vec2::splat(1024.0), Vec3::Y, direction);
    (footprint, lod)
}

/// The footprint |w + s t| / |n.d| in ULPs of the result (each at most 2^-23 of it; nothing cancels,
/// every term is positive): the width costs the shader 1 ULP (its multiply and add correctly
/// rounded, possibly fused) and the mirror 1, the division 2.5 on the device and 0.5 in Rust; n.d is
/// exact on both sides (products with 0 and 1).
const FOOTPRINT_ULPS: f32 = 5.0;

/// The LOD log2|w| + (log2 1024 + log2 1024) / 2 - log2|n.d| as an absolute bound, for widths whose
/// log2 lies within +-16 and cosines down to 0.02, so every term and sum stays below 32 in magnitude:
/// Vulkan's log2 is within 3 ULP (2^-19 each below 32), three of them 5.7e-6, the mirror's three
/// within 1 ULP, 5.7e-6, three additions on each side 5.7e-6 each, and the width's 2 ULP carried
/// through log2 (2^-22 / ln 2): about 2.3e-5 in all.
const LOD_TOLERANCE: f32 = 2.5e-5;

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
    // The module directory the build script was given (`DEP_RAY_FOOTPRINT_SLANG_INCLUDE`) is the
    // crate's own.
    let exported = env!("RAY_FOOTPRINT_SLANG_INCLUDE");
    if exported != SLANG_INCLUDE_DIR {
        return Err(format!(
            "the build script got {exported}, the crate names {SLANG_INCLUDE_DIR}"
        ));
    }
    let mut spirv = spirv::from_bytes(FOOTPRINT_SPIRV).map_err(|e| format!("footprint.spv: {e}"))?;
    // SPIR-V tools older than Slang's source-language enumerant, such as Debian 12's validation
    // layer 1.3.239, reject a module that names it.
    spirv::without_slang_source_language(&mut spirv);
    let gpu = Gpu::new().map_err(|e| format!("{e}; run scripts/setup.sh"))?;
    let kernel = ComputeKernel::new(&gpu, &spirv, 0).map_err(|e| e.to_string())?;
    let hits = hits();
    let input: Vec<u32> = hits
        .iter()
        .flat_map(|hit| [hit.cone.width, hit.cone.spread_angle, hit.t, hit.cosine].map(f32::to_bits))
        .collect();
    let output = kernel
        .dispatch(hits.len(), &input, 2 * hits.len())
        .map_err(|e| e.to_string())?;
    let (mut footprint_ulps, mut lod_error) = (0.0f32, 0.0f32);
    for (hit, words) in hits.iter().zip(output.chunks_exact(2)) {
        let (footprint, lod) = (f32::from_bits(words[0]), f32::from_bits(words[1]));
        let (expected_footprint, expected_lod) = mirror(hit);
        let ulps = (footprint - expected_footprint).abs() / (f32::EPSILON * expected_footprint.abs());
        let error = (lod - expected_lod).abs();
        if !(ulps <= FOOTPRINT_ULPS && error <= LOD_TOLERANCE) {
            return Err(format!(
                "width {}, spread {}, t {}, cosine {}: shader ({footprint}, {lod}), mirror ({expected_footprint}, {expected_lod})",
                hit.cone.width, hit.cone.spread_angle, hit.t, hit.cosine
            ));
        }
        footprint_ulps = footprint_ulps.max(ulps);
        lod_error = lod_error.max(error);
    }
    Ok(format!(
        "Slang modules in {exported}\ndevice: {}\nSlang shader from the build script: {} cases agree with the mirror \
         (footprint within {footprint_ulps:.2} of {FOOTPRINT_ULPS} ULP, LOD within {lod_error:.3e} of {LOD_TOLERANCE:e})",
        gpu.name(),
        hits.len()
    ))
}
