//! The Slang compiler as a library in this process: the shared library `slangc` itself loads
//! (`libslang-compiler`, `libslang` in releases before 2025), found beside the `slangc` on the
//! `PATH` or in its `../lib`, else by the system's loader, and driven through its C interface
//! (`slang.h`: `slang_createGlobalSession2`, `spCreateCompileRequest`,
//! `spProcessCommandLineArguments`, `spCompile`) with slangc's own command-line options, in a
//! global session made as slangc makes its own (GLSL compatibility on, so that `import glsl`
//! works).
//!
//! The SPIR-V is slangc's, byte for byte (`tests::the_library_writes_what_slangc_writes`); what
//! changes is that no process starts per shader. slangc spends most of its time on a small shader
//! starting: loading the library and Slang's core module, about 0.3 s of the 0.37 s a kernel of
//! this crate takes on a 2-core x86-64 machine, where the library takes 0.06-0.10 s a kernel
//! after making a session (about 0.2-0.3 s, once). The compiles of all threads share a pool of at
//! most four sessions (`MAX_SESSIONS`), each used by one compile at a time.

use super::CompileError;
use libloading::Library;
use std::ffi::{c_char, c_int, c_void, CString, OsString};
use std::path::{Path, PathBuf};
use std::sync::{Condvar, Mutex, OnceLock, PoisonError};

/// `SlangSession*` and `SlangCompileRequest*`: opaque.
type Handle = *mut c_void;

/// The functions of the C interface this module calls.
struct Api {
    create_session: unsafe extern "C" fn(*const GlobalSessionDescription, *mut Handle) -> i32,
    destroy_session: unsafe extern "C" fn(Handle),
    create_request: unsafe extern "C" fn(Handle) -> Handle,
    destroy_request: unsafe extern "C" fn(Handle),
    process_arguments: unsafe extern "C" fn(Handle, *const *const c_char, c_int) -> i32,
    compile: unsafe extern "C" fn(Handle) -> i32,
    diagnostics: unsafe extern "C" fn(Handle) -> *const c_char,
    code: unsafe extern "C" fn(Handle, *mut usize) -> *const c_void,
    container: unsafe extern "C" fn(Handle, *mut *mut Blob) -> i32,
    /// Kept loaded for the process: the functions above point into it.
    _library: Library,
}

/// `ISlangBlob` of `slang.h`: a COM object whose first word points at its functions.
#[repr(C)]
struct Blob {
    functions: *const BlobFunctions,
}

/// `ISlangBlob`'s functions, in `slang.h`'s order: `ISlangUnknown`'s, then the blob's.
#[repr(C)]
struct BlobFunctions {
    query_interface: *const c_void,
    add_ref: *const c_void,
    release: unsafe extern "C" fn(*mut Blob) -> u32,
    buffer_pointer: unsafe extern "C" fn(*mut Blob) -> *const c_void,
    buffer_size: unsafe extern "C" fn(*mut Blob) -> usize,
}

/// `SlangGlobalSessionDesc` of `slang.h`.
#[repr(C)]
struct GlobalSessionDescription {
    structure_size: u32,
    api_version: u32,
    min_language_version: u32,
    enable_glsl: bool,
    reserved: [u32; 16],
}

impl GlobalSessionDescription {
    /// slangc's: the defaults (API version 0, language version 2025) with GLSL compatibility on.
    fn slangc() -> Self {
        GlobalSessionDescription {
            structure_size: std::mem::size_of::<Self>() as u32,
            api_version: 0,
            min_language_version: 2025,
            enable_glsl: true,
            reserved: [0; 16],
        }
    }
}

/// The library's file names, newest first.
const STEMS: [&str; 2] = ["slang-compiler", "slang"];

/// The library, loaded once per process, or why it cannot be.
fn api() -> Result<&'static Api, CompileError> {
    static API: OnceLock<Result<Api, String>> = OnceLock::new();
    API.get_or_init(load)
        .as_ref()
        .map_err(|message| CompileError::NotRun(message.clone()))
}

