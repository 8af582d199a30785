//! Values that travel between the Rust mirror and a generated kernel as raw 32-bit words.
//!
//! Every value is written as words (floats by their bit pattern), read by the kernel field by field,
//! passed to the shader function, and the result is written back as words: nothing is converted, so
//! the comparison sees exactly what the shader computed. Outputs are compared as `f32` components,
//! which is exact for floats, booleans and integers below 2^24.

use crate::ray_cone::{PackedRayCone, RayCone};
use glam::{Mat4, Vec2, Vec3, Vec4};
use std::fmt::Debug;

/// A shader-side type, with enough information to load and store it in WGSL and GLSL.
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
    /// `mat4x4<f32>` / `mat4`, column-major.
    Mat4,
    /// A struct declared by a module under the same name in WGSL and GLSL.
    Struct(&'static StructType),
}

/// A struct declared by a shader module: its name and its fields in declaration order.
#[derive(Debug, PartialEq, Eq)]
pub struct StructType {
    /// The struct's name in both shader languages.
    pub name: &'static str,
    /// Field names and types, in declaration order.
    pub fields: &'static [(&'static str, ShaderType)],
}

/// The ray cone as the shaders declare it.
pub const RAY_CONE: StructType = StructType {
    name: "RfRayCone",
    fields: &[("width", ShaderType::F32), ("spread_angle", ShaderType::F32)],
};

/// The hit payload as the shaders declare it.
pub const HIT_PAYLOAD: StructType = StructType {
    name: "RfHitPayload",
    fields: &[
        ("colour", ShaderType::Vec3),
        ("weight", ShaderType::F32),
        ("cone", ShaderType::Struct(&RAY_CONE)),
        ("depth", ShaderType::U32),
        ("pad", ShaderType::U32),
    ],
};

/// The ray-cone push constants as the shaders declare them.
pub const RAY_CONE_PUSH_CONSTANTS: StructType = StructType {
    name: "RfRayConePushConstants",
    fields: &[
        ("tex_grad_scale", ShaderType::F32),
        ("pixel_spread_angle", ShaderType::F32),
    ],
};

impl ShaderType {
    /// How many 32-bit words the value takes.
    pub fn words(self) -> usize {
        match self {
            ShaderType::F32 | ShaderType::U32 | ShaderType::I32 | ShaderType::Bool => 1,
            ShaderType::Vec2 => 2,
            ShaderType::Vec3 => 3,
            ShaderType::Vec4 => 4,
            ShaderType::Mat4 => 16,
            ShaderType::Struct(s) => s.fields.iter().map(|(_, ty)| ty.words()).sum(),
        }
    }
}

/// A Rust value with a shader twin of type [`GpuValue::TYPE`].
pub trait GpuValue: Copy + Debug {
    /// The shader-side type.
    const TYPE: ShaderType;
    /// Appends the value's words.
    fn write(&self, words: &mut Vec<u32>);
    /// Reads the value from the front of `words` and advances past it.
    fn read(words: &mut &[u32]) -> Self;
    /// The numbers compared between the mirror and the shader, in a fixed order.
    fn components(&self, out: &mut Vec<f32>);
    /// Whether every float in the value is finite.
    fn is_finite(&self) -> bool;
}

/// Removes and returns the first word (a kernel's output always has the expected length).
pub(crate) fn take(words: &mut &[u32]) -> u32 {
    let (first, rest) = words
        .split_first()
        .expect("kernel output has the expected length");
    *words = rest;
    *first
}

