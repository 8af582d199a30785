//! Shrinking: the failing case made simpler through the random words its strategy drew.
//!
//! The words the strategy read for the failing case are taken from its batch's random stream and
//! replayed through the strategy (proptest's pass-through generator), so every candidate is a case
//! the strategy itself makes: its maps, filters and unions hold, and a unit vector stays a unit
//! vector. Each word is moved toward its origin, as long as the case still fails: where the word
//! draws one float component, toward the word that draws it closest to 0 (0 itself where its
//! range holds 0, else the bound nearer 0), else toward 0. The candidates of a word are its
//! origin, the words that draw
//! simple values (integers, halves) of its component, and the words that cut the distance from the
//! closest word known to pass to the current one in sixteen; all candidates of a round run in one
//! dispatch. A word's search ends when the words next to it toward the origin pass, and shrinking
//! ends when a fresh round finds no single word that can move toward its origin and still fail.
//!
//! Strategies that draw a fresh random generator (proptest's `prop_perturb`) do not replay through
//! the pass-through generator; their failing case is reported as generated, and says so.
//! [`FunctionCheck::with_perturbation`] draws its generator's seed as words, and replays.

use super::batches::{generate, Mismatch};
use super::config::{batch_runner, RunConfig};
use super::oracle::Judged;
use super::FunctionCheck;
use crate::gpu::compute::{Dispatch, KernelRun};
use crate::gpu::error::Error;
use crate::gpu::phases::PhaseTimes;
use crate::value::{Args, Value};
use proptest::prelude::Rng;
use proptest::strategy::{BoxedStrategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// Words of the batch's random stream kept from the failing case on: far more than a case draws
/// unless its strategy rejects thousands of values.
const RECORDED_WORDS: usize = 1 << 14;

/// Parts a word's remaining search interval is cut into per round.
const PARTS: u64 = 16;

/// Words kept after those the failing case reads, for candidates that read more.
const TAIL_WORDS: usize = 256;

/// Rejected values a replay tolerates in a row: a candidate whose draws a filter keeps rejecting
/// is dropped rather than retried thousands of times.
const REPLAY_ATTEMPTS: usize = 16;

/// The most float values a bisection for a simple value replays (2^32 words).
const BISECTION_STEPS: usize = 33;

/// The simplest failing case shrinking found, and what it took.
pub(super) struct Shrunk<A, R> {
    /// The shrunk case.
    pub args: A,
    /// Why it fails.
    pub reason: String,
    /// The shader's result for it (for a relation, for the transformed case).
    pub shader: R,
    /// The result expected of it: the mirror's, or the relation's.
    pub expected: R,
    /// The case as generated.
    pub generated: A,
    /// Moves to a simpler failing case.
    pub steps: usize,
    /// Dispatches of candidates.
    pub dispatches: usize,
    /// Why the case was not shrunk, where it was not.
    pub not_shrunk: Option<String>,
}

/// The search of one word: the word it moves toward, and how close to the current word a word is
/// known to pass (in words from the origin; `None`: nothing known).
#[derive(Clone, Copy)]
struct WordSearch {
    origin: u32,
    passing: Option<u64>,
}

/// A candidate: word `word` set to `value`, and the case it draws.
struct Candidate<A> {
    word: usize,
    value: u32,
    args: A,
}

/// The state of a shrink: the failing case, its words, and each word's search.
struct Shrinker<'a, A: Args, R: Value> {
    check: &'a FunctionCheck<A, R>,
    strategy: BoxedStrategy<A>,
    pipeline: &'a dyn Dispatch,
    batch: usize,
    /// The recorded words, the first `used` of them changed by shrinking.
    words: Vec<u32>,
    used: usize,
    searches: Vec<WordSearch>,
    args: A,
    /// The current case's judgement: the shader's result, the expected one and why they differ.
    judged: Judged<R>,
    steps: usize,
    dispatches: usize,
}

