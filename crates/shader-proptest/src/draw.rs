//! Strategies that draw a case with fewer random words and allocations than proptest's own: a float
//! in a range from one word ([`uniform`]), and a weighted choice that builds the chosen strategy's
//! value only ([`one_of!`](crate::one_of)).
//!
//! Generating cases is most of a check's work on a fast device (the harness README's "Where the
//! time goes"), and two of proptest's strategies cost most of it:
//!
//! - A float range (`0.0f32..1.0`) splits the range into intervals and picks among them until two
//!   floats are left, about 150 ns a value; [`uniform`] maps one 32-bit word onto the range, about
//!   20 ns.
//! - `prop_oneof!` builds, beside the chosen strategy's value, a deferred value of every other arm,
//!   each holding a copy of the test runner with a generator of its own, so that shrinking can move
//!   to an earlier arm; about 600 ns for five arms of floats. [`one_of!`](crate::one_of) draws one word, builds
//!   the chosen arm's value and nothing else, about 130 ns.
//!
//! Both read their words from the runner's generator, so a batch's cases depend on its seed only
//! and shrinking replays them ([`crate::FunctionCheck`]). A choice shrinks within its arm.
//!
//! ```
//! use shader_proptest::draw::uniform;
//! use shader_proptest::one_of;
//! use shader_proptest::proptest::prelude::*;
//! use shader_proptest::proptest::strategy::ValueTree;
//!
//! // A field of view: mostly ordinary, sometimes 0 or tiny (log-uniform).
//! let fov = one_of![
//!     6 => uniform(0.05, 3.0),
//!     1 => Just(0.0f32),
//!     1 => uniform(-9.0, -2.0).prop_map(|e| 10f32.powf(e)),
//! ];
//! let mut runner = proptest::test_runner::TestRunner::deterministic();
//! let value = fov.new_tree(&mut runner).expect("no filter").current();
//! assert!(value == 0.0 || (1.0e-9..3.0).contains(&value));
//! ```

use proptest::prelude::*;
use proptest::strategy::{BoxedStrategy, Map, NewTree, ValueTree};
use proptest::test_runner::TestRunner;
use std::fmt::Debug;

/// A float in `[low, high)`: one 32-bit word `w` drawn, `low + (high - low) w / 2^32` computed in
/// f64 and rounded to f32 (the value `low` where that rounds up to `high`). The step between values
/// is `(high - low) / 2^32`, finer than an f32's spacing at the range's larger end. Shrinks toward
/// `low`. Panics unless `low < high`, both finite.
///
/// ```
/// use shader_proptest::draw::uniform;
/// use shader_proptest::proptest::prelude::*;
/// use shader_proptest::proptest::strategy::ValueTree;
///
/// let mut runner = proptest::test_runner::TestRunner::deterministic();
/// let strategy = uniform(-1.0, 2.0);
/// let values: Vec<f32> = (0..1000).map(|_| strategy.new_tree(&mut runner).unwrap().current()).collect();
/// assert!(values.iter().all(|v| (-1.0..2.0).contains(v)));
/// assert!(values.iter().any(|&v| v < -0.9) && values.iter().any(|&v| v > 1.9));
/// ```
pub fn uniform(low: f32, high: f32) -> Map<proptest::num::u32::Any, impl Fn(u32) -> f32 + Clone> {
    assert!(
        low.is_finite() && high.is_finite() && low < high,
        "uniform({low}, {high}): the range must be finite and not empty"
    );
    let (start, span) = (f64::from(low), f64::from(high) - f64::from(low));
    any::<u32>().prop_map(move |word| {
        let value = (start + span * (f64::from(word) / 4_294_967_296.0)) as f32;
        if value < high {
            value
        } else {
            low
        }
    })
}

/// A weighted choice among strategies of one value type ([`one_of!`](crate::one_of) builds it): one 32-bit word
/// picks an arm with probability proportional to its weight, and only that arm draws a value.
pub struct OneOf<T> {
    arms: Vec<(u32, BoxedStrategy<T>)>,
    total: u64,
}

impl<T: Debug> OneOf<T> {
    /// A choice among `arms`, each with its weight. Panics when the weights add up to 0 or to
    /// more than `u32::MAX`.
    pub fn new(arms: Vec<(u32, BoxedStrategy<T>)>) -> OneOf<T> {
        let total: u64 = arms.iter().map(|&(weight, _)| u64::from(weight)).sum();
        assert!(
            total > 0 && total <= u64::from(u32::MAX),
            "one_of: the weights add up to {total}, not to 1..=u32::MAX"
        );
        OneOf { arms, total }
    }

    /// The arm a word picks: `word * total / 2^32` falls into the arm's share of the weights.
    fn arm(&self, word: u32) -> &BoxedStrategy<T> {
        let mut pick = (u64::from(word) * self.total) >> 32;
        for (weight, arm) in &self.arms {
            let weight = u64::from(*weight);
            if pick < weight {
                return arm;
            }
            pick -= weight;
        }
        unreachable!("a pick below the total weight falls into an arm")
    }
}

