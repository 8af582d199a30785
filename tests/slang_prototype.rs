//! Slang on the Vulkan device (lavapipe unless `RAY_FOOTPRINT_DEVICE` names another), through the
//! harness's pipeline and dispatch, with the validation layer on: a generated Slang kernel with the
//! same word contract as the WGSL and GLSL kernels (arguments as 32-bit words from binding 0, the
//! result's words to binding 1), and the shared structs' layouts as Slang compiles them.

#[path = "common/slangc.rs"]
mod slangc;

use glam::{Mat4, Vec3};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;
use ray_footprint::abi::shared_layouts;
use ray_footprint::gpu::{suite, GpuArgs, GpuValue, ShaderType};
use ray_footprint::gpu::{FunctionCheck, Gpu};
use ray_footprint::layout::{compare, render_columns, spirv_layout};
use ray_footprint::shaders::Module;
use std::fmt::Write as _;

/// Invocations per workgroup, as in the harness's kernels.
const WORKGROUP_SIZE: u32 = 64;

/// The Slang spelling of a type (matrices as Slang reads them: `m[r][c]` is row r, column c).
fn type_name(ty: ShaderType) -> &'static str {
    match ty {
        ShaderType::F32 => "float",
        ShaderType::U32 => "uint",
        ShaderType::I32 => "int",
        ShaderType::Bool => "bool",
        ShaderType::Vec2 => "float2",
        ShaderType::Vec3 => "float3",
        ShaderType::Vec4 => "float4",
        ShaderType::Mat4 => "float4x4",
        ShaderType::Struct(s) => s.name,
    }
}

/// An expression reading a value of type `ty` at input word `i + offset`; advances `offset`.
/// A matrix arrives column by column (glam's order) and is built row by row, as Slang's
/// constructor takes it.
fn load(ty: ShaderType, offset: &mut usize) -> String {
    let word = |offset: &mut usize| {
        *offset += 1;
        format!("kernel_inputs[i + {}u]", *offset - 1)
    };
    match ty {
        ShaderType::F32 => format!("asfloat({})", word(offset)),
        ShaderType::U32 => word(offset),
        ShaderType::I32 => format!("asint({})", word(offset)),
        ShaderType::Bool => format!("({} != 0u)", word(offset)),
        ShaderType::Vec2 | ShaderType::Vec3 | ShaderType::Vec4 => {
            let floats: Vec<String> = (0..ty.words()).map(|_| load(ShaderType::F32, offset)).collect();
            format!("{}({})", type_name(ty), floats.join(", "))
        }
        ShaderType::Mat4 => {
            let first = *offset;
            *offset += 16;
            let elements: Vec<String> = (0..4)
                .flat_map(|row| (0..4).map(move |column| first + 4 * column + row))
                .map(|at| format!("asfloat(kernel_inputs[i + {at}u])"))
                .collect();
            format!("float4x4({})", elements.join(", "))
        }
        ShaderType::Struct(s) => {
            let fields: Vec<String> = s.fields.iter().map(|&(_, field)| load(field, offset)).collect();
            format!("{}({})", s.name, fields.join(", "))
        }
    }
}

/// Statements writing `expr` of type `ty` to output words `o + offset..`; advances `offset`.
fn store(ty: ShaderType, expr: &str, offset: &mut usize, out: &mut String) {
    let mut word = |value: String, offset: &mut usize| {
        writeln!(out, "    kernel_outputs[o + {}u] = {value};", *offset).expect("writing to a String");
        *offset += 1;
    };
    match ty {
        ShaderType::F32 | ShaderType::I32 => word(format!("asuint({expr})"), offset),
        ShaderType::U32 => word(expr.to_string(), offset),
        ShaderType::Bool => word(format!("({expr} ? 1u : 0u)"), offset),
        ShaderType::Vec2 | ShaderType::Vec3 | ShaderType::Vec4 => {
            for component in ["x", "y", "z", "w"].iter().take(ty.words()) {
                store(ShaderType::F32, &format!("{expr}.{component}"), offset, out);
            }
        }
        ShaderType::Mat4 => {
            for column in 0..4 {
                for row in 0..4 {
                    store(ShaderType::F32, &format!("{expr}[{row}][{column}]"), offset, out);
                }
            }
        }
        ShaderType::Struct(s) => {
            for &(name, field) in s.fields {
                store(field, &format!("{expr}.{name}"), offset, out);
            }
        }
    }
}

