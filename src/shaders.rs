//! The shader modules as source text, and the ways to include them in your shaders.
//!
//! Each concept is one WGSL module, one GLSL module, one Slang module and one HLSL module with the
//! same stem. The modules declare only
//! functions, structs and constants, all prefixed `rf_` / `Rf` / `RF_`, and none depends on another,
//! so any set of them can be combined with each other and with your code.
//!
//! - WGSL, pasted in front of your shader: [`wgsl_prelude`].
//! - GLSL with glslang: `#include "ray_cone.glsl"` with [`GLSL_INCLUDE_DIR`] on the include path
//!   (`glslangValidator -I...`); a dependent's build script finds the same directory in the
//!   environment variable `DEP_RAY_FOOTPRINT_GLSL_INCLUDE`.
//! - GLSL with shaderc: [`resolve_glsl_include`] as the include callback.
//! - naga_oil (Bevy): `ray_footprint::naga_oil::add_composable_modules` (feature `naga_oil`).
//! - Slang: `import ray_cone;` or `#include "ray_cone.slang"` with [`SLANG_INCLUDE_DIR`] on the
//!   search path (`slangc -I...`); a dependent's build script finds the same directory in the
//!   environment variable `DEP_RAY_FOOTPRINT_SLANG_INCLUDE`.
//! - HLSL (2021, for DXC, glslang's HLSL front end or slangc): `#include "ray_cone.hlsl"` with
//!   [`HLSL_INCLUDE_DIR`] on the include path (`dxc -I...`, `glslangValidator -D -I...`,
//!   `slangc -I...`); a dependent's build script finds the same directory in the environment
//!   variable `DEP_RAY_FOOTPRINT_HLSL_INCLUDE`.
//!
//! ```
//! use ray_footprint::shaders::{wgsl_prelude, Module};
//!
//! let my_shader = "fn lod_at(t: f32) -> f32 { return rf_width_at(RfRayCone(0.0, 0.001), t); }";
//! let source = format!("{}{}", wgsl_prelude(&[Module::RayCone]), my_shader);
//! assert!(source.contains("fn rf_width_at"));
//! ```

/// Directory holding the GLSL modules, for `glslangValidator -I` or a shaderc include callback.
pub const GLSL_INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/glsl");

/// Directory holding the Slang modules, for `slangc -I` or a Slang session's search paths.
pub const SLANG_INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/slang");

/// Directory holding the HLSL modules, for `dxc -I`, `glslangValidator -D -I` or `slangc -I`.
pub const HLSL_INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/hlsl");

/// Declares the modules: variant, stem, and the constants holding their sources.
macro_rules! modules {
    ($($(#[$doc:meta])* $variant:ident, $stem:literal, $wgsl:ident, $glsl:ident, $slang:ident, $hlsl:ident;)+) => {
        $(
            #[doc = concat!("WGSL source of `shaders/wgsl/", $stem, ".wgsl`.")]
            pub const $wgsl: &str = include_str!(concat!("../shaders/wgsl/", $stem, ".wgsl"));
            #[doc = concat!("GLSL source of `shaders/glsl/", $stem, ".glsl`.")]
            pub const $glsl: &str = include_str!(concat!("../shaders/glsl/", $stem, ".glsl"));
            #[doc = concat!("Slang source of `shaders/slang/", $stem, ".slang`.")]
            pub const $slang: &str = include_str!(concat!("../shaders/slang/", $stem, ".slang"));
            #[doc = concat!("HLSL source of `shaders/hlsl/", $stem, ".hlsl`.")]
            pub const $hlsl: &str = include_str!(concat!("../shaders/hlsl/", $stem, ".hlsl"));
        )+

        /// A shader module of this crate.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Module {
            $($(#[$doc])* $variant,)+
        }

        impl Module {
            /// Every module.
            pub const ALL: &'static [Module] = &[$(Module::$variant),+];

            /// The file stem shared by the WGSL, GLSL, Slang and HLSL files and the Rust module.
            pub fn stem(self) -> &'static str {
                match self {
                    $(Module::$variant => $stem,)+
                }
            }

            /// The WGSL source.
            pub fn wgsl(self) -> &'static str {
                match self {
                    $(Module::$variant => $wgsl,)+
                }
            }

            /// The GLSL source.
            pub fn glsl(self) -> &'static str {
                match self {
                    $(Module::$variant => $glsl,)+
                }
            }

            /// The Slang source.
            pub fn slang(self) -> &'static str {
                match self {
                    $(Module::$variant => $slang,)+
                }
            }

            /// The HLSL source.
            pub fn hlsl(self) -> &'static str {
                match self {
                    $(Module::$variant => $hlsl,)+
                }
            }

            /// The source of the Rust mirror module `src/<stem>.rs`.
            fn mirror_source(self) -> &'static str {
                match self {
                    $(Module::$variant => include_str!(concat!($stem, ".rs")),)+
                }
            }
        }
    };
}

