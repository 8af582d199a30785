//! A Bevy-style shader that `#import`s ray-footprint's modules by path through naga_oil, composed,
//! validated by naga and written as SPIR-V.

use naga_oil::compose::{Composer, NagaModuleDescriptor};
use ray_footprint::shaders::Module;
use std::process::ExitCode;

const SHADER: &str = "
#import ray_footprint::ray_cone::{rf_pixel_spread_angle, rf_pinhole_ray_cone, rf_world_footprint}
#import ray_footprint::wireframe::{rf_process_wireframe, RF_WIREFRAME_DEFAULT}

@group(0) @binding(0) var<storage, read_write> results: array<f32>;

@compute @workgroup_size(1)
fn main() {
    let cone = rf_pinhole_ray_cone(rf_pixel_spread_angle(1.0, 720.0));
    results[0] = rf_world_footprint(cone, 10.0, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, -1.0, 0.0));
    results[1] = rf_process_wireframe(RF_WIREFRAME_DEFAULT, vec3<f32>(0.5, 0.25, 0.25), vec3<f32>(0.01));
}
";

fn main() -> ExitCode {
    match compose() {
        Ok(words) => {
            println!("composed with naga_oil, validated by naga: {words} SPIR-V words");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn compose() -> Result<usize, String> {
    let modules = [Module::RayCone, Module::Wireframe];
    let capabilities = ray_footprint::naga_oil::capabilities(&modules);
    let mut composer = Composer::default().with_capabilities(capabilities);
    ray_footprint::naga_oil::add_composable_modules(&mut composer, &modules).map_err(|e| format!("{e:?}"))?;
    let module = composer
        .make_naga_module(NagaModuleDescriptor {
            source: SHADER,
            file_path: "footprint.wgsl",
            ..Default::default()
        })
        .map_err(|e| e.emit_to_string(&composer))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| format!("naga validation: {e:?}"))?;
    let words =
        naga::back::spv::write_vec(&module, &info, &Default::default(), None).map_err(|e| e.to_string())?;
    Ok(words.len())
}
