//! WGSL checks in a browser (feature `browser`): headless Chromium's WebGPU, where WGSL is
//! compiled by Tint (Dawn's compiler, not naga) and runs on Chromium's adapter (SwiftShader's
//! Vulkan on a machine without a GPU).
//!
//! [`BrowserDevice`] serves a runner page on a loopback HTTP server, starts Chromium
//! ([`Chromium`], driven over the DevTools protocol through the `headless_chrome` crate: a
//! synchronous client, as the harness is, with no async runtime) and opens the page, which asks
//! for an adapter and a device. A check compares layouts and signatures and compiles its kernel
//! with naga as on the Vulkan path; the page then fetches the kernel's WGSL and compiles it with
//! Tint. Each batch is one DevTools call, `runBatch(kernel, batch, groups, words)`, of a few
//! bytes: the page fetches the batch's input words from the server as bytes, dispatches, and
//! posts the output words back as bytes, so no number is ever written as text.
//!
//! Tint's warnings and errors (`getCompilationInfo`) and a pipeline WebGPU refuses fail the
//! check's preparation ([`Error::Compile`]); a WebGPU error during a batch (error scopes around
//! every call), an uncaptured error or the device's loss fail the run ([`Error::WebGpu`]), as the
//! validation layer's messages do on Vulkan. Every DevTools call waits at most
//! [`ChromiumOptions::timeout`] (30 s unless set): a page that does not answer is
//! [`Error::Browser`], never a hang.

mod chromium;
mod server;

pub use chromium::{BrowserPage, Chromium, ChromiumOptions, CHROMIUM_ENV};
pub use server::{Handler, LoopbackServer, Request, Response};

use super::check::{Check, FunctionCheck, PreparedCheck, Report, RunConfig};
use super::compute::{Dispatch, KernelRun};
use super::device::Error;
use super::lock;
use super::phases::{Phase, PhaseTimes};
use super::wgsl_device::WgslDevice;
use crate::shader::{Feature, Shader};
use crate::value::{Args, Value};
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

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
    page: BrowserPage,
    chromium: Chromium,
    _server: LoopbackServer,
    exchange: Arc<Exchange>,
    description: String,
    next_id: AtomicU64,
}

impl BrowserDevice {
    /// Chromium with [`ChromiumOptions::default`], its adapter and a device on it.
    pub fn new() -> Result<BrowserDevice, Error> {
        BrowserDevice::with_options(&ChromiumOptions::default())
    }

    /// Chromium started with `options`, its adapter and a device on it. [`Error::Setup`] when
    /// there is no Chromium (naming what to install) or no WebGPU adapter; [`Error::Browser`]
    /// when Chromium or the page does not answer within `options.timeout`.
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
            page,
            chromium,
            _server: server,
            exchange,
            description,
            next_id: AtomicU64::new(0),
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

    /// Evaluates `call`, a function of the runner page that resolves to WebGPU's messages.
    fn messages(&self, call: &str) -> Result<Vec<String>, Error> {
        let answer = self.page.evaluate(call)?;
        serde_json::from_value(answer.clone())
            .map_err(|_| Error::Browser(format!("the runner page answered {answer} to `{call}`")))
    }

    /// A number no kernel or batch of this device had.
    fn next_id(&self) -> u64 {
        self.next_id.fetch_add(1, Ordering::Relaxed)
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

/// What the runner page's server hands out and takes in: kernels' WGSL and batches' input words,
/// by id, until taken back; batches' output words, until the dispatch takes them.
#[derive(Default)]
struct Exchange {
    kernels: Mutex<HashMap<u64, String>>,
    inputs: Mutex<HashMap<u64, Vec<u8>>>,
    outputs: Mutex<HashMap<u64, Vec<u8>>>,
}

impl Exchange {
    /// The page, `GET /kernel/<id>`, `GET /input/<id>` and `POST /output/<id>`.
    fn answer(&self, request: Request) -> Response {
        if request.path == "/" {
            return Response::ok("text/html; charset=utf-8", RUNNER);
        }
        let (kind, id) = match request.path.rsplit_once('/') {
            Some((kind, id)) => (kind, id.parse::<u64>().ok()),
            None => ("", None),
        };
        match (request.method.as_str(), kind, id) {
            ("GET", "/kernel", Some(id)) => match lock(&self.kernels).get(&id) {
                Some(kernel) => Response::ok("text/plain; charset=utf-8", kernel.as_bytes()),
                None => Response::not_found(&request.path),
            },
            ("GET", "/input", Some(id)) => match lock(&self.inputs).get(&id) {
                Some(input) => Response::ok("application/octet-stream", input.as_slice()),
                None => Response::not_found(&request.path),
            },
            ("POST", "/output", Some(id)) => {
                lock(&self.outputs).insert(id, request.body);
                Response::ok("text/plain", "")
            }
            _ => Response::not_found(&request.path),
        }
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
        let id = device.next_id();
        lock(&device.exchange.kernels).insert(id, kernel.to_string());
        let messages = device.messages(&format!("compileKernel({id})"));
        lock(&device.exchange.kernels).remove(&id);
        let messages = messages?;
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
        // The page forgets the pipeline; a page that no longer answers has forgotten it already.
        let _ = self.device.page.evaluate(&format!("dropKernel({})", self.id));
    }
}

impl Dispatch for BrowserKernel<'_> {
    fn dispatch(&self, run: KernelRun<'_>, times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
        let mut clock = Instant::now();
        let groups = run.groups(MAX_WORKGROUPS)?;
        let exchange = &self.device.exchange;
        let batch = self.device.next_id();
        let input: &[u8] = bytemuck::cast_slice(run.input);
        lock(&exchange.inputs).insert(batch, input.to_vec());
        times.lap(Phase::Upload, &mut clock);
        let call = format!("runBatch({}, {batch}, {groups}, {})", self.id, run.output_words);
        let messages = self.device.messages(&call);
        lock(&exchange.inputs).remove(&batch);
        let output = lock(&exchange.outputs).remove(&batch);
        let messages = messages?;
        if !messages.is_empty() {
            return Err(Error::WebGpu(messages));
        }
        times.lap(Phase::Dispatch, &mut clock);
        let output = output
            .filter(|bytes| bytes.len() >= run.output_words * 4)
            .ok_or_else(|| {
                Error::Browser(format!(
                    "the runner page posted no output of {} words for `{call}`",
                    run.output_words
                ))
            })?;
        let words = output[..run.output_words * 4]
            .chunks_exact(4)
            .map(|word| u32::from_le_bytes([word[0], word[1], word[2], word[3]]))
            .collect();
        times.lap(Phase::ReadBack, &mut clock);
        Ok(words)
    }
}
