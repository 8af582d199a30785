//! The shading languages a check runs in, each with its compiler: what a [`crate::Shader`] is
//! written in. Which back end writes, compiles and lays out a language's kernels is decided in
//! `back/mod.rs` (with [`Language::type_name`], which asks it).

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
        match self {
            Language::Wgsl => "WGSL",
            Language::Glsl => "GLSL",
            Language::Slang => "Slang",
            Language::HlslGlslang => "HLSL (glslang)",
            Language::HlslSlangc => "HLSL (slangc)",
        }
    }
}

impl fmt::Display for Language {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}
