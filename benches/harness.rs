//! How many GPU-verified function evaluations per second the harness achieves for `rf_texture_lod`:
//! generate a batch, upload it, dispatch once, read back, compare every case with the Rust mirror.
//!
//! `cargo bench --all-features --bench harness`
//!
//! Prints, per language and batch size, the verified evaluations per second with two generators:
//! proptest (the strategy the agreement tests use) and a plain xorshift generator over the same
//! domain. The one-case-per-dispatch loop is the baseline that batching is measured against.

use glam::{Vec2, Vec3};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;
use ray_footprint::gpu::suite::ray_cone::{texture_lod, TextureLodArgs};
use ray_footprint::gpu::{FunctionCheck, Gpu, Language};
use std::time::{Duration, Instant};

/// Evaluations measured per configuration (at least one batch).
const EVALUATIONS: usize = 1 << 20;
/// Dispatches measured for the one-case-per-dispatch baseline.
const SINGLE_DISPATCHES: usize = 2000;

/// A small, fast generator: xorshift64*.
struct Xorshift(u64);

impl Xorshift {
    fn next_f32(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 40) as f32 / (1u64 << 24) as f32
    }

    fn range(&mut self, low: f32, high: f32) -> f32 {
        low + (high - low) * self.next_f32()
    }

    fn unit_vec3(&mut self) -> Vec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f32::consts::TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    }

    /// Arguments over the agreement strategy's domain: widths log-uniform in [1e-12, 1e12].
    fn texture_lod_args(&mut self) -> TextureLodArgs {
        let width = 10f32.powf(self.range(-12.0, 12.0));
        let size = Vec2::new(self.range(1.0, 16384.0).floor(), self.range(1.0, 16384.0).floor());
        (
            self.range(-20.0, 20.0),
            width,
            size,
            self.unit_vec3(),
            self.unit_vec3(),
        )
    }
}

enum Generator {
    Proptest(Box<TestRunner>),
    Xorshift(Xorshift),
}

impl Generator {
    fn batch(&mut self, check: &FunctionCheck<TextureLodArgs, f32>, size: usize) -> Vec<TextureLodArgs> {
        match self {
            Generator::Proptest(runner) => {
                let strategy = (check.strategy)();
                (0..size)
                    .map(|_| strategy.new_tree(runner).expect("strategy generates").current())
                    .collect()
            }
            Generator::Xorshift(rng) => (0..size).map(|_| rng.texture_lod_args()).collect(),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Generator::Proptest(_) => "proptest",
            Generator::Xorshift(_) => "xorshift",
        }
    }
}

/// Verified evaluations per second over `batches` dispatches of `batch` cases each.
fn rate(
    gpu: &Gpu,
    language: Language,
    generator: &mut Generator,
    batch: usize,
    batches: usize,
) -> (f64, Duration) {
    let check = texture_lod();
    let pipeline = check.pipeline(gpu, language).expect("kernel compiles");
    let started = Instant::now();
    for _ in 0..batches {
        let cases = generator.batch(&check, batch);
        let outcome = check.check_batch(gpu, &pipeline, &cases).expect("dispatch runs");
        if let Err(failure) = outcome {
            panic!("disagreement while benchmarking: {failure}");
        }
    }
    let elapsed = started.elapsed();
    gpu.destroy_pipeline(pipeline);
    ((batch * batches) as f64 / elapsed.as_secs_f64(), elapsed)
}

fn main() {
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    println!("device: {}; function: rf_texture_lod", gpu.name());
    for language in Language::ALL {
        let mut xorshift = Generator::Xorshift(Xorshift(0x9e37_79b9_7f4a_7c15));
        let (single, _) = rate(&gpu, language, &mut xorshift, 1, SINGLE_DISPATCHES);
        println!(
            "{:<5} one case per dispatch: {:>12.0} verified evaluations/s",
            language.name(),
            single
        );
        for batch in [1024, 16 * 1024, 64 * 1024, 256 * 1024] {
            for generator in [
                &mut Generator::Proptest(Box::new(TestRunner::deterministic())),
                &mut xorshift,
            ] {
                let batches = EVALUATIONS.div_ceil(batch);
                let (per_second, elapsed) = rate(&gpu, language, generator, batch, batches);
                println!(
                    "{:<5} batch {:>7} ({:<8}): {:>12.0} verified evaluations/s ({:>5.1}x one per dispatch; {} cases in {:.2} s)",
                    language.name(),
                    batch,
                    generator.name(),
                    per_second,
                    per_second / single,
                    batch * batches,
                    elapsed.as_secs_f64()
                );
            }
        }
    }
}
