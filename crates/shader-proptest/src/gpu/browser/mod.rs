//! WGSL checks in a browser (feature `browser`): headless Chromium's WebGPU, where WGSL is
//! compiled by Tint (Dawn's compiler, not naga) and runs on Chromium's adapter (SwiftShader's
//! Vulkan on a machine without a GPU).
//!
//! [`BrowserDevice`] serves a runner page on a loopback HTTP server, starts Chromium
//! ([`Chromium`], driven over the DevTools protocol on its debugging pipe, `devtools.rs`) and opens
//! the page, which asks for an adapter and a device. From then on the page takes jobs from the
//! server and posts their answers there, as bytes: a kernel's WGSL to compile (Tint), a batch's
//! input words to run, its output words back; no number is ever written as text, and no batch
//! goes through the DevTools protocol, which only opens the page. A check compares layouts and
//! signatures and compiles its kernel with naga as on the Vulkan path before the page compiles it
//! again.
//!
//! The protocol is spoken here, over the pipe Chromium offers (`--remote-debugging-pipe`), with
//! `serde_json` and nothing else: the harness needs a few of its commands (the version, a new
//! target, attaching to it, navigating, evaluating a script, a screenshot), synchronously as the
//! harness runs, and a client crate with the whole protocol's types took longer to build than
//! the rest of the feature.
//!
//! Tint's warnings and errors (`getCompilationInfo`) and a pipeline WebGPU refuses fail the
//! check's preparation ([`Error::Compile`]); a WebGPU error during a batch (error scopes around
//! every call), an uncaptured error or the device's loss fail the run ([`Error::WebGpu`]), as the
//! validation layer's messages do on Vulkan. Chromium's start waits at most
//! [`ChromiumOptions::start_timeout`], and every job and DevTools call after it at most
//! [`ChromiumOptions::timeout`] (30 s each unless set): a page that does not answer is
//! [`Error::Browser`], never a hang.

#[cfg(not(unix))]
compile_error!("the `browser` feature drives Chromium over its debugging pipe, on Unix only");

mod chromium;
mod devtools;
mod server;

pub use chromium::{BrowserPage, Chromium, ChromiumOptions, CHROMIUM_ENV};
pub use server::{Handler, LoopbackServer, Request, Response};

use super::check::{Check, FunctionCheck, PreparedCheck, Report, RunConfig};
use super::compute::{Dispatch, KernelRun};
use super::error::Error;
use super::lock::lock;
use super::phases::{Phase, PhaseTimes};
use super::wgsl_device::WgslDevice;
use crate::shader::{Feature, Shader};
use crate::value::{Args, Value};
use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{channel, Sender};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// The runner page.
const RUNNER: &str = include_str!("runner.html");

/// Workgroups per dispatch that every WebGPU device allows (`maxComputeWorkgroupsPerDimension`).
const MAX_WORKGROUPS: u32 = 65_535;

/// A WebGPU device in headless Chromium: the runner page open on Chromium's adapter, and the
/// loopback server it takes kernels and batches from.
///
/// ```no_run
/// use shader_proptest::proptest::prelude::*;
/// use shader_proptest::{BrowserDevice, FunctionCheck, RunConfig, Shader};
///
/// let device = BrowserDevice::new()?;
/// let check = FunctionCheck::new("half", || (-1.0f32..1.0,), |(x,)| 0.5 * x);
/// let shader = Shader::wgsl("fn half(x: f32) -> f32 { return 0.5 * x; }");
/// let report = check.run_browser(&device, &shader, &RunConfig::default())?;
/// println!("{report}"); // ... on swiftshader (google) through Chromium 156.0.8078.108 WebGPU
/// report.assert_passed();
/// # Ok::<(), shader_proptest::Error>(())
/// ```
pub struct BrowserDevice {
    // Dropped in this order: the page, then Chromium, then the server the page used.
    _page: BrowserPage,
    chromium: Chromium,
    _server: LoopbackServer,
    exchange: Arc<Exchange>,
    description: String,
    timeout: Duration,
    next_kernel: AtomicU64,
}

