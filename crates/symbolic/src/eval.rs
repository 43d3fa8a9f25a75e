//! Evaluation of [`Poly`] and [`Sym`] at assigned values: exactly in ℚ, or
//! in any [`trig_core::Ring`] (f64, [`trig_core::Mpfr`], …).
//!
//! Evaluation is of the reduced representative, so it is a ring
//! homomorphism when the values of `s` and `c` satisfy `s² + c² = 1`
//! (e.g. `s = 2k/(1+k²)`, `c = (1−k²)/(1+k²)`), and for any values when the
//! expression contains neither.

use rug::Rational;
use trig_core::Ring;

use crate::coef::Coef;
use crate::error::SymError;
use crate::poly::Poly;
use crate::residue::Residue;
use crate::sym::Sym;
use crate::var::Var;

/// The operations evaluation needs, for ℚ and for any [`Ring`].
trait Field: Clone {
    fn constant(&self, q: &Coef) -> Self;
    fn add(self, other: &Self) -> Self;
    fn mul(self, other: &Self) -> Self;
    fn div(self, other: &Self) -> Self;
    fn pow(&self, n: u32) -> Self;
    fn is_zero(&self) -> bool;
}

/// Exact rationals, inline while they are small ([`Coef`]).
impl Field for Coef {
    fn constant(&self, q: &Coef) -> Self {
        q.clone()
    }
    fn add(self, other: &Self) -> Self {
        Coef::add(&self, other)
    }
    fn mul(self, other: &Self) -> Self {
        Coef::mul(&self, other)
    }
    fn div(self, other: &Self) -> Self {
        // evaluation divides only by denominators checked to be nonzero
        self.checked_div(other).expect("a nonzero denominator")
    }
    fn pow(&self, n: u32) -> Self {
        Coef::pow(self, n)
    }
    fn is_zero(&self) -> bool {
        Coef::is_zero(self)
    }
}

/// Residues modulo a prime ([`Residue`]); `None` where undefined (a
/// denominator divisible by the prime), and undefined stays undefined.
impl Field for Option<Residue> {
    fn constant(&self, q: &Coef) -> Self {
        Residue::of_coef(q)
    }
    fn add(self, other: &Self) -> Self {
        Some(self? + (*other)?)
    }
    fn mul(self, other: &Self) -> Self {
        Some(self? * (*other)?)
    }
    fn div(self, other: &Self) -> Self {
        self?.checked_div((*other)?)
    }
    fn pow(&self, n: u32) -> Self {
        self.map(|r| r.pow(n))
    }
    fn is_zero(&self) -> bool {
        self.is_some_and(Residue::is_zero)
    }
}

/// A [`Ring`] value seen as a [`Field`].
#[derive(Clone)]
struct InRing<T>(T);

impl<T: Ring> Field for InRing<T> {
    fn constant(&self, q: &Coef) -> Self {
        InRing(self.0.rational(&q.to_rational()))
    }
    fn add(self, other: &Self) -> Self {
        InRing(self.0 + &other.0)
    }
    fn mul(self, other: &Self) -> Self {
        InRing(self.0 * &other.0)
    }
    fn div(self, other: &Self) -> Self {
        InRing(self.0 / &other.0)
    }
    fn pow(&self, n: u32) -> Self {
        InRing(self.0.powi(n))
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}

/// The values of the variables, each looked up once, when first met, with
/// whether the value is exactly zero (so that every term with that variable
/// is zero, whatever its other factors: a residue `0` is not enough, since
/// a value `p` times an undefined residue `1/p` is `1`).
struct Values<'a, F> {
    assign: &'a dyn Fn(&str) -> Option<(F, bool)>,
    bound: Vec<(Var, F, bool)>,
}

