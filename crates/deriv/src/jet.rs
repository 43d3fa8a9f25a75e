//! Truncated Taylor series ("jets") over any [`Ring`].
//!
//! A [`Jet<T, K>`] is `x₀ + x₁ε + … + x_{K−1}ε^{K−1}` with `ε^K = 0`: the
//! coefficients are Taylor coefficients, `x_k = f^{(k)}(a)/k!`, so a jet
//! seeded with [`Jet::variable`] carries the derivatives of order `0..K` of
//! every expression evaluated on it.
//!
//! The arithmetic is generic over [`Ring`] and uses nothing else: constants
//! are built from existing values (`x.int(n)`, `x.rational(q)`), never from
//! f64 literals, so the same code runs on f64, [`trig_core::Mpfr`] and exact
//! rings. Each rule is written once: the Cauchy product in `mul_coeffs`,
//! the quotient recurrence in `div_coeffs`, and the joint sine/cosine
//! recurrence in `sin_cos_coeffs`; the operator impls only delegate.
//!
//! Comparison (`PartialEq`, `PartialOrd`) looks at the value (constant term)
//! only, as in `num-dual`, so that domain checks such as
//! [`trig_core::Variable::contains`] behave on jets as on their values.
//! Compare [`Jet::coeffs`] for equality of whole series.

use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::Rational;
use trig_core::{Atoms, Family, Real, Ring};

/// A truncated Taylor series with `K` coefficients (order `K − 1`).
#[derive(Clone, Debug)]
pub struct Jet<T, const K: usize> {
    c: [T; K],
}

/// `k!` in the context of `like`, as a product of ring integers (exact in
/// exact rings, and in f64 for `k ≤ 18`; no big-number allocation).
pub(crate) fn factorial<T: Ring>(like: &T, k: usize) -> T {
    (2..=k as i64).fold(like.int(1), |acc, j| acc * &like.int(j))
}

impl<T: Ring, const K: usize> Jet<T, K> {
    /// The jet with these Taylor coefficients.
    pub fn from_coeffs(c: [T; K]) -> Self {
        const { assert!(K >= 1, "a jet needs at least one coefficient") };
        Jet { c }
    }

    /// The jet with these derivatives of orders `0..K` (`x_k = f^{(k)}/k!`).
    ///
    /// # Panics
    /// If `d` does not have `K` entries.
    pub fn from_derivatives(d: &[T]) -> Self {
        assert_eq!(d.len(), K, "one derivative per coefficient");
        Self::from_coeffs(std::array::from_fn(|k| d[k].clone() / &factorial(&d[k], k)))
    }

    /// The constant `x` (all higher coefficients zero).
    pub fn constant(x: T) -> Self {
        let zero = x.int(0);
        let mut c: [T; K] = std::array::from_fn(|_| zero.clone());
        c[0] = x;
        Self::from_coeffs(c)
    }

    /// The independent variable at `x0`: `x0 + ε` (just `x0` when `K = 1`).
    pub fn variable(x0: T) -> Self {
        let one = x0.int(1);
        let mut jet = Self::constant(x0);
        if K > 1 {
            jet.c[1] = one;
        }
        jet
    }

    /// The Taylor coefficients `x_k = f^{(k)}/k!`.
    pub fn coeffs(&self) -> &[T; K] {
        &self.c
    }

    /// The Taylor coefficients, by value.
    pub fn into_coeffs(self) -> [T; K] {
        self.c
    }

    /// The value (constant term).
    pub fn value(&self) -> &T {
        &self.c[0]
    }

    /// The derivative of order `k`, `k!·x_k` (`k!` built in the ring, then
    /// one multiplication).
    ///
    /// # Panics
    /// If `k ≥ K`.
    pub fn derivative(&self, k: usize) -> T {
        assert!(
            k < K,
            "derivative of order {k} of a jet with {K} coefficients"
        );
        let x = &self.c[k];
        x.clone() * &factorial(x, k)
    }

    /// The derivatives of orders `0..K`.
    pub fn derivatives(&self) -> Vec<T> {
        (0..K).map(|k| self.derivative(k)).collect()
    }

    fn map(&self, f: impl Fn(&T) -> T) -> Self {
        Jet {
            c: std::array::from_fn(|k| f(&self.c[k])),
        }
    }

