//! WGSL, compiled by naga: kernels are the module's text followed by the wrapper, and layouts are
//! naga's (the WGSL rules for host-shareable memory, which storage buffers and push constants use).

use super::backend::{Backend, KernelCall, KernelEcho, WORKGROUP_SIZE};
use super::spelling::{MatrixOrder, Spelling};
use crate::compile::{compile_wgsl, CompileError, Target};
use crate::layout::{FieldLayout, GlslPacking, LayoutError, StructLayout};
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::{DeclaredType, Signature};
#[cfg(feature = "gpu")]
use crate::value::ShaderType;

/// The WGSL back end.
pub(crate) struct Wgsl;

/// WGSL's names and casts.
const SPELLING: Spelling = Spelling {
    types: [
        "f32",
        "u32",
        "i32",
        "bool",
        "vec2<f32>",
        "vec3<f32>",
        "vec4<f32>",
        "mat2x2<f32>",
        "mat3x3<f32>",
        "mat4x4<f32>",
    ],
    int_from_bits: "bitcast<i32>({})",
    float_bits: "bitcast<u32>({})",
    int_bits: "bitcast<u32>({})",
    bool_word: "select(0u, 1u, {})",
    matrix_order: MatrixOrder::Columns,
};

impl Backend for Wgsl {
    fn spelling(&self) -> &'static Spelling {
        &SPELLING
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

    /// The functions of naga's module of the source.
    #[cfg(feature = "gpu")]
    fn declared_signatures(&self, shader: &Shader, function: &str) -> Option<Vec<Signature>> {
        let module = naga::front::wgsl::parse_str(shader.source()).ok()?;
        let declared = |ty: naga::Handle<naga::Type>| declared_type(&module, ty);
        module
            .functions
            .iter()
            .filter(|(_, f)| f.name.as_deref() == Some(function))
            .map(|(_, f)| Signature {
                parameters: f
                    .arguments
                    .iter()
                    .map(|argument| (argument.name.clone().unwrap_or_default(), declared(argument.ty)))
                    .collect(),
                result: f.result.as_ref().map_or_else(
                    || DeclaredType::Other(String::from("nothing")),
                    |result| declared(result.ty),
                ),
            })
            .collect::<Vec<_>>()
            .into()
    }

    /// WGSL converts no argument: a kernel naga accepts passes exactly the kernel's types.
    #[cfg(feature = "gpu")]
    fn called_signature(&self, _kernel: &[u32], _function: &str) -> Option<Signature> {
        None
    }
}

/// The path of the first `bool` among `members`, through nested structs and arrays:
/// `inner.flag`.
fn bool_member(module: &naga::Module, members: &[naga::StructMember]) -> Option<String> {
    members.iter().find_map(|member| {
        let name = member.name.clone().unwrap_or_default();
        let mut ty = &module.types[member.ty].inner;
        while let naga::TypeInner::Array { base, .. } = ty {
            ty = &module.types[*base].inner;
        }
        match ty {
            naga::TypeInner::Scalar(scalar) if scalar.kind == naga::ScalarKind::Bool => Some(name),
            naga::TypeInner::Struct { members, .. } => {
                bool_member(module, members).map(|inner| format!("{name}.{inner}"))
            }
            _ => None,
        }
    })
}

/// The WGSL type `ty` of `module` as a signature shows it.
#[cfg(feature = "gpu")]
fn declared_type(module: &naga::Module, ty: naga::Handle<naga::Type>) -> DeclaredType {
    use naga::common::wgsl::TypeContext;
    use naga::{ScalarKind, TypeInner, VectorSize};
    let f32 = naga::Scalar::F32;
    let known = match &module.types[ty].inner {
        TypeInner::Scalar(scalar) => match (scalar.kind, scalar.width) {
            (ScalarKind::Float, 4) => Some(ShaderType::F32),
            (ScalarKind::Uint, 4) => Some(ShaderType::U32),
            (ScalarKind::Sint, 4) => Some(ShaderType::I32),
            (ScalarKind::Bool, _) => Some(ShaderType::Bool),
            _ => None,
        },
        TypeInner::Vector { size, scalar } if *scalar == f32 => match size {
            VectorSize::Bi => Some(ShaderType::Vec2),
            VectorSize::Tri => Some(ShaderType::Vec3),
            VectorSize::Quad => Some(ShaderType::Vec4),
        },
        TypeInner::Matrix {
            columns,
            rows,
            scalar,
        } if *scalar == f32 && columns == rows => match columns {
            VectorSize::Bi => Some(ShaderType::Mat2),
            VectorSize::Tri => Some(ShaderType::Mat3),
            VectorSize::Quad => Some(ShaderType::Mat4),
        },
        TypeInner::Struct { .. } => {
            return DeclaredType::Struct(module.types[ty].name.clone().unwrap_or_default());
        }
        _ => None,
    };
    known.map_or_else(
        || DeclaredType::Other(module.to_ctx().type_to_string(ty)),
        DeclaredType::Value,
    )
}

/// The layout naga gives the WGSL struct `name` declared in `source` (the WGSL rules for
/// host-shareable memory, which storage buffers and push constants use). A struct that holds a
/// `bool`, directly or in a struct or array it holds, is refused naming the field
/// ([`LayoutError::BoolInBuffer`]): WGSL forbids `bool` in host-shareable memory.
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
    if let Some(field) = bool_member(&module, members) {
        return Err(LayoutError::BoolInBuffer {
            structure: name.to_string(),
            field,
        });
    }
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
