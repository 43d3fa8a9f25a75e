//! # trig-verdict
//!
//! What a verdict is, below every claim: its [`Status`] (holds, fails,
//! not checkable, …), how it was decided, and the [`Evidence`] it rests on —
//! exact expressions in every form a reader or a program needs ([`Expr`]),
//! and, for a failing identity, a [`Witness`]: a rational (or real) point
//! with both values exactly, found by [`witness`] (and [`real_witness`] for
//! the dependent atoms of a spec basis). The judges (`trig-judge`)
//! return a [`Verdict`]; the report renders it. Nothing here knows what a
//! claim is.
//!
//! ```
//! use trig_symbolic::Sym;
//! use trig_verdict::witness;
//!
//! // (x + 1)² = x² + 1 fails: a point where the sides differ, both values exact
//! let x = Sym::var("x");
//! let x_plus_1 = x.clone() + &Sym::one();
//! let left = x_plus_1.clone() * &x_plus_1;
//! let right = x.clone() * &x + &Sym::one();
//! let w = witness::find(&left, &right, ("left", "right")).expect("they differ");
//! assert_eq!(w.values.len(), 2);
//! assert!(w.exact);
//! ```

pub mod evidence;
pub mod real_witness;
pub mod status;
pub mod verdict;
pub mod witness;

pub use evidence::{Evidence, EvidenceList, Expr, Witness};
pub use status::Status;
pub use verdict::Verdict;

/// `n` with the noun in the singular or plural (`1 claim`, `2 claims`).
pub fn plural(n: usize, singular: &str, plural: &str) -> String {
    format!("{n} {}", if n == 1 { singular } else { plural })
}

#[cfg(test)]
mod tests {
    use super::plural;

    #[test]
    fn plurals_agree() {
        assert_eq!(plural(1, "claim", "claims"), "1 claim");
        assert_eq!(plural(2, "claim", "claims"), "2 claims");
        assert_eq!(plural(0, "box", "boxes"), "0 boxes");
    }
}
