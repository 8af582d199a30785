//! Headless Chromium with WebGPU, started as a child process and driven over the DevTools protocol
//! on its debugging pipe ([`super::devtools`]): pages opened in it, scripts evaluated (promises
//! awaited), screenshots taken, the start bounded by one timeout and each call after it by another.

use super::devtools::{decode_base64, DevTools};
use crate::gpu::error::Error;
use serde_json::{json, Value};
use std::ffi::OsString;
use std::io::{BufRead, BufReader};
use std::os::fd::{AsRawFd, RawFd};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStderr, Command, Stdio};
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Environment variable naming the Chromium (or Chrome) executable to start, instead of the first
/// of `chromium`, `chromium-browser`, `google-chrome` on the `PATH`.
pub const CHROMIUM_ENV: &str = "SHADER_PROPTEST_CHROMIUM";

/// What to install when no Chromium is found.
const INSTALL: &str = "install Chromium (Debian: `apt-get install chromium`, which the repository's \
     scripts/setup.sh does) or set SHADER_PROPTEST_CHROMIUM to a Chromium or Chrome executable";

/// Names tried on the `PATH`, in order.
const EXECUTABLES: [&str; 3] = ["chromium", "chromium-browser", "google-chrome"];

/// Flags for a headless Chromium that offers WebGPU (on a machine without a GPU, SwiftShader's
/// Vulkan), takes DevTools commands on its file descriptors 3 and 4, and reaches nothing but
/// loopback pages: no first-run, sync, component or background connections. `--no-sandbox`: the
/// pages are the harness's own, and the sandbox cannot start as root.
const FLAGS: [&str; 9] = [
    "--headless",
    "--no-sandbox",
    "--enable-unsafe-webgpu",
    "--remote-debugging-pipe",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
];

/// How to start Chromium.
#[derive(Clone, Debug)]
pub struct ChromiumOptions {
    /// The executable; `None`: [`CHROMIUM_ENV`], else the first of `chromium`,
    /// `chromium-browser`, `google-chrome` on the `PATH`.
    pub executable: Option<PathBuf>,
    /// The longest wait for Chromium to start and answer its first DevTools command: a cold start
    /// on a busy machine takes seconds. Past it [`Chromium::launch`] fails with [`Error::Browser`].
    pub start_timeout: Duration,
    /// The longest wait for anything a started Chromium is asked: a page's load, a script's
    /// answer (its promise), a screenshot. Past it the call fails with [`Error::Browser`].
    pub timeout: Duration,
}

impl Default for ChromiumOptions {
    /// The executable from the environment or the `PATH`, 30 s to start and 30 s for any answer.
    fn default() -> Self {
        ChromiumOptions {
            executable: None,
            start_timeout: Duration::from_secs(30),
            timeout: Duration::from_secs(30),
        }
    }
}

/// A headless Chromium with WebGPU, killed (and its profile removed) when dropped.
///
/// ```no_run
/// use shader_proptest::{Chromium, ChromiumOptions};
///
/// let chromium = Chromium::launch(&ChromiumOptions::default())?;
/// let page = chromium.open("data:text/html,<p>hello</p>")?;
/// let adapter = page.evaluate("navigator.gpu.requestAdapter().then(a => a.info.architecture)")?;
/// println!("{} offers the adapter {adapter}", chromium.version());
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct Chromium {
    devtools: Arc<DevTools>,
    process: Child,
    profile: PathBuf,
    version: String,
    timeout: Duration,
}

