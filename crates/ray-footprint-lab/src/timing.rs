//! GPU timing that holds when it is measured again: what the benches `mode_costs` and
//! `function_costs` share.
//!
//! - Timestamps in a query pool, one pair per timed piece of work, all of a round's work recorded
//!   into one command buffer and submitted at once, so the GPU is never idle between two frames
//!   and the CPU never waits inside a round ([`Timestamps`], [`query_pool`], [`read_queries`]).
//! - Warm-up until two successive medians agree within [`SETTLED`] ([`warm_up`]): a GPU starts a
//!   run at a low clock and raises it under load, and the first rounds time the clock, not the
//!   work.
//! - Rounds that time every variant, in one order in even rounds and the reverse in odd ones
//!   ([`round_order`]), so that neither a variant's place in a round nor a drifting clock favours
//!   one variant.
//! - Per variant the median of its round medians and their spread, smallest to largest
//!   ([`Spread`]); a verdict only where the two spreads do not overlap ([`verdict`]).
//! - The GPU's clocks from `nvidia-smi` at the start and the end of a run ([`gpu_clocks`]).
//!
//! [`function`] writes the kernels that time one shader function, [`peers`] those of the peers'
//! originals beside them.
//!
//! ```
//! use ray_footprint_lab::timing::{verdict, Spread, Verdict};
//!
//! let baseline = Spread::of(&[2.00, 2.02, 1.99, 2.01]);
//! let slower = Spread::of(&[2.30, 2.28, 2.31, 2.29]);
//! assert_eq!(verdict(&slower, &baseline), Verdict::Slower);
//! let close = Spread::of(&[2.01, 2.03, 1.98, 2.00]);
//! assert_eq!(verdict(&close, &baseline), Verdict::NotSeparable);
//! ```

pub mod function;
pub mod peers;

use ash::vk;
use shader_proptest::{vulkan, Error, Gpu, Object, Owner};
use std::process::Command;
use std::time::Duration;

/// Largest relative change between two successive warm-up medians at which the GPU counts as
/// settled: 2%.
pub const SETTLED: f64 = 0.02;

/// The device's timestamps: nanoseconds per tick and the bits that count.
#[derive(Clone, Copy, Debug)]
pub struct Timestamps {
    period_ns: f64,
    valid_bits: u32,
}

impl Timestamps {
    /// The timestamps of `gpu`'s queue, or why it has none (a reason to report the timing as not
    /// run).
    pub fn of(gpu: &Gpu) -> Result<Timestamps, String> {
        let limits = gpu.properties().limits;
        // SAFETY: a plain query.
        let families = unsafe {
            gpu.instance()
                .get_physical_device_queue_family_properties(gpu.physical_device())
        };
        let valid_bits = families
            .get(gpu.queue_family() as usize)
            .map_or(0, |family| family.timestamp_valid_bits);
        if valid_bits == 0 {
            let compute_and_graphics = limits.timestamp_compute_and_graphics == vk::TRUE;
            return Err(format!(
                "{}: queue family {} has timestampValidBits 0 (timestampComputeAndGraphics {compute_and_graphics})",
                gpu.name(),
                gpu.queue_family()
            ));
        }
        Ok(Timestamps {
            period_ns: f64::from(limits.timestamp_period),
            valid_bits,
        })
    }

    /// The time between two timestamps, counting only the valid bits (which may wrap).
    pub fn elapsed(self, start: u64, end: u64) -> Duration {
        let mask = if self.valid_bits >= 64 {
            u64::MAX
        } else {
            (1u64 << self.valid_bits) - 1
        };
        let ticks = end.wrapping_sub(start) & mask;
        Duration::from_secs_f64(ticks as f64 * self.period_ns * 1e-9)
    }

    /// The times between the timestamps of each pair `(2k, 2k + 1)` of `ticks`.
    pub fn pairs(self, ticks: &[u64]) -> Vec<Duration> {
        ticks
            .chunks_exact(2)
            .map(|pair| self.elapsed(pair[0], pair[1]))
            .collect()
    }
}