/// Loads the first library of [`candidates`] that opens and has every function of [`Api`].
fn load() -> Result<Api, String> {
    let mut failures = Vec::new();
    for candidate in candidates() {
        // SAFETY: loading Slang's library runs its initialisers, which have no preconditions.
        match unsafe { Library::new(&candidate) }.and_then(|library| unsafe { functions(library) }) {
            Ok(api) => return Ok(api),
            Err(error) => failures.push(format!("{}: {error}", candidate.to_string_lossy())),
        }
    }
    Err(format!(
        "cannot load the Slang compiler library (installed with slangc; scripts/setup.sh installs it): {}",
        failures.join("; ")
    ))
}

/// The C functions of `library`.
///
/// # Safety
/// `library` must be Slang's compiler library, whose functions have the signatures of [`Api`].
unsafe fn functions(library: Library) -> Result<Api, libloading::Error> {
    Ok(Api {
        create_session: *library.get(b"slang_createGlobalSession2\0")?,
        destroy_session: *library.get(b"spDestroySession\0")?,
        create_request: *library.get(b"spCreateCompileRequest\0")?,
        destroy_request: *library.get(b"spDestroyCompileRequest\0")?,
        process_arguments: *library.get(b"spProcessCommandLineArguments\0")?,
        compile: *library.get(b"spCompile\0")?,
        diagnostics: *library.get(b"spGetDiagnosticOutput\0")?,
        code: *library.get(b"spGetCompileRequestCode\0")?,
        container: *library.get(b"spGetContainerCode\0")?,
        _library: library,
    })
}

/// Where the library may be: files of its names in the directory of the `slangc` on the `PATH`
/// (symbolic links followed) and in that directory's `../lib`, then its plain names for the
/// system's loader.
fn candidates() -> Vec<OsString> {
    let slangc_dir = std::env::var_os("PATH")
        .iter()
        .flat_map(std::env::split_paths)
        .map(|dir| dir.join(format!("slangc{}", std::env::consts::EXE_SUFFIX)))
        .find(|path| path.is_file())
        .and_then(|path| path.canonicalize().ok())
        .and_then(|path| path.parent().map(Path::to_path_buf));
    let mut found: Vec<OsString> = slangc_dir
        .iter()
        .flat_map(|dir| [dir.clone(), dir.join("../lib")])
        .flat_map(|dir| library_files(&dir))
        .map(PathBuf::into_os_string)
        .collect();
    found.extend(STEMS.map(|stem| file_name(stem).into()));
    found
}

/// `lib<stem>.so` on Linux, `<stem>.dll` on Windows, `lib<stem>.dylib` on macOS.
fn file_name(stem: &str) -> String {
    format!(
        "{}{stem}{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    )
}

/// The files in `dir` named as the library, versioned names (`libslang-compiler.so.0.2026.14.1`)
/// included, in the order of [`STEMS`].
fn library_files(dir: &Path) -> Vec<PathBuf> {
    let names: Vec<String> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|entry| entry.file_name().to_string_lossy().into_owned())
        .collect();
    STEMS
        .iter()
        .flat_map(|stem| {
            let plain = file_name(stem);
            let mut matching: Vec<&String> = names
                .iter()
                .filter(|name| **name == plain || name.starts_with(&format!("{plain}.")))
                .collect();
            matching.sort();
            matching.into_iter().map(|name| dir.join(name))
        })
        .collect()
}

/// A Slang session (a global session, in `slang.h`'s words). The library lets one thread at a time
/// call into a session; [`SessionPool`] hands each to one compile at a time.
struct Session(Handle);

// SAFETY: a session is used by one thread at a time (it is either in the pool or held by the one
// compile that took it), which is all the Slang library asks of its callers.
unsafe impl Send for Session {}

