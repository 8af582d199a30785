//! Values that travel between a Rust mirror and a generated kernel as raw 32-bit words.
//!
//! Every argument is written as words (floats by their bit pattern, booleans as 0 or 1), read by the
//! kernel field by field, passed to the shader function, and the result is written back as words:
//! nothing is converted on the way, so the comparison sees exactly what the shader computed.
//! Results are compared as `f32` components, which is exact for floats, booleans and integers below
//! 2^24.
//!
//! [`Value`] is implemented for `f32`, `u32`, `i32`, `bool` and glam's `Vec2`, `Vec3`, `Vec4`,
//! `Mat2`, `Mat3` and `Mat4`; [`shader_struct!`](crate::shader_struct) implements it for a struct
//! of such fields (and, with `pod`, records the struct's Rust layout, which every check compares
//! with the shader's); [`Args`] is implemented for tuples of up to eight values.

use crate::layout::StructLayout;
use glam::{Mat2, Mat3, Mat4, Vec2, Vec3, Vec4};
use std::fmt::Debug;

/// A shader-side type: enough to load it from words and store it as words in WGSL, GLSL and Slang.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderType {
    /// `f32` / `float`.
    F32,
    /// `u32` / `uint`.
    U32,
    /// `i32` / `int`.
    I32,
    /// `bool`, carried as a word (0 = false).
    Bool,
    /// `vec2<f32>` / `vec2`.
    Vec2,
    /// `vec3<f32>` / `vec3`.
    Vec3,
    /// `vec4<f32>` / `vec4`.
    Vec4,
    /// `mat2x2<f32>` / `mat2`, column-major.
    Mat2,
    /// `mat3x3<f32>` / `mat3`, column-major.
    Mat3,
    /// `mat4x4<f32>` / `mat4`, column-major.
    Mat4,
    /// A struct the shader declares under the same name in every language.
    Struct(&'static StructType),
}

impl ShaderType {
    /// Appends, per 32-bit word of the value, whether it is a float.
    pub fn float_words(self, out: &mut Vec<bool>) {
        match self {
            ShaderType::U32 | ShaderType::I32 | ShaderType::Bool => out.push(false),
            ShaderType::Struct(s) => s.fields.iter().for_each(|&(_, field)| field.float_words(out)),
            float => out.extend(std::iter::repeat_n(true, float.words())),
        }
    }

    /// How many 32-bit words the value takes.
    pub fn words(self) -> usize {
        match self {
            ShaderType::F32 | ShaderType::U32 | ShaderType::I32 | ShaderType::Bool => 1,
            ShaderType::Vec2 => 2,
            ShaderType::Vec3 => 3,
            ShaderType::Vec4 | ShaderType::Mat2 => 4,
            ShaderType::Mat3 => 9,
            ShaderType::Mat4 => 16,
            ShaderType::Struct(s) => s.fields.iter().map(|(_, ty)| ty.words()).sum(),
        }
    }

    /// The Rust type a value of this type is: `f32`, `Vec3`, a struct's Rust name.
    pub fn rust_name(self) -> &'static str {
        match self {
            ShaderType::F32 => "f32",
            ShaderType::U32 => "u32",
            ShaderType::I32 => "i32",
            ShaderType::Bool => "bool",
            ShaderType::Vec2 => "Vec2",
            ShaderType::Vec3 => "Vec3",
            ShaderType::Vec4 => "Vec4",
            ShaderType::Mat2 => "Mat2",
            ShaderType::Mat3 => "Mat3",
            ShaderType::Mat4 => "Mat4",
            ShaderType::Struct(s) => s.rust_name,
        }
    }

    /// Every struct type reachable from this one (itself first), each once.
    pub fn structs(self, out: &mut Vec<&'static StructType>) {
        if let ShaderType::Struct(s) = self {
            if !out.iter().any(|seen| std::ptr::eq(*seen, s)) {
                out.push(s);
                s.fields.iter().for_each(|(_, field)| field.structs(out));
            }
        }
    }
}

/// A struct declared by the shader: its name and its fields in declaration order.
#[derive(Debug)]
pub struct StructType {
    /// The struct's name in the shader.
    pub name: &'static str,
    /// The struct's name in Rust.
    pub rust_name: &'static str,
    /// Field names and types, in declaration order.
    pub fields: &'static [(&'static str, ShaderType)],
    /// For a `#[repr(C)]` bytemuck `Pod` struct: its Rust layout, which a check compares with the
    /// shader's (WGSL: naga's layout; GLSL: std430) before it runs.
    pub rust_layout: Option<fn() -> StructLayout>,
}

