//! Division by an expression that can vanish is refused: before a formula
//! divides by `d`, we prove `d ≠ 0` on the whole domain for every parameter
//! in its declared range, open and infinite ends excluded exactly.
//!
//! `d` is factored exactly first ([`Sym::factored`]) and each factor is
//! proved nonzero on its own — so a divisor written as a definition
//! (`D = 2α(1 − cos α)`), whose value arrives expanded, is still proved
//! factor by factor. Products of exponential atoms (`E = exp(κx)`,
//! `exp(βp)`) never vanish. Otherwise the proof is the certifier's
//! ([`trig_certify::nonneg::definite_sign`]) on the standard pieces of the
//! domain ([`trig_certify::standardize`]): Weierstrass `z = tan(θ/2)`,
//! every parameter set mapped onto a unit coordinate,
//! `π ∈ [314159/100000, 314160/100000]`, and exact Bernstein subdivision
//! until the factor has one strict sign on every cell; or, for factors not
//! polynomial in sin, cos or the variable on a standard domain, the
//! engine's branch and bound ([`trig_certify::factors::nonzero`]).
//! Otherwise the file is refused with a witness: a rational point where
//! the factor is 0, or two where its signs differ; or, when no method
//! decides, with that said (a division we could not prove safe is never
//! accepted).

use rug::Rational;
use trig_certify::branch::Outcome;
use trig_certify::factors;
use trig_certify::nonneg::definite_sign;
use trig_certify::{ParamBox, standardize};
use trig_core::Domain;
use trig_symbolic::Sym;

use trig_core::ParamRange;

/// The name `π` takes while it is bounded as a parameter.
const PI_VAR: &str = "__pi";

/// True for the atoms that are positive wherever they are defined.
fn positive_atom(v: &str) -> bool {
    v == "E" || v.starts_with("exp(")
}

