//! The browser tests, in one binary: headless Chromium's WebGPU (Tint compiling the WGSL, on
//! Chromium's adapter: SwiftShader here) with every WebGPU message failing a test.
//!
//! - [`agreement`]: every f32 WGSL function against its Rust mirror, the records' own agreement
//!   checks; the f64 module's are reported as not run;
//! - [`page`]: the demo page (`web/`), each mode's screenshot against lavapipe's rendering of the
//!   same shader, with FLIP.

mod agreement;
mod page;

use shader_proptest::{BrowserDevice, ChromiumOptions};

/// The command that installs what the browser tests need on Debian 12.
const SETUP_COMMAND: &str = "scripts/setup.sh";

/// Chromium's WebGPU device; panics with what to install when there is none (a browser test
/// never passes by skipping).
fn browser() -> BrowserDevice {
    BrowserDevice::with_options(&browser_options())
        .unwrap_or_else(|error| panic!("{error}\non Debian 12 run `{SETUP_COMMAND}`"))
}

/// How the tests start Chromium: the default executable and timeout.
fn browser_options() -> ChromiumOptions {
    ChromiumOptions::default()
}