impl Drop for Session {
    fn drop(&mut self) {
        if let (false, Ok(api)) = (self.0.is_null(), api()) {
            // SAFETY: the session was made by this library and no request of it is alive.
            unsafe { (api.destroy_session)(self.0) };
        }
    }
}

/// The sessions of this process not in use, and how many were made: at most [`MAX_SESSIONS`], so
/// that compiles on many threads share a few sessions instead of each making one. Making a session
/// loads Slang's core module: 0.3 s on one thread, and on a 16-thread host sixteen threads making
/// theirs at once took 32-35 s summed (up to 4 s each), more than all their compiles together.
struct SessionPool {
    free: Vec<Session>,
    made: usize,
}

/// The most sessions this process makes; a compile that finds none free while this many exist
/// waits for one. Cold verification of the whole suite on a 16-thread host (an NVIDIA H200's)
/// took 8.6-9.2 s with a session per thread, 12.7-14.2 s with 1 session, 8.0-9.4 s with 2, 6.1-6.6
/// s with 4 and 6.6-6.9 s with 8.
const MAX_SESSIONS: usize = 4;

/// This process's [`SessionPool`] and the signal that a session was put back.
fn session_pool() -> &'static (Mutex<SessionPool>, Condvar) {
    static POOL: OnceLock<(Mutex<SessionPool>, Condvar)> = OnceLock::new();
    POOL.get_or_init(|| {
        let pool = SessionPool {
            free: Vec::new(),
            made: 0,
        };
        (Mutex::new(pool), Condvar::new())
    })
}

/// A free session, or a new one while fewer than [`MAX_SESSIONS`] exist, or the next one put back.
fn take_session(api: &Api) -> Result<Session, CompileError> {
    let (lock, returned) = session_pool();
    let mut pool = lock.lock().unwrap_or_else(PoisonError::into_inner);
    loop {
        if let Some(session) = pool.free.pop() {
            return Ok(session);
        }
        if pool.made < MAX_SESSIONS {
            pool.made += 1;
            drop(pool);
            let mut handle = std::ptr::null_mut();
            // SAFETY: the description is `slang.h`'s struct and outlives the call; a failure
            // leaves the handle null.
            let result = unsafe { (api.create_session)(&GlobalSessionDescription::slangc(), &mut handle) };
            if result < 0 || handle.is_null() {
                lock.lock().unwrap_or_else(PoisonError::into_inner).made -= 1;
                returned.notify_one();
                return Err(CompileError::NotRun(
                    "the Slang library made no session".to_string(),
                ));
            }
            return Ok(Session(handle));
        }
        pool = returned.wait(pool).unwrap_or_else(PoisonError::into_inner);
    }
}

/// Puts `session` back for the next compile.
fn put_back(session: Session) {
    let (lock, returned) = session_pool();
    lock.lock()
        .unwrap_or_else(PoisonError::into_inner)
        .free
        .push(session);
    returned.notify_one();
}

/// What slangc sets before its command line's options and a compile request does not: column-major
/// matrices, in Slang's sense of the words (`slang.h`'s `SLANG_MATRIX_LAYOUT_COLUMN_MAJOR`; a
/// request's own default is row-major). A later option on the command line overrides it, as it
/// does slangc's default.
const SLANGC_DEFAULTS: [&str; 1] = ["-matrix-layout-column-major"];

/// Compiles as `slangc <arguments>` would, `arguments` naming the input file and no output
/// file: the target code's bytes, or the diagnostics (which name `input`) where it fails.
pub(super) fn compile(arguments: &[OsString], input: &Path) -> Result<Vec<u8>, CompileError> {
    run_request(arguments, input, target_code)
}

/// Compiles as `slangc <arguments>` would where `arguments` name a module file as the output
/// (`-o m.slang-module`): the module file's bytes, which slangc would write there, or the
/// diagnostics (which name `input`) where it fails.
pub(super) fn compile_module(arguments: &[OsString], input: &Path) -> Result<Vec<u8>, CompileError> {
    run_request(arguments, input, container_code)
}

