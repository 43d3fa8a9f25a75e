//! Time-bounded decisions: a decision that does not finish within its
//! budget is `not-checkable` (with the reason), never a hang.
//!
//! The certification searches (Bernstein subdivision, resultants, Sturm
//! sequences) are finite but can be long for formulas inside every
//! documented limit. [`within`] runs one decision on its own thread and
//! waits at most the budget; a decision that runs over is abandoned (its
//! thread ends with the process) and reported as not checkable.

use std::sync::mpsc;
use std::time::Duration;

use crate::verdict::Verdict;

/// Default budget of one claim of a spec audit.
pub const CLAIM_BUDGET: Duration = Duration::from_secs(10);

/// Stack of a decision's thread: as deep as the main thread's and more.
const STACK: usize = 64 << 20;

/// `decide()`, or `not-checkable` if it takes longer than `budget` (or
/// its thread cannot start or panics).
pub fn within(budget: Duration, decide: impl FnOnce() -> Verdict + Send + 'static) -> Verdict {
    bounded(budget, decide).unwrap_or_else(Verdict::not_checkable)
}

/// `work()` on its own thread, waiting at most `budget`; the reason when
/// it did not finish (time limit, thread not started, panic).
pub fn bounded<T: Send + 'static>(
    budget: Duration,
    work: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("claim".into())
        .stack_size(STACK)
        .spawn(move || {
            // the receiver may be gone (budget spent): nothing to report to
            let _ = tx.send(work());
        })
        .map_err(|e| format!("the decision could not be started: {e}"))?;
    match rx.recv_timeout(budget) {
        Ok(v) => Ok(v),
        Err(mpsc::RecvTimeoutError::Timeout) => Err(format!(
            "the decision did not finish within the time limit of {} s (the certification search was stopped; a longer --time-limit may decide it)",
            budget.as_secs_f64()
        )),
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            Err("the decision stopped without a result".into())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Status;

    #[test]
    fn a_slow_decision_is_not_checkable_and_a_fast_one_is_kept() {
        let slow = within(Duration::from_millis(50), || {
            std::thread::sleep(Duration::from_secs(5));
            Verdict::not_checkable("never seen")
        });
        assert_eq!(slow.status, Status::NotCheckable);
        assert!(slow.evidence[0].contains("time limit"), "{slow:?}");
        let fast = within(Duration::from_secs(5), || {
            Verdict::new(Status::Holds, "m", Vec::<String>::new())
        });
        assert_eq!(fast.status, Status::Holds);
    }
}
