//! ABI: every shared struct has one layout in Rust, WGSL, GLSL std430 and GLSL scalar, and values
//! written from Rust are read field by field by the shaders, bit for bit.

use bytemuck::{Pod, Zeroable};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use ray_footprint::abi::{
    self, HitPayload, RayConePushConstants, RayDiff, WireframePushConstants, WireframeSettingsIo,
    PUSH_CONSTANT_LIMIT,
};
use ray_footprint::gpu::suite::{ray_diff, wireframe};
use ray_footprint::gpu::{self, compile, echo_kernel_source, Gpu, Language, ShaderType, StructType};
use ray_footprint::layout::{self, GlslPacking, LayoutError};
use ray_footprint::ray_cone::RayCone;
use ray_footprint::rust_layout;
use ray_footprint::shaders::Module;
use std::cell::Cell;

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|error| panic!("{error}"))
}

/// Rust, WGSL, std430 and scalar agree for every shared struct; prints the table.
#[test]
fn every_shared_struct_has_one_layout() {
    let tables = abi::verify_shared_layouts().unwrap_or_else(|error| panic!("{error}"));
    println!("{tables}");
}

/// Every push-constant block fits the 128 bytes every Vulkan device accepts.
#[test]
fn push_constant_blocks_fit_the_vulkan_minimum() {
    let blocks: Vec<_> = abi::shared_layouts()
        .into_iter()
        .filter(|(_, layout)| layout.name.ends_with("PushConstants"))
        .collect();
    assert!(!blocks.is_empty());
    for (_, layout) in blocks {
        println!("{}: {} of {PUSH_CONSTANT_LIMIT} bytes", layout.name, layout.size);
        assert!(
            layout.size as usize <= PUSH_CONSTANT_LIMIT,
            "{} is {} bytes",
            layout.name,
            layout.size
        );
    }
}