/// The strict sign of the factor `n` of `d` by the engine's branch and
/// bound (functions not polynomial in sin, cos or the variable on a
/// standard domain).
fn interval_sign(
    d: &Sym,
    n: &Sym,
    domain: &Domain,
    params: &[(String, ParamRange)],
) -> Result<(), String> {
    let axes = params
        .iter()
        .map(|(name, r)| {
            trig_certify::branch::Axis::from_range(r).ok_or_else(|| {
                format!("division by `{d}`: the range of {name} is unbounded; the interval method needs bounded ranges")
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    let failed = match factors::nonzero(n, domain, &axes) {
        Ok(_) => return Ok(()),
        Err(failed) => failed,
    };
    let part = if failed.factor == Sym::from_poly(d.numerator().clone()) {
        String::new()
    } else {
        format!(" (its factor `{}`)", failed.factor)
    };
    match (failed.positive, failed.negative) {
        (
            Outcome::Negative {
                x: x1, params: p1, ..
            },
            Outcome::Negative {
                x: x2, params: p2, ..
            },
        ) => Err(format!(
            "division by `{d}`, which changes sign{part}: it is negative at {} and positive at {} (certified enclosures)",
            at(domain, x1, &p1),
            at(domain, x2, &p2)
        )),
        (Outcome::Undecided(why), _) | (_, Outcome::Undecided(why)) => Err(format!(
            "division by `{d}`: could not prove that it{part} does not vanish in the declared domain and range ({why}); restate the formula or narrow the range"
        )),
        _ => Err(format!(
            "division by `{d}`: could not prove that it{part} does not vanish in the declared domain and range; restate the formula or narrow the range"
        )),
    }
}

fn at(domain: &Domain, x: f64, params: &[Rational]) -> String {
    let mut parts: Vec<String> = domain
        .param_names
        .iter()
        .zip(params)
        .map(|(n, v)| format!("{n} = {v}"))
        .collect();
    parts.push(format!("{} ≈ {x:.6}", domain.name));
    parts.join(", ")
}

/// `Ok` when `d` cannot vanish; otherwise why (with a witness).
pub fn check(d: &Sym, domain: &Domain, params: &[(String, ParamRange)]) -> Result<(), String> {
    let n = Sym::from_poly(d.numerator().clone());
    if let Some(q) = n.as_rational() {
        return if q == 0 {
            Err("division by zero".into())
        } else {
            Ok(())
        };
    }
    let single = d.numerator().len() == 1;
    if single && n.variables().iter().all(|v| positive_atom(v)) {
        return Ok(());
    }
    let known = |v: &str| {
        ["s", "c", "t", "E", "pi"].contains(&v)
            || v.contains('(')
            || params.iter().any(|(p, _)| p == v)
    };
    let unknown: Vec<String> = n.variables().into_iter().filter(|v| !known(v)).collect();
    if !unknown.is_empty() {
        return Err(format!(
            "division by `{d}`, which depends on {}: only divisions by expressions in the variable, the parameters and pi are allowed",
            unknown.join(", ")
        ));
    }
    // a product is nonzero exactly when its factors are, and each is
    // smaller to prove (a definition `2α(1 − cos α)` is factored again)
    for (factor, _) in &n.factored().num {
        check_factor(d, &Sym::from_poly(factor.clone()), domain, params)?;
    }
    Ok(())
}

/// Where exact `values` (formulas in the parameters of `params`, perhaps
/// in other symbols too: control points, weights) are singular: every
/// factor of their denominators that involves a parameter and is not
/// proved nonzero on the ranges ([`check`]; a factor with other symbols is
/// never proved), as the joins state it ([`trig_deriv::vanishing`]:
/// `α = −1`, or `α² − β = 0`). Empty where no division by a parameter can
/// vanish. Each factor is named once, in the order first met.
pub fn singular_where<'a>(
    values: impl IntoIterator<Item = &'a Sym>,
    domain: &Domain,
    params: &[(String, ParamRange)],
) -> Vec<String> {
    let is_param = |v: &String| params.iter().any(|(p, _)| p == v);
    let mut seen = std::collections::BTreeSet::new();
    let mut out = Vec::new();
    for v in values {
        for den in v.denominator().keys() {
            if !seen.insert(den.clone()) {
                continue;
            }
            for (factor, _) in &Sym::from_poly(den.clone()).factored().num {
                let factor = Sym::from_poly(factor.clone());
                let vars = factor.variables();
                if !vars.iter().any(is_param) {
                    continue;
                }
                let only_params = vars.iter().all(|v| is_param(v) || v == "pi");
                if only_params && check(&factor, domain, params).is_ok() {
                    continue;
                }
                for note in trig_deriv::vanishing(&factor) {
                    if !out.contains(&note) {
                        out.push(note);
                    }
                }
            }
        }
    }
    out
}

/// True when `n` is a polynomial in `y = exp(p)` alone, `p` a parameter,
/// with no root for `y` in the image of `p`'s range (bounded or not):
/// `(0, ∞)` maps onto `(1, ∞)`, a finite end `q ≠ 0` onto a rational
/// bound of `exp(q)` rounded outward (a larger set, so no root there is a
/// proof); Sturm sequences count the roots, `∞` replaced by the roots'
/// bound.
fn exp_polynomial_nonzero(n: &Sym, params: &[(String, ParamRange)]) -> bool {
    use rug::Float;
    use rug::float::Round;
    use trig_certify::sturm::UPoly;
    use trig_core::End;
    let vars = n.variables();
    let [v] = vars.iter().collect::<Vec<_>>()[..] else {
        return false;
    };
    let Some((_, r)) = params.iter().find(|(name, _)| *v == format!("exp({name})")) else {
        return false;
    };
    let Some(p) = UPoly::from_poly(n.numerator(), v) else {
        return false;
    };
    if r.pi || p.is_zero() {
        return false;
    }
    // the image of an end: (value, open); exp(0) = 1 exactly
    let image = |q: &Rational, open: bool, up: bool| -> Option<(Rational, bool)> {
        if *q == 0 {
            return Some((Rational::from(1), open));
        }
        // exp(q) rounded outward: q rounded the same way first
        let round = if up { Round::Up } else { Round::Down };
        let mut x = Float::with_val_round(256, q, round).0;
        x.exp_round(round);
        x.to_rational().map(|v| (v, false))
    };
    let (lo, lo_open) = match &r.lo {
        End::Unbounded => (Rational::new(), true),
        End::Closed(q) => match image(q, false, false) {
            Some(x) => x,
            None => return false,
        },
        End::Open(q) => match image(q, true, false) {
            Some(x) => x,
            None => return false,
        },
    };
    let (hi, hi_open) = match &r.hi {
        End::Unbounded => (p.root_bound() + Rational::from(1), true),
        End::Closed(q) => match image(q, false, true) {
            Some(x) => x,
            None => return false,
        },
        End::Open(q) => match image(q, true, true) {
            Some(x) => x,
            None => return false,
        },
    };
    // roots in (lo, hi], then the ends
    let inside = p.count_roots(&lo, &hi);
    let hi_root = usize::from(p.sign_at(&hi) == 0);
    let interior = inside - hi_root;
    interior == 0 && (lo_open || p.sign_at(&lo) != 0) && (hi_open || p.sign_at(&hi) != 0)
}

/// `Ok` when the factor `n` of the divisor `d` cannot vanish.
fn check_factor(
    d: &Sym,
    n: &Sym,
    domain: &Domain,
    params: &[(String, ParamRange)],
) -> Result<(), String> {
    if n.numerator().len() == 1 && n.variables().iter().all(|v| positive_atom(v)) {
        return Ok(());
    }
    if exp_polynomial_nonzero(n, params) {
        return Ok(());
    }
    let pi_range = params
        .iter()
        .any(|(name, r)| r.pi && n.variables().contains(name));
    let st = match standardize(n, domain) {
        Ok(st) if !pi_range => st,
        _ => return interval_sign(d, n, domain, params),
    };
    let mut sign = 0;
    for piece in &st.pieces {
        let piece = piece.subs("pi", &Sym::var(PI_VAR));
        let mut boxes: Vec<(&str, ParamBox)> = params
            .iter()
            .filter(|(name, _)| piece.variables().contains(name))
            .map(|(name, r)| (name.as_str(), trig_certify::ParamBox::from_range(r)))
            .collect();
        if piece.variables().contains(PI_VAR) {
            boxes.push((
                PI_VAR,
                ParamBox::closed(
                    Rational::from((314_159, 100_000)),
                    Rational::from((314_160, 100_000)),
                ),
            ));
        }
        let s = definite_sign(&piece, st.trigonometric, &boxes).map_err(|why| {
            let why = why.replace(PI_VAR, "pi");
            if why.contains("cannot fix the sign") {
                format!(
                    "division by `{d}`: could not prove that it does not vanish in the declared domain and range ({why}); restate the formula or narrow the range"
                )
            } else {
                format!("division by `{d}`, which vanishes in the declared domain and range: {why}")
            }
        })?;
        if sign != 0 && s != sign {
            return Err(format!(
                "division by `{d}`, which changes sign between the quarter turns of the domain"
            ));
        }
        sign = s;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Variable;

    fn v(x: Variable) -> Domain {
        Domain::from_variable(x, &[])
    }

    fn range(text: &str) -> ParamRange {
        ParamRange::parse(text).unwrap()
    }

    #[test]
    fn exponential_divisors_on_half_lines() {
        // exp(α) − 1 (the EB normaliser) and (exp α − 1)² (2 cosh α − 2 times
        // exp α) do not vanish for α ∈ (0, ∞); exp(α) − 2 vanishes at ln 2
        let y = Sym::var("exp(alpha)");
        let one = Sym::one();
        let half_line = [("alpha".to_string(), range("(0, inf)"))];
        assert!(exp_polynomial_nonzero(&(y.clone() - &one), &half_line));
        let sq = (y.clone() - &one) * &(y.clone() - &one);
        assert!(exp_polynomial_nonzero(&sq, &half_line));
        assert!(!exp_polynomial_nonzero(
            &(y.clone() - &Sym::int(2)),
            &half_line
        ));
        // closed at 0: exp(0) − 1 = 0
        let closed = [("alpha".to_string(), range("[0, inf)"))];
        assert!(!exp_polynomial_nonzero(&(y.clone() - &one), &closed));
        // [1, 2]: exp α ∈ [e, e²] ∌ 2 (bounds rounded outward)
        let bounded = [("alpha".to_string(), range("[1, 2]"))];
        assert!(exp_polynomial_nonzero(
            &(y.clone() - &Sym::int(2)),
            &bounded
        ));
        assert!(!exp_polynomial_nonzero(
            &(y.clone() - &Sym::int(5)),
            &bounded
        ));
    }

    #[test]
    fn safe_divisors_pass_and_vanishing_ones_are_caught() {
        let m = Sym::var("m");
        let p = vec![("m".to_string(), range("[-2, 1]"))];
        // m + 3 > 0 on [−2, 1]
        assert!(check(&(m.clone() + &Sym::int(3)), &v(Variable::UnitAngle), &p).is_ok());
        // m + 2 vanishes at the end m = −2
        let e = check(&(m.clone() + &Sym::int(2)), &v(Variable::UnitAngle), &p).unwrap_err();
        assert!(e.contains("m = -2"), "{e}");
        // m changes sign inside
        let e = check(&m, &v(Variable::UnitAngle), &p).unwrap_err();
        assert!(e.contains("vanishes"), "{e}");
        // 1 + m s ≥ 1 − 2 < 0 somewhere: vanishes; 3 + m s > 0
        assert!(
            check(
                &(Sym::one() + &(m.clone() * &Sym::var("s"))),
                &v(Variable::Angle),
                &p
            )
            .is_err()
        );
        assert!(
            check(
                &(Sym::int(3) + &(m.clone() * &Sym::var("s"))),
                &v(Variable::Angle),
                &p
            )
            .is_ok()
        );
        // seed 000's 6ζ² − 6ζ + 10 on [0, 4]; a half-line β + 1, β ∈ [0, ∞)
        let z = Sym::var("zeta");
        let d = Sym::int(6) * &z * &z - &(Sym::int(6) * &z) + &Sym::int(10);
        assert!(check(&d, &v(Variable::Angle), &[("zeta".into(), range("[0, 4]"))]).is_ok());
        let b = Sym::var("beta") + &Sym::one();
        assert!(
            check(
                &b,
                &v(Variable::UnitAngle),
                &[("beta".into(), range("[0, inf)"))]
            )
            .is_ok()
        );
        let b = Sym::var("beta") - &Sym::int(5);
        assert!(
            check(
                &b,
                &v(Variable::UnitAngle),
                &[("beta".into(), range("[0, inf)"))]
            )
            .is_err()
        );
        // 1 + t on [0, 1]; 2 − π (sign known); control points are refused
        assert!(
            check(
                &(Sym::var("t") + &Sym::one()),
                &v(Variable::Polynomial),
                &[]
            )
            .is_ok()
        );
        assert!(check(&(Sym::int(2) - &Sym::pi()), &v(Variable::Angle), &[]).is_ok());
        assert!(check(&Sym::var("P0"), &v(Variable::Angle), &[]).is_err());
    }

    #[test]
    fn rational_bernstein_denominators_are_accepted_with_exact_refusals() {
        // (1 − t)² + 2w t(1 − t) + t² = 1 + 2(w − 1)t(1 − t) > 0 for w > −1
        let (t, w) = (Sym::var("t"), Sym::var("w"));
        let d = Sym::one() + &(Sym::int(2) * &(w.clone() - &Sym::one()) * &t * &(Sym::one() - &t));
        for ok in ["[0, inf)", "[-1/10, 1000]", "(-1, 0]"] {
            let p = vec![("w".to_string(), range(ok))];
            assert!(check(&d, &v(Variable::Polynomial), &p).is_ok(), "{ok}");
        }
        // at w = −1 the denominator is 0 at t = 1/2: a rational witness
        let p = vec![("w".to_string(), range("[-1, 0]"))];
        let e = check(&d, &v(Variable::Polynomial), &p).unwrap_err();
        assert!(e.contains("w = -1") && e.contains("t = 1/2"), "{e}");
        // 1/(1 − λ) on λ ∈ [0, 1): the open end is excluded exactly
        let l = Sym::var("lambda");
        let p = vec![("lambda".to_string(), range("[0, 1)"))];
        assert!(check(&(Sym::one() - &l), &v(Variable::Angle), &p).is_ok());
        let p = vec![("lambda".to_string(), range("[0, 1]"))];
        assert!(check(&(Sym::one() - &l), &v(Variable::Angle), &p).is_err());
    }
}
