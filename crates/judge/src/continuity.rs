//! The continuity judge: how smooth a piecewise function is at its knots —
//! the order achieved for every parameter value, the exceptional values
//! where it rises, a witness where it falls short — for any basis: the
//! uniform B-spline assembled from the `n` functions of a catalog family
//! or a spec file (piece `k` is function `n − 1 − k`), a uniform curve of
//! the basis (polynomial or rational, control points as symbols), and the
//! B-spline basis function on a knot vector (its pieces the segment
//! functions of consecutive spans, [`trig_specfile::knots`]).

use trig_deriv::continuity::{
    KnotContinuity, MAX_ORDER, Piece, achieved, classify, continuity, curve_jumps, uniform_bspline,
};
use trig_deriv::table::{End, Wrt, curve_endpoint_derivatives};
use trig_specfile::knots::Knots;
use trig_symbolic::Sym;

use crate::domain::param_symbols;
use crate::exact::{ExactBasis, symbols};
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
    let knots = in_range(basis, continuity(&pieces, true, param));
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

/// The basis's one shape parameter, if it has exactly one.
fn one_param<B: ExactBasis>(basis: &B) -> Option<String> {
    match basis.param_names().as_slice() {
        [one] => Some(one.clone()),
        _ => None,
    }
}

/// Exceptional values outside the declared range are not values of the
/// basis (the C-B-spline's `α = 0` is 0/0): they are dropped.
fn in_range<B: ExactBasis>(basis: &B, mut knots: Vec<KnotContinuity>) -> Vec<KnotContinuity> {
    if let [p] = basis.parameters().as_slice() {
        for k in &mut knots {
            k.exceptions.retain(|e| p.range.contains(&e.value));
        }
    }
    knots
}

/// The uniform curve `Σ bᵢ P_{s+i}` of `basis` on each of the consecutive
/// `segments` `s` (unit knot spacing; control points `point0, point1, …`
/// as symbols; with `weights` the rational curve `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`,
/// weights `w0, w1, …`) is `C^order` at the knots between them, for every
/// parameter value: at knot `s` the end of segment `s − 1` meets the start
/// of segment `s` (only these one-sided derivatives are formed).
pub fn curve_continuity<B: ExactBasis>(
    basis: &B,
    order: usize,
    point: &str,
    weights: bool,
    segments: &[i64],
) -> Verdict {
    let n = basis.function_names().len();
    let param = one_param(basis);
    let params = param_symbols(basis);
    let count = segments.iter().max().map_or(0, |s| *s as usize) + n;
    let (p, w) = (symbols(point, count), symbols("w", count));
    let knots: Vec<KnotContinuity> = segments
        .iter()
        .skip(1)
        .map(|s| {
            let s = *s as usize;
            let (left, right) = (s - 1..s - 1 + n, s..s + n);
            let jumps = curve_jumps(
                basis,
                &params,
                (&p[left.clone()], &p[right.clone()]),
                weights.then(|| (&w[left], &w[right])),
            );
            classify(s, jumps, param.as_deref())
        })
        .collect();
    let curve = if weights {
        format!("the rational curve Σ w_i b_i {point}_i / Σ w_i b_i")
    } else {
        format!("the curve Σ b_i {point}_i")
    };
    at_least(
        &format!(
            "{curve} (segments {}–{}, symbolic control points{}), unit knot spacing",
            segments[0],
            segments[segments.len() - 1],
            if weights { " and weights" } else { "" }
        ),
        &in_range(basis, knots),
        order,
        param.as_deref(),
    )
}

