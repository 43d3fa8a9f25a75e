//! Join claims of a spec file, stated for the join judge
//! ([`trig_judge::join`]): the printed conditions as printed terms over
//! their denominators, in the file's convention, with equal or different
//! parameters.

use trig_deriv::{JoinKind, Wrt};
use trig_specfile::{Condition, Spec};
use trig_symbolic::Sym;

use trig_judge::domain::param_symbols;
use trig_judge::exact::symbols;
use trig_judge::join::{Printed, PrintedJoin, audit, conventions};
use trig_verdict::verdict::Verdict;

/// Printed join conditions, decided by the join judge as for the catalog:
/// the printed convention, a sign typo, the other conventions of the
/// basis, the derived formula; singular where a printed division vanishes
/// inside the ranges.
pub fn printed_join(
    spec: &Spec,
    kind: JoinKind,
    wrt: Wrt,
    different: bool,
    factors: &[String; 2],
    conditions: &[Condition],
) -> Verdict {
    let n = spec.functions.len();
    let (first, second) = if different {
        (spec.segment_params(1), spec.segment_params(2))
    } else {
        (param_symbols(spec), param_symbols(spec))
    };
    let (p, q) = (symbols("P", n), symbols("Q", n));
    let printed = conditions
        .iter()
        .map(|c| {
            Printed::over(c.point, c.terms.clone(), c.denominator.clone())
                .singular(c.singular.clone())
        })
        .collect();
    let mut notes = vec![format!(
        "printed conditions: {}",
        conditions
            .iter()
            .map(|c| c.text.as_str())
            .collect::<Vec<_>>()
            .join("; ")
    )];
    if different {
        notes.push(format!(
            "parameters: {} on the first segment, {} on the second",
            list(&first),
            list(&second)
        ));
    }
    let mut join = PrintedJoin::new(spec, kind, (first, second), (p, q), printed);
    join.factors = [Sym::var(&factors[0]), Sym::var(&factors[1])];
    join.conventions = conventions(spec, wrt);
    join.declared = true;
    join.notes = notes;
    audit(&join)
}

fn list(xs: &[Sym]) -> String {
    xs.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}
