//! Curves and joins of a spec basis, through the same join solver as the
//! catalog ([`trig_deriv::solve_join`] on `JoinSetup<&Spec>`): derived
//! `Cᵏ` conditions, printed `Cᵏ`/`G¹`/`G²` conditions with equal or
//! different parameters, printed curve derivatives (terminal tangents), and
//! the continuity of the uniform B-spline assembled from the functions.

use trig_deriv::{
    End, JoinKind, JoinSetup, Wrt, curve_endpoint_derivatives, knot_derivatives, solve_join,
    vanishing,
};
use trig_specfile::{Condition, Spec};
use trig_symbolic::Sym;

use super::geometry::{describe_wrt, end_text};
use super::{K, params};
use crate::exact::{IDENTITY, identities, symbols};
use crate::status::Status;
use crate::verdict::Verdict;

/// The join of two segments of the spec basis in the convention `wrt`.
fn setup<'a>(
    spec: &'a Spec,
    wrt: Wrt,
    first: &'a [Sym],
    second: &'a [Sym],
    factors: [Sym; 2],
) -> JoinSetup<'a, &'a Spec> {
    JoinSetup {
        basis: spec,
        first_params: first,
        second_params: second,
        wrt,
        h: (Sym::one(), Sym::one()),
        factors,
    }
}

/// The control points the join forces, as printed lines (with where each
/// formula is singular).
fn forced_lines(
    spec: &Spec,
    s: &JoinSetup<'_, &Spec>,
    kind: JoinKind,
) -> Result<Vec<String>, String> {
    let n = spec.functions.len();
    let (p, q) = (symbols("P", n), symbols("Q", n));
    let join = solve_join(s, kind, &p, &q).map_err(|e| e.to_string())?;
    Ok(join
        .forced
        .iter()
        .map(|f| {
            let mut line = format!("Q{} = {}", f.index, f.value);
            let singular = vanishing(&f.pivot);
            if !singular.is_empty() {
                line.push_str(&format!(" (singular where {})", singular.join(", ")));
            }
            line
        })
        .collect())
}

/// The standard battery's `Cᵏ` join: the second segment's points forced by
/// the join (solved exactly). Holds when every order can be met.
pub fn derived_join(spec: &Spec, order: usize) -> Verdict {
    let p = params(spec);
    let wrt = if spec.legacy.is_some() {
        Wrt::Angle
    } else {
        Wrt::Variable
    };
    let s = setup(spec, wrt, &p, &p, trig_deriv::default_factors());
    let head = format!(
        "conditions Q^(k)(start) = P^(k)(end), k ≤ {order}, {}, solved exactly for the second segment's control points",
        describe_wrt(spec, wrt)
    );
    match forced_lines(spec, &s, JoinKind::C(order as u8)) {
        Ok(lines) => {
            let mut evidence = vec![head];
            evidence.extend(lines);
            Verdict::new(Status::Holds, IDENTITY, evidence)
        }
        Err(why) => Verdict::new(
            Status::Fails,
            IDENTITY,
            vec![head, format!("a C{order} join cannot be met: {why}")],
        ),
    }
}

/// Printed join conditions: with them substituted, every condition of the
/// kind holds exactly. On failure the conditions the solver derives are
/// shown as the correction.
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
        (params(spec), params(spec))
    };
    let factors = [Sym::var(&factors[0]), Sym::var(&factors[1])];
    let s = setup(spec, wrt, &first, &second, factors);
    let p = symbols("P", n);
    let mut q = symbols("Q", n);
    for c in conditions {
        q[c.point] = c.value.clone();
    }
    let zero = Sym::zero();
    let parts = s
        .residuals(kind, &p, &q)
        .into_iter()
        .enumerate()
        .map(|(j, r)| {
            (
                format!("order {j} of {kind}: Q side − P side"),
                r,
                zero.clone(),
            )
        })
        .collect();
    let mut v = identities(parts);
    let mut head = vec![format!(
        "printed conditions: {}",
        conditions
            .iter()
            .map(|c| c.text.as_str())
            .collect::<Vec<_>>()
            .join("; ")
    )];
    if different {
        head.push(format!(
            "parameters: {} on the first segment, {} on the second",
            list(&first),
            list(&second)
        ));
    }
    head.push(describe_wrt(spec, wrt));
    v.evidence.prepend(head);
    let singular: Vec<String> = conditions
        .iter()
        .flat_map(|c| c.singular.iter().cloned())
        .collect();
    if !singular.is_empty() {
        v.status = Status::Fails;
        v.evidence.push(format!(
            "the printed conditions are singular inside the printed ranges, where they give no join: {}",
            singular.join("; ")
        ));
    }
    if v.status == Status::Fails {
        if let Ok(lines) = forced_lines(spec, &s, kind) {
            v = v.with_correction(format!("the join holds with {}", lines.join("; ")));
        }
    }
    v
}

fn list(xs: &[Sym]) -> String {
    xs.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// A printed derivative of the curve `Σ bᵢPᵢ` at one end (terminal
/// tangents): exact; a failure shows the computed combination.
pub fn curve_derivative(
    spec: &Spec,
    end: End,
    order: usize,
    wrt: Wrt,
    text: &str,
    value: &Sym,
) -> Verdict {
    let p = symbols("P", spec.functions.len());
    let d =
        curve_endpoint_derivatives::<Sym, K>(spec, &params(spec), &p, None, end, wrt, &Sym::one());
    let computed = d[order].clone();
    let names: Vec<String> = p.iter().map(ToString::to_string).collect();
    let v = identities(vec![(
        format!(
            "r^({order})({}) [{}] = {text}",
            end_text(spec, end),
            describe_wrt(spec, wrt)
        ),
        computed.clone(),
        value.clone(),
    )]);
    if v.status == Status::Holds {
        v
    } else {
        v.with_correction(format!(
            "r^({order})({}) = {} (computed)",
            end_text(spec, end),
            computed.to_combination(&names)
        ))
    }
}

/// `Cᵏ` of the uniform B-spline assembled from the `n` functions (piece
/// `k` is function `n − 1 − k`): jumps of orders `0…k` vanish at every knot.
pub fn continuity(spec: &Spec, order: usize) -> Verdict {
    let knots = knot_derivatives::<Sym, K>(spec, &params(spec), Wrt::U, &Sym::one());
    let mut parts = Vec::new();
    for k in &knots {
        let zero = vec![Sym::zero(); K];
        let l = k.left.clone().unwrap_or_else(|| zero.clone());
        let r = k.right.clone().unwrap_or(zero);
        for j in 0..=order {
            parts.push((
                format!("knot n{}: jump of order {j} (right − left)", k.knot),
                r[j].clone(),
                l[j].clone(),
            ));
        }
    }
    let mut v = identities(parts);
    v.evidence.insert(
        0,
        format!(
            "the uniform B-spline of {} pieces (piece k is function {} − k), unit knot spacing",
            spec.functions.len(),
            spec.functions.len() - 1
        ),
    );
    v
}
