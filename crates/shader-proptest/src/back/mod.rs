//! Back ends: everything the harness does differently per shading language, one file per language,
//! as naga keeps one folder per output language in `back/`.
//!
//! A [`Backend`] spells the generated kernels (type names, bit casts, matrix order, the kernel's
//! buffers and entry point), compiles a kernel with the language's compiler, and reads a struct's
//! layout the way that compiler lays it out. Everything else (which words a value takes, which
//! loads and stores a signature needs, running, judging, shrinking, reporting) is written once,
//! against this trait.
//!
//! A back end is a language together with the compiler that compiles it. A language with two
//! compilers (HLSL through glslang's HLSL front end and through slangc) is two back ends that
//! share the language's spelling: one type holding the compiler choice, one instance per compiler,
//! one [`Language`] per instance. Adding a back end is a file here, a variant of [`Language`] and
//! its arm in [`Language::backend`], and the language's shader files.

mod glsl;
mod hlsl;
mod slang;
mod wgsl;

pub use glsl::glsl_layout;
pub use slang::slang_layout;
pub use wgsl::wgsl_layout;

use crate::compile::CompileError;
use crate::layout::{GlslPacking, LayoutError, StructLayout};
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::Signature;
use crate::value::{ShaderType, StructType};
use std::fmt;

/// A shader language (with its compiler): the public name of a back end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// WGSL, compiled by naga.
    Wgsl,
    /// GLSL 460, compiled by glslang.
    Glsl,
    /// Slang, compiled by slangc.
    Slang,
    /// HLSL 2021, compiled by glslang's HLSL front end (`glslangValidator -D`).
    HlslGlslang,
    /// HLSL 2021, compiled by slangc.
    HlslSlangc,
}

impl Language {
    /// Every language.
    pub const ALL: [Language; 5] = [
        Language::Wgsl,
        Language::Glsl,
        Language::Slang,
        Language::HlslGlslang,
        Language::HlslSlangc,
    ];

    /// `"WGSL"`, `"GLSL"`, `"Slang"`, `"HLSL (glslang)"` or `"HLSL (slangc)"`.
    pub fn name(self) -> &'static str {
        self.backend().name()
    }

    /// The name of `ty` in this language (a struct's own name for a struct): `vec3<f32>` in
    /// WGSL, `vec3` in GLSL, `float3` in Slang and HLSL.
    pub fn type_name(self, ty: ShaderType) -> &'static str {
        self.backend().type_name(ty)
    }

    /// The back end that writes, compiles and lays out this language's kernels.
    pub(crate) fn backend(self) -> &'static dyn Backend {
        match self {
            Language::Wgsl => &wgsl::Wgsl,
            Language::Glsl => &glsl::Glsl,
            Language::Slang => &slang::Slang,
            Language::HlslGlslang => &hlsl::Hlsl(hlsl::HlslCompiler::Glslang),
            Language::HlslSlangc => &hlsl::Hlsl(hlsl::HlslCompiler::Slangc),
        }
    }
}

impl fmt::Display for Language {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

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

/// One shading language as the harness writes, compiles and lays it out.
pub(crate) trait Backend: Send + Sync {
    /// The language's name in reports: `"WGSL"`.
    fn name(&self) -> &'static str;

    /// How the language spells value types, bit casts and matrices.
    fn spelling(&self) -> &'static Spelling;

    /// The name of `ty` in the language (a struct's own name for a struct).
    fn type_name(&self, ty: ShaderType) -> &'static str {
        match VALUE_TYPES.iter().position(|&value| value == ty) {
            Some(index) => self.spelling().types[index],
            None => match ty {
                ShaderType::Struct(s) => s.name,
                _ => unreachable!("VALUE_TYPES lists every ShaderType but Struct"),
            },
        }
    }

    /// An `i32` expression with the bits of the `u32` expression `word`.
    fn int_from_bits(&self, word: &str) -> String {
        self.spelling().int_from_bits.replace("{}", word)
    }

    /// A `u32` expression with the bits of the `f32` expression `value`.
    fn float_bits(&self, value: &str) -> String {
        self.spelling().float_bits.replace("{}", value)
    }

    /// A `u32` expression with the bits of the `i32` expression `value`.
    fn int_bits(&self, value: &str) -> String {
        self.spelling().int_bits.replace("{}", value)
    }

