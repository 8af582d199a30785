//! Independent references: each public function compared with something that is not its mirror.
//!
//! The agreement checks prove that the shaders and the Rust mirror give the same answers; they
//! cannot catch a mirror that is wrong in the same way as the shaders. A [`Reference`] compares the
//! mirror with an independent computation, in f64, over cases of its own:
//!
//! - [`Kind::ExactGeometry`]: the rays themselves, traced and intersected exactly (boundary and
//!   neighbour rays, a mirror-image camera);
//! - [`Kind::FiniteDifference`]: central differences in f64 of the exact map the function
//!   differentiates (re-intersection, Snell refraction, the eye-ray map of the matrices);
//! - [`Kind::ClosedForm`]: the same quantity computed another way (Heron's formula for an area, a
//!   matrix inverted in f64, a solid angle integrated numerically);
//! - [`Kind::Identity`]: what the function must satisfy (a round trip, an invariance, a limit case
//!   its source states);
//! - [`Kind::PeerOriginal`]: an implementation of the same formula from elsewhere.
//!
//! A reference's property returns the [`Deviation`] it measured and the bound that deviation must
//! stay within, derived next to it: the f32 rounding of the mirror against the f64 reference, plus,
//! where the function approximates (a small-angle form, a first-order cone), the approximation's
//! error bound. The runner ([`Reference::run`]) draws [`CASES`] cases from a fixed seed
//! ([`DEFAULT_SEED`], or [`SEED_ENV`]), shrinks a failing case to a minimal one and reports the
//! largest deviation as a share of its bound. [`crate::pages::proven_table`] writes the table of
//! `src/proven.md`.
//!
//! ```
//! use proptest::prelude::*;
//! use ray_footprint::ray_cone::{self as rc, RayCone};
//! use ray_footprint::shaders::Module;
//! use ray_footprint_cases::reference::{Deviation, Kind, Reference, DEFAULT_SEED, U};
//! use ray_footprint_cases::Record;
//!
//! let record = Record::new(
//!     Module::RayCone,
//!     "width_at",
//!     |(cone, t): (RayCone, f32)| rc::width_at(cone, t),
//!     || (0.0f32..1.0, 0.0f32..1.0, 0.0f32..10.0)
//!         .prop_map(|(width, spread_angle, t)| (RayCone { width, spread_angle }, t))
//!         .boxed(),
//! )
//! .reference(Reference::new(
//!     Kind::Identity,
//!     "a cone of spread 0 keeps its width",
//!     || (0.0f32..1.0, 0.0f32..10.0).boxed(),
//!     |&(width, t), width_at| {
//!         let got = width_at((RayCone { width, spread_angle: 0.0 }, t));
//!         // One product with 0 and one addition of 0: exact.
//!         Some(Deviation::within(f64::from(got), f64::from(width), 0.0))
//!     },
//! ));
//! let report = record.run_reference(0, DEFAULT_SEED);
//! assert!(report.outcome.is_ok(), "{report}");
//! # let _ = U;
//! ```

use proptest::strategy::BoxedStrategy;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use ray_footprint::shaders::Module;
use std::cell::Cell;
use std::fmt::{self, Debug};

/// Cases each reference runs (accepted cases: those its property does not leave out).
pub const CASES: u32 = 10_000;
/// The seed of a run when [`SEED_ENV`] is not set.
pub const DEFAULT_SEED: u64 = 0x7265_6665_7265_6e63;
/// Environment variable that replaces [`DEFAULT_SEED`] (decimal, or hexadecimal after `0x`), to run
/// the references on other cases.
pub const SEED_ENV: &str = "RAY_FOOTPRINT_REFERENCE_SEED";

/// The unit roundoff of f32, `2^-24`: a correctly rounded operation is off by at most this much
/// relative to its exact result.
pub const U: f64 = 1.0 / 16_777_216.0;

/// `gamma(n) = n u / (1 - n u)` (Higham, "Accuracy and Stability of Numerical Algorithms", Lemma
/// 3.1): `n` roundings of f32 change a product of their factors by at most this much, relative.
pub fn gamma(n: u32) -> f64 {
    let nu = f64::from(n) * U;
    nu / (1.0 - nu)
}

/// What an independent reference is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The rays traced and intersected exactly.
    ExactGeometry,
    /// Central differences in f64 of the exact map the function differentiates.
    FiniteDifference,
    /// The same quantity computed another way.
    ClosedForm,
    /// A property the function must satisfy (a round trip, an invariance, a stated limit case).
    Identity,
    /// An implementation of the same formula from elsewhere.
    PeerOriginal,
}

