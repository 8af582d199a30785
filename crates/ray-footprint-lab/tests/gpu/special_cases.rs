//! Special values for every function (each record's special-value check,
//! [`ray_footprint_cases::special`]): special floats, zero and axis-aligned vectors, vectors tied to
//! each other, in WGSL, GLSL, Slang and HLSL (glslang, slangc). Finite inputs must give finite outputs in every language,
//! and the shader must agree with the mirror within the function's tolerance, which, where the
//! function is ill-conditioned, widens to the documented clamp.

use super::{assert_all_pass, gpu};
use ray_footprint::shaders::Module;
use ray_footprint_cases::module_records;
use shader_proptest::Language;

fn special_values_agree(module: Module, language: Language) {
    let gpu = gpu();
    let shader = module.shader(language);
    let checks: Vec<_> = module_records(module)
        .map(|record| record.special_check())
        .collect();
    let checks = checks.iter().map(AsRef::as_ref);
    assert_all_pass(&gpu, &shader, language, checks, "failed on special values");
}

#[test]
fn ray_cone_wgsl() {
    special_values_agree(Module::RayCone, Language::Wgsl);
}

#[test]
fn ray_cone_glsl() {
    special_values_agree(Module::RayCone, Language::Glsl);
}

#[test]
fn ray_cone_slang() {
    special_values_agree(Module::RayCone, Language::Slang);
}

#[test]
fn ray_cone_hlsl_glslang() {
    special_values_agree(Module::RayCone, Language::HlslGlslang);
}

#[test]
fn ray_cone_hlsl_slangc() {
    special_values_agree(Module::RayCone, Language::HlslSlangc);
}

#[test]
fn ray_diff_wgsl() {
    special_values_agree(Module::RayDiff, Language::Wgsl);
}

#[test]
fn ray_diff_glsl() {
    special_values_agree(Module::RayDiff, Language::Glsl);
}

#[test]
fn ray_diff_slang() {
    special_values_agree(Module::RayDiff, Language::Slang);
}

#[test]
fn ray_diff_hlsl_glslang() {
    special_values_agree(Module::RayDiff, Language::HlslGlslang);
}

#[test]
fn ray_diff_hlsl_slangc() {
    special_values_agree(Module::RayDiff, Language::HlslSlangc);
}

#[test]
fn ray_diff_f64_wgsl() {
    special_values_agree(Module::RayDiffF64, Language::Wgsl);
}

#[test]
fn ray_diff_f64_glsl() {
    special_values_agree(Module::RayDiffF64, Language::Glsl);
}

#[test]
fn ray_diff_f64_slang() {
    special_values_agree(Module::RayDiffF64, Language::Slang);
}

#[test]
fn ray_diff_f64_hlsl_glslang() {
    special_values_agree(Module::RayDiffF64, Language::HlslGlslang);
}

#[test]
fn ray_diff_f64_hlsl_slangc() {
    special_values_agree(Module::RayDiffF64, Language::HlslSlangc);
}

#[test]
fn wireframe_wgsl() {
    special_values_agree(Module::Wireframe, Language::Wgsl);
}

#[test]
fn wireframe_glsl() {
    special_values_agree(Module::Wireframe, Language::Glsl);
}

#[test]
fn wireframe_slang() {
    special_values_agree(Module::Wireframe, Language::Slang);
}

#[test]
fn wireframe_hlsl_glslang() {
    special_values_agree(Module::Wireframe, Language::HlslGlslang);
}

#[test]
fn wireframe_hlsl_slangc() {
    special_values_agree(Module::Wireframe, Language::HlslSlangc);
}
