//! The shader twins of `luminance` and `tone_map` agree with the Rust functions, on lavapipe (the
//! first test is the one of shader-proptest's README); and a function of the user's own beside
//! ray-footprint's ray-cone module (`Shader::with_source`, as in the README): `footprint` calls
//! the module's `rf_pinhole_ray_cone` and `rf_width_at` and is checked against the Rust functions
//! of the same names, in every language.

use downstream_shader_proptest_user::{luminance, tone_map};
use ray_footprint::ray_cone::{pinhole_ray_cone, width_at};
use ray_footprint::shaders::Module;
use shader_proptest::{proptest::prelude::*, FunctionCheck, Gpu, Language, RunConfig, Shader, Tolerance};

/// A dot product of three terms: three roundings (possibly fused), and the mirror's own.
#[test]
fn wgsl_luminance_agrees() -> Result<(), shader_proptest::Error> {
    let shader = Shader::wgsl(include_str!("../shaders/colour.wgsl"));
    let colour = || (0.0f32..10.0, 0.0f32..10.0, 0.0f32..10.0).prop_map(|(r, g, b)| (glam::vec3(r, g, b),));
    let check = FunctionCheck::new("luminance", colour, |(c,)| luminance(c)).tolerance(Tolerance::ulps(4));
    let report = check.run(&Gpu::new()?, &shader, &RunConfig::default())?;
    println!("{report}");
    report.assert_passed();
    Ok(())
}

/// The same for `tone_map`, written as GLSL includes it and as Slang imports it.
#[test]
fn glsl_and_slang_tone_maps_agree() {
    let colour = || (0.0f32..10.0, 0.0f32..10.0, 0.0f32..10.0).prop_map(|(r, g, b)| (glam::vec3(r, g, b),));
    // A correctly rounded sum and a division of 2.5 ULP on the device, 0.5 each in Rust.
    let check = FunctionCheck::new("tone_map", colour, |(c,)| tone_map(c)).tolerance(Tolerance::ulps(4));
    let gpu = Gpu::new().unwrap();
    let shaders = [
        Shader::glsl("#include \"colour.glsl\""),
        Shader::slang("import colour;"),
    ];
    for shader in shaders {
        let shader = shader.include_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders"));
        let report = check.run(&gpu, &shader, &RunConfig::default()).unwrap();
        println!("{report}");
        report.assert_passed();
    }
}

/// `footprint` beside the ray-cone module, in every language.
#[test]
fn footprint_agrees_beside_the_ray_cone_module() {
    // 0 + spread * t: one correctly rounded product on either side, so bit for bit.
    let check = FunctionCheck::new(
        "footprint",
        || (0.0f32..0.01, 0.0f32..1000.0),
        |(s, t)| width_at(pinhole_ray_cone(s), t),
    );
    let gpu = Gpu::new().unwrap();
    let sources = [
        (Language::Wgsl, include_str!("../shaders/footprint.wgsl")),
        (Language::Glsl, include_str!("../shaders/footprint.glsl")),
        (Language::Slang, include_str!("../shaders/footprint.slang")),
    ];
    for (language, footprint) in sources {
        let shader = Module::RayCone.shader(language).with_source(footprint);
        let report = check.run(&gpu, &shader, &RunConfig::default()).unwrap();
        println!("{report}");
        report.assert_passed();
    }
}