impl Kind {
    /// The kind in words, as the table of `src/proven.md` names it.
    pub fn name(self) -> &'static str {
        match self {
            Kind::ExactGeometry => "exact geometry",
            Kind::FiniteDifference => "f64 finite differences",
            Kind::ClosedForm => "closed form computed another way",
            Kind::Identity => "identity",
            Kind::PeerOriginal => "peer original",
        }
    }
}

/// A measured deviation from a reference and the bound it must stay within.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deviation {
    /// What was measured (`|mirror - reference|`, or a distance outside an interval).
    pub measured: f64,
    /// The largest deviation the derivation allows.
    pub bound: f64,
}

impl Deviation {
    /// No deviation, with no room: what a property that measured nothing returns.
    pub const NONE: Deviation = Deviation {
        measured: 0.0,
        bound: 0.0,
    };

    /// `measured` against `bound`.
    pub fn new(measured: f64, bound: f64) -> Deviation {
        Deviation { measured, bound }
    }

    /// `|got - expected|` against `bound`.
    pub fn within(got: f64, expected: f64, bound: f64) -> Deviation {
        Deviation::new((got - expected).abs(), bound)
    }

    /// The distance of `value` from the interval `[low, high]` measured from its centre: within
    /// the bound (the half-width) exactly when `value` lies in the interval.
    pub fn in_interval(value: f64, low: f64, high: f64) -> Deviation {
        Deviation::new((value - 0.5 * (low + high)).abs(), 0.5 * (high - low))
    }

    /// The deviation as a share of its bound: 0 when both are 0, infinite when only the bound is.
    pub fn share(self) -> f64 {
        if self.measured == 0.0 {
            0.0
        } else if self.bound > 0.0 {
            self.measured / self.bound
        } else {
            f64::INFINITY
        }
    }

    /// Whether the deviation stays within its bound (a NaN never does).
    pub fn holds(self) -> bool {
        self.measured <= self.bound
    }

    /// Of `self` and `other`, the deviation that uses the larger share of its bound, or the one
    /// that does not hold.
    pub fn and(self, other: Deviation) -> Deviation {
        if !other.holds() || (self.holds() && other.share() > self.share()) {
            other
        } else {
            self
        }
    }

    /// The deviation of several components, each against its own bound: the worst of them.
    pub fn worst(deviations: impl IntoIterator<Item = Deviation>) -> Deviation {
        deviations.into_iter().fold(Deviation::NONE, Deviation::and)
    }
}

/// A reference's property: its case, and the mirror of the function it checks, to the deviation
/// measured, or `None` where the case lies outside the reference's domain (it is then not counted).
type Property<T, A, R> = fn(&T, &dyn Fn(A) -> R) -> Option<Deviation>;

/// Runs a reference on the mirror from a seed.
type Runner<A, R> = Box<dyn Fn(&dyn Fn(A) -> R, u64) -> Result<Summary, String> + Send + Sync>;

/// One independent reference of a function: its kind, a one-line description, and how it runs.
pub struct Reference<A, R> {
    kind: Kind,
    description: &'static str,
    run: Runner<A, R>,
}

/// What a reference measured over its cases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Summary {
    /// The cases checked.
    pub cases: u32,
    /// The cases drawn that lay outside the reference's domain (not checked; at most four times
    /// [`CASES`]).
    pub left_out: u32,
    /// The function's evaluations made at another scale, through a scale symmetry
    /// ([`crate::Record::run_reference`]).
    pub scaled: u32,
    /// The deviation that used the largest share of its bound.
    pub worst: Deviation,
}

impl<A: 'static, R: 'static> Reference<A, R> {
    /// A reference of kind `kind` described by `description` (one line): `property` compares the
    /// function's mirror with the reference on each case that `inputs` draws and returns the
    /// deviation and its bound, or `None` for a case outside the reference's domain.
    pub fn new<T: Debug + Clone + 'static>(
        kind: Kind,
        description: &'static str,
        inputs: fn() -> BoxedStrategy<T>,
        property: Property<T, A, R>,
    ) -> Self {
        Reference {
            kind,
            description,
            run: Box::new(move |mirror, seed| run(inputs, property, mirror, seed)),
        }
    }

    /// Its kind.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// Its description.
    pub fn description(&self) -> &'static str {
        self.description
    }

    /// Runs [`CASES`] cases drawn from `seed` through `mirror`: the summary, or the failure with the
    /// minimal failing case.
    pub fn run(&self, mirror: &dyn Fn(A) -> R, seed: u64) -> Result<Summary, String> {
        (self.run)(mirror, seed)
    }
}

