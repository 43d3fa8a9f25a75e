//! Every claim of `shared/claims.md` that this stage decides, one file per
//! source document.

use crate::claim::Claim;

mod seed000_appendix_e;
mod seed000_appendix_print;

/// The Rust checkers of the claims still marked `built-in`.
pub fn all() -> Vec<Claim> {
    [seed000_appendix_e::CLAIMS].concat()
}
