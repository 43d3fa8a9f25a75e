//! Exact functions in the coordinates of the branch and bound.
//!
//! The variable is normalised, `x = a(p) + L(p)·τ` with `τ ∈ [0, 1]`, and
//! each parameter is a coordinate (`π·y` on a π axis). A function of the
//! box coordinates is `Σ coef(τ)·sym` ([`BoxFunction`]): exact values with
//! polynomial factors in `τ` from the chain rule (`∂τ = L·∂x`,
//! `∂pᵢ = ∂pᵢ|ₓ + (aᵢ + Lᵢτ)·∂x`), so every derivative is exact. On a box
//! it is enclosed by Taylor models ([`crate::enclosure`]) intersected with
//! plain interval evaluation (exact at a face where a model keeps a
//! rounding remainder); on a face of the region it is decided exactly
//! whether it vanishes identically.

use std::cell::RefCell;
use std::rc::Rc;

use rug::float::Round;
use rug::{Float, Rational};
use trig_core::{Affine, Atoms, Domain, Interval, Ring};
use trig_symbolic::Sym;

use crate::atoms::{ParamAtom, d_param, d_variable, param_atoms, value};
use crate::enclosure::{BoxAtoms, DEGREE};

/// Working precision of the plain interval enclosures (bits).
const PREC: u32 = 128;

/// A parameter's set: `[lo, hi]` with open ends where flagged; with `pi`
/// the ends are multiples of π (the parameter is `π·y`, `y ∈ [lo, hi]`).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub lo: Rational,
    pub hi: Rational,
    pub lo_open: bool,
    pub hi_open: bool,
    pub pi: bool,
}

/// `Σ coef(τ)·sym`: an exact function of the box coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxFunction {
    terms: Vec<Term>,
}

#[derive(Debug, Clone, PartialEq)]
struct Term {
    coef: Vec<Rational>,
    sym: Sym,
}

impl BoxFunction {
    /// True when the function is identically zero (no terms).
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// `−f`.
    pub fn negated(&self) -> BoxFunction {
        BoxFunction {
            terms: self
                .terms
                .iter()
                .map(|t| Term {
                    coef: t.coef.clone(),
                    sym: -t.sym.clone(),
                })
                .collect(),
        }
    }
}

/// A box and the atoms on it.
type LastBox<'a> = (Vec<(Rational, Rational)>, Rc<BoxAtoms<'a>>);

/// The coordinates of a domain and its parameter axes.
#[derive(Debug)]
pub struct Coordinates<'a> {
    pub domain: &'a Domain,
    pub axes: &'a [Axis],
    atoms: Vec<ParamAtom>,
    /// The atoms of the last box enclosed (a box is enclosed for a
    /// function and its derivatives in turn).
    last: RefCell<Option<LastBox<'a>>>,
}

fn float(q: &Rational, round: Round) -> Float {
    Float::with_val_round(PREC, q, round).0
}

fn interval(lo: &Rational, hi: &Rational) -> Interval {
    Interval::from_ends(PREC, &float(lo, Round::Down), &float(hi, Round::Up))
}

fn poly_mul(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::new(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += Rational::from(x * y);
        }
    }
    out
}

fn poly_derivative(a: &[Rational]) -> Vec<Rational> {
    if a.len() <= 1 {
        return vec![Rational::new()];
    }
    a.iter()
        .enumerate()
        .skip(1)
        .map(|(k, q)| Rational::from(q * k as u32))
        .collect()
}

fn poly_at(a: &[Rational], x: &Rational) -> Rational {
    a.iter().rev().fold(Rational::new(), |acc, q| acc * x + q)
}

