//! Every claim of `shared/claims.md` that this stage decides, one file per
//! source document.

use crate::claim::Claim;

mod shape_effect;

/// The Rust checkers of the claims still marked `built-in`.
pub fn all() -> Vec<Claim> {
    shape_effect::CLAIMS.to_vec()
}