/// A compiled request's target code, if it has one.
///
/// # Safety
/// `request` must be a live compile request of `api`'s library.
unsafe fn target_code(api: &Api, request: Handle) -> Option<Vec<u8>> {
    let mut size = 0;
    let code = (api.code)(request, &mut size);
    (!code.is_null() && size > 0).then(|| std::slice::from_raw_parts(code.cast::<u8>(), size).to_vec())
}

/// A compiled request's container (a module file's bytes), if it has one.
///
/// # Safety
/// `request` must be a live compile request of `api`'s library.
unsafe fn container_code(api: &Api, request: Handle) -> Option<Vec<u8>> {
    let mut blob = std::ptr::null_mut();
    if (api.container)(request, &mut blob) < 0 || blob.is_null() {
        return None;
    }
    let functions = &*(*blob).functions;
    let (pointer, size) = ((functions.buffer_pointer)(blob), (functions.buffer_size)(blob));
    let bytes = (!pointer.is_null() && size > 0)
        .then(|| std::slice::from_raw_parts(pointer.cast::<u8>(), size).to_vec());
    (functions.release)(blob);
    bytes
}

/// Runs one compile request of `arguments` after [`SLANGC_DEFAULTS`] on a session of the pool,
/// and `read`s its output (a compile with none fails).
fn run_request(
    arguments: &[OsString],
    input: &Path,
    read: unsafe fn(&Api, Handle) -> Option<Vec<u8>>,
) -> Result<Vec<u8>, CompileError> {
    let api = api()?;
    let arguments = SLANGC_DEFAULTS
        .iter()
        .map(OsString::from)
        .chain(arguments.iter().cloned())
        .map(|argument| CString::new(argument.into_encoded_bytes()))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| CompileError::NotRun(format!("a slangc argument holds a NUL byte: {e}")))?;
    let pointers: Vec<*const c_char> = arguments.iter().map(|argument| argument.as_ptr()).collect();
    let session = take_session(api)?;
    let output = compile_request(api, &session, &pointers, input, read);
    put_back(session);
    output
}

/// Runs one compile request of the arguments `pointers` on `session`, which this compile holds,
/// and `read`s its output (a compile with none fails).
fn compile_request(
    api: &Api,
    session: &Session,
    pointers: &[*const c_char],
    input: &Path,
    read: unsafe fn(&Api, Handle) -> Option<Vec<u8>>,
) -> Result<Vec<u8>, CompileError> {
    let count = c_int::try_from(pointers.len())
        .map_err(|_| CompileError::NotRun(format!("{} slangc arguments", pointers.len())))?;
    // SAFETY: the request is made, used and destroyed here, by the one compile holding the
    // session; the argument pointers outlive the call that reads them; the code and the
    // diagnostics are copied before the request is destroyed.
    unsafe {
        let request = (api.create_request)(session.0);
        if request.is_null() {
            return Err(CompileError::NotRun(
                "the Slang library made no compile request".to_string(),
            ));
        }
        let mut result = (api.process_arguments)(request, pointers.as_ptr(), count);
        if result >= 0 {
            result = (api.compile)(request);
        }
        let code = if result < 0 { None } else { read(api, request) };
        let output = code.ok_or_else(|| CompileError::Failed {
            log: diagnostics(api, request, result),
            source_path: input.display().to_string(),
        });
        (api.destroy_request)(request);
        output
    }
}

