//! naga_oil composable modules (feature `naga_oil`), for Bevy and other naga_oil users.
//!
//! Each WGSL module is registered under the import path `ray_footprint::<stem>`, so a shader
//! can `#import ray_footprint::ray_cone::{RfRayCone, rf_width_at}`. The composer needs the
//! capabilities of [`capabilities`] (Bevy enables them on adapters that have them).
//!
//! ```
//! use naga_oil::compose::{Composer, NagaModuleDescriptor};
//! use ray_footprint::shaders::Module;
//!
//! let mut composer = Composer::default().with_capabilities(ray_footprint::naga_oil::capabilities(&[Module::RayCone]));
//! ray_footprint::naga_oil::add_composable_modules(&mut composer, &[Module::RayCone])?;
//! let module = composer.make_naga_module(NagaModuleDescriptor {
//!     source: "#import ray_footprint::ray_cone::{RfRayCone, rf_width_at}
//!              @compute @workgroup_size(1) fn main() { _ = rf_width_at(RfRayCone(0.0, 0.001), 10.0); }",
//!     file_path: "lod.wgsl",
//!     ..Default::default()
//! })?;
//! assert!(module.functions.iter().any(|(_, f)| f.name.as_deref().is_some_and(|n| n.contains("rf_width_at"))));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A composer built without those capabilities accepts the modules but fails later, on the first
//! shader that uses them, with a message about an invalid header; [`add_composable_modules`]
//! refuses such a composer up front ([`RegisterError::MissingCapabilities`]).

use crate::shaders::Module;
use naga_oil::compose::{ComposableModuleDescriptor, Composer, ComposerError, ShaderLanguage};
use std::fmt;

/// The import path of a module: `ray_footprint::<stem>`.
pub fn import_path(module: Module) -> String {
    format!("ray_footprint::{}", module.stem())
}

/// The naga capabilities `modules` need together ([`Module::naga_capabilities`]).
pub fn capabilities(modules: &[Module]) -> naga::valid::Capabilities {
    modules
        .iter()
        .fold(naga::valid::Capabilities::empty(), |all, module| {
            all | module.naga_capabilities()
        })
}

/// Why [`add_composable_modules`] did not register a module.
#[derive(Debug)]
pub enum RegisterError {
    /// The composer lacks naga capabilities the module needs.
    MissingCapabilities {
        /// The module.
        module: Module,
        /// The capabilities it needs that the composer lacks.
        missing: naga::valid::Capabilities,
    },
    /// naga_oil rejected the module; render the error with `error.emit_to_string(&composer)`.
    Composer {
        /// The module.
        module: Module,
        /// naga_oil's error.
        error: Box<ComposerError>,
    },
}

impl fmt::Display for RegisterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RegisterError::MissingCapabilities { module, missing } => write!(
                f,
                "{}: the composer lacks the capabilities {missing:?}; build it with \
                 `Composer::default().with_capabilities(ray_footprint::naga_oil::capabilities(modules))`",
                import_path(*module)
            ),
            RegisterError::Composer { module, error } => write!(f, "{}: {error}", import_path(*module)),
        }
    }
}

impl std::error::Error for RegisterError {}

/// Registers `modules` with `composer` under their [`import_path`]s, after checking that the
/// composer has the [`capabilities`] each needs.
pub fn add_composable_modules(composer: &mut Composer, modules: &[Module]) -> Result<(), RegisterError> {
    for &module in modules {
        let missing = capabilities(&[module]).difference(composer.capabilities);
        if !missing.is_empty() {
            return Err(RegisterError::MissingCapabilities { module, missing });
        }
        composer
            .add_composable_module(ComposableModuleDescriptor {
                source: module.wgsl(),
                file_path: &format!("ray_footprint/{}.wgsl", module.stem()),
                language: ShaderLanguage::Wgsl,
                as_name: Some(import_path(module)),
                ..Default::default()
            })
            .map_err(|error| RegisterError::Composer {
                module,
                error: Box::new(error),
            })?;
    }
    Ok(())
}
