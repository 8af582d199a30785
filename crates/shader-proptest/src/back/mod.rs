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
//! one [`Language`] per instance. Adding a back end is a file here, a variant of [`Language`]
//! (`language.rs`) and its arm in [`Language::backend`], and the language's shader files. The trait
//! and what the kernel writer hands it are `backend.rs`, the spelling as data `spelling.rs`; this
//! file chooses the back end of a [`Language`] and of a [`Shader`].

pub(crate) mod backend;
mod glsl;
mod hlsl;
mod slang;
pub(crate) mod spelling;
mod wgsl;

pub use backend::WORKGROUP_SIZE;
pub use glsl::glsl_layout;
pub use slang::slang_layout;
pub use wgsl::wgsl_layout;

use crate::compile::CompileError;
use crate::language::Language;
use crate::layout::{LayoutError, StructLayout};
use crate::shader::Shader;
use crate::value::ShaderType;
use backend::Backend;
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock, PoisonError};

impl Language {
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

impl Shader {
    /// The back end of the language.
    pub(crate) fn backend(&self) -> &'static dyn Backend {
        self.language().backend()
    }

    /// Compiles a whole compute shader written against this one (its source in front, as
    /// [`crate::kernel_source`] writes) to SPIR-V for Vulkan 1.1. A kernel this process compiled
    /// before, with the same language, capabilities and include directories, is not compiled again:
    /// running slangc costs about a second, and an echo or a shrinking run compiles the same
    /// kernel many times.
    pub fn compile_kernel(&self, kernel: &str) -> Result<Vec<u32>, CompileError> {
        static COMPILED: OnceLock<Mutex<HashMap<String, Vec<u32>>>> = OnceLock::new();
        let key = format!(
            "{:?} {:?} {:?}\n{kernel}",
            self.language(),
            self.naga_capabilities(),
            self.include_dirs()
        );
        let compiled = COMPILED.get_or_init(Mutex::default);
        if let Some(spirv) = compiled.lock().unwrap_or_else(PoisonError::into_inner).get(&key) {
            return Ok(spirv.clone());
        }
        let spirv = self.backend().compile_kernel(self, kernel)?;
        compiled
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .insert(key, spirv.clone());
        Ok(spirv)
    }

    /// The layout of the struct `name` this source declares, as a storage buffer holds it: naga's
    /// WGSL layout, or the element of a `std430` buffer compiled by glslang or slangc.
    pub fn struct_layout(&self, name: &str) -> Result<StructLayout, LayoutError> {
        self.backend().struct_layout(self, name)
    }
}
