//! Taylor models over MPFR: a polynomial `P(u)` in the box's normalised
//! variables `u ∈ [−1, 1]ⁿ` with MPFR coefficients, and a remainder
//! radius `r`, such that the function lies in `P(u) + [−r, r]` at every
//! point of the box (Makino & Berz, "Taylor models and other validated
//! functional inclusion methods", Int. J. Pure Appl. Math. 4 (2003)
//! 379–456).
//!
//! Why: interval evaluation forgets that `sin α·cos t − cos α·sin t` is
//! `sin(α − t)`, so on a box of width `w` it overestimates by `O(w)` times
//! the size of the cancelling terms (the dependency problem). A Taylor
//! model carries the dependency in its polynomial part: the overestimation
//! is `O(w^{d+1})` for degree `d`.
//!
//! Rigour, operation by operation (`u = 2^{−prec}`, `γₘ = mu/(1 − mu)`):
//! * coefficients are rounded to nearest; a sum of `m` products computed
//!   by recursive summation errs by at most `γₘ·Σ|xᵢyᵢ|` (Higham, Accuracy
//!   and Stability of Numerical Algorithms, 2nd ed., (3.5)), so a product of
//!   models adds `γₘ·‖P₁‖₁‖P₂‖₁` to the remainder, `m` the number of terms;
//! * terms of degree above `d` are dropped with `|cᵢcⱼuᵅ⁺ᵝ| ≤ |cᵢcⱼ|`;
//! * `(P₁ + I₁)(P₂ + I₂) ⊂ P₁P₂ + [−(|P₁|r₂ + |P₂|r₁ + r₁r₂), …]` with
//!   `|P| ≤ ‖P‖₁` on the unit box;
//! * every bound is an f64 computed with upward rounding (`rounding::up`).
//!
//! Constants are made from an existing model ([`trig_core::Ring`]): the
//! models of one box share their [`Space`]. Elementary functions of models
//! are in [`crate::elementary`], with the [`trig_core::Ring`] implementation.

use std::cell::{Cell, RefCell};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::rc::Rc;

use rug::float::Round;
use rug::ops::NegAssign;
use rug::{Assign, Float, Rational};
use trig_core::Interval;

use crate::bernstein_bound::{Span, conversion};
use crate::rounding::up;

/// The monomials of total degree at most `degree` in `vars` variables, the
/// table of their products, and the count of operations done in them.
pub struct Space {
    vars: usize,
    degree: u32,
    prec: u32,
    /// Exponent vectors, graded (degree 0 first).
    exps: Vec<Vec<u32>>,
    /// `product[i·M + j]`: the index of monomial `i` times monomial `j`,
    /// when its degree is at most `degree`.
    product: Vec<Option<u32>>,
    /// True when every exponent is even (the monomial is `≥ 0` on the box).
    even: Vec<bool>,
    /// Power-to-Bernstein coefficients ([`crate::bernstein_bound`]).
    to_bernstein: Vec<Vec<Span>>,
    /// Operations on models of this space (products and series), the
    /// engine's unit of work.
    ops: Cell<u64>,
    /// Coefficient vectors of dropped models, reused by new ones: a model
    /// is made and dropped per operation, and one heap allocation per
    /// MPFR coefficient was a third of the engine's time.
    pool: RefCell<Vec<Vec<Float>>>,
}

impl fmt::Debug for Space {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Space({} variables, degree {}, {} bits)",
            self.vars, self.degree, self.prec
        )
    }
}

impl Space {
    /// The space of `vars` variables, degree `degree`, `prec`-bit
    /// coefficients, made once per thread.
    pub fn new(vars: usize, degree: u32, prec: u32) -> Rc<Space> {
        thread_local! {
            static SPACES: std::cell::RefCell<Vec<Rc<Space>>> = const { std::cell::RefCell::new(Vec::new()) };
        }
        SPACES.with(|spaces| {
            let mut spaces = spaces.borrow_mut();
            if let Some(s) = spaces
                .iter()
                .find(|s| s.vars == vars && s.degree == degree && s.prec == prec)
            {
                return s.clone();
            }
            let s = Space::build(vars, degree, prec);
            spaces.push(s.clone());
            s
        })
    }

