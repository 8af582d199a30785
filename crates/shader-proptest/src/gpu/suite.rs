//! Many checks in a row, the next ones prepared while one runs, and the cases of a function
//! generated once for all its shaders.
//!
//! Before its first case a check compares layouts, compiles its kernel (glslang and slangc are
//! processes of their own) and has the driver make a pipeline: on an NVIDIA H100 about 0.3 s per
//! check, where its 100,000 cases take a few milliseconds. [`run_checks`] does that part on
//! threads of its own, ahead of the check that runs. Neighbouring entries of one check (the same
//! function in several languages) run together, each batch generated once and run on each of
//! their shaders ([`Check::run_prepared`]); two such groups run at once, and report in order.

use super::check::{Check, PreparedCheck, Report, RunConfig};
use super::device::Gpu;
use super::error::Error;
use super::phases::Phase;
use crate::shader::Shader;
use std::collections::{BTreeMap, VecDeque};
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::sync_channel;
use std::time::{Duration, Instant};

/// Groups of checks run at once: while the last batches of one are dispatched, the next one's are
/// generated.
const GROUPS_AT_ONCE: usize = 2;

/// Runs every check of `checks` on its shader, as [`Check::run`] does, and hands each result to
/// `each` in the order of `checks`. Every check runs with one seed, `config`'s (a fresh one if it
/// has none, printed in every report), so that neighbouring entries of the same check run the
/// same cases, generated once. `preparers` threads prepare the checks ([`Check::prepare`]) at most
/// `preparers` checks ahead of those running; 0 is [`Error::Config`], as is a `config` that
/// [`RunConfig::validate`] refuses. Two groups run at once, each on threads of its own, and
/// report in order. The time the calling thread waited for a group's checks to be prepared is
/// shared among their reports' [`Phase::WaitForPreparation`].
pub fn run_checks(
    gpu: &Gpu,
    checks: &[(&dyn Check, Shader)],
    config: &RunConfig,
    preparers: usize,
    mut each: impl FnMut(usize, Result<Report, Error>),
) -> Result<(), Error> {
    if preparers == 0 {
        return Err(Error::Config {
            field: "preparers",
            value: "0".into(),
            expected: "at least 1",
        });
    }
    let config = RunConfig {
        seed: Some(config.validate()?),
        ..*config
    };
    let groups = neighbours(checks);
    let next = AtomicUsize::new(0);
    let (sender, receiver) = sync_channel::<(usize, Result<PreparedCheck<'_>, Error>)>(preparers);
    std::thread::scope(|scope| {
        for _ in 0..preparers {
            let sender = sender.clone();
            let next = &next;
            scope.spawn(move || loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                if index >= checks.len() {
                    break;
                }
                let (check, shader) = &checks[index];
                if sender.send((index, check.prepare(gpu, shader))).is_err() {
                    break;
                }
            });
        }
        drop(sender);
        // Checks prepared out of order wait here until their group is complete and may start.
        let mut waiting = BTreeMap::new();
        let mut groups = groups.into_iter().peekable();
        let mut waited = Duration::ZERO;
        // The groups running, oldest first, each with its share of the wait for its preparation.
        let mut running = VecDeque::new();
        let mut report = |group: Range<usize>, wait: Duration, results: Vec<Result<Report, Error>>| {
            for (index, result) in group.zip(results) {
                each(
                    index,
                    result.map(|mut report| {
                        report.phases.add(Phase::WaitForPreparation, wait);
                        report
                    }),
                );
            }
        };
        loop {
            while running.len() < GROUPS_AT_ONCE {
                let Some(group) = groups.next_if(|group| group.clone().all(|i| waiting.contains_key(&i)))
                else {
                    break;
                };
                let prepared: Vec<_> = group
                    .clone()
                    .map(|i| waiting.remove(&i).expect("prepared"))
                    .collect();
                let wait = std::mem::take(&mut waited) / group.len() as u32;
                let (check, config) = (checks[group.start].0, &config);
                running.push_back((
                    group,
                    wait,
                    scope.spawn(move || run_group(check, prepared, config)),
                ));
            }
            // The oldest group reports once no other may start beside it.
            if running.len() == GROUPS_AT_ONCE || (groups.peek().is_none() && !running.is_empty()) {
                let (group, wait, run) = running.pop_front().expect("a group runs");
                report(
                    group,
                    wait,
                    run.join()
                        .unwrap_or_else(|panic| std::panic::resume_unwind(panic)),
                );
                continue;
            }
            let receiving = Instant::now();
            let Ok((index, prepared)) = receiver.recv() else {
                break;
            };
            waited += receiving.elapsed();
            waiting.insert(index, prepared);
        }
    });
    Ok(())
}

/// The runs of neighbouring entries of `checks` that hold the same check, in order.
fn neighbours(checks: &[(&dyn Check, Shader)]) -> Vec<Range<usize>> {
    let mut groups: Vec<Range<usize>> = Vec::new();
    for (index, (check, _)) in checks.iter().enumerate() {
        match groups.last_mut() {
            Some(group) if std::ptr::addr_eq(checks[group.start].0, *check) => group.end = index + 1,
            _ => groups.push(index..index + 1),
        }
    }
    groups
}

/// Runs a group's prepared checks together; a check whose preparation failed gets its error.
fn run_group(
    check: &dyn Check,
    prepared: Vec<Result<PreparedCheck<'_>, Error>>,
    config: &RunConfig,
) -> Vec<Result<Report, Error>> {
    let mut ready = Vec::new();
    let errors: Vec<Option<Error>> = prepared
        .into_iter()
        .map(|result| result.map(|check| ready.push(check)).err())
        .collect();
    let mut reports = check.run_prepared(ready, config).into_iter();
    errors
        .into_iter()
        .map(|error| match error {
            Some(e) => Err(e),
            None => reports.next().expect("a report per prepared check"),
        })
        .collect()
}