/// The diagnostics of `request`, which ended with `result`, or a line saying there were none.
///
/// # Safety
/// `request` must be a live compile request of `api`'s library.
unsafe fn diagnostics(api: &Api, request: Handle, result: i32) -> String {
    let log = (api.diagnostics)(request);
    let log = if log.is_null() {
        String::new()
    } else {
        std::ffi::CStr::from_ptr(log).to_string_lossy().into_owned()
    };
    if log.trim().is_empty() {
        format!("slangc failed with result {result:#x} and no diagnostic")
    } else {
        log
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::process::Command;

    /// Three Slang shaders (one importing GLSL's functions, one reading matrices from a buffer,
    /// whose layout decorations follow the default matrix layout) and an HLSL shader, each
    /// compiled by the library and by a slangc process with the same options: the same bytes. A shader with an error fails with slangc's diagnostic,
    /// naming the file and the line.
    #[test]
    fn the_library_writes_what_slangc_writes() {
        let dir = std::env::temp_dir().join(format!("shader-proptest-slang-library-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a scratch directory");
        let shaders = [
            (
                "kernel.slang",
                "RWStructuredBuffer<float> data;\n[shader(\"compute\")][numthreads(64, 1, 1)]\n\
                 void main(uint3 id : SV_DispatchThreadID) { data[id.x] = sqrt(data[id.x]) * 2.0; }\n",
            ),
            (
                "glsl_functions.slang",
                "import glsl;\nRWStructuredBuffer<float> data;\n[shader(\"compute\")][numthreads(1, 1, 1)]\n\
                 void main(uint3 id : SV_DispatchThreadID) { data[id.x] = fract(data[id.x]); }\n",
            ),
            (
                "matrices.slang",
                "struct Frame { float3x3 rotation; float4x4 projection; };\n\
                 RWStructuredBuffer<Frame> frames;\nRWStructuredBuffer<float3> points;\n\
                 [shader(\"compute\")][numthreads(1, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {\n\
                 points[id.x] = mul(frames[0].rotation, points[id.x]) + frames[0].projection[1].xyz; }\n",
            ),
            (
                "kernel.hlsl",
                "RWStructuredBuffer<float2> data;\n[numthreads(8, 1, 1)]\n\
                 void main(uint3 id : SV_DispatchThreadID) { data[id.x] = normalize(data[id.x]); }\n",
            ),
        ];
        let options = [
            "-target",
            "spirv",
            "-profile",
            "spirv_1_3",
            "-entry",
            "main",
            "-stage",
            "compute",
            "-O0",
        ];
        for (name, source) in shaders {
            let input = dir.join(name);
            let output = dir.join(format!("{name}.spv"));
            std::fs::write(&input, source).expect("a shader file");
            let arguments: Vec<OsString> = options
                .iter()
                .map(OsString::from)
                .chain([input.clone().into()])
                .collect();
            let library = compile(&arguments, &input).expect("the library compiles the shader");
            let process = Command::new("slangc")
                .args(&arguments)
                .arg("-o")
                .arg(&output)
                .status()
                .expect("slangc runs (scripts/setup.sh installs it)");
            assert!(process.success(), "slangc failed on {name}");
            let expected = std::fs::read(&output).expect("slangc's output");
            assert_eq!(library.len(), expected.len(), "{name}: the sizes differ");
            assert!(
                library == expected,
                "{name}: the library's SPIR-V is not slangc's"
            );
        }
        let broken = dir.join("broken.slang");
        std::fs::write(
            &broken,
            "[numthreads(1, 1, 1)]\nvoid main() {\n  undeclared = 1;\n}\n",
        )
        .expect("a shader file");
        let arguments: Vec<OsString> = options
            .iter()
            .map(OsString::from)
            .chain([broken.clone().into()])
            .collect();
        match compile(&arguments, &broken) {
            Err(CompileError::Failed { log, source_path }) => {
                assert!(
                    log.contains("broken.slang:3"),
                    "the log names no file and line: {log}"
                );
                assert!(log.contains("undeclared"), "the log names no identifier: {log}");
                assert_eq!(source_path, broken.display().to_string());
            }
            other => panic!("a shader with an error compiled: {other:?}"),
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
