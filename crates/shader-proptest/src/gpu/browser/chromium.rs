//! Headless Chromium with WebGPU, started as a child process and driven over the DevTools protocol
//! through the `headless_chrome` crate: pages opened in it, scripts evaluated (promises awaited),
//! screenshots taken, the start bounded by one timeout and each call after it by another.

use crate::gpu::error::Error;
use headless_chrome::protocol::cdp::Page::CaptureScreenshotFormatOption;
use headless_chrome::protocol::cdp::Runtime;
use headless_chrome::{Browser, Tab};
use std::ffi::OsString;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStderr, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::sync::Arc;
use std::time::Duration;

/// Environment variable naming the Chromium (or Chrome) executable to start, instead of the first
/// of `chromium`, `chromium-browser`, `google-chrome` on the `PATH`.
pub const CHROMIUM_ENV: &str = "SHADER_PROPTEST_CHROMIUM";

/// What to install when no Chromium is found.
const INSTALL: &str = "install Chromium (Debian: `apt-get install chromium`, which the repository's \
     scripts/setup.sh does) or set SHADER_PROPTEST_CHROMIUM to a Chromium or Chrome executable";

/// Names tried on the `PATH`, in order.
const EXECUTABLES: [&str; 3] = ["chromium", "chromium-browser", "google-chrome"];

/// Flags for a headless Chromium that offers WebGPU (on a machine without a GPU, SwiftShader's
/// Vulkan) and reaches nothing but loopback pages: no first-run, sync, component or background
/// connections. `--no-sandbox`: the pages are the harness's own, and the sandbox cannot start as
/// root.
const FLAGS: [&str; 9] = [
    "--headless",
    "--no-sandbox",
    "--enable-unsafe-webgpu",
    "--remote-debugging-port=0",
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
    /// The longest wait for Chromium to start and print its DevTools address: a cold start on a busy
    /// machine takes seconds. Past it [`Chromium::launch`] fails with [`Error::Browser`].
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
    browser: Browser,
    process: Child,
    profile: PathBuf,
    version: String,
    timeout: Duration,
    /// Set when dropped: ends the thread that keeps the connection busy.
    closing: Arc<AtomicBool>,
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
        let mut process = Command::new(&executable)
            .args(FLAGS)
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|error| {
                Error::Setup(format!(
                    "{} does not start ({error}): {INSTALL}",
                    executable.display()
                ))
            })?;
        let stderr = process.stderr.take().expect("stderr is piped");
        let connected = devtools_address(stderr, options.start_timeout)
            .map_err(|problem| Error::Browser(format!("{}: {problem}", executable.display())))
            .and_then(|address| connect(address, options.timeout));
        let (browser, version) = match connected {
            Ok(connected) => connected,
            Err(error) => {
                end(&mut process, &profile);
                return Err(error);
            }
        };
        let closing = Arc::new(AtomicBool::new(false));
        keep_busy(&browser, options.timeout, &closing);
        Ok(Chromium {
            browser,
            process,
            profile,
            version,
            timeout: options.timeout,
            closing,
        })
    }

    /// The browser and its version, as Chromium names them: `Chromium 156.0.8078.108` (a
    /// headless Chrome says `HeadlessChrome/...`, reported as `Chromium ...` too).
    pub fn version(&self) -> &str {
        &self.version
    }

    /// Opens `url` in a new tab and waits for it to load.
    pub fn open(&self, url: &str) -> Result<BrowserPage, Error> {
        let tab = self
            .browser
            .new_tab()
            .map_err(|error| devtools_failure("opening a tab", error))?;
        tab.set_default_timeout(self.timeout);
        tab.navigate_to(url)
            .and_then(|tab| tab.wait_until_navigated())
            .map_err(|error| devtools_failure(&format!("loading {url}"), error))?;
        Ok(BrowserPage {
            tab,
            timeout: self.timeout,
        })
    }
}

impl Drop for Chromium {
    fn drop(&mut self) {
        self.closing.store(true, Ordering::Relaxed);
        end(&mut self.process, &self.profile);
    }
}

/// A page open in [`Chromium`].
pub struct BrowserPage {
    tab: Arc<Tab>,
    timeout: Duration,
}

