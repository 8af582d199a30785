//! Edge cases for every function (`ray_footprint_lab::checks::edge`): special floats, zero and
//! axis-aligned vectors, vectors tied to each other, in WGSL, GLSL and Slang. Finite inputs must give
//! finite outputs in every language, and the shader must agree with the mirror within the
//! function's tolerance, which, where the function is ill-conditioned, widens to the documented
//! clamp.

use super::{assert_all_pass, gpu};
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks::entries;
use shader_proptest::Language;

fn edges_agree(module: Module, language: Language) {
    let gpu = gpu();
    let shader = module.shader(language);
    let entries = entries(module);
    let edges = entries.iter().map(|entry| entry.item.edge.as_ref());
    assert_all_pass(&gpu, &shader, language, edges, "failed on edge cases");
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
