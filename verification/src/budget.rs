//! Time-bounded decisions: a decision that does not finish within its
//! time limit is *cut off* — it gets no verdict, and the report says so —
//! never a hang, and never a verdict that depends on the machine.
//!
//! Every decision is bounded in work by counted budgets (Bernstein
//! subdivision, the interval search, the precision climb), so its verdict
//! is the same on every machine; `not-checkable` comes from those budgets
//! only. The time limit is a guard on top: [`bounded`] runs one decision on
//! its own thread and waits at most the limit; a decision that runs over is
//! abandoned (its thread ends with the process) and reported as cut off.

use std::sync::mpsc;
use std::time::Duration;

/// Default time limit of one claim of a spec audit.
pub const CLAIM_BUDGET: Duration = Duration::from_secs(10);

/// Stack of a decision's thread: as deep as the main thread's and more.
const STACK: usize = 64 << 20;

/// Why a decision gave no result.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stopped {
    /// It ran past the time limit (no verdict: cut off).
    CutOff,
    /// It could not run or stopped without a result (the reason).
    Failed(String),
}

/// `work()` on its own thread, waiting at most `budget`.
pub fn bounded<T: Send + 'static>(
    budget: Duration,
    work: impl FnOnce() -> T + Send + 'static,
) -> Result<T, Stopped> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("claim".into())
        .stack_size(STACK)
        .spawn(move || {
            // the receiver may be gone (budget spent): nothing to report to
            let _ = tx.send(work());
        })
        .map_err(|e| Stopped::Failed(format!("the decision could not be started: {e}")))?;
    match rx.recv_timeout(budget) {
        Ok(v) => Ok(v),
        Err(mpsc::RecvTimeoutError::Timeout) => Err(Stopped::CutOff),
        Err(mpsc::RecvTimeoutError::Disconnected) => Err(Stopped::Failed(
            "the decision stopped without a result".into(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slow_decision_is_cut_off_and_a_fast_one_is_kept() {
        let slow = bounded(Duration::from_millis(50), || {
            std::thread::sleep(Duration::from_secs(5));
            1
        });
        assert_eq!(slow, Err(Stopped::CutOff));
        assert_eq!(bounded(Duration::from_secs(5), || 2), Ok(2));
    }
}