    /// A `u32` expression that is 1 where the `bool` expression `value` holds, else 0.
    fn bool_word(&self, value: &str) -> String {
        self.spelling().bool_word.replace("{}", value)
    }

    /// How matrix constructors take their elements.
    fn matrix_order(&self) -> MatrixOrder {
        self.spelling().matrix_order
    }

    /// An expression of the struct `ty` from the expressions of its fields in declaration order:
    /// a constructor call `Name(...)` unless the language has none.
    fn struct_value(&self, ty: &StructType, fields: &[String]) -> String {
        format!("{}({})", ty.name, fields.join(", "))
    }

    /// A whole compute kernel: `source` (the [`Shader`]'s), the input and output word arrays
    /// (bindings 0 and 1), a `kernel_f32(word)` that reads input word `word` as a float, and an
    /// entry point `main` that runs `call` once per case.
    fn call_kernel(&self, source: &str, call: &KernelCall<'_>) -> String;

    /// A whole echo kernel: `source`, a storage buffer `echo_values` of the struct (binding 0, laid
    /// out by `packing` where the language lets a buffer choose), the output words (binding 1), a
    /// push-constant block `echo_push` of the struct, and an entry point `main` that runs `echo`
    /// once per value.
    fn echo_kernel(&self, source: &str, packing: GlslPacking, echo: &KernelEcho<'_>) -> String;

    /// Compiles a whole compute kernel written against `shader` to SPIR-V for Vulkan 1.1.
    fn compile_kernel(&self, shader: &Shader, kernel: &str) -> Result<Vec<u32>, CompileError>;

    /// The layout of the struct `name` that `shader` declares, as a storage buffer holds it.
    fn struct_layout(&self, shader: &Shader, name: &str) -> Result<StructLayout, LayoutError>;

    /// The signatures of the functions named `function` that `shader` declares, as the
    /// language's compiler reads them without a kernel (to explain a kernel that does not
    /// compile): empty where it declares none, `None` where the source does not compile either.
    #[cfg(feature = "gpu")]
    fn declared_signatures(&self, shader: &Shader, function: &str) -> Option<Vec<Signature>>;

    /// The signature of the function named `function` that the compiled `kernel` calls, where
    /// the language converts arguments implicitly, so that a kernel compiles with other types
    /// than the Rust ones; `None` where every call the compiler accepts has the kernel's types.
    #[cfg(feature = "gpu")]
    fn called_signature(&self, kernel: &[u32], function: &str) -> Option<Signature>;
}

/// What one invocation of a call kernel does, spelled by the back end ([`crate::kernel_source`]).
pub(crate) struct KernelCall<'a> {
    /// Input words per case.
    pub in_words: usize,
    /// Output words per case.
    pub out_words: usize,
    /// The result's type name.
    pub result_type: &'a str,
    /// Every struct type among the arguments (and the structs they hold), each once.
    pub structs: &'a [&'static StructType],
    /// The call, reading its arguments from input words `i`, `i + 1`, ...
    pub call: &'a str,
    /// Statements writing `result` to output words `o`, `o + 1`, ...
    pub stores: &'a str,
}

impl KernelCall<'_> {
    /// The invocation's statements in a language that declares a variable by its type (GLSL,
    /// Slang), for the case numbered by the expression `index`.
    pub fn typed_statements(&self, index: &str) -> String {
        format!(
            "    uint i = {index} * {in_words}u;
    uint o = {index} * {out_words}u;
    {result_type} result = {call};
{stores}",
            in_words = self.in_words,
            out_words = self.out_words,
            result_type = self.result_type,
            call = self.call,
            stores = self.stores,
        )
    }
}

/// What one invocation of an echo kernel does ([`crate::echo_kernel_source`]).
pub(crate) struct KernelEcho<'a> {
    /// The struct's name.
    pub name: &'a str,
    /// Output words per value: the stored value's, then the pushed value's.
    pub out_words: usize,
    /// Statements writing `stored` and then `pushed` to output words `o`, `o + 1`, ...
    pub stores: &'a str,
}

impl KernelEcho<'_> {
    /// The invocation's statements in a language that declares a variable by its type, for the
    /// value numbered by the expression `index`.
    pub fn typed_statements(&self, index: &str) -> String {
        format!(
            "    uint o = {index} * {out_words}u;
    {name} stored = echo_values[{index}];
    {name} pushed = echo_push;
{stores}",
            name = self.name,
            out_words = self.out_words,
            stores = self.stores,
        )
    }
}