impl<A: Args, R: Value> FunctionCheck<A, R> {
    /// Shrinks the case of `mismatch`, evaluating candidates on `pipeline`, in at most
    /// `config.shrink_steps` dispatches of at most `config.batch` cases.
    pub(super) fn shrink(
        &self,
        pipeline: &dyn Dispatch,
        config: &RunConfig,
        seed: u64,
        mismatch: Mismatch,
    ) -> Result<Shrunk<A, R>, Error> {
        let (generated, words) = self.recorded(seed, &mismatch)?;
        let strategy = (self.strategy)();
        let mut judged = self.run_judged(pipeline, &[&generated])?.remove(0);
        judged.disagreement = Some(mismatch.reason);
        let mut shrinker = Shrinker {
            check: self,
            strategy,
            pipeline,
            batch: config.batch,
            used: 0,
            searches: Vec::new(),
            judged,
            args: generated.clone(),
            words,
            steps: 0,
            dispatches: 0,
        };
        let not_shrunk = match shrinker.replay(&shrinker.words) {
            Some(replayed) if same(&replayed, &generated) => {
                shrinker.measure();
                shrinker.run(config.shrink_steps)?;
                None
            }
            _ => Some(String::from(
                "its strategy's random draws do not replay: it draws a generator of its own, as prop_perturb does",
            )),
        };
        let judged = shrinker.judged;
        Ok(Shrunk {
            args: shrinker.args,
            reason: judged.disagreement.expect("the current case fails"),
            shader: judged.shader,
            expected: judged.expected,
            generated,
            steps: shrinker.steps,
            dispatches: shrinker.dispatches,
            not_shrunk,
        })
    }

    /// The failing case of `mismatch` re-generated, and the words of its batch's random stream
    /// from the failing case on.
    fn recorded(&self, seed: u64, mismatch: &Mismatch) -> Result<(A, Vec<u32>), Error> {
        let mut runner = batch_runner(seed, mismatch.batch);
        let mut cases = Vec::with_capacity(mismatch.case + 1);
        (self.generator)(&mut runner, mismatch.case, &mut cases)?;
        let mut stream = runner.rng().clone();
        let words = (0..RECORDED_WORDS).map(|_| stream.next_u32()).collect();
        (self.generator)(&mut runner, 1, &mut cases)?;
        let failing = cases.pop().expect("the failing case was generated");
        Ok((failing, words))
    }

    /// Runs `cases` on `pipeline` in one dispatch and judges each: the shader's result, the
    /// result expected of it and why they differ.
    fn run_judged(&self, pipeline: &dyn Dispatch, cases: &[&A]) -> Result<Vec<Judged<R>>, Error> {
        let mut input = Vec::new();
        cases.iter().for_each(|args| self.oracle.encode(args, &mut input));
        let invocations = cases.len() * self.oracle.invocations();
        let run = KernelRun::per_case(invocations, &input, R::TYPE.words());
        let output = pipeline.dispatch(run, &mut PhaseTimes::default())?;
        let mut words = &output[..];
        Ok(cases
            .iter()
            .map(|args| {
                let (shader, related) = self.oracle.read(args, &mut words);
                let expected = related.unwrap_or_else(|| self.mirror((*args).clone()));
                let disagreement = self.judge_result(args, &shader, &expected).disagreement;
                Judged {
                    shader,
                    expected,
                    disagreement,
                }
            })
            .collect())
    }
}

/// Whether two cases have the same words.
fn same<A: Args>(a: &A, b: &A) -> bool {
    words_of(a) == words_of(b)
}

fn words_of<A: Args>(args: &A) -> Vec<u32> {
    let mut words = Vec::new();
    args.write(&mut words);
    words
}

/// The distance from `origin` to `word`, in words.
fn distance(origin: u32, word: u32) -> u64 {
    u64::from(origin.abs_diff(word))
}

/// The word `distance` words from `origin` on the side of `toward`.
fn word_at(origin: u32, toward: u32, distance: u64) -> u32 {
    let distance = distance as u32;
    if toward >= origin {
        origin + distance
    } else {
        origin - distance
    }
}