impl BrowserPage {
    /// The value of the script `expression` (awaited when it is a promise), as JSON. A script
    /// that throws or rejects is [`Error::Browser`] with the page's message; so is one that has
    /// not answered within the timeout.
    pub fn evaluate(&self, expression: &str) -> Result<serde_json::Value, Error> {
        let answer = self
            .tab
            .call_method(Runtime::Evaluate {
                expression: expression.to_string(),
                object_group: None,
                include_command_line_api: None,
                silent: None,
                context_id: None,
                return_by_value: Some(true),
                generate_preview: None,
                user_gesture: None,
                await_promise: Some(true),
                throw_on_side_effect: None,
                timeout: None,
                disable_breaks: None,
                repl_mode: None,
                allow_unsafe_eval_blocked_by_csp: None,
                unique_context_id: None,
                serialization_options: None,
            })
            .map_err(|error| self.unanswered(expression, error))?;
        if let Some(details) = answer.exception_details {
            let thrown = details.exception.and_then(|exception| exception.description);
            return Err(Error::Browser(format!(
                "the page's `{}` threw: {}",
                short(expression),
                thrown.unwrap_or(details.text)
            )));
        }
        Ok(answer.result.value.unwrap_or(serde_json::Value::Null))
    }

    /// A PNG of the page's viewport.
    pub fn screenshot(&self) -> Result<Vec<u8>, Error> {
        self.tab
            .capture_screenshot(CaptureScreenshotFormatOption::Png, None, None, true)
            .map_err(|error| self.unanswered("a screenshot", error))
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

/// The DevTools address Chromium prints on `stderr` when it listens, within `timeout`; its last
/// lines where it exits first. A thread reads `stderr` to its end, so that Chromium never blocks
/// on a full pipe.
fn devtools_address(stderr: ChildStderr, timeout: Duration) -> Result<String, String> {
    let (sender, receiver) = channel();
    std::thread::spawn(move || read_stderr(stderr, &sender));
    match receiver.recv_timeout(timeout) {
        Ok(Ok(address)) => Ok(address),
        Ok(Err(last_lines)) => Err(format!("exited before listening; it said:\n{last_lines}")),
        Err(RecvTimeoutError::Timeout) => Err(format!(
            "did not print its DevTools address within {:.1} s",
            timeout.as_secs_f64()
        )),
        Err(RecvTimeoutError::Disconnected) => Err("its output ended without an address".into()),
    }
}

/// Reads Chromium's `stderr` to its end; sends the DevTools address when it appears, or the last
/// lines when the output ends first.
fn read_stderr(stderr: ChildStderr, sender: &Sender<Result<String, String>>) {
    const PREFIX: &str = "DevTools listening on ";
    let mut last_lines: Vec<String> = Vec::new();
    let mut sent = false;
    for line in BufReader::new(stderr).lines() {
        let Ok(line) = line else { break };
        if !sent {
            if let Some(address) = line.strip_prefix(PREFIX) {
                // The receiver is gone only where the start timed out.
                let _ = sender.send(Ok(address.trim().to_string()));
                sent = true;
            } else {
                last_lines.push(line);
                let excess = last_lines.len().saturating_sub(8);
                last_lines.drain(..excess);
            }
        }
    }
    if !sent {
        let _ = sender.send(Err(last_lines.join("\n")));
    }
}

/// A connection to the Chromium listening at `address`, and its version.
fn connect(address: String, timeout: Duration) -> Result<(Browser, String), Error> {
    let browser = Browser::connect_with_timeout(address, timeout)
        .map_err(|error| devtools_failure("connecting", error))?;
    let version = browser
        .get_version()
        .map_err(|error| devtools_failure("telling its version", error))?;
    let number = version
        .product
        .rsplit('/')
        .next()
        .unwrap_or(&version.product)
        .to_string();
    Ok((browser, format!("Chromium {number}")))
}

/// Asks `browser` its version every third of `timeout` until `closing`: the connection closes
/// after `timeout` without a message from Chromium, and a page at work sends none.
fn keep_busy(browser: &Browser, timeout: Duration, closing: &Arc<AtomicBool>) {
    let (browser, closing) = (browser.clone(), Arc::clone(closing));
    std::thread::spawn(move || {
        while !closing.load(Ordering::Relaxed) {
            std::thread::sleep(timeout / 3);
            if closing.load(Ordering::Relaxed) || browser.get_version().is_err() {
                break;
            }
        }
    });
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
