//! GLSL 460, compiled by glslang (`glslangValidator`, the compiler Vulkan's GLSL users use):
//! kernels put the [`Shader`]'s source (for example an `#include`) after `#version 460`, exactly
//! as users do, and layouts are read from the SPIR-V glslang writes for a probe block.

use super::backend::{Backend, KernelCall, KernelEcho, WORKGROUP_SIZE};
use super::spelling::{MatrixOrder, Spelling};
#[cfg(feature = "gpu")]
use crate::compile::glslang;
use crate::compile::{compile_glsl, CompileError, Stage, Target};
use crate::layout::{is_identifier, line_after, probe_error, GlslPacking, LayoutError, StructLayout};
use crate::reflect;
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::Signature;

use std::path::Path;

/// The GLSL back end.
pub(crate) struct Glsl;

/// GLSL's names and casts.
const SPELLING: Spelling = Spelling {
    types: [
        "float", "uint", "int", "bool", "vec2", "vec3", "vec4", "mat2", "mat3", "mat4",
    ],
    int_from_bits: "int({})",
    float_bits: "floatBitsToUint({})",
    int_bits: "uint({})",
    bool_word: "({} ? 1u : 0u)",
    matrix_order: MatrixOrder::Columns,
};

impl Backend for Glsl {
    fn spelling(&self) -> &'static Spelling {
        &SPELLING
    }

    fn call_kernel(&self, source: &str, call: &KernelCall<'_>) -> String {
        format!(
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
            main = main(
                &format!("uint(kernel_outputs.length()) / {}u", call.out_words),
                |index| call.typed_statements(index),
            ),
        )
    }

    fn echo_kernel(&self, source: &str, packing: GlslPacking, echo: &KernelEcho<'_>) -> String {
        format!(
            "#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
{source}

layout(local_size_x = {WORKGROUP_SIZE}) in;
layout({packing}, set = 0, binding = 0) readonly buffer EchoValues {{ {name} echo_values[]; }};
layout(std430, set = 0, binding = 1) writeonly buffer KernelOutputs {{ uint kernel_outputs[]; }};
layout({packing}, push_constant) uniform EchoPush {{ {name} echo_push; }};

{main}",
            packing = packing.qualifier(),
            name = echo.name,
            main = main("uint(echo_values.length())", |index| echo.typed_statements(index)),
        )
    }

    /// glslang, with the shader's include directories.
    fn compile_kernel(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, CompileError> {
        compile_glsl(kernel, Stage::Compute, Target::Vulkan1_1, &shader.include_dirs())
    }

    /// The element of a `std430` storage buffer.
    fn struct_layout(&self, shader: &Shader, name: &str) -> Result<StructLayout, LayoutError> {
        glsl_layout(shader.source(), name, GlslPacking::Std430, &shader.include_dirs())
    }

    /// From the SPIR-V of the source with an empty `main`, compiled keeping the functions nothing
    /// calls (glslang's `--keep-uncalled`).
    #[cfg(feature = "gpu")]
    fn declared_signatures(&self, shader: &Shader, function: &str) -> Option<Vec<Signature>> {
        let probe = format!(
            "#version 460\n#extension GL_GOOGLE_include_directive : require\n{}\n\
             layout(local_size_x = 1) in;\nvoid main() {{}}\n",
            shader.source()
        );
        let options = ["--keep-uncalled"];
        glslang(
            &probe,
            Stage::Compute,
            Target::Vulkan1_1,
            &shader.include_dirs(),
            &options,
        )
        .ok()
        .map(|spirv| reflect::signatures(&spirv, function, false))
    }

    /// GLSL converts `int` and `uint` arguments to `float` implicitly.
    #[cfg(feature = "gpu")]
    fn called_signature(&self, kernel: &[u32], function: &str) -> Option<Signature> {
        reflect::signatures(kernel, function, true).into_iter().next()
    }
}

/// A GLSL `main`: invocation `gl_GlobalInvocationID.x` returns unless it is below `cases`, then
/// runs `statements` of its index expression.
fn main(cases: &str, statements: impl FnOnce(&str) -> String) -> String {
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

/// The layout glslang gives the GLSL struct `name` (declared in `source`, a module without
/// `#version` or `main`, which may `#include` files from `include_dirs`) as the element of a
/// runtime array in a `packing` storage block: field offsets from the SPIR-V `Offset` decorations,
/// the size from the array's `ArrayStride`. Needs `glslangValidator` on the `PATH`. Compiler
/// errors name the lines of `source` as `source:LINE`.
pub fn glsl_layout(
    source: &str,
    name: &str,
    packing: GlslPacking,
    include_dirs: &[&Path],
) -> Result<StructLayout, LayoutError> {
    if !is_identifier(name) {
        return Err(LayoutError::StructNotFound(name.to_string()));
    }
    // `#line 1` numbers the lines of `source` from 1; the probe block follows on the next line.
    let probe = format!(
        "#version 460\n#extension GL_GOOGLE_include_directive : require\n\
         #extension GL_EXT_scalar_block_layout : require\n#line 1\n{source}\n\
         layout({}, set = 0, binding = 0) readonly buffer LayoutProbe {{ {name} layout_probe[]; }};\n\
         layout(local_size_x = 1) in;\nvoid main() {{}}\n",
        packing.qualifier()
    );
    let probe_line = line_after(source);
    let spirv = compile_glsl(&probe, Stage::Compute, Target::Vulkan1_2, include_dirs)
        .map_err(|error| probe_error(error, |log| compile_error(log, name, probe_line)))?;
    reflect::struct_layout(&spirv, name).ok_or_else(|| LayoutError::StructNotFound(name.to_string()))
}

/// The error for a failed probe compile: errors at the probe block alone mean `name` is not a type
/// the source declares; otherwise glslang's errors about the source (`source:LINE: ...`).
fn compile_error(log: &str, name: &str, probe_line: usize) -> LayoutError {
    let errors: Vec<&str> = log
        .lines()
        .filter_map(|line| line.strip_prefix("ERROR: "))
        .filter(|line| !line.contains("compilation errors") && !line.starts_with("Linking"))
        .collect();
    let at_probe = format!("source:{probe_line}:");
    if !errors.is_empty() && errors.iter().all(|line| line.starts_with(&at_probe)) {
        LayoutError::StructNotFound(name.to_string())
    } else if errors.is_empty() {
        LayoutError::Source(log.to_string())
    } else {
        LayoutError::Source(errors.join("\n"))
    }
}