impl Chromium {
    /// Starts Chromium headless with WebGPU and connects to it. [`Error::Setup`] names what to
    /// install when there is no executable; [`Error::Browser`] says why a Chromium that was found
    /// did not start within the options' `start_timeout`.
    pub fn launch(options: &ChromiumOptions) -> Result<Chromium, Error> {
        let executable = match &options.executable {
            Some(path) => existing(path)?,
            None => find_chromium(std::env::var_os(CHROMIUM_ENV), std::env::var_os("PATH"))?,
        };
        let profile = std::env::temp_dir().join(format!(
            "shader-proptest-chromium-{}-{}",
            std::process::id(),
            unique()
        ));
        let pipe_failure = |error: std::io::Error| Error::Browser(format!("no pipe for Chromium: {error}"));
        let (chromium_reads, commands) = std::io::pipe().map_err(pipe_failure)?;
        let (messages, chromium_writes) = std::io::pipe().map_err(pipe_failure)?;
        let (input, output) = (chromium_reads.as_raw_fd(), chromium_writes.as_raw_fd());
        let mut command = Command::new(&executable);
        command
            .args(FLAGS)
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        // SAFETY: the closure runs in the child between fork and exec and calls only fcntl, dup2
        // and close, which are async-signal-safe; it allocates nothing.
        unsafe {
            command.pre_exec(move || debugging_pipe_descriptors(input, output));
        }
        let mut process = command.spawn().map_err(|error| {
            Error::Setup(format!(
                "{} does not start ({error}): {INSTALL}",
                executable.display()
            ))
        })?;
        // Chromium holds its own ends now; closing ours lets the pipe close when it exits.
        drop((chromium_reads, chromium_writes));
        let last_lines = read_stderr(process.stderr.take().expect("stderr is piped"));
        let devtools = Arc::new(DevTools::new(commands, messages));
        match browser_version(&devtools, options.start_timeout, &last_lines) {
            Ok(version) => Ok(Chromium {
                devtools,
                process,
                profile,
                version,
                timeout: options.timeout,
            }),
            Err(problem) => {
                end(&mut process, &profile);
                Err(Error::Browser(format!("{}: {problem}", executable.display())))
            }
        }
    }

    /// The browser and its version, as Chromium names them: `Chromium 156.0.8078.108` (a
    /// headless Chrome says `HeadlessChrome/...`, reported as `Chromium ...` too).
    pub fn version(&self) -> &str {
        &self.version
    }

    /// Opens `url` in a new tab and waits for it to load.
    pub fn open(&self, url: &str) -> Result<BrowserPage, Error> {
        let loading = format!("loading {url}");
        let failed = |problem: &dyn std::fmt::Display| devtools_failure(&loading, problem);
        let call = |session: Option<&str>, method: &str, params: Value| {
            self.devtools
                .call(session, method, params, self.timeout)
                .map_err(|error| failed(&error))
        };
        let target = call(None, "Target.createTarget", json!({ "url": "about:blank" }))?;
        let attached = call(
            None,
            "Target.attachToTarget",
            json!({ "targetId": target["targetId"], "flatten": true }),
        )?;
        let session = attached["sessionId"]
            .as_str()
            .ok_or_else(|| failed(&"no session for the new tab"))?
            .to_string();
        let events = self.devtools.events(&session);
        call(Some(&session), "Page.enable", json!({}))?;
        call(
            Some(&session),
            "Page.setLifecycleEventsEnabled",
            json!({ "enabled": true }),
        )?;
        let started = Instant::now();
        let navigated = call(Some(&session), "Page.navigate", json!({ "url": url }))?;
        if let Some(problem) = navigated["errorText"].as_str() {
            return Err(failed(&problem));
        }
        let loader = navigated["loaderId"].clone();
        wait_for_load(&events, &loader, self.timeout.saturating_sub(started.elapsed()))
            .map_err(|problem| failed(&problem))?;
        Ok(BrowserPage {
            devtools: Arc::clone(&self.devtools),
            session,
            timeout: self.timeout,
        })
    }
}

impl Drop for Chromium {
    fn drop(&mut self) {
        end(&mut self.process, &self.profile);
    }
}

/// A page open in [`Chromium`].
pub struct BrowserPage {
    devtools: Arc<DevTools>,
    session: String,
    timeout: Duration,
}

