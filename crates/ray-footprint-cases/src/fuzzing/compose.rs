//! `compose`: arbitrary user shader text combined with ray-footprint's WGSL modules.
//!
//! The first byte selects the modules (bit `i` for `Module::ALL[i]`), the rest is the user's text
//! (invalid UTF-8 replaced). Properties:
//!
//! - The module set: [`wgsl_prelude`] holds every selected module, the prelude alone parses and
//!   validates with naga (with the capabilities the modules need), and the modules register with a
//!   naga_oil composer ([`ray_footprint::naga_oil::add_composable_modules`]).
//! - The text after the prelude goes through naga's WGSL front end and validator, and to the
//!   composer as the top-level shader: no panic, errors are returned (and render as text).
//!
//! # Work per input
//!
//! Nothing about a module set depends on the text, so each set is checked once per thread and kept
//! with the names its modules declare and its composer; an input then costs only the work its text
//! needs. The text is parsed after the prelude of the selected modules it can interact with: those
//! declaring a name the text spells (every ASCII run of letters, digits and `_` in the text is
//! compared with the names), and all selected modules when the text spells `enable`, `requires` or
//! `diagnostic` (directives, which must come before every declaration). A module the text never
//! names cannot change how naga reads it: naga parses without resolving names and then resolves the
//! text's identifiers by name, and the modules declare only functions, structs and constants. The
//! source naga sees then differs from the full prelude only in the declarations it leaves out (and
//! so in the numbering of naga's arenas). Parsing the selected modules' WGSL (up to 43 KB) for
//! every input was nearly all of the target's time; now a text pays only for the modules it names.

use ray_footprint::shaders::{wgsl_prelude, Module};

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
    naga_check::check(&text, &modules)
}

/// The prelude of `modules`, checked to hold each of them.
fn full_prelude(modules: &[Module]) -> Result<String, String> {
    let prelude = wgsl_prelude(modules);
    if modules.iter().any(|module| !prelude.contains(module.wgsl())) {
        return Err(format!("the prelude of {modules:?} lacks a module"));
    }
    Ok(prelude)
}

/// Every ASCII run of letters, digits and `_` in `text`: a superset of the identifiers naga reads
/// there that are spelled in ASCII.
fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|word| !word.is_empty())
}

/// The names `module` declares at module scope, as naga reads them: functions, named types,
/// constants, global variables and overrides.
pub fn declared_names(module: Module) -> Result<std::collections::HashSet<String>, String> {
    let parsed = naga::front::wgsl::parse_str(module.wgsl())
        .map_err(|error| format!("{module:?}: {}", error.emit_to_string(module.wgsl())))?;
    let functions = parsed.functions.iter().map(|(_, f)| &f.name);
    let types = parsed.types.iter().map(|(_, t)| &t.name);
    let constants = parsed.constants.iter().map(|(_, c)| &c.name);
    let globals = parsed.global_variables.iter().map(|(_, g)| &g.name);
    let overrides = parsed.overrides.iter().map(|(_, o)| &o.name);
    Ok(functions
        .chain(types)
        .chain(constants)
        .chain(globals)
        .chain(overrides)
        .flatten()
        .cloned()
        .collect())
}

mod naga_check {
    use super::{declared_names, full_prelude, words};
    use ray_footprint::shaders::{wgsl_prelude, Module};
    use std::collections::{HashMap, HashSet};

    /// Words that begin a directive, which must precede every declaration.
    const DIRECTIVES: [&str; 3] = ["enable", "requires", "diagnostic"];

    /// A checked module set: its modules with the names each declares, and its composer.
    struct ModuleSet {
        names: Vec<(Module, HashSet<String>)>,
        capabilities: naga::valid::Capabilities,
        composer: naga_oil::compose::Composer,
    }

    /// The capabilities `modules` need together ([`Module::naga_capabilities`]).
    fn capabilities(modules: &[Module]) -> naga::valid::Capabilities {
        modules
            .iter()
            .fold(naga::valid::Capabilities::empty(), |all, module| {
                all | module.naga_capabilities()
            })
    }

