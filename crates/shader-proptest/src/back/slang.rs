//! Slang, compiled by slangc: kernels start with the [`Shader`]'s source (for example an
//! `import`) and declare their buffers as structured buffers, and layouts are read from the SPIR-V
//! slangc writes for a probe buffer.
//!
//! Slang's matrix constructors take a matrix row by row and `m[r]` is row r, so kernels build a
//! matrix from its elements in row order and store `transpose(m)[c]` ([`MatrixOrder::Rows`]).

use super::backend::{Backend, KernelCall, KernelEcho, WORKGROUP_SIZE};
use super::spelling::{MatrixOrder, Spelling};
use crate::compile::{compile_slang, CompileError, Stage, Target};
use crate::layout::{is_identifier, line_after, probe_error, GlslPacking, LayoutError, StructLayout};
use crate::reflect;
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::{DeclaredType, Signature};
#[cfg(feature = "gpu")]
use crate::value::ShaderType;
use std::path::Path;

/// The Slang back end.
pub(crate) struct Slang;

/// Slang's names and casts, which are HLSL's.
pub(super) const SPELLING: Spelling = Spelling {
    types: [
        "float", "uint", "int", "bool", "float2", "float3", "float4", "float2x2", "float3x3", "float4x4",
    ],
    int_from_bits: "asint({})",
    float_bits: "asuint({})",
    int_bits: "asuint({})",
    bool_word: "({} ? 1u : 0u)",
    matrix_order: MatrixOrder::Rows,
};

impl Backend for Slang {
    fn spelling(&self) -> &'static Spelling {
        &SPELLING
    }

    fn call_kernel(&self, source: &str, call: &KernelCall<'_>) -> String {
        structured_call_kernel(source, "", call)
    }

    /// Both buffers take `packing`'s data layout.
    fn echo_kernel(&self, source: &str, packing: GlslPacking, echo: &KernelEcho<'_>) -> String {
        let (name, layout) = (echo.name, packing.slang_layout());
        let push = format!("[[vk::push_constant]] ConstantBuffer<{name}, {layout}> echo_push;");
        structured_echo_kernel(source, &format!("{name}, {layout}"), &push, echo)
    }

    /// slangc, with the shader's search paths.
    fn compile_kernel(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, CompileError> {
        compile_slang(kernel, Stage::Compute, Target::Vulkan1_1, &shader.include_dirs())
    }

    /// The element of a `std430` structured buffer.
    fn struct_layout(&self, shader: &Shader, name: &str) -> Result<StructLayout, LayoutError> {
        slang_layout(shader.source(), name, GlslPacking::Std430, &shader.include_dirs())
    }

    /// From slangc's own words ([`slangc_declared_signatures`]).
    #[cfg(feature = "gpu")]
    fn declared_signatures(&self, shader: &Shader, function: &str) -> Option<Vec<Signature>> {
        slangc_declared_signatures(shader, function, |probe| {
            compile_slang(probe, Stage::Compute, Target::Vulkan1_1, &shader.include_dirs())
        })
    }

    /// Slang converts scalars to vectors and integers to floats implicitly.
    #[cfg(feature = "gpu")]
    fn called_signature(&self, kernel: &[u32], function: &str) -> Option<Signature> {
        reflect::signatures(kernel, function, true).into_iter().next()
    }
}

/// The signatures of the functions named `function` that `shader` declares, from slangc's own
/// words: slangc writes no function that no entry point calls, so a probe, compiled by `compile`,
/// assigns the function to an `int`, and slangc's error spells its type (`got '(float, float,
/// float) -> float'`), or each overload's (`candidate: func falloff(float3) -> float`), or says
/// that the name is an `undefined identifier`. Parameter names are not in them. Slang and HLSL
/// read by slangc share it.
#[cfg(feature = "gpu")]
pub(super) fn slangc_declared_signatures(
    shader: &Shader,
    function: &str,
    compile: impl FnOnce(&str) -> Result<Vec<u32>, CompileError>,
) -> Option<Vec<Signature>> {
    if !is_identifier(function) {
        return None;
    }
    let probe = format!(
        "{}\n[shader(\"compute\")]\n[numthreads(1, 1, 1)]\nvoid main() {{ int signature_probe = {function}; }}\n",
        shader.source()
    );
    let Err(CompileError::Failed { log, .. }) = compile(&probe) else {
        return None;
    };
    let signatures: Vec<Signature> = log.lines().filter_map(spelled_signature).collect();
    (!signatures.is_empty() || log.contains("undefined identifier")).then_some(signatures)
}

/// The signature in a line of slangc's log that spells a function type: `... got '(float3,
/// float) -> float'`, or `candidate: func name(float3, float) -> float`.
#[cfg(feature = "gpu")]
fn spelled_signature(line: &str) -> Option<Signature> {
    let spelled = match line.split_once("got '") {
        Some((_, got)) => got.strip_suffix('\'')?,
        None => line.split_once("candidate: func ")?.1,
    };
    let (name_and_parameters, result) = spelled.rsplit_once(" -> ")?;
    let parameters = name_and_parameters.split_once('(')?.1.strip_suffix(')')?;
    Some(Signature {
        parameters: top_level_items(parameters)
            .map(|ty| (String::new(), declared_type(ty)))
            .collect(),
        result: declared_type(result.trim()),
    })
}

/// The comma-separated items of `list`, keeping the commas inside `<...>` (`vector<float,3>`).
#[cfg(feature = "gpu")]
fn top_level_items(list: &str) -> impl Iterator<Item = &str> {
    let mut depth = 0;
    list.split(move |c| {
        match c {
            '<' => depth += 1,
            '>' => depth -= 1,
            _ => {}
        }
        c == ',' && depth == 0
    })
    .map(str::trim)
    .filter(|item| !item.is_empty())
}

