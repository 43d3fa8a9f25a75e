//! The namespace of a command's output ([`trig_symbolic::Names`]): the
//! basis's user names, from which every symbol the command introduces
//! (control points, weights, interval lengths, `G` factors, segment copies
//! of parameters) is drawn so that none reads like another.

use trig_core::Described;
use trig_specfile::AnyBasis;
use trig_symbolic::{Names, Sym};

use crate::commands::CliError;

/// The user names of `subject`: parameters (with their printed symbols)
/// and, for a spec file, its functions and definitions.
pub fn names_of(subject: &AnyBasis) -> Names {
    match subject {
        AnyBasis::Spec(spec) => spec.names(),
        AnyBasis::Family(f) => {
            let params = f.param_names();
            Names::of_parameters(params.iter().map(|p| (p.as_str(), p.as_str())))
        }
    }
}

/// The copies `p1` (or `p2`) of `subject`'s parameters on one segment of a
/// join, reserved in `names`; an error naming the clash when a copy would
/// read as another name (a parameter `m1` beside `m`).
pub fn segment_copies(
    names: &mut Names,
    subject: &AnyBasis,
    segment: usize,
) -> Result<Vec<Sym>, CliError> {
    subject
        .param_names()
        .iter()
        .map(|p| {
            names
                .fixed(
                    &format!("{p}{segment}"),
                    &format!("`{p}` on segment {segment}"),
                )
                .map_err(|e| CliError::Usage(format!("--params different: {e}")))
        })
        .collect()
}
