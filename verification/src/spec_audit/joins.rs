//! Join claims of a spec file, stated for the join judge
//! ([`trig_judge::join`]): the printed conditions as printed terms over
//! their denominators, in the file's convention, with equal or different
//! parameters, the segments' points and parameters named as printed.

use trig_deriv::{JoinKind, Wrt};
use trig_specfile::{Condition, JoinSegments, Spec};
use trig_symbolic::Sym;

use trig_judge::domain::param_symbols;
use trig_judge::join::{Printed, PrintedJoin, audit, conventions, holds_as_printed};
use trig_judge::join_singular::{Segments, join_singularities};
use trig_verdict::verdict::Verdict;

/// What a join claim states besides its conditions.
pub struct Stated<'a> {
    pub kind: JoinKind,
    pub wrt: Wrt,
    /// The claim declares its convention (`wrt` not `unstated`).
    pub declared: bool,
    pub different: bool,
    /// The printed factors give the first segment's derivatives from the
    /// second's.
    pub reversed: bool,
    pub segments: &'a JoinSegments,
}

/// Printed join conditions, decided by the join judge as for the catalog:
/// the printed convention, a sign typo, the other conventions of the
/// basis, the derived formula; singular where a printed division vanishes
/// inside the ranges. With another reading of the segments' parameters
/// (`also-params`), whether the printed formulas hold under it too, for
/// information.
pub fn printed_join(
    spec: &Spec,
    stated: Stated<'_>,
    factors: &[String; 2],
    conditions: &[Condition],
) -> Verdict {
    let [first, second] = if stated.different {
        stated.segments.param_copies(spec)
    } else {
        [param_symbols(spec), param_symbols(spec)]
    };
    let [p, q] = stated
        .segments
        .points
        .clone()
        .map(|names| names.iter().map(|n| Sym::var(n)).collect::<Vec<_>>());
    let printed = conditions
        .iter()
        .map(|c| {
            Printed::over(c.point, c.terms.clone(), c.denominator.clone())
                .brackets(c.brackets.clone())
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
    if stated.different {
        notes.push(format!(
            "parameters: {} on the first segment, {} on the second",
            list(&first),
            list(&second)
        ));
    }
    let [a, b] = factors.each_ref().map(|f| Sym::var(f));
    if stated.reversed {
        let (a, b) = (a.to_unicode(), b.to_unicode());
        notes.push(format!(
            "printed orientation (R1, R2 the first and second segment): R1'(1) = {a}·R2'(0), R1''(1) = {a}²·R2''(0) + {b}·R2'(0); decided as R2'(0) = (1/{a})·R1'(1), R2''(0) = (1/{a}²)·R1''(1) − ({b}/{a}³)·R1'(1)"
        ));
    }
    let mut join = PrintedJoin::new(spec, stated.kind, (first, second), (p, q), printed);
    join.factors = if stated.reversed {
        [Sym::one() / &a, -(b / &(a.clone() * &a * &a))]
    } else {
        [a, b]
    };
    join.conventions = conventions(spec, stated.wrt);
    join.declared = stated.declared;
    join.notes = notes;
    let mut verdict = audit(&join);
    if let Some([first, second]) = &stated.segments.also {
        verdict.evidence.push(other_reading(&join, first, second));
    }
    verdict
}

/// For information, not a verdict: whether the printed formulas hold in
/// the printed convention when the segments carry the parameters `first`,
/// `second` instead (another reading of the print).
fn other_reading(join: &PrintedJoin<&Spec>, first: &[Sym], second: &[Sym]) -> String {
    let reading = PrintedJoin {
        first_params: first.to_vec(),
        second_params: second.to_vec(),
        ..join.clone()
    };
    let list = |xs: &[Sym]| {
        xs.iter()
            .map(Sym::to_unicode)
            .collect::<Vec<_>>()
            .join(", ")
    };
    format!(
        "for information, not a verdict: read with {} on the first segment and {} on the second, the printed formulas {} with derivatives in {}",
        list(first),
        list(second),
        if holds_as_printed(&reading) {
            "hold"
        } else {
            "fail"
        },
        join.convention()
    )
}

fn list(xs: &[Sym]) -> String {
    xs.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// Where the joins of the basis break, against the printed values (each
/// of the parameter and of its segment copies).
pub fn join_singular(
    spec: &Spec,
    wrt: Wrt,
    copies: &[Vec<Sym>; 2],
    values: &[(usize, Sym)],
) -> Verdict {
    let same = param_symbols(spec);
    let printed: Vec<(Sym, Sym)> = values
        .iter()
        .flat_map(|(i, v)| {
            [
                same[*i].clone(),
                copies[0][*i].clone(),
                copies[1][*i].clone(),
            ]
            .map(|p| (p, v.clone()))
        })
        .collect();
    let label = spec
        .params
        .iter()
        .map(|p| p.symbol.clone())
        .collect::<Vec<_>>()
        .join(", ");
    let factors = spec.join_factors().map(|f| Sym::var(&f));
    let segments = Segments {
        same,
        different: copies.clone(),
        label,
    };
    join_singularities(spec, wrt, factors, &segments, &printed)
}
