//! Enclosures of exact functions on a box of (normalised variable,
//! parameters) by Taylor models ([`crate::taylor`]).
//!
//! The box is `τ ∈ [τ₀, τ₁]` (the variable `x = a(p) + L(p)·τ` of a
//! [`Domain`]) times one interval per parameter (in units of π on a π
//! axis). Each side is a coordinate of the models; the atoms of the domain
//! (`s`, `c`, `t`, `E`, `sin(bα)`, `exp(bα)`, `sqrt(p)`, `pi`) are formed
//! once per box as models ([`crate::atoms::value`]), and every exact value
//! ([`Sym`]) is evaluated in them — its expanded form, whose cancellations
//! the models keep.

use std::cell::RefCell;
use std::collections::HashMap;

use rug::Rational;
use trig_core::{Atoms, Domain, Interval, Ring};
use trig_symbolic::{Poly, Sym};

use crate::atoms::{ParamAtom, param_sin_cos, sin_cos_names, value};
use crate::taylor::{Space, TaylorModel};

/// Degree of the models.
pub const DEGREE: u32 = 4;
/// Coefficient precision (bits).
pub const PREC: u32 = 128;

/// The powers `atomᵉ` formed during one evaluation (a few: found by a
/// scan, without forming a key).
type Powers = Vec<(String, u32, TaylorModel)>;

/// The atoms of one box as Taylor models.
pub struct BoxAtoms<'a> {
    domain: &'a Domain,
    param_atoms: Vec<ParamAtom>,
    tau: TaylorModel,
    params: Vec<TaylorModel>,
    atoms: Atoms<TaylorModel>,
    cache: RefCell<HashMap<String, TaylorModel>>,
}

impl std::fmt::Debug for BoxAtoms<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "BoxAtoms({:?})", self.tau.space())
    }
}

impl<'a> BoxAtoms<'a> {
    /// The atoms on the box `bx` (coordinate 0 is `τ`, then one per
    /// parameter; `pi[i]` when parameter `i` is measured in units of π).
    /// The variables of the models are the box's sides of positive width
    /// (a point side is a constant). `None` when an atom has no enclosure
    /// there.
    pub fn new(
        domain: &'a Domain,
        param_atoms: &[ParamAtom],
        pi: &[bool],
        bx: &[(Rational, Rational)],
        degree: u32,
    ) -> Option<BoxAtoms<'a>> {
        let wide: Vec<usize> = (0..bx.len()).filter(|&k| bx[k].0 != bx[k].1).collect();
        let space = Space::new(wide.len(), degree, PREC);
        let side = |k: usize| match wide.iter().position(|&j| j == k) {
            Some(v) => TaylorModel::coordinate(&space, v, &bx[k].0, &bx[k].1),
            None => TaylorModel::constant(&space, &bx[k].0),
        };
        let tau = side(0);
        let params: Vec<TaylorModel> = (1..bx.len())
            .map(|k| {
                let y = side(k);
                if pi.get(k - 1).copied().unwrap_or(false) {
                    y.clone() * &y.pi()
                } else {
                    y
                }
            })
            .collect();
        let a = domain.start_value(&tau, &params);
        let x = a.clone() + &((domain.end_value(&tau, &params) - &a) * &tau);
        let (s, c) = match &domain.angle {
            Some(_) => (x.clone() * &domain.angle_rate(&tau)).try_sin_cos()?,
            None => (tau.int(0), tau.int(1)),
        };
        let e = match &domain.exp {
            Some(k) => (x.clone() * &tau.rational(k)).try_exp()?,
            None => tau.int(1),
        };
        let atoms = Atoms { s, c, t: x, e };
        if [&atoms.s, &atoms.c, &atoms.t, &atoms.e]
            .iter()
            .any(|m| m.is_fault())
        {
            return None;
        }
        Some(BoxAtoms {
            domain,
            param_atoms: param_atoms.to_vec(),
            tau,
            params,
            atoms,
            cache: RefCell::new(HashMap::new()),
        })
    }

    /// The model of `τ`.
    pub fn tau(&self) -> &TaylorModel {
        &self.tau
    }

    /// The model of the variable `x`.
    pub fn x(&self) -> &TaylorModel {
        &self.atoms.t
    }

    fn atom(&self, name: &str) -> Option<TaylorModel> {
        if let Some(m) = self.cache.borrow().get(name) {
            return Some(m.clone());
        }
        // a sine or cosine of a parameter: the pair is one computation
        if let Some(a) = self.param_atoms.iter().find(|a| a.name == name)
            && let Some((sin_name, cos_name)) = sin_cos_names(a, &self.param_atoms)
        {
            let (s, c) = param_sin_cos(a, &self.atoms, &self.params)?;
            let mut cache = self.cache.borrow_mut();
            cache.insert(sin_name.to_string(), s);
            cache.insert(cos_name.to_string(), c);
            return cache.get(name).cloned();
        }
        let m = value(
            name,
            self.domain,
            &self.atoms,
            &self.params,
            &self.param_atoms,
        )?;
        self.cache.borrow_mut().insert(name.to_string(), m.clone());
        Some(m)
    }

    /// The model of `f` on the box, or `None` (an unknown atom, or no
    /// enclosure: a denominator whose range may contain zero). The powers
    /// of the atoms are formed once per evaluation.
    pub fn eval(&self, f: &Sym) -> Option<TaylorModel> {
        let mut powers = Powers::new();
        let mut m = self.eval_poly(f.numerator(), &mut powers)?;
        for (factor, e) in f.denominator() {
            let d = self.eval_poly(factor, &mut powers)?;
            for _ in 0..*e {
                m = m / &d;
            }
        }
        (!m.is_fault()).then_some(m)
    }

    fn eval_poly(&self, p: &Poly, powers: &mut Powers) -> Option<TaylorModel> {
        let mut sum = self.tau.int(0);
        for (monomial, q) in p.terms() {
            let mut term = self.tau.rational(&q.to_rational());
            for (v, e) in monomial.factors() {
                term = term * &self.power(v.name(), e, powers)?;
            }
            sum = sum + &term;
        }
        Some(sum)
    }

    /// `atomᵉ`, from the cache or by one product with a cached power.
    fn power(&self, name: &str, e: u32, powers: &mut Powers) -> Option<TaylorModel> {
        if let Some((.., m)) = powers.iter().find(|(n, k, _)| *k == e && n == name) {
            return Some(m.clone());
        }
        let m = if e == 1 {
            self.atom(name)?
        } else if e % 2 == 0 {
            let h = self.power(name, e / 2, powers)?;
            h.clone() * &h
        } else {
            self.power(name, e - 1, powers)? * &self.atom(name)?
        };
        powers.push((name.to_string(), e, m.clone()));
        Some(m)
    }

    /// `Σ coef(τ)·sym` (a polynomial in `τ` times an exact value, summed).
    pub fn eval_terms<'t>(
        &self,
        terms: impl IntoIterator<Item = (&'t [Rational], &'t Sym)>,
    ) -> Option<TaylorModel> {
        let mut sum = self.tau.int(0);
        for (coef, sym) in terms {
            let p = coef.iter().rev().fold(self.tau.int(0), |acc, q| {
                acc * &self.tau + &self.tau.rational(q)
            });
            sum = sum + &(p * &self.eval(sym)?);
        }
        (!sum.is_fault()).then_some(sum)
    }
}