/// The B-spline basis function `F_j` on the claim's knot vector (`j` its
/// span) is `C^order` at its knots, for every parameter value: piece `i`
/// on `[n_{j+i}, n_{j+i+1})` is the segment function `n − 1 − i` of that
/// span (`Σ_k M_{n−1−i,k} f_k`, the knot family's printed coefficients,
/// [`Knots::row`]), its derivatives in the global knot parameter (`u =
/// (x − n_{j+i})/q_{j+i}` the basis's unit parameter, so the `r`-th
/// derivative is divided by `q^r`); a span of zero length (a multiple
/// knot) has no piece. Where the printed formulas are undefined on the
/// knots the function does not exist: `not-checkable`, the formula named.
pub fn knot_continuity<B: ExactBasis>(basis: &B, order: usize, knots: &Knots) -> Verdict {
    let Some((names, param)) = Knots::family(&knots.coefficients) else {
        return Verdict::not_checkable(format!("`{}`: no such knot family", knots.coefficients));
    };
    let n = names.len();
    let params = param_symbols(basis);
    let (j, one) = (knots.span, Sym::one());
    let undefined = |why: String| {
        Verdict::not_checkable(format!(
            "the printed coefficient formulas of {} are undefined on the knots {}: {why}",
            knots.coefficients,
            knots.texts.join(", ")
        ))
    };
    let mut pieces = Vec::new();
    for i in 0..n {
        let span = j + i as i64;
        let at = |k: i64| usize::try_from(k).ok().and_then(|k| knots.values.get(k));
        let (Some(a), Some(b)) = (at(span), at(span + 1)) else {
            return undefined(format!(
                "the piece on [n_{span}, n_{}) needs knots outside the vector",
                span + 1
            ));
        };
        let q = b.clone() - a;
        if q.is_zero() {
            continue;
        }
        let row = match (Knots {
            span,
            ..knots.clone()
        })
        .row(n - 1 - i, &Sym::var(param))
        {
            Ok(row) => row,
            Err(e) => return undefined(e.to_string()),
        };
        let scaled = |end| {
            let mut factor = Sym::one();
            curve_endpoint_derivatives::<Sym, { MAX_ORDER + 1 }>(
                basis,
                &params,
                &row,
                None,
                end,
                Wrt::U,
                &one,
            )
            .into_iter()
            .map(|d| {
                let v = d / &factor;
                factor = factor.clone() * &q;
                v
            })
            .collect()
        };
        pieces.push(Piece {
            start: scaled(End::Start),
            end: scaled(End::End),
        });
    }
    let param = one_param(basis);
    let reversed: Vec<&str> = names.iter().rev().copied().collect();
    at_least(
        &format!(
            "the B-spline F_{j} on the knots (pieces {} of the spans {j}–{}, the printed coefficients of {})",
            reversed.join(", "),
            j + n as i64 - 1,
            knots.coefficients
        ),
        &in_range(basis, continuity(&pieces, true, param.as_deref())),
        order,
        param.as_deref(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;
    use trig_specfile::Spec;

    fn line<'a>(v: &'a Verdict, needle: &str) -> &'a Evidence {
        v.evidence
            .iter()
            .find(|e| e.line().contains(needle))
            .unwrap_or_else(|| panic!("{needle}: {:?}", v.evidence))
    }

    #[test]
    fn a_cubic_bspline_curve_is_c2_and_not_c3_at_its_knots() {
        let basis = Family::BSpline3;
        let c2 = curve_continuity(&basis, 2, "P", false, &[0, 1, 2]);
        assert_eq!(c2.status, Status::Holds);
        assert!(line(&c2, "knot 2").line().contains("exactly C^2"));
        let c3 = curve_continuity(&basis, 3, "P", false, &[0, 1]);
        assert_eq!(c3.status, Status::Fails);
        // the rational curve with equal weights is the same curve
        let w = curve_continuity(&basis, 2, "P", true, &[0, 1]);
        assert_eq!(w.status, Status::Holds);
    }

    fn knots(values: &[i64]) -> Knots {
        Knots {
            coefficients: "seed000-nonuniform".into(),
            texts: values.iter().map(i64::to_string).collect(),
            values: values.iter().map(|v| Sym::int(*v)).collect(),
            span: 8,
        }
    }

    #[test]
    fn the_bspline_on_knots_is_assembled_from_its_spans_and_refused_where_undefined() {
        let spec = Spec::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/catalog/seed000-blending.toml"
        )))
        .expect("the catalog's blending functions");
        let mut v = vec![0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25, 26, 29];
        // seed 000's printed coefficients: C^3 at the first knot, a jump of
        // the value itself at the second
        let c = knot_continuity(&spec, 0, &knots(&v));
        assert_eq!(c.status, Status::Fails);
        assert!(line(&c, "knot 0").line().contains("exactly C^3"));
        assert!(line(&c, "knot 1").line().contains("discontinuous"));
        // a double knot: three pieces, four knots
        v[11] = 19;
        let double = knot_continuity(&spec, 0, &knots(&v));
        assert!(line(&double, "knot 3").line().contains("exactly C^3"));
        assert!(!double.evidence.iter().any(|e| e.line().contains("knot 4")));
        // a triple knot: α_10 divides by zero
        v[12] = 19;
        let triple = knot_continuity(&spec, 0, &knots(&v));
        assert_eq!(triple.status, Status::NotCheckable);
        assert!(
            triple.evidence[0].line().contains("alpha_10"),
            "{:?}",
            triple.evidence
        );
    }
}
