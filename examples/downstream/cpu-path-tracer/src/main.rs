//! A CPU ray caster that picks texture mip levels with ray cones, using ray-footprint's Rust
//! mirror alone (default features: no GPU crates, no Vulkan device).
//!
//! A pinhole camera 1.5 units above an infinite ground plane (1 UV unit per world unit, 1024^2
//! texture) looks slightly down. Each image row's texture LOD must rise towards the horizon, where
//! the plane is farther and seen at a more grazing angle.

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone;
use std::process::ExitCode;

const WIDTH: u32 = 64;
const HEIGHT: u32 = 48;
const FOV_Y: f32 = 1.0;
const TEXTURE_SIZE: f32 = 1024.0;

/// Texture LOD where the ray through the centre column of `row` hits the ground, if it does.
fn row_lod(row: u32, eye: Vec3, pitch: f32) -> Option<f32> {
    let ndc_y = 1.0 - 2.0 * (row as f32 + 0.5) / HEIGHT as f32;
    let camera_dir = Vec3::new(0.0, ndc_y * (0.5 * FOV_Y).tan(), -1.0).normalize();
    let (sin, cos) = pitch.sin_cos();
    let direction = Vec3::new(
        0.0,
        camera_dir.y * cos + camera_dir.z * sin,
        camera_dir.z * cos - camera_dir.y * sin,
    );
    let t = -eye.y / direction.y;
    if !(t > 0.0) {
        return None;
    }
    // One ground triangle: world and UV edges of the same length, so the base LOD is 0.
    let base_lod = ray_cone::triangle_base_lod(Vec3::ZERO, Vec3::X, Vec3::Z, Vec2::ZERO, Vec2::X, Vec2::Y);
    let cone = ray_cone::pinhole_ray_cone(ray_cone::pixel_spread_angle(FOV_Y, HEIGHT as f32));
    let width = ray_cone::width_at(cone, t);
    Some(ray_cone::texture_lod(
        base_lod,
        width,
        Vec2::splat(TEXTURE_SIZE),
        Vec3::Y,
        direction,
    ))
}

fn main() -> ExitCode {
    let eye = Vec3::new(0.0, 1.5, 0.0);
    let lods: Vec<(u32, f32)> = (0..HEIGHT)
        .filter_map(|row| row_lod(row, eye, 0.35).map(|lod| (row, lod)))
        .collect();
    for (row, lod) in lods.iter().step_by(4) {
        println!(
            "row {row:>2}: LOD {lod:>6.2} {}",
            "#".repeat(lod.max(0.0).round() as usize)
        );
    }
    let rises = lods.windows(2).all(|pair| pair[0].1 > pair[1].1);
    let (Some(first), Some(last)) = (lods.first(), lods.last()) else {
        eprintln!("error: no row of the {WIDTH}x{HEIGHT} image hits the ground");
        return ExitCode::FAILURE;
    };
    println!(
        "{} ground rows; LOD {:.2} near the horizon (row {}), {:.2} at the bottom (row {})",
        lods.len(),
        first.1,
        first.0,
        last.1,
        last.0
    );
    if rises {
        ExitCode::SUCCESS
    } else {
        eprintln!("error: the LOD does not rise monotonically towards the horizon");
        ExitCode::FAILURE
    }
}