/// The range of `f` on the box by a Taylor model (see [`BoxAtoms`]).
pub fn enclose(
    f: &Sym,
    domain: &Domain,
    param_atoms: &[ParamAtom],
    pi: &[bool],
    bx: &[(Rational, Rational)],
) -> Option<Interval> {
    BoxAtoms::new(domain, param_atoms, pi, bx, DEGREE)?
        .eval(f)?
        .range()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::atoms::param_atoms;
    use crate::testing::q;
    use trig_core::Affine;

    fn c_curve() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(q(1, 1))),
            uses_variable: true,
            exp: None,
            param_angles: vec![(0, q(1, 1))],
            param_exps: Vec::new(),
        }
    }

    #[test]
    fn sin_of_a_difference_keeps_its_dependency() {
        // sin(α − t) = sin α·c − cos α·s on t = ατ, τ ∈ [0.9, 1], α ∈ [2, 2.1]:
        // α − t ∈ [0, 0.21], so sin(α − t) ∈ [0, 0.21]; intervals give ±1.6
        let d = c_curve();
        let pa = param_atoms(&d);
        let f =
            Sym::var("sin(alpha)") * &Sym::var("c") - &(Sym::var("cos(alpha)") * &Sym::var("s"));
        let bx = [(q(9, 10), q(1, 1)), (q(2, 1), q(21, 10))];
        let r = enclose(&f, &d, &pa, &[false], &bx).unwrap();
        assert!(r.lo().to_f64() > -0.01 && r.hi().to_f64() < 0.25, "{r:?}");
    }

    #[test]
    fn pi_axes_and_exponentials() {
        let d = Domain {
            exp: Some(q(1, 1)),
            param_exps: vec![(0, q(1, 1))],
            angle: None,
            param_angles: Vec::new(),
            ..c_curve()
        };
        let pa = param_atoms(&d);
        // exp(α) − E ≥ 0 on t ∈ [0, α], α = π·y, y ∈ [1/2, 1]
        let f = Sym::var("exp(alpha)") - &Sym::var("E");
        let bx = [(q(0, 1), q(1, 2)), (q(1, 2), q(1, 1))];
        let r = enclose(&f, &d, &pa, &[true], &bx).unwrap();
        assert!(r.lo().to_f64() > 0.0, "{r:?}");
    }
}