impl BrowserPage {
    /// The value of the script `expression` (awaited when it is a promise), as JSON. A script
    /// that throws or rejects is [`Error::Browser`] with the page's message; so is one that has
    /// not answered within the timeout.
    pub fn evaluate(&self, expression: &str) -> Result<Value, Error> {
        let params = json!({ "expression": expression, "returnByValue": true, "awaitPromise": true });
        let answer = self.call("Runtime.evaluate", params, expression)?;
        if let Some(details) = answer.get("exceptionDetails") {
            let thrown = details["exception"]["description"]
                .as_str()
                .or(details["text"].as_str())
                .unwrap_or("an exception without a description");
            return Err(Error::Browser(format!(
                "the page's `{}` threw: {thrown}",
                short(expression)
            )));
        }
        Ok(answer["result"]["value"].clone())
    }

    /// A PNG of the page's viewport.
    pub fn screenshot(&self) -> Result<Vec<u8>, Error> {
        let answer = self.call(
            "Page.captureScreenshot",
            json!({ "format": "png" }),
            "a screenshot",
        )?;
        decode_base64(answer["data"].as_str().unwrap_or_default())
            .map_err(|problem| self.unanswered("a screenshot", problem))
    }

    /// The result of `method` with `params` on this page; `what` names it in an error.
    fn call(&self, method: &str, params: Value, what: &str) -> Result<Value, Error> {
        self.devtools
            .call(Some(&self.session), method, params, self.timeout)
            .map_err(|problem| self.unanswered(what, problem))
    }

    /// The error of a call that failed or was not answered in time.
    fn unanswered(&self, what: &str, error: impl std::fmt::Display) -> Error {
        Error::Browser(format!(
            "the page did not answer `{}` within {:.1} s: {error}",
            short(what),
            self.timeout.as_secs_f64()
        ))
    }
}

/// The first 120 characters of a script, for messages.
fn short(script: &str) -> String {
    let mut text: String = script.chars().take(120).collect();
    if text.len() < script.len() {
        text.push_str("...");
    }
    text
}

/// A failed DevTools call, as [`Error::Browser`].
fn devtools_failure(what: &str, error: impl std::fmt::Display) -> Error {
    Error::Browser(format!("Chromium failed {what}: {error}"))
}

/// `path` if it is a file, else [`Error::Setup`] naming it and what to install.
fn existing(path: &Path) -> Result<PathBuf, Error> {
    if path.is_file() {
        Ok(path.to_path_buf())
    } else {
        Err(Error::Setup(format!(
            "no Chromium at {}: {INSTALL}",
            path.display()
        )))
    }
}

/// The Chromium to start: `named` (the value of [`CHROMIUM_ENV`]) if set, else the first of
/// [`EXECUTABLES`] in the directories of `path` (the value of `PATH`).
fn find_chromium(named: Option<OsString>, path: Option<OsString>) -> Result<PathBuf, Error> {
    if let Some(named) = named {
        return existing(Path::new(&named));
    }
    let directories: Vec<PathBuf> = path.map_or_else(Vec::new, |path| std::env::split_paths(&path).collect());
    EXECUTABLES
        .iter()
        .flat_map(|name| directories.iter().map(move |directory| directory.join(name)))
        .find(|candidate| candidate.is_file())
        .ok_or_else(|| {
            Error::Setup(format!(
                "no Chromium: none of {} is on the PATH; {INSTALL}",
                EXECUTABLES.join(", ")
            ))
        })
}