impl<A: Args, R: Value> Shrinker<'_, A, R> {
    /// The case `words` draw (the words the case reads and [`TAIL_WORDS`] more), or `None` where
    /// the strategy rejects them all.
    fn replay(&self, words: &[u32]) -> Option<A> {
        let read = match self.used {
            0 => words.len(),
            used => (used + TAIL_WORDS).min(words.len()),
        };
        let bytes: Vec<u8> = words[..read].iter().flat_map(|word| word.to_le_bytes()).collect();
        let rng = TestRng::from_seed(RngAlgorithm::PassThrough, &bytes);
        let config = Config {
            max_local_rejects: 1024,
            ..Config::default()
        };
        let mut runner = TestRunner::new_with_rng(config, rng);
        generate(&self.strategy, &mut runner, REPLAY_ATTEMPTS)
            .ok()
            .map(|tree| tree.current())
    }

    /// The case with word `word` set to `value`.
    fn replay_with(&self, word: usize, value: u32) -> Option<A> {
        let mut words = self.words.clone();
        words[word] = value;
        self.replay(&words)
    }

    /// Measures the current case: how many words it reads (the words after them can change
    /// without changing it) and each word's origin. A word keeps what its search knew where its
    /// origin is the same.
    fn measure(&mut self) {
        self.used = 0;
        let (mut low, mut high) = (0, self.words.len());
        while low < high {
            let middle = (low + high) / 2;
            let mut changed = self.words.clone();
            changed[middle..].iter_mut().for_each(|word| *word = !*word);
            match self.replay(&changed) {
                Some(args) if same(&args, &self.args) => high = middle,
                _ => low = middle + 1,
            }
        }
        self.used = low;
        let searches: Vec<WordSearch> = (0..self.used)
            .map(|word| {
                let origin = self.origin(word);
                let passing = self
                    .searches
                    .get(word)
                    .filter(|search| search.origin == origin)
                    .and_then(|search| search.passing);
                WordSearch { origin, passing }
            })
            .collect();
        self.searches = searches;
    }

    /// The word whose draw of the one float component that word `word` draws is closest to 0:
    /// the word that draws 0 where the component's range holds 0 (found by bisection), else the
    /// end (1 or `u32::MAX`) that draws the smaller magnitude, which for a range is the bound
    /// nearer 0. A word that draws no single float component moves toward 0. (The low end is 1:
    /// a sampler that rejects part of its draws, as an integer range does, rejects a word of 0
    /// and draws again, and so reads the words after it for other values.)
    fn origin(&self, word: usize) -> u32 {
        let Some(component) = self.drawn_component(word) else {
            return 0;
        };
        let value = |w: u32| self.component(word, w, component);
        let (Some(first), Some(last)) = (value(1), value(u32::MAX)) else {
            return 0;
        };
        if first.signum() != last.signum() && first != 0.0 && last != 0.0 {
            return self.bisect(word, component, 1, u32::MAX, 0.0).unwrap_or(1);
        }
        if last.abs() < first.abs() {
            u32::MAX
        } else {
            1
        }
    }

    /// The float component (an index into the case's words) that word `word` draws: the first
    /// one that changes both when the word is complemented and when its top bit flips, where it
    /// is a float. Components after it may change too: a float drawn closer to 0 reads more
    /// words, and the values after it are drawn from later words.
    fn drawn_component(&self, word: usize) -> Option<usize> {
        let current = words_of(&self.args);
        let changed = |value: u32| -> Vec<usize> {
            let other = self.replay_with(word, value).map(|args| words_of(&args));
            (0..current.len())
                .filter(|&i| {
                    other
                        .as_ref()
                        .is_none_or(|other| other.get(i) != Some(&current[i]))
                })
                .collect()
        };
        let original = self.words[word];
        let flipped = changed(original ^ 0x8000_0000);
        let first = changed(!original).into_iter().find(|i| flipped.contains(i))?;
        float_words::<A>()[first].then_some(first)
    }

    /// Float component `component` of the case drawn with word `word` set to `value`.
    fn component(&self, word: usize, value: u32, component: usize) -> Option<f32> {
        let words = words_of(&self.replay_with(word, value)?);
        words.get(component).map(|&bits| f32::from_bits(bits))
    }

    /// A word between `low` and `high` (either order) at which component `component` is
    /// `target`, by bisection on the component's (assumed monotonic) value; `None` where none is.
    fn bisect(&self, word: usize, component: usize, low: u32, high: u32, target: f32) -> Option<u32> {
        let value = |w: u32| self.component(word, w, component);
        let rising = value(low)? <= value(high)?;
        let (mut below, mut above) = (low, high);
        for _ in 0..BISECTION_STEPS {
            let middle = word_at(below, above, distance(below, above) / 2);
            let found = value(middle)?;
            if found == target {
                return Some(middle);
            }
            if middle == below {
                break;
            }
            if (found < target) == rising {
                below = middle;
            } else {
                above = middle;
            }
        }
        [below, above].into_iter().find(|&w| value(w) == Some(target))
    }

    /// Shrinks until every word's search has ended with no move since the searches last started
    /// afresh, in at most `dispatches` dispatches. A move can make a word that passed fail, so
    /// the searches start afresh (from the origins) after any move.
    fn run(&mut self, dispatches: usize) -> Result<(), Error> {
        let mut moved = false;
        while self.dispatches < dispatches {
            if !self.searching() {
                if !moved {
                    return Ok(());
                }
                self.searches.iter_mut().for_each(|search| search.passing = None);
                moved = false;
            }
            moved |= self.round()?;
        }
        Ok(())
    }

    /// Whether some word still has candidates between the closest word known to pass and its
    /// current one.
    fn searching(&self) -> bool {
        (0..self.used).any(|word| {
            let search = self.searches[word];
            let current = distance(search.origin, self.words[word]);
            current > search.passing.map_or(0, |passing| passing + 1)
        })
    }

    /// One round: every word's candidates in one dispatch; the moves that keep the case failing,
    /// applied together where together they fail, else the first. Whether anything moved.
    fn round(&mut self) -> Result<bool, Error> {
        let mut candidates: Vec<Candidate<A>> = Vec::new();
        for word in 0..self.used {
            let before = candidates.len();
            for value in self.candidate_values(word) {
                if let Some(args) = self
                    .replay_with(word, value)
                    .filter(|args| !same(args, &self.args))
                {
                    candidates.push(Candidate { word, value, args });
                }
            }
            if candidates.len() == before {
                // No candidate draws another case: the word's search has ended.
                let search = &mut self.searches[word];
                search.passing = Some(distance(search.origin, self.words[word]).saturating_sub(1));
            }
        }
        if candidates.is_empty() {
            return Ok(false);
        }
        let results = self.evaluate(candidates.iter().map(|candidate| &candidate.args))?;
        let mut moves: Vec<usize> = Vec::new();
        for word in 0..self.used {
            if let Some(best) = self.learn(word, &candidates, &results) {
                moves.push(best);
            }
        }
        match moves.as_slice() {
            [] => Ok(false),
            [only] => {
                self.adopt(&candidates[*only], &results[*only]);
                Ok(true)
            }
            [first, ..] => {
                let mut words = self.words.clone();
                moves
                    .iter()
                    .for_each(|&m| words[candidates[m].word] = candidates[m].value);
                let joint = self.replay(&words).map(|args| (words, args));
                let joint_result = match &joint {
                    Some((_, args)) => Some(self.evaluate([args])?.remove(0)),
                    None => None,
                };
                match (joint, joint_result) {
                    (Some((words, args)), Some(judged)) if judged.disagreement.is_some() => {
                        self.words = words;
                        self.args = args;
                        self.judged = judged;
                        self.steps += moves.len();
                        self.measure();
                    }
                    _ => self.adopt(&candidates[*first], &results[*first]),
                }
                Ok(true)
            }
        }
    }

    /// The words to try for word `word`: its origin, while nothing closer is known to pass, the
    /// words that cut the rest of the way in [`PARTS`], and the words of simple values of its
    /// float component on the way.
    fn candidate_values(&self, word: usize) -> Vec<u32> {
        let search = self.searches[word];
        let current = self.words[word];
        let span = distance(search.origin, current);
        let passing = search.passing.unwrap_or(0);
        if span <= passing + u64::from(search.passing.is_some()) {
            return Vec::new();
        }
        let mut distances: Vec<u64> = (1..PARTS)
            .map(|part| passing + (span - passing) * part / PARTS)
            .collect();
        if search.passing.is_none() {
            distances.push(0);
        }
        let mut values: Vec<u32> = distances
            .into_iter()
            .filter(|&d| d < span && search.passing.is_none_or(|p| d > p))
            .map(|d| word_at(search.origin, current, d))
            .collect();
        values.extend(self.simple_values(word, word_at(search.origin, current, passing), current));
        values.sort_unstable();
        values.dedup();
        values
    }

    /// The words between `from` and `current` (neither included) that draw integers and halves
    /// of word `word`'s float component: for each, the one nearest `from` and the one nearest
    /// `current`.
    fn simple_values(&self, word: usize, from: u32, current: u32) -> Vec<u32> {
        let Some(component) = self.drawn_component(word) else {
            return Vec::new();
        };
        let (Some(start), Some(end)) = (
            self.component(word, from, component),
            self.component(word, current, component),
        ) else {
            return Vec::new();
        };
        let (low, high) = (start.min(end), start.max(end));
        let mut targets = Vec::new();
        for step in [1.0f32, 0.5] {
            let first = (low / step).floor() * step + step;
            let last = (high / step).ceil() * step - step;
            targets.extend([first, last].into_iter().filter(|t| *t > low && *t < high));
        }
        targets
            .into_iter()
            .filter_map(|target| self.bisect(word, component, from, current, target))
            .filter(|&value| value != from && value != current)
            .collect()
    }

    /// What this round's results say about word `word`: the candidate of the word closest to its
    /// origin that still fails (its index), and the closest to the current word known to pass.
    fn learn(&mut self, word: usize, candidates: &[Candidate<A>], results: &[Judged<R>]) -> Option<usize> {
        let origin = self.searches[word].origin;
        let of_word = || (0..candidates.len()).filter(|&i| candidates[i].word == word);
        let best = of_word()
            .filter(|&i| results[i].disagreement.is_some())
            .min_by_key(|&i| distance(origin, candidates[i].value));
        let limit = best.map_or(distance(origin, self.words[word]), |i| {
            distance(origin, candidates[i].value)
        });
        let passing = of_word()
            .filter(|&i| results[i].disagreement.is_none())
            .map(|i| distance(origin, candidates[i].value))
            .filter(|&d| d < limit)
            .max();
        let search = &mut self.searches[word];
        search.passing = search.passing.filter(|&p| p < limit).max(passing);
        best
    }

    /// Makes `candidate`, which fails with `result`, the current case.
    fn adopt(&mut self, candidate: &Candidate<A>, result: &Judged<R>) {
        self.words[candidate.word] = candidate.value;
        self.args = candidate.args.clone();
        assert!(result.disagreement.is_some(), "an adopted candidate fails");
        self.judged = result.clone();
        self.steps += 1;
        self.measure();
    }

    /// Runs `cases` in dispatches of at most a batch: each case's judgement.
    fn evaluate<'c>(&mut self, cases: impl IntoIterator<Item = &'c A>) -> Result<Vec<Judged<R>>, Error>
    where
        A: 'c,
    {
        let cases: Vec<&A> = cases.into_iter().collect();
        let mut results = Vec::with_capacity(cases.len());
        for chunk in cases.chunks(self.batch) {
            results.extend(self.check.run_judged(self.pipeline, chunk)?);
            self.dispatches += 1;
        }
        Ok(results)
    }
}

