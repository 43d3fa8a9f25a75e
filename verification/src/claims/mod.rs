//! Every claim of `shared/claims.md` that this stage decides, one file per
//! source document.

use crate::claim::Claim;

mod seed000;
mod seed002;
mod seed003;
mod seed004;
mod thesis;

/// All claims, in report order.
pub fn all() -> Vec<Claim> {
    [
        thesis::CLAIMS,
        seed000::CLAIMS,
        seed002::CLAIMS,
        seed003::CLAIMS,
        seed004::CLAIMS,
    ]
    .concat()
}
