//! Generated compute kernels: one entry point that calls one shader function per invocation.
//!
//! The kernel reads each case's arguments from a word array (binding 0), calls the function, and
//! writes the result's words to a second array (binding 1). Which words a value takes, and which
//! loads and stores a signature needs, is decided here once; the back end of the [`Shader`]'s
//! language spells them and writes the kernel around them, with the source in front.
//!
//! Matrices cross as their columns, one after the other (glam's order). Where the language's
//! constructors take a matrix column by column and `m[c]` is column c (WGSL, GLSL), a matrix is
//! built from its words in order and stored as `m[c]`; where they take it row by row and `m[r]` is
//! row r (Slang, HLSL), it is built from its elements in row order and stored as `transpose(m)[c]`.

use crate::back::backend::{Backend, KernelCall, KernelEcho};
use crate::back::spelling::MatrixOrder;
use crate::layout::GlslPacking;
use crate::shader::Shader;
use crate::value::{ShaderType, StructType};
use std::fmt::Write as _;

/// The source of a kernel that calls `function` of `shader` once per case, with arguments of types
/// `parameters`, returning `result`.
pub fn kernel_source(
    shader: &Shader,
    function: &str,
    parameters: &[ShaderType],
    result: ShaderType,
) -> String {
    let backend = shader.backend();
    let mut offset = 0;
    let arguments: Vec<String> = parameters
        .iter()
        .map(|&ty| load(backend, ty, &mut offset))
        .collect();
    let mut stores = String::new();
    store(backend, result, "result", &mut 0, &mut stores);
    let mut structs = Vec::new();
    parameters.iter().for_each(|ty| ty.structs(&mut structs));
    let call = KernelCall {
        in_words: offset,
        out_words: result.words(),
        result_type: backend.type_name(result),
        structs: &structs,
        call: &format!("{function}({})", arguments.join(", ")),
        stores: &stores,
    };
    backend.call_kernel(shader.source(), &call)
}

/// The source of an echo kernel for the struct `ty` declared by `shader`: invocation `i` reads
/// element `i` of a storage buffer of `ty` (binding 0) and the push-constant block (a `ty`), and
/// writes every field of both, by name and in declaration order, as words to binding 1 (the
/// element first, then the push constants). GLSL blocks and Slang buffers use `packing`; WGSL has
/// its own rules.
pub fn echo_kernel_source(shader: &Shader, packing: GlslPacking, ty: &'static StructType) -> String {
    let backend = shader.backend();
    let words = ShaderType::Struct(ty).words();
    let mut stores = String::new();
    store(backend, ShaderType::Struct(ty), "stored", &mut 0, &mut stores);
    store(
        backend,
        ShaderType::Struct(ty),
        "pushed",
        &mut { words },
        &mut stores,
    );
    let echo = KernelEcho {
        name: ty.name,
        out_words: 2 * words,
        stores: &stores,
    };
    backend.echo_kernel(shader.source(), packing, &echo)
}

/// An expression reading a value of type `ty` at input word `i + offset`; advances `offset`.
fn load(backend: &dyn Backend, ty: ShaderType, offset: &mut usize) -> String {
    let mut next = || {
        let word = *offset;
        *offset += 1;
        word
    };
    match ty {
        ShaderType::F32 => format!("kernel_f32(i + {}u)", next()),
        ShaderType::U32 => format!("kernel_inputs[i + {}u]", next()),
        ShaderType::I32 => backend.int_from_bits(&format!("kernel_inputs[i + {}u]", next())),
        ShaderType::Bool => format!("(kernel_inputs[i + {}u] != 0u)", next()),
        ShaderType::Vec2
        | ShaderType::Vec3
        | ShaderType::Vec4
        | ShaderType::Mat2
        | ShaderType::Mat3
        | ShaderType::Mat4 => {
            let first = *offset;
            *offset += ty.words();
            let floats: Vec<String> = constructor_words(backend, ty)
                .map(|word| format!("kernel_f32(i + {}u)", first + word))
                .collect();
            format!("{}({})", backend.type_name(ty), floats.join(", "))
        }
        ShaderType::Struct(s) => {
            let fields: Vec<String> = s
                .fields
                .iter()
                .map(|&(_, field)| load(backend, field, offset))
                .collect();
            backend.struct_value(s, &fields)
        }
    }
}

/// The input words, relative to a value's first, in the order the type's constructor takes its
/// components: word order, except for a matrix in a language whose constructors take rows, whose
/// element (r, c) is word c n + r.
fn constructor_words(backend: &dyn Backend, ty: ShaderType) -> impl Iterator<Item = usize> {
    let words = ty.words();
    let columns = match (backend.matrix_order(), ty) {
        (MatrixOrder::Rows, ShaderType::Mat2 | ShaderType::Mat3 | ShaderType::Mat4) => words.isqrt(),
        _ => 1,
    };
    (0..words).map(move |index| (index % columns) * columns + index / columns)
}

/// Statements writing `expr` of type `ty` to output words `o + offset..`; advances `offset`.
fn store(backend: &dyn Backend, ty: ShaderType, expr: &str, offset: &mut usize, out: &mut String) {
    let mut word = |value: String| {
        writeln!(out, "    kernel_outputs[o + {}u] = {value};", *offset).expect("writing to a String");
        *offset += 1;
    };
    match ty {
        ShaderType::F32 => word(backend.float_bits(expr)),
        ShaderType::U32 => word(expr.to_string()),
        ShaderType::I32 => word(backend.int_bits(expr)),
        ShaderType::Bool => word(backend.bool_word(expr)),
        ShaderType::Vec2 | ShaderType::Vec3 | ShaderType::Vec4 => {
            for component in ["x", "y", "z", "w"].iter().take(ty.words()) {
                store(
                    backend,
                    ShaderType::F32,
                    &format!("{expr}.{component}"),
                    offset,
                    out,
                );
            }
        }
        ShaderType::Mat2 => store_columns(backend, ShaderType::Vec2, 2, expr, offset, out),
        ShaderType::Mat3 => store_columns(backend, ShaderType::Vec3, 3, expr, offset, out),
        ShaderType::Mat4 => store_columns(backend, ShaderType::Vec4, 4, expr, offset, out),
        ShaderType::Struct(s) => {
            for &(name, field) in s.fields {
                store(backend, field, &format!("{expr}.{name}"), offset, out);
            }
        }
    }
}

/// Statements writing the `columns` columns of the matrix `expr`, each a `column` vector.
fn store_columns(
    backend: &dyn Backend,
    column: ShaderType,
    columns: usize,
    expr: &str,
    offset: &mut usize,
    out: &mut String,
) {
    for index in 0..columns {
        let column_expr = match backend.matrix_order() {
            MatrixOrder::Columns => format!("{expr}[{index}]"),
            MatrixOrder::Rows => format!("transpose({expr})[{index}]"),
        };
        store(backend, column, &column_expr, offset, out);
    }
}
