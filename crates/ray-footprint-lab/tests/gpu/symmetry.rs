//! Every declared symmetry of every function on the device ([`ray_footprint_cases::symmetry`]):
//! the shader function against itself, its result for a transformed case restored to the case's
//! terms and held to its result for the case, within the bound derived from the record's
//! tolerance, as a metamorphic check ([`shader_proptest::MetamorphicCheck`]), in WGSL, GLSL,
//! Slang and HLSL (glslang, slangc).

use super::{assert_all_pass, gpu};
use ray_footprint::shaders::Module;
use ray_footprint_cases::module_records;
use shader_proptest::Language;

fn symmetries_hold(module: Module, language: Language) {
    let gpu = gpu();
    let checks: Vec<_> = module_records(module)
        .flat_map(|record| (0..record.symmetry_list().len()).map(|index| record.symmetry_check(index)))
        .collect();
    let shader = module.shader(language);
    assert_all_pass(
        &gpu,
        &shader,
        language,
        checks.iter().map(AsRef::as_ref),
        "break a symmetry",
    );
}

#[test]
fn ray_cone_glsl() {
    symmetries_hold(Module::RayCone, Language::Glsl);
}
