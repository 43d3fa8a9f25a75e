//! Verdicts and their evidence.

use crate::evidence::{Evidence, EvidenceList};
use crate::status::Status;

/// A computed verdict: status, how it was decided, the evidence (exact
/// residuals, values, counterexamples), and the correction where one holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Verdict {
    pub status: Status,
    /// How we know (e.g. "exact identity in Q(params)[s, c]/(s² + c² − 1)").
    pub method: String,
    /// The evidence, item by item ([`crate::evidence`]).
    pub evidence: EvidenceList,
    /// The minimal correction, for [`Status::HoldsAfterCorrection`] (or a
    /// suggested one for [`Status::Fails`]).
    pub correction: Option<String>,
}

impl Verdict {
    /// A verdict with no correction; evidence items or prose notes.
    pub fn new<E: Into<Evidence>>(
        status: Status,
        method: impl Into<String>,
        evidence: impl IntoIterator<Item = E>,
    ) -> Self {
        Verdict {
            status,
            method: method.into(),
            evidence: evidence.into_iter().collect(),
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
        Verdict::new(
            Status::NotCheckable,
            "none possible",
            [Evidence::note(reason)],
        )
    }

    /// The evidence of this verdict as the part `name` of a larger claim:
    /// every item placed inside the part, with this verdict's status. A
    /// part with a single item that checks nothing else (no subject of its
    /// own, or the part's name as subject) is that item, about the part.
    pub fn into_part(self, name: &str) -> Vec<Evidence> {
        let status = self.status;
        let mut items = self.evidence.into_vec();
        if let [item] = items.as_mut_slice()
            && item.parts.is_empty()
            && item.subject.as_deref().is_none_or(|s| s == name)
        {
            item.subject = Some(name.to_string());
            item.status = Some(item.status.unwrap_or(status));
            return items;
        }
        items
            .into_iter()
            .map(|e| e.in_part(name.to_string(), status))
            .collect()
    }

    /// Combines the verdicts of the parts of one claim (a conjunction): it
    /// holds only if every part holds, fails when a part fails, and is
    /// not-checkable when no part fails but one could not be decided; the
    /// evidence of every part is kept, in order, inside its part.
    pub fn all(method: impl Into<String>, parts: Vec<(String, Verdict)>) -> Self {
        let status = Status::conjunction(parts.iter().map(|(_, v)| v.status));
        let evidence: Vec<Evidence> = parts
            .into_iter()
            .flat_map(|(name, v)| v.into_part(&name))
            .collect();
        Verdict::new(status, method, evidence)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_claim_holds_only_when_every_part_holds() {
        let holds = Verdict::new(Status::Holds, "m", ["ok"]);
        let fails = Verdict::new(Status::Fails, "m", ["residual 1"]);
        let all = Verdict::all(
            "m",
            vec![("a".into(), holds.clone()), ("b".into(), holds.clone())],
        );
        assert_eq!(all.status, Status::Holds);
        let some = Verdict::all("m", vec![("a".into(), holds), ("b".into(), fails)]);
        assert_eq!(some.status, Status::Fails);
        let lines: Vec<String> = some.evidence.iter().map(Evidence::line).collect();
        assert_eq!(lines, ["a: holds — ok", "b: fails — residual 1"]);
        // a part of several items keeps them inside it
        let two = Verdict::new(Status::Fails, "m", ["x", "y"]);
        let nested = Verdict::all("m", vec![("c".into(), two)]);
        assert_eq!(nested.evidence[1].line(), "c: fails — y");
    }
}
