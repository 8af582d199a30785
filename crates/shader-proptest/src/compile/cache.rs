//! Compiled SPIR-V kept for the life of the process, so that a kernel that several checks of one
//! run compile (agreement, special values, symmetries) is compiled once ([`remembered`]), and on
//! disk between runs, for the command-line compilers (glslang, slangc), when [`SPIRV_CACHE_ENV`]
//! names a directory.
//!
//! A compile's key is everything its output depends on, written out in full: the compiler's
//! name and the version it prints, its options, the source's file extension and text, and every
//! file under the include directories (path and contents). The key is stored beside the words and
//! compared byte for byte on a lookup, so a hit is a compile of exactly the same input by a
//! compiler that reports the same version; a file name is only a hash of the key. Files a source
//! reads from outside its include directories (an absolute `#include` path) are not part of the
//! key: such shaders should not be compiled with the cache on. Failed compiles are not kept. A
//! cache that cannot be read or written is skipped: the compiler runs as without it.

use std::collections::HashMap;
use std::ffi::OsString;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock, PoisonError};

/// The environment variable naming the directory of the SPIR-V cache; unset or empty, every
/// shader is compiled.
pub const SPIRV_CACHE_ENV: &str = "SHADER_PROPTEST_SPIRV_CACHE";

/// The first line of every key: a new layout of the key or the file changes it.
const FORMAT: &str = "shader-proptest SPIR-V cache 1";

/// The cache's directory, from [`SPIRV_CACHE_ENV`].
pub(crate) fn directory() -> Option<PathBuf> {
    std::env::var_os(SPIRV_CACHE_ENV)
        .filter(|dir| !dir.is_empty())
        .map(PathBuf::from)
}

/// Everything a compile's output depends on: `command` (the compiler and its options, before the
/// input and output paths), `extension`, `source` and the files under `include_dirs`. `None`
/// where the compiler's version or an include directory cannot be read.
pub(crate) fn key(
    command: &Command,
    extension: &str,
    source: &str,
    include_dirs: &[&Path],
) -> Option<Vec<u8>> {
    let program = command.get_program();
    let mut key = Vec::new();
    let mut line = |bytes: &[u8]| {
        key.extend_from_slice(&(bytes.len() as u64).to_le_bytes());
        key.extend_from_slice(bytes);
    };
    line(FORMAT.as_bytes());
    line(program.as_encoded_bytes());
    line(version(program.to_os_string())?.as_bytes());
    command.get_args().for_each(|arg| line(arg.as_encoded_bytes()));
    line(extension.as_bytes());
    line(source.as_bytes());
    for dir in include_dirs {
        line(dir.as_os_str().as_encoded_bytes());
        for (path, contents) in files_under(dir)? {
            line(path.as_os_str().as_encoded_bytes());
            line(&contents);
        }
    }
    Some(key)
}

/// What `program` prints for its version (`slangc -version`, `glslangValidator --version`), asked
/// once per process.
fn version(program: OsString) -> Option<String> {
    static VERSIONS: OnceLock<Mutex<HashMap<OsString, Option<String>>>> = OnceLock::new();
    let versions = VERSIONS.get_or_init(Mutex::default);
    let mut versions = versions.lock().unwrap_or_else(PoisonError::into_inner);
    versions
        .entry(program.clone())
        .or_insert_with(|| {
            let flag = if program.to_string_lossy().contains("slangc") {
                "-version"
            } else {
                "--version"
            };
            let output = Command::new(&program).arg(flag).output().ok()?;
            output.status.success().then(|| {
                format!(
                    "{}{}",
                    String::from_utf8_lossy(&output.stdout),
                    String::from_utf8_lossy(&output.stderr)
                )
            })
        })
        .clone()
}

/// Every file under `dir` (recursively), by path, in the order of their paths.
fn files_under(dir: &Path) -> Option<Vec<(PathBuf, Vec<u8>)>> {
    let mut files = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(dir) = pending.pop() {
        for entry in std::fs::read_dir(&dir).ok()? {
            let path = entry.ok()?.path();
            if path.is_dir() {
                pending.push(path);
            } else {
                let contents = std::fs::read(&path).ok()?;
                files.push((path, contents));
            }
        }
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    Some(files)
}

/// The compiles of this process, by key.
fn memory() -> &'static Mutex<HashMap<Vec<u8>, Vec<u32>>> {
    static MEMORY: OnceLock<Mutex<HashMap<Vec<u8>, Vec<u32>>>> = OnceLock::new();
    MEMORY.get_or_init(Mutex::default)
}

