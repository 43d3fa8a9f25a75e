//! The four verdicts a claim can get.

use std::fmt;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// What the audit concluded about a claim.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize, JsonSchema,
)]
#[serde(rename_all = "kebab-case")]
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
