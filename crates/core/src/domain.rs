//! The domain of a basis in general form: the variable `x ∈ [a, b]` with
//! exact ends that may involve π and the shape parameters (`[0, α]` for
//! C-curves, `[0, π]`, `[−π/2, π/2]`), and the atoms its formulas are
//! written in:
//!
//! * `s = sin(ωx)`, `c = cos(ωx)` for a constant rate `ω = q₁ + q₂π`
//!   (`π/2` for `u ∈ [0, 1]` with `θ = πu/2`, `1` for the angle itself,
//!   `1/2` for half angles);
//! * `t = x`, the variable itself (polynomial and algebraic-trigonometric
//!   bases, span{1, t, sin t, cos t});
//! * `e = exp(κx)` for a rational rate `κ` (hyperbolic and exponential
//!   bases: `sinh(κx) = (e − 1/e)/2`).
//!
//! The catalog's three [`Variable`]s are special cases
//! ([`Domain::from_variable`]); spec files build any other. Every consumer
//! — numeric evaluation, jets, exact tables, joins, plots, certification —
//! reads the domain, so a user's basis goes through the same path as the
//! catalog.

use std::fmt;

use rug::Rational;

use crate::angles::{angle_sum, multiple_angle};
use crate::error::{CoreError, Result};
use crate::scalar::{Real, Ring};
use crate::variable::{Atoms, Variable};

/// An exact real `q₀ + q_π·π + Σ qᵢ·pᵢ`, linear in the shape parameters
/// `pᵢ` (by index).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default)]
pub struct Affine {
    pub constant: Rational,
    pub pi: Rational,
    /// `(parameter index, coefficient)`, nonzero coefficients only.
    pub params: Vec<(usize, Rational)>,
}

impl Affine {
    /// The rational `q`.
    pub fn rational(q: Rational) -> Affine {
        Affine {
            constant: q,
            ..Affine::default()
        }
    }

    /// `q·π`.
    pub fn pi_times(q: Rational) -> Affine {
        Affine {
            pi: q,
            ..Affine::default()
        }
    }

    /// The parameter with index `i`.
    pub fn param(i: usize) -> Affine {
        Affine {
            params: vec![(i, Rational::from(1))],
            ..Affine::default()
        }
    }

    /// True when no parameter occurs.
    pub fn is_constant(&self) -> bool {
        self.params.is_empty()
    }

    /// The value when it is a rational number.
    pub fn as_rational(&self) -> Option<&Rational> {
        (self.pi == 0 && self.params.is_empty()).then_some(&self.constant)
    }

    /// `k` when the value is `k·π/2` for an integer `k` (angles whose sine
    /// and cosine are exact: 0, ±1).
    pub fn quarter_turns(&self) -> Option<i64> {
        if self.constant != 0 || !self.params.is_empty() {
            return None;
        }
        let k = Rational::from(&self.pi * 2u32);
        (*k.denom() == 1).then(|| k.numer().to_i64()).flatten()
    }

    /// The value in the ring of `like`, parameters from `params`.
    pub fn eval<T: Ring>(&self, like: &T, params: &[T]) -> T {
        let mut v = like.rational(&self.constant);
        if self.pi != 0 {
            v = v + &(like.pi() * &like.rational(&self.pi));
        }
        for (i, q) in &self.params {
            v = v + &(params[*i].clone() * &like.rational(q));
        }
        v
    }

    /// The f64 nearest `q₀ + q_π·π` (parameters ignored: callers pass
    /// values; a multiple of π from a 128-bit MPFR evaluation) — for
    /// drawing and fitting, never for a decision.
    pub fn to_f64(&self) -> f64 {
        if self.pi == 0 {
            // nearest (`Rational::to_f64` truncates: 1/20 would be 0.049999…)
            return rug::Float::with_val(53, &self.constant).to_f64();
        }
        let pi = rug::Float::with_val(128, rug::float::Constant::Pi);
        let v = rug::Float::with_val(128, &self.constant) + pi * &self.pi;
        v.to_f64()
    }

    /// `self·q`.
    pub fn scale(&self, q: &Rational) -> Affine {
        let mul = |x: &Rational| Rational::from(x * q);
        Affine {
            constant: mul(&self.constant),
            pi: mul(&self.pi),
            params: if *q == 0 {
                Vec::new()
            } else {
                self.params.iter().map(|(i, c)| (*i, mul(c))).collect()
            },
        }
    }

    /// `self·w` when it is again affine (not `π²`, not `π·p`).
    pub fn times(&self, w: &Affine) -> Option<Affine> {
        if let Some(q) = w.as_rational() {
            return Some(self.scale(q));
        }
        let q = self.as_rational()?;
        Some(w.scale(q))
    }

