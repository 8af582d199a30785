//! `compose`: arbitrary user shader text combined with the crate's WGSL modules.
//!
//! The first byte selects the modules (bit `i` for `Module::ALL[i]`), the rest is the user's text
//! (invalid UTF-8 replaced). The text goes, after [`wgsl_prelude`] of the selected modules, through
//! naga's WGSL front end and validator (with the capabilities the modules need); with the `naga_oil`
//! feature it also goes to a naga_oil composer holding the modules
//! ([`crate::naga_oil::add_composable_modules`]) as the top-level shader. Properties: no panic, errors
//! are returned (and render as text); the modules alone (empty or blank text) always validate and
//! always register with the composer. Without naga (default features) only the prelude is built.

use crate::shaders::{wgsl_prelude, Module};

/// The `compose` target.
pub fn compose(data: &[u8]) -> Result<(), String> {
    let (selector, text) = data.split_first().unwrap_or((&0, &[]));
    let modules: Vec<Module> = Module::ALL
        .iter()
        .enumerate()
        .filter(|(index, _)| selector & (1 << index) != 0)
        .map(|(_, &module)| module)
        .collect();
    let text = String::from_utf8_lossy(text);
    let prelude = wgsl_prelude(&modules);
    if modules.iter().any(|module| !prelude.contains(module.wgsl())) {
        return Err(format!("the prelude of {modules:?} lacks a module"));
    }
    // Without naga there is nothing to parse the text with.
    #[cfg(not(any(feature = "validate", feature = "naga_oil")))]
    let _ = text;
    #[cfg(any(feature = "validate", feature = "naga_oil"))]
    naga_check::with_prelude(&prelude, &text, &modules)?;
    #[cfg(feature = "naga_oil")]
    naga_check::with_composer(&text, &modules)?;
    Ok(())
}

#[cfg(any(feature = "validate", feature = "naga_oil"))]
mod naga_check {
    use crate::shaders::Module;

    fn capabilities(modules: &[Module]) -> naga::valid::Capabilities {
        let mut capabilities = naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32;
        if modules.iter().any(|module| module.needs_f64()) {
            capabilities |= naga::valid::Capabilities::FLOAT64;
        }
        capabilities
    }

    /// Parses and validates `prelude + text`; an error is fine unless `text` is blank.
    pub fn with_prelude(prelude: &str, text: &str, modules: &[Module]) -> Result<(), String> {
        let source = format!("{prelude}{text}");
        let outcome = naga::front::wgsl::parse_str(&source)
            .map_err(|error| error.emit_to_string_with_path(&source, "user.wgsl"))
            .and_then(|module| {
                naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities(modules))
                    .validate(&module)
                    .map(drop)
                    .map_err(|error| error.emit_to_string_with_path(&source, "user.wgsl"))
            });
        match outcome {
            Err(message) if text.trim().is_empty() => {
                Err(format!("the modules {modules:?} alone fail: {message}"))
            }
            _ => Ok(()),
        }
    }

    /// Composes `text` against the naga_oil modules; an error is fine, but the modules must register.
    ///
    /// The composer holding a module set is built once per set and thread, and reused: naga_oil only
    /// caches the compiled imports in it, and building it anew for every input ran about three
    /// inputs per second under the fuzzer's sanitizer.
    #[cfg(feature = "naga_oil")]
    pub fn with_composer(text: &str, modules: &[Module]) -> Result<(), String> {
        use naga_oil::compose::{Composer, NagaModuleDescriptor};
        use std::collections::HashMap;
        thread_local! {
            static COMPOSERS: std::cell::RefCell<HashMap<Vec<Module>, Composer>> = Default::default();
        }
        COMPOSERS.with_borrow_mut(|composers| {
            let composer = match composers.entry(modules.to_vec()) {
                std::collections::hash_map::Entry::Occupied(entry) => entry.into_mut(),
                std::collections::hash_map::Entry::Vacant(entry) => {
                    let mut composer =
                        Composer::default().with_capabilities(crate::naga_oil::capabilities(modules));
                    crate::naga_oil::add_composable_modules(&mut composer, modules).map_err(|error| {
                        format!("registering {modules:?}: {}", error.emit_to_string(&composer))
                    })?;
                    entry.insert(composer)
                }
            };
            let composed = composer.make_naga_module(NagaModuleDescriptor {
                source: text,
                file_path: "user.wgsl",
                ..Default::default()
            });
            if let Err(error) = composed {
                let _message = error.emit_to_string(composer);
            }
            Ok(())
        })
    }
}
