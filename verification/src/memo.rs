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
use std::sync::{Mutex, OnceLock};

/// Results of one decision, by the text of its inputs.
pub struct Memo<V> {
    cell: OnceLock<Mutex<HashMap<String, V>>>,
}

impl<V: Clone> Memo<V> {
    /// An empty memo (for a `static`).
    pub const fn new() -> Memo<V> {
        Memo {
            cell: OnceLock::new(),
        }
    }

    /// The result for `key`, computed by `work` the first time. The lock
    /// is not held while `work` runs: two threads asking at once may both
    /// compute (the same value); the first stored is kept.
    pub fn get_or_compute(&self, key: String, work: impl FnOnce() -> V) -> V {
        let map = self.cell.get_or_init(|| Mutex::new(HashMap::new()));
        if let Some(v) = lock(map).get(&key) {
            return v.clone();
        }
        let v = work();
        lock(map).entry(key).or_insert(v).clone()
    }
}

impl<V: Clone> Default for Memo<V> {
    fn default() -> Self {
        Memo::new()
    }
}

/// The map, also after a panic in another thread (entries are only ever
/// inserted whole, so a poisoned map is still consistent).
fn lock<V>(map: &Mutex<HashMap<String, V>>) -> std::sync::MutexGuard<'_, HashMap<String, V>> {
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