impl BrowserDevice {
    /// Chromium with [`ChromiumOptions::default`], its adapter and a device on it.
    pub fn new() -> Result<BrowserDevice, Error> {
        BrowserDevice::with_options(&ChromiumOptions::default())
    }

    /// Chromium started with `options`, its adapter and a device on it. [`Error::Setup`] when
    /// there is no Chromium (naming what to install) or no WebGPU adapter; [`Error::Browser`]
    /// when Chromium does not start within `options.start_timeout` or the page does not answer
    /// within `options.timeout`.
    pub fn with_options(options: &ChromiumOptions) -> Result<BrowserDevice, Error> {
        let exchange = Arc::new(Exchange::default());
        let server = {
            let exchange = Arc::clone(&exchange);
            LoopbackServer::start(0, move |request| exchange.answer(request))?
        };
        let chromium = Chromium::launch(options)?;
        let page = chromium.open(&server.url("/"))?;
        let adapter = page
            .evaluate("openDevice()")
            .map_err(|error| Error::Setup(format!("no WebGPU device in {}: {error}", chromium.version())))?;
        let description = format!("{} through {} WebGPU", adapter_name(&adapter), chromium.version());
        Ok(BrowserDevice {
            _page: page,
            chromium,
            _server: server,
            exchange,
            description,
            timeout: options.timeout,
            next_kernel: AtomicU64::new(0),
        })
    }

    /// The adapter and the browser: `swiftshader (google) through Chromium 156.0.8078.108 WebGPU`.
    pub fn description(&self) -> &str {
        &self.description
    }

    /// The Chromium the page runs in.
    pub fn chromium(&self) -> &Chromium {
        &self.chromium
    }

    /// Runs a job of `kind` on the runner page and waits for its result: WebGPU's messages are
    /// [`Error::WebGpu`], what the page threw and no answer within the timeout [`Error::Browser`].
    fn submit(&self, kind: &str, fields: serde_json::Value, bytes: Vec<u8>) -> Result<Vec<u8>, Error> {
        match self.exchange.submit(kind, fields, bytes, self.timeout)? {
            Answer::Done(result) => Ok(result),
            Answer::Failed(messages) => Err(Error::WebGpu(
                serde_json::from_slice(&messages)
                    .unwrap_or_else(|_| vec![String::from_utf8_lossy(&messages).into_owned()]),
            )),
            Answer::Threw(thrown) => Err(Error::Browser(format!(
                "the runner page threw: {}",
                String::from_utf8_lossy(&thrown)
            ))),
        }
    }
}

/// The adapter's name from the page's `adapter.info`: `architecture (vendor, device, description)`,
/// each where WebGPU gives it.
fn adapter_name(info: &serde_json::Value) -> String {
    let field = |name: &str| info[name].as_str().unwrap_or_default().to_string();
    let details: Vec<String> = ["vendor", "device", "description"]
        .iter()
        .map(|name| field(name))
        .filter(|value| !value.is_empty())
        .collect();
    format!("{} ({})", field("architecture"), details.join(", "))
}

impl WgslDevice for BrowserDevice {
    const TAKER: &'static str = "WebGPU";

    fn description(&self) -> String {
        self.description.clone()
    }

    /// WebGPU has none of the optional Vulkan features a shader may need.
    fn missing_feature(&self, features: &[Feature]) -> Option<String> {
        features.first().map(|feature| match feature {
            Feature::ShaderFloat64 => "WebGPU has no 64-bit floats".to_string(),
            other => format!("WebGPU has no {}", other.name()),
        })
    }

