//! HLSL, compiled by glslang's HLSL front end or by slangc: two back ends that spell their kernels
//! the same way and differ in the compiler. Kernels put the [`Shader`]'s source (for example an
//! `#include`) in front, declare their buffers as structured buffers with `vk::binding`, and the
//! push constants as a `vk::push_constant` constant buffer; layouts are read from the SPIR-V the
//! compiler writes for a probe buffer.
//!
//! HLSL has no struct constructors: a kernel declares one function per struct it builds,
//! `kernel_make_<Name>`, that returns an initializer list of its parameters. Matrix constructors
//! take a matrix row by row and `m[r]` is row r ([`super::MatrixOrder::Rows`]), as in Slang.
//! Kernels are Slang's, written by [`super::slang::structured_call_kernel`] and
//! [`super::slang::structured_echo_kernel`]. Buffers take the compiler's default layout for
//! Vulkan, `std430` (storage buffers and push constants alike): HLSL has no way to choose another
//! in the source, so an echo kernel ignores its packing, as WGSL's does.

use super::backend::{Backend, KernelCall, KernelEcho};
#[cfg(feature = "gpu")]
use super::slang::slangc_declared_signatures;
use super::slang::{self, structured_call_kernel, structured_echo_kernel};
use super::spelling::Spelling;
use crate::compile::{compile_hlsl_with_glslang, compile_hlsl_with_slangc, CompileError, Stage, Target};
use crate::layout::{is_identifier, line_after, probe_error, GlslPacking, LayoutError, StructLayout};
use crate::reflect;
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::Signature;
use crate::value::StructType;
use std::fmt::Write as _;
use std::path::Path;

/// The compiler an HLSL back end uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum HlslCompiler {
    /// glslang's HLSL front end (`glslangValidator -D`).
    Glslang,
    /// slangc, reading the kernel as HLSL.
    Slangc,
}

/// An HLSL back end: the language's spelling with one compiler.
pub(crate) struct Hlsl(pub HlslCompiler);

impl Backend for Hlsl {
    /// Types, bit casts and matrix order are spelled as in Slang, which reads HLSL's.
    fn spelling(&self) -> &'static Spelling {
        &slang::SPELLING
    }

    /// A call of the struct's `kernel_make_` function, which [`Backend::call_kernel`] declares.
    fn struct_value(&self, ty: &StructType, fields: &[String]) -> String {
        format!("kernel_make_{}({})", ty.name, fields.join(", "))
    }

    fn call_kernel(&self, source: &str, call: &KernelCall<'_>) -> String {
        structured_call_kernel(source, &self.struct_makers(call.structs), call)
    }

    /// The buffer and the push constants in `std430` whatever `packing` says (see the module
    /// documentation). The push constants are a constant buffer holding one struct member, which
    /// glslang can copy whole (it cannot copy a `ConstantBuffer<T>` into a `T`).
    fn echo_kernel(&self, source: &str, _packing: GlslPacking, echo: &KernelEcho<'_>) -> String {
        let push = format!(
            "[[vk::push_constant]] cbuffer EchoPush {{\n    {} echo_push;\n}};",
            echo.name
        );
        structured_echo_kernel(source, echo.name, &push, echo)
    }

    fn compile_kernel(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, CompileError> {
        self.compile(kernel, Target::Vulkan1_1, &shader.include_dirs())
    }

    /// The element of a structured buffer (`std430`).
    fn struct_layout(&self, shader: &Shader, name: &str) -> Result<StructLayout, LayoutError> {
        if !is_identifier(name) {
            return Err(LayoutError::StructNotFound(name.to_string()));
        }
        let probe = format!(
            "{source}
[[vk::binding(0, 0)]] RWStructuredBuffer<{name}> layout_probe;
[numthreads(1, 1, 1)]
void main() {{ layout_probe[0] = layout_probe[1]; }}
",
            source = shader.source()
        );
        let probe_line = line_after(shader.source());
        let spirv = self
            .compile(&probe, Target::Vulkan1_1, &shader.include_dirs())
            .map_err(|error| probe_error(error, |log| compile_error(log, name, probe_line)))?;
        let mut layout = reflect::buffer_element_layout(&spirv, "layout_probe")
            .ok_or_else(|| LayoutError::StructNotFound(name.to_string()))?;
        layout.name = name.to_string();
        Ok(layout)
    }

    /// From slangc's words on the source read as HLSL, for either compiler: glslang's HLSL front
    /// end drops the functions nothing calls even with `--keep-uncalled`, and its errors do not
    /// spell a function's type. Where slangc cannot read a source that glslang compiles, a kernel
    /// that does not compile is reported as a compile error.
    #[cfg(feature = "gpu")]
    fn declared_signatures(&self, shader: &Shader, function: &str) -> Option<Vec<Signature>> {
        slangc_declared_signatures(shader, function, |probe| {
            compile_hlsl_with_slangc(probe, Stage::Compute, Target::Vulkan1_1, &shader.include_dirs())
        })
    }

    /// HLSL converts integers to floats and scalars to vectors implicitly.
    #[cfg(feature = "gpu")]
    fn called_signature(&self, kernel: &[u32], function: &str) -> Option<Signature> {
        reflect::signatures(kernel, function, true).into_iter().next()
    }
}