/// A Slang kernel that imports `module` and calls `rf_<function>` once per case: the harness's
/// contract, with the buffers at set 0, bindings 0 and 1.
fn kernel_source(module: Module, function: &str, parameters: &[ShaderType], result: ShaderType) -> String {
    let mut offset = 0;
    let arguments: Vec<String> = parameters.iter().map(|&ty| load(ty, &mut offset)).collect();
    let mut stores = String::new();
    store(result, "result", &mut 0, &mut stores);
    let (in_words, out_words) = (offset, result.words());
    format!(
        "import {stem};

[[vk::binding(0, 0)]] StructuredBuffer<uint> kernel_inputs;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> kernel_outputs;

[shader(\"compute\")]
[numthreads({WORKGROUP_SIZE}, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {{
    uint output_words;
    uint stride;
    kernel_outputs.GetDimensions(output_words, stride);
    if (id.x >= output_words / {out_words}u) {{
        return;
    }}
    uint i = id.x * {in_words}u;
    uint o = id.x * {out_words}u;
    {result_type} result = rf_{function}({arguments});
{stores}}}
",
        stem = module.stem(),
        result_type = type_name(result),
        arguments = arguments.join(", "),
    )
}

/// `cases` inputs from the check's own strategy, the same ones on every run.
fn generate<A: GpuArgs, R>(check: &FunctionCheck<A, R>, cases: usize) -> Vec<A> {
    let mut runner = TestRunner::deterministic();
    let strategy = (check.strategy)();
    (0..cases)
        .map(|_| {
            strategy
                .new_tree(&mut runner)
                .expect("the strategy generates")
                .current()
        })
        .collect()
}

/// Compiles the kernel for `rf_<function>` of `module`, checks it with spirv-val, runs it once per
/// case on the device and returns the output words.
fn run_kernel<A: GpuArgs, R: GpuValue>(gpu: &Gpu, module: Module, function: &str, cases: &[A]) -> Vec<u32> {
    let source = kernel_source(module, function, A::TYPES, R::TYPE);
    let spirv = slangc::compile(&source, "compute", "spirv_1_3").unwrap_or_else(|log| panic!("{log}"));
    slangc::validate(&spirv, "vulkan1.1").unwrap_or_else(|log| panic!("{log}"));
    let pipeline = gpu.pipeline(&spirv, 0).unwrap_or_else(|error| panic!("{error}"));
    let mut input = Vec::new();
    cases.iter().for_each(|args| args.write(&mut input));
    let output = gpu
        .dispatch(&pipeline, cases.len(), &input, cases.len() * R::TYPE.words())
        .unwrap_or_else(|error| panic!("{error}"));
    gpu.destroy_pipeline(pipeline);
    output
}

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|error| panic!("{error}"))
}

#[test]
fn texture_lod_in_slang_agrees_with_the_mirror_on_the_device() {
    let gpu = gpu();
    let check = suite::ray_cone::texture_lod();
    let cases = generate(&check, 4096);
    let output = run_kernel::<_, f32>(&gpu, check.module, check.function, &cases);

    let (mut max_error, mut max_ratio) = (0.0f32, 0.0f32);
    for (args, &word) in cases.iter().zip(&output) {
        let shader = f32::from_bits(word);
        let mirror = (check.mirror)(*args);
        let error = if shader == mirror {
            0.0
        } else {
            (shader - mirror).abs()
        };
        let tolerance = (check.tolerance)(args, 0, mirror);
        assert!(
            shader.is_finite() && error <= tolerance,
            "rf_texture_lod{args:?}: Slang {shader}, mirror {mirror}, error {error:e} > tolerance {tolerance:e}"
        );
        max_error = max_error.max(error);
        max_ratio = max_ratio.max(error / tolerance);
    }
    println!(
        "{}: texture_lod in Slang, {} cases, max error {max_error:.3e} ({max_ratio:.4} of tolerance)",
        gpu.name(),
        cases.len()
    );
}

/// The kernel hands a matrix to Slang as glam means it: rf_transform_point(m, 0) is exactly the
/// upper part of m's last column (every other term is a product with 0), which a transposed load
/// would replace by the last row.
#[test]
fn matrices_reach_slang_column_by_column() {
    let gpu = gpu();
    let cases: Vec<(Mat4, Vec3)> = (0..256)
        .map(|case| {
            let elements: Vec<f32> = (0..16)
                .map(|element| (case * 16 + element) as f32 + 0.5)
                .collect();
            (Mat4::from_cols_slice(&elements), Vec3::ZERO)
        })
        .collect();
    let output = run_kernel::<_, Vec3>(&gpu, Module::RayDiff, "transform_point", &cases);
    for ((matrix, _), words) in cases.iter().zip(output.chunks_exact(3)) {
        let shader = Vec3::from_array([0, 1, 2].map(|index| f32::from_bits(words[index])));
        assert_eq!(
            shader,
            matrix.w_axis.truncate(),
            "rf_transform_point({matrix}, 0)"
        );
    }
    println!(
        "{} matrices: rf_transform_point(m, 0) is m's last column",
        cases.len()
    );
}

#[test]
fn shared_structs_have_the_rust_layout_in_slang_scalar_buffers() {
    let mut tables = Vec::new();
    for (module, rust) in shared_layouts() {
        let name = &rust.name;
        let probe = format!(
            "import {stem};

RWStructuredBuffer<{name}> layout_probe;

[shader(\"compute\")]
[numthreads(1, 1, 1)]
void main() {{
    layout_probe[0] = layout_probe[1];
}}
",
            stem = module.stem()
        );
        let spirv = slangc::compile(&probe, "compute", "spirv_1_3").unwrap_or_else(|log| panic!("{log}"));
        let mut slang =
            spirv_layout(&spirv, &format!("{name}_natural")).unwrap_or_else(|error| panic!("{error}"));
        slang.name = name.clone();
        compare(&rust, &slang).unwrap_or_else(|error| panic!("{error}"));
        tables.push(render_columns(&rust, &[("Slang scalar", &slang)]));
    }
    println!("{}", tables.join("\n"));
}
