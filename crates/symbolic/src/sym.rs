//! [`Sym`]: an element of the field of fractions of
//! `ℚ[vars][s, c]/(s² + c² − 1)`, as a numerator over a factored
//! denominator.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use rug::Rational;
use rug::ops::Pow;

use crate::error::SymError;
use crate::gcd::common_factor;
use crate::modular::Images;
use crate::poly::Poly;
use crate::var::{PI, Var};

/// An exact symbolic value `num / Π fᵢ^eᵢ`.
///
/// Invariants (the canonical form), restored after every operation:
/// * `num` and every factor `fᵢ` are reduced modulo `s² + c² − 1`;
/// * every factor is non-constant, primitive (coprime integer
///   coefficients), has a positive leading coefficient, and is either a
///   single variable or has no monomial content; constants are folded into
///   `num`;
/// * no factor divides `num` (cancellation by exact division);
/// * zero is `0` with no factors.
///
/// Addition uses the least common denominator by exponents, so
/// `a/d + b/d = (a + b)/d`. Equality (`==`, [`Sym::equals`]) is
/// mathematical equality, decided exactly by cross-multiplication.
#[derive(Clone)]
pub struct Sym {
    num: Poly,
    den: BTreeMap<Poly, u32>,
}

impl Sym {
    /// The polynomial `p` (no denominator).
    pub fn from_poly(p: Poly) -> Sym {
        Sym {
            num: p,
            den: BTreeMap::new(),
        }
    }

    /// Zero.
    pub fn zero() -> Sym {
        Sym::from_poly(Poly::zero())
    }

    /// One.
    pub fn one() -> Sym {
        Sym::from_poly(Poly::one())
    }

    /// The integer `n`.
    pub fn int(n: i64) -> Sym {
        Sym::from_poly(Poly::int(n))
    }

    /// The rational `q`.
    pub fn rational(q: Rational) -> Sym {
        Sym::from_poly(Poly::constant(q))
    }

    /// The variable `name` (any string; `s`, `c` are `sin θ`, `cos θ`).
    pub fn var(name: &str) -> Sym {
        Sym::from_poly(Poly::var(name))
    }

    /// The symbol `π` (the variable `pi`).
    pub fn pi() -> Sym {
        Sym::var(PI)
    }

    /// True when the value is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// The value when it is a constant.
    pub fn as_rational(&self) -> Option<Rational> {
        if self.den.is_empty() {
            self.num.as_constant()
        } else {
            None
        }
    }

    /// The numerator.
    pub fn numerator(&self) -> &Poly {
        &self.num
    }

    /// The denominator as factors with multiplicities (empty for a
    /// polynomial).
    pub fn denominator(&self) -> &BTreeMap<Poly, u32> {
        &self.den
    }

    /// The denominator multiplied out.
    pub fn denominator_poly(&self) -> Poly {
        self.den
            .iter()
            .fold(Poly::one(), |acc, (f, e)| acc * &f.pow(*e))
    }

    /// The names of the variables that occur.
    pub fn variables(&self) -> BTreeSet<String> {
        crate::var::names(self.vars())
    }

    /// The variables of the numerator and of every denominator factor.
    pub(crate) fn vars(&self) -> Vec<Var> {
        let mut out = Vec::new();
        self.num.collect_vars(&mut out);
        for f in self.den.keys() {
            f.collect_vars(&mut out);
        }
        out
    }

    /// Exact mathematical equality.
    pub fn equals(&self, other: &Sym) -> bool {
        if self.den == other.den {
            return self.num == other.num;
        }
        let l = common_denominator(&self.den, &other.den);
        self.lift(&l) == other.lift(&l)
    }

    /// `self / other`, or `None` when `other` is exactly zero.
    pub fn checked_div(&self, other: &Sym) -> Option<Sym> {
        if other.is_zero() {
            return None;
        }
        let mut num = other
            .den
            .iter()
            .fold(self.num.clone(), |acc, (f, e)| acc * &f.pow(*e));
        let mut den = self.den.clone();
        insert_factor(&mut num, &mut den, &other.num, 1);
        Some(cancel(num, den))
    }

    /// `self ± other` (`negate` selects `−`).
    pub(crate) fn add_signed(&self, other: &Sym, negate: bool) -> Sym {
        let combine = |a: Poly, b: &Poly| if negate { a - b } else { a + b };
        if self.den == other.den {
            return cancel(combine(self.num.clone(), &other.num), self.den.clone());
        }
        let l = common_denominator(&self.den, &other.den);
        cancel(combine(self.lift(&l), &other.lift(&l)), l)
    }