modules! {
    /// Ray cones: [`crate::ray_cone`].
    RayCone, "ray_cone", RAY_CONE_WGSL, RAY_CONE_GLSL, RAY_CONE_SLANG, RAY_CONE_HLSL;
    /// Ray differentials: [`crate::ray_diff`].
    RayDiff, "ray_diff", RAY_DIFF_WGSL, RAY_DIFF_GLSL, RAY_DIFF_SLANG, RAY_DIFF_HLSL;
    /// Ray differentials in double precision (needs shader f64): [`crate::ray_diff_f64`].
    RayDiffF64, "ray_diff_f64", RAY_DIFF_F64_WGSL, RAY_DIFF_F64_GLSL, RAY_DIFF_F64_SLANG, RAY_DIFF_F64_HLSL;
    /// Anti-aliased barycentric wireframe: [`crate::wireframe`].
    Wireframe, "wireframe", WIREFRAME_WGSL, WIREFRAME_GLSL, WIREFRAME_SLANG, WIREFRAME_HLSL;
}

impl Module {
    /// The module's functions, in the module's order: the public functions of the Rust mirror
    /// (each shader module declares them, prefixed `rf_`, in the same order, along with helper
    /// functions the Rust mirror keeps private).
    ///
    /// # Examples
    ///
    /// ```
    /// use ray_footprint::shaders::Module;
    ///
    /// // The WGSL module declares each function, prefixed rf_, in the same order.
    /// let functions = Module::Wireframe.functions();
    /// assert_eq!(functions[0], "unpack_wireframe_settings");
    /// let wgsl = Module::Wireframe.wgsl();
    /// let positions: Vec<usize> = functions
    ///     .iter()
    ///     .map(|name| wgsl.find(&format!("fn rf_{name}(")).expect("declared in WGSL"))
    ///     .collect();
    /// assert!(positions.windows(2).all(|pair| pair[0] < pair[1]));
    /// ```
    pub fn functions(self) -> Vec<&'static str> {
        self.mirror_source()
            .lines()
            .filter_map(|line| line.strip_prefix("pub fn "))
            .filter_map(|rest| rest.split(['(', '<']).next())
            .collect()
    }

    /// Whether the module uses 64-bit floats (naga `FLOAT64`, Vulkan `shaderFloat64`).
    ///
    /// # Examples
    ///
    /// ```
    /// use ray_footprint::shaders::Module;
    ///
    /// // Only the double-precision module declares f64 values in its WGSL.
    /// for module in Module::ALL {
    ///     assert_eq!(module.needs_f64(), module.wgsl().contains("f64"), "{module:?}");
    /// }
    /// ```
    pub fn needs_f64(self) -> bool {
        self.stem().ends_with("_f64")
    }

    /// The naga capabilities the WGSL module needs beyond naga's defaults: `pack2x16float` and
    /// `unpack2x16float` (naga's `SHADER_FLOAT16_IN_FLOAT32`, wgpu's downlevel flag
    /// `SHADER_F16_IN_F32`, on every Vulkan, Metal and DX12 adapter), plus `FLOAT64` for the `_f64`
    /// modules. Every place that validates or composes the modules asks this.
    #[cfg(any(feature = "validate", feature = "naga_oil", feature = "shader-proptest"))]
    pub fn naga_capabilities(self) -> naga::valid::Capabilities {
        let capabilities = naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32;
        if self.needs_f64() {
            capabilities | naga::valid::Capabilities::FLOAT64
        } else {
            capabilities
        }
    }

    /// The module as a `shader_proptest::Shader` in `language` (feature `shader-proptest`): the
    /// WGSL module text with its naga capabilities, `#include "<stem>.glsl"` with
    /// [`GLSL_INCLUDE_DIR`] on the include path, `import <stem>;` with [`SLANG_INCLUDE_DIR`] on
    /// the search path, or for either HLSL compiler `#include "<stem>.hlsl"` with
    /// [`HLSL_INCLUDE_DIR`] on the include path; the `_f64` modules require `shaderFloat64`. Check your own functions that
    /// use the module by appending them to its source.
    #[cfg(feature = "shader-proptest")]
    pub fn shader(self, language: shader_proptest::Language) -> shader_proptest::Shader {
        use shader_proptest::{Feature, Language, Shader};
        let shader = match language {
            Language::Wgsl => Shader::wgsl(self.wgsl()).capabilities(self.naga_capabilities()),
            Language::Glsl => {
                Shader::glsl(format!("#include \"{}.glsl\"", self.stem())).include_dir(GLSL_INCLUDE_DIR)
            }
            Language::Slang => {
                Shader::slang(format!("import {};", self.stem())).include_dir(SLANG_INCLUDE_DIR)
            }
            Language::HlslGlslang | Language::HlslSlangc => {
                Shader::new(language, format!("#include \"{}.hlsl\"", self.stem()))
                    .include_dir(HLSL_INCLUDE_DIR)
            }
        };
        if self.needs_f64() {
            shader.requires(Feature::ShaderFloat64)
        } else {
            shader
        }
    }
}

