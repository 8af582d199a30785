//! The browser tests, in one binary: headless Chromium's WebGPU (Tint compiling the WGSL, on
//! Chromium's adapter: SwiftShader here) with every WebGPU message failing a test.
//!
//! - [`agreement`]: every f32 WGSL function against its Rust mirror, the records' own agreement
//!   checks; the f64 module's are reported as not run.

mod agreement;

use shader_proptest::BrowserDevice;

/// The command that installs what the browser tests need on Debian 12.
const SETUP_COMMAND: &str = "scripts/setup.sh";

/// Chromium's WebGPU device; panics with what to install when there is none (a browser test
/// never passes by skipping).
fn browser() -> BrowserDevice {
    BrowserDevice::new().unwrap_or_else(|error| panic!("{error}\non Debian 12 run `{SETUP_COMMAND}`"))
}