    fn zip(&self, other: &Self, f: impl Fn(&T, &T) -> T) -> Self {
        Jet {
            c: std::array::from_fn(|k| f(&self.c[k], &other.c[k])),
        }
    }
}

/// Cauchy product: `(ab)_k = Σ_{j=0..k} a_j b_{k−j}`.
fn mul_coeffs<T: Ring, const K: usize>(a: &[T; K], b: &[T; K]) -> [T; K] {
    std::array::from_fn(|k| {
        (1..=k).fold(a[0].clone() * &b[k], |acc, j| {
            acc + &(a[j].clone() * &b[k - j])
        })
    })
}

/// Quotient `q = a/b`: `q_k = (a_k − Σ_{j=1..k} b_j q_{k−j}) / b₀`.
/// Undefined when `b₀ = 0` (the caller's concern, as for the scalars).
fn div_coeffs<T: Ring, const K: usize>(a: &[T; K], b: &[T; K]) -> [T; K] {
    let mut q: [T; K] = a.clone();
    for k in 0..K {
        let num = (1..=k).fold(a[k].clone(), |acc, j| acc - &(b[j].clone() * &q[k - j]));
        q[k] = num / &b[0];
    }
    q
}

/// `(sin x, cos x)` by the joint recurrence from `s₀, c₀ = sin x₀, cos x₀`:
/// `k·s_k = Σ_{j=1..k} j·x_j·c_{k−j}`, `k·c_k = −Σ_{j=1..k} j·x_j·s_{k−j}`
/// (from `s' = x'c`, `c' = −x's`).
fn sin_cos_coeffs<T: Ring, const K: usize>(x: &[T; K], s0: T, c0: T) -> ([T; K], [T; K]) {
    // j·x_j: the coefficients of x' (shifted by one).
    let dx: [T; K] = std::array::from_fn(|j| x[j].clone() * &x[j].int(j as i64));
    let mut s: [T; K] = std::array::from_fn(|_| s0.clone());
    let mut c: [T; K] = std::array::from_fn(|_| c0.clone());
    for k in 1..K {
        let zero = x[0].int(0);
        let (sk, ck) = (1..=k).fold((zero.clone(), zero), |(sk, ck), j| {
            (
                sk + &(dx[j].clone() * &c[k - j]),
                ck - &(dx[j].clone() * &s[k - j]),
            )
        });
        let kk = x[0].int(k as i64);
        s[k] = sk / &kk;
        c[k] = ck / &kk;
    }
    (s, c)
}

/// `exp x` by the recurrence from `e₀ = exp x₀`: `k·e_k = Σ_{j=1..k} j·x_j·e_{k−j}`
/// (from `e' = x'e`).
fn exp_coeffs<T: Ring, const K: usize>(x: &[T; K], e0: T) -> [T; K] {
    let mut e: [T; K] = std::array::from_fn(|_| e0.clone());
    for k in 1..K {
        let sum = (1..=k).fold(x[0].int(0), |acc, j| {
            acc + &(x[j].clone() * &x[j].int(j as i64) * &e[k - j])
        });
        e[k] = sum / &x[0].int(k as i64);
    }
    e
}

/// The series of `sin(θ₀+ε)`, `cos(θ₀+ε)` from `s0 = sin θ₀`, `c0 = cos θ₀`
/// alone: the `k`-th derivatives cycle through `s, c, −s, −c` (sine) and
/// `c, −s, −c, s` (cosine), each divided by `k!` (built in the ring).
fn angle_series<T: Ring, const K: usize>(s0: &T, c0: &T) -> ([T; K], [T; K]) {
    let term = |k: usize, x: &T, negate: bool| {
        let t = x.clone() / &factorial(x, k);
        if negate { -t } else { t }
    };
    let sin = std::array::from_fn(|k| match k % 4 {
        0 => term(k, s0, false),
        1 => term(k, c0, false),
        2 => term(k, s0, true),
        _ => term(k, c0, true),
    });
    let cos = std::array::from_fn(|k| match k % 4 {
        0 => term(k, c0, false),
        1 => term(k, s0, true),
        2 => term(k, c0, true),
        _ => term(k, s0, false),
    });
    (sin, cos)
}

