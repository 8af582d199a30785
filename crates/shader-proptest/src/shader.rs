//! Where the functions under test come from: a language, the source text in front of the generated
//! kernel, and what compiling and running it needs. Compiling a kernel and reading a struct's
//! layout ([`Shader::compile_kernel`], [`Shader::struct_layout`]) ask the language's back end, in
//! `back/mod.rs`.

use crate::compile::base_capabilities;
use crate::language::Language;
use std::path::{Path, PathBuf};

/// An optional device feature a shader or a program may need.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// 64-bit floats in shaders (`shaderFloat64`).
    ShaderFloat64,
    /// Anisotropic texture filtering (`samplerAnisotropy`).
    SamplerAnisotropy,
    /// Acceleration structures (`VK_KHR_acceleration_structure`, with buffer device addresses and
    /// deferred host operations).
    AccelerationStructure,
    /// Ray-tracing pipelines (`VK_KHR_ray_tracing_pipeline`).
    RayTracingPipeline,
    /// Ray queries in any shader stage (`VK_KHR_ray_query`).
    RayQuery,
}

impl Feature {
    /// The Vulkan name of the feature.
    pub fn name(self) -> &'static str {
        match self {
            Feature::ShaderFloat64 => "shaderFloat64",
            Feature::SamplerAnisotropy => "samplerAnisotropy",
            Feature::AccelerationStructure => "VK_KHR_acceleration_structure",
            Feature::RayTracingPipeline => "VK_KHR_ray_tracing_pipeline",
            Feature::RayQuery => "VK_KHR_ray_query",
        }
    }
}

/// The functions under test: a language and the source text placed in front of each generated
/// kernel (a WGSL module, GLSL such as `#include "colour.glsl"`, Slang such as `import colour;`, or
/// HLSL such as `#include "colour.hlsl"`), with the GLSL or HLSL include directories or Slang search
/// paths, the naga capabilities WGSL may use, and
/// the device features the code needs.
///
/// ```
/// use shader_proptest::Shader;
///
/// let wgsl = Shader::wgsl("fn luminance(c: vec3<f32>) -> f32 { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }");
/// let glsl = Shader::glsl("#include \"colour.glsl\"").include_dir("shaders/glsl");
/// let slang = Shader::slang("import colour;").include_dir("shaders/slang");
/// # let _ = (wgsl, glsl, slang);
/// ```
#[derive(Clone, Debug)]
pub struct Shader {
    language: Language,
    source: String,
    include_dirs: Vec<PathBuf>,
    capabilities: naga::valid::Capabilities,
    features: Vec<Feature>,
}

impl Shader {
    /// WGSL source declaring the functions, with [`base_capabilities`].
    pub fn wgsl(source: impl Into<String>) -> Shader {
        Shader::new(Language::Wgsl, source)
    }

    /// GLSL source declaring (or `#include`-ing) the functions; no `#version` and no `main`.
    pub fn glsl(source: impl Into<String>) -> Shader {
        Shader::new(Language::Glsl, source)
    }

    /// Slang source declaring the functions, or bringing them in (`import colour;`,
    /// `#include "colour.slang"`); no entry point. Functions of an imported module must be `public`.
    pub fn slang(source: impl Into<String>) -> Shader {
        Shader::new(Language::Slang, source)
    }

    /// Source in `language`: [`Shader::wgsl`], [`Shader::glsl`] or [`Shader::slang`] by a value,
    /// and the only way to HLSL (`Language::HlslGlslang`, `Language::HlslSlangc`: no entry point,
    /// functions and structs declared or `#include`d).
    pub fn new(language: Language, source: impl Into<String>) -> Shader {
        Shader {
            language,
            source: source.into(),
            include_dirs: Vec::new(),
            capabilities: base_capabilities(),
            features: Vec::new(),
        }
    }

    /// The same shader with `code` after its source (on a line of its own): a function of your
    /// own beside the functions a module's shader declares or brings in, such as a
    /// `ray_footprint` module's (`Module::RayCone.shader(language)`), for a check of it.
    ///
    /// ```
    /// use shader_proptest::Shader;
    ///
    /// let module = Shader::wgsl("fn double(x: f32) -> f32 { return 2.0 * x; }");
    /// let shader = module.with_source("fn quadruple(x: f32) -> f32 { return double(double(x)); }");
    /// assert!(shader.source().ends_with("\nfn quadruple(x: f32) -> f32 { return double(double(x)); }"));
    /// ```
    pub fn with_source(mut self, code: &str) -> Shader {
        self.source.push('\n');
        self.source.push_str(code);
        self
    }

    /// Adds a directory to the GLSL or HLSL include path, or to the Slang search path (`import`
    /// and `#include`).
    pub fn include_dir(mut self, dir: impl AsRef<Path>) -> Shader {
        self.include_dirs.push(dir.as_ref().to_path_buf());
        self
    }

    /// Allows these naga capabilities beyond [`base_capabilities`] (WGSL).
    pub fn capabilities(mut self, capabilities: naga::valid::Capabilities) -> Shader {
        self.capabilities |= capabilities;
        self
    }

    /// Declares that the code needs `feature` on the device: a check on a device without it is
    /// reported as not run, with the reason.
    pub fn requires(mut self, feature: Feature) -> Shader {
        if !self.features.contains(&feature) {
            self.features.push(feature);
        }
        self
    }

    /// The language.
    pub fn language(&self) -> Language {
        self.language
    }

    /// The naga capabilities WGSL may use.
    pub(crate) fn naga_capabilities(&self) -> naga::valid::Capabilities {
        self.capabilities
    }

    /// The source text placed in front of every kernel.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The GLSL or HLSL include directories or Slang search paths.
    pub fn include_dirs(&self) -> Vec<&Path> {
        self.include_dirs.iter().map(PathBuf::as_path).collect()
    }

    /// The device features the code needs.
    pub fn features(&self) -> &[Feature] {
        &self.features
    }
}