/// Two struct types are the same shader type when their names and fields are.
impl PartialEq for StructType {
    fn eq(&self, other: &StructType) -> bool {
        self.name == other.name && self.fields == other.fields
    }
}

impl Eq for StructType {}

/// A Rust value with a shader twin of type [`Value::TYPE`].
pub trait Value: Clone + Debug + Send + Sync + 'static {
    /// The shader-side type.
    const TYPE: ShaderType;
    /// Appends the value's words.
    fn write(&self, words: &mut Vec<u32>);
    /// Reads the value from the front of `words` and advances past it.
    ///
    /// # Panics
    /// If `words` is shorter than the value (a kernel's output always has the expected length).
    fn read(words: &mut &[u32]) -> Self;
    /// The numbers compared between the mirror and the shader, in a fixed order.
    fn components(&self, out: &mut Vec<f32>);
    /// Whether every float in the value is finite.
    fn is_finite(&self) -> bool;
}

/// Removes and returns the first word.
///
/// # Panics
/// If `words` is empty.
pub fn take(words: &mut &[u32]) -> u32 {
    let (first, rest) = words
        .split_first()
        .expect("a kernel's output has the expected length");
    *words = rest;
    *first
}

/// Compiles only for bytemuck `Pod` types; [`shader_struct!`](crate::shader_struct)`(pod ...)`
/// uses it to require one.
#[doc(hidden)]
pub fn assert_pod<T: bytemuck::Pod>() {}

impl Value for f32 {
    const TYPE: ShaderType = ShaderType::F32;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(self.to_bits());
    }
    fn read(words: &mut &[u32]) -> Self {
        f32::from_bits(take(words))
    }
    fn components(&self, out: &mut Vec<f32>) {
        out.push(*self);
    }
    fn is_finite(&self) -> bool {
        f32::is_finite(*self)
    }
}

impl Value for u32 {
    const TYPE: ShaderType = ShaderType::U32;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(*self);
    }
    fn read(words: &mut &[u32]) -> Self {
        take(words)
    }
    fn components(&self, out: &mut Vec<f32>) {
        out.push(*self as f32);
    }
    fn is_finite(&self) -> bool {
        true
    }
}

impl Value for i32 {
    const TYPE: ShaderType = ShaderType::I32;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(*self as u32);
    }
    fn read(words: &mut &[u32]) -> Self {
        take(words) as i32
    }
    fn components(&self, out: &mut Vec<f32>) {
        out.push(*self as f32);
    }
    fn is_finite(&self) -> bool {
        true
    }
}

impl Value for bool {
    const TYPE: ShaderType = ShaderType::Bool;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(u32::from(*self));
    }
    fn read(words: &mut &[u32]) -> Self {
        take(words) != 0
    }
    fn components(&self, out: &mut Vec<f32>) {
        out.push(f32::from(u8::from(*self)));
    }
    fn is_finite(&self) -> bool {
        true
    }
}

/// Implements [`Value`] for a glam float type from its array form.
macro_rules! float_array_value {
    ($rust:ty, $shader:expr, $to_array:ident, $from_array:ident, $len:literal) => {
        impl Value for $rust {
            const TYPE: ShaderType = $shader;
            fn write(&self, words: &mut Vec<u32>) {
                words.extend(self.$to_array().map(f32::to_bits));
            }
            fn read(words: &mut &[u32]) -> Self {
                <$rust>::$from_array(&std::array::from_fn::<f32, $len, _>(|_| {
                    f32::from_bits(take(words))
                }))
            }
            fn components(&self, out: &mut Vec<f32>) {
                out.extend(self.$to_array());
            }
            fn is_finite(&self) -> bool {
                self.$to_array().iter().all(|x| x.is_finite())
            }
        }
    };
}

float_array_value!(Vec2, ShaderType::Vec2, to_array, from_slice, 2);
float_array_value!(Vec3, ShaderType::Vec3, to_array, from_slice, 3);
float_array_value!(Vec4, ShaderType::Vec4, to_array, from_slice, 4);
float_array_value!(Mat2, ShaderType::Mat2, to_cols_array, from_cols_slice, 4);
float_array_value!(Mat3, ShaderType::Mat3, to_cols_array, from_cols_slice, 9);
float_array_value!(Mat4, ShaderType::Mat4, to_cols_array, from_cols_slice, 16);

