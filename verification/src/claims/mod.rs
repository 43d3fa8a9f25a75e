//! Every claim of `shared/claims.md` that this stage decides, one file per
//! source document.

use crate::claim::Claim;

mod local_control;
mod local_control_joins;
mod properties;
mod properties_formulas;
mod second_list;
mod seed000;
mod seed000_appendix_b;
mod seed000_appendix_c;
mod seed000_appendix_e;
mod seed000_appendix_print;
mod seed002;
mod seed004;
mod shape_effect;
mod thesis;
mod thesis_interp;
mod thesis_out_of_range;
mod thesis_text;

/// The Rust checkers of the claims still marked `built-in`.
pub fn all() -> Vec<Claim> {
    [
        thesis::CLAIMS,
        seed000::CLAIMS,
        seed000_appendix_c::CLAIMS,
        seed000_appendix_e::CLAIMS,
        seed000_appendix_b::CLAIMS,
        properties::CLAIMS,
        second_list::CLAIMS,
        thesis_out_of_range::CLAIMS,
        thesis_text::CLAIMS,
        shape_effect::CLAIMS,
        local_control::CLAIMS,
    ]
    .concat()
}
