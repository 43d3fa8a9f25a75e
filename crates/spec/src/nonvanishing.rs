//! Division by an expression that can vanish is refused: before a formula
//! divides by `d`, we prove `d ≠ 0` on the whole domain (θ ∈ [0, π/2] or
//! t ∈ [0, 1]) for every parameter in the closure of its declared range.
//!
//! Method (exact, rational arithmetic): the numerator of `d` is mapped to a
//! polynomial on the unit box — `z = tan(θ/2)` for `s`, `c` (Weierstrass),
//! `p = a + (b − a)y` for a bounded range, `p = a + y/(1 − y)` for a
//! half-line, `π ∈ [314159/100000, 314160/100000]` — then the box is
//! bisected: a box is settled when interval arithmetic shows the polynomial
//! has one strict sign there. An exact zero at a sampled point, or two
//! samples of opposite signs (intermediate value theorem), is a proof that
//! `d` vanishes; a budget of boxes bounds the work, and exhausting it is
//! reported (we never accept a division we could not prove safe).

use std::collections::BTreeMap;

use rug::Rational;
use trig_core::Variable;
use trig_symbolic::{Poly, Sym};

use crate::range::{End, SpecRange};

/// Boxes examined before giving up.
pub const BUDGET: usize = 4_000;

/// `Ok` when `d` cannot vanish; otherwise why (with a witness).
pub fn check(d: &Sym, variable: Variable, params: &[(String, SpecRange)]) -> Result<(), String> {
    let n = Sym::from_poly(d.numerator().clone());
    if n.as_rational().is_some() {
        return if n.is_zero() {
            Err("division by zero".into())
        } else {
            Ok(())
        };
    }
    let mut maps: Vec<(String, Sym)> = Vec::new();
    let mut q = n.clone();
    let vars = n.variables();
    if vars.contains("s") || vars.contains("c") {
        let z = Sym::var("__y_z");
        let w = Sym::one() + &(z.clone() * &z);
        q = q
            .subs("s", &(Sym::int(2) * &z / &w))
            .subs("c", &((Sym::one() - &(z.clone() * &z)) / &w));
        maps.push(("tan(θ/2)".into(), z));
    }
    if vars.contains("t") && !variable.is_trigonometric() {
        let y = Sym::var("__y_t");
        q = q.subs("t", &y);
        maps.push((String::from("t"), y));
    }
    if vars.contains("pi") {
        let y = Sym::var("__y_pi");
        let a = Sym::rational(Rational::from((314_159, 100_000)));
        let value = a + &(Sym::rational(Rational::from((1, 100_000))) * &y);
        q = q.subs("pi", &value);
        maps.push(("pi".into(), value));
    }
    for (name, range) in params {
        if !vars.contains(name.as_str()) {
            continue;
        }
        let y = Sym::var(&format!("__y_{name}"));
        let frac = y.clone() / &(Sym::one() - &y);
        let value = match (&range.lo, &range.hi) {
            (lo, hi) if lo.value().is_some() && hi.value().is_some() => {
                let (a, b) = (
                    lo.value().cloned().unwrap_or_default(),
                    hi.value().cloned().unwrap_or_default(),
                );
                Sym::rational(a.clone()) + &(Sym::rational(b - a) * &y)
            }
            (End::Closed(a) | End::Open(a), End::Unbounded) => Sym::rational(a.clone()) + &frac,
            (End::Unbounded, End::Closed(b) | End::Open(b)) => Sym::rational(b.clone()) - &frac,
            _ => (Sym::int(2) * &y - &Sym::one()) / &(y.clone() * &(Sym::one() - &y)),
        };
        q = q.subs(name, &value);
        maps.push((name.clone(), value));
    }
    let poly = q.numerator().clone();
    let unknown: Vec<String> = poly
        .variables()
        .into_iter()
        .filter(|v| !v.starts_with("__y_"))
        .collect();
    if !unknown.is_empty() {
        return Err(format!(
            "division by `{d}`, which depends on {}: only divisions by expressions in the variable, the parameters and pi are allowed",
            unknown.join(", ")
        ));
    }
    let names: Vec<String> = poly.variables().into_iter().collect();
    let witness = |point: &BTreeMap<String, Rational>| -> String {
        maps.iter()
            .filter_map(|(label, value)| {
                let v = value.eval_rational(&|n| point.get(n).cloned()).ok()?;
                Some(format!("{label} = {v}"))
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    match search(&poly, &names) {
        Search::NonZero => Ok(()),
        Search::Zero(p) => Err(format!(
            "division by `{d}`, which vanishes in the declared domain and range: it is 0 at {}",
            witness(&p)
        )),
        Search::SignChange(a, b) => Err(format!(
            "division by `{d}`, which vanishes in the declared domain and range: it changes sign between {} and {}",
            witness(&a),
            witness(&b)
        )),
        Search::Budget => Err(format!(
            "division by `{d}`: could not prove that it does not vanish in the declared domain and range ({BUDGET} boxes); restate the formula or narrow the range"
        )),
    }
}

enum Search {
    NonZero,
    Zero(BTreeMap<String, Rational>),
    SignChange(BTreeMap<String, Rational>, BTreeMap<String, Rational>),
    Budget,
}

type Cell = Vec<(Rational, Rational)>;

fn value_at(p: &Poly, names: &[String], point: &BTreeMap<String, Rational>) -> Rational {
    let _ = names;
    p.eval_rational(&|n| point.get(n).cloned())
        .unwrap_or_default()
}

/// Bounds of `p` on a box inside `[0, 1]ⁿ` (all variables nonnegative).
fn bounds(p: &Poly, names: &[String], cell: &Cell) -> (Rational, Rational) {
    let mut lo = Rational::new();
    let mut hi = Rational::new();
    for (m, q) in p.terms() {
        let (mut a, mut b) = (Rational::from(1), Rational::from(1));
        for (v, e) in m.factors() {
            let i = names.iter().position(|n| n == v.name()).unwrap_or(0);
            let (l, h) = &cell[i];
            for _ in 0..e {
                a *= l;
                b *= h;
            }
        }
        if *q >= 0 {
            lo += a * q;
            hi += b * q;
        } else {
            lo += b * q;
            hi += a * q;
        }
    }
    (lo, hi)
}

fn search(p: &Poly, names: &[String]) -> Search {
    let point = |cell: &Cell, pick: &dyn Fn(&(Rational, Rational)) -> Rational| {
        names
            .iter()
            .zip(cell)
            .map(|(n, iv)| (n.clone(), pick(iv)))
            .collect::<BTreeMap<_, _>>()
    };
    let root: Cell = names
        .iter()
        .map(|_| (Rational::new(), Rational::from(1)))
        .collect();
    // corners of the whole box first: zeros on the boundary are common
    let mut reference: Option<(Rational, BTreeMap<String, Rational>)> = None;
    for mask in 0..(1u32 << names.len().min(8)) {
        let corner: BTreeMap<String, Rational> = names
            .iter()
            .enumerate()
            .map(|(i, n)| (n.clone(), Rational::from((mask >> i) & 1)))
            .collect();
        let v = value_at(p, names, &corner);
        if v == 0 {
            return Search::Zero(corner);
        }
        match &reference {
            None => reference = Some((v, corner)),
            Some((r, at)) if (*r > 0) != (v > 0) => return Search::SignChange(at.clone(), corner),
            Some(_) => {}
        }
    }
    let Some((sign, at)) = reference else {
        return Search::NonZero;
    };
    let positive = sign > 0;
    let mut stack = vec![(root, 0usize)];
    let mut examined = 0;
    while let Some((cell, axis)) = stack.pop() {
        examined += 1;
        if examined > BUDGET {
            return Search::Budget;
        }
        let (lo, hi) = bounds(p, names, &cell);
        if lo > 0 || hi < 0 {
            if (lo > 0) != positive {
                return Search::SignChange(at, point(&cell, &|iv| iv.0.clone()));
            }
            continue;
        }
        let mid = point(&cell, &|iv| (iv.0.clone() + &iv.1) / 2u32);
        let v = value_at(p, names, &mid);
        if v == 0 {
            return Search::Zero(mid);
        }
        if (v > 0) != positive {
            return Search::SignChange(at, mid);
        }
        let (a, b) = cell[axis].clone();
        let m = (a.clone() + &b) / 2u32;
        let mut left = cell.clone();
        left[axis] = (a, m.clone());
        let mut right = cell;
        right[axis] = (m, b);
        let next = (axis + 1) % names.len();
        stack.push((left, next));
        stack.push((right, next));
    }
    Search::NonZero
}

#[cfg(test)]
mod tests {
    use super::*;

    fn range(text: &str) -> SpecRange {
        SpecRange::parse(text).unwrap()
    }

    #[test]
    fn safe_divisors_pass_and_vanishing_ones_are_caught() {
        let m = Sym::var("m");
        let p = vec![("m".to_string(), range("[-2, 1]"))];
        // m + 3 > 0 on [−2, 1]
        assert!(check(&(m.clone() + &Sym::int(3)), Variable::UnitAngle, &p).is_ok());
        // m + 2 vanishes at the end m = −2
        let e = check(&(m.clone() + &Sym::int(2)), Variable::UnitAngle, &p).unwrap_err();
        assert!(e.contains("m = -2"), "{e}");
        // m changes sign inside
        let e = check(&m, Variable::UnitAngle, &p).unwrap_err();
        assert!(e.contains("vanishes"), "{e}");
        // 1 + m s ≥ 1 − 2 < 0 somewhere: vanishes; 3 + m s > 0
        assert!(
            check(
                &(Sym::one() + &(m.clone() * &Sym::var("s"))),
                Variable::Angle,
                &p
            )
            .is_err()
        );
        assert!(
            check(
                &(Sym::int(3) + &(m.clone() * &Sym::var("s"))),
                Variable::Angle,
                &p
            )
            .is_ok()
        );
        // seed 000's 6ζ² − 6ζ + 10 on [0, 4]; a half-line β + 1, β ∈ [0, ∞)
        let z = Sym::var("zeta");
        let d = Sym::int(6) * &z * &z - &(Sym::int(6) * &z) + &Sym::int(10);
        assert!(check(&d, Variable::Angle, &[("zeta".into(), range("[0, 4]"))]).is_ok());
        let b = Sym::var("beta") + &Sym::one();
        assert!(
            check(
                &b,
                Variable::UnitAngle,
                &[("beta".into(), range("[0, inf)"))]
            )
            .is_ok()
        );
        let b = Sym::var("beta") - &Sym::int(5);
        assert!(
            check(
                &b,
                Variable::UnitAngle,
                &[("beta".into(), range("[0, inf)"))]
            )
            .is_err()
        );
        // 1 + t on [0, 1]; 2 − π (sign known); control points are refused
        assert!(check(&(Sym::var("t") + &Sym::one()), Variable::Polynomial, &[]).is_ok());
        assert!(check(&(Sym::int(2) - &Sym::pi()), Variable::Angle, &[]).is_ok());
        assert!(check(&Sym::var("P0"), Variable::Angle, &[]).is_err());
    }
}