    /// `self · other`.
    pub(crate) fn mul_ref(&self, other: &Sym) -> Sym {
        if self.is_zero() || other.is_zero() {
            return Sym::zero();
        }
        let mut num = &self.num * &other.num;
        let mut den = self.den.clone();
        for (f, e) in &other.den {
            insert_factor(&mut num, &mut den, f, *e);
        }
        cancel(num, den)
    }

    /// `1 / denominator` (already canonical).
    pub(crate) fn denominator_inverse(&self) -> Sym {
        Sym {
            num: Poly::one(),
            den: self.den.clone(),
        }
    }

    /// `−self`.
    pub(crate) fn negated(self) -> Sym {
        Sym {
            num: -self.num,
            den: self.den,
        }
    }

    /// The numerator over the multiple `l` of the denominator.
    fn lift(&self, l: &BTreeMap<Poly, u32>) -> Poly {
        l.iter().fold(self.num.clone(), |acc, (f, e)| {
            let own = self.den.get(f).copied().unwrap_or(0);
            if *e > own { acc * &f.pow(e - own) } else { acc }
        })
    }

    /// The value with the variable `name` replaced by `value`, or an error
    /// when a denominator factor becomes zero.
    pub fn try_subs(&self, name: &str, value: &Sym) -> Result<Sym, SymError> {
        let num = subs_poly(&self.num, name, value);
        let mut den = Sym::one();
        for (f, e) in &self.den {
            let fv = subs_poly(f, name, value);
            if fv.is_zero() {
                return Err(SymError::ZeroDenominator(f.to_string()));
            }
            den = den.mul_ref(&pow(&fv, *e));
        }
        num.checked_div(&den)
            .ok_or_else(|| SymError::ZeroDenominator(self.denominator_poly().to_string()))
    }

    /// The value with the variable `name` replaced by `value`.
    ///
    /// # Panics
    /// When a denominator factor becomes zero; see [`Sym::try_subs`].
    pub fn subs(&self, name: &str, value: &Sym) -> Sym {
        self.try_subs(name, value)
            .unwrap_or_else(|e| panic!("Sym::subs({name} := {value}): {e}"))
    }
}

/// `xⁿ` by repeated squaring.
fn pow(x: &Sym, n: u32) -> Sym {
    crate::power::by_squaring(x, n, Sym::one(), Sym::mul_ref)
}

/// The polynomial `p` with `name := value`.
fn subs_poly(p: &Poly, name: &str, value: &Sym) -> Sym {
    if value.den.is_empty() {
        return Sym::from_poly(p.subs(name, &value.num));
    }
    // p = Σ gₑ xᵉ
    let groups = p.coefficients_in(name);
    let top = groups.len() - 1;
    if top == 0 {
        return Sym::from_poly(p.clone());
    }
    // value = a/b: p = Σ gₑ aᵉ b^{top−e} / b^top, the numerator by Horner's
    // rule in a, and the fraction brought to lowest terms once
    let b = value.denominator_poly();
    let mut b_power = Poly::one();
    let mut acc = Poly::zero();
    for g in groups.iter().rev() {
        acc = &acc * &value.num + &(g * &b_power);
        b_power = &b_power * &b;
    }
    let den = value
        .den
        .iter()
        .map(|(f, k)| (f.clone(), k * top as u32))
        .collect();
    cancel(acc, den)
}

/// The least common multiple of two factored denominators by exponents.
fn common_denominator(a: &BTreeMap<Poly, u32>, b: &BTreeMap<Poly, u32>) -> BTreeMap<Poly, u32> {
    let mut l = a.clone();
    for (f, e) in b {
        let x = l.entry(f.clone()).or_insert(0);
        *x = (*x).max(*e);
    }
    l
}

/// Multiplies the denominator by `pᵉ` (`p ≠ 0`), keeping factors
/// canonical: the unit and the content go to `num`, the monomial content is
/// split into single variables, and a factor already present (or dividing
/// `p` exactly) has its exponent raised.
fn insert_factor(num: &mut Poly, den: &mut BTreeMap<Poly, u32>, p: &Poly, e: u32) {
    let (u, p) = p.canonical();
    *num = num.scale(&u.pow(e).recip());
    let content = p
        .terms()
        .map(|(m, _)| m.clone())
        .reduce(|a, b| a.gcd(&b))
        .unwrap_or_default();
    let mut p = p;
    if !content.is_one() {
        for (v, k) in content.factors() {
            *den.entry(Poly::var(v.name())).or_insert(0) += k * e;
        }
        let monomial = Poly::term(content, Rational::from(1));
        p = p.exact_div(&monomial).unwrap_or(p);
    }
    if p.as_constant().is_some() {
        return;
    }
    if let Some(x) = den.get_mut(&p) {
        *x += e;
        return;
    }
    let found = den
        .keys()
        .find_map(|f| p.exact_div(f).map(|q| (f.clone(), q)));
    match found {
        Some((f, q)) => {
            *den.entry(f).or_insert(0) += e;
            insert_factor(num, den, &q, e);
        }
        None => {
            den.insert(p, e);
        }
    }
}

