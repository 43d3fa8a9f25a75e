//! Elementary functions of Taylor models ([`crate::taylor`]): `sin`, `cos`,
//! `exp`, `1/x`, `√x` by their Taylor series at the model's constant term
//! `c₀`, with Lagrange's remainder.
//!
//! For `x = c₀ + h` with `|h| ≤ H` on the box (the model's deviation,
//! remainder included) and `f` analytic on `[c₀ − H, c₀ + H]`:
//!
//! `f(x) = Σ_{k ≤ d} f⁽ᵏ⁾(c₀)/k!·hᵏ + f⁽ᵈ⁺¹⁾(ξ)/(d+1)!·hᵈ⁺¹`,
//!
//! the powers `hᵏ` computed as models, the coefficients `f⁽ᵏ⁾(c₀)/k!` as
//! MPFR intervals (their midpoints in the polynomial, radius·Hᵏ in the
//! remainder), and the last term bounded by
//! * `sin`, `cos`: `|f⁽ᵈ⁺¹⁾| ≤ 1`;
//! * `exp`: `f⁽ᵈ⁺¹⁾(ξ) ≤ exp(c₀ + H)`;
//! * `1/x`: the exact remainder `(−h)^{d+1}/(c₀^{d+1}(c₀ + h))`, at most
//!   `H^{d+1}/(|c₀|^{d+1}(|c₀| − H))` when `|c₀| > H` (otherwise the range
//!   may contain 0: no enclosure);
//! * `√x`: `|(1/2 choose d+1)|·(c₀ − H)^{1/2 − d − 1}`, when `c₀ > H`.

use std::ops::Div;

use rug::Float;
use rug::Rational;
use rug::float::{Constant, Round};
use trig_core::{Interval, Real, Ring};

use crate::rounding::{down, up};
use crate::taylor::TaylorModel;

/// `h¹, …, hᵈ` (index 0 unused: the constant 1).
fn powers(h: &TaylorModel, d: u32) -> Vec<TaylorModel> {
    let mut out = vec![h.int(1)];
    if d == 0 {
        return out;
    }
    out.push(h.clone());
    for k in 2..=d as usize {
        let next = out[k - 1].clone() * h;
        out.push(next);
    }
    out
}

fn midpoint_and_radius(a: &Interval) -> (Float, f64) {
    let prec = a.prec();
    let mid = Float::with_val(prec, a.lo() + a.hi()) / 2u32;
    let r1 = Float::with_val_round(prec, a.hi() - &mid, Round::Up).0;
    let r2 = Float::with_val_round(prec, &mid - a.lo(), Round::Up).0;
    let r = r1.max(&r2).to_f64_round(Round::Up);
    (mid, r)
}

/// `Σ aₖ hᵏ` plus `lagrange` in the remainder.
fn series(powers: &[TaylorModel], coefs: &[Interval], hb: f64, lagrange: f64) -> TaylorModel {
    let mut out = TaylorModel::zero(powers[0].space());
    let mut extra = lagrange;
    let mut hk = 1.0;
    for (k, a) in coefs.iter().enumerate() {
        if !a.is_finite() {
            out.fail();
            return out;
        }
        let (mid, r) = midpoint_and_radius(a);
        if k == 0 {
            out = out.shift(&mid);
        } else if hk != 0.0 {
            out.add_scaled(&powers[k], &mid);
        }
        extra = up(extra + up(r * hk));
        hk = up(hk * hb);
    }
    out.widen(extra);
    out
}

/// `H^{d+1}/(d+1)!` as an upper bound.
fn power_over_factorial(hb: f64, d: u32) -> f64 {
    let mut out = 1.0;
    for k in 1..=d + 1 {
        out = up(up(out * hb) / f64::from(k));
    }
    out
}

struct Expansion {
    c0: Interval,
    h: TaylorModel,
    hb: f64,
    d: u32,
}

fn expand(x: &TaylorModel) -> Option<Expansion> {
    if x.is_fault() {
        return None;
    }
    let prec = x.space().prec();
    let c = x.constant_term();
    let h = x.without_constant();
    let hb = h.deviation();
    hb.is_finite().then(|| Expansion {
        c0: Interval::from_ends(prec, c, c),
        h,
        hb,
        d: x.space().degree(),
    })
}

fn fault(x: &TaylorModel) -> TaylorModel {
    let mut m = x.clone();
    m.fail();
    m
}

