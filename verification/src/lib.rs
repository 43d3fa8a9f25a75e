//! # trig-verification
//!
//! The audit: every claim of `shared/claims.md` as data ([`Claim`]: id,
//! source, statement as printed, checker), each checker stating what is
//! printed and calling the judges of `trig-judge` — identities exactly in
//! the symbolic ring, with the exact residual or a 256-bit MPFR
//! counterexample as evidence when a claim fails; and the claims of a spec
//! file ([`spec_audit`]). A claim never carries its verdict: [`run`]
//! computes every verdict, and `trig-report` renders them.

pub mod budget;
pub mod claim;
mod claims;
pub mod entry;
pub mod figures;
pub mod minimum;
pub mod spec_audit;

pub use claim::{Claim, Seed};
pub use entry::{Document, Entry};
pub use trig_verdict::{Status, Verdict, Witness};

/// Every claim the audit decides, in report order.
pub fn all_claims() -> Vec<Claim> {
    claims::all()
}

/// A claim with its computed verdict.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub claim: Claim,
    pub verdict: Verdict,
}

/// Runs the checkers of the selected claims (all when both filters are `None`),
/// on every available core ([`trig_core::parallel::map`]); the outcomes come back in
/// report order, whatever order the checkers finish in.
pub fn run(seed: Option<Seed>, claim_id: Option<&str>) -> Vec<Outcome> {
    let claims: Vec<Claim> = all_claims()
        .into_iter()
        .filter(|c| seed.is_none_or(|s| c.seed == s))
        .filter(|c| claim_id.is_none_or(|id| c.id.eq_ignore_ascii_case(id)))
        .collect();
    let verdicts = trig_core::parallel::map(&claims, |claim| (claim.check)());
    claims
        .into_iter()
        .zip(verdicts)
        .map(|(claim, verdict)| Outcome { claim, verdict })
        .collect()
}