/// The GLSL reader sees the difference between std430 (vec3 aligned to 16) and scalar (to 4).
#[test]
fn glsl_packings_differ_where_the_rules_differ() {
    let source = "struct Probe { float a; vec3 b; };";
    let offset_of_b = |packing| {
        layout::glsl_layout(source, "Probe", packing, &[])
            .expect("compiles")
            .fields[1]
            .offset
    };
    assert_eq!(offset_of_b(GlslPacking::Std430), 16);
    assert_eq!(offset_of_b(GlslPacking::Scalar), 4);
    let wgsl = layout::wgsl_layout("struct Probe { a: f32, b: vec3<f32> }", "Probe").expect("parses");
    assert_eq!((wgsl.fields[1].offset, wgsl.size, wgsl.align), (16, 32, 16));
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Probe {
    a: f32,
    b: [f32; 3],
}

/// The verification API names what is wrong instead of panicking.
#[test]
fn layout_errors_name_the_struct_and_field() {
    let rust = rust_layout!(Probe { a, b });
    let wgsl = |source: &str| layout::wgsl_layout(source, "Probe");
    assert_eq!(
        wgsl("struct Other { a: f32 }"),
        Err(LayoutError::StructNotFound("Probe".into()))
    );
    assert!(matches!(
        wgsl("struct Probe { a: f32"),
        Err(LayoutError::Source(_))
    ));
    let missing_in_rust = wgsl("struct Probe { a: f32, b: array<f32, 3>, c: f32 }").expect("parses");
    assert_eq!(
        layout::compare(&rust, &missing_in_rust),
        Err(LayoutError::MissingField {
            structure: "Probe".into(),
            field: "c".into(),
            missing_in: "Rust"
        })
    );
    let missing_in_shader = wgsl("struct Probe { a: f32 }").expect("parses");
    assert!(matches!(
        layout::compare(&rust, &missing_in_shader),
        Err(LayoutError::MissingField {
            missing_in: "shader",
            ..
        })
    ));
    match layout::compare(
        &rust,
        &wgsl("struct Probe { a: f32, b: vec3<f32> }").expect("parses"),
    ) {
        Err(LayoutError::Mismatch(table)) => {
            println!("{table}");
            assert_eq!(table.mismatches(), ["b", "(size)"]);
        }
        other => panic!("expected a mismatch, got {other:?}"),
    }
    let good = wgsl("struct Probe { a: f32, b: array<f32, 3> }").expect("parses");
    assert!(layout::compare(&rust, &good).is_ok());
    assert!(matches!(
        layout::glsl_layout("struct Probe { float a; }", "Missing", GlslPacking::Std430, &[]),
        Err(LayoutError::StructNotFound(_))
    ));
    assert!(matches!(
        layout::glsl_layout("struct Probe { float a }", "Probe", GlslPacking::Std430, &[]),
        Err(LayoutError::Source(_))
    ));
}

#[repr(C)]
struct Padded {
    flag: u8,
    value: f32,
}

/// A Rust struct with implicit padding is refused even where the offsets happen to agree.
#[test]
fn implicit_padding_is_reported() {
    let rust = rust_layout!(Padded { flag, value });
    let shader = layout::StructLayout {
        name: "Padded".into(),
        ..rust.clone()
    };
    assert_eq!(
        layout::compare(&rust, &shader),
        Err(LayoutError::ImplicitPadding {
            structure: "Padded".into(),
            uncovered: 3
        })
    );
}

/// Words of a random value of a shader struct: any bits for integer fields, any non-NaN bits for
/// float fields (a NaN's payload may legally change when a float is loaded).
fn struct_words(ty: &'static StructType) -> BoxedStrategy<Vec<u32>> {
    fn kinds(ty: ShaderType, out: &mut Vec<bool>) {
        match ty {
            ShaderType::Struct(s) => s.fields.iter().for_each(|&(_, field)| kinds(field, out)),
            ShaderType::U32 | ShaderType::I32 | ShaderType::Bool => out.push(false),
            float => out.extend(std::iter::repeat_n(true, float.words())),
        }
    }
    let mut is_float = Vec::new();
    kinds(ShaderType::Struct(ty), &mut is_float);
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
/// must come back bit for bit, in WGSL, GLSL std430 and GLSL scalar.
fn echo<T: Pod>(module: Module, ty: &'static StructType) {
    let size = std::mem::size_of::<T>();
    assert_eq!(
        size,
        4 * ShaderType::Struct(ty).words(),
        "{}: Rust size vs shader words",
        ty.name
    );
    let gpu = gpu();
    let targets = [
        (Language::Wgsl, GlslPacking::Std430, "WGSL"),
        (Language::Glsl, GlslPacking::Std430, "GLSL std430"),
        (Language::Glsl, GlslPacking::Scalar, "GLSL scalar"),
    ];
    for (language, packing, label) in targets {
        let source = echo_kernel_source(language, packing, module, ty);
        let spirv = compile(language, module, &source).unwrap_or_else(|error| panic!("{label}: {error}"));
        let pipeline = gpu
            .pipeline(&spirv, size as u32)
            .unwrap_or_else(|error| panic!("{label}: {error}"));
        let mut runner = TestRunner::new(Config {
            cases: 64,
            failure_persistence: None,
            ..Config::default()
        });
        let checked = Cell::new(0);
        let outcome = runner.run(
            &(vec(struct_words(ty), 1..256), struct_words(ty)),
            |(values, pushed)| {
                let value_words: Vec<u32> = values
                    .iter()
                    .flat_map(|v| {
                        let value: T = bytemuck::pod_read_unaligned(bytemuck::cast_slice(v));
                        bytemuck::cast_slice::<u8, u32>(bytemuck::bytes_of(&value)).to_vec()
                    })
                    .collect();
                let pushed_value: T = bytemuck::pod_read_unaligned(bytemuck::cast_slice(&pushed));
                let words = size / 4;
                let output = gpu
                    .dispatch_with_push_constants(
                        &pipeline,
                        values.len(),
                        &value_words,
                        values.len() * 2 * words,
                        bytemuck::bytes_of(&pushed_value),
                    )
                    .unwrap_or_else(|error| panic!("{label}: {error}"));
                for (case, echoed) in output.chunks(2 * words).enumerate() {
                    prop_assert_eq!(
                        &echoed[..words],
                        &value_words[case * words..(case + 1) * words],
                        "{} storage buffer, case {}",
                        label,
                        case
                    );
                    prop_assert_eq!(&echoed[words..], &pushed[..], "{} push constants", label);
                }
                checked.set(checked.get() + values.len());
                Ok(())
            },
        );
        gpu.destroy_pipeline(pipeline);
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
    echo::<RayCone>(Module::RayCone, &gpu::RAY_CONE);
}

#[test]
fn hit_payload_echoes() {
    echo::<HitPayload>(Module::RayCone, &gpu::HIT_PAYLOAD);
}

#[test]
fn ray_cone_push_constants_echo() {
    echo::<RayConePushConstants>(Module::RayCone, &gpu::RAY_CONE_PUSH_CONSTANTS);
}

#[test]
fn ray_diff_echoes() {
    echo::<RayDiff>(Module::RayDiff, &ray_diff::RAY_DIFF);
}

#[test]
fn wireframe_settings_io_echoes() {
    echo::<WireframeSettingsIo>(Module::Wireframe, &wireframe::WIREFRAME_SETTINGS_IO);
}

#[test]
fn wireframe_push_constants_echo() {
    echo::<WireframePushConstants>(Module::Wireframe, &wireframe::WIREFRAME_PUSH_CONSTANTS);
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
    let spirv = compile(Language::Glsl, Module::RayCone, &source).expect("compiles");
    let pipeline = gpu.pipeline(&spirv, 16).expect("pipeline");
    let words = gpu
        .dispatch_with_push_constants(&pipeline, 1, &[0], 4, bytes)
        .expect("runs");
    gpu.destroy_pipeline(pipeline);
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
    let error = compile(Language::Wgsl, Module::RayCone, wgsl).expect_err("WGSL has no host-shareable bool");
    println!("WGSL: {error}");
    assert!(
        error.to_string().contains("HOST_SHAREABLE"),
        "refused for the bool, not for something else: {error}"
    );
}
