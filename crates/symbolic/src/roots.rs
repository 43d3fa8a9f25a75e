//! Rational roots of a polynomial in one of its variables that make it
//! vanish identically in the others (exceptional parameter values).

use std::collections::BTreeMap;

use rug::{Integer, Rational};

use crate::monomial::Monomial;
use crate::poly::Poly;
use crate::residue::Residue;
use crate::var::Var;

/// Largest coefficient (in absolute value) whose divisors are enumerated.
const DIVISOR_LIMIT: u64 = 1 << 40;

/// The rational roots `v` of `p` in `var` such that `p(var := v)` vanishes
/// identically in the other variables, sorted; `false` when some candidate
/// divisors were not enumerated (coefficient beyond `DIVISOR_LIMIT`).
pub fn rational_roots(p: &Poly, var: &str) -> (Vec<Rational>, bool) {
    if p.is_zero() || p.degree_in(var) == 0 {
        return (Vec::new(), true);
    }
    // one coefficient group (fixed monomial in the other variables) gives a
    // univariate polynomial whose roots include every common root
    let Some(v) = Var::find(var) else {
        return (Vec::new(), true);
    };
    // ordered, so that ties between groups of one size break the same way
    // in every run
    let mut groups: BTreeMap<Monomial, BTreeMap<u32, Rational>> = BTreeMap::new();
    for (m, q) in p.terms() {
        let (rest, e) = m.split_off(v);
        *groups.entry(rest).or_default().entry(e).or_default() += q.to_rational();
    }
    let Some(group) = groups.values().max_by_key(|g| g.len()) else {
        return (Vec::new(), true);
    };
    let lcm = group
        .values()
        .fold(Integer::from(1), |acc, q| acc.lcm(q.denom()));
    let coeffs: BTreeMap<u32, Integer> = group
        .iter()
        .filter(|(_, q)| **q != 0)
        .map(|(e, q)| (*e, (q.clone() * &lcm).numer().clone()))
        .collect();
    let (Some((&low_e, low)), Some((_, high))) = (coeffs.iter().next(), coeffs.iter().next_back())
    else {
        return (Vec::new(), true);
    };
    let mut candidates = Vec::new();
    if low_e > 0 {
        candidates.push(Rational::new());
    }
    let (num_div, ok1) = divisors(low);
    let (den_div, ok2) = divisors(high);
    for a in &num_div {
        for b in &den_div {
            let r = Rational::from((a.clone(), b.clone()));
            candidates.push(r.clone());
            candidates.push(-r);
        }
    }
    candidates.sort();
    candidates.dedup();
    // a root of `p` is a root of the group's polynomial, and its image
    // modulo a prime a root of the image: a nonzero image proves at word
    // cost that a candidate is none; the others are substituted into `p`
    let images: Option<Vec<(u32, Residue)>> = coeffs
        .iter()
        .map(|(e, c)| Some((*e, Residue::of(&Rational::from(c))?)))
        .collect();
    let image_vanishes = |v: &Rational| -> bool {
        let (Some(images), Some(r)) = (&images, Residue::of(v)) else {
            return true;
        };
        images
            .iter()
            .fold(Residue::ZERO, |acc, (e, c)| acc + *c * r.pow(*e))
            .is_zero()
    };
    let roots = candidates
        .into_iter()
        .filter(|v| image_vanishes(v) && p.subs(var, &Poly::constant(v.clone())).is_zero())
        .collect();
    (roots, ok1 && ok2)
}

/// Positive divisors of `|n|` by trial division; `false` beyond the limit.
fn divisors(n: &Integer) -> (Vec<Integer>, bool) {
    let n = n.clone().abs();
    let Some(small) = n.to_u64().filter(|v| *v <= DIVISOR_LIMIT) else {
        return (vec![Integer::from(1)], false);
    };
    let mut out = Vec::new();
    let mut d = 1u64;
    while d * d <= small {
        if small % d == 0 {
            out.push(Integer::from(d));
            out.push(Integer::from(small / d));
        }
        d += 1;
    }
    out.sort();
    out.dedup();
    (out, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_that_vanish_in_every_other_variable() {
        let (x, y) = (Poly::var("x"), Poly::var("y"));
        // (2x − 1)(x + 3)·y: roots 1/2 and −3 whatever y
        let p = &(&(&(&x * &Poly::int(2)) - &Poly::int(1)) * &(&x + &Poly::int(3))) * &y;
        let (roots, complete) = rational_roots(&p, "x");
        assert_eq!(roots, vec![Rational::from(-3), Rational::from((1, 2))]);
        assert!(complete);
        // x + y vanishes at no x for every y
        assert!(rational_roots(&(&x + &y), "x").0.is_empty());
        assert!(rational_roots(&x, "y").0.is_empty());
    }
}