/// Brings `num / den` to lowest terms: every factor that divides `num`
/// exactly is removed as often as it does, and a factor free of `s`, `c`
/// that shares a divisor `g` with `num` is split, `g` cancelled
/// ([`crate::gcd::common_factor`]). Each split lowers the degree of `num`,
/// so this ends.
fn cancel(mut num: Poly, den: BTreeMap<Poly, u32>) -> Sym {
    if num.is_zero() {
        return Sym::zero();
    }
    let mut out: BTreeMap<Poly, u32> = BTreeMap::new();
    let mut pending: Vec<(Poly, u32)> = den.into_iter().collect();
    // the numerator's images for the variables of every factor, formed in
    // one pass and kept until the numerator changes
    let mut images = Images::default();
    let mut vars = Vec::new();
    for (f, _) in &pending {
        f.collect_vars(&mut vars);
    }
    images.form(&num, &vars);
    while let Some((f, mut e)) = pending.pop() {
        // Most factors share nothing with the numerator, and a modular
        // image proves it at word cost (then neither an exact division nor
        // a common factor exists).
        if !f.is_trig() && crate::modular::coprime_to_images(&f, &mut [(&num, &mut images)]) {
            *out.entry(f).or_insert(0) += e;
            continue;
        }
        while e > 0 {
            match num.exact_div(&f) {
                Some(q) => {
                    num = q;
                    images = Images::default();
                    e -= 1;
                }
                None => break,
            }
        }
        if e == 0 {
            continue;
        }
        let Some(g) = common_factor(&num, &f) else {
            *out.entry(f).or_insert(0) += e;
            continue;
        };
        num = num.exact_div(&g).expect("a common factor divides");
        images = Images::default();
        let (unit, rest) = f
            .exact_div(&g)
            .expect("a common factor divides")
            .canonical();
        num = num.scale(&unit.recip());
        if e > 1 {
            pending.push((f, e - 1));
        }
        if rest.as_constant().is_none() {
            pending.push((rest, 1));
        }
    }
    Sym { num, den: out }
}

impl PartialEq for Sym {
    fn eq(&self, other: &Self) -> bool {
        self.equals(other)
    }
}

impl Eq for Sym {}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Sym({self})")
    }
}

impl From<Poly> for Sym {
    fn from(p: Poly) -> Sym {
        Sym::from_poly(p)
    }
}

