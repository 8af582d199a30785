//! The shader modules as source text, and where they live on disk.
//!
//! Each concept is one WGSL module and one GLSL module with the same stem. The modules declare only
//! functions, structs and constants, all prefixed `rf_` / `Rf` / `RF_`, so they can be pasted in front
//! of a user's shader (WGSL) or `#include`d (GLSL, with `GL_GOOGLE_include_directive` and
//! [`GLSL_INCLUDE_DIR`] on the include path).
//!
//! A dependent's build script also finds the GLSL include directory in the environment variable
//! `DEP_RAY_FOOTPRINT_GLSL_INCLUDE`.

/// Directory holding the GLSL modules, for `glslangValidator -I` or a shaderc include callback.
pub const GLSL_INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/glsl");

/// Declares the modules: variant, stem, and the constants holding their sources.
macro_rules! modules {
    ($($(#[$doc:meta])* $variant:ident, $stem:literal, $wgsl:ident, $glsl:ident;)+) => {
        $(
            #[doc = concat!("WGSL source of `shaders/wgsl/", $stem, ".wgsl`.")]
            pub const $wgsl: &str = include_str!(concat!("../shaders/wgsl/", $stem, ".wgsl"));
            #[doc = concat!("GLSL source of `shaders/glsl/", $stem, ".glsl`.")]
            pub const $glsl: &str = include_str!(concat!("../shaders/glsl/", $stem, ".glsl"));
        )+

        /// A shader module of this crate.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Module {
            $($(#[$doc])* $variant,)+
        }

        impl Module {
            /// Every module.
            pub const ALL: &'static [Module] = &[$(Module::$variant),+];

            /// The file stem shared by the WGSL file, the GLSL file and the Rust module.
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
        }
    };
}

modules! {
    /// Ray cones: [`crate::ray_cone`].
    RayCone, "ray_cone", RAY_CONE_WGSL, RAY_CONE_GLSL;
    /// Ray differentials: [`crate::ray_diff`].
    RayDiff, "ray_diff", RAY_DIFF_WGSL, RAY_DIFF_GLSL;
    /// Ray differentials in double precision (needs shader f64): [`crate::ray_diff_f64`].
    RayDiffF64, "ray_diff_f64", RAY_DIFF_F64_WGSL, RAY_DIFF_F64_GLSL;
    /// Anti-aliased barycentric wireframe: [`crate::wireframe`].
    Wireframe, "wireframe", WIREFRAME_WGSL, WIREFRAME_GLSL;
}

impl Module {
    /// Whether the module uses 64-bit floats (naga `FLOAT64`, Vulkan `shaderFloat64`).
    pub fn needs_f64(self) -> bool {
        self.stem().ends_with("_f64")
    }
}