    fn pipeline<'g>(&'g self, kernel: &str) -> Result<Box<dyn Dispatch + 'g>, Error> {
        Ok(Box::new(BrowserKernel::new(self, kernel)?))
    }
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// Runs the check on the WGSL function of `shader` in the browser (see
    /// [`FunctionCheck::run`]). GLSL, Slang and HLSL shaders are refused ([`Error::Setup`]).
    pub fn run_browser(
        &self,
        device: &BrowserDevice,
        shader: &Shader,
        config: &RunConfig,
    ) -> Result<Report, Error> {
        Check::run_browser(self, device, shader, config)
    }

    /// [`FunctionCheck::prepare`] in the browser: layouts, signature, naga's compilation, then
    /// Tint's and the page's pipeline.
    pub fn prepare_browser<'g>(
        &self,
        device: &'g BrowserDevice,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error> {
        self.prepare_wgsl(device, shader)
    }
}

/// Longest a request for the next job waits for one before it is answered with none (the page
/// asks again at once).
const JOB_POLL: Duration = Duration::from_secs(1);

/// A job for the runner page: its description (JSON) and its bytes.
struct Job {
    description: serde_json::Value,
    bytes: Vec<u8>,
}

impl Job {
    /// The job as the page fetches it: the description's length as a little-endian u32, the
    /// description padded with spaces to a multiple of 4 bytes (so that the bytes after it can be
    /// copied as words), the bytes.
    fn encode(&self) -> Vec<u8> {
        let mut description = self.description.to_string().into_bytes();
        description.resize(description.len().next_multiple_of(4), b' ');
        let mut encoded = Vec::with_capacity(4 + description.len() + self.bytes.len());
        encoded.extend_from_slice(&(description.len() as u32).to_le_bytes());
        encoded.extend_from_slice(&description);
        encoded.extend_from_slice(&self.bytes);
        encoded
    }
}

/// How the page answered a job.
enum Answer {
    /// The job's result: a compile's messages as JSON, a batch's output words.
    Done(Vec<u8>),
    /// The WebGPU messages that failed a batch, as JSON.
    Failed(Vec<u8>),
    /// What the page threw.
    Threw(Vec<u8>),
}

/// The jobs waiting for the runner page, and the answers the harness waits for, by job.
#[derive(Default)]
struct Exchange {
    jobs: Mutex<VecDeque<Job>>,
    job_ready: Condvar,
    answers: Mutex<HashMap<u64, Sender<Answer>>>,
    next_job: AtomicU64,
}

impl Exchange {
    /// The page (`GET /`), the next job (`GET /job`) and the answers (`POST /done/<job>`,
    /// `/failed/<job>`, `/threw/<job>`).
    fn answer(&self, request: Request) -> Response {
        match (request.method.as_str(), request.path.as_str()) {
            ("GET", "/") => Response::ok("text/html; charset=utf-8", RUNNER),
            ("GET", "/job") => match self.take_job() {
                Some(job) => Response::ok("application/octet-stream", job.encode()),
                None => Response::no_content(),
            },
            ("POST", path) => self.deliver(path, request.body),
            _ => Response::not_found(&request.path),
        }
    }

    /// The next job, waiting up to [`JOB_POLL`] for one.
    fn take_job(&self) -> Option<Job> {
        let jobs = lock(&self.jobs);
        let (mut jobs, _) = self
            .job_ready
            .wait_timeout_while(jobs, JOB_POLL, |jobs| jobs.is_empty())
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        jobs.pop_front()
    }

    /// Hands the answer at `path` to whoever waits for it (nobody, once it has timed out).
    fn deliver(&self, path: &str, body: Vec<u8>) -> Response {
        let answer = |kind: &str| path.strip_prefix(kind).and_then(|job| job.parse::<u64>().ok());
        let (job, answer) = if let Some(job) = answer("/done/") {
            (job, Answer::Done(body))
        } else if let Some(job) = answer("/failed/") {
            (job, Answer::Failed(body))
        } else if let Some(job) = answer("/threw/") {
            (job, Answer::Threw(body))
        } else {
            return Response::not_found(path);
        };
        if let Some(waiting) = lock(&self.answers).remove(&job) {
            // The receiver is gone only where the harness stopped waiting.
            let _ = waiting.send(answer);
        }
        Response::ok("text/plain", "")
    }

