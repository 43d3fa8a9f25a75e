//! Renaming variables: `x ↦ x'` for distinct new variables.
//!
//! A renaming that is injective on the variables of an expression, and
//! sends none of them onto another variable the expression keeps, is a
//! ring isomorphism onto its image; when it also leaves the reduced atoms
//! (`s`, `sin(X)`, `sqrt(p)`), their cosine partners and `π` alone, it
//! commutes with the normal form modulo `s² + c² − 1`. So lowest terms stay
//! lowest terms, and only the order of terms and the sign normalisation of
//! the denominator factors (positive leading coefficient) need redoing.
//! That makes a renaming far cheaper than substituting each new variable
//! for an old one ([`Sym::subs`]), and equal to it.

use std::collections::BTreeMap;

use rug::ops::Pow;

use crate::error::SymError;
use crate::monomial::Monomial;
use crate::poly::Poly;
use crate::sym::Sym;
use crate::var::Var;

impl Sym {
    /// `self` with every variable named `from` replaced by the variable
    /// named `to`, for each pair `(from, to)`.
    ///
    /// # Errors
    /// [`SymError::Rename`] when a name on either side is `π` or a
    /// trigonometric atom, two names go to one, or a new name already
    /// occurs in `self` and is not renamed itself.
    pub fn rename(&self, pairs: &[(&str, &str)]) -> Result<Sym, SymError> {
        let map: Vec<(Var, Var)> = pairs
            .iter()
            .map(|(from, to)| (Var::new(from), Var::new(to)))
            .collect();
        let refuse = |why: String| Err(SymError::Rename(why));
        for (i, (from, to)) in map.iter().enumerate() {
            if let Some(v) = [from, to]
                .into_iter()
                .find(|v| v.is_trig() || v.name() == crate::var::PI)
            {
                return refuse(format!("`{}` is not a plain variable", v.name()));
            }
            if map[..i].iter().any(|(_, t)| t == to) {
                return refuse(format!("two variables renamed `{}`", to.name()));
            }
        }
        let kept = self.vars();
        if let Some((_, to)) = map
            .iter()
            .find(|(_, to)| kept.contains(to) && map.iter().all(|(from, _)| from != to))
        {
            return refuse(format!("`{}` already occurs", to.name()));
        }
        let rename = |v: &Var| map.iter().find(|(f, _)| f == v).map_or(*v, |(_, t)| *t);
        let mut num = self.numerator().rename(&rename);
        let mut den = BTreeMap::new();
        for (f, e) in self.denominator() {
            let (unit, g) = f.rename(&rename).canonical();
            num = num.scale(&unit.pow(*e).recip());
            den.insert(g, *e);
        }
        Ok(Sym::from_lowest_terms(num, den))
    }
}

impl Poly {
    /// `self` with each variable `v` replaced by `rename(v)`, `rename`
    /// injective on the variables of `self`.
    fn rename(&self, rename: &impl Fn(&Var) -> Var) -> Poly {
        Poly::from_terms(self.terms().map(|(m, q)| {
            let mut factors: Vec<(Var, u32)> = m.factors().map(|(v, e)| (rename(v), e)).collect();
            factors.sort_by_key(|f| f.0);
            (Monomial::from_factors(factors), q.clone())
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    #[test]
    fn renaming_equals_substitution() {
        // (P1 − 2·P0·m)/((A1 − P0)(m·P1 + 3)) with P0 → A0, P1 → Z: the new
        // names reorder the terms, and A1 − P0 becomes −(A0 − A1) (the
        // leading term is now A0's)
        let x = (v("P1") - &(v("P0") * &v("m") * &Sym::int(2)))
            / &((v("A1") - &v("P0")) * &(v("m") * &v("P1") + &Sym::int(3)));
        let pairs = [("P0", "A0"), ("P1", "Z")];
        let by_subs = x.subs("P0", &v("A0")).subs("P1", &v("Z"));
        let renamed = x.rename(&pairs).unwrap();
        assert_eq!(renamed, by_subs);
        assert_eq!(renamed.to_string(), by_subs.to_string());
        assert_eq!(renamed.numerator(), by_subs.numerator());
        // a swap is a renaming too
        let swapped = x.rename(&[("P0", "P1"), ("P1", "P0")]).unwrap();
        let t = v("T");
        let by_subs = x.subs("P0", &t).subs("P1", &v("P0")).subs("T", &v("P1"));
        assert_eq!(swapped, by_subs);
    }

    #[test]
    fn renamings_that_are_not_isomorphisms_are_refused() {
        let x = v("P0") + &v("P1") * &v("s");
        assert!(matches!(
            x.rename(&[("P0", "P1")]),
            Err(SymError::Rename(_))
        ));
        assert!(matches!(
            x.rename(&[("P0", "A"), ("P1", "A")]),
            Err(SymError::Rename(_))
        ));
        assert!(matches!(x.rename(&[("s", "A")]), Err(SymError::Rename(_))));
        assert!(matches!(x.rename(&[("P0", "c")]), Err(SymError::Rename(_))));
        assert!(matches!(
            x.rename(&[("P0", "pi")]),
            Err(SymError::Rename(_))
        ));
        assert_eq!(x.rename(&[]), Ok(x.clone()));
    }
}
