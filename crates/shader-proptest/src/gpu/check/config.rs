//! How many cases a check runs, how they are batched, and the seeds they are generated from.

use crate::gpu::error::Error;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// Environment variable that sets [`RunConfig::seed`] (decimal, or hexadecimal after `0x`), to
/// replay a run.
pub const SEED_ENV: &str = "SHADER_PROPTEST_SEED";

/// How many cases a check runs, how they are batched and generated.
///
/// ```
/// use shader_proptest::RunConfig;
///
/// // A quick run that replays the same cases every time.
/// let config = RunConfig {
///     cases: 10_000,
///     seed: Some(7),
///     ..RunConfig::default()
/// };
/// assert_eq!(config.validate()?, 7);
/// let nothing = RunConfig { cases: 0, ..config };
/// assert_eq!(nothing.validate().unwrap_err().to_string(), "cases = \"0\": expected at least 1");
/// # Ok::<(), shader_proptest::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct RunConfig {
    /// At least this many cases are checked (before any shrinking).
    pub cases: usize,
    /// Cases per batch (one dispatch).
    pub batch: usize,
    /// The seed of the run; batch `i` is generated from a seed derived from it and `i`. `None`: the
    /// seed in [`SEED_ENV`] if that is set, else a fresh seed; either is printed in the report.
    pub seed: Option<u64>,
    /// Threads that generate cases and run the mirror.
    pub threads: usize,
    /// Most dispatches shrinking may take after a failure (each runs many candidates).
    pub shrink_steps: usize,
}

impl Default for RunConfig {
    /// 100,000 cases in batches of 8,192, the seed from [`SEED_ENV`] if set (else fresh), one
    /// thread per processor, up to 1,024 shrinking dispatches.
    fn default() -> Self {
        RunConfig {
            cases: 100_000,
            batch: 8192,
            seed: None,
            threads: std::thread::available_parallelism().map_or(1, usize::from),
            shrink_steps: 1024,
        }
    }
}

impl RunConfig {
    /// The configuration as a run uses it: [`Error::Config`] names the first field that is 0
    /// (`cases`, `batch`, `threads`: a run of nothing, or one no thread generates), or
    /// [`SEED_ENV`] with its value where `seed` is `None` and that variable holds no seed.
    /// Otherwise the seed the run uses: `seed`, else the variable's, else a fresh one.
    pub fn validate(&self) -> Result<u64, Error> {
        let counts = [
            ("cases", self.cases),
            ("batch", self.batch),
            ("threads", self.threads),
        ];
        if let Some(&(field, _)) = counts.iter().find(|(_, count)| *count == 0) {
            return Err(Error::Config {
                field,
                value: "0".into(),
                expected: "at least 1",
            });
        }
        run_seed(self.seed, std::env::var(SEED_ENV).ok())
    }
}

/// The seed of a run: `seed`, else the one in `variable` (the value of [`SEED_ENV`]), else a fresh
/// one; [`Error::Config`] where `variable` holds no seed.
fn run_seed(seed: Option<u64>, variable: Option<String>) -> Result<u64, Error> {
    match (seed, variable) {
        (Some(seed), _) => Ok(seed),
        (None, Some(text)) => parse_seed(&text).ok_or(Error::Config {
            field: SEED_ENV,
            value: text,
            expected: "a decimal seed, or a hexadecimal one after 0x",
        }),
        (None, None) => Ok(fresh_seed()),
    }
}

fn parse_seed(text: &str) -> Option<u64> {
    match text.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

/// A seed no earlier run used: the clock's nanoseconds mixed with the process id.
fn fresh_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |elapsed| elapsed.as_nanos() as u64);
    splitmix(nanos ^ u64::from(std::process::id()).rotate_left(32))
}

/// SplitMix64's finaliser: spreads the bits of `x`.
pub(super) fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The proptest runner that generates batch `batch` of a run seeded with `seed`.
pub(super) fn batch_runner(seed: u64, batch: usize) -> TestRunner {
    let first = splitmix(seed ^ splitmix(batch as u64));
    let mut bytes = [0u8; 16];
    bytes[..8].copy_from_slice(&first.to_le_bytes());
    bytes[8..].copy_from_slice(&splitmix(first).to_le_bytes());
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::XorShift, &bytes),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run of 0 cases, batches of 0 or 0 threads is refused, naming the field and the value.
    #[test]
    fn zero_counts_are_refused_naming_the_field() {
        let zero_cases = RunConfig {
            cases: 0,
            ..RunConfig::default()
        };
        let zero_batch = RunConfig {
            batch: 0,
            ..RunConfig::default()
        };
        let zero_threads = RunConfig {
            threads: 0,
            ..RunConfig::default()
        };
        for (config, field) in [
            (zero_cases, "cases"),
            (zero_batch, "batch"),
            (zero_threads, "threads"),
        ] {
            let message = config.validate().expect_err(field).to_string();
            assert_eq!(message, format!("{field} = \"0\": expected at least 1"));
        }
    }

    /// The seed comes from the configuration, else from the variable; a variable that holds no
    /// seed is refused, naming the variable and its value.
    #[test]
    fn the_seed_variable_must_hold_a_seed() {
        assert_eq!(run_seed(Some(5), Some("banana".into())).ok(), Some(5));
        assert_eq!(run_seed(None, Some("0x1f".into())).ok(), Some(31));
        assert_eq!(run_seed(None, Some("31".into())).ok(), Some(31));
        for text in ["banana", "", "0x", "-1", "0x1g"] {
            let message = run_seed(None, Some(text.into())).expect_err(text).to_string();
            assert!(
                message.starts_with(&format!("{SEED_ENV} = {text:?}")),
                "{message}"
            );
        }
    }
}
