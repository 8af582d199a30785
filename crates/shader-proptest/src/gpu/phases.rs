//! Where a check's time goes, phase by phase: each phase's time summed over the threads that
//! worked in it, measured with one clock reading per phase and batch (never per case).

use std::ops::AddAssign;
use std::time::{Duration, Instant};

/// A phase of a check. The work phases run on different threads and overlap: the preparation on
/// [`crate::run_checks`]' threads, generation, encoding, mirror and tolerance on the generating
/// threads (shared equally among the shaders that run the same cases), the rest on the thread
/// that dispatches to the check's shader; the two waits are that thread's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Comparing the layouts, writing the kernel, compiling it (glslang and slangc run as
    /// processes of their own) and comparing the signature.
    Compile,
    /// The driver making the compute pipeline from the SPIR-V.
    Pipeline,
    /// Drawing the cases from the strategy.
    Generation,
    /// Writing the cases' arguments as words.
    Encoding,
    /// Running the mirror on every case.
    Mirror,
    /// The tolerance's bound of every output component, and counting the vacuous ones.
    Tolerance,
    /// Copying the words into the device's input buffer (on a kernel's first dispatch, making the
    /// buffers too).
    Upload,
    /// Recording, submitting and waiting for one dispatch, then reading the validation layer's
    /// messages; with it, waiting for a free command buffer, or for the queue while another thread
    /// submits to it.
    Dispatch,
    /// Copying the output words out of the device's buffer.
    ReadBack,
    /// Reading each case's result from the words and judging it against the mirror's.
    Comparison,
    /// Shrinking a disagreement, its dispatches included.
    Shrinking,
    /// The dispatching thread waiting for the check (and the others that run its cases) to be
    /// prepared, shared equally among them.
    WaitForPreparation,
    /// The dispatching thread waiting for a batch to be generated, shared equally among the
    /// shaders that run the same cases.
    WaitForBatch,
}

impl Phase {
    /// Every phase, in the order a check goes through them, the waits last.
    pub const ALL: [Phase; 13] = [
        Phase::Compile,
        Phase::Pipeline,
        Phase::Generation,
        Phase::Encoding,
        Phase::Mirror,
        Phase::Tolerance,
        Phase::Upload,
        Phase::Dispatch,
        Phase::ReadBack,
        Phase::Comparison,
        Phase::Shrinking,
        Phase::WaitForPreparation,
        Phase::WaitForBatch,
    ];

    /// The phase in a few words, for tables.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Compile => "compile",
            Phase::Pipeline => "pipeline creation",
            Phase::Generation => "generation",
            Phase::Encoding => "encoding",
            Phase::Mirror => "mirror",
            Phase::Tolerance => "tolerance",
            Phase::Upload => "upload",
            Phase::Dispatch => "dispatch",
            Phase::ReadBack => "read-back",
            Phase::Comparison => "comparison",
            Phase::Shrinking => "shrinking",
            Phase::WaitForPreparation => "waiting for a prepared check",
            Phase::WaitForBatch => "waiting for a generated batch",
        }
    }

    /// Whether the phase is the dispatching thread waiting rather than working.
    pub fn is_wait(self) -> bool {
        matches!(self, Phase::WaitForPreparation | Phase::WaitForBatch)
    }
}

/// The time of each [`Phase`], summed over the threads that worked in it;
/// [`Report::phases`](crate::Report::phases) holds a check's.
///
/// ```
/// use shader_proptest::{Phase, PhaseTimes};
/// use std::time::Duration;
///
/// let mut check = PhaseTimes::default();
/// check.add(Phase::Mirror, Duration::from_millis(3));
/// check.add(Phase::WaitForBatch, Duration::from_millis(5));
/// let mut suite = PhaseTimes::default();
/// suite += check;
/// suite += check;
/// assert_eq!(suite.get(Phase::Mirror), Duration::from_millis(6));
/// assert_eq!(suite.get(Phase::WaitForBatch), Duration::from_millis(10));
/// assert_eq!(suite.work(), Duration::from_millis(6));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PhaseTimes([Duration; Phase::ALL.len()]);

impl PhaseTimes {
    /// The time spent in `phase`.
    pub fn get(&self, phase: Phase) -> Duration {
        self.0[phase as usize]
    }

    /// Adds `time` to `phase`.
    pub fn add(&mut self, phase: Phase, time: Duration) {
        self.0[phase as usize] += time;
    }

    /// Adds the time since `clock` to `phase` and sets `clock` to now, where the next phase
    /// starts.
    pub(crate) fn lap(&mut self, phase: Phase, clock: &mut Instant) {
        let now = Instant::now();
        self.add(phase, now - *clock);
        *clock = now;
    }

    /// One of `parts` equal shares of every phase's time (for work done once for several
    /// checks). `parts` is at least 1.
    pub(crate) fn shared(&self, parts: u32) -> PhaseTimes {
        PhaseTimes(self.0.map(|time| time / parts.max(1)))
    }

    /// The time of every work phase, the waits left out.
    pub fn work(&self) -> Duration {
        Phase::ALL
            .iter()
            .filter(|phase| !phase.is_wait())
            .map(|&phase| self.get(phase))
            .sum()
    }
}

impl AddAssign for PhaseTimes {
    fn add_assign(&mut self, other: PhaseTimes) {
        Phase::ALL
            .iter()
            .for_each(|&phase| self.add(phase, other.get(phase)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `ALL` lists each phase once, at the index of its discriminant, so `get` reads what `add`
    /// wrote to that phase and to no other.
    #[test]
    fn every_phase_has_a_slot_of_its_own() {
        for (index, &phase) in Phase::ALL.iter().enumerate() {
            assert_eq!(phase as usize, index, "{phase:?}");
            let mut times = PhaseTimes::default();
            times.add(phase, Duration::from_nanos(7));
            for other in Phase::ALL.into_iter().filter(|&other| other != phase) {
                assert!(times.get(other).is_zero(), "{phase:?} wrote to {other:?}");
            }
            assert_eq!(times.get(phase), Duration::from_nanos(7));
        }
    }

    /// Shares of a time add up to it, to within a nanosecond per share.
    #[test]
    fn shares_add_up_to_the_whole() {
        let mut times = PhaseTimes::default();
        times.add(Phase::Generation, Duration::from_nanos(1_000_003));
        let share = times.shared(5);
        assert_eq!(share.get(Phase::Generation), Duration::from_nanos(200_000));
        let whole = share.get(Phase::Generation) * 5;
        assert!(times.get(Phase::Generation) - whole < Duration::from_nanos(5));
        assert!(share.get(Phase::Mirror).is_zero());
    }

    /// A lap adds the time since the clock to its phase and restarts the clock there.
    #[test]
    fn a_lap_restarts_the_clock() {
        let mut times = PhaseTimes::default();
        let before = Instant::now();
        let mut clock = before;
        std::thread::sleep(Duration::from_millis(2));
        times.lap(Phase::Dispatch, &mut clock);
        assert!(clock - before >= Duration::from_millis(2));
        assert_eq!(times.get(Phase::Dispatch), clock - before);
    }
}
