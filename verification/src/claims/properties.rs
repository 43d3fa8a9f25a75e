//! Claims of the second list of `shared/claims.md` ("More claims:
//! properties, shapes, conics, and the arithmetic of the text") that the
//! judges decide so far: linear independence, the convex hull, affine
//! invariance, conic arcs. Each states what is printed and calls a judge.

use trig_core::Family;
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_symbolic::Sym;

use super::properties_formulas::t45;
use crate::claim::Claim;
use trig_judge::exact::IDENTITY;
use trig_judge::{endpoint, nonnegative, unity};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// In report order (after each document's first-list claims).
pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T45",
        check: t45,
    },
    Claim {
        id: "T49",
        check: t49,
    },
];

/// The Bézier properties of (3.7) on `m ∈ (−2, 1]`, each by its judge:
/// interpolation of the end points, the end tangents `Q'(0) = c·(P1 − P0)`,
/// `Q'(1) = c·(P3 − P2)` with `c > 0` on the range, the convex hull
/// (unity and certified nonnegativity) and affine invariance (unity).
fn t49() -> Verdict {
    let family = Family::ThesisCubic;
    let range = trig_core::ParamRange::parse("(-2, 1]").expect("a valid range");
    let tangents = [(End::Start, 0, 1, "Q'(0) along P1 − P0"), (End::End, 2, 3, "Q'(1) along P3 − P2")]
        .iter()
        .map(|(end, from, to, label)| {
            let p = trig_judge::exact::symbols("P", 4);
            let d: Vec<Sym> = endpoint_derivatives::<Sym, 2>(family, &[Sym::var("m")], *end, Wrt::Angle, &Sym::one())
                .into_iter()
                .map(|d| d[1].clone())
                .collect();
            let slope = trig_judge::exact::combination(&d, &p);
            let c = slope.diff(&format!("P{to}"));
            let along = trig_judge::exact::identity_item(
                &format!("{label}: Q' − c·(P{to} − P{from}), c = ∂Q'/∂P{to}"),
                &slope,
                &(c.clone() * &(p[*to].clone() - &p[*from])),
            );
            let positive = positive_on(&c, "m", &range);
            let status = match (along.status, positive) {
                (Some(Status::Holds), Some(true)) => Status::Holds,
                (Some(Status::Fails), _) | (_, Some(false)) => Status::Fails,
                _ => Status::NotCheckable,
            };
            let mut v = Verdict::new(status, IDENTITY, [along]);
            v.evidence.push(format!(
                "c = {}: {} on m ∈ {range}",
                c.to_unicode(),
                match positive {
                    Some(true) => "positive (linear in m, positive at both ends of the range or zero only at an open end)",
                    Some(false) => "not positive everywhere",
                    None => "sign not decided (numerator not linear in m)",
                }
            ));
            ((*label).to_string(), v)
        })
        .collect::<Vec<_>>();
    let mut parts = vec![(
        "Q(0) = P0, Q(1) = P3".to_string(),
        endpoint::interpolation(&family),
    )];
    parts.extend(tangents);
    parts.push((
        "convex hull".into(),
        nonnegative::convex_hull(&family, Some(&range)),
    ));
    parts.push((
        "affine invariance (Σ b_i = 1)".into(),
        unity::unity(&family),
    ));
    Verdict::all(trig_judge::certificate::CERTIFIED, parts)
}

/// `Some(true)` when `c` (a polynomial in `var` of degree ≤ 1, free of other
/// variables) is positive on `range`, `Some(false)` when it is not, `None`
/// when undecided here.
fn positive_on(c: &Sym, var: &str, range: &trig_core::ParamRange) -> Option<bool> {
    if !c.denominator().is_empty() {
        return None;
    }
    let num = c.numerator();
    if num.variables().iter().any(|v| v != var) || num.degree_in(var) > 1 {
        return None;
    }
    let at = |x: &rug::Rational| {
        num.subs(var, &trig_symbolic::Poly::constant(x.clone()))
            .as_constant()
    };
    if range.pi {
        return None;
    }
    let end = |e: &trig_core::range::End| -> Option<(rug::Rational, bool)> {
        match e {
            trig_core::range::End::Closed(q) => Some((q.clone(), false)),
            trig_core::range::End::Open(q) => Some((q.clone(), true)),
            trig_core::range::End::Unbounded => None,
        }
    };
    let ((lo, lo_open), (hi, hi_open)) = (end(&range.lo)?, end(&range.hi)?);
    let (a, b) = (at(&lo)?, at(&hi)?);
    // linear: positive on the range iff positive at both ends, an open end
    // allowed to be a root
    let ok_lo = a > 0 || (a == 0 && lo_open);
    let ok_hi = b > 0 || (b == 0 && hi_open);
    Some(ok_lo && ok_hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_positivity_on_a_range_respects_open_and_closed_ends() {
        let range = |r: &str| trig_core::ParamRange::parse(r).expect("a valid range");
        let m = Sym::var("m");
        let c = m.clone() + &Sym::int(2);
        assert_eq!(positive_on(&c, "m", &range("(-2, 1]")), Some(true));
        assert_eq!(positive_on(&c, "m", &range("[-2, 1]")), Some(false));
        assert_eq!(positive_on(&c, "m", &range("[-3, 1]")), Some(false));
        let d = Sym::one() - &m;
        assert_eq!(positive_on(&d, "m", &range("(-2, 1]")), Some(false));
        assert_eq!(positive_on(&d, "m", &range("(-2, 1)")), Some(true));
        assert_eq!(positive_on(&(m.clone() * &m), "m", &range("(-2, 1]")), None);
        assert_eq!(positive_on(&c, "m", &range("(-2, inf)")), None);
    }
}
