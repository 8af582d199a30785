//! Devices that take a check's kernel as WGSL text (wgpu, a browser's WebGPU): the check compares
//! layouts and signatures and compiles the kernel with naga as on the Vulkan path, then hands the
//! WGSL to the device, which compiles it again with its own compiler and rules.

use super::check::{FunctionCheck, PreparedCheck};
use super::compute::Dispatch;
use super::error::Error;
use super::phases::{Phase, PhaseTimes};
use crate::shader::{Feature, Shader};
use crate::value::{Args, Value};
use std::time::Instant;

/// What a check needs of a device that takes WGSL.
pub(crate) trait WgslDevice {
    /// Who takes the WGSL, for the refusal of other languages: `wgpu`, `WebGPU`.
    const TAKER: &'static str;
    /// The device for reports.
    fn description(&self) -> String;
    /// The first of `features` the device lacks, as a reason.
    fn missing_feature(&self, features: &[Feature]) -> Option<String>;
    /// The device's pipeline of the WGSL `kernel`; a kernel its compiler rejects is
    /// [`Error::Compile`].
    fn pipeline<'g>(&'g self, kernel: &str) -> Result<Box<dyn Dispatch + 'g>, Error>;
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// [`FunctionCheck::prepare`] on a device that takes WGSL: layouts, signature and naga's
    /// compilation, then the device's pipeline. A shader in another language is
    /// [`Error::Setup`].
    pub(in crate::gpu) fn prepare_wgsl<'g, D: WgslDevice>(
        &self,
        device: &'g D,
        shader: &Shader,
    ) -> Result<PreparedCheck<'g>, Error> {
        if shader.language() != crate::Language::Wgsl {
            return Err(Error::Setup(format!(
                "{} takes WGSL; run {} checks on a Gpu",
                D::TAKER,
                shader.language()
            )));
        }
        let started = Instant::now();
        let (mut clock, mut times) = (started, PhaseTimes::default());
        let kernel = self.kernel(shader);
        let pipeline = match device.missing_feature(shader.features()) {
            Some(reason) => Err(reason),
            None => {
                self.compile(shader, &kernel)?;
                times.lap(Phase::Compile, &mut clock);
                let pipeline = device.pipeline(&kernel)?;
                times.lap(Phase::Pipeline, &mut clock);
                Ok(pipeline)
            }
        };
        Ok(PreparedCheck::new(
            shader,
            device.description(),
            kernel,
            pipeline,
            (started, times),
        ))
    }
}