/// The words this process compiled for `key`, if it did.
pub(crate) fn remembered(key: &[u8]) -> Option<Vec<u32>> {
    memory()
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .get(key)
        .cloned()
}

/// Keeps `words` for `key` for the life of the process.
pub(crate) fn remember(key: &[u8], words: &[u32]) {
    memory()
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .insert(key.to_vec(), words.to_vec());
}

/// Forgets every compile this process kept in memory.
pub(crate) fn forget() {
    memory().lock().unwrap_or_else(PoisonError::into_inner).clear();
}

/// The file of `key` in `dir`, named by a hash of the key.
fn file(dir: &Path, key: &[u8]) -> PathBuf {
    let mut hasher = std::hash::DefaultHasher::new();
    key.hash(&mut hasher);
    dir.join(format!("{:016x}.spv", hasher.finish()))
}

/// The words kept for `key`, if its file holds exactly this key followed by SPIR-V.
pub(crate) fn lookup(dir: &Path, key: &[u8]) -> Option<Vec<u32>> {
    let bytes = std::fs::read(file(dir, key)).ok()?;
    let stored_length = u64::from_le_bytes(bytes.get(..8)?.try_into().ok()?);
    let words_at = 8 + usize::try_from(stored_length).ok()?;
    if bytes.get(8..words_at)? != key {
        return None;
    }
    crate::spirv::from_bytes(&bytes[words_at..]).ok()
}

/// Keeps `words` for `key` in `dir`: written to a file of this process, then renamed, so that a
/// reader never sees half a file. Failures are ignored (the next run compiles again).
pub(crate) fn store(dir: &Path, key: &[u8], words: &[u32]) {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let target = file(dir, key);
    let partial = target.with_extension(format!(
        "{}-{}.partial",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let mut bytes = Vec::with_capacity(8 + key.len() + 4 * words.len());
    bytes.extend_from_slice(&(key.len() as u64).to_le_bytes());
    bytes.extend_from_slice(key);
    words
        .iter()
        .for_each(|word| bytes.extend_from_slice(&word.to_le_bytes()));
    let written = std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&partial, &bytes));
    if written.and_then(|()| std::fs::rename(&partial, &target)).is_err() {
        let _ = std::fs::remove_file(&partial);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("shader-proptest-cache-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    /// What is stored under a key is found under the same key, and under no other: another
    /// source, another option, or an include file changed by one byte.
    #[test]
    fn a_lookup_finds_only_its_own_key() {
        let dir = scratch("keys");
        let include = dir.join("include");
        std::fs::create_dir_all(&include).expect("a scratch directory");
        std::fs::write(include.join("a.glsl"), "float a() { return 1.0; }").expect("a file");
        let command = || {
            let mut command = Command::new("glslangValidator");
            command.args(["--target-env", "vulkan1.1"]);
            command
        };
        let key = key(&command(), "comp", "void main() {}", &[&include])
            .expect("glslangValidator answers --version (scripts/setup.sh installs it)");
        let words = [crate::spirv::MAGIC, 0x0001_0300, 7, 9, 0];
        store(&dir, &key, &words);
        assert_eq!(lookup(&dir, &key), Some(words.to_vec()));
        let other_source = super::key(&command(), "comp", "void main() { }", &[&include]).expect("a key");
        let mut other_options = command();
        other_options.arg("-g");
        let other_options = super::key(&other_options, "comp", "void main() {}", &[&include]).expect("a key");
        std::fs::write(include.join("a.glsl"), "float a() { return 2.0; }").expect("a file");
        let other_include = super::key(&command(), "comp", "void main() {}", &[&include]).expect("a key");
        for other in [other_source, other_options, other_include] {
            assert_ne!(other, key);
            assert_eq!(lookup(&dir, &other), None);
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A file whose stored key differs (a hash collision) or whose words are not SPIR-V is a miss.
    #[test]
    fn a_file_for_another_key_or_not_spirv_is_a_miss() {
        let dir = scratch("collision");
        let key = b"the key".to_vec();
        store(&dir, &key, &[crate::spirv::MAGIC, 1]);
        let mut bytes = std::fs::read(file(&dir, &key)).expect("the stored file");
        bytes[8] ^= 1;
        std::fs::write(file(&dir, &key), &bytes).expect("a file");
        assert_eq!(lookup(&dir, &key), None);
        store(&dir, &key, &[0xdead_beef, 1]);
        assert_eq!(lookup(&dir, &key), None);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
