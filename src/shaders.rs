//! The shader modules as source text, and where they live on disk.
//!
//! Each concept is one WGSL module and one GLSL module with the same stem. The modules declare only
//! functions, structs and constants, all prefixed `rf_` / `Rf` / `RF_`, so they can be pasted in front
//! of a user's shader (WGSL) or `#include`d (GLSL, with `GL_GOOGLE_include_directive` and
//! [`GLSL_INCLUDE_DIR`] on the include path).
//!
//! A dependent's build script also finds the GLSL include directory in the environment variable
//! `DEP_RAY_FOOTPRINT_GLSL_INCLUDE`.

/// WGSL source of the ray-cone module (`shaders/wgsl/ray_cone.wgsl`).
pub const RAY_CONE_WGSL: &str = include_str!("../shaders/wgsl/ray_cone.wgsl");
/// GLSL source of the ray-cone module (`shaders/glsl/ray_cone.glsl`).
pub const RAY_CONE_GLSL: &str = include_str!("../shaders/glsl/ray_cone.glsl");

/// Directory holding the GLSL modules, for `glslangValidator -I` or a shaderc include callback.
pub const GLSL_INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/glsl");

/// A shader module of this crate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Module {
    /// Ray cones: `ray_cone.wgsl`, `ray_cone.glsl`, [`crate::ray_cone`].
    RayCone,
}

impl Module {
    /// Every module, in dependency order.
    pub const ALL: [Module; 1] = [Module::RayCone];

    /// The file stem shared by the WGSL file, the GLSL file and the Rust module.
    pub fn stem(self) -> &'static str {
        match self {
            Module::RayCone => "ray_cone",
        }
    }

    /// The WGSL source.
    pub fn wgsl(self) -> &'static str {
        match self {
            Module::RayCone => RAY_CONE_WGSL,
        }
    }

    /// The GLSL source.
    pub fn glsl(self) -> &'static str {
        match self {
            Module::RayCone => RAY_CONE_GLSL,
        }
    }
}