/// Jet atoms at the angle `θ₀` without evaluating `sin`: `s`, `c` are the
/// series of `sin(θ₀+ε)`, `cos(θ₀+ε)` built from `s0 = sin θ₀`,
/// `c0 = cos θ₀` (coefficients `s0, c0, −s0/2!, −c0/3!, s0/4!, …` for the
/// sine), and `t = θ₀ + ε`. For exact rings, where `s0`, `c0` are given
/// exactly (or as symbols).
///
/// The derivatives are with respect to the angle; for a family in
/// [`trig_core::Variable::UnitAngle`] multiply the order-`k` derivative by
/// `(π/2)^k` ([`trig_core::Variable::angle_rate`]).
pub fn angle_atoms<T: Ring, const K: usize>(s0: &T, c0: &T, theta0: T) -> Atoms<Jet<T, K>> {
    let (s, c) = angle_series(s0, c0);
    let one = theta0.int(1);
    Atoms {
        s: Jet::from_coeffs(s),
        c: Jet::from_coeffs(c),
        t: Jet::variable(theta0),
        e: Jet::constant(one),
    }
}

/// The derivatives of orders `0..K` of every function of `family` with
/// respect to its native variable at `x`, as a matrix `[function][order]`.
///
/// The jet `x + ε` is seeded in the native variable and
/// [`trig_core::Variable::atoms`] does the rest (for `UnitAngle` it forms
/// `θ = (x + ε)·π/2` on jets, so the chain rule factor `(π/2)^k` is
/// included). Parameters enter as constant jets, in the order of
/// [`trig_core::FamilyInfo::params`]. No domain check is made.
///
/// # Panics
/// If the family has no formulas or `params` has the wrong length (as
/// [`Family::eval`]).
pub fn family_derivatives<T: Real, const K: usize>(
    family: Family,
    x: &T,
    params: &[T],
) -> Vec<Vec<T>> {
    let variable = family.info().variable;
    let atoms = variable.atoms(&Jet::<T, K>::variable(x.clone()));
    let params: Vec<Jet<T, K>> = params.iter().cloned().map(Jet::constant).collect();
    family
        .eval(&atoms, &params)
        .iter()
        .map(Jet::derivatives)
        .collect()
}

impl<T: Ring, const K: usize> Add<&Jet<T, K>> for Jet<T, K> {
    type Output = Jet<T, K>;
    fn add(self, rhs: &Jet<T, K>) -> Jet<T, K> {
        self.zip(rhs, |a, b| a.clone() + b)
    }
}

impl<T: Ring, const K: usize> Sub<&Jet<T, K>> for Jet<T, K> {
    type Output = Jet<T, K>;
    fn sub(self, rhs: &Jet<T, K>) -> Jet<T, K> {
        self.zip(rhs, |a, b| a.clone() - b)
    }
}

impl<T: Ring, const K: usize> Mul<&Jet<T, K>> for Jet<T, K> {
    type Output = Jet<T, K>;
    fn mul(self, rhs: &Jet<T, K>) -> Jet<T, K> {
        Jet {
            c: mul_coeffs(&self.c, &rhs.c),
        }
    }
}

impl<T: Ring, const K: usize> Div<&Jet<T, K>> for Jet<T, K> {
    type Output = Jet<T, K>;
    fn div(self, rhs: &Jet<T, K>) -> Jet<T, K> {
        Jet {
            c: div_coeffs(&self.c, &rhs.c),
        }
    }
}

/// The owned-right-operand operators delegate to the borrowed ones.
macro_rules! owned_rhs {
    ($Trait:ident, $method:ident) => {
        impl<T: Ring, const K: usize> $Trait<Jet<T, K>> for Jet<T, K> {
            type Output = Jet<T, K>;
            fn $method(self, rhs: Jet<T, K>) -> Jet<T, K> {
                self.$method(&rhs)
            }
        }
    };
}

owned_rhs!(Add, add);
owned_rhs!(Sub, sub);
owned_rhs!(Mul, mul);
owned_rhs!(Div, div);

impl<T: Ring, const K: usize> Neg for Jet<T, K> {
    type Output = Jet<T, K>;
    fn neg(self) -> Jet<T, K> {
        self.map(|a| -a.clone())
    }
}

impl<T: Ring, const K: usize> Ring for Jet<T, K> {
    fn int(&self, n: i64) -> Self {
        Jet::constant(self.value().int(n))
    }

