//! Claims of the second list of `shared/claims.md` ("More claims:
//! properties, shapes, conics, and the arithmetic of the text") that the
//! judges decide so far: linear independence, the convex hull, affine
//! invariance. Each states what is printed and calls a judge.

use trig_core::Family;

use crate::claim::{Claim, Seed};
use crate::judge::{independence, nonnegative, unity};
use crate::verdict::Verdict;

/// In report order (after each document's first-list claims).
pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T50",
        seed: Seed::S001,
        source: "Definition 3.2 (implicit: \"four basis functions\")",
        statement: "b0 … b3 of (3.7) are linearly independent for every m",
        check: t50,
    },
    Claim {
        id: "M16",
        seed: Seed::S000,
        source: "3.1.1",
        statement: "the curve (6) always lies in the convex hull of its control polygon",
        check: m16,
    },
    Claim {
        id: "M17",
        seed: Seed::S000,
        source: "3.1.2",
        statement: "affine invariance L(Σ S_j F_j(n)) = Σ L(S_j) F_j(n) (sum written 0 … n)",
        check: m17,
    },
    Claim {
        id: "D18",
        seed: Seed::S002,
        source: "Definition 1 (implicit: \"basis functions\")",
        statement: "b0 … b5 are linearly independent",
        check: d18,
    },
];

/// Every `m`: the judge's exact decision does not depend on a range when
/// the Wronskian's coefficients have no common factor.
fn t50() -> Verdict {
    independence::independent(&Family::ThesisCubic, None)
}

/// Unity and nonnegativity of the segment functions on the published
/// range of ζ: the convex-hull property of every segment of (6).
fn m16() -> Verdict {
    nonnegative::convex_hull(&Family::Seed000Uniform, None)
}

/// An affine map `L(x) = Ax + b` commutes with `Σ S_j F_j` for every `S_j`
/// exactly when `Σ F_j = 1` (the translation part): decided as the
/// partition of unity of the segment functions.
fn m17() -> Verdict {
    let mut v = unity::unity(&Family::Seed000Uniform);
    v.evidence.insert(
        0,
        "L(Σ S_j F_j) = A Σ S_j F_j + b and Σ L(S_j) F_j = A Σ S_j F_j + b Σ F_j: equal for every affine L exactly when Σ F_j = 1",
    );
    v
}

fn d18() -> Verdict {
    independence::independent(&Family::Seed002Quartic, None)
}