/// A pool of `count` timestamp queries, kept by `owner`.
pub fn query_pool(owner: &mut Owner<'_>, count: u32) -> Result<vk::QueryPool, Error> {
    let info = vk::QueryPoolCreateInfo::default()
        .query_type(vk::QueryType::TIMESTAMP)
        .query_count(count);
    // SAFETY: a valid create-info; the pool is handed to the owner.
    let pool =
        unsafe { owner.device().create_query_pool(&info, None) }.map_err(vulkan("vkCreateQueryPool"))?;
    Ok(owner.keep(pool, Object::QueryPool))
}

/// Records, into `command_buffer` (recording), a timestamp into query `query` of `pool` once every
/// command recorded before it has completed.
///
/// # Safety
/// `command_buffer` must be recording and `pool` alive, with query `query` reset before.
pub unsafe fn write_timestamp(
    device: &ash::Device,
    command_buffer: vk::CommandBuffer,
    pool: vk::QueryPool,
    query: u32,
) {
    // SAFETY: the caller's guarantees.
    unsafe {
        device.cmd_write_timestamp(
            command_buffer,
            vk::PipelineStageFlags::BOTTOM_OF_PIPE,
            pool,
            query,
        )
    }
}

/// The first `count` timestamps of `pool`, after the submission that wrote them was waited for.
pub fn read_queries(owner: &Owner<'_>, pool: vk::QueryPool, count: usize) -> Result<Vec<u64>, Error> {
    let mut ticks = vec![0u64; count];
    // SAFETY: the submission that wrote the queries was waited for; `ticks` holds `count` results.
    unsafe {
        owner.device().get_query_pool_results(
            pool,
            0,
            &mut ticks,
            vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
        )
    }
    .map_err(vulkan("vkGetQueryPoolResults"))?;
    Ok(ticks)
}

/// The median of `values` (the mean of the middle two for an even count); 0 for none.
pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let middle = sorted.len() / 2;
    match sorted.len() {
        0 => 0.0,
        n if n.is_multiple_of(2) => 0.5 * (sorted[middle - 1] + sorted[middle]),
        _ => sorted[middle],
    }
}

/// The medians of one variant's rounds: their median and their spread, smallest to largest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    /// Median of the round medians.
    pub median: f64,
    /// Smallest round median.
    pub min: f64,
    /// Largest round median.
    pub max: f64,
}

impl Spread {
    /// The spread of `round_medians`.
    pub fn of(round_medians: &[f64]) -> Spread {
        Spread {
            median: median(round_medians),
            min: round_medians.iter().copied().fold(f64::INFINITY, f64::min),
            max: round_medians.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        }
    }

    /// The spread of `self - baseline` over every pair of their round medians: the median
    /// difference, and from `self.min - baseline.max` to `self.max - baseline.min`.
    pub fn minus(&self, baseline: &Spread) -> Spread {
        Spread {
            median: self.median - baseline.median,
            min: self.min - baseline.max,
            max: self.max - baseline.min,
        }
    }
}

/// How a variant compares with a baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Every round median of the variant is above every round median of the baseline.
    Slower,
    /// Every round median of the variant is below every round median of the baseline.
    Faster,
    /// The spreads overlap: the difference is within the rounds' variation at this load.
    NotSeparable,
}

/// Whether `variant` differs from `baseline` by more than their spreads: only where the ranges of
/// round medians do not overlap.
pub fn verdict(variant: &Spread, baseline: &Spread) -> Verdict {
    if variant.min > baseline.max {
        Verdict::Slower
    } else if variant.max < baseline.min {
        Verdict::Faster
    } else {
        Verdict::NotSeparable
    }
}