    fn build(vars: usize, degree: u32, prec: u32) -> Rc<Space> {
        let mut exps: Vec<Vec<u32>> = Vec::new();
        for total in 0..=degree {
            let mut e = vec![0u32; vars];
            push_with_total(&mut exps, &mut e, 0, total);
        }
        let m = exps.len();
        let mut product = vec![None; m * m];
        for i in 0..m {
            for j in 0..m {
                let sum: Vec<u32> = exps[i].iter().zip(&exps[j]).map(|(a, b)| a + b).collect();
                if sum.iter().sum::<u32>() <= degree {
                    product[i * m + j] = exps.iter().position(|x| *x == sum).map(|k| k as u32);
                }
            }
        }
        let even = exps.iter().map(|e| e.iter().all(|k| k % 2 == 0)).collect();
        Rc::new(Space {
            vars,
            degree,
            prec,
            exps,
            product,
            even,
            to_bernstein: conversion(degree),
            ops: Cell::new(0),
            pool: RefCell::new(Vec::new()),
        })
    }

    /// Number of monomials.
    pub fn len(&self) -> usize {
        self.exps.len()
    }

    /// True for the space of no monomials (never: degree 0 has one).
    pub fn is_empty(&self) -> bool {
        self.exps.is_empty()
    }

    /// The degree of the models.
    pub fn degree(&self) -> u32 {
        self.degree
    }

    /// Coefficient precision in bits.
    pub fn prec(&self) -> u32 {
        self.prec
    }

    /// Operations done so far on models of this space.
    pub fn ops(&self) -> u64 {
        self.ops.get()
    }

    fn count(&self) {
        self.ops.set(self.ops.get() + 1);
    }

    /// A coefficient vector of the space's length and precision whose
    /// values are to be overwritten: a recycled one, or a new one of zeros.
    fn coefficients(&self) -> Vec<Float> {
        self.pool
            .borrow_mut()
            .pop()
            .unwrap_or_else(|| vec![Float::new(self.prec); self.len()])
    }

    /// Takes back the coefficients of a dropped model when they have the
    /// space's length and precision (a model may hold a coefficient of
    /// another precision, which a recycled vector must not pass on).
    fn recycle(&self, coef: Vec<Float>) {
        const KEPT: usize = 64;
        let mut pool = self.pool.borrow_mut();
        if pool.len() < KEPT
            && coef.len() == self.len()
            && coef.iter().all(|c| c.prec() == self.prec)
        {
            pool.push(coef);
        }
    }

    /// `γₘ` for sums of `m` rounded terms, as an f64 upper bound.
    fn gamma(&self, m: usize) -> f64 {
        let mu = m as f64 * (-(self.prec as f64)).exp2();
        up(mu / (1.0 - mu) * (1.0 + f64::EPSILON))
    }
}

fn push_with_total(out: &mut Vec<Vec<u32>>, e: &mut [u32], at: usize, left: u32) {
    if at + 1 == e.len() {
        e[at] = left;
        out.push(e.to_vec());
        return;
    }
    if e.is_empty() {
        if left == 0 {
            out.push(Vec::new());
        }
        return;
    }
    for k in (0..=left).rev() {
        e[at] = k;
        push_with_total(out, e, at + 1, left - k);
    }
    e[at] = 0;
}

/// An upper bound of `|x|` as an f64.
pub fn abs_up(x: &Float) -> f64 {
    if x.is_nan() {
        return f64::INFINITY;
    }
    // no copy of `x`: |x| rounded up is −(x rounded down) for x < 0
    if x.is_sign_negative() {
        -x.to_f64_round(Round::Down)
    } else {
        x.to_f64_round(Round::Up)
    }
}

/// A Taylor model on the unit box of its [`Space`] (see the module docs).
pub struct TaylorModel {
    space: Rc<Space>,
    coef: Vec<Float>,
    /// The remainder lies in `[−rad, rad]`.
    rad: f64,
    /// No enclosure: a division by a model whose range may contain zero, a
    /// series outside its domain, an overflow.
    fault: bool,
}

impl Clone for TaylorModel {
    fn clone(&self) -> TaylorModel {
        let mut coef = self.space.coefficients();
        for (to, from) in coef.iter_mut().zip(&self.coef) {
            if to.prec() == from.prec() {
                to.assign(from);
            } else {
                *to = from.clone();
            }
        }
        TaylorModel {
            space: self.space.clone(),
            coef,
            rad: self.rad,
            fault: self.fault,
        }
    }
}

