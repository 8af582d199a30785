//! Generated compute kernels: one entry point that calls one shader function per invocation.
//!
//! The kernel reads each case's arguments from a word array (binding 0), calls the function, and
//! writes the result's words to a second array (binding 1). The [`Shader`]'s source comes first:
//! WGSL kernels are the module text followed by the wrapper; GLSL kernels put the source (for
//! example an `#include`) after `#version 460`, exactly as users do; Slang kernels start with the
//! source (for example an `import`) and declare the buffers as structured buffers.
//!
//! Matrices cross as their columns, one after the other (glam's order). GLSL and WGSL constructors
//! take a matrix column by column and `m[c]` is column c; Slang's take it row by row and `m[r]` is
//! row r, so Slang kernels build a matrix from its elements in row order and store
//! `transpose(m)[c]`.

use crate::compile::Language;
use crate::layout::GlslPacking;
use crate::shader::Shader;
use crate::value::{ShaderType, StructType};
use std::fmt::Write as _;

/// Invocations per workgroup in every generated kernel.
pub const WORKGROUP_SIZE: u32 = 64;

/// The source of a kernel that calls `function` of `shader` once per case, with arguments of types
/// `parameters`, returning `result`.
pub fn kernel_source(
    shader: &Shader,
    function: &str,
    parameters: &[ShaderType],
    result: ShaderType,
) -> String {
    let syntax = Syntax::of(shader.language());
    let mut offset = 0;
    let arguments: Vec<String> = parameters
        .iter()
        .map(|&ty| syntax.load(ty, &mut offset))
        .collect();
    let mut stores = String::new();
    syntax.store(result, "result", &mut 0, &mut stores);
    let call = format!("{function}({})", arguments.join(", "));
    let (in_words, out_words) = (offset, result.words());
    let result_type = syntax.type_name(result);
    let call_statements = |index: &str| {
        format!(
            "    uint i = {index} * {in_words}u;
    uint o = {index} * {out_words}u;
    {result_type} result = {call};
{stores}"
        )
    };
    match shader.language() {
        Language::Wgsl => format!(
            "{source}
@group(0) @binding(0) var<storage, read> kernel_inputs: array<u32>;
@group(0) @binding(1) var<storage, read_write> kernel_outputs: array<u32>;

fn kernel_f32(word: u32) -> f32 {{
    return bitcast<f32>(kernel_inputs[word]);
}}

@compute @workgroup_size({WORKGROUP_SIZE})
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    if id.x >= arrayLength(&kernel_outputs) / {out_words}u {{
        return;
    }}
    let i = id.x * {in_words}u;
    let o = id.x * {out_words}u;
    let result = {call};
{stores}}}
",
            source = shader.source()
        ),
        Language::Glsl => format!(
            "#version 460
#extension GL_GOOGLE_include_directive : require
{source}

layout(local_size_x = {WORKGROUP_SIZE}) in;
layout(std430, set = 0, binding = 0) readonly buffer KernelInputs {{ uint kernel_inputs[]; }};
layout(std430, set = 0, binding = 1) writeonly buffer KernelOutputs {{ uint kernel_outputs[]; }};

float kernel_f32(uint word) {{
    return uintBitsToFloat(kernel_inputs[word]);
}}

{main}",
            source = shader.source(),
            main = glsl_main(
                &format!("uint(kernel_outputs.length()) / {out_words}u"),
                call_statements,
            ),
        ),
        Language::Slang => format!(
            "{source}

[[vk::binding(0, 0)]] StructuredBuffer<uint> kernel_inputs;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> kernel_outputs;

float kernel_f32(uint word) {{
    return asfloat(kernel_inputs[word]);
}}

{main}",
            source = shader.source(),
            main = slang_main(
                "kernel_outputs",
                &format!("buffer_length / {out_words}u"),
                call_statements,
            ),
        ),
    }
}