/// `(sin x, cos x)`.
pub fn sin_cos(x: &TaylorModel) -> (TaylorModel, TaylorModel) {
    let Some(e) = expand(x) else {
        return (fault(x), fault(x));
    };
    let (s, c) = Real::sin_cos(&e.c0);
    let ps = powers(&e.h, if e.hb == 0.0 { 0 } else { e.d });
    let d = ps.len() as u32 - 1;
    let rest = if e.hb == 0.0 {
        0.0
    } else {
        power_over_factorial(e.hb, d)
    };
    // sin⁽ᵏ⁾/k! and cos⁽ᵏ⁾/k!: the cycle sin, cos, −sin, −cos over k!
    let mut sin_coefs: Vec<Interval> = Vec::new();
    let mut cos_coefs: Vec<Interval> = Vec::new();
    let (mut sv, mut cv) = (s, c);
    for k in 0..=d {
        if k > 0 {
            let kk = e.c0.int(i64::from(k));
            // (sin)' = cos, (cos)' = −sin, divided by k
            let next_s = cv.clone() / &kk;
            let next_c = -sv.clone() / &kk;
            (sv, cv) = (next_s, next_c);
        }
        sin_coefs.push(sv.clone());
        cos_coefs.push(cv.clone());
    }
    (
        series(&ps, &sin_coefs, e.hb, rest),
        series(&ps, &cos_coefs, e.hb, rest),
    )
}

/// `exp x`.
pub fn exp(x: &TaylorModel) -> TaylorModel {
    let Some(e) = expand(x) else {
        return fault(x);
    };
    let ec = Real::exp(&e.c0);
    let ps = powers(&e.h, if e.hb == 0.0 { 0 } else { e.d });
    let d = ps.len() as u32 - 1;
    let rest = if e.hb == 0.0 {
        0.0
    } else {
        let prec = x.space().prec();
        let top = Float::with_val_round(prec, e.c0.hi() + e.hb, Round::Up).0;
        let bound = Float::with_val_round(prec, top.exp_ref(), Round::Up)
            .0
            .to_f64_round(Round::Up);
        up(bound * power_over_factorial(e.hb, d))
    };
    let mut coefs: Vec<Interval> = vec![ec];
    for k in 1..=d {
        let next = coefs[k as usize - 1].clone() / &e.c0.int(i64::from(k));
        coefs.push(next);
    }
    series(&ps, &coefs, e.hb, rest)
}

/// `1/x`, or no enclosure when the range of `x` may contain 0.
pub fn recip(x: &TaylorModel) -> TaylorModel {
    let Some(e) = expand(x) else {
        return fault(x);
    };
    let prec = x.space().prec();
    let a = Float::with_val(prec, e.c0.lo().abs_ref()).to_f64_round(Round::Down);
    let m = a - up(e.hb);
    if !(m > 0.0 && m.is_finite()) {
        return fault(x);
    }
    let m = down(m);
    let ps = powers(&e.h, if e.hb == 0.0 { 0 } else { e.d });
    let d = ps.len() as u32 - 1;
    let rest = if e.hb == 0.0 {
        0.0
    } else {
        // 1/(c₀ + h) − Σ_{k ≤ d} (−h)ᵏ/c₀^{k+1} = (−h)^{d+1}/(c₀^{d+1}(c₀ + h)),
        // so |R| ≤ H^{d+1}/(|c₀|^{d+1}·m)
        let ratio = up(e.hb / a);
        let mut r = up(1.0 / m);
        for _ in 0..=d {
            r = up(r * ratio);
        }
        r
    };
    let inv = e.c0.int(1) / &e.c0;
    let mut coefs = Vec::new();
    let mut a_k = inv.clone();
    for k in 0..=d {
        coefs.push(if k % 2 == 0 {
            a_k.clone()
        } else {
            -a_k.clone()
        });
        a_k = a_k * &inv;
    }
    series(&ps, &coefs, e.hb, rest)
}

/// `√x`, or no enclosure when the range of `x` may reach 0 or below.
pub fn sqrt(x: &TaylorModel) -> TaylorModel {
    let Some(e) = expand(x) else {
        return fault(x);
    };
    let prec = x.space().prec();
    let m = e.c0.lo().to_f64_round(Round::Down) - up(e.hb);
    if !(m > 0.0 && m.is_finite()) {
        return fault(x);
    }
    let m = down(m);
    let Some(root) = e.c0.try_sqrt() else {
        return fault(x);
    };
    let ps = powers(&e.h, if e.hb == 0.0 { 0 } else { e.d });
    let d = ps.len() as u32 - 1;
    // (1/2 choose k), exactly
    let binom = |k: u32| -> Rational {
        (0..k).fold(Rational::from(1), |acc, j| {
            acc * (Rational::from((1, 2)) - Rational::from(j)) / Rational::from(j + 1)
        })
    };
    let rest = if e.hb == 0.0 {
        0.0
    } else {
        // |binom(1/2, d+1)|·H^{d+1}·m^{1/2−d−1}
        let b = binom(d + 1).abs().to_f64() * (1.0 + 1e-15);
        let mut r = up(b * up(1.0 / Float::with_val(prec, m).sqrt().to_f64_round(Round::Down)));
        let ratio = up(e.hb / m);
        for _ in 0..=d {
            r = up(r * ratio);
        }
        up(r * m)
    };
    let mut coefs = Vec::new();
    let mut pow = root.clone();
    for k in 0..=d {
        coefs.push(pow.clone() * &e.c0.rational(&binom(k)));
        pow = pow / &e.c0;
    }
    series(&ps, &coefs, e.hb, rest)
}