impl Drop for TaylorModel {
    fn drop(&mut self) {
        self.space.recycle(std::mem::take(&mut self.coef));
    }
}

impl fmt::Debug for TaylorModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.fault {
            return write!(f, "TaylorModel(no enclosure)");
        }
        write!(
            f,
            "TaylorModel({} + … ± {:e}, range {:?})",
            self.coef[0].to_f64(),
            self.rad,
            self.range().map(|i| (i.lo().to_f64(), i.hi().to_f64()))
        )
    }
}

impl TaylorModel {
    /// The constant `q` (rounded to nearest, the error in the remainder).
    pub fn constant(space: &Rc<Space>, q: &Rational) -> TaylorModel {
        let mut m = TaylorModel::zero(space);
        let (v, o) = Float::with_val_round(space.prec, q, Round::Nearest);
        if o != Ordering::Equal {
            m.rad = ulp(&v);
        }
        m.coef[0] = v;
        m
    }

    /// The model of the float `v` rounded to nearest: `v` with one unit in
    /// its last place as remainder.
    pub fn rounded(space: &Rc<Space>, v: Float) -> TaylorModel {
        let mut m = TaylorModel::zero(space);
        m.rad = ulp(&v);
        m.coef[0] = v;
        m
    }

    /// Proved zero: every coefficient and the remainder are zero.
    pub fn is_exact_zero(&self) -> bool {
        !self.fault && self.rad == 0.0 && self.coef.iter().all(|c| c.is_zero())
    }

    /// The exact zero of the space.
    pub fn zero(space: &Rc<Space>) -> TaylorModel {
        let mut coef = space.coefficients();
        for c in &mut coef {
            c.assign(0u32);
        }
        TaylorModel {
            space: space.clone(),
            coef,
            rad: 0.0,
            fault: false,
        }
    }

    /// The interval `[lo, hi]` as a constant model (midpoint and radius).
    pub fn from_interval(space: &Rc<Space>, x: &Interval) -> TaylorModel {
        let mut m = TaylorModel::zero(space);
        if !trig_core::Real::is_finite(x) {
            m.fault = true;
            return m;
        }
        let prec = space.prec;
        let mid = Float::with_val(prec, x.lo() + x.hi()) / 2u32;
        let r = Float::with_val_round(prec, x.hi() - &mid, Round::Up)
            .0
            .max(&Float::with_val_round(prec, &mid - x.lo(), Round::Up).0);
        m.rad = up(r.to_f64_round(Round::Up));
        m.coef[0] = mid;
        m
    }

    /// The coordinate `x = lo + (hi − lo)(u + 1)/2` of variable `k`: the
    /// box side `[lo, hi]` mapped onto `u ∈ [−1, 1]`.
    pub fn coordinate(space: &Rc<Space>, k: usize, lo: &Rational, hi: &Rational) -> TaylorModel {
        let mid = Rational::from(lo + hi) / 2u32;
        let half = Rational::from(hi - lo) / 2u32;
        let mut m = TaylorModel::constant(space, &mid);
        if half != 0 {
            let (v, o) = Float::with_val_round(space.prec, &half, Round::Nearest);
            if o != Ordering::Equal {
                m.rad = up(m.rad + ulp(&v));
            }
            let index = space
                .exps
                .iter()
                .position(|e| e.iter().enumerate().all(|(i, x)| *x == u32::from(i == k)))
                .expect("a variable of the space");
            m.coef[index] = v;
        }
        m
    }

    /// The space of the model.
    pub fn space(&self) -> &Rc<Space> {
        &self.space
    }

    /// True when the model has no enclosure.
    pub fn is_fault(&self) -> bool {
        self.fault
    }

    /// The constant coefficient.
    pub fn constant_term(&self) -> &Float {
        &self.coef[0]
    }

    /// The remainder radius.
    pub fn remainder(&self) -> f64 {
        self.rad
    }

    /// `‖P − P(0)‖₁`, an upper bound of `|P(u) − P(0)|` on the box.
    fn spread(&self) -> f64 {
        self.coef[1..]
            .iter()
            .filter(|c| !c.is_zero())
            .fold(0.0, |acc, c| up(acc + abs_up(c)))
    }

    /// `‖P‖₁`.
    fn norm(&self) -> f64 {
        up(abs_up(&self.coef[0]) + self.spread())
    }