/// The order of `count` variants in round `round`: in order in even rounds, reversed in odd ones.
pub fn round_order(count: usize, round: usize) -> Vec<usize> {
    if round.is_multiple_of(2) {
        (0..count).collect()
    } else {
        (0..count).rev().collect()
    }
}

/// How the warm-up went: each batch's median, and whether the last two agreed within
/// [`SETTLED`].
#[derive(Clone, Debug, PartialEq)]
pub struct WarmUp {
    /// The median of each batch, in order.
    pub medians: Vec<f64>,
    /// Whether the last two medians agreed within [`SETTLED`].
    pub settled: bool,
}

/// Runs `batch` (which does a batch of the work and returns its median time) until two successive
/// medians agree within [`SETTLED`], or `max_batches` ran.
pub fn warm_up<E>(max_batches: usize, mut batch: impl FnMut() -> Result<f64, E>) -> Result<WarmUp, E> {
    let mut medians: Vec<f64> = Vec::new();
    while medians.len() < max_batches.max(2) {
        medians.push(batch()?);
        if let [.., previous, last] = medians[..] {
            if (last - previous).abs() <= SETTLED * previous.abs() {
                return Ok(WarmUp {
                    medians,
                    settled: true,
                });
            }
        }
    }
    Ok(WarmUp {
        medians,
        settled: false,
    })
}

/// The GPU's SM and memory clocks as `nvidia-smi --query-gpu=clocks.sm,clocks.mem
/// --format=csv,noheader` prints them (one line per GPU), or `not available` where it does not run.
pub fn gpu_clocks() -> String {
    let output = Command::new("nvidia-smi")
        .args(["--query-gpu=clocks.sm,clocks.mem", "--format=csv,noheader"])
        .output();
    match output {
        Ok(output) if output.status.success() => {
            let text = String::from_utf8_lossy(&output.stdout);
            let lines: Vec<&str> = text.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
            if lines.is_empty() {
                String::from("not available (nvidia-smi printed nothing)")
            } else {
                format!("SM, memory: {}", lines.join("; "))
            }
        }
        Ok(output) => format!("not available (nvidia-smi exited with {})", output.status),
        Err(error) => format!("not available ({error})"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(&[]), 0.0);
    }

    #[test]
    fn rounds_alternate_their_order() {
        assert_eq!(round_order(3, 0), [0, 1, 2]);
        assert_eq!(round_order(3, 1), [2, 1, 0]);
        assert_eq!(round_order(3, 2), [0, 1, 2]);
    }

    #[test]
    fn a_verdict_needs_spreads_that_do_not_overlap() {
        let baseline = Spread::of(&[1.0, 1.1, 1.05]);
        assert_eq!(verdict(&Spread::of(&[1.2, 1.3]), &baseline), Verdict::Slower);
        assert_eq!(verdict(&Spread::of(&[0.8, 0.95]), &baseline), Verdict::Faster);
        assert_eq!(
            verdict(&Spread::of(&[1.1, 1.3]), &baseline),
            Verdict::NotSeparable
        );
        let added = Spread::of(&[1.2, 1.3]).minus(&baseline);
        assert!((added.min - 0.1).abs() < 1e-12 && (added.max - 0.3).abs() < 1e-12);
    }

    #[test]
    fn warm_up_stops_when_two_medians_agree() {
        // 2.1 to 2.05 is 2.4%: one more batch.
        let mut clock_ramp = [4.25, 3.0, 2.1, 2.05, 2.06].into_iter();
        let warm = warm_up(10, || Ok::<f64, ()>(clock_ramp.next().unwrap_or(2.05))).unwrap();
        assert_eq!(warm.medians, [4.25, 3.0, 2.1, 2.05, 2.06]);
        assert!(warm.settled);
        let mut drifting = (1..).map(|k| k as f64);
        let unsettled = warm_up(4, || Ok::<f64, ()>(drifting.next().unwrap_or(0.0))).unwrap();
        assert_eq!(unsettled.medians.len(), 4);
        assert!(!unsettled.settled);
    }
}
