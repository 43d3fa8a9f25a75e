//! Seed 001, the thesis: the endpoint lists of Chapter 4 and (4.30), the
//! cylinder of 5.4.3 and the Appendix 1 listing, and the umbrella T26 over
//! the surface joins (the curve and surface join formulas (4.6)–(4.18),
//! (5.13)–(5.47) and the revised range (−2, 1] are data: the thesis's
//! document file).
//!
//! Conventions, as the text states them: the first curve `Q₁` has control
//! points `P₀…P₃`, the second `Q₂` has `P₄…P₇`; with different parameters the
//! text gives `m₁` to `Q₂` and `m₂` to `Q₁`.

use trig_symbolic::Sym;

use crate::claim::Claim;

mod cylinder;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T26k",
    check: cylinder::t26k,
}];

fn n(k: i64) -> Sym {
    Sym::int(k)
}

/// `a·m + b` for a parameter symbol.
fn lin(a: i64, m: &Sym, b: i64) -> Sym {
    n(a) * m + &n(b)
}
