//! A deterministic parallel map over the cores of the machine.
//!
//! For independent computations (the claims of an audit; the functions of a
//! basis a certificate proves one by one): a pool of scoped threads takes
//! them one at a time from a shared counter (so a long item does not hold
//! up a queue of short ones), and each result is stored at its item's
//! index. The output is therefore the same as a sequential `map`, in the
//! same order, whatever the number of threads or the order in which they
//! finish. Work budgets are counted per computation, never per thread or
//! by time ([`crate::work`]), so a result never depends on the threads.

use std::num::NonZeroUsize;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Stack of a worker thread (reserved, not committed): formulas are
/// evaluated recursively.
const STACK: usize = 64 << 20;

/// Number of worker threads: the `TRIG_AUDIT_THREADS` environment variable
/// when it is a positive integer, otherwise the available parallelism.
pub fn threads() -> usize {
    std::env::var("TRIG_AUDIT_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<NonZeroUsize>().ok())
        .or_else(|| std::thread::available_parallelism().ok())
        .map_or(1, NonZeroUsize::get)
}

/// `items.iter().map(f).collect()`, computed on up to [`threads`] threads.
///
/// # Panics
/// When `f` panics for some item (the panic is propagated).
pub fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let workers = threads().min(items.len());
    if workers <= 1 {
        return items.iter().map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = items.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..workers {
            let work = || {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(i) else { break };
                    let r = f(item);
                    *slots[i].lock().expect("no worker panicked holding a slot") = Some(r);
                }
            };
            // as deep a stack as a decision's own thread; without one, the
            // work runs on this thread when the others are done
            if std::thread::Builder::new()
                .stack_size(STACK)
                .spawn_scoped(scope, work)
                .is_err()
            {
                break;
            }
        }
    });
    // items no worker took (no thread could be started)
    for (i, item) in items.iter().enumerate() {
        let mut slot = slots[i].lock().expect("no worker panicked holding a slot");
        if slot.is_none() {
            *slot = Some(f(item));
        }
    }
    slots
        .into_iter()
        .map(|slot| {
            slot.into_inner()
                .expect("no worker panicked holding a slot")
                .expect("every item was computed")
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_as_a_sequential_map_in_order() {
        let items: Vec<u64> = (0..200).collect();
        // uneven work, so threads finish out of order
        let f = |&n: &u64| (0..(n % 7) * 10_000).fold(n, |a, k| a.wrapping_mul(31) ^ k);
        let sequential: Vec<u64> = items.iter().map(f).collect();
        assert_eq!(map(&items, f), sequential);
        assert_eq!(map(&[] as &[u64], f), Vec::<u64>::new());
    }
}