/// Zero.
impl Default for Sym {
    fn default() -> Sym {
        Sym::zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    #[test]
    fn pythagoras_is_zero() {
        let x = v("s") * &v("s") + &(v("c") * &v("c")) - &Sym::int(1);
        assert!(x.is_zero());
        let y = (v("s") + &v("c")) * &(v("s") + &v("c"))
            - &(Sym::int(2) * &v("s") * &v("c"))
            - &Sym::int(1);
        assert!(y.is_zero());
    }

    #[test]
    fn equal_denominators_stay() {
        let d = v("beta") + &Sym::int(1);
        let a = v("m") / &d;
        let b = v("s") / &d;
        let sum = a + &b;
        assert_eq!(sum.denominator().len(), 1);
        assert_eq!(sum.denominator().get(d.numerator()), Some(&1));
        assert_eq!(sum.numerator(), (v("m") + &v("s")).numerator());
    }

    #[test]
    fn substituting_a_fraction_equals_the_arithmetic() {
        // p = 3x²y − x·s + 5 with x := (y + 1)/(y − 2)² and x := 2z/(1 + z²)
        let (x, y, z) = (v("x"), v("y"), v("z"));
        let p = Sym::int(3) * &x * &x * &y - &(x.clone() * &v("s")) + &Sym::int(5);
        let at = |value: &Sym| {
            Sym::int(3) * value * value * &y - &(value.clone() * &v("s")) + &Sym::int(5)
        };
        let y2 = y.clone() - &Sym::int(2);
        for value in [
            (y.clone() + &Sym::one()) / &(y2.clone() * &y2),
            Sym::int(2) * &z / &(Sym::one() + &(z.clone() * &z)),
        ] {
            assert_eq!(p.subs("x", &value), at(&value));
        }
        // a denominator that cancels: x² − 1 at x := 1/y is (1 − y²)/y²
        let q = x.clone() * &x - &Sym::one();
        let value = Sym::one() / &y;
        assert_eq!(
            q.subs("x", &value),
            (Sym::one() - &(y.clone() * &y)) / &(y.clone() * &y)
        );
    }

    #[test]
    fn cancellation_to_one() {
        let d = v("beta") + &Sym::int(1);
        let x = v("beta") / &d + &(Sym::int(1) / &d);
        assert_eq!(x.as_rational(), Some(Rational::from(1)));
        assert!(x.denominator().is_empty());
    }

    #[test]
    fn lowest_terms_through_gcd() {
        // (m + 2)/(m² − 4) = 1/(m − 2): m² − 4 does not divide m + 2, but
        // the two share m + 2.
        let m = v("m");
        let x = (m.clone() + &Sym::int(2)) / &(m.clone() * &m - &Sym::int(4));
        assert_eq!(x.to_string(), "1/(m - 2)");
        // Several parameters and a trigonometric numerator:
        // (λ + μ)(s + c)/((λ + μ)²(λ − μ)) = (s + c)/((λ + μ)(λ − μ)).
        let (l, u) = (v("lambda"), v("mu"));
        let sum = l.clone() + &u;
        let num = sum.clone() * &(v("s") + &v("c"));
        let y = num / &(sum.clone() * &sum * &(l.clone() - &u));
        assert_eq!(y.numerator(), (v("s") + &v("c")).numerator());
        let rest = sum * &(l - &u);
        assert_eq!(&y.denominator_poly(), rest.numerator());
        assert_eq!(y * &rest, v("s") + &v("c"));
    }

    #[test]
    fn factors_are_canonical() {
        // 1/(2 − 2β) = (−1/2)/(β − 1)
        let x = Sym::int(1) / &(Sym::int(2) - &(Sym::int(2) * &v("beta")));
        let f = v("beta") - &Sym::int(1);
        assert_eq!(x.denominator().get(f.numerator()), Some(&1));
        assert_eq!(x.numerator(), &Poly::constant(Rational::from((-1, 2))));
        // 1/(m² s + m s) = 1/(m·s·(m + 1))
        let y = Sym::int(1) / &(v("m") * &v("m") * &v("s") + &(v("m") * &v("s")));
        assert_eq!(y.denominator().len(), 3);
        // (β+1)² merges with the existing β + 1
        let b1 = v("beta") + &Sym::int(1);
        let z = (Sym::int(1) / &b1) / &(b1.clone() * &b1);
        assert_eq!(z.denominator().get(b1.numerator()), Some(&3));
        // a product with the same factor: exponents add
        let w = (v("m") / &b1) * &(v("s") / &b1);
        assert_eq!(w.denominator().get(b1.numerator()), Some(&2));
        // s²/s cancels through the relation
        assert_eq!(v("s") * &v("s") / &v("s"), v("s"));
        assert!((v("s") * &v("s") / &v("s")).denominator().is_empty());
    }

    #[test]
    fn division_by_zero() {
        let zero = v("s") * &v("s") + &(v("c") * &v("c")) - &Sym::int(1);
        assert!(Sym::int(1).checked_div(&zero).is_none());
        let r = std::panic::catch_unwind(|| Sym::int(1) / &Sym::zero());
        assert!(r.is_err());
    }

    #[test]
    fn equality_is_mathematical() {
        let b1 = v("beta") + &Sym::int(1);
        let a = (v("beta") * &v("beta") - &Sym::int(1)) / &(b1.clone() * &v("m"));
        let b = (v("beta") - &Sym::int(1)) / &v("m");
        assert!(a.equals(&b));
        assert_eq!(a, b);
        assert_ne!(a, v("beta") / &v("m"));
        assert_eq!(
            Sym::rational(Rational::from((3, 4))).as_rational(),
            Some(Rational::from((3, 4)))
        );
        assert_eq!(a.variables().into_iter().collect::<Vec<_>>(), ["beta", "m"]);
    }

    #[test]
    fn substitution() {
        let b1 = v("beta") + &Sym::int(1);
        let x = v("beta") / &b1 * &v("s");
        let y = x.subs("beta", &(Sym::int(1) / &v("m")));
        // (1/m)/(1/m + 1)·s = s/(1 + m)
        assert_eq!(y, v("s") / &(v("m") + &Sym::int(1)));
        assert_eq!(x.subs("s", &Sym::int(2)), Sym::int(2) * &v("beta") / &b1);
        assert!(x.try_subs("beta", &Sym::int(-1)).is_err());
        // substitution acts on the reduced representative: s² is 1 − c²
        let z = (v("s") * &v("s")).subs("c", &Sym::rational(Rational::from((3, 5))));
        assert_eq!(z.as_rational(), Some(Rational::from((16, 25))));
    }
}