impl GpuValue for f32 {
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

impl GpuValue for u32 {
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

impl GpuValue for i32 {
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

impl GpuValue for bool {
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

/// Implements [`GpuValue`] for a type made of `f32` fields, listed in shader order:
/// `float_value!(Type, shader_type, |v| [v.a, v.b], |w| Type { a: w(), b: w() })`.
macro_rules! float_value {
    ($rust:ty, $shader:expr, |$v:ident| [$($field:expr),+], |$w:ident| $build:expr) => {
        impl GpuValue for $rust {
            const TYPE: ShaderType = $shader;
            fn write(&self, words: &mut Vec<u32>) {
                let $v = self;
                words.extend([$($field.to_bits()),+]);
            }
            fn read(words: &mut &[u32]) -> Self {
                let mut $w = || f32::from_bits($crate::gpu::value::take(words));
                $build
            }
            fn components(&self, out: &mut Vec<f32>) {
                let $v = self;
                out.extend([$($field),+]);
            }
            fn is_finite(&self) -> bool {
                let $v = self;
                [$($field),+].iter().all(|x| x.is_finite())
            }
        }
    };
}

pub(crate) use float_value;

float_value!(Vec2, ShaderType::Vec2, |v| [v.x, v.y], |w| Vec2::new(w(), w()));
float_value!(Vec3, ShaderType::Vec3, |v| [v.x, v.y, v.z], |w| Vec3::new(
    w(),
    w(),
    w()
));
float_value!(Vec4, ShaderType::Vec4, |v| [v.x, v.y, v.z, v.w], |w| Vec4::new(
    w(),
    w(),
    w(),
    w()
));
float_value!(
    RayCone,
    ShaderType::Struct(&RAY_CONE),
    |v| [v.width, v.spread_angle],
    |w| RayCone {
        width: w(),
        spread_angle: w()
    }
);

impl GpuValue for Mat4 {
    const TYPE: ShaderType = ShaderType::Mat4;
    fn write(&self, words: &mut Vec<u32>) {
        words.extend(self.to_cols_array().map(f32::to_bits));
    }
    fn read(words: &mut &[u32]) -> Self {
        Mat4::from_cols_array(&std::array::from_fn(|_| f32::from_bits(take(words))))
    }
    fn components(&self, out: &mut Vec<f32>) {
        out.extend(self.to_cols_array());
    }
    fn is_finite(&self) -> bool {
        Mat4::is_finite(self)
    }
}

/// The packed cone travels as a `u32`; it is compared by its two unpacked halves, because the
/// rounding mode of `packHalf2x16` is left to the implementation.
impl GpuValue for PackedRayCone {
    const TYPE: ShaderType = ShaderType::U32;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(self.0);
    }
    fn read(words: &mut &[u32]) -> Self {
        PackedRayCone(take(words))
    }
    fn components(&self, out: &mut Vec<f32>) {
        crate::ray_cone::unpack_ray_cone(*self).components(out);
    }
    fn is_finite(&self) -> bool {
        true
    }
}

/// The argument list of a shader function: a tuple of [`GpuValue`]s.
pub trait GpuArgs: Clone + Debug {
    /// The shader-side parameter types, in order.
    const TYPES: &'static [ShaderType];
    /// Appends every argument's words.
    fn write(&self, words: &mut Vec<u32>);
    /// Whether every float in every argument is finite.
    fn is_finite(&self) -> bool;
}

macro_rules! args_tuple {
    ($($name:ident),+) => {
        impl<$($name: GpuValue),+> GpuArgs for ($($name,)+) {
            const TYPES: &'static [ShaderType] = &[$($name::TYPE),+];
            #[allow(non_snake_case)]
            fn write(&self, words: &mut Vec<u32>) {
                let ($($name,)+) = self;
                $($name.write(words);)+
            }
            #[allow(non_snake_case)]
            fn is_finite(&self) -> bool {
                let ($($name,)+) = self;
                true $(&& $name.is_finite())+
            }
        }
    };
}

args_tuple!(A);
args_tuple!(A, B);
args_tuple!(A, B, C);
args_tuple!(A, B, C, D);
args_tuple!(A, B, C, D, E);
args_tuple!(A, B, C, D, E, F);
args_tuple!(A, B, C, D, E, F, G);
args_tuple!(A, B, C, D, E, F, G, H);