/// A variable without a value was met (its name).
struct Unbound(&'static str);

impl<'a, F: Field> Values<'a, F> {
    fn new(assign: &'a dyn Fn(&str) -> Option<(F, bool)>) -> Values<'a, F> {
        Values {
            assign,
            bound: Vec::new(),
        }
    }

    /// The value of `v` and whether it is exactly zero.
    fn get(&mut self, v: &Var) -> Result<(&F, bool), Unbound> {
        let i = match self.bound.iter().position(|(w, ..)| w == v) {
            Some(i) => i,
            None => {
                let (x, zero) = (self.assign)(v.name()).ok_or(Unbound(v.name()))?;
                self.bound.push((*v, x, zero));
                self.bound.len() - 1
            }
        };
        let (_, x, zero) = &self.bound[i];
        Ok((x, *zero))
    }
}

/// The error for the first unbound variable of `vars` in name order (`met`
/// was found unbound).
fn unbound<F>(vars: Vec<Var>, assign: &dyn Fn(&str) -> Option<F>, met: Unbound) -> SymError {
    let first = vars
        .iter()
        .map(Var::name)
        .filter(|n| assign(n).is_none())
        .min()
        .unwrap_or(met.0);
    SymError::UnboundVariable(first.to_string())
}

/// `p` at the values; a term with a variable whose value is exactly zero
/// is skipped (its other variables are still looked up, so that every
/// variable of `p` is bound).
fn eval_poly<F: Field>(p: &Poly, like: &F, values: &mut Values<F>) -> Result<F, Unbound> {
    let mut acc = like.constant(&Coef::ZERO);
    for (m, q) in p.terms() {
        let mut zero = false;
        for (v, _) in m.factors() {
            zero |= values.get(v)?.1;
        }
        if zero {
            continue;
        }
        let mut term = like.constant(q);
        for (v, e) in m.factors() {
            term = term.mul(&values.get(v)?.0.pow(e));
        }
        acc = acc.add(&term);
    }
    Ok(acc)
}

/// `x` at the values: unbound variables first, then every denominator
/// factor checked.
fn eval_sym<F: Field>(x: &Sym, like: &F, values: &mut Values<F>) -> Result<F, SymError> {
    let unbound = |values: &Values<F>, met| unbound(x.vars(), values.assign, met);
    let mut den = like.constant(&Coef::ONE);
    let mut vanishing = None;
    for (f, e) in x.denominator() {
        let value = eval_poly(f, like, values).map_err(|met| unbound(values, met))?;
        if value.is_zero() {
            vanishing.get_or_insert(f);
        }
        den = den.mul(&value.pow(*e));
    }
    let num = eval_poly(x.numerator(), like, values).map_err(|met| unbound(values, met))?;
    match vanishing {
        Some(f) => Err(SymError::ZeroDenominator(f.to_string())),
        None => Ok(num.div(&den)),
    }
}

/// An exact value, with whether it is zero.
fn exact(q: Coef) -> (Coef, bool) {
    let zero = q.is_zero();
    (q, zero)
}

/// A ring value, with whether the ring knows it is its zero
/// ([`Ring::is_exact_zero`]: never a jet whose value alone is zero).
fn in_ring<T: Ring>(x: T) -> (InRing<T>, bool) {
    let zero = x.is_exact_zero();
    (InRing(x), zero)
}

impl Poly {
    /// The exact value at the assigned rationals.
    pub fn eval_rational(
        &self,
        assign: &dyn Fn(&str) -> Option<Rational>,
    ) -> Result<Rational, SymError> {
        let assign = |n: &str| assign(n).map(|q| exact(Coef::from(q)));
        eval_poly(self, &Coef::ZERO, &mut Values::new(&assign))
            .map(|x| x.to_rational())
            .map_err(|met| unbound(self.vars(), &assign, met))
    }

    /// The value in the ring of `like` at the assigned values; coefficients
    /// are converted with `like.rational(q)`.
    pub fn eval<T: Ring>(
        &self,
        like: &T,
        assign: &dyn Fn(&str) -> Option<T>,
    ) -> Result<T, SymError> {
        let assign = |n: &str| assign(n).map(in_ring);
        eval_poly(self, &InRing(like.clone()), &mut Values::new(&assign))
            .map(|x| x.0)
            .map_err(|met| unbound(self.vars(), &assign, met))
    }
}

impl Sym {
    /// The exact value at the assigned rationals; an error for an unbound
    /// variable or a vanishing denominator factor.
    pub fn eval_rational(
        &self,
        assign: &dyn Fn(&str) -> Option<Rational>,
    ) -> Result<Rational, SymError> {
        let assign = |n: &str| assign(n).map(|q| exact(Coef::from(q)));
        eval_sym(self, &Coef::ZERO, &mut Values::new(&assign)).map(|x| x.to_rational())
    }

    /// The image modulo a prime ([`Residue`]) of the value at the assigned
    /// rationals: `None` for an unbound variable or where the image is
    /// undefined (a value's or a coefficient's denominator divisible by the
    /// prime, a denominator factor vanishing modulo it). Images that differ
    /// prove values that differ.
    pub fn eval_mod(&self, assign: &dyn Fn(&str) -> Option<Rational>) -> Option<Residue> {
        let assign = |n: &str| assign(n).map(|q| (Residue::of(&q), q == 0));
        eval_sym(self, &None, &mut Values::new(&assign))
            .ok()
            .flatten()
    }

    /// `self` with each named variable replaced by its value at once: one
    /// evaluation in the exact ring, every other variable standing for
    /// itself (substituting one variable after another would normalise
    /// every intermediate rational function); an error where a denominator
    /// factor vanishes.
    pub fn subs_all(&self, values: &[(&str, Sym)]) -> Result<Sym, SymError> {
        if values.is_empty() {
            return Ok(self.clone());
        }
        let value = |name: &str| {
            Some(
                values
                    .iter()
                    .find(|(n, _)| *n == name)
                    .map_or_else(|| Sym::var(name), |(_, v)| v.clone()),
            )
        };
        self.eval(&Sym::one(), &value)
    }

    /// The value in the ring of `like` (f64, MPFR, …) at the assigned
    /// values; coefficients are converted with `like.rational(q)`, and a
    /// denominator factor with `is_zero()` is an error.
    pub fn eval<T: Ring>(
        &self,
        like: &T,
        assign: &dyn Fn(&str) -> Option<T>,
    ) -> Result<T, SymError> {
        let assign = |n: &str| assign(n).map(in_ring);
        eval_sym(self, &InRing(like.clone()), &mut Values::new(&assign)).map(|x| x.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Mpfr;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    /// `(m² s + 3/2)/(m + c)` at m = 1/3, s = 3/5, c = 4/5.
    fn sample() -> Sym {
        (v("m") * &v("m") * &v("s") + &Sym::rational(Rational::from((3, 2)))) / &(v("m") + &v("c"))
    }

    fn exact(name: &str) -> Option<Rational> {
        match name {
            "m" => Some(Rational::from((1, 3))),
            "s" => Some(Rational::from((3, 5))),
            "c" => Some(Rational::from((4, 5))),
            _ => None,
        }
    }

    #[test]
    fn image_modulo_a_prime() {
        let image = Residue::of(&Rational::from((47, 34)));
        assert_eq!(sample().eval_mod(&exact), image);
        // m + c = 0 at m = −4/5: the denominator vanishes, no image
        let pole = |n: &str| {
            if n == "m" {
                Some(Rational::from((-4, 5)))
            } else {
                exact(n)
            }
        };
        assert_eq!(sample().eval_mod(&pole), None);
        assert_eq!(sample().eval_mod(&|_| None), None);
    }

    #[test]
    fn terms_with_a_zero_factor_are_skipped_soundly() {
        // m·x/p + 2y at m = 0: the first coefficient has no image mod p,
        // but its term is 0 at the point, so the image is that of 2y
        let p = Rational::from(crate::residue::P);
        let x =
            v("m") * &v("x") * &Sym::rational(Rational::from(1) / &p) + &(v("y") * &Sym::int(2));
        let at = |m: i64| move |n: &str| Some(Rational::from(if n == "m" { m } else { 3 }));
        assert_eq!(x.eval_mod(&at(0)), Residue::of(&Rational::from(6)));
        assert_eq!(x.eval_mod(&at(1)), None);
        // a value that is 0 modulo p but not 0 skips nothing: m = p gives
        // p·3/p + 6 = 9, whose image is not that of 6 (review of the skip)
        let sound = |image: Option<Residue>, value: i64| {
            image.is_none() || image == Residue::of(&Rational::from(value))
        };
        assert!(sound(x.eval_mod(&at(crate::residue::P as i64)), 9));
        let xy = v("x") * &v("y") + &Sym::one();
        let xy_at = |n: &str| match n {
            "x" => Some(p.clone()),
            _ => Some(Rational::from(1) / &p),
        };
        assert!(sound(xy.eval_mod(&xy_at), 2));
        // a variable of a skipped term must still be bound
        let zero_m = |n: &str| (n != "x").then(|| Rational::from(if n == "m" { 0 } else { 3 }));
        assert_eq!(
            x.eval_rational(&zero_m),
            Err(SymError::UnboundVariable("x".into()))
        );
        // in the exact ring: an exact zero removes its terms, π stays
        let y = v("m") * &v("pi") + &(v("pi") * &v("pi"));
        let sym = |n: &str| match n {
            "m" => Some(Sym::zero()),
            _ => Some(Sym::pi()),
        };
        assert_eq!(y.eval(&Sym::one(), &sym), Ok(Sym::pi() * &Sym::pi()));
        let sym1 = |n: &str| Some(if n == "m" { Sym::one() } else { Sym::pi() });
        assert_eq!(
            y.eval(&Sym::one(), &sym1),
            Ok(Sym::pi() + &(Sym::pi() * &Sym::pi()))
        );
    }

    #[test]
    fn rational_value() {
        // (1/15 + 3/2)/(17/15) = (47/30)/(17/15) = 47/34
        assert_eq!(sample().eval_rational(&exact), Ok(Rational::from((47, 34))));
    }

    #[test]
    fn f64_and_mpfr_agree_with_exact() {
        let q = sample().eval_rational(&exact).unwrap().to_f64();
        let x = sample()
            .eval(&0.0_f64, &|n| exact(n).map(|q| q.to_f64()))
            .unwrap();
        assert!((x - q).abs() < 1e-14);
        let like = Mpfr::from_f64(200, 0.0);
        let y = sample()
            .eval(&like, &|n| exact(n).map(|q| Mpfr::from_rational(200, &q)))
            .unwrap();
        assert!((y.0 - q).abs() < 1e-15);
        let p = sample()
            .numerator()
            .eval(&0.0_f64, &|n| exact(n).map(|q| q.to_f64()));
        assert!((p.unwrap() - 47.0 / 30.0).abs() < 1e-14);
    }

    #[test]
    fn errors() {
        let unbound = sample().eval_rational(&|n| (n != "c").then(|| Rational::from(1)));
        assert_eq!(unbound, Err(SymError::UnboundVariable("c".into())));
        let zero = sample().eval_rational(&|n| match n {
            "m" => Some(Rational::from(-1)),
            _ => Some(Rational::from(1)),
        });
        assert_eq!(zero, Err(SymError::ZeroDenominator("m + c".into())));
        let pi = Sym::pi().eval(&0.0_f64, &|n| (n == "pi").then_some(std::f64::consts::PI));
        assert_eq!(pi, Ok(std::f64::consts::PI));
    }

    #[test]
    fn placeholders_are_substituted_at_once() {
        let (x, y, w) = (Sym::var("__at0"), Sym::var("__at1"), Sym::var("w"));
        let (a, b) = (Sym::var("s") + &Sym::one(), Sym::var("c"));
        let side = w.clone() * &x / &(x.clone() + &y);
        let values = [("__at0", a.clone()), ("__at1", b.clone())];
        assert_eq!(side.subs_all(&values).unwrap(), w * &a / &(a.clone() + &b));
        // a denominator that vanishes once applied is an error, not a panic
        let pole = Sym::one() / &(x - &y);
        assert!(
            pole.subs_all(&[("__at0", a.clone()), ("__at1", a)])
                .is_err()
        );
    }
}
