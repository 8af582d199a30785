//! Many checks in a row, the next ones prepared while one runs.
//!
//! Before its first case a check compares layouts, compiles its kernel (glslang and slangc are
//! processes of their own) and has the driver make a pipeline: on an NVIDIA H100 about 0.3 s per
//! check, where its 100,000 cases take a few milliseconds. [`run_checks`] does that part on
//! threads of its own, ahead of the check that runs, and runs the cases one check at a time, in
//! order, as [`Check::run`] would.

use super::check::{Check, PreparedCheck, Report, RunConfig};
use super::device::{Error, Gpu};
use super::phases::Phase;
use crate::shader::Shader;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::sync_channel;
use std::time::{Duration, Instant};

/// Runs every check of `checks` on its shader, as [`Check::run`] does, and hands each result to
/// `each` in the order of `checks`. `preparers` threads prepare the checks ([`Check::prepare`])
/// at most `preparers` checks ahead of the one running; 0 is [`Error::Config`]. The time the
/// running thread waited for a check to be prepared is in its report's
/// [`Phase::WaitForPreparation`].
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
        // Checks prepared out of order wait here until those before them have run.
        let mut waiting = BTreeMap::new();
        let mut due = 0;
        // The time spent waiting for the due check, added to its report.
        let mut waited = Duration::ZERO;
        loop {
            let receiving = Instant::now();
            let Ok((index, prepared)) = receiver.recv() else {
                break;
            };
            waited += receiving.elapsed();
            waiting.insert(index, prepared);
            while let Some(prepared) = waiting.remove(&due) {
                let check = checks[due].0;
                let result = prepared.and_then(|prepared| check.run_prepared(prepared, config));
                each(
                    due,
                    result.map(|mut report| {
                        let wait = std::mem::take(&mut waited);
                        report.phases.add(Phase::WaitForPreparation, wait);
                        report
                    }),
                );
                due += 1;
            }
        }
    });
    Ok(())
}
