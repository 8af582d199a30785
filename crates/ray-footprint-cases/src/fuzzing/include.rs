//! `include`: arbitrary names through [`resolve_glsl_include`].
//!
//! A name resolves only when it is exactly `<stem>.glsl` of one of the crate's modules (so never
//! through `..`, an absolute path, a separator or a symlink: the resolver reads no file), and then
//! to `ray_footprint/<stem>.glsl` and that module's embedded source. Every other name is an error
//! carrying the name as requested, quoted in its message.

use ray_footprint::shaders::{resolve_glsl_include, Module};

/// The `include` target: the bytes as a name (invalid UTF-8 replaced).
pub fn include(data: &[u8]) -> Result<(), String> {
    check_include(&String::from_utf8_lossy(data))
}

/// The properties of [`resolve_glsl_include`] for one request.
pub fn check_include(requested: &str) -> Result<(), String> {
    let expected = Module::ALL
        .iter()
        .find(|module| requested == format!("{}.glsl", module.stem()));
    match (resolve_glsl_include(requested), expected) {
        (Ok((name, source)), Some(module)) => {
            let name_ok = name == format!("ray_footprint/{}.glsl", module.stem());
            if name_ok && source == module.glsl() {
                Ok(())
            } else {
                Err(format!(
                    "{requested:?} resolved to {name:?} with a source that is not its module's"
                ))
            }
        }
        (Ok((name, _)), None) => Err(format!("{requested:?} resolved to {name:?}; it names no module")),
        (Err(error), Some(_)) => Err(format!("the module {requested:?} did not resolve: {error}")),
        (Err(error), None) => {
            let quoted = format!("{requested:?}");
            if error.requested == requested && error.to_string().contains(&quoted) {
                Ok(())
            } else {
                Err(format!("the error for {quoted} does not name it: {error}"))
            }
        }
    }
}
