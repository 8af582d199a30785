//! Edge cases for every function (`ray_footprint_lab::checks::edge`): special floats, zero and
//! axis-aligned vectors, vectors tied to each other, in WGSL, GLSL and Slang. Finite inputs must give
//! finite outputs in every language, and the shader must agree with the mirror within the
//! function's tolerance, which, where the function is ill-conditioned, widens to the documented
//! clamp.

use super::gpu;
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks::entries;
use shader_proptest::{Language, RunConfig};

fn edges_agree(module: Module, language: Language) {
    let gpu = gpu();
    let shader = module.shader(language);
    let mut failures = Vec::new();
    for entry in entries(module) {
        let report = entry
            .edge
            .run(&gpu, &shader, &RunConfig::default())
            .unwrap_or_else(|error| panic!("{} ({}): {error}", entry.edge.function(), language.name()));
        println!("{report}");
        if !report.passed() {
            failures.push(report.to_string());
        }
    }
    assert!(
        failures.is_empty(),
        "{} function(s) failed on edge cases:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

#[test]
fn ray_cone_wgsl() {
    edges_agree(Module::RayCone, Language::Wgsl);
}

#[test]
fn ray_cone_glsl() {
    edges_agree(Module::RayCone, Language::Glsl);
}

#[test]
fn ray_cone_slang() {
    edges_agree(Module::RayCone, Language::Slang);
}

#[test]
fn ray_diff_wgsl() {
    edges_agree(Module::RayDiff, Language::Wgsl);
}

#[test]
fn ray_diff_glsl() {
    edges_agree(Module::RayDiff, Language::Glsl);
}

#[test]
fn ray_diff_slang() {
    edges_agree(Module::RayDiff, Language::Slang);
}

#[test]
fn ray_diff_f64_wgsl() {
    edges_agree(Module::RayDiffF64, Language::Wgsl);
}

#[test]
fn ray_diff_f64_glsl() {
    edges_agree(Module::RayDiffF64, Language::Glsl);
}

#[test]
fn ray_diff_f64_slang() {
    edges_agree(Module::RayDiffF64, Language::Slang);
}

#[test]
fn wireframe_wgsl() {
    edges_agree(Module::Wireframe, Language::Wgsl);
}

#[test]
fn wireframe_glsl() {
    edges_agree(Module::Wireframe, Language::Glsl);
}

#[test]
fn wireframe_slang() {
    edges_agree(Module::Wireframe, Language::Slang);
}
