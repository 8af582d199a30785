//! Replays every committed fuzz corpus file (`fuzz/corpus/<target>/`) through the same checks the
//! cargo-fuzz targets run (`ray_footprint_cases::fuzzing`), on stable Rust, so CI exercises them without a
//! nightly toolchain. A panic or a violated property fails the test, naming the file.

use ray_footprint::shaders::{Module, GLSL_INCLUDE_DIR};
use ray_footprint_cases::fuzzing::{self, Target};
use std::path::{Path, PathBuf};

/// The repository root, which holds the fuzz targets and their corpora.
const REPOSITORY: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn corpus_files(name: &str) -> Vec<PathBuf> {
    let dir = Path::new(REPOSITORY).join("fuzz/corpus").join(name);
    let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    let mut files: Vec<PathBuf> = entries
        .map(|entry| entry.expect("a readable corpus entry").path())
        .collect();
    files.sort();
    files
}

fn target(name: &str) -> Target {
    fuzzing::TARGETS
        .iter()
        .find(|(target, _)| *target == name)
        .map(|&(_, target)| target)
        .unwrap_or_else(|| panic!("no fuzz target {name}"))
}

fn replay(name: &str) {
    let files = corpus_files(name);
    assert!(!files.is_empty(), "the {name} corpus is empty");
    let check = target(name);
    let failures: Vec<String> = files
        .iter()
        .filter_map(|path| {
            let data = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            check(&data)
                .err()
                .map(|violation| format!("{}: {violation}", path.display()))
        })
        .collect();
    println!("{name}: replayed {} corpus files", files.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn abi_bytes_corpus() {
    replay("abi_bytes");
}

#[test]
fn cpu_mirror_corpus() {
    replay("cpu_mirror");
}

#[test]
fn compose_corpus() {
    replay("compose");
}

#[test]
fn include_corpus() {
    replay("include");
}

#[test]
fn every_target_has_a_corpus_and_a_fuzz_binary() {
    for (name, _) in fuzzing::TARGETS {
        let binary = Path::new(REPOSITORY).join(format!("fuzz/fuzz_targets/{name}.rs"));
        assert!(binary.is_file(), "{} is missing", binary.display());
        assert!(!corpus_files(name).is_empty(), "{name} has no corpus");
    }
}

/// The compose target leaves a module out of a text's parse when the text spells none of the
/// names the module declares, so those names must be every module-scope declaration: each line of
/// a WGSL module that starts with `fn`, `struct`, `const`, `alias` or `override` declares one of them.
#[test]
fn compose_knows_every_name_a_module_declares() {
    use ray_footprint_cases::fuzzing::compose::declared_names;
    for &module in Module::ALL {
        let names = declared_names(module).expect("the module parses");
        let mut declarations = 0;
        for line in module.wgsl().lines() {
            let mut words = line
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .filter(|word| !word.is_empty());
            let (Some(keyword), Some(name)) = (words.next(), words.next()) else {
                continue;
            };
            if line.starts_with(keyword) && ["fn", "struct", "const", "alias", "override"].contains(&keyword)
            {
                assert!(
                    names.contains(name),
                    "{}: `{keyword} {name}` is not among the names {names:?}",
                    module.stem()
                );
                declarations += 1;
            }
        }
        assert!(declarations > 0, "{}: no declaration found", module.stem());
        println!("{}: {declarations} declared names", module.stem());
    }
}

/// The include directory holds the embedded sources as regular files inside it (no symlink that
/// could lead elsewhere), so what the resolver serves is what `-I GLSL_INCLUDE_DIR` serves.
#[test]
fn glsl_include_dir_holds_the_embedded_modules() {
    let dir = Path::new(GLSL_INCLUDE_DIR)
        .canonicalize()
        .expect("the include directory exists");
    for &module in Module::ALL {
        let path = dir.join(format!("{}.glsl", module.stem()));
        let metadata = std::fs::symlink_metadata(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            metadata.file_type().is_file(),
            "{} is not a regular file",
            path.display()
        );
        assert!(path.canonicalize().expect("canonical").starts_with(&dir));
        let text = std::fs::read_to_string(&path).expect("readable");
        assert_eq!(
            text,
            module.glsl(),
            "{} differs from the embedded source",
            path.display()
        );
    }
}
