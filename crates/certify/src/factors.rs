//! Signs of products and quotients decided factor by factor.
//!
//! `f = u·Π nᵢ^{aᵢ}/Π dⱼ^{bⱼ}` (the exact factorisation of the numerator,
//! [`Sym::factored`], and the factored denominator): `f ≥ 0` on the domain
//! for every parameter in the axes follows when every denominator factor
//! keeps one strict sign, every numerator factor of odd multiplicity keeps
//! one sign (`≥ 0` or `≤ 0`), and the signs multiply to `+` (factors of even
//! multiplicity are `≥ 0`). Each factor is smaller than the product, and a
//! product of plainly nonnegative factors (`3w(1 − w)²` of the exponential
//! Bernstein basis) is never expanded into a function whose sign no
//! enclosure sees. When a factor's sign is not fixed (it changes sign, or
//! the search does not finish) the numerator is decided as a whole — also
//! the way to a counterexample when the signs multiply to `−`.

use trig_core::Domain;
use trig_symbolic::Sym;

use crate::branch::{self, Axis, Outcome};

/// The sign a factor keeps on the domain × box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sign {
    Plus,
    Minus,
}

/// The sign `g` keeps on the domain for every parameter in `axes` (strict
/// for `strict`: `> 0` or `< 0`, else `≥ 0` or `≤ 0`), with the boxes it
/// took, or why not.
pub fn sign_of(
    g: &Sym,
    domain: &Domain,
    axes: &[Axis],
    strict: bool,
) -> Result<(Sign, usize), String> {
    let decide = |x: &Sym| {
        if strict {
            branch::positive(x, domain, axes)
        } else {
            branch::nonnegative(x, domain, axes)
        }
    };
    let up = decide(g);
    if let Outcome::Proved { boxes } = up {
        return Ok((Sign::Plus, boxes));
    }
    let down = decide(&-g.clone());
    if let Outcome::Proved { boxes } = down {
        return Ok((Sign::Minus, boxes));
    }
    Err(match (up, down) {
        (Outcome::Negative { .. }, Outcome::Negative { .. }) => format!("{g} changes sign"),
        (Outcome::Undecided(why), _) | (_, Outcome::Undecided(why)) => {
            format!("the sign of {g} was not decided ({why})")
        }
        _ => format!("the sign of {g} was not decided"),
    })
}

/// `f ≥ 0` on the domain for every parameter in `axes`, factor by factor
/// (see the module docs): `Proved` with the boxes of all factors, a
/// counterexample of the whole numerator, or undecided with the reason (a
/// denominator factor of unproved sign is named).
pub fn nonnegative(f: &Sym, domain: &Domain, axes: &[Axis]) -> Outcome {
    let mut sign = Sign::Plus;
    let mut boxes = 0;
    for (factor, e) in f.denominator() {
        let g = Sym::from_poly(factor.clone());
        match sign_of(&g, domain, axes, true) {
            Ok((s, b)) => {
                boxes += b;
                if e % 2 == 1 && s == Sign::Minus {
                    sign = flip(sign);
                }
            }
            Err(why) => {
                return Outcome::Undecided(format!(
                    "the sign of its denominator factor {g} was not proved: {why}"
                ));
            }
        }
    }
    let numerator = f.numerator();
    let signed = |s: Sign| {
        Sym::from_poly(if s == Sign::Minus {
            -numerator.clone()
        } else {
            numerator.clone()
        })
    };
    if numerator.is_zero() {
        return Outcome::Proved { boxes };
    }
    let q = Sym::from_poly(numerator.clone()).factored();
    let nontrivial = q.num.len() > 1 || q.num.iter().any(|(_, e)| *e > 1);
    if nontrivial {
        let mut product = if q.unit < 0 { flip(sign) } else { sign };
        let mut all = true;
        let mut spent = 0;
        for (factor, e) in &q.num {
            if e % 2 == 0 {
                continue;
            }
            match sign_of(&Sym::from_poly(factor.clone()), domain, axes, false) {
                Ok((s, b)) => {
                    spent += b;
                    if s == Sign::Minus {
                        product = flip(product);
                    }
                }
                Err(_) => {
                    all = false;
                    break;
                }
            }
        }
        if all && product == Sign::Plus {
            return Outcome::Proved {
                boxes: boxes + spent,
            };
        }
    }
    match branch::nonnegative(&signed(sign), domain, axes) {
        Outcome::Proved { boxes: b } => Outcome::Proved { boxes: boxes + b },
        other => other,
    }
}