/// The source of an echo kernel for the struct `ty` declared by `shader`: invocation `i` reads
/// element `i` of a storage buffer of `ty` (binding 0) and the push-constant block (a `ty`), and
/// writes every field of both, by name and in declaration order, as words to binding 1 (the
/// element first, then the push constants). GLSL blocks and Slang buffers use `packing`; WGSL has
/// its own rules.
pub fn echo_kernel_source(shader: &Shader, packing: GlslPacking, ty: &'static StructType) -> String {
    let syntax = Syntax::of(shader.language());
    let words = ShaderType::Struct(ty).words();
    let mut stores = String::new();
    syntax.store(ShaderType::Struct(ty), "stored", &mut 0, &mut stores);
    syntax.store(ShaderType::Struct(ty), "pushed", &mut { words }, &mut stores);
    let name = ty.name;
    let out_words = 2 * words;
    let echo_statements = |index: &str| {
        format!(
            "    uint o = {index} * {out_words}u;
    {name} stored = echo_values[{index}];
    {name} pushed = echo_push;
{stores}"
        )
    };
    match shader.language() {
        Language::Wgsl => format!(
            "{source}
@group(0) @binding(0) var<storage, read> echo_values: array<{name}>;
@group(0) @binding(1) var<storage, read_write> kernel_outputs: array<u32>;
var<immediate> echo_push: {name};

@compute @workgroup_size({WORKGROUP_SIZE})
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    if id.x >= arrayLength(&echo_values) {{
        return;
    }}
    let o = id.x * {out_words}u;
    let stored = echo_values[id.x];
    let pushed = echo_push;
{stores}}}
",
            source = shader.source()
        ),
        Language::Glsl => format!(
            "#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
{source}

layout(local_size_x = {WORKGROUP_SIZE}) in;
layout({packing}, set = 0, binding = 0) readonly buffer EchoValues {{ {name} echo_values[]; }};
layout(std430, set = 0, binding = 1) writeonly buffer KernelOutputs {{ uint kernel_outputs[]; }};
layout({packing}, push_constant) uniform EchoPush {{ {name} echo_push; }};

{main}",
            source = shader.source(),
            packing = packing.qualifier(),
            main = glsl_main("uint(echo_values.length())", echo_statements),
        ),
        Language::Slang => format!(
            "{source}

[[vk::binding(0, 0)]] StructuredBuffer<{name}, {layout}> echo_values;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> kernel_outputs;
[[vk::push_constant]] ConstantBuffer<{name}, {layout}> echo_push;

{main}",
            source = shader.source(),
            layout = packing.slang_layout(),
            main = slang_main("echo_values", "buffer_length", echo_statements),
        ),
    }
}

/// A GLSL `main`: invocation `gl_GlobalInvocationID.x` returns unless it is below `cases`, then
/// runs `statements` of its index expression.
fn glsl_main(cases: &str, statements: impl FnOnce(&str) -> String) -> String {
    let index = "gl_GlobalInvocationID.x";
    format!(
        "void main() {{
    if ({index} >= {cases}) {{
        return;
    }}
{}}}
",
        statements(index)
    )
}

