//! Every GPU test of ray-footprint, in one binary, on the local Vulkan device (lavapipe unless
//! `SHADER_PROPTEST_DEVICE` names another) with the validation layer on: any validation message
//! fails a test.
//!
//! - [`agreement`]: every shader function against its Rust mirror, in WGSL, GLSL, Slang and HLSL
//!   (compiled by glslang and by slangc);
//! - [`chains`]: reflection chains followed by a ray cone and a ray differential in a shader of
//!   the lab's own, against its Rust mirror and against each other, in WGSL, GLSL and Slang;
//! - [`abi`]: the shared structs echoed through storage buffers and push constants, bit for bit;
//! - [`special_cases`]: every function on special values (zeros, the domain's bounds, tied
//!   vectors), in WGSL, GLSL, Slang and HLSL: agreement where the function is well-conditioned,
//!   with at most `MAX_VACUOUS` vacuous cases, and its promises elsewhere;
//! - [`degenerate`]: the degenerate-input table on the GPU;
//! - [`rt`]: the ray-tracing renderer's per-pixel values against the mirror;
//! - [`quality`]: the quality lab at a tiny size (finite metrics, a ground truth that scores
//!   itself perfectly).

/// Declares, where it is used, one `#[test]` per shader module and language, named
/// `<module>_<language>` (`ray_cone_wgsl` ... `ray_diff_f64_hlsl_slangc`), that calls
/// `$runner(module, language)`: a suite writes its test once, as wgpu's `#[gpu_test]` carries a
/// test once, and this table names every pair.
macro_rules! module_and_language_tests {
    ($runner:ident) => {
        module_and_language_tests!($runner, RayCone: ray_cone_wgsl => Wgsl, ray_cone_glsl => Glsl,
            ray_cone_slang => Slang, ray_cone_hlsl_glslang => HlslGlslang, ray_cone_hlsl_slangc => HlslSlangc);
        module_and_language_tests!($runner, Wireframe: wireframe_wgsl => Wgsl, wireframe_glsl => Glsl,
            wireframe_slang => Slang, wireframe_hlsl_glslang => HlslGlslang, wireframe_hlsl_slangc => HlslSlangc);
        module_and_language_tests!($runner, RayDiff: ray_diff_wgsl => Wgsl, ray_diff_glsl => Glsl,
            ray_diff_slang => Slang, ray_diff_hlsl_glslang => HlslGlslang, ray_diff_hlsl_slangc => HlslSlangc);
        module_and_language_tests!($runner, RayDiffF64: ray_diff_f64_wgsl => Wgsl, ray_diff_f64_glsl => Glsl,
            ray_diff_f64_slang => Slang, ray_diff_f64_hlsl_glslang => HlslGlslang,
            ray_diff_f64_hlsl_slangc => HlslSlangc);
    };
    ($runner:ident, $module:ident: $($test:ident => $language:ident),+) => {
        $(
            #[test]
            fn $test() {
                $runner(ray_footprint::shaders::Module::$module, shader_proptest::Language::$language);
            }
        )+
    };
}

/// Declares, where it is used, one `#[test]` per `test => Language` pair, that calls
/// `$runner(language)`.
macro_rules! language_tests {
    ($runner:ident: $($test:ident => $language:ident),+ $(,)?) => {
        $(
            #[test]
            fn $test() {
                $runner(shader_proptest::Language::$language);
            }
        )+
    };
}

mod abi;
mod agreement;
mod chains;
mod degenerate;
mod path_rules;
mod quality;
mod rt;
mod special_cases;
mod symmetry;

use shader_proptest::{Check, Gpu, Language, RunConfig, Shader};

/// The command that installs what the GPU tests need on Debian 12.
const SETUP_COMMAND: &str = "scripts/setup.sh";

/// The compute device; panics with what to install when there is none (a GPU test never passes
/// by skipping).
fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|error| panic!("{error}\non Debian 12 run `{SETUP_COMMAND}`"))
}

/// Runs every check on `shader` in `language` with `config`, printing each report; fails with the
/// reports of those that did not pass, as function(s) that `failed`.
fn assert_all_pass<'a>(
    gpu: &Gpu,
    shader: &Shader,
    language: Language,
    checks: impl Iterator<Item = &'a dyn Check>,
    config: &RunConfig,
    failed: &str,
) {
    let mut failures = Vec::new();
    for check in checks {
        let report = check
            .run(gpu, shader, config)
            .unwrap_or_else(|error| panic!("{} ({}): {error}", check.function(), language.name()));
        println!("{report}");
        if !report.passed() {
            failures.push(report.to_string());
        }
    }
    assert!(
        failures.is_empty(),
        "{} function(s) {failed}:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}