    /// An upper bound of `|x − x(0)|` on the box, remainder included: the
    /// radius of the model around its constant term.
    pub fn deviation(&self) -> f64 {
        up(self.spread() + self.rad)
    }

    /// The model with its constant term removed (`x − x(0)`).
    pub fn without_constant(&self) -> TaylorModel {
        let mut m = self.clone();
        if m.coef[0].prec() == self.space.prec {
            m.coef[0].assign(0u32);
        } else {
            m.coef[0] = Float::new(self.space.prec);
        }
        m
    }

    /// The enclosure of the model's range on the box: the range of the
    /// polynomial (the tighter of its Bernstein bound and the sum of its
    /// terms, `uᵅ ∈ [0, 1]` for even `α`, `[−1, 1]` otherwise) widened by the
    /// remainder; `None` without an enclosure.
    pub fn range(&self) -> Option<Interval> {
        if self.fault {
            return None;
        }
        let (mut below, mut above) = (0.0, 0.0);
        for (i, c) in self.coef.iter().enumerate().skip(1) {
            if c.is_zero() {
                continue;
            }
            let a = abs_up(c);
            if self.space.even[i] {
                if *c > 0 {
                    above = up(above + a);
                } else {
                    below = up(below + a);
                }
            } else {
                above = up(above + a);
                below = up(below + a);
            }
        }
        if !(below.is_finite() && above.is_finite() && self.rad.is_finite()) {
            return None;
        }
        let prec = self.space.prec;
        let c0 = &self.coef[0];
        let mut lo = Float::with_val_round(prec, c0 - below, Round::Down).0;
        let mut hi = Float::with_val_round(prec, c0 + above, Round::Up).0;
        if self.space.vars > 0 && self.space.degree > 1 {
            let spans: Vec<Span> = self.coef.iter().map(Span::float).collect();
            let b = crate::bernstein_bound::range(
                &spans,
                &self.space.exps,
                self.space.vars,
                self.space.degree,
                &self.space.to_bernstein,
            );
            if b.lo.is_finite() && b.lo > lo {
                lo = Float::with_val(prec, b.lo);
            }
            if b.hi.is_finite() && b.hi < hi {
                hi = Float::with_val(prec, b.hi);
            }
        }
        let lo = Float::with_val_round(prec, &lo - self.rad, Round::Down).0;
        let hi = Float::with_val_round(prec, &hi + self.rad, Round::Up).0;
        Some(Interval::from_ends(prec, &lo, &hi))
    }

    /// `c·self` for an MPFR constant `c` (exact input).
    pub fn scale(&self, c: &Float) -> TaylorModel {
        if self.fault {
            return self.clone();
        }
        let mut out = self.clone();
        for x in &mut out.coef {
            if !x.is_zero() {
                *x *= c;
            }
        }
        let ac = abs_up(c);
        let rounding = up(self.space.gamma(1) * up(ac * self.norm()));
        out.rad = up(up(self.rad * ac) + rounding);
        out.check();
        out
    }

    /// `self += c·p` for an MPFR constant `c` (exact input).
    pub fn add_scaled(&mut self, p: &TaylorModel, c: &Float) {
        if self.fault || p.fault {
            self.fault = true;
            return;
        }
        let ac = abs_up(c);
        let rounding = up(self.space.gamma(2) * up(up(ac * p.norm()) + self.norm()));
        let mut tmp = Float::new(self.space.prec);
        for (x, y) in self.coef.iter_mut().zip(&p.coef) {
            if y.is_zero() {
                continue;
            }
            tmp.assign(y * c);
            *x += &tmp;
        }
        self.rad = up(up(self.rad + up(p.rad * ac)) + rounding);
        self.check();
    }

    /// `self + c` for an MPFR constant.
    pub fn shift(&self, c: &Float) -> TaylorModel {
        let mut out = self.clone();
        let (v, o) = Float::with_val_round(self.space.prec, &self.coef[0] + c, Round::Nearest);
        if o != Ordering::Equal {
            out.rad = up(out.rad + ulp(&v));
        }
        out.coef[0] = v;
        out.check();
        out
    }

    /// Widens the remainder by `r ≥ 0`.
    pub fn widen(&mut self, r: f64) {
        self.rad = up(self.rad + r);
        self.check();
    }

    /// Marks the model as without enclosure.
    pub fn fail(&mut self) {
        self.fault = true;
    }