/// Implements [`Value`](crate::Value) for a struct whose shader twin has the same fields in the
/// same order, each of a type that implements `Value`. List every field with its type; the
/// generated `read` builds the struct from the list, so a missing field does not compile.
///
/// With `pod`, the struct must be a `#[repr(C)]` bytemuck `Pod` type, and its Rust layout (from
/// `offset_of!`) is recorded: every check that passes or returns it first compares it with the
/// shader's layout (naga's WGSL layout; GLSL std430) and fails, naming the field, if they differ.
///
/// ```
/// use glam::Vec3;
/// use shader_proptest::shader_struct;
///
/// #[repr(C)]
/// #[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
/// pub struct Light {
///     pub direction: Vec3,
///     pub intensity: f32,
/// }
///
/// shader_struct!(pod Light as "Light" { direction: Vec3, intensity: f32 });
/// ```
#[macro_export]
macro_rules! shader_struct {
    (pod $ty:ty as $name:literal { $($field:ident: $field_ty:ty),+ $(,)? }) => {
        $crate::shader_struct!(@impl $ty, $name, ::core::option::Option::Some({
            fn rust_layout() -> $crate::layout::StructLayout {
                $crate::rust_layout!(@build $ty, $name, $($field),+)
            }
            rust_layout as fn() -> $crate::layout::StructLayout
        }), $($field: $field_ty),+);
        const _: fn() = $crate::value::assert_pod::<$ty>;
    };
    ($ty:ty as $name:literal { $($field:ident: $field_ty:ty),+ $(,)? }) => {
        $crate::shader_struct!(@impl $ty, $name, ::core::option::Option::None, $($field: $field_ty),+);
    };
    (@impl $ty:ty, $name:literal, $layout:expr, $($field:ident: $field_ty:ty),+) => {
        impl $crate::Value for $ty {
            const TYPE: $crate::ShaderType = {
                const STRUCT: $crate::StructType = $crate::StructType {
                    name: $name,
                    rust_name: stringify!($ty),
                    fields: &[$((stringify!($field), <$field_ty as $crate::Value>::TYPE)),+],
                    rust_layout: $layout,
                };
                $crate::ShaderType::Struct(&STRUCT)
            };
            fn write(&self, words: &mut ::std::vec::Vec<u32>) {
                $(<$field_ty as $crate::Value>::write(&self.$field, words);)+
            }
            fn read(words: &mut &[u32]) -> Self {
                Self { $($field: <$field_ty as $crate::Value>::read(words),)+ }
            }
            fn components(&self, out: &mut ::std::vec::Vec<f32>) {
                $(<$field_ty as $crate::Value>::components(&self.$field, out);)+
            }
            fn is_finite(&self) -> bool {
                true $(&& <$field_ty as $crate::Value>::is_finite(&self.$field))+
            }
        }
    };
}

/// The argument list of a shader function: a tuple of [`Value`]s.
pub trait Args: Clone + Debug + Send + Sync + 'static {
    /// The shader-side parameter types, in order.
    const TYPES: &'static [ShaderType];
    /// Appends every argument's words.
    fn write(&self, words: &mut Vec<u32>);
    /// Reads the arguments back from their words, advancing `words`.
    fn read(words: &mut &[u32]) -> Self;
    /// Whether every float in every argument is finite.
    fn is_finite(&self) -> bool;
}

macro_rules! args_tuple {
    ($($name:ident),+) => {
        impl<$($name: Value),+> Args for ($($name,)+) {
            const TYPES: &'static [ShaderType] = &[$($name::TYPE),+];
            #[allow(non_snake_case)]
            fn write(&self, words: &mut Vec<u32>) {
                let ($($name,)+) = self;
                $($name.write(words);)+
            }
            fn read(words: &mut &[u32]) -> Self {
                ($($name::read(words),)+)
            }
            #[allow(non_snake_case)]
            fn is_finite(&self) -> bool {
                let ($($name,)+) = self;
                true $(&& $name.is_finite())+
            }
        }
    };
}

/// Invokes `$tuple_impl!` once per tuple size that [`Args`] is implemented for (1 to 10), with that
/// many type-parameter names (`A`, then `A, B`, ...): a trait implemented for argument tuples
/// covers the same sizes as [`Args`].
#[macro_export]
macro_rules! for_each_args_tuple {
    ($tuple_impl:ident) => {
        $tuple_impl!(A);
        $tuple_impl!(A, B);
        $tuple_impl!(A, B, C);
        $tuple_impl!(A, B, C, D);
        $tuple_impl!(A, B, C, D, E);
        $tuple_impl!(A, B, C, D, E, F);
        $tuple_impl!(A, B, C, D, E, F, G);
        $tuple_impl!(A, B, C, D, E, F, G, H);
        $tuple_impl!(A, B, C, D, E, F, G, H, I);
        $tuple_impl!(A, B, C, D, E, F, G, H, I, J);
    };
}

for_each_args_tuple!(args_tuple);
