//! Where the joins of a basis break: every join kind (`C⁰ … C³`, `G¹`,
//! `G²`), with one set of parameters for both segments and with each
//! segment's own, solved exactly for the second segment's forced control
//! points (Gauss–Jordan over `Q(parameters, G factors)`); a forced point
//! is singular where its pivot vanishes. A paper that prints "the joins
//! break at `m = −2`" (division by `m + 2`) is decided by comparing the
//! pivots' vanishing sets with the printed values: it holds when some join
//! is singular and every singularity is a printed value (of the parameter
//! or of a segment's copy of it).

use std::collections::BTreeSet;

use trig_deriv::{JoinKind, JoinSetup, Wrt, solve_join, vanishing};
use trig_symbolic::Sym;

use crate::exact::{ExactBasis, symbols};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The parameters of the joins: `same` on both segments, or `different`
/// (the first segment's, the second's); `label` names them in the evidence
/// (`m`).
#[derive(Debug)]
pub struct Segments {
    pub same: Vec<Sym>,
    pub different: [Vec<Sym>; 2],
    pub label: String,
}

/// The joins of `basis` in the convention `wrt` (`G` factors `factors`)
/// break exactly at the printed values `printed` (`(parameter, value)`;
/// `copies` the segment copies of each parameter, in the same order).
pub fn join_singularities<B: ExactBasis>(
    basis: &B,
    wrt: Wrt,
    factors: [Sym; 2],
    segments: &Segments,
    printed: &[(Sym, Sym)],
) -> Verdict {
    let n = basis.function_names().len();
    let (p, q) = (symbols("P", n), symbols("Q", n));
    let mut evidence = Vec::new();
    let mut singular = BTreeSet::new();
    for kind in JoinKind::ALL {
        for same in [true, false] {
            let (first, second) = if same {
                (&segments.same, &segments.same)
            } else {
                (&segments.different[0], &segments.different[1])
            };
            let setup = JoinSetup {
                basis,
                first_params: first,
                second_params: second,
                wrt,
                h: (Sym::one(), Sym::one()),
                factors: factors.clone(),
            };
            let which = if same { "same" } else { "different" };
            match solve_join(&setup, kind, &p, &q) {
                Ok(solved) => {
                    let conditions: Vec<String> = solved
                        .forced
                        .iter()
                        .flat_map(|f| vanishing(&f.pivot))
                        .collect();
                    singular.extend(conditions.iter().cloned());
                    evidence.push(format!(
                        "{kind} ({which} {}): pivots vanish where {}",
                        segments.label,
                        if conditions.is_empty() {
                            "never".to_string()
                        } else {
                            conditions.join(", ")
                        }
                    ));
                }
                Err(e) => evidence.push(format!("{kind}: {e}")),
            }
        }
    }
    // each printed value, of the parameter and of its segment copies,
    // described by the same function as the pivots
    let expected: BTreeSet<String> = printed
        .iter()
        .flat_map(|(param, value)| vanishing(&(param.clone() - value)))
        .collect();
    let status = if !singular.is_empty() && singular.is_subset(&expected) {
        Status::Holds
    } else {
        Status::Fails
    };
    evidence.push(format!(
        "singular set over all joins: {}",
        singular.into_iter().collect::<Vec<_>>().join(", ")
    ));
    let field: Vec<String> = segments
        .same
        .iter()
        .chain(&factors)
        .map(Sym::to_unicode)
        .collect();
    let method = format!(
        "pivots of the exact join solution (Gauss–Jordan over Q({})) and where they vanish",
        field.join(", ")
    );
    Verdict::new(status, method, evidence)
}
