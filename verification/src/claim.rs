//! The Rust checkers of the claims not yet stated as data, by id, and what
//! several of them share. A claim never carries its verdict.

use trig_verdict::{Evidence, Status, Verdict};

/// The Rust checker of a claim still marked `built-in` in its document
/// file (`documents/`), which states what is printed (id, source,
/// statement); issue 41 moves each to a check of the spec language.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The claim's id in its document file (`T4`, `T4b`, …).
    pub id: &'static str,
    /// The checker.
    pub check: fn() -> Verdict,
}

/// How an umbrella claim is decided, as the report states it.
const UMBRELLA: &str =
    "umbrella: holds only if every part holds (each part is reported as its own claim)";

/// An umbrella claim over separately reported claims (T24 over T24a–f):
/// a conjunction whose evidence is one line per part with its verdict,
/// and, for each part that does not hold, its first witness.
pub(crate) fn umbrella(parts: Vec<(String, Verdict)>) -> Verdict {
    let status = Status::conjunction(parts.iter().map(|(_, v)| v.status));
    let mut evidence = Vec::new();
    for (name, v) in parts {
        let mut line = Evidence::note(format!("reported as claim {name}"));
        line.subject = Some(name.clone());
        line.status = Some(v.status);
        evidence.push(line);
        if v.status != Status::Holds
            && let Some(w) = v
                .evidence
                .into_vec()
                .into_iter()
                .find(|e| e.witness.is_some())
        {
            evidence.push(w.in_part(name, v.status));
        }
    }
    Verdict::new(status, UMBRELLA, evidence)
}