/// Per word of a case of type `A`, whether it is a float.
fn float_words<A: Args>() -> Vec<bool> {
    let mut floats = Vec::new();
    A::TYPES.iter().for_each(|ty| ty.float_words(&mut floats));
    floats
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::check::batches::Lane;
    use glam::Vec3;
    use proptest::prelude::*;

    /// A device that computes `v.x` on the processor for cases of one `Vec3`.
    struct FirstComponent;

    impl Dispatch for FirstComponent {
        fn dispatch(&self, run: KernelRun<'_>, _times: &mut PhaseTimes) -> Result<Vec<u32>, Error> {
            Ok((0..run.invocations).map(|case| run.input[3 * case]).collect())
        }
    }

    /// Unit vectors, from a longitude and a height.
    fn unit_vectors() -> impl Strategy<Value = (Vec3,)> {
        (0.0f32..std::f32::consts::TAU, -1.0f32..1.0).prop_map(|(longitude, z)| {
            let (sin, cos) = longitude.sin_cos();
            let r = (1.0 - z * z).sqrt();
            (Vec3::new(r * cos, r * sin, z),)
        })
    }

    /// Shrinks a failing case of `check` (whose mirror is `v.x` but for `x > 0.5`) on the
    /// processor's "device".
    fn shrunk(check: &FunctionCheck<(Vec3,), f32>) -> Shrunk<(Vec3,), f32> {
        let config = RunConfig {
            seed: Some(3),
            cases: 4096,
            batch: 1024,
            ..RunConfig::default()
        };
        let mut lanes = [Lane::new(&FirstComponent)];
        check.run_batches(&mut lanes, &config, 3).expect("runs");
        let [lane] = lanes;
        let mismatch = lane.first.expect("a mismatch");
        check
            .shrink(&FirstComponent, &config, 3, mismatch)
            .expect("shrinks")
    }

    /// Every candidate is a case the strategy makes: the shrunk vector is still a unit vector,
    /// its `x` just past the failing bound; a perturbed strategy replays and shrinks too.
    #[test]
    fn shrunk_cases_are_cases_of_the_strategy() {
        let check = || {
            FunctionCheck::new(
                "x",
                unit_vectors,
                |(v,): (Vec3,)| {
                    if v.x > 0.5 {
                        v.x + 1.0
                    } else {
                        v.x
                    }
                },
            )
        };
        let flip = |(v,): (Vec3,), rng: &mut TestRng| (if rng.random::<bool>() { -v } else { v },);
        for check in [check(), check().with_perturbation(flip)] {
            let shrunk = shrunk(&check);
            let (v,) = shrunk.args;
            println!(
                "{:?} shrunk to {v:?} in {} dispatches",
                shrunk.generated, shrunk.dispatches
            );
            assert_eq!(shrunk.not_shrunk, None);
            assert!((v.length() - 1.0).abs() < 1e-6, "{v:?}");
            assert!(v.x > 0.5 && v.x < 0.501, "{v:?}");
        }
    }
}