    /// Queues a job of `kind` with `fields` and `bytes` and waits up to `timeout` for its answer.
    fn submit(
        &self,
        kind: &str,
        fields: serde_json::Value,
        bytes: Vec<u8>,
        timeout: Duration,
    ) -> Result<Answer, Error> {
        let job = self.next_job.fetch_add(1, Ordering::Relaxed);
        let mut description = fields;
        description["job"] = job.into();
        description["kind"] = kind.into();
        let (sender, receiver) = channel();
        lock(&self.answers).insert(job, sender);
        lock(&self.jobs).push_back(Job {
            description: description.clone(),
            bytes,
        });
        self.job_ready.notify_one();
        receiver.recv_timeout(timeout).map_err(|_| {
            lock(&self.answers).remove(&job);
            Error::Browser(format!(
                "the runner page did not answer the job {description} within {:.1} s",
                timeout.as_secs_f64()
            ))
        })
    }

    /// Queues a job of `kind` with `fields` whose answer nobody waits for.
    fn send(&self, kind: &str, fields: serde_json::Value) {
        let mut description = fields;
        description["job"] = self.next_job.fetch_add(1, Ordering::Relaxed).into();
        description["kind"] = kind.into();
        lock(&self.jobs).push_back(Job {
            description,
            bytes: Vec::new(),
        });
        self.job_ready.notify_one();
    }
}

/// A kernel's pipeline on the runner page, forgotten there when dropped.
struct BrowserKernel<'d> {
    device: &'d BrowserDevice,
    id: u64,
}

impl<'d> BrowserKernel<'d> {
    /// The page's pipeline of the WGSL `kernel`; Tint's messages are [`Error::Compile`].
    fn new(device: &'d BrowserDevice, kernel: &str) -> Result<BrowserKernel<'d>, Error> {
        let id = device.next_kernel.fetch_add(1, Ordering::Relaxed);
        let fields = serde_json::json!({ "kernel": id });
        let answer = device.submit("compile", fields, kernel.as_bytes().to_vec())?;
        let messages: Vec<String> = serde_json::from_slice(&answer)
            .map_err(|_| Error::Browser(format!("the runner page answered {answer:?} to a compile")))?;
        if !messages.is_empty() {
            return Err(Error::Compile(format!(
                "{} reported {} message(s) on the kernel:\n  {}\n--- kernel ---\n{kernel}",
                device.description,
                messages.len(),
                messages.join("\n  ")
            )));
        }
        Ok(BrowserKernel { device, id })
    }
}

impl Drop for BrowserKernel<'_> {
    fn drop(&mut self) {
        self.device
            .exchange
            .send("drop", serde_json::json!({ "kernel": self.id }));
    }
}

impl Dispatch for BrowserKernel<'_> {
    fn dispatch(&self, run: KernelRun<'_>, times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
        let mut clock = Instant::now();
        let groups = run.groups(MAX_WORKGROUPS)?;
        let input = bytemuck::cast_slice::<u32, u8>(run.input).to_vec();
        let fields = serde_json::json!({ "kernel": self.id, "groups": groups, "words": run.output_words });
        times.lap(Phase::Upload, &mut clock);
        let output = self.device.submit("run", fields, input)?;
        times.lap(Phase::Dispatch, &mut clock);
        if output.len() < run.output_words * 4 {
            return Err(Error::Browser(format!(
                "the runner page answered {} bytes for {} output words",
                output.len(),
                run.output_words
            )));
        }
        let words = output[..run.output_words * 4]
            .chunks_exact(4)
            .map(|word| u32::from_le_bytes([word[0], word[1], word[2], word[3]]))
            .collect();
        times.lap(Phase::ReadBack, &mut clock);
        Ok(words)
    }
}
