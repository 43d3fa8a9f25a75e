//! The audit's nonnegativity prover (Weierstrass substitution + exact
//! Bernstein subdivision, [`trig_certify::nonneg::certify`]) in the form
//! `trig_interp::certified_minimum` takes, so the interpolation claims and the
//! `interp` command certify minima the same way.

use rug::Rational;
use trig_interp::Proof;
use trig_symbolic::Sym;

use trig_certify::ParamBox;
use trig_certify::nonneg::{Certificate, certify};

/// Proves `f(θ) ≥ 0` on `[0, π/2]` (no shape parameter), or finds where it
/// is negative.
pub fn prove(f: &Sym) -> Proof {
    match certify(
        f,
        true,
        None,
        &ParamBox::closed(Rational::new(), Rational::new()),
    ) {
        Certificate::NonNegative { .. } => Proof::NonNegative,
        Certificate::Counterexample { z, .. } => Proof::Negative { z },
        Certificate::Pole(why) | Certificate::Undecided(why) => Proof::Undecided(why),
    }
}