impl<T> Debug for OneOf<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let weights: Vec<u32> = self.arms.iter().map(|&(weight, _)| weight).collect();
        f.debug_struct("OneOf").field("weights", &weights).finish()
    }
}

impl<T: Debug> Strategy for OneOf<T> {
    type Tree = Box<dyn ValueTree<Value = T>>;
    type Value = T;

    fn new_tree(&self, runner: &mut TestRunner) -> NewTree<Self> {
        let word = runner.rng().next_u32();
        self.arm(word).new_tree(runner)
    }
}

/// A weighted choice among strategies of one value type, as `prop_oneof!` writes it (`weight =>
/// strategy`, or strategies alone, each of weight 1), drawn as [`OneOf`] draws it.
///
/// ```
/// use shader_proptest::one_of;
/// use shader_proptest::proptest::prelude::*;
/// use shader_proptest::proptest::strategy::ValueTree;
///
/// let sign = one_of![Just(-1.0f32), Just(1.0f32)];
/// let mut runner = proptest::test_runner::TestRunner::deterministic();
/// assert!(sign.new_tree(&mut runner).unwrap().current().abs() == 1.0);
/// ```
#[macro_export]
macro_rules! one_of {
    ($($weight:expr => $arm:expr),+ $(,)?) => {
        $crate::draw::OneOf::new(::std::vec![
            $(($weight, $crate::proptest::strategy::Strategy::boxed($arm))),+
        ])
    };
    ($($arm:expr),+ $(,)?) => {
        $crate::draw::OneOf::new(::std::vec![
            $((1, $crate::proptest::strategy::Strategy::boxed($arm))),+
        ])
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng};

    fn runner() -> TestRunner {
        TestRunner::new_with_rng(
            Config::default(),
            TestRng::from_seed(RngAlgorithm::XorShift, &[7; 16]),
        )
    }

    /// The ends of the word range land on the ends of the float range: word 0 on `low`, the
    /// largest word just below `high` (or on `low` where it rounds up to `high`).
    #[test]
    fn the_extreme_words_land_inside_the_range() {
        for (low, high) in [
            (0.0f32, 1.0f32),
            (-1.0e12, 1.0e12),
            (1.0, 1.0 + f32::EPSILON),
            (-3.0, -2.0),
        ] {
            for word in [0u32, 1, u32::MAX / 2, u32::MAX - 1, u32::MAX] {
                let bytes = word.to_le_bytes();
                let mut replay = TestRunner::new_with_rng(
                    Config::default(),
                    TestRng::from_seed(RngAlgorithm::PassThrough, &bytes),
                );
                let value = uniform(low, high)
                    .new_tree(&mut replay)
                    .expect("a value")
                    .current();
                assert!(
                    (low..high).contains(&value),
                    "word {word}: {value} outside [{low}, {high})"
                );
                if word == 0 {
                    assert_eq!(value, low);
                }
            }
        }
    }

    /// Each arm is chosen in proportion to its weight: 100,000 draws of weights 6, 1, 3 land
    /// within 1% of 60%, 10% and 30%.
    #[test]
    fn arms_are_chosen_in_proportion_to_their_weights() {
        let choice = crate::one_of![6 => Just(0usize), 1 => Just(1usize), 3 => Just(2usize)];
        let mut counts = [0usize; 3];
        let mut runner = runner();
        for _ in 0..100_000 {
            counts[choice.new_tree(&mut runner).expect("a value").current()] += 1;
        }
        for (count, share) in counts.iter().zip([0.6, 0.1, 0.3]) {
            let measured = *count as f64 / 100_000.0;
            assert!((measured - share).abs() < 0.01, "{counts:?}");
        }
    }

    /// The same seed draws the same values: a choice of uniform floats replays from the words it
    /// read, as shrinking replays a case.
    #[test]
    fn a_choice_replays_from_the_words_it_read() {
        let choice = crate::one_of![uniform(0.0, 1.0), uniform(-5.0, -4.0).prop_map(|x| x * 2.0)];
        let mut recorded = runner();
        let mut stream = recorded.rng().clone();
        let values: Vec<f32> = (0..100)
            .map(|_| choice.new_tree(&mut recorded).expect("a value").current())
            .collect();
        let bytes: Vec<u8> = (0..200).flat_map(|_| stream.next_u32().to_le_bytes()).collect();
        let mut replay = TestRunner::new_with_rng(
            Config::default(),
            TestRng::from_seed(RngAlgorithm::PassThrough, &bytes),
        );
        for value in values {
            let replayed = choice.new_tree(&mut replay).expect("a value").current();
            assert_eq!(value.to_bits(), replayed.to_bits());
        }
    }

    /// Weights that add up to 0 are refused with the sum.
    #[test]
    #[should_panic(expected = "the weights add up to 0")]
    fn zero_weights_are_refused() {
        let _ = crate::one_of![0 => Just(1.0f32)];
    }
}
