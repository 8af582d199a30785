//! Chains by the thousand: through the Rust mirror, through the shader on the device (both against
//! the rounding bound of [`super::bound`]), and the shader against the mirror
//! ([`reflection_chain_check`]).

use super::mirror::{chain_shader, reflection_chain, ChainArgs, ChainCamera, ChainLeg, ChainSamples};
use super::{head_on_chain_with_one_saddle, in_plane_chain, Chain, ChainStats, Comparison};
use super::{CHAIN_MAX_BOUNCES, CHAIN_ORTHOGRAPHIC, CHAIN_PINHOLE};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRng, TestRunner};
use ray_footprint::ray_cone::{MAX_FOV_Y, MIN_COS, MIN_MAGNITUDE};
use ray_footprint_cases::ray_diff::{
    b_eye_ray_direction_derivatives, b_reflected_direction, b_transferred_origin,
};
use shader_proptest::interval::{interval3 as v3, Interval as I, Interval3 as V3, IntervalVec as V};
use shader_proptest::{kernel_source, Args, ComputeKernel, FunctionCheck, Gpu, Language, Tolerance, Value};
use std::cell::RefCell;

/// Chains per dispatch on the device.
const BATCH: usize = 8192;

/// The configuration of a run of `cases` chains: no failure files.
fn config(cases: u32) -> Config {
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

/// A runner with a fixed seed, so that every run sees the same chains.
fn fixed_runner(cases: u32) -> TestRunner {
    let config = config(cases);
    let rng = TestRng::deterministic_rng(config.rng_algorithm);
    TestRunner::new_with_rng(config, rng)
}

/// Runs `cases` chains from `chains` through the Rust mirror (a fixed seed, so the printed numbers
/// repeat) and checks every sample against its rounding bound. `Err`: the first failure, shrunk to
/// a small chain, with its samples.
pub fn check_on_the_cpu(
    chains: BoxedStrategy<Chain>,
    comparison: Comparison,
    cases: u32,
) -> Result<ChainStats, String> {
    let stats = RefCell::new(ChainStats::default());
    let result = fixed_runner(cases).run(&chains, |chain| {
        let samples = chain.samples(comparison, &chain.trace(comparison));
        if let Some(sample) = samples.iter().find(|s| !s.within_bound()) {
            return Err(TestCaseError::fail(format!("{sample:?} in {samples:?}")));
        }
        stats.borrow_mut().add(&chain, &samples);
        Ok(())
    });
    result.map_err(|failure| format!("{comparison:?}: {failure}"))?;
    Ok(stats.into_inner())
}

/// Runs `cases` chains from `chains` (a fixed seed, as [`check_on_the_cpu`]) through the chain
/// shader in `language` on `gpu`, one dispatch per batch, and checks every sample the device returns
/// against its rounding bound. `Err`: the harness could not run, or the first chain with a sample
/// beyond its bound, with its samples.
pub fn check_on_the_device(
    gpu: &Gpu,
    language: Language,
    chains: BoxedStrategy<Chain>,
    comparison: Comparison,
    cases: u32,
) -> Result<ChainStats, String> {
    let mut runner = fixed_runner(cases);
    let chains = (0..cases)
        .map(|_| chains.new_tree(&mut runner).map(|tree| tree.current()))
        .collect::<Result<Vec<Chain>, _>>()
        .map_err(|reason| reason.to_string())?;
    let shader = chain_shader(language)?;
    let kernel = kernel_source(&shader, "reflection_chain", ChainArgs::TYPES, ChainSamples::TYPE);
    let spirv = shader
        .compile_kernel(&kernel)
        .map_err(|error| format!("{error}\n--- kernel ---\n{kernel}"))?;
    let pipeline = ComputeKernel::new(gpu, &spirv, 0).map_err(|error| error.to_string())?;
    let mut stats = ChainStats::default();
    for batch in chains.chunks(BATCH) {
        let mut input = Vec::new();
        batch
            .iter()
            .for_each(|chain| chain.args(comparison).write(&mut input));
        let output = pipeline
            .dispatch(batch.len(), &input, batch.len() * ChainSamples::TYPE.words())
            .map_err(|error| error.to_string())?;
        let mut words = &output[..];
        for chain in batch {
            let samples = chain.samples(comparison, &ChainSamples::read(&mut words));
            if let Some(sample) = samples.iter().find(|s| !s.within_bound()) {
                return Err(format!(
                    "{comparison:?} in {}: {sample:?} in {samples:?}\n{chain:?}",
                    language.name()
                ));
            }
            stats.add(chain, &samples);
        }
    }
    Ok(stats)
}

/// The check of the shader function `reflection_chain` against [`reflection_chain`]: in-plane
/// chains and (one in five) head-on chains with a saddle, each with the curvatures its comparison
/// gives the cone. The tolerance of every output is the width of its enclosure
/// (`shader_proptest::interval`): the chain re-evaluated in interval arithmetic on the same f32
/// inputs, in the mirror's order of operations, widened after every operation by the rounding that
/// Vulkan allows the device (and that the mirror makes), so that both results lie inside.
pub fn reflection_chain_check() -> FunctionCheck<ChainArgs, ChainSamples> {
    let chains = || {
        prop_oneof![
            4 => in_plane_chain().prop_map(|chain| chain.args(Comparison::InPlane)),
            1 => head_on_chain_with_one_saddle().prop_map(|chain| chain.args(Comparison::Mean)),
        ]
    };
    let mirror = |(camera, bounces, leg0, leg1, leg2, leg3, leg4): ChainArgs| {
        reflection_chain(camera, bounces, leg0, leg1, leg2, leg3, leg4)
    };
    let widths =
        |args: &ChainArgs, _: &[f32]| b_reflection_chain(args).iter().map(|i| i.tolerance()).collect();
    FunctionCheck::new("reflection_chain", chains, mirror).tolerance(Tolerance::per_case(widths))
}

// ---------------------------------------------------------------------------------------------
// The enclosure of `reflection_chain` (same order of operations as mirror.rs)
// ---------------------------------------------------------------------------------------------

/// An exact f32 input.
fn s(x: f32) -> I {
    I::exact(x)
}

/// A ray of the chain in intervals: the cone, and the differential's origin and direction changes
/// per pixel step right and down.
#[derive(Clone, Copy)]
struct IntervalRay {
    width: I,
    spread: I,
    d_origin: [V3; 2],
    d_direction: [V3; 2],
}

fn b_pixel_spread_angle_small(fov_y: f32, image_height: f32) -> I {
    I::c(2.0) * I::tan_exact(0.5 * fov_y.clamp(0.0, MAX_FOV_Y)) / s(image_height.max(1.0))
}

fn b_chain_pixel_axis_ray(width: I, spread: I) -> IntervalRay {
    let zero = I::c(0.0);
    IntervalRay {
        width,
        spread,
        d_origin: [V([width, zero, zero]), V([zero, -width, zero])],
        d_direction: [V([spread, zero, zero]), V([zero, -spread, zero])],
    }
}

fn b_chain_primary(camera: ChainCamera) -> IntervalRay {
    if camera.kind == CHAIN_PINHOLE {
        let size = Vec2::splat(camera.image_height);
        let centre = (0.5 * size).floor();
        let eye = (centre, size, camera.fov_y, Vec3::X, Vec3::Y, Vec3::Z);
        let (dd_dx, dd_dy) = b_eye_ray_direction_derivatives(&eye);
        let zero = V([I::c(0.0); 3]);
        return IntervalRay {
            width: I::c(0.0),
            spread: b_pixel_spread_angle_small(camera.fov_y, camera.image_height),
            d_origin: [zero, zero],
            d_direction: [dd_dx, dd_dy],
        };
    }
    if camera.kind == CHAIN_ORTHOGRAPHIC {
        let width = s(camera.view_height) / s(camera.image_height.max(1.0));
        return b_chain_pixel_axis_ray(width, I::c(0.0));
    }
    let alpha = b_pixel_spread_angle_small(camera.fov_y, camera.image_height);
    let spread = alpha - s(camera.aperture) / s(camera.focus_distance.max(MIN_MAGNITUDE));
    b_chain_pixel_axis_ray(s(camera.aperture), spread)
}

fn b_chain_normal_change(leg: &ChainLeg, dp: V3) -> V3 {
    let (first, second) = (
        v3(leg.first_principal_direction),
        v3(leg.second_principal_direction),
    );
    let k = leg.principal_curvatures;
    first * (s(k.x) * first.dot(dp)) + second * (s(k.y) * second.dot(dp))
}

fn b_chain_reflect(ray: IntervalRay, at_hit: [V3; 2], width: I, leg: &ChainLeg) -> IntervalRay {
    let facing = -v3(leg.normal).dot(v3(leg.direction));
    let beta = (I::c(2.0) * s(leg.curvature) * width).div_away(facing, f64::from(MIN_COS));
    let reflected = |axis: usize| {
        let normal_change = b_chain_normal_change(leg, at_hit[axis]);
        b_reflected_direction(ray.d_direction[axis], leg.direction, leg.normal, normal_change)
    };
    IntervalRay {
        width,
        spread: ray.spread + beta,
        d_origin: at_hit,
        d_direction: [reflected(0), reflected(1)],
    }
}

/// The 15 outputs of `reflection_chain`: width and the two footprints after each leg, exactly 0
/// past the last.
fn b_reflection_chain(&(camera, bounces, leg0, leg1, leg2, leg3, leg4): &ChainArgs) -> Vec<I> {
    let legs = [leg0, leg1, leg2, leg3, leg4];
    let reflections = bounces.min(CHAIN_MAX_BOUNCES) as usize;
    let mut outputs = vec![I::c(0.0); 15];
    let mut ray = b_chain_primary(camera);
    for (index, leg) in legs.iter().enumerate().take(reflections + 1) {
        let at_hit = [0, 1].map(|axis| {
            b_transferred_origin(
                ray.d_origin[axis],
                ray.d_direction[axis],
                leg.direction,
                leg.distance,
                leg.normal,
            )
        });
        let width = ray.width + ray.spread * s(leg.distance);
        outputs[3 * index] = width;
        outputs[3 * index + 1] = at_hit[0].dot(v3(leg.right));
        outputs[3 * index + 2] = at_hit[1].dot(v3(leg.down));
        if index < reflections {
            ray = b_chain_reflect(ray, at_hit, width, leg);
        }
    }
    outputs
}