    fn check(&mut self) {
        if !self.rad.is_finite() || self.coef.iter().any(|c| !c.is_finite()) {
            self.fault = true;
        }
    }

    fn faulty(&self) -> TaylorModel {
        let mut m = self.clone();
        m.fault = true;
        m
    }

    fn add_signed(mut self, rhs: &TaylorModel, negate: bool) -> TaylorModel {
        if self.fault || rhs.fault {
            return self.faulty();
        }
        let rounding = up(self.space.gamma(1) * up(self.norm() + rhs.norm()));
        for (x, y) in self.coef.iter_mut().zip(&rhs.coef) {
            if y.is_zero() {
                continue;
            }
            if negate {
                *x -= y;
            } else {
                *x += y;
            }
        }
        self.rad = up(up(self.rad + rhs.rad) + rounding);
        self.check();
        self
    }

    fn product(&self, rhs: &TaylorModel) -> TaylorModel {
        if self.fault || rhs.fault {
            return self.faulty();
        }
        let space = &self.space;
        space.count();
        let m = space.len();
        let mut out = TaylorModel::zero(space);
        let mut tmp = Float::new(space.prec);
        let mut truncated = 0.0;
        let mut terms = vec![0usize; m];
        for (i, a) in self.coef.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            let abs_a = abs_up(a);
            for (j, b) in rhs.coef.iter().enumerate() {
                if b.is_zero() {
                    continue;
                }
                match space.product[i * m + j] {
                    Some(k) => {
                        tmp.assign(a * b);
                        out.coef[k as usize] += &tmp;
                        terms[k as usize] += 1;
                    }
                    None => truncated = up(truncated + up(abs_a * abs_up(b))),
                }
            }
        }
        let (na, nb) = (self.norm(), rhs.norm());
        let most = terms.iter().max().copied().unwrap_or(0) + 1;
        let rounding = up(space.gamma(most) * up(na * nb));
        let cross = up(up(na * rhs.rad) + up(nb * self.rad));
        out.rad = up(up(up(truncated + cross) + up(self.rad * rhs.rad)) + rounding);
        out.check();
        out
    }
}

/// One unit in the last place of `x` (an upper bound of the error of
/// rounding to nearest to `x`'s precision).
pub fn ulp(x: &Float) -> f64 {
    match x.get_exp() {
        Some(e) => {
            let k = i64::from(e) - i64::from(x.prec());
            if k < -1074 {
                f64::from_bits(1)
            } else if k > 1023 {
                f64::INFINITY
            } else {
                (k as f64).exp2()
            }
        }
        None if x.is_zero() => 0.0,
        None => f64::INFINITY,
    }
}

macro_rules! by_ref {
    ($Trait:ident, $method:ident, $body:expr) => {
        impl $Trait<&TaylorModel> for TaylorModel {
            type Output = TaylorModel;
            fn $method(self, rhs: &TaylorModel) -> TaylorModel {
                $body(self, rhs)
            }
        }
        impl $Trait<TaylorModel> for TaylorModel {
            type Output = TaylorModel;
            fn $method(self, rhs: TaylorModel) -> TaylorModel {
                $body(self, &rhs)
            }
        }
    };
}

by_ref!(Add, add, |a: TaylorModel, b: &TaylorModel| a
    .add_signed(b, false));
by_ref!(Sub, sub, |a: TaylorModel, b: &TaylorModel| a
    .add_signed(b, true));
by_ref!(Mul, mul, |a: TaylorModel, b: &TaylorModel| a.product(b));