    /// `self + other`.
    pub fn plus(&self, other: &Affine) -> Affine {
        let mut out = Affine {
            constant: Rational::from(&self.constant + &other.constant),
            pi: Rational::from(&self.pi + &other.pi),
            params: self.params.clone(),
        };
        for (i, q) in &other.params {
            match out.params.iter_mut().find(|(j, _)| j == i) {
                Some((_, r)) => *r += q,
                None => out.params.push((*i, q.clone())),
            }
        }
        out.params.retain(|(_, q)| *q != 0);
        out.params.sort_by_key(|(i, _)| *i);
        out
    }

    /// The value for the exact parameter values `params` (each `q₀ + q_π·π`,
    /// as [`crate::parse_point`] reads them): again `q₀ + q_π·π`.
    pub fn at(&self, params: &[Affine]) -> Affine {
        let mut out = Affine {
            constant: self.constant.clone(),
            pi: self.pi.clone(),
            params: Vec::new(),
        };
        for (i, q) in &self.params {
            let p = &params[*i];
            out.constant += Rational::from(q * &p.constant);
            out.pi += Rational::from(q * &p.pi);
        }
        out
    }

    /// As printed, with the parameters named (`pi/2`, `2*alpha - 1`).
    pub fn text(&self, names: &[String]) -> String {
        let mut terms: Vec<(String, Rational)> = Vec::new();
        for (i, q) in &self.params {
            let name = names.get(*i).cloned().unwrap_or_else(|| format!("p{i}"));
            terms.push((name, q.clone()));
        }
        if self.pi != 0 {
            terms.push(("pi".into(), self.pi.clone()));
        }
        let mut out = String::new();
        for (name, q) in &terms {
            let (neg, abs) = (*q < 0, Rational::from(q.abs_ref()));
            out.push_str(match (out.is_empty(), neg) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            });
            let (num, den) = (abs.numer().clone(), abs.denom().clone());
            if num != 1 {
                out.push_str(&format!("{num}*"));
            }
            out.push_str(name);
            if den != 1 {
                out.push_str(&format!("/{den}"));
            }
        }
        if self.constant != 0 || out.is_empty() {
            let c = &self.constant;
            if out.is_empty() {
                out = c.to_string();
            } else if *c < 0 {
                out.push_str(&format!(" - {}", Rational::from(-c)));
            } else {
                out.push_str(&format!(" + {c}"));
            }
        }
        out
    }
}

/// The domain and atoms of a basis; see the [module documentation](self).
#[derive(Debug, Clone, PartialEq)]
pub struct Domain {
    /// The variable's name in formulas and output (`u`, `t`, `x`).
    pub name: String,
    /// The shape parameters' names (for printing the ends).
    pub param_names: Vec<String>,
    pub start: Affine,
    pub end: Affine,
    /// `ω` with `s = sin(ωx)`, `c = cos(ωx)`; `None` when the formulas have
    /// no trigonometric atoms.
    pub angle: Option<Affine>,
    /// True when the formulas use the variable itself (`t = x`).
    pub uses_variable: bool,
    /// `κ` with `e = exp(κx)`; `None` when unused.
    pub exp: Option<Rational>,
    /// The base rate `bᵢ` of each parameter `pᵢ` inside sines and cosines:
    /// the exact ring keeps one pair of atoms `sin(bᵢpᵢ)`, `cos(bᵢpᵢ)` and
    /// expands every `sin(k·bᵢpᵢ)` from it.
    pub param_angles: Vec<(usize, Rational)>,
    /// The base rate of each parameter inside exponentials (`exp(bᵢpᵢ)`).
    pub param_exps: Vec<(usize, Rational)>,
}

impl Domain {
    /// The domain of a catalog [`Variable`].
    pub fn from_variable(v: Variable, param_names: &[&str]) -> Domain {
        let half_pi = Affine::pi_times(Rational::from((1, 2)));
        let one = Affine::rational(Rational::from(1));
        let (name, end, angle) = match v {
            Variable::UnitAngle => ("u", one.clone(), Some(half_pi)),
            Variable::Angle => ("t", half_pi, Some(one)),
            Variable::Polynomial => ("t", one, None),
        };
        Domain {
            name: name.into(),
            param_names: param_names.iter().map(|n| n.to_string()).collect(),
            start: Affine::default(),
            end,
            angle,
            uses_variable: v == Variable::Polynomial,
            exp: None,
            param_angles: Vec::new(),
            param_exps: Vec::new(),
        }
    }