/// A type as slangc spells it in a diagnostic: `float`, `float3` or `vector<float,3>`,
/// `float3x3` or `matrix<float,3,3>`, a struct by its (possibly module-qualified) name.
#[cfg(feature = "gpu")]
fn declared_type(spelled: &str) -> DeclaredType {
    let known = match spelled.replace(' ', "").as_str() {
        "float" => Some(ShaderType::F32),
        "uint" => Some(ShaderType::U32),
        "int" => Some(ShaderType::I32),
        "bool" => Some(ShaderType::Bool),
        "float2" | "vector<float,2>" => Some(ShaderType::Vec2),
        "float3" | "vector<float,3>" => Some(ShaderType::Vec3),
        "float4" | "vector<float,4>" => Some(ShaderType::Vec4),
        "float2x2" | "matrix<float,2,2>" => Some(ShaderType::Mat2),
        "float3x3" | "matrix<float,3,3>" => Some(ShaderType::Mat3),
        "float4x4" | "matrix<float,4,4>" => Some(ShaderType::Mat4),
        _ => None,
    };
    let name = spelled.rsplit('.').next().unwrap_or(spelled);
    match known {
        Some(ty) => DeclaredType::Value(ty),
        None if is_identifier(name) => DeclaredType::Struct(name.to_string()),
        None => DeclaredType::Other(spelled.to_string()),
    }
}

/// A call kernel of Slang or HLSL, which declare their buffers as structured buffers: `source`,
/// the input and output words, `kernel_f32`, the functions `helpers` (which the call may use) and
/// `main`.
pub(super) fn structured_call_kernel(source: &str, helpers: &str, call: &KernelCall<'_>) -> String {
    format!(
        "{source}

[[vk::binding(0, 0)]] StructuredBuffer<uint> kernel_inputs;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> kernel_outputs;

float kernel_f32(uint word) {{
    return asfloat(kernel_inputs[word]);
}}
{helpers}
{main}",
        main = main(
            "kernel_outputs",
            &format!("buffer_length / {}u", call.out_words),
            |index| call.typed_statements(index),
        ),
    )
}

/// An echo kernel of Slang or HLSL: `source`, the values in a `StructuredBuffer<{element}>`, the
/// output words, the declaration `push` of the push constants `echo_push`, and `main`.
pub(super) fn structured_echo_kernel(
    source: &str,
    element: &str,
    push: &str,
    echo: &KernelEcho<'_>,
) -> String {
    format!(
        "{source}

[[vk::binding(0, 0)]] StructuredBuffer<{element}> echo_values;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> kernel_outputs;
{push}

{main}",
        main = main("echo_values", "buffer_length", |index| echo
            .typed_statements(index)),
    )
}

/// A compute `main` of Slang or HLSL (its stage given to the compiler): invocation `id.x` returns
/// unless it is below `cases`, an expression that may use `buffer_length`, the element count of
/// the structured buffer `buffer`; then runs `statements` of its index expression.
fn main(buffer: &str, cases: &str, statements: impl FnOnce(&str) -> String) -> String {
    let index = "id.x";
    format!(
        "[numthreads({WORKGROUP_SIZE}, 1, 1)]
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

/// The layout slangc gives the Slang struct `name` (declared in `source`, which may `import` or
/// `#include` modules from `search_dirs`) as the element of a `StructuredBuffer` with `packing`'s
/// data layout: field offsets from the SPIR-V `Offset` decorations, the size from the array's
/// `ArrayStride`. The struct is found as the element type of the probe buffer, since slangc names
/// a struct in SPIR-V after its layout (`RfRayCone_std430`, `RfRayCone_natural` under scalar
/// rules). Needs `slangc` on the `PATH`.
pub fn slang_layout(
    source: &str,
    name: &str,
    packing: GlslPacking,
    search_dirs: &[&Path],
) -> Result<StructLayout, LayoutError> {
    if !is_identifier(name) {
        return Err(LayoutError::StructNotFound(name.to_string()));
    }
    let probe = format!(
        "{source}
[[vk::binding(0, 0)]] RWStructuredBuffer<{name}, {}> layout_probe;
         [shader(\"compute\")]
[numthreads(1, 1, 1)]
         void main() {{ layout_probe[0] = layout_probe[1]; }}
",
        packing.slang_layout()
    );
    // Errors at the probe buffer alone mean `name` is not a type the source declares.
    let probe_line = line_after(source);
    let spirv = compile_slang(&probe, Stage::Compute, Target::Vulkan1_1, search_dirs)
        .map_err(|error| probe_error(error, |log| compile_error(log, name, probe_line)))?;
    let mut layout = reflect::buffer_element_layout(&spirv, "layout_probe")
        .ok_or_else(|| LayoutError::StructNotFound(name.to_string()))?;
    layout.name = name.to_string();
    Ok(layout)
}

/// The error for a failed probe compile: errors (slangc's `--> source:LINE:` lines) at the probe
/// buffer alone mean `name` is not a type the source declares; otherwise slangc's log.
fn compile_error(log: &str, name: &str, probe_line: usize) -> LayoutError {
    let at_probe = format!("source:{probe_line}:");
    let errors: Vec<&str> = log
        .lines()
        .filter(|line| line.trim_start().starts_with("--> "))
        .collect();
    if !errors.is_empty() && errors.iter().all(|line| line.contains(&at_probe)) {
        LayoutError::StructNotFound(name.to_string())
    } else {
        LayoutError::Source(log.to_string())
    }
}
