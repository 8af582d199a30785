//! How a language spells what the generated kernels need besides their text: type names, bit
//! casts and matrix order, as data that each back end declares once.

use crate::value::ShaderType;

/// How a language's matrix constructors take their elements, and what `m[k]` is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MatrixOrder {
    /// Column by column, and `m[k]` is column k (WGSL, GLSL).
    Columns,
    /// Row by row, and `m[k]` is row k (Slang, HLSL).
    Rows,
}

/// Every [`ShaderType`] but a struct, in the order of [`Spelling::types`].
const VALUE_TYPES: [ShaderType; 10] = [
    ShaderType::F32,
    ShaderType::U32,
    ShaderType::I32,
    ShaderType::Bool,
    ShaderType::Vec2,
    ShaderType::Vec3,
    ShaderType::Vec4,
    ShaderType::Mat2,
    ShaderType::Mat3,
    ShaderType::Mat4,
];

/// How a language spells what kernels need besides its [`Backend::call_kernel`] text: a type's
/// name, and expressions as templates in which `{}` stands for the operand.
pub(crate) struct Spelling {
    /// The names of the [`VALUE_TYPES`], in their order: `"float"`, `"uint"`, ... in GLSL.
    pub types: [&'static str; 10],
    /// An `i32` with the bits of a `u32`: `"int({})"` in GLSL.
    pub int_from_bits: &'static str,
    /// A `u32` with the bits of an `f32`: `"floatBitsToUint({})"` in GLSL.
    pub float_bits: &'static str,
    /// A `u32` with the bits of an `i32`: `"uint({})"` in GLSL.
    pub int_bits: &'static str,
    /// A `u32` that is 1 where a `bool` holds, else 0: `"({} ? 1u : 0u)"` in GLSL.
    pub bool_word: &'static str,
    /// How matrix constructors take their elements.
    pub matrix_order: MatrixOrder,
}

impl Spelling {
    /// The name of `ty` in the language (a struct's own name for a struct).
    pub fn type_name(&self, ty: ShaderType) -> &'static str {
        match VALUE_TYPES.iter().position(|&value| value == ty) {
            Some(index) => self.types[index],
            None => match ty {
                ShaderType::Struct(s) => s.name,
                _ => unreachable!("VALUE_TYPES lists every ShaderType but Struct"),
            },
        }
    }
}