/// `a / b = a · (1/b)`, the reciprocal by its series ([`recip`]).
impl Div<&TaylorModel> for TaylorModel {
    type Output = TaylorModel;
    #[expect(
        clippy::suspicious_arithmetic_impl,
        reason = "a quotient of models is a product with the reciprocal"
    )]
    fn div(self, rhs: &TaylorModel) -> TaylorModel {
        self * &recip(rhs)
    }
}

impl Div<TaylorModel> for TaylorModel {
    type Output = TaylorModel;
    fn div(self, rhs: TaylorModel) -> TaylorModel {
        self / &rhs
    }
}

/// Taylor models are a [`Ring`] with the elementary functions of this
/// module: the same basis formulas evaluate on them.
impl Ring for TaylorModel {
    fn int(&self, n: i64) -> Self {
        TaylorModel::constant(self.space(), &Rational::from(n))
    }

    fn ratio(&self, num: i64, den: i64) -> Self {
        TaylorModel::constant(self.space(), &Rational::from((num, den)))
    }

    fn rational(&self, q: &Rational) -> Self {
        TaylorModel::constant(self.space(), q)
    }

    fn pi(&self) -> Self {
        let space = self.space();
        TaylorModel::rounded(space, Float::with_val(space.prec(), Constant::Pi))
    }

    /// Proved zero: every coefficient and the remainder are zero.
    fn is_zero(&self) -> bool {
        self.is_exact_zero()
    }

    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        Some(sin_cos(self))
    }

    fn try_exp(&self) -> Option<Self> {
        Some(exp(self))
    }

    fn try_sqrt(&self) -> Option<Self> {
        Some(sqrt(self))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::taylor::Space;
    use crate::testing::q;

    /// The model's range contains `f` at a grid of points of `[lo, hi]`.
    fn encloses(m: &TaylorModel, lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
        let r = m.range().expect("an enclosure");
        let (a, b) = (r.lo().to_f64(), r.hi().to_f64());
        for k in 0..=20 {
            let x = lo + (hi - lo) * f64::from(k) / 20.0;
            let v = f(x);
            assert!(
                a - 1e-12 <= v && v <= b + 1e-12,
                "{v} not in [{a}, {b}] at {x}"
            );
        }
        b - a
    }

    #[test]
    fn series_enclose_and_are_tight() {
        let s = Space::new(1, 6, 128);
        let x = TaylorModel::coordinate(&s, 0, &q(1, 2), &q(3, 2));
        let (sn, cs) = sin_cos(&x);
        let w = encloses(&sn, 0.5, 1.5, f64::sin);
        assert!(w < 0.85, "{w}");
        encloses(&cs, 0.5, 1.5, f64::cos);
        // sin² + cos² − 1 is tiny, unlike in interval arithmetic
        let one = sn.clone() * &sn + &(cs.clone() * &cs) - &x.int(1);
        let r = one.range().unwrap();
        assert!(r.width().to_f64() < 1e-3, "{:?}", r);
        encloses(&exp(&x), 0.5, 1.5, f64::exp);
        let inv = recip(&x);
        encloses(&inv, 0.5, 1.5, |v| 1.0 / v);
        encloses(&sqrt(&x), 0.5, 1.5, f64::sqrt);
        // x·(1/x) − 1 is tiny
        let r = (x.clone() * &inv - &x.int(1)).range().unwrap();
        assert!(r.width().to_f64() < 0.1, "{:?}", r);
    }

    #[test]
    fn the_variable_beside_sin_cancels() {
        // α − sin α on [1/4, 1/2]: positive, and the model proves it
        let s = Space::new(1, 6, 128);
        let a = TaylorModel::coordinate(&s, 0, &q(1, 4), &q(1, 2));
        let f = a.clone() - &sin_cos(&a).0;
        let r = f.range().unwrap();
        assert!(*r.lo() > 0, "{:?}", r);
        encloses(&f, 0.25, 0.5, |v| v - v.sin());
    }

    #[test]
    fn divisions_by_ranges_with_zero_have_no_enclosure() {
        let s = Space::new(1, 4, 64);
        let x = TaylorModel::coordinate(&s, 0, &q(-1, 2), &q(1, 2));
        assert!(recip(&x).is_fault());
        assert!(sqrt(&x).is_fault());
        let y = x.int(1) / &x;
        assert!(y.range().is_none());
    }
}
