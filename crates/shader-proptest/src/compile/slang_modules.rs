//! Slang modules compiled once per process. A Slang shader that imports a module of its search
//! path (`import ray_cone;`) has the compiler parse and check that module's source on every
//! compile, most of a small kernel's time; a module compiled once to Slang's binary module file
//! (what `slangc m.slang -o m.slang-module` writes) is loaded instead, with the same SPIR-V as a
//! result (`tests::binary_modules_give_the_sources_spirv`).
//!
//! The modules a shader imports directly (its `import name;` lines) are compiled the first time a
//! shader imports them and kept in memory, keyed by the module's file, its contents and the search
//! directories, so an edited module is compiled again. A module that does not compile on its own
//! is read from its source, as before; so are the modules it imports.

use super::{slang_library, CompileError};
use std::collections::HashMap;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

/// A module file's name (`ray_cone.slang-module`) and its bytes.
pub(super) type BinaryModule = (String, Arc<Vec<u8>>);

/// The modules this process compiled (`None`: did not compile), by [`module_key`].
type Modules = HashMap<Vec<u8>, Option<Arc<Vec<u8>>>>;

/// This process's [`Modules`].
fn memory() -> &'static Mutex<Modules> {
    static MEMORY: OnceLock<Mutex<Modules>> = OnceLock::new();
    MEMORY.get_or_init(Mutex::default)
}

/// Forgets every module this process compiled, as in a new process.
pub(super) fn forget() {
    memory().lock().unwrap_or_else(PoisonError::into_inner).clear();
}

/// The names of the modules `source` imports on lines of their own (`import ray_cone;`).
fn imports(source: &str) -> impl Iterator<Item = &str> {
    source.lines().filter_map(|line| {
        let name = line
            .trim()
            .strip_prefix("import ")?
            .trim()
            .strip_suffix(';')?
            .trim();
        let plain = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        plain.then_some(name)
    })
}

/// The key of the module in `file`: the file, its contents and the search directories.
fn module_key(file: &Path, contents: &[u8], search_dirs: &[&Path]) -> Vec<u8> {
    let mut key = Vec::new();
    for part in [file.as_os_str()]
        .into_iter()
        .chain(search_dirs.iter().map(|dir| dir.as_os_str()))
    {
        key.extend_from_slice(part.as_encoded_bytes());
        key.push(0);
    }
    key.extend_from_slice(contents);
    key
}

/// The binary modules of the modules `source` imports that a search directory holds (the first
/// directory with `name.slang`), each compiled the first time this process sees its file.
pub(super) fn imported_modules(source: &str, search_dirs: &[&Path]) -> Vec<BinaryModule> {
    imports(source)
        .filter_map(|name| {
            let file = search_dirs
                .iter()
                .map(|dir| dir.join(format!("{name}.slang")))
                .find(|file| file.is_file())?;
            let contents = std::fs::read(&file).ok()?;
            let key = module_key(&file, &contents, search_dirs);
            let mut memory = memory().lock().unwrap_or_else(PoisonError::into_inner);
            let bytes = memory
                .entry(key)
                .or_insert_with(|| compile_module(&file, search_dirs).ok().map(Arc::new))
                .clone()?;
            Some((format!("{name}.slang-module"), bytes))
        })
        .collect()
}

/// The module file of the module in `file`, compiled with `search_dirs` on its search path. The
/// output path names the format; the library hands the file's bytes back and writes nothing
/// there, and should a Slang release write it, it is removed.
fn compile_module(file: &Path, search_dirs: &[&Path]) -> Result<Vec<u8>, CompileError> {
    let stem = file.file_stem().unwrap_or_default().to_string_lossy();
    let output: PathBuf = std::env::temp_dir().join(format!(
        "shader-proptest-{}-{stem}.slang-module",
        std::process::id()
    ));
    let mut arguments: Vec<OsString> = vec![file.into()];
    for dir in search_dirs {
        arguments.extend(["-I".into(), dir.as_os_str().to_os_string()]);
    }
    arguments.extend(["-o".into(), output.as_os_str().into()]);
    let bytes = slang_library::compile_module(&arguments, file);
    let _ = std::fs::remove_file(&output);
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compile::{compile_slang, Stage, Target};

    /// A kernel importing a module that imports another compiles to the same SPIR-V with the
    /// module it imports loaded from its binary file as from its source; only that module is
    /// compiled, and an import with no file in the search directories is left to the compiler.
    #[test]
    fn binary_modules_give_the_sources_spirv() {
        let dir = std::env::temp_dir().join(format!("shader-proptest-modules-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        let files = [
            ("scale.slang", "module scale;\npublic float twice(float x) { return 2.0 * x; }\n"),
            (
                "offset.slang",
                "module offset;\nimport scale;\npublic float twice_plus(float x, float y) { return twice(x) + y; }\n",
            ),
        ];
        for (name, contents) in files {
            std::fs::write(dir.join(name), contents).expect("a module file");
        }
        let search_dirs = [dir.as_path()];
        let imported = imported_modules("import offset;\nimport elsewhere;\n", &search_dirs);
        let names: Vec<&str> = imported.iter().map(|(name, _)| name.as_str()).collect();
        assert_eq!(names, ["offset.slang-module"]);

        let kernel = "import offset;\nRWStructuredBuffer<float> values;\n[numthreads(64, 1, 1)]\n\
                      void main(uint3 id : SV_DispatchThreadID) { values[id.x] = twice_plus(values[id.x], 0.5); }\n";
        let with_modules =
            compile_slang(kernel, Stage::Compute, Target::Vulkan1_1, &search_dirs).expect("a kernel");
        let input = dir.join("kernel.slang");
        std::fs::write(&input, kernel).expect("the kernel's file");
        let arguments: Vec<OsString> = [
            "-target",
            "spirv",
            "-profile",
            Target::Vulkan1_1.slang_profile(),
            "-entry",
            "main",
            "-stage",
            "compute",
            "-O0",
            "-warnings-as-errors",
            "all",
            "-I",
        ]
        .into_iter()
        .map(OsString::from)
        .chain([dir.as_os_str().into(), input.as_os_str().into()])
        .collect();
        let bytes = slang_library::compile(&arguments, &input).expect("a kernel from the sources");
        let mut from_sources = crate::spirv::from_bytes(&bytes).expect("SPIR-V");
        crate::spirv::without_slang_source_language(&mut from_sources);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(with_modules, from_sources);
    }
}