    /// `(sin θ, cos θ)` of an exact angle `θ = q₀ + q_π·π + Σ qᵢpᵢ` in the
    /// ring of `like`: the constant part by [`Ring::try_sin_cos`] (exact at
    /// multiples of π/12 in the exact ring), each parameter part as the
    /// multiple `qᵢ/bᵢ` of its base angle ([`Domain::param_angles`]),
    /// combined by the sum formula. `None` when the ring cannot form a part
    /// (or `qᵢ/bᵢ` is not an integer).
    pub fn sin_cos_of<T: Ring>(&self, theta: &Affine, like: &T, params: &[T]) -> Option<(T, T)> {
        let constant = Affine {
            params: Vec::new(),
            ..theta.clone()
        };
        // quarter turns are exact in every ring (0, ±1)
        let mut acc = match constant.quarter_turns() {
            Some(k) => {
                let (s, c) = [(0, 1), (1, 0), (0, -1), (-1, 0)][k.rem_euclid(4) as usize];
                (like.int(s), like.int(c))
            }
            None => constant.eval(like, &[]).try_sin_cos()?,
        };
        for (i, q) in &theta.params {
            let (base, k) = multiple_of_base(&self.param_angles, *i, q)?;
            let (s, c) = (params[*i].clone() * &like.rational(&base)).try_sin_cos()?;
            acc = angle_sum(&acc, &multiple_angle(&s, &c, k));
        }
        Some(acc)
    }

    /// `exp x` of an exact `x` (no π): the constant part by
    /// [`Ring::try_exp`], each parameter part as a power of its base
    /// ([`Domain::param_exps`]).
    pub fn exp_of<T: Ring>(&self, x: &Affine, like: &T, params: &[T]) -> Option<T> {
        if x.pi != 0 {
            return None;
        }
        let mut acc = if x.constant == 0 {
            like.int(1)
        } else {
            like.rational(&x.constant).try_exp()?
        };
        for (i, q) in &x.params {
            let (base, k) = multiple_of_base(&self.param_exps, *i, q)?;
            let e = (params[*i].clone() * &like.rational(&base)).try_exp()?;
            let power = e.powi(k.unsigned_abs() as u32);
            acc = if k < 0 { acc / &power } else { acc * &power };
        }
        Some(acc)
    }

    /// The atoms at an exact point `x` (an end of the domain): `s, c` of
    /// `ωx`, `t = x`, `e = exp(κx)`, in the ring of `like`; `None` when the
    /// ring cannot form them exactly (e.g. `sin 1` in the exact ring).
    pub fn atoms_at<T: Ring>(&self, x: &Affine, like: &T, params: &[T]) -> Option<Atoms<T>> {
        let (s, c) = match &self.angle {
            Some(w) => self.sin_cos_of(&x.times(w)?, like, params)?,
            None => (like.int(0), like.int(1)),
        };
        let e = match &self.exp {
            Some(k) => self.exp_of(&x.scale(k), like, params)?,
            None => like.int(1),
        };
        Some(Atoms {
            s,
            c,
            t: x.eval(like, params),
            e,
        })
    }

    /// True when the formulas use `s`, `c`.
    pub fn is_trigonometric(&self) -> bool {
        self.angle.is_some()
    }

    /// True when the formulas are polynomials in `s`, `c` alone (no `t`,
    /// no `e`): the angle is then the natural variable of derivatives.
    pub fn is_pure_trigonometric(&self) -> bool {
        self.angle.is_some() && !self.uses_variable && self.exp.is_none()
    }

    /// The start `a` in the ring of `like` (parameters `params`).
    pub fn start_value<T: Ring>(&self, like: &T, params: &[T]) -> T {
        self.start.eval(like, params)
    }

    /// The end `b` in the ring of `like` (parameters `params`).
    pub fn end_value<T: Ring>(&self, like: &T, params: &[T]) -> T {
        self.end.eval(like, params)
    }

    /// The angle rate `ω` (1 when there is no angle).
    pub fn angle_rate<T: Ring>(&self, like: &T) -> T {
        self.angle
            .as_ref()
            .map_or_else(|| like.int(1), |w| w.eval(like, &[]))
    }

    /// The atoms at a point `x`: `s, c = sin(ωx), cos(ωx)` (of `x` itself
    /// when there is no angle, so the struct is complete), `t = x`,
    /// `e = exp(κx)` (1 when unused).
    pub fn atoms<T: Real>(&self, x: &T) -> Atoms<T> {
        let theta = match &self.angle {
            Some(w) => x.clone() * &w.eval(x, &[]),
            None => x.clone(),
        };
        let (s, c) = theta.sin_cos();
        let e = match &self.exp {
            Some(k) => (x.clone() * &x.rational(k)).exp(),
            None => x.int(1),
        };
        Atoms {
            s,
            c,
            t: x.clone(),
            e,
        }
    }

    /// True when `a ≤ x ≤ b` for these parameters.
    pub fn contains<T: Real>(&self, x: &T, params: &[T]) -> bool {
        *x >= self.start_value(x, params) && *x <= self.end_value(x, params)
    }