impl<'a> Coordinates<'a> {
    /// The coordinates of `domain` with one axis per parameter.
    pub fn new(domain: &'a Domain, axes: &'a [Axis]) -> Coordinates<'a> {
        Coordinates {
            domain,
            axes,
            atoms: param_atoms(domain),
            last: RefCell::new(None),
        }
    }

    /// `f` as a function of the coordinates.
    pub fn function(&self, f: &Sym) -> BoxFunction {
        BoxFunction {
            terms: if f.is_zero() {
                Vec::new()
            } else {
                vec![Term {
                    coef: vec![Rational::from(1)],
                    sym: f.clone(),
                }]
            },
        }
    }

    /// `a(p)`, `L(p) = b(p) − a(p)` as exact values in the parameters.
    fn start_and_length(&self) -> (Sym, Sym) {
        let p: Vec<Sym> = self
            .domain
            .param_names
            .iter()
            .map(|n| Sym::var(n))
            .collect();
        let a = self.domain.start.eval(&Sym::one(), &p);
        let b = self.domain.end.eval(&Sym::one(), &p);
        (a.clone(), b - &a)
    }

    /// The enclosure of `e` on the box `[lo, hi]` (coordinate 0 is `τ`):
    /// by Taylor models ([`crate::enclosure`]), by plain intervals when the
    /// models have none.
    pub fn enclose(&self, e: &BoxFunction, bx: &[(Rational, Rational)]) -> Option<Interval> {
        let by_models = self
            .box_atoms(bx)
            .and_then(|atoms| atoms.eval_terms(e.terms.iter().map(|t| (t.coef.as_slice(), &t.sym))))
            .and_then(|m| m.range());
        let decided = |v: &Interval| *v.lo() >= 0 || *v.hi() < 0;
        match by_models {
            Some(v) if decided(&v) => Some(v),
            // both enclose: their intersection does (plain intervals are
            // exact at a face where a model keeps a rounding remainder)
            Some(v) => match self.enclose_by_intervals(e, bx) {
                Some(w) => Some(Interval::from_ends(
                    PREC,
                    &v.lo().clone().max(w.lo()),
                    &v.hi().clone().min(w.hi()),
                )),
                None => Some(v),
            },
            None => self.enclose_by_intervals(e, bx),
        }
    }

    /// The atoms of the box as Taylor models (those of the last box kept).
    fn box_atoms(&self, bx: &[(Rational, Rational)]) -> Option<Rc<BoxAtoms<'a>>> {
        if let Some((b, atoms)) = self.last.borrow().as_ref() {
            if b.as_slice() == bx {
                return Some(atoms.clone());
            }
        }
        let pi: Vec<bool> = self.axes.iter().map(|a| a.pi).collect();
        let atoms = Rc::new(BoxAtoms::new(self.domain, &self.atoms, &pi, bx, DEGREE)?);
        *self.last.borrow_mut() = Some((bx.to_vec(), atoms.clone()));
        Some(atoms)
    }

    /// The enclosure of `e` by interval evaluation of its exact formula.
    fn enclose_by_intervals(
        &self,
        e: &BoxFunction,
        bx: &[(Rational, Rational)],
    ) -> Option<Interval> {
        let tau = interval(&bx[0].0, &bx[0].1);
        let p = self.params(&tau, &bx[1..]);
        let d = self.domain;
        let a = d.start_value(&tau, &p);
        let x = a.clone() + &((d.end_value(&tau, &p) - &a) * &tau);
        let theta = x.clone() * &d.angle_rate(&tau);
        let (s, c) = theta.try_sin_cos()?;
        let ex = match &d.exp {
            Some(k) => (x.clone() * &tau.rational(k)).try_exp()?,
            None => tau.int(1),
        };
        let atoms = Atoms { s, c, t: x, e: ex };
        let mut sum = tau.int(0);
        for term in &e.terms {
            let coef = term
                .coef
                .iter()
                .rev()
                .fold(tau.int(0), |acc, q| acc * &tau + &tau.rational(q));
            let v = term
                .sym
                .eval(&tau, &|n| value(n, d, &atoms, &p, &self.atoms))
                .ok()?;
            sum = sum + &(coef * &v);
        }
        trig_core::Real::is_finite(&sum).then_some(sum)
    }

    /// The parameters on the box's coordinates (`π·y` on a π axis).
    fn params(&self, like: &Interval, coords: &[(Rational, Rational)]) -> Vec<Interval> {
        coords
            .iter()
            .zip(self.axes)
            .map(|((l, h), a)| {
                let y = interval(l, h);
                if a.pi { y * &like.pi() } else { y }
            })
            .collect()
    }

    /// `∂/∂(coordinate k)` of `e` (`k = 0` is `τ`).
    pub fn derivative(&self, e: &BoxFunction, k: usize) -> BoxFunction {
        let (_, length) = self.start_and_length();
        let mut out: Vec<Term> = Vec::new();
        let mut push = |coef: Vec<Rational>, sym: Sym| {
            if sym.is_zero() || coef.iter().all(|q| *q == 0) {
                return;
            }
            match out.iter_mut().find(|t| t.coef == coef) {
                Some(t) => t.sym = t.sym.clone() + &sym,
                None => out.push(Term { coef, sym }),
            }
        };
        for t in &e.terms {
            let dx = d_variable(&t.sym, self.domain);
            if k == 0 {
                push(poly_derivative(&t.coef), t.sym.clone());
                push(t.coef.clone(), length.clone() * &dx);
            } else {
                let i = k - 1;
                // ∂x/∂pᵢ = aᵢ + Lᵢτ
                let coef_of = |a: &Affine| {
                    a.params
                        .iter()
                        .find(|(j, _)| *j == i)
                        .map_or_else(Rational::new, |(_, q)| q.clone())
                };
                let ai = coef_of(&self.domain.start);
                let li = Rational::from(&coef_of(&self.domain.end) - &ai);
                push(t.coef.clone(), d_param(&t.sym, self.domain, i, &self.atoms));
                push(poly_mul(&t.coef, &[ai, li]), dx);
            }
        }
        BoxFunction { terms: out }
    }

    /// `e` exactly zero on the face `coordinate k = v` of the box `bx`:
    /// with that coordinate and every degenerate side of the box pinned
    /// (`τ` only at 0 or 1), the rest formal. The variable's atoms are
    /// exact at a pinned `τ`, or where the domain shrinks to a point; the
    /// parameters' atoms must be exact at their pinned values (otherwise
    /// `false`). Zero as a formal expression in what stays free is zero
    /// for every value of it, so `true` is a proof.
    pub fn zero_on_face(
        &self,
        e: &BoxFunction,
        bx: &[(Rational, Rational)],
        k: usize,
        v: &Rational,
    ) -> bool {
        let pinned = |j: usize| -> Option<Rational> {
            if j == k {
                Some(v.clone())
            } else if bx[j].0 == bx[j].1 {
                Some(bx[j].0.clone())
            } else {
                None
            }
        };
        let tau = pinned(0).filter(|t| *t == 0 || *t == 1);
        let params: Vec<Option<Rational>> = (1..bx.len()).map(pinned).collect();
        let vars: Vec<Sym> = self
            .domain
            .param_names
            .iter()
            .map(|n| Sym::var(n))
            .collect();
        // where the variable is, exactly: an end of the domain, or the
        // single point of a domain shrunk by the pinned parameters
        let d = self.domain;
        let fixed = |a: &Affine| a.params.iter().all(|(i, _)| params[*i].is_some());
        let length = d.end.plus(&d.start.scale(&Rational::from(-1)));
        let at_pins = |a: &Affine| -> Option<Rational> {
            let mut x = Affine {
                params: Vec::new(),
                ..a.clone()
            };
            for (i, q) in &a.params {
                let v = Rational::from(q * params[*i].as_ref()?);
                if self.axes[*i].pi {
                    x.pi += v;
                } else {
                    x.constant += v;
                }
            }
            (x.pi == 0).then_some(x.constant)
        };
        let shrunk = fixed(&length) && at_pins(&length).is_some_and(|l| l == 0);
        let position = match &tau {
            Some(t) if *t == 0 => Some(&d.start),
            Some(_) => Some(&d.end),
            None if shrunk => Some(&d.start),
            None => None,
        };
        let atoms = match position {
            Some(x) => match d.atoms_at(x, &Sym::one(), &vars) {
                Some(a) => Some(a),
                None => return false,
            },
            None => None,
        };
        let formal_tau = Sym::var("__tau");
        let mut total = Sym::zero();
        for t in &e.terms {
            let coef = match &tau {
                Some(v) => Sym::rational(poly_at(&t.coef, v)),
                None => t.coef.iter().rev().fold(Sym::zero(), |acc, q| {
                    acc * &formal_tau + &Sym::rational(q.clone())
                }),
            };
            let sym = match &atoms {
                Some(at) => t
                    .sym
                    .subs("s", &Sym::var("__s"))
                    .subs("c", &at.c)
                    .subs("__s", &at.s)
                    .subs("t", &at.t)
                    .subs("E", &at.e),
                None => t.sym.clone(),
            };
            total = total + &(coef * &sym);
        }
        // the pinned parameters and their atoms, exactly
        let symbols = trig_symbolic::symbolic_atoms();
        let mut values = vars.clone();
        for (i, q) in params.iter().enumerate() {
            if let Some(q) = q {
                values[i] = if self.axes[i].pi {
                    Sym::rational(q.clone()) * &Sym::pi()
                } else {
                    Sym::rational(q.clone())
                };
            }
        }
        for (i, q) in params.iter().enumerate() {
            if q.is_none() {
                continue;
            }
            total = total.subs(&d.param_names[i], &values[i]);
            for atom in self.atoms.iter().filter(|a| a.param == i) {
                if !total.variables().contains(&atom.name) {
                    continue;
                }
                match value(&atom.name, d, &symbols, &values, &self.atoms) {
                    Some(exact) => total = total.subs(&atom.name, &exact),
                    None => return false,
                }
            }
        }
        total.is_zero()
    }

    /// The variable `x = a(p) + L(p)τ` at a point, to f64 (for display).
    pub fn x_at(&self, tau: &Rational, params: &[Rational]) -> f64 {
        let t = interval(tau, tau);
        let point: Vec<(Rational, Rational)> =
            params.iter().map(|q| (q.clone(), q.clone())).collect();
        let p = self.params(&t, &point);
        let d = self.domain;
        let a = d.start_value(&t, &p);
        let x = a.clone() + &((d.end_value(&t, &p) - &a) * &t);
        trig_core::Real::to_f64(&x)
    }
}
