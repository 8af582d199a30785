//! Build script: declares the case files, so that a function's case file is the one file of this
//! crate that adding the function edits.
//!
//! For each shader module `<stem>` it reads `src/<stem>/` and writes `$OUT_DIR/<stem>.rs`, which
//! `src/<stem>.rs` includes:
//!
//! - a module for each `.rs` file of `src/<stem>/`: what several sections share;
//! - a module for each section folder `src/<stem>/<folder>/`, declaring each of its `.rs` files: a
//!   file named after a public function of the module is that function's case file, with its
//!   record as `pub fn record()`; any other file holds what the section's files share;
//! - `records()`: every case file's record, in the module's order ([`Module::functions`]);
//! - `SECTION_FILES`: every file of the section folders as `(folder, file stem)`, which
//!   `sections::check_sections` holds to the module's section banners.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The root crate's `Module`: every shader module, its stem and its public functions in order,
/// from the one place that knows them. The rest of that file (sources, includes, capabilities)
/// is unused here.
#[allow(dead_code, unexpected_cfgs)]
#[path = "../../src/shaders.rs"]
mod shaders;

use shaders::Module;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    println!("cargo:rerun-if-changed=src");
    for &module in Module::ALL {
        let folder = manifest.join("src").join(module.stem());
        let code = declarations(module, &folder);
        write_if_changed(&out.join(format!("{}.rs", module.stem())), &code);
    }
}

/// A file (by its stem) or a folder, and its path.
type Entry = (String, PathBuf);

/// The `.rs` files and the folders of `folder`, each sorted by name; nothing for a folder that
/// does not exist.
fn entries(folder: &Path) -> (Vec<Entry>, Vec<Entry>) {
    let (mut files, mut folders) = (Vec::new(), Vec::new());
    let Ok(read) = std::fs::read_dir(folder) else {
        return (files, folders);
    };
    for entry in read {
        let path = entry
            .unwrap_or_else(|e| panic!("{}: {e}", folder.display()))
            .path();
        let name = path
            .file_name()
            .and_then(|name| name.to_str())
            .unwrap_or_default()
            .to_string();
        if path.is_dir() {
            folders.push((name, path));
        } else if let Some(stem) = name.strip_suffix(".rs") {
            files.push((stem.to_string(), path));
        }
    }
    files.sort();
    folders.sort();
    (files, folders)
}

/// `pub mod <name>;` at `path`, indented by `indent`.
fn declare(code: &mut String, indent: &str, name: &str, path: &Path) {
    writeln!(code, "{indent}#[path = {:?}]", path.display().to_string()).expect("a String");
    writeln!(code, "{indent}pub mod {name};").expect("a String");
}

/// The declarations of `module`'s case files and helpers in `folder`, its record list and its
/// section files.
fn declarations(module: Module, folder: &Path) -> String {
    let functions = module.functions();
    let stem = module.stem();
    let mut code =
        format!("// Written by the build script of ray-footprint-cases from src/{stem}/: do not edit.\n\n");
    let (helpers, sections) = entries(folder);
    for (name, path) in &helpers {
        declare(&mut code, "", name, path);
    }
    let mut case_files: Vec<(&str, String)> = Vec::new();
    let mut section_files: Vec<(String, String)> = Vec::new();
    for (section, path) in &sections {
        let (files, nested) = entries(path);
        if let Some((_, nested)) = nested.first() {
            panic!("{}: a section folder holds files, not folders", nested.display());
        }
        writeln!(code, "\n/// The functions of the section in `src/{stem}/{section}/`, a case file each, and what they share.").expect("a String");
        writeln!(code, "pub mod {section} {{").expect("a String");
        for (name, path) in &files {
            if name == section {
                // A section may be named for its one function (`transfer/transfer.rs`).
                writeln!(code, "    #[allow(clippy::module_inception)]").expect("a String");
            }
            declare(&mut code, "    ", name, path);
            if let Some(&function) = functions.iter().find(|&&function| function == name) {
                case_files.push((function, section.clone()));
            }
            section_files.push((section.clone(), name.clone()));
        }
        writeln!(code, "}}").expect("a String");
    }
    writeln!(code, "\n/// Every case file's record, in the module's order.").expect("a String");
    writeln!(
        code,
        "pub(crate) fn records() -> Vec<Box<dyn crate::record::Function>> {{"
    )
    .expect("a String");
    writeln!(code, "    vec![").expect("a String");
    for function in &functions {
        for (_, section) in case_files.iter().filter(|(name, _)| name == function) {
            writeln!(
                code,
                "        Box::new({section}::{function}::record()) as Box<dyn crate::record::Function>,"
            )
            .expect("a String");
        }
    }
    writeln!(code, "    ]\n}}").expect("a String");
    writeln!(
        code,
        "\n/// Every file of the section folders, as `(folder, file stem)`."
    )
    .expect("a String");
    writeln!(code, "pub const SECTION_FILES: &[(&str, &str)] = &[").expect("a String");
    for (section, name) in &section_files {
        writeln!(code, "    ({section:?}, {name:?}),").expect("a String");
    }
    writeln!(code, "];").expect("a String");
    code
}

/// Writes `code` to `path` unless it holds that already (an unchanged file leaves the crate
/// compiled).
fn write_if_changed(path: &Path, code: &str) {
    if std::fs::read_to_string(path).ok().as_deref() != Some(code) {
        std::fs::write(path, code).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