    /// Checks an evaluation point: finite, and inside the domain unless
    /// `allow_outside`.
    pub fn check_point<T: Real>(&self, x: &T, params: &[T], allow_outside: bool) -> Result<()> {
        if !x.is_finite() {
            return Err(CoreError::NotFinite {
                what: "the evaluation point".into(),
            });
        }
        if !allow_outside && !self.contains(x, params) {
            return Err(CoreError::PointOutsideDomain {
                value: format!("{}", x.to_f64()),
                domain: self.to_string(),
            });
        }
        Ok(())
    }

    /// The reflection `x ↦ a + b − x` of the domain onto itself.
    pub fn reflection(&self) -> Affine {
        let mut sum = self.start.clone();
        sum.constant += &self.end.constant;
        sum.pi += &self.end.pi;
        for (i, q) in &self.end.params {
            match sum.params.iter_mut().find(|(j, _)| j == i) {
                Some((_, r)) => *r += q,
                None => sum.params.push((*i, q.clone())),
            }
        }
        sum.params.retain(|(_, q)| *q != 0);
        sum.params.sort_by_key(|(i, _)| *i);
        sum
    }
}

/// `(bᵢ, qᵢ/bᵢ)` for parameter `i` with coefficient `q`: its base rate (the
/// coefficient itself when none is recorded) and the integer multiple.
fn multiple_of_base(
    bases: &[(usize, Rational)],
    i: usize,
    q: &Rational,
) -> Option<(Rational, i64)> {
    let base = bases
        .iter()
        .find(|(j, _)| *j == i)
        .map_or_else(|| q.clone(), |(_, b)| b.clone());
    let k = Rational::from(q / &base);
    (*k.denom() == 1)
        .then(|| k.numer().to_i64())
        .flatten()
        .map(|k| (base, k))
}

impl fmt::Display for Domain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} in [{}, {}]",
            self.name,
            self.start.text(&self.param_names),
            self.end.text(&self.param_names)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn catalog_variables_keep_their_domains() {
        for (v, text) in [
            (Variable::UnitAngle, "u in [0, 1]"),
            (Variable::Angle, "t in [0, pi/2]"),
            (Variable::Polynomial, "t in [0, 1]"),
        ] {
            let d = Domain::from_variable(v, &[]);
            assert_eq!(d.to_string(), text);
            assert_eq!(d.to_string(), v.domain());
            // the atoms agree with the variable's
            let (x, y) = (d.atoms(&0.3_f64), v.atoms(&0.3_f64));
            assert_eq!((x.s, x.c, x.t), (y.s, y.c, y.t));
        }
    }

    #[test]
    fn parameter_ends_and_reflection() {
        // C-curves: t ∈ [0, α]; half angles ω = 1/2; e = exp(t)
        let d = Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(q(1, 2))),
            uses_variable: true,
            exp: Some(q(1, 1)),
            param_angles: vec![(0, q(1, 2))],
            param_exps: Vec::new(),
        };
        // the atoms at the end t = α: sin(α/2) from the base α/2
        let at = d.atoms_at(&d.end, &0.0_f64, &[2.0]).unwrap();
        assert!((at.s - 1f64.sin()).abs() < 1e-15 && (at.t - 2.0).abs() < 1e-15);
        assert!((at.e - 2f64.exp()).abs() < 1e-14);
        assert_eq!(d.to_string(), "t in [0, alpha]");
        assert!(d.contains(&1.0_f64, &[2.0]) && !d.contains(&2.5_f64, &[2.0]));
        assert!(d.check_point(&2.5_f64, &[2.0], false).is_err());
        assert!(d.check_point(&f64::NAN, &[2.0], true).is_err());
        let a = d.atoms(&1.0_f64);
        assert!((a.s - 0.5_f64.sin()).abs() < 1e-15 && (a.e - 1f64.exp()).abs() < 1e-15);
        assert_eq!(d.reflection().text(&d.param_names), "alpha");
        // [−π/2, π/2]: the reflection is x ↦ −x
        let sym = Domain {
            start: Affine::pi_times(q(-1, 2)),
            end: Affine::pi_times(q(1, 2)),
            ..d
        };
        assert_eq!(sym.reflection().text(&[]), "0");
        assert_eq!(sym.to_string(), "t in [-pi/2, pi/2]");
        assert_eq!(Affine::pi_times(q(3, 2)).quarter_turns(), Some(3));
        assert_eq!(Affine::pi_times(q(1, 4)).quarter_turns(), None);
        let mixed = Affine {
            constant: q(-1, 3),
            pi: q(2, 1),
            params: vec![(0, q(-3, 2))],
        };
        assert_eq!(mixed.text(&["beta".into()]), "-3*beta/2 + 2*pi - 1/3");
    }
}