/// A Slang compute `main`: invocation `id.x` returns unless it is below `cases`, an expression
/// that may use `buffer_length`, the element count of the structured buffer `buffer`; then runs
/// `statements` of its index expression.
fn slang_main(buffer: &str, cases: &str, statements: impl FnOnce(&str) -> String) -> String {
    let index = "id.x";
    format!(
        "[shader(\"compute\")]
[numthreads({WORKGROUP_SIZE}, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {{
    uint buffer_length;
    uint buffer_stride;
    {buffer}.GetDimensions(buffer_length, buffer_stride);
    if ({index} >= {cases}) {{
        return;
    }}
{}}}
",
        statements(index)
    )
}

/// Spelling of loads, stores and type names in one language.
struct Syntax {
    language: Language,
}

impl Syntax {
    fn of(language: Language) -> Syntax {
        Syntax { language }
    }

    fn type_name(&self, ty: ShaderType) -> &'static str {
        let (wgsl, glsl, slang) = match ty {
            ShaderType::F32 => ("f32", "float", "float"),
            ShaderType::U32 => ("u32", "uint", "uint"),
            ShaderType::I32 => ("i32", "int", "int"),
            ShaderType::Bool => ("bool", "bool", "bool"),
            ShaderType::Vec2 => ("vec2<f32>", "vec2", "float2"),
            ShaderType::Vec3 => ("vec3<f32>", "vec3", "float3"),
            ShaderType::Vec4 => ("vec4<f32>", "vec4", "float4"),
            ShaderType::Mat2 => ("mat2x2<f32>", "mat2", "float2x2"),
            ShaderType::Mat3 => ("mat3x3<f32>", "mat3", "float3x3"),
            ShaderType::Mat4 => ("mat4x4<f32>", "mat4", "float4x4"),
            ShaderType::Struct(s) => (s.name, s.name, s.name),
        };
        match self.language {
            Language::Wgsl => wgsl,
            Language::Glsl => glsl,
            Language::Slang => slang,
        }
    }

    /// An expression reading a value of type `ty` at input word `i + offset`; advances `offset`.
    fn load(&self, ty: ShaderType, offset: &mut usize) -> String {
        let mut next = || {
            let word = *offset;
            *offset += 1;
            word
        };
        match ty {
            ShaderType::F32 => format!("kernel_f32(i + {}u)", next()),
            ShaderType::U32 => format!("kernel_inputs[i + {}u]", next()),
            ShaderType::I32 => {
                let word = format!("kernel_inputs[i + {}u]", next());
                match self.language {
                    Language::Wgsl => format!("bitcast<i32>({word})"),
                    Language::Glsl => format!("int({word})"),
                    Language::Slang => format!("asint({word})"),
                }
            }
            ShaderType::Bool => format!("(kernel_inputs[i + {}u] != 0u)", next()),
            ShaderType::Vec2
            | ShaderType::Vec3
            | ShaderType::Vec4
            | ShaderType::Mat2
            | ShaderType::Mat3
            | ShaderType::Mat4 => {
                let first = *offset;
                *offset += ty.words();
                let floats: Vec<String> = self
                    .constructor_words(ty)
                    .map(|word| format!("kernel_f32(i + {}u)", first + word))
                    .collect();
                format!("{}({})", self.type_name(ty), floats.join(", "))
            }
            ShaderType::Struct(s) => {
                let fields: Vec<String> = s
                    .fields
                    .iter()
                    .map(|&(_, field)| self.load(field, offset))
                    .collect();
                format!("{}({})", s.name, fields.join(", "))
            }
        }
    }

    /// The input words, relative to a value's first, in the order the type's constructor takes its
    /// components: word order, except for Slang matrices, whose element (r, c) is word c n + r.
    fn constructor_words(&self, ty: ShaderType) -> impl Iterator<Item = usize> {
        let words = ty.words();
        let columns = match (self.language, ty) {
            (Language::Slang, ShaderType::Mat2 | ShaderType::Mat3 | ShaderType::Mat4) => words.isqrt(),
            _ => 1,
        };
        (0..words).map(move |index| (index % columns) * columns + index / columns)
    }

    /// Statements writing `expr` of type `ty` to output words `o + offset..`; advances `offset`.
    fn store(&self, ty: ShaderType, expr: &str, offset: &mut usize, out: &mut String) {
        let language = self.language;
        let mut word = |value: String| {
            writeln!(out, "    kernel_outputs[o + {}u] = {value};", *offset).expect("writing to a String");
            *offset += 1;
        };
        match ty {
            ShaderType::F32 => word(match language {
                Language::Wgsl => format!("bitcast<u32>({expr})"),
                Language::Glsl => format!("floatBitsToUint({expr})"),
                Language::Slang => format!("asuint({expr})"),
            }),
            ShaderType::U32 => word(expr.to_string()),
            ShaderType::I32 => word(match language {
                Language::Wgsl => format!("bitcast<u32>({expr})"),
                Language::Glsl => format!("uint({expr})"),
                Language::Slang => format!("asuint({expr})"),
            }),
            ShaderType::Bool => word(match language {
                Language::Wgsl => format!("select(0u, 1u, {expr})"),
                Language::Glsl | Language::Slang => format!("({expr} ? 1u : 0u)"),
            }),
            ShaderType::Vec2 | ShaderType::Vec3 | ShaderType::Vec4 => {
                for component in ["x", "y", "z", "w"].iter().take(ty.words()) {
                    self.store(ShaderType::F32, &format!("{expr}.{component}"), offset, out);
                }
            }
            ShaderType::Mat2 => self.store_columns(ShaderType::Vec2, 2, expr, offset, out),
            ShaderType::Mat3 => self.store_columns(ShaderType::Vec3, 3, expr, offset, out),
            ShaderType::Mat4 => self.store_columns(ShaderType::Vec4, 4, expr, offset, out),
            ShaderType::Struct(s) => {
                for &(name, field) in s.fields {
                    self.store(field, &format!("{expr}.{name}"), offset, out);
                }
            }
        }
    }

    /// Statements writing the `columns` columns of the matrix `expr`, each a `column` vector.
    fn store_columns(
        &self,
        column: ShaderType,
        columns: usize,
        expr: &str,
        offset: &mut usize,
        out: &mut String,
    ) {
        for index in 0..columns {
            let column_expr = match self.language {
                Language::Wgsl | Language::Glsl => format!("{expr}[{index}]"),
                Language::Slang => format!("transpose({expr})[{index}]"),
            };
            self.store(column, &column_expr, offset, out);
        }
    }
}
