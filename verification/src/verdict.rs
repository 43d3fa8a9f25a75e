//! Verdicts and their evidence.

use std::fmt;

/// What the audit concluded about a claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Status {
    /// Proved exactly (or certified).
    Holds,
    /// Refuted, with evidence.
    Fails,
    /// The printed form fails; a named minimal correction holds.
    HoldsAfterCorrection,
    /// The formula is missing or unreadable.
    NotCheckable,
}

impl Status {
    /// Every status, in report order.
    pub const ALL: [Status; 4] = [
        Status::Holds,
        Status::Fails,
        Status::HoldsAfterCorrection,
        Status::NotCheckable,
    ];

    /// The status of "every part holds" from the parts' statuses: a failed
    /// part decides it (fails; a part that holds only after a correction
    /// counts as failing as printed); otherwise an undecided part leaves it
    /// not-checkable; otherwise it holds.
    pub fn conjunction(parts: impl IntoIterator<Item = Status>) -> Status {
        let mut undecided = false;
        for s in parts {
            match s {
                Status::Fails | Status::HoldsAfterCorrection => return Status::Fails,
                Status::NotCheckable => undecided = true,
                Status::Holds => {}
            }
        }
        if undecided {
            Status::NotCheckable
        } else {
            Status::Holds
        }
    }

    /// The verdict as the report prints it.
    pub fn label(&self) -> &'static str {
        match self {
            Status::Holds => "holds",
            Status::Fails => "fails",
            Status::HoldsAfterCorrection => "holds-after-correction",
            Status::NotCheckable => "not-checkable",
        }
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.label())
    }
}

/// A computed verdict: status, how it was decided, the evidence (exact
/// residuals, values, counterexamples), and the correction where one holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Verdict {
    pub status: Status,
    /// How we know (e.g. "exact identity in Q(params)[s, c]/(s² + c² − 1)").
    pub method: String,
    /// Lines of evidence, each self-contained and re-checkable.
    pub evidence: Vec<String>,
    /// The minimal correction, for [`Status::HoldsAfterCorrection`] (or a
    /// suggested one for [`Status::Fails`]).
    pub correction: Option<String>,
}

impl Verdict {
    /// A verdict with no correction.
    pub fn new(status: Status, method: impl Into<String>, evidence: Vec<String>) -> Self {
        Verdict {
            status,
            method: method.into(),
            evidence,
            correction: None,
        }
    }

    /// The same verdict with a correction.
    pub fn with_correction(mut self, correction: impl Into<String>) -> Self {
        self.correction = Some(correction.into());
        self
    }

    /// `not-checkable`, with the reason.
    pub fn not_checkable(reason: impl Into<String>) -> Self {
        Verdict::new(Status::NotCheckable, "none possible", vec![reason.into()])
    }

    /// Combines the verdicts of the parts of one claim (a conjunction): it
    /// holds only if every part holds, fails when a part fails, and is
    /// not-checkable when no part fails but one could not be decided; the
    /// evidence of every part is kept, in order.
    pub fn all(method: impl Into<String>, parts: Vec<(String, Verdict)>) -> Self {
        let status = Status::conjunction(parts.iter().map(|(_, v)| v.status));
        let evidence = parts
            .iter()
            .flat_map(|(name, v)| {
                v.evidence
                    .iter()
                    .map(move |e| format!("{name}: {} — {e}", v.status))
            })
            .collect();
        Verdict::new(status, method, evidence)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_claim_holds_only_when_every_part_holds() {
        let holds = Verdict::new(Status::Holds, "m", vec!["ok".into()]);
        let fails = Verdict::new(Status::Fails, "m", vec!["residual 1".into()]);
        let all = Verdict::all(
            "m",
            vec![("a".into(), holds.clone()), ("b".into(), holds.clone())],
        );
        assert_eq!(all.status, Status::Holds);
        let some = Verdict::all("m", vec![("a".into(), holds), ("b".into(), fails)]);
        assert_eq!(some.status, Status::Fails);
        assert_eq!(
            some.evidence,
            vec!["a: holds — ok", "b: fails — residual 1"]
        );
    }
}
