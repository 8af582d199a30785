//! ABI on the GPU: values of every shared struct written from Rust are read field by field by the
//! shaders, from storage buffers and push constants, bit for bit; and why booleans cross as
//! integers.

use super::gpu;
use bytemuck::{Pod, Zeroable};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use ray_footprint::abi::{
    HitPayload, RayConePushConstants, RayDiff, WireframePushConstants, WireframeSettingsIo,
};
use ray_footprint::layout::GlslPacking;
use ray_footprint::ray_cone::RayCone;
use ray_footprint::shaders::Module;
use shader_proptest::{echo, ComputeKernel, Gpu, Language, Shader, ShaderType, StructType, Value};
use std::cell::Cell;

/// Words of a random value of a shader struct: any bits for integer fields, any non-NaN bits for
/// float fields (a NaN's payload may legally change when a float is loaded).
fn struct_words(ty: &'static StructType) -> BoxedStrategy<Vec<u32>> {
    let mut is_float = Vec::new();
    ShaderType::Struct(ty).float_words(&mut is_float);
    let words: Vec<BoxedStrategy<u32>> = is_float
        .into_iter()
        .map(|float| {
            if float {
                any::<f32>()
                    .prop_filter("not NaN", |x| !x.is_nan())
                    .prop_map(f32::to_bits)
                    .boxed()
            } else {
                any::<u32>().boxed()
            }
        })
        .collect();
    words.boxed()
}

/// Writes random values of `T` from Rust as raw bytes into a storage buffer and a push-constant
/// block; the kernel reads every field by name and writes them back in declaration order. The words
/// must come back bit for bit, in WGSL, GLSL std430 and scalar, Slang std430 and scalar, and HLSL
/// through glslang and slangc (structured buffers and push constants in their default std430:
/// HLSL source cannot choose another).
fn echoes<T: Pod + Value>(module: Module) {
    let ShaderType::Struct(ty) = T::TYPE else {
        panic!("{:?} is not a struct", T::TYPE)
    };
    let gpu = gpu();
    let targets = [
        (Language::Wgsl, GlslPacking::Std430, "WGSL"),
        (Language::Glsl, GlslPacking::Std430, "GLSL std430"),
        (Language::Glsl, GlslPacking::Scalar, "GLSL scalar"),
        (Language::Slang, GlslPacking::Std430, "Slang std430"),
        (Language::Slang, GlslPacking::Scalar, "Slang scalar"),
        (Language::HlslGlslang, GlslPacking::Std430, "HLSL glslang"),
        (Language::HlslSlangc, GlslPacking::Std430, "HLSL slangc"),
    ];
    for (language, packing, label) in targets {
        let shader = module.shader(language);
        let mut runner = TestRunner::new(Config {
            cases: 64,
            failure_persistence: None,
            ..Config::default()
        });
        let checked = Cell::new(0);
        let value = |words: &Vec<u32>| -> T { bytemuck::pod_read_unaligned(bytemuck::cast_slice(words)) };
        let outcome = runner.run(
            &(vec(struct_words(ty), 1..256), struct_words(ty)),
            |(values, pushed)| {
                let values: Vec<T> = values.iter().map(value).collect();
                let echoed = echo(&gpu, &shader, packing, &values, &value(&pushed))
                    .unwrap_or_else(|error| panic!("{label}: {error}"));
                prop_assert!(echoed.is_ok(), "{}: {}", label, echoed.unwrap_err());
                checked.set(checked.get() + values.len());
                Ok(())
            },
        );
        outcome.unwrap_or_else(|failure| panic!("{}: {label}: {failure}", ty.name));
        println!(
            "{:<24} {label:<12} {} values and 64 push-constant blocks echoed bit for bit",
            ty.name,
            checked.get()
        );
    }
}

#[test]
fn ray_cone_echoes() {
    echoes::<RayCone>(Module::RayCone);
}

#[test]
fn hit_payload_echoes() {
    echoes::<HitPayload>(Module::RayCone);
}

#[test]
fn ray_cone_push_constants_echo() {
    echoes::<RayConePushConstants>(Module::RayCone);
}

#[test]
fn ray_diff_echoes() {
    echoes::<RayDiff>(Module::RayDiff);
}

#[test]
fn wireframe_settings_io_echoes() {
    echoes::<WireframeSettingsIo>(Module::Wireframe);
}

#[test]
fn wireframe_push_constants_echo() {
    echoes::<WireframePushConstants>(Module::Wireframe);
}