/// The WGSL sources of `modules`, each once, in the order of [`Module::ALL`], ready to be
/// pasted in front of a shader. The modules do not depend on one another, so this is every
/// module the listed ones need.
///
/// # Examples
///
/// ```
/// use ray_footprint::shaders::{wgsl_prelude, Module};
///
/// // Asked in any order and with repeats, each module comes once, in the order of Module::ALL.
/// let prelude = wgsl_prelude(&[Module::Wireframe, Module::RayCone, Module::Wireframe]);
/// assert_eq!(prelude, format!("{}\n{}\n", Module::RayCone.wgsl(), Module::Wireframe.wgsl()));
/// ```
pub fn wgsl_prelude(modules: &[Module]) -> String {
    Module::ALL
        .iter()
        .filter(|module| modules.contains(module))
        .map(|module| format!("{}\n", module.wgsl()))
        .collect()
}

/// An `#include` this crate does not serve.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IncludeError {
    /// The name that was asked for.
    pub requested: String,
}

impl std::fmt::Display for IncludeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "ray-footprint has no GLSL module named {:?}; available: ",
            self.requested
        )?;
        let names: Vec<String> = Module::ALL
            .iter()
            .map(|module| format!("{}.glsl", module.stem()))
            .collect();
        write!(f, "{}", names.join(", "))
    }
}

impl std::error::Error for IncludeError {}

/// Resolves a GLSL `#include` of one of this crate's modules by its file name (`"ray_cone.glsl"`)
/// to `(resolved name, source)`, for a shaderc include callback or any other resolver.
///
/// Only the exact file names of the modules resolve, from sources embedded in the crate: the file
/// system is never read, so no request (`..`, absolute paths, symlinks) can reach anything else.
///
/// ```
/// use ray_footprint::shaders::resolve_glsl_include;
///
/// let (name, source) = resolve_glsl_include("ray_cone.glsl")?;
/// assert_eq!(name, "ray_footprint/ray_cone.glsl");
/// assert!(source.contains("rf_width_at"));
/// assert!(resolve_glsl_include("../Cargo.toml").is_err());
/// # Ok::<(), ray_footprint::shaders::IncludeError>(())
/// ```
pub fn resolve_glsl_include(requested: &str) -> Result<(String, &'static str), IncludeError> {
    Module::ALL
        .iter()
        .find(|module| requested.strip_suffix(".glsl") == Some(module.stem()))
        .map(|module| (format!("ray_footprint/{}.glsl", module.stem()), module.glsl()))
        .ok_or_else(|| IncludeError {
            requested: requested.to_string(),
        })
}