    fn ratio(&self, num: i64, den: i64) -> Self {
        Jet::constant(self.value().ratio(num, den))
    }

    fn rational(&self, q: &Rational) -> Self {
        Jet::constant(self.value().rational(q))
    }

    fn pi(&self) -> Self {
        Jet::constant(self.value().pi())
    }

    /// The value is zero: dividing by this jet is undefined.
    fn is_zero(&self) -> bool {
        self.value().is_zero()
    }

    fn square(&self) -> Self {
        Jet {
            c: mul_coeffs(&self.c, &self.c),
        }
    }

    /// When the value's sine and cosine can be formed, the series by the
    /// joint recurrence.
    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        let (s0, c0) = self.value().try_sin_cos()?;
        let (s, c) = sin_cos_coeffs(&self.c, s0, c0);
        Some((Jet { c: s }, Jet { c }))
    }

    /// When the value's square root can be formed and is nonzero, the
    /// series by `r_k = (x_k − Σ_{j=1..k−1} r_j r_{k−j}) / (2r₀)`.
    fn try_sqrt(&self) -> Option<Self> {
        let r0 = self.value().try_sqrt()?;
        if K > 1 && r0.is_zero() {
            return None;
        }
        let mut r: [T; K] = std::array::from_fn(|_| r0.clone());
        let two_r0 = r0.clone() * &r0.int(2);
        for k in 1..K {
            let sum = (1..k).fold(self.c[k].clone(), |acc, j| {
                acc - &(r[j].clone() * &r[k - j])
            });
            r[k] = sum / &two_r0;
        }
        Some(Jet { c: r })
    }

    /// When the value's exponential can be formed, the series by its
    /// recurrence.
    fn try_exp(&self) -> Option<Self> {
        let e0 = self.value().try_exp()?;
        Some(Jet {
            c: exp_coeffs(&self.c, e0),
        })
    }
}

/// Equality of values (constant terms) only; see the module docs.
impl<T: PartialEq, const K: usize> PartialEq for Jet<T, K> {
    fn eq(&self, other: &Self) -> bool {
        self.c[0] == other.c[0]
    }
}

/// Order of values (constant terms) only; see the module docs.
impl<T: PartialOrd, const K: usize> PartialOrd for Jet<T, K> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.c[0].partial_cmp(&other.c[0])
    }
}

impl<T: Real, const K: usize> Real for Jet<T, K> {
    fn sin_cos(&self) -> (Self, Self) {
        let (s0, c0) = self.value().sin_cos();
        let (s, c) = sin_cos_coeffs(&self.c, s0, c0);
        (Jet { c: s }, Jet { c })
    }

    fn exp(&self) -> Self {
        Jet {
            c: exp_coeffs(&self.c, self.value().exp()),
        }
    }

    /// The value as f64.
    fn to_f64(&self) -> f64 {
        self.value().to_f64()
    }

