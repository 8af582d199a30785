//! The degenerate-input table (the root crate's `src/degenerate.md`,
//! [`ray_footprint_cases::degenerate`]) on the GPU: every record's degenerate rows through the
//! WGSL, GLSL, Slang and HLSL (glslang, slangc) kernels (the mirror's rows are the cases crate's own test).

use super::gpu;
use ray_footprint_cases::records;
use shader_proptest::Language;

fn gpu_follows_the_table(language: Language) {
    let gpu = gpu();
    println!("device: {}", gpu.name());
    let mut failures = Vec::new();
    for record in records() {
        failures.extend(
            record
                .degenerate_gpu(&gpu, language)
                .unwrap_or_else(|error| panic!("{error}")),
        );
    }
    gpu.check_messages().unwrap_or_else(|error| panic!("{error}"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

language_tests!(gpu_follows_the_table:
    wgsl_follows_the_table => Wgsl,
    glsl_follows_the_table => Glsl,
    slang_follows_the_table => Slang,
    hlsl_glslang_follows_the_table => HlslGlslang,
    hlsl_slangc_follows_the_table => HlslSlangc,
);