/// `d ≠ 0` on the domain for every parameter in `axes` (open ends
/// excluded): every factor of the numerator keeps one strict sign. `Ok`
/// with the boxes, or the factor that could not be proved nonzero with
/// the outcomes of `factor > 0` and `factor < 0`.
pub fn nonzero(d: &Sym, domain: &Domain, axes: &[Axis]) -> Result<usize, Box<NonZero>> {
    let q = Sym::from_poly(d.numerator().clone()).factored();
    let mut boxes = 0;
    for (factor, _) in &q.num {
        let g = Sym::from_poly(factor.clone());
        if g.variables()
            .iter()
            .all(|v| v == "E" || v.starts_with("exp("))
            && factor.len() == 1
        {
            continue; // a monomial in exponentials: positive
        }
        let up = branch::positive(&g, domain, axes);
        if let Outcome::Proved { boxes: b } = up {
            boxes += b;
            continue;
        }
        let down = branch::positive(&-g.clone(), domain, axes);
        if let Outcome::Proved { boxes: b } = down {
            boxes += b;
            continue;
        }
        return Err(Box::new(NonZero {
            factor: g,
            positive: up,
            negative: down,
        }));
    }
    Ok(boxes)
}

/// A factor not proved nonzero, with the outcomes of `factor > 0` and
/// `−factor > 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct NonZero {
    pub factor: Sym,
    pub positive: Outcome,
    pub negative: Outcome,
}

/// The opposite sign.
pub fn flip(s: Sign) -> Sign {
    match s {
        Sign::Plus => Sign::Minus,
        Sign::Minus => Sign::Plus,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;
    use trig_core::Affine;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    /// `t ∈ [0, α]` with `E = exp(t)` and `exp(α)`.
    fn exponential() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: None,
            uses_variable: false,
            exp: Some(q(1, 1)),
            param_angles: Vec::new(),
            param_exps: vec![(0, q(1, 1))],
        }
    }

    fn axis(lo: Rational, hi: Rational) -> Vec<Axis> {
        vec![Axis {
            lo,
            hi,
            lo_open: false,
            hi_open: false,
            pi: false,
        }]
    }

    #[test]
    fn exponential_bernstein_is_decided_factor_by_factor() {
        // b1 = 3w(1 − w)², w = (E − 1)/(exp(α) − 1)
        let d = exponential();
        let (e, ea) = (Sym::var("E"), Sym::var("exp(alpha)"));
        let w = (e.clone() - &Sym::one()) / &(ea.clone() - &Sym::one());
        let one_minus = Sym::one() - &w;
        let b1 = Sym::int(3) * &w * &one_minus * &one_minus;
        let axes = axis(q(1, 2), q(4, 1));
        assert!(matches!(
            nonnegative(&b1, &d, &axes),
            Outcome::Proved { .. }
        ));
        // −b1 is not: a counterexample of the whole
        assert!(matches!(
            nonnegative(&-b1, &d, &axes),
            Outcome::Negative { .. }
        ));
    }

    #[test]
    fn divisors_factor_by_factor() {
        // 2α(1 − cos α) ≠ 0 on (0, 2π)... here with exponentials:
        // α(exp(α) − 1) ≠ 0 for α ∈ [1/2, 4]; (α − 1)(exp(α) − 1) is not
        let d = exponential();
        let a = Sym::var("alpha");
        let ea = Sym::var("exp(alpha)");
        let axes = axis(q(1, 2), q(4, 1));
        let g = a.clone() * &(ea.clone() - &Sym::one());
        assert!(nonzero(&g, &d, &axes).is_ok());
        let h = (a - &Sym::one()) * &(ea - &Sym::one());
        let err = nonzero(&h, &d, &axes).unwrap_err();
        assert_eq!(err.factor.to_string(), "alpha - 1");
    }
}