    /// Parses and validates `source` with naga; the error is rendered as text.
    fn parse_and_validate(source: &str, capabilities: naga::valid::Capabilities) -> Result<(), String> {
        let module = naga::front::wgsl::parse_str(source)
            .map_err(|error| error.emit_to_string_with_path(source, "user.wgsl"))?;
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
            .validate(&module)
            .map(drop)
            .map_err(|error| error.emit_to_string_with_path(source, "user.wgsl"))
    }

    impl ModuleSet {
        /// Checks the set's prelude alone and registers the modules with a composer.
        fn new(modules: &[Module]) -> Result<ModuleSet, String> {
            let capabilities = capabilities(modules);
            parse_and_validate(&full_prelude(modules)?, capabilities)
                .map_err(|message| format!("the modules {modules:?} alone fail: {message}"))?;
            let names = modules
                .iter()
                .map(|&module| declared_names(module).map(|names| (module, names)))
                .collect::<Result<_, _>>()?;
            Ok(ModuleSet {
                names,
                capabilities,
                composer: composer(modules)?,
            })
        }

        /// The selected modules `text` can interact with (see the module docs).
        fn named_by(&self, text: &str) -> Vec<Module> {
            let spelled: HashSet<&str> = words(text).collect();
            let directive = DIRECTIVES.iter().any(|word| spelled.contains(word));
            self.names
                .iter()
                .filter(|(_, names)| directive || names.iter().any(|name| spelled.contains(name.as_str())))
                .map(|(module, _)| *module)
                .collect()
        }
    }

    fn composer(modules: &[Module]) -> Result<naga_oil::compose::Composer, String> {
        let mut composer = naga_oil::compose::Composer::default()
            .with_capabilities(ray_footprint::naga_oil::capabilities(modules));
        ray_footprint::naga_oil::add_composable_modules(&mut composer, modules).map_err(
            |error| match error {
                ray_footprint::naga_oil::RegisterError::Composer { error, .. } => {
                    format!("registering {modules:?}: {}", error.emit_to_string(&composer))
                }
                other => format!("registering {modules:?}: {other}"),
            },
        )?;
        Ok(composer)
    }

    /// Both properties for `text` and `modules`; the module set is checked once per thread.
    pub fn check(text: &str, modules: &[Module]) -> Result<(), String> {
        thread_local! {
            static SETS: std::cell::RefCell<HashMap<Vec<Module>, Result<ModuleSet, String>>> =
                Default::default();
        }
        SETS.with_borrow_mut(|sets| {
            let set = sets
                .entry(modules.to_vec())
                .or_insert_with(|| ModuleSet::new(modules))
                .as_mut()
                .map_err(|message| message.clone())?;
            with_prelude(text, set);
            with_composer(text, set);
            Ok(())
        })
    }

    /// The prefixes naga_oil decorates module items with; a shader composed with naga_oil must not
    /// spell them.
    const NAGA_OIL_RESERVED: [&str; 2] = ["X_naga_oil_mod_X", "X_naga_oil_vrt_X"];

    /// Parses and validates the text after the prelude of the modules it names; an error is fine.
    fn with_prelude(text: &str, set: &ModuleSet) {
        let source = format!("{}{text}", wgsl_prelude(&set.named_by(text)));
        let _outcome = parse_and_validate(&source, set.capabilities);
    }

    /// Composes `text` against the set's naga_oil modules; an error is fine. A text that spells
    /// naga_oil's own name decorations ([`NAGA_OIL_RESERVED`]) is left out: naga_oil 0.23 decodes
    /// what follows them with `unwrap` and panics when it is not base32, whatever the modules.
    fn with_composer(text: &str, set: &mut ModuleSet) {
        if NAGA_OIL_RESERVED.iter().any(|reserved| text.contains(reserved)) {
            return;
        }
        let composed = set
            .composer
            .make_naga_module(naga_oil::compose::NagaModuleDescriptor {
                source: text,
                file_path: "user.wgsl",
                ..Default::default()
            });
        if let Err(error) = composed {
            let _message = error.emit_to_string(&set.composer);
        }
    }
}
