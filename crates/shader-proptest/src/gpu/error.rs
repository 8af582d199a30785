//! The harness's error type: everything that can keep a check or a program from running on the
//! device, which every part of the device side returns.

use crate::layout::LayoutError;
use ash::vk;
use std::fmt;

/// Everything that can keep a check or a program from running on the device.
#[derive(Clone, Debug)]
pub enum Error {
    /// No usable Vulkan loader, layer, device or device feature; the message says what is missing.
    Setup(String),
    /// A Vulkan call failed.
    Vulkan(&'static str, vk::Result),
    /// A shader failed to compile: the compiler's message and the source.
    Compile(String),
    /// A `pod` struct's Rust layout is not the shader's: the comparison, field by field.
    Layout(LayoutError),
    /// The Rust types of a check are not those of the shader function: both, in their terms.
    Signature(String),
    /// The validation layer reported messages (each one fails the run).
    Validation(Vec<String>),
    /// A browser's WebGPU reported errors during a run (an error scope's, an uncaptured error,
    /// the device's loss): each one fails the run, as the validation layer's messages do.
    WebGpu(Vec<String>),
    /// A browser did not start, or a page in it threw or did not answer in time: what failed.
    Browser(String),
    /// A batch is larger than one dispatch can hold.
    BatchTooLarge(usize),
    /// A check's strategy produced no value: proptest's reason.
    Strategy(String),
    /// A [`crate::RunConfig`] field (or the environment variable standing in for it) holds a value
    /// no run can use.
    Config {
        /// The field or variable.
        field: &'static str,
        /// Its value, as given.
        value: String,
        /// What it should be.
        expected: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Setup(message) => write!(f, "{message}"),
            Error::Vulkan(call, result) => write!(f, "{call} failed: {result}"),
            Error::Compile(message) => write!(f, "shader compilation failed:\n{message}"),
            Error::Layout(error) => write!(f, "the Rust and shader layouts differ: {error}"),
            Error::Signature(message) => write!(f, "{message}"),
            Error::Validation(messages) => {
                write!(
                    f,
                    "the Vulkan validation layer reported {} message(s):",
                    messages.len()
                )?;
                messages.iter().try_for_each(|m| write!(f, "\n  {m}"))
            }
            Error::WebGpu(messages) => {
                write!(f, "WebGPU reported {} message(s):", messages.len())?;
                messages.iter().try_for_each(|m| write!(f, "\n  {m}"))
            }
            Error::Browser(message) => write!(f, "{message}"),
            Error::BatchTooLarge(cases) => write!(f, "a batch of {cases} cases does not fit in one dispatch"),
            Error::Strategy(reason) => write!(f, "no cases: {reason}"),
            Error::Config {
                field,
                value,
                expected,
            } => write!(f, "{field} = {value:?}: expected {expected}"),
        }
    }
}

impl std::error::Error for Error {}

/// Maps a failed Vulkan call's result to [`Error::Vulkan`] naming the call.
pub fn vulkan(call: &'static str) -> impl FnOnce(vk::Result) -> Error {
    move |result| Error::Vulkan(call, result)
}
