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
//! # Ok::<(), naga_oil::compose::ComposerError>(())
//! ```

use crate::shaders::Module;
use naga_oil::compose::{ComposableModuleDescriptor, Composer, ComposerError, ShaderLanguage};

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

/// Registers `modules` with `composer` under their [`import_path`]s.
// The composer's own error type, passed through unchanged so callers can report it as usual.
#[allow(clippy::result_large_err)]
pub fn add_composable_modules(composer: &mut Composer, modules: &[Module]) -> Result<(), ComposerError> {
    for &module in modules {
        composer.add_composable_module(ComposableModuleDescriptor {
            source: module.wgsl(),
            file_path: &format!("ray_footprint/{}.wgsl", module.stem()),
            language: ShaderLanguage::Wgsl,
            as_name: Some(import_path(module)),
            ..Default::default()
        })?;
    }
    Ok(())
}
