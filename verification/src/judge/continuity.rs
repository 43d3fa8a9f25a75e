//! The continuity judge: how smooth a piecewise function is at its knots —
//! the order achieved for every parameter value, the exceptional values
//! where it rises, a witness where it falls short — for any basis: the
//! uniform B-spline assembled from the `n` functions of a catalog family
//! or a spec file (piece `k` is function `n − 1 − k`), and the pieces a
//! catalog claim assembles itself.

use crate::continuity::{KnotContinuity, METHOD, achieved, continuity, uniform_bspline};
use crate::exact::ExactBasis;
use crate::judge::domain::param_symbols;
use crate::status::Status;
use crate::verdict::Verdict;

/// `C^r` at every knot, for every parameter value: each knot's achieved
/// order with its exceptional values (`param`, the one shape parameter),
/// and a witness where it falls short; `label` names the function.
pub fn at_least(label: &str, knots: &[KnotContinuity], r: usize, param: Option<&str>) -> Verdict {
    let evidence: Vec<crate::evidence::Evidence> = knots
        .iter()
        .map(|k| {
            let item = k.describe(param);
            if k.smoothness.is_at_least(r) {
                item
            } else {
                item.witnessed(k.witness())
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
    at_least(
        &format!(
            "the uniform B-spline of {n} pieces (piece k is function {} − k), unit knot spacing",
            n - 1
        ),
        &knots,
        order,
        param,
    )
}
