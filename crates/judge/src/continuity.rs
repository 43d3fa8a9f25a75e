//! The continuity judge: how smooth a piecewise function is at its knots —
//! the order achieved for every parameter value, the exceptional values
//! where it rises, a witness where it falls short — for any basis: the
//! uniform B-spline assembled from the `n` functions of a catalog family
//! or a spec file (piece `k` is function `n − 1 − k`), and the pieces a
//! catalog claim assembles itself.

use trig_deriv::continuity::{KnotContinuity, achieved, continuity, uniform_bspline};
use trig_symbolic::Sym;

use crate::domain::param_symbols;
use crate::exact::ExactBasis;
use trig_verdict::evidence::{Evidence, Expr, Kind, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How continuity is decided, as the report states it.
pub const METHOD: &str = "exact one-sided derivatives of orders 0–6 (Taylor jets in the symbolic ring) at every knot; a jump is decided by the exact zero test; exceptional parameter values are the rational roots of the first nonzero jump's numerator";

/// A point where the first nonzero jump of `k` is visibly nonzero, with
/// its exact value there (right − left).
pub fn knot_witness(k: &KnotContinuity) -> Option<Witness> {
    let (r, j) = k.first_jump()?;
    if j.as_rational().is_some() {
        // A constant jump is its own witness (shown in the item).
        return None;
    }
    let mut w = trig_verdict::witness::find(j, &Sym::zero(), (&format!("jump of order {r}"), "0"))?;
    w.values.truncate(1);
    Some(w)
}

/// The continuity at knot `k` as one line for the report.
pub fn describe(k: &KnotContinuity, param: Option<&str>) -> Evidence {
    let mut text = k.smoothness.to_string();
    let p = param.unwrap_or("parameter");
    for e in &k.exceptions {
        text.push_str(&format!("; at {p} = {}: {}", e.value, e.smoothness));
    }
    if k.roots_incomplete {
        text.push_str("; (rational-root search incomplete: coefficients too large)");
    }
    let mut item = Evidence::new(Kind::Identity, text);
    item.subject = Some(format!("knot {}", k.knot));
    if let Some((r, j)) = k.first_jump() {
        item = item.with(format!("jump of order {r}"), Expr::new(j));
    }
    for e in &k.exceptions {
        if let Some((r, j)) = &e.jump {
            item = item.with(
                format!("jump of order {r} at {p} = {}", e.value),
                Expr::new(j),
            );
        }
    }
    item
}

/// `C^r` at every knot, for every parameter value: each knot's achieved
/// order with its exceptional values (`param`, the one shape parameter),
/// and a witness where it falls short; `label` names the function.
pub fn at_least(label: &str, knots: &[KnotContinuity], r: usize, param: Option<&str>) -> Verdict {
    let evidence: Vec<trig_verdict::evidence::Evidence> = knots
        .iter()
        .map(|k| {
            let item = describe(k, param);
            if k.smoothness.is_at_least(r) {
                item
            } else {
                item.witnessed(knot_witness(k))
            }
        })
        .collect();
    let ok = knots.iter().all(|k| k.smoothness.is_at_least(r));
    let mut evidence = evidence;
    evidence.insert(
        0,
        format!(
            "{label}: achieved for all parameter values: {}",
            achieved(knots).map_or("no knots".into(), |s| s.to_string())
        )
        .into(),
    );
    Verdict::new(
        if ok { Status::Holds } else { Status::Fails },
        METHOD,
        evidence,
    )
}

/// The uniform B-spline assembled from the functions of `basis` is `C^order`
/// at its knots (unit spacing), for every parameter value.
pub fn bspline_continuity<B: ExactBasis>(basis: &B, order: usize) -> Verdict {
    let n = basis.function_names().len();
    let names = basis.param_names();
    let param = match names.as_slice() {
        [one] => Some(one.as_str()),
        _ => None,
    };
    let pieces = uniform_bspline(basis, &param_symbols(basis));
    let mut knots = continuity(&pieces, true, param);
    // Exceptional values outside the declared range are not values of
    // the basis (the C-B-spline's α = 0 is 0/0).
    if let [p] = basis.parameters().as_slice() {
        for k in &mut knots {
            k.exceptions.retain(|e| p.range.contains(&e.value));
        }
    }
    let v = at_least(
        &format!(
            "the uniform B-spline of {n} pieces (piece k is function {} − k), unit knot spacing",
            n - 1
        ),
        &knots,
        order,
        param,
    );
    crate::exact::defined_by(v, basis)
}