impl Neg for TaylorModel {
    type Output = TaylorModel;
    /// Exact: every coefficient negated.
    fn neg(mut self) -> TaylorModel {
        for c in &mut self.coef {
            c.neg_assign();
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::q;
    use trig_core::{Real, Ring};

    /// `abs_up(x) ≥ |x|` exactly, and it is the nearest f64 above: for
    /// values between f64s of both signs, ±0, and beyond the f64 range.
    #[test]
    fn abs_up_bounds_the_magnitude_from_above() {
        let third = Float::with_val(200, 1) / 3u32;
        let huge = Float::with_val(200, Float::parse("1e400").expect("a number"));
        for x in [
            third.clone(),
            -third,
            Float::with_val(200, 0),
            -huge.clone(),
            huge,
        ] {
            let a = abs_up(&x);
            let magnitude = x.clone().abs();
            assert!(Float::with_val(200, a) >= magnitude, "{x}: {a}");
            if a.is_finite() && a > 0.0 {
                assert!(Float::with_val(200, a.next_down()) < magnitude, "{x}: {a}");
            }
        }
        assert_eq!(abs_up(&Float::with_val(53, -0.5)), 0.5);
        assert_eq!(abs_up(&Float::with_val(53, f64::NAN)), f64::INFINITY);
    }

    fn range(m: &TaylorModel) -> (f64, f64) {
        let r = m.range().expect("an enclosure");
        (r.lo().to_f64(), r.hi().to_f64())
    }

    #[test]
    fn spaces_list_graded_monomials() {
        let s = Space::new(2, 3, 64);
        assert_eq!(s.len(), 10);
        assert_eq!(s.exps[0], vec![0, 0]);
        // u0 · u1 lies in the space, u0³ · u1 does not
        let i = s.exps.iter().position(|e| *e == vec![1, 0]).unwrap();
        let j = s.exps.iter().position(|e| *e == vec![0, 1]).unwrap();
        let k = s.exps.iter().position(|e| *e == vec![3, 0]).unwrap();
        assert!(s.product[i * s.len() + j].is_some());
        assert!(s.product[k * s.len() + j].is_none());
        assert_eq!(Space::new(0, 4, 64).len(), 1);
    }

    #[test]
    fn dependency_cancels() {
        let s = Space::new(1, 4, 128);
        let x = TaylorModel::coordinate(&s, 0, &q(1, 3), &q(2, 3));
        // x − x = 0 and (x + 1)² − x² − 2x − 1 = 0 up to rounding
        let zero = x.clone() - &x;
        let (lo, hi) = range(&zero);
        assert!(lo <= 0.0 && hi >= 0.0 && hi - lo < 1e-30, "{lo} {hi}");
        let one = x.int(1);
        let y =
            (x.clone() + &one) * &(x.clone() + &one) - &(x.clone() * &x) - &(x.int(2) * &x) - &one;
        let (lo, hi) = range(&y);
        assert!(lo <= 0.0 && hi >= 0.0 && hi - lo < 1e-30, "{lo} {hi}");
        // interval arithmetic on the same expression is wide
        let i = Interval::from_ends(
            128,
            &(Float::with_val(128, 1) / 3u32),
            &(Float::with_val(128, 2) / 3u32),
        );
        let w = (i.clone() + &i.int(1)) * &(i.clone() + &i.int(1)) - &(i.clone() * &i);
        assert!(w.width().to_f64() > 0.5);
    }

    #[test]
    fn truncation_keeps_the_enclosure() {
        // x⁵ on [−1, 1] with degree 2: the terms above degree 2 go to the
        // remainder, and the range still holds ±1
        let s = Space::new(1, 2, 64);
        let x = TaylorModel::coordinate(&s, 0, &q(-1, 1), &q(1, 1));
        let x5 = x.powi(5);
        let (lo, hi) = range(&x5);
        assert!(lo <= -1.0 && hi >= 1.0);
        assert!(x5.remainder() >= 1.0);
        // x² has an even monomial: range [0, 1]
        let (lo, hi) = range(&(x.clone() * &x));
        assert!(
            (-1e-15..=0.0).contains(&lo) && (1.0..1.0 + 1e-15).contains(&hi),
            "{lo} {hi}"
        );
    }

    #[test]
    fn constants_carry_their_rounding() {
        let s = Space::new(1, 3, 64);
        let third = TaylorModel::constant(&s, &q(1, 3));
        assert!(third.remainder() > 0.0);
        let r = third.range().unwrap();
        assert!(
            *r.lo() < Float::with_val(200, 1) / 3u32 && *r.hi() > Float::with_val(200, 1) / 3u32
        );
        assert!(TaylorModel::constant(&s, &q(1, 4)).remainder() == 0.0);
        let pi = third.pi();
        let r = pi.range().unwrap();
        assert!(r.lo().to_f64() <= std::f64::consts::PI && r.hi().to_f64() >= std::f64::consts::PI);
        assert!(!pi.is_fault());
        assert!(third.int(0).is_zero() && !third.is_zero());
        assert!((Real::to_f64(&r) - std::f64::consts::PI).abs() < 1e-15);
    }
}