    /// True when every coefficient is finite.
    fn is_finite(&self) -> bool {
        self.c.iter().all(T::is_finite)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use trig_core::{Mpfr, Variable};

    const PREC: u32 = 256;

    fn mp(x: f64) -> Mpfr {
        Mpfr::from_f64(PREC, x)
    }

    fn mpq(num: i64, den: i64) -> Mpfr {
        Mpfr::from_rational(PREC, &Rational::from((num, den)))
    }

    fn abs<T: Real>(x: &T) -> T {
        if *x < x.int(0) { -x.clone() } else { x.clone() }
    }

    /// `2^e` in the context of `like`.
    fn pow2<T: Ring>(like: &T, e: i32) -> T {
        let two = like.int(2);
        if e >= 0 {
            two.powi(e as u32)
        } else {
            like.int(1) / &two.powi((-e) as u32)
        }
    }

    /// `sin^{(k)}(y)` and `cos^{(k)}(y)` from the derivative cycle.
    fn sin_cos_deriv<T: Real>(y: &T, k: usize) -> (T, T) {
        let (s, c) = y.sin_cos();
        match k % 4 {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    const KC: usize = 8;

    /// Checks every closed form at `x0`. `tol(k, scale)` is the allowed
    /// absolute error of the order-`k` derivative whose magnitude is bounded
    /// by `scale`.
    fn check_closed_forms<T: Real + std::fmt::Display>(x0: T, tol: impl Fn(usize, &T) -> T) {
        let x = Jet::<T, KC>::variable(x0.clone());
        let (s, c) = x.sin_cos();
        let one = x.int(1);
        let two = x.int(2);
        let y2 = x0.clone() * &x0.int(2);
        let (s0, c0) = x0.sin_cos();
        let d = x0.int(2) + &s0;

        // (name, jet, closed form of order k, magnitude bound of order k)
        type Closed<'a, T> = Box<dyn Fn(usize) -> Option<T> + 'a>;
        type Scale<'a, T> = Box<dyn Fn(usize) -> T + 'a>;
        type Case<'a, T> = (&'static str, Jet<T, KC>, Closed<'a, T>, Scale<'a, T>);
        let cases: Vec<Case<T>> = vec![
            (
                "sin",
                s.clone(),
                Box::new(|k| Some(sin_cos_deriv(&x0, k).0)),
                Box::new(|_| x0.int(1)),
            ),
            (
                "cos",
                c.clone(),
                Box::new(|k| Some(sin_cos_deriv(&x0, k).1)),
                Box::new(|_| x0.int(1)),
            ),
            (
                // sin·cos = sin(2x)/2: order k is 2^{k−1}·sin^{(k)}(2x)
                "sin*cos",
                s.clone() * &c,
                Box::new(|k| Some(sin_cos_deriv(&y2, k).0 * &pow2(&x0, k as i32 - 1))),
                Box::new(|k| pow2(&x0, k as i32)),
            ),
            (
                // sin² = (1 − cos 2x)/2: order k ≥ 1 is −2^{k−1}·cos^{(k)}(2x)
                "sin^2",
                s.square(),
                Box::new(|k| {
                    Some(if k == 0 {
                        s0.square()
                    } else {
                        -(sin_cos_deriv(&y2, k).1 * &pow2(&x0, k as i32 - 1))
                    })
                }),
                Box::new(|k| pow2(&x0, k as i32)),
            ),
            (
                // f = 1/(2+s): f' = −c/(2+s)², f'' = (1+2s+c²)/(2+s)³,
                // f''' = c(s²−8s−2)/(2+s)⁴ (checked with a CAS).
                "1/(2+sin)",
                one.clone() / &(two.clone() + &s),
                Box::new(|k| match k {
                    0 => Some(x0.int(1) / &d),
                    1 => Some(-c0.clone() / &d.square()),
                    2 => Some((x0.int(1) + &(s0.clone() * &x0.int(2)) + &c0.square()) / &d.powi(3)),
                    3 => Some(
                        c0.clone() * &(s0.square() - &(s0.clone() * &x0.int(8)) - &x0.int(2))
                            / &d.powi(4),
                    ),
                    _ => None,
                }),
                Box::new(|_| x0.int(2)),
            ),
            (
                "x^3",
                x.powi(3),
                Box::new(|k| {
                    Some(match k {
                        0 => x0.powi(3),
                        1 => x0.square() * &x0.int(3),
                        2 => x0.clone() * &x0.int(6),
                        3 => x0.int(6),
                        _ => x0.int(0),
                    })
                }),
                Box::new(|_| x0.int(6)),
            ),
        ];
        for (name, jet, closed, scale) in &cases {
            for k in 0..KC {
                let Some(expected) = closed(k) else { continue };
                let got = jet.derivative(k);
                let err = abs(&(got.clone() - &expected));
                let allowed = tol(k, &scale(k));
                assert!(
                    err <= allowed,
                    "{name}, order {k}: jet {got}, closed form {expected}, error {err} > {allowed}"
                );
            }
        }
    }

    #[test]
    fn closed_forms_in_f64() {
        // Each Taylor coefficient goes through at most ~K rounded
        // multiply-adds on O(1) terms plus the exact-k! rescaling, and the
        // closed forms themselves carry a few roundings: allow 4·(k+1) ulps
        // of the derivative's magnitude bound.
        for x0 in [0.7_f64, -1.3, 2.9] {
            check_closed_forms(x0, |k, scale| 4.0 * (k as f64 + 1.0) * f64::EPSILON * scale);
        }
    }

    #[test]
    fn closed_forms_in_mpfr_256() {
        // 256-bit arithmetic with O(K) roundings per coefficient: relative
        // 2⁻²⁴⁰ of the magnitude bound leaves 16 bits of headroom.
        for (n, d) in [(7, 10), (-13, 10), (29, 10)] {
            check_closed_forms(mpq(n, d), |_, scale| scale.clone() * &pow2(scale, -240));
        }
    }

    /// Midpoint of a published range (lo + 1 when unbounded above).
    fn midpoint(spec: &trig_core::ParamSpec) -> Rational {
        match (spec.range.lo.value(), spec.range.hi.value()) {
            (Some(lo), Some(hi)) => (lo + hi) / 2,
            (Some(lo), None) => lo + 1,
            (None, Some(hi)) => hi - 1,
            (None, None) => Rational::new(),
        }
    }

    #[test]
    fn jets_agree_with_central_differences_for_every_family() {
        // h = 2⁻⁶⁰: the truncation errors are h²/6·|f'''| and h²/12·|f''''|,
        // i.e. ≈ 2⁻¹²⁰ times derivatives that are at most a few hundred here;
        // the rounding errors are 2⁻²⁵⁶·|f|/h ≈ 2⁻¹⁹⁶ and 2⁻²⁵⁶·|f|/h² ≈ 2⁻¹³⁶.
        // Tolerance: 2⁻¹⁰⁰ · max(1, |f^{(k)}|).
        let h = pow2(&mp(0.0), -60);
        let tol = pow2(&h, -100);
        let x = mpq(2, 5); // interior of [0, 1] and of [0, π/2]
        let mut checked = 0;
        for family in Family::ALL.into_iter().filter(Family::has_formulas) {
            let info = family.info();
            let params: Vec<Mpfr> = info
                .params
                .iter()
                .map(|spec| Mpfr::from_rational(PREC, &midpoint(spec)))
                .collect();
            let values = |at: &Mpfr| family.eval(&info.variable.atoms(at), &params);
            let plus = values(&(x.clone() + &h));
            let mid = values(&x);
            let minus = values(&(x.clone() - &h));
            let jets = family_derivatives::<Mpfr, 3>(family, &x, &params);
            assert_eq!(jets.len(), info.functions.len());
            for (i, name) in info.functions.iter().enumerate() {
                let d1 = (plus[i].clone() - &minus[i]) / &(h.clone() * &h.int(2));
                let d2 =
                    (plus[i].clone() - &(mid[i].clone() * &h.int(2)) + &minus[i]) / &h.square();
                for (k, fd) in [(0, mid[i].clone()), (1, d1), (2, d2)] {
                    let jet = &jets[i][k];
                    let one = jet.int(1);
                    let mag = abs(jet);
                    let bound = tol.clone() * if mag > one { &mag } else { &one };
                    let err = abs(&(jet.clone() - &fd));
                    assert!(
                        err <= bound,
                        "{} {name} order {k}: jet {jet}, finite difference {fd}",
                        info.id
                    );
                }
            }
            checked += 1;
        }
        assert_eq!(checked, 13);
    }

    #[test]
    fn angle_atoms_at_zero_match_the_sine_recurrence() {
        const K: usize = 10;
        let atoms: Atoms<Jet<f64, K>> = angle_atoms(&0.0, &1.0, 0.0);
        let (s, c) = Jet::<f64, K>::variable(0.0).sin_cos();
        // Both are ±1/k! rounded: exactly via the rational in `angle_atoms`,
        // through k divisions in the recurrence, so a few ulps of 1/k! apart.
        for (a, b) in [(&atoms.s, &s), (&atoms.c, &c)] {
            for (k, (x, y)) in a.coeffs().iter().zip(b.coeffs()).enumerate() {
                let tol = 2.0 * (k as f64 + 1.0) * f64::EPSILON * x.abs();
                assert!((x - y).abs() <= tol, "order {k}: {x} vs {y}");
            }
        }
        assert_eq!(atoms.t.coeffs()[..2], [0.0, 1.0]);
        // and the generic construction at another angle, against sin_cos
        let theta = 0.8_f64;
        let (s0, c0) = theta.sin_cos();
        let a: Atoms<Jet<f64, K>> = angle_atoms(&s0, &c0, theta);
        let (s, c) = Jet::<f64, K>::variable(theta).sin_cos();
        for k in 0..K {
            assert!((a.s.derivative(k) - s.derivative(k)).abs() < 1e-15);
            assert!((a.c.derivative(k) - c.derivative(k)).abs() < 1e-15);
        }
    }

    #[test]
    fn ring_structure_of_jets() {
        let x = Jet::<f64, 4>::variable(0.5);
        assert!(!x.is_zero());
        assert!(Jet::<f64, 4>::variable(0.0).is_zero());
        assert_eq!(x.int(3).coeffs(), &[3.0, 0.0, 0.0, 0.0]);
        assert_eq!(x.ratio(1, 4).coeffs(), &[0.25, 0.0, 0.0, 0.0]);
        // (x/x) = 1 exactly for this dyadic point; x·(1/x) likewise
        let q = x.clone() / &x;
        assert_eq!(q.coeffs(), &[1.0, 0.0, 0.0, 0.0]);
        assert_eq!((-x.clone()).coeffs(), &[-0.5, -1.0, 0.0, 0.0]);
        assert_eq!((x.clone() - x.clone()).coeffs(), &[0.0; 4]);
        // 1/(1−ε) = 1 + ε + ε² + ε³
        let one = x.int(1);
        let geo = one.clone() / (one - Jet::variable(0.0));
        assert_eq!(geo.coeffs(), &[1.0; 4]);
        assert!(x > x.int(0) && x == Jet::constant(0.5));
        assert!(x.is_finite() && x.to_f64() == 0.5);
        assert_eq!(Jet::<f64, 1>::variable(2.0).derivatives(), vec![2.0]);
    }

    /// `θ`-Taylor coefficient of a `u`-derivative: `d_k / ((π/2)^k·k!)`.
    fn normalized(d: f64, k: usize) -> f64 {
        let fact: f64 = (1..=k).map(|i| i as f64).product();
        d / (std::f64::consts::FRAC_PI_2.powi(k as i32) * fact)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        // The thesis cubic is a cubic polynomial in s, c with coefficients
        // bounded by 2(1+|m|) ≤ 6; its θ-derivatives are bounded by C·3^k,
        // so the θ-Taylor coefficients d_k/((π/2)^k·k!) are O(10) (3^k/k! ≤ 4.5).
        // f64 computes each through O(K) products of O(1) terms with
        // ≤ 2⁻⁵³ relative error each and no catastrophic cancellation beyond
        // that scale (K·10·few ≈ 10³ ulps ≈ 2·10⁻¹³), so 1e-12 absolute.
        #[test]
        fn thesis_cubic_f64_jets_match_mpfr(u in 0.0_f64..=1.0, m in -2.0_f64..=1.0) {
            const K: usize = 9;
            let f = family_derivatives::<f64, K>(Family::ThesisCubic, &u, &[m]);
            let g = family_derivatives::<Mpfr, K>(Family::ThesisCubic, &mp(u), &[mp(m)]);
            for i in 0..4 {
                for k in 0..K {
                    let a = normalized(f[i][k], k);
                    let b = normalized(g[i][k].to_f64(), k);
                    prop_assert!((a - b).abs() <= 1e-12, "b{i} order {k}: {a} vs {b}");
                }
            }
            for k in 1..K {
                let sum_f: f64 = (0..4).map(|i| f[i][k]).sum();
                prop_assert!(normalized(sum_f, k).abs() <= 1e-12, "f64 order {k}: {sum_f}");
                let sum_g = (1..4).fold(g[0][k].clone(), |acc, i| acc + &g[i][k]);
                prop_assert!(
                    // 256-bit roundings leave ≈ 2⁻²⁴⁵; 1e-60 ≈ 2⁻¹⁹⁹ is generous
                    normalized(sum_g.to_f64(), k).abs() <= 1e-60,
                    "mpfr order {k}: {sum_g}"
                );
            }
        }
    }

    #[test]
    fn unit_angle_atoms_on_jets_include_the_chain_rule() {
        // d/du sin(πu/2) = π/2·cos(πu/2)
        let u = 0.3_f64;
        let a = Variable::UnitAngle.atoms(&Jet::<f64, 2>::variable(u));
        let theta = u * std::f64::consts::FRAC_PI_2;
        assert!((a.s.derivative(1) - std::f64::consts::FRAC_PI_2 * theta.cos()).abs() < 1e-15);
    }
}
