//! Work shared between claims: a decision that several entries ask for
//! with the same inputs (the battery's nonnegativity and a printed
//! "maximal range" claim over the declared range; a spec file audited
//! twice in one process) is computed once per process.
//!
//! The key is the full text of every input the decision reads — the
//! expanded exact functions, the domain, the parameters, the range and the
//! witness context (`Debug` forms, which print every field) — never a name,
//! so two bases that share names but not formulas never share a result.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Results of one decision, by the text of its inputs.
pub struct Memo<V> {
    cell: OnceLock<Mutex<HashMap<String, Arc<OnceLock<V>>>>>,
}

impl<V: Clone> Memo<V> {
    /// An empty memo (for a `static`).
    pub const fn new() -> Memo<V> {
        Memo {
            cell: OnceLock::new(),
        }
    }

    /// The result for `key`, computed by `work` the first time. A second
    /// caller with the same key waits for that computation instead of
    /// repeating it (claims run in parallel, and an umbrella claim asks for
    /// what its parts decide); the map itself is locked only to find the
    /// key's cell, so other keys are computed meanwhile.
    pub fn get_or_compute(&self, key: String, work: impl FnOnce() -> V) -> V {
        let map = self.cell.get_or_init(|| Mutex::new(HashMap::new()));
        let cell = Arc::clone(lock(map).entry(key).or_default());
        cell.get_or_init(work).clone()
    }
}

impl<V> std::fmt::Debug for Memo<V> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Memo").finish_non_exhaustive()
    }
}

impl<V: Clone> Default for Memo<V> {
    fn default() -> Self {
        Memo::new()
    }
}

/// The map, also after a panic in another thread (entries are only ever
/// inserted whole, so a poisoned map is still consistent).
fn lock<V>(
    map: &Mutex<HashMap<String, Arc<OnceLock<V>>>>,
) -> std::sync::MutexGuard<'_, HashMap<String, Arc<OnceLock<V>>>> {
    map.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn computes_once_per_key() {
        static MEMO: Memo<u32> = Memo::new();
        let mut runs = 0;
        assert_eq!(
            MEMO.get_or_compute("a".into(), || {
                runs += 1;
                1
            }),
            1
        );
        assert_eq!(
            MEMO.get_or_compute("a".into(), || {
                runs += 1;
                2
            }),
            1
        );
        assert_eq!(
            MEMO.get_or_compute("b".into(), || {
                runs += 1;
                3
            }),
            3
        );
        assert_eq!(runs, 2);
    }
}