/// Wireframe-style settings with Rust bools: 1-byte bools and 3 bytes of padding.
#[repr(C)]
struct NaiveSettings {
    thickness: f32,
    stipple: bool,
    screen_space: bool,
    smoothing: f32,
}

/// The same settings with every bool as a 32-bit integer, as `WireframeSettingsIo` does.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct IntSettings {
    thickness: f32,
    stipple: i32,
    screen_space: i32,
    smoothing: f32,
}

const SETTINGS_KERNEL: &str = "#version 460
struct Settings { float thickness; BOOL stipple; BOOL screen_space; float smoothing; };
layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 1) writeonly buffer Out { uint words[]; };
layout(push_constant) uniform Push { Settings settings; };
void main() {
    words[0] = floatBitsToUint(settings.thickness);
    words[1] = settings.stipple != BOOL(0) ? 1u : 0u;
    words[2] = settings.screen_space != BOOL(0) ? 1u : 0u;
    words[3] = floatBitsToUint(settings.smoothing);
}
";

/// What the shader reads from push-constant bytes: thickness, stipple, screen_space, smoothing.
fn read_settings(gpu: &Gpu, glsl_bool: &str, bytes: &[u8]) -> (f32, bool, bool, f32) {
    let source = SETTINGS_KERNEL.replace("BOOL", glsl_bool);
    let spirv = Shader::glsl("").compile_kernel(&source).expect("compiles");
    let pipeline = ComputeKernel::new(gpu, &spirv, 16).expect("pipeline");
    let words = pipeline
        .dispatch_with_push_constants(1, &[0], 4, bytes)
        .expect("runs");
    (
        f32::from_bits(words[0]),
        words[1] != 0,
        words[2] != 0,
        f32::from_bits(words[3]),
    )
}

/// The bool pitfall, on the GPU: Rust's layout of a struct with `bool` fields (1 byte each),
/// pushed to a GLSL block with `bool` fields (4 bytes each), makes the shader read `screen_space`
/// from the bits of `smoothing` and `smoothing` from bytes past the struct. The integer mirror is
/// read exactly. WGSL refuses a `bool` in push constants outright.
#[test]
fn rust_bools_in_a_glsl_block_are_read_from_the_wrong_bytes() {
    let gpu = gpu();
    let (thickness, stipple, screen_space, smoothing) = (1.5f32, true, false, 0.25f32);
    // Rust's bytes for NaiveSettings, placed at Rust's own offsets (padding left zero).
    let mut naive = vec![0u8; std::mem::size_of::<NaiveSettings>()];
    naive[std::mem::offset_of!(NaiveSettings, thickness)..][..4].copy_from_slice(&thickness.to_le_bytes());
    naive[std::mem::offset_of!(NaiveSettings, stipple)] = u8::from(stipple);
    naive[std::mem::offset_of!(NaiveSettings, screen_space)] = u8::from(screen_space);
    naive[std::mem::offset_of!(NaiveSettings, smoothing)..][..4].copy_from_slice(&smoothing.to_le_bytes());
    assert_eq!(naive.len(), 12, "Rust packs the two bools into one 4-byte slot");
    let seen = read_settings(&gpu, "bool", &naive);
    println!(
        "Rust bools -> GLSL bools: sent {:?}, shader read {seen:?}",
        (thickness, stipple, screen_space, smoothing)
    );
    assert!(
        seen.2,
        "screen_space is read from the bits of smoothing, so it is true"
    );
    assert_eq!(
        seen.3, 0.0,
        "smoothing is read from past the end of the Rust struct"
    );

    let int_settings = IntSettings {
        thickness,
        stipple: i32::from(stipple),
        screen_space: i32::from(screen_space),
        smoothing,
    };
    let seen = read_settings(&gpu, "int", bytemuck::bytes_of(&int_settings));
    assert_eq!(seen, (thickness, stipple, screen_space, smoothing));

    let wgsl = "struct Settings { thickness: f32, stipple: bool }\nvar<immediate> settings: Settings;\n\
                @compute @workgroup_size(1) fn main() { _ = settings.thickness; }";
    let error = Shader::wgsl("")
        .compile_kernel(wgsl)
        .expect_err("WGSL has no host-shareable bool");
    println!("WGSL: {error}");
    assert!(
        error.to_string().contains("HOST_SHAREABLE"),
        "refused for the bool, not for something else: {error}"
    );
}