/// A number no other Chromium of this process got.
fn unique() -> u64 {
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// Kills `process`, waits for it and removes its `profile`.
fn end(process: &mut Child, profile: &Path) {
    // Either may fail only where the process has already gone.
    let _ = process.kill();
    let _ = process.wait();
    let _ = std::fs::remove_dir_all(profile);
}

/// In the child, before Chromium starts: the pipe ends `input` and `output` put where
/// `--remote-debugging-pipe` looks for them, on descriptors 3 (commands) and 4 (answers and
/// events). Each is copied above 4 first, so that neither `dup2` replaces the other's source; the
/// copies are closed after.
fn debugging_pipe_descriptors(input: RawFd, output: RawFd) -> std::io::Result<()> {
    let checked = |result: libc::c_int| {
        if result < 0 {
            Err(std::io::Error::last_os_error())
        } else {
            Ok(result)
        }
    };
    // SAFETY: fcntl, dup2 and close on descriptors this process owns; none allocates.
    unsafe {
        let input_copy = checked(libc::fcntl(input, libc::F_DUPFD, 5))?;
        let output_copy = checked(libc::fcntl(output, libc::F_DUPFD, 5))?;
        checked(libc::dup2(input_copy, 3))?;
        checked(libc::dup2(output_copy, 4))?;
        checked(libc::close(input_copy))?;
        checked(libc::close(output_copy))?;
    }
    Ok(())
}

/// Reads Chromium's `stderr` to its end on a thread of its own, so that Chromium never blocks on
/// a full pipe, keeping its last lines for the error of a start that fails.
fn read_stderr(stderr: ChildStderr) -> Arc<Mutex<Vec<String>>> {
    let last_lines = Arc::new(Mutex::new(Vec::new()));
    let kept = Arc::clone(&last_lines);
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines() {
            let Ok(line) = line else { break };
            let mut lines = kept.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
            lines.push(line);
            let excess = lines.len().saturating_sub(8);
            lines.drain(..excess);
        }
    });
    last_lines
}

/// The browser's version as `Chromium <number>`, its first answer, within `timeout`; where it
/// exits or never answers, why, with the last lines it printed.
fn browser_version(
    devtools: &DevTools,
    timeout: Duration,
    last_lines: &Mutex<Vec<String>>,
) -> Result<String, String> {
    match devtools.call(None, "Browser.getVersion", json!({}), timeout) {
        Ok(version) => {
            let product = version["product"].as_str().unwrap_or_default();
            Ok(format!(
                "Chromium {}",
                product.rsplit('/').next().unwrap_or(product)
            ))
        }
        Err(problem) => {
            // Its last words may still be on their way when the pipe closes.
            std::thread::sleep(Duration::from_millis(200));
            let said = last_lines
                .lock()
                .unwrap_or_else(|poisoned| poisoned.into_inner())
                .join("\n");
            Err(format!(
                "did not answer over its DevTools pipe within {:.1} s ({problem}); it said:\n{said}",
                timeout.as_secs_f64()
            ))
        }
    }
}

/// Waits at most `timeout` for the page's `load` of the navigation `loader` among `events`.
fn wait_for_load(events: &Receiver<Value>, loader: &Value, timeout: Duration) -> Result<(), String> {
    let deadline = Instant::now() + timeout;
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        match events.recv_timeout(left) {
            Ok(event) => {
                let params = &event["params"];
                if event["method"] == "Page.lifecycleEvent"
                    && params["name"] == "load"
                    && &params["loaderId"] == loader
                {
                    return Ok(());
                }
            }
            Err(RecvTimeoutError::Timeout) => {
                return Err(format!("no load within {:.1} s", timeout.as_secs_f64()))
            }
            Err(RecvTimeoutError::Disconnected) => return Err("Chromium closed its DevTools pipe".into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Without the variable and without any of the names on the `PATH`, the error names the
    /// package and the variable.
    #[test]
    fn no_chromium_names_what_to_install() {
        let empty = std::env::temp_dir().join("shader-proptest-no-chromium-here");
        let message = find_chromium(None, Some(empty.into_os_string()))
            .expect_err("no chromium in an empty directory")
            .to_string();
        assert!(message.contains("apt-get install chromium"), "{message}");
        assert!(message.contains(CHROMIUM_ENV), "{message}");
    }

    /// A variable that names no file is refused, naming the path.
    #[test]
    fn a_named_executable_must_exist() {
        let message = find_chromium(Some("/nonexistent/chromium".into()), None)
            .expect_err("no such file")
            .to_string();
        assert!(
            message.contains("no Chromium at /nonexistent/chromium"),
            "{message}"
        );
    }
}
