//! What every back end does ([`Backend`]), and what the kernel writer hands it: the statements of
//! one invocation of a call kernel ([`KernelCall`]) or an echo kernel ([`KernelEcho`]).

use super::spelling::{MatrixOrder, Spelling};
use crate::compile::CompileError;
use crate::layout::{GlslPacking, LayoutError, StructLayout};
use crate::shader::Shader;
#[cfg(feature = "gpu")]
use crate::signature::Signature;
use crate::value::{ShaderType, StructType};

/// Invocations per workgroup in every generated kernel.
pub const WORKGROUP_SIZE: u32 = 64;

/// One shading language as the harness writes, compiles and lays it out.
pub(crate) trait Backend: Send + Sync {
    /// How the language spells value types, bit casts and matrices.
    fn spelling(&self) -> &'static Spelling;

    /// The name of `ty` in the language (a struct's own name for a struct).
    fn type_name(&self, ty: ShaderType) -> &'static str {
        self.spelling().type_name(ty)
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
