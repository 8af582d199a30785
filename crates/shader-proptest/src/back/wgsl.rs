//! WGSL, compiled by naga: kernels are the module's text followed by the wrapper, and layouts are
//! naga's (the WGSL rules for host-shareable memory, which storage buffers and push constants use).

use super::{Backend, KernelCall, KernelEcho, MatrixOrder};
use crate::compile::{compile_wgsl, CompileError, Target};
use crate::kernel::WORKGROUP_SIZE;
use crate::layout::{FieldLayout, GlslPacking, LayoutError, StructLayout};
use crate::shader::Shader;
use crate::value::ShaderType;

/// The WGSL back end.
pub(crate) struct Wgsl;

impl Backend for Wgsl {
    fn name(&self) -> &'static str {
        "WGSL"
    }

    fn type_name(&self, ty: ShaderType) -> &'static str {
        match ty {
            ShaderType::F32 => "f32",
            ShaderType::U32 => "u32",
            ShaderType::I32 => "i32",
            ShaderType::Bool => "bool",
            ShaderType::Vec2 => "vec2<f32>",
            ShaderType::Vec3 => "vec3<f32>",
            ShaderType::Vec4 => "vec4<f32>",
            ShaderType::Mat2 => "mat2x2<f32>",
            ShaderType::Mat3 => "mat3x3<f32>",
            ShaderType::Mat4 => "mat4x4<f32>",
            ShaderType::Struct(s) => s.name,
        }
    }

    fn int_from_bits(&self, word: &str) -> String {
        format!("bitcast<i32>({word})")
    }

    fn float_bits(&self, value: &str) -> String {
        format!("bitcast<u32>({value})")
    }

    fn int_bits(&self, value: &str) -> String {
        format!("bitcast<u32>({value})")
    }

    fn bool_word(&self, value: &str) -> String {
        format!("select(0u, 1u, {value})")
    }

    fn matrix_order(&self) -> MatrixOrder {
        MatrixOrder::Columns
    }

    fn call_kernel(&self, source: &str, call: &KernelCall<'_>) -> String {
        let KernelCall {
            in_words,
            out_words,
            call,
            stores,
            ..
        } = call;
        format!(
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
"
        )
    }

    /// WGSL has one layout for storage buffers and push constants: `packing` does not apply.
    fn echo_kernel(&self, source: &str, _packing: GlslPacking, echo: &KernelEcho<'_>) -> String {
        let KernelEcho {
            name,
            out_words,
            stores,
        } = echo;
        format!(
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
"
        )
    }

    /// naga, with the shader's capabilities and push constants (`var<immediate>`).
    fn compile_kernel(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, CompileError> {
        compile_wgsl(
            kernel,
            "kernel.wgsl",
            shader.naga_capabilities() | naga::valid::Capabilities::IMMEDIATES,
            Target::Vulkan1_1,
        )
    }

    fn struct_layout(&self, shader: &Shader, name: &str) -> Result<StructLayout, LayoutError> {
        wgsl_layout(shader.source(), name)
    }
}

/// The layout naga gives the WGSL struct `name` declared in `source` (the WGSL rules for
/// host-shareable memory, which storage buffers and push constants use).
pub fn wgsl_layout(source: &str, name: &str) -> Result<StructLayout, LayoutError> {
    let module = naga::front::wgsl::parse_str(source)
        .map_err(|error| LayoutError::Source(error.emit_to_string(source)))?;
    let mut layouter = naga::proc::Layouter::default();
    layouter
        .update(module.to_ctx())
        .map_err(|error| LayoutError::Source(format!("layout: {error}")))?;
    let (handle, members, span) = module
        .types
        .iter()
        .find_map(|(handle, ty)| match &ty.inner {
            naga::TypeInner::Struct { members, span } if ty.name.as_deref() == Some(name) => {
                Some((handle, members, *span))
            }
            _ => None,
        })
        .ok_or_else(|| LayoutError::StructNotFound(name.to_string()))?;
    let fields = members
        .iter()
        .map(|member| FieldLayout {
            name: member.name.clone().unwrap_or_default(),
            offset: member.offset,
            size: layouter[member.ty].size,
        })
        .collect();
    Ok(StructLayout {
        name: name.to_string(),
        size: span,
        align: layouter[handle].alignment * 1,
        fields,
    })
}