impl Hlsl {
    /// Compiles a compute shader with this back end's compiler.
    fn compile(
        &self,
        source: &str,
        target: Target,
        include_dirs: &[&Path],
    ) -> Result<Vec<u32>, CompileError> {
        match self.0 {
            HlslCompiler::Glslang => compile_hlsl_with_glslang(source, Stage::Compute, target, include_dirs),
            HlslCompiler::Slangc => compile_hlsl_with_slangc(source, Stage::Compute, target, include_dirs),
        }
    }

    /// `kernel_make_<Name>` for each struct in `structs`: its fields as parameters `f0`, `f1`, ...
    /// (never a field's own name, which may be an intrinsic's), returned as an initializer list.
    fn struct_makers(&self, structs: &[&StructType]) -> String {
        let mut out = String::new();
        for ty in structs {
            let parameters: Vec<String> = ty
                .fields
                .iter()
                .enumerate()
                .map(|(index, &(_, field))| format!("{} f{index}", self.type_name(field)))
                .collect();
            let values: Vec<String> = (0..ty.fields.len()).map(|index| format!("f{index}")).collect();
            writeln!(
                out,
                "
{name} kernel_make_{name}({parameters}) {{
    {name} value = {{ {values} }};
    return value;
}}",
                name = ty.name,
                parameters = parameters.join(", "),
                values = values.join(", "),
            )
            .expect("writing to a String");
        }
        out
    }
}

/// The error for a failed probe compile: errors at the probe buffer's line alone mean `name` is not
/// a type the source declares; otherwise the compiler's errors (glslang's `ERROR: source:LINE: ...`
/// lines), or its whole log (slangc's, which starts with the first error).
fn compile_error(log: &str, name: &str, probe_line: usize) -> LayoutError {
    let at_probe = format!("source:{probe_line}:");
    let glslang_errors: Vec<&str> = log
        .lines()
        .filter_map(|line| line.strip_prefix("ERROR: "))
        .filter(|line| line.starts_with("source:"))
        .collect();
    let slangc_errors: Vec<&str> = log
        .lines()
        .map(str::trim_start)
        .filter(|line| line.starts_with("--> "))
        .collect();
    let errors = if glslang_errors.is_empty() {
        slangc_errors
    } else {
        glslang_errors.clone()
    };
    if !errors.is_empty() && errors.iter().all(|line| line.contains(&at_probe)) {
        LayoutError::StructNotFound(name.to_string())
    } else if glslang_errors.is_empty() {
        LayoutError::Source(log.to_string())
    } else {
        LayoutError::Source(glslang_errors.join("\n"))
    }
}