fn run<T: Debug + Clone + 'static, A, R>(
    inputs: fn() -> BoxedStrategy<T>,
    property: Property<T, A, R>,
    mirror: &dyn Fn(A) -> R,
    seed: u64,
) -> Result<Summary, String> {
    let config = Config {
        cases: CASES,
        max_global_rejects: 4 * CASES,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner = TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &seed_bytes(seed)),
    );
    let worst = Cell::new(Deviation::NONE);
    let left_out = Cell::new(0u32);
    runner
        .run(&inputs(), |case| match property(&case, mirror) {
            None => {
                left_out.set(left_out.get() + 1);
                Err(TestCaseError::reject("outside the reference's domain"))
            }
            Some(deviation) if deviation.holds() => {
                worst.set(worst.get().and(deviation));
                Ok(())
            }
            Some(deviation) => Err(TestCaseError::fail(format!(
                "deviation {:e} exceeds its bound {:e}",
                deviation.measured, deviation.bound
            ))),
        })
        .map_err(|error| error.to_string())?;
    Ok(Summary {
        cases: CASES,
        left_out: left_out.get(),
        scaled: 0,
        worst: worst.get(),
    })
}

/// The 32 bytes of a ChaCha seed from a 64-bit one (SplitMix64 steps).
fn seed_bytes(seed: u64) -> [u8; 32] {
    let mut state = seed;
    let mut bytes = [0u8; 32];
    for chunk in bytes.chunks_mut(8) {
        state = splitmix(state);
        chunk.copy_from_slice(&state.to_le_bytes());
    }
    bytes
}

/// SplitMix64's step: spreads the bits of `x`.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The seed of a run: [`SEED_ENV`]'s value if set (an error names it where it holds no seed), else
/// [`DEFAULT_SEED`].
pub fn run_seed() -> Result<u64, String> {
    env_seed(SEED_ENV, DEFAULT_SEED)
}

/// The seed the environment variable `variable` holds, decimal or hexadecimal after `0x`, or
/// `default` where it is not set; an error names the variable where it holds no seed.
pub fn env_seed(variable: &str, default: u64) -> Result<u64, String> {
    match std::env::var(variable) {
        Err(_) => Ok(default),
        Ok(text) => parse_seed(&text).ok_or_else(|| {
            format!("{variable} = {text:?}: expected a decimal seed, or a hexadecimal one after 0x")
        }),
    }
}

fn parse_seed(text: &str) -> Option<u64> {
    match text.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

/// The seed of reference `index` of `function` in a run seeded with `seed`: each reference draws
/// its own cases, whatever runs before it.
pub fn reference_seed(seed: u64, module: Module, function: &str, index: usize) -> u64 {
    // FNV-1a over the names.
    let name = format!("{}::{function}#{index}", module.stem());
    let hash = name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    splitmix(seed ^ hash)
}

/// What one reference of one function gave.
pub struct ReferenceReport {
    /// `module::function`.
    pub function: String,
    /// The reference's kind.
    pub kind: Kind,
    /// Its description.
    pub description: &'static str,
    /// The seed its cases were drawn from.
    pub seed: u64,
    /// The summary, or the failure with the minimal failing case.
    pub outcome: Result<Summary, String>,
}

impl fmt::Display for ReferenceReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} [{}] {}: ",
            self.function,
            self.kind.name(),
            self.description
        )?;
        match &self.outcome {
            Ok(summary) => write!(
                f,
                "{} cases ({} left out, {} evaluations scaled), largest deviation {:.3e} = {:.1}% of its bound {:.3e}",
                summary.cases,
                summary.left_out,
                summary.scaled,
                summary.worst.measured,
                100.0 * summary.worst.share(),
                summary.worst.bound
            ),
            Err(failure) => write!(f, "FAILED (seed {:#x}): {failure}", self.seed),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_and_the_worst_deviation() {
        assert_eq!(Deviation::new(0.0, 0.0).share(), 0.0);
        assert_eq!(Deviation::new(1.0, 0.0).share(), f64::INFINITY);
        assert!(!Deviation::new(f64::NAN, 1.0).holds());
        let small = Deviation::new(1.0, 10.0);
        let large = Deviation::new(5.0, 10.0);
        let broken = Deviation::new(2.0, 1.0);
        assert_eq!(small.and(large), large);
        assert_eq!(large.and(small), large);
        assert_eq!(Deviation::worst([small, broken, large]), broken);
        assert_eq!(Deviation::in_interval(3.0, 1.0, 5.0), Deviation::new(0.0, 2.0));
        assert!(!Deviation::in_interval(6.0, 1.0, 5.0).holds());
    }

    #[test]
    fn seeds_parse_and_differ_per_reference() {
        assert_eq!(parse_seed("0x10"), Some(16));
        assert_eq!(parse_seed("10"), Some(10));
        assert_eq!(parse_seed("x"), None);
        let a = reference_seed(1, Module::RayCone, "width_at", 0);
        assert_ne!(a, reference_seed(1, Module::RayCone, "width_at", 1));
        assert_ne!(a, reference_seed(2, Module::RayCone, "width_at", 0));
    }
}
