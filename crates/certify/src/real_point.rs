//! A real point of the domain and the parameter set where two exact
//! values differ — a witness a reader can re-check.
//!
//! An exact value of a basis is a function of the variable `x` and the
//! parameters through its atoms (`sin ωx`, `x`, `exp κx`, `sin(bα)`, `α`,
//! …); giving each atom its own number (`sin(α/2) = 1, cos(α/2) = 2`) is
//! not a point at all. Here the point is chosen first — the parameters and
//! `x = a(p) + L(p)·τ`, as exact reals (rationals or rational multiples of
//! π) — and the atoms are computed from it: exactly when they are exact
//! there (angles at multiples of π/12, `exp` at 0), the two values then
//! compared exactly; otherwise both are enclosed at the point in MPFR
//! ([`Coordinates::enclose`]) and the point is a witness only when the
//! enclosures are disjoint. Every witness returned has been evaluated at
//! the real point it names.

use rug::Rational;
use trig_core::{Affine, Domain, Interval};
use trig_symbolic::Sym;

use crate::atoms::{param_atoms, value};
use crate::branch::Axis;
use crate::coordinates::Coordinates;
use crate::range::simplest_between;

/// The value of an exact function at a real point.
#[derive(Debug, Clone)]
pub enum RealValue {
    /// Exact (an element of `ℚ(π, √2, √3, …)`).
    Exact(Sym),
    /// A certified enclosure (MPFR, outward rounding).
    Enclosure(Interval),
}

/// Where two values differ: the parameters and the variable, exactly.
#[derive(Debug, Clone)]
pub struct Difference {
    /// The parameter values (rationals or rational multiples of π).
    pub params: Vec<Sym>,
    /// The variable `x`.
    pub x: Sym,
    pub left: RealValue,
    pub right: RealValue,
}

/// Fractions of the domain tried for `x` (`τ`).
const TAUS: [(i64, i64); 6] = [(1, 2), (1, 3), (2, 3), (1, 4), (3, 4), (1, 5)];

/// Simple values inside an axis (its closed part, open ends excluded),
/// in the axis' units: the simplest rationals of its halves, and on a π
/// axis the multiples of 1/12 first.
fn inside(axis: &Axis) -> Vec<Rational> {
    let (lo, hi) = (&axis.lo, &axis.hi);
    if lo == hi {
        return vec![lo.clone()];
    }
    let mut out = Vec::new();
    if axis.pi {
        for den in [2u32, 3, 4, 6, 12] {
            let mut k = Rational::from(lo * den).floor();
            while Rational::from(&k / den) <= *hi && out.len() < 8 {
                let v = Rational::from(&k / den);
                let open = (v == *lo && axis.lo_open) || (v == *hi && axis.hi_open);
                if v >= *lo && !open && !out.contains(&v) {
                    out.push(v);
                }
                k += 1u32;
            }
        }
    }
    let mid = Rational::from(lo + hi) / 2u32;
    for (a, b) in [
        (lo.clone(), hi.clone()),
        (lo.clone(), mid.clone()),
        (mid, hi.clone()),
    ] {
        let v = simplest_between(&a, &b);
        let open = (v == *lo && axis.lo_open) || (v == *hi && axis.hi_open);
        if !open && !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The parameter value in the ring (`q·π` on a π axis).
fn param_value(q: &Rational, axis: &Axis) -> Sym {
    if axis.pi {
        Sym::rational(q.clone()) * &Sym::pi()
    } else {
        Sym::rational(q.clone())
    }
}

/// `f` at the point exactly, when every atom is exact there.
fn exactly(f: &Sym, domain: &Domain, params: &[Sym], x: &Affine) -> Option<Sym> {
    let at = domain.atoms_at(x, &Sym::one(), params)?;
    let mut g = f
        .subs("s", &Sym::var("__s"))
        .subs("c", &at.c)
        .subs("__s", &at.s)
        .subs("t", &at.t)
        .subs("E", &at.e);
    let atoms = param_atoms(domain);
    let symbols = trig_symbolic::symbolic_atoms();
    for (i, name) in domain.param_names.iter().enumerate() {
        g = g.try_subs(name, &params[i]).ok()?;
    }
    for a in &atoms {
        if g.variables().contains(&a.name) {
            g = g
                .try_subs(&a.name, &value(&a.name, domain, &symbols, params, &atoms)?)
                .ok()?;
        }
    }
    let free = g
        .variables()
        .into_iter()
        .all(|v| v == "pi" || v.starts_with("sqrt("));
    free.then_some(g)
}

/// The affine `x` at the parameter values `p` (axis units): a constant
/// plus a multiple of π.
fn constant_at(x: &Affine, p: &[Rational], axes: &[Axis]) -> Affine {
    let mut out = Affine {
        params: Vec::new(),
        ..x.clone()
    };
    for (i, q) in &x.params {
        let v = Rational::from(q * &p[*i]);
        if axes[*i].pi {
            out.pi += v;
        } else {
            out.constant += v;
        }
    }
    out
}

/// Every combination of one value per axis.
fn combinations(choices: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    choices.iter().fold(vec![Vec::new()], |acc, c| {
        acc.iter()
            .flat_map(|prefix| {
                c.iter().map(move |v| {
                    let mut p = prefix.clone();
                    p.push(v.clone());
                    p
                })
            })
            .collect()
    })
}

/// A real point of the domain (for parameters in `axes`) where `left`
/// and `right` differ, exact when possible, certified otherwise.
pub fn differ(left: &Sym, right: &Sym, domain: &Domain, axes: &[Axis]) -> Option<Difference> {
    let coords = Coordinates::new(domain, axes);
    let choices: Vec<Vec<Rational>> = axes.iter().map(inside).collect();
    let points = combinations(&choices);
    let (lf, rf) = (coords.function(left), coords.function(right));
    // exact points first, then certified enclosures
    for exact in [true, false] {
        for p in &points {
            let params: Vec<Sym> = p.iter().zip(axes).map(|(q, a)| param_value(q, a)).collect();
            for (n, d) in TAUS {
                let tau = Rational::from((n, d));
                let x_affine = constant_at(
                    &domain
                        .start
                        .scale(&(1 - tau.clone()))
                        .plus(&domain.end.scale(&tau)),
                    p,
                    axes,
                );
                let x = x_affine.eval(&Sym::one(), &params);
                if exact {
                    let (Some(l), Some(r)) = (
                        exactly(left, domain, &params, &x_affine),
                        exactly(right, domain, &params, &x_affine),
                    ) else {
                        continue;
                    };
                    if !(l.clone() - &r).is_zero() {
                        return Some(Difference {
                            params,
                            x,
                            left: RealValue::Exact(l),
                            right: RealValue::Exact(r),
                        });
                    }
                } else {
                    let mut cell = vec![(tau.clone(), tau.clone())];
                    cell.extend(p.iter().map(|q| (q.clone(), q.clone())));
                    let (Some(l), Some(r)) =
                        (coords.enclose(&lf, &cell), coords.enclose(&rf, &cell))
                    else {
                        continue;
                    };
                    if l.hi() < r.lo() || r.hi() < l.lo() {
                        return Some(Difference {
                            params,
                            x,
                            left: RealValue::Enclosure(l),
                            right: RealValue::Enclosure(r),
                        });
                    }
                }
            }
        }
    }
    None
}

/// The values of expressions at one real point: the parameters, the
/// variable and the values there (exact or certified enclosures).
#[derive(Debug, Clone)]
pub struct Instance {
    /// The parameter values (rationals or rational multiples of π).
    pub params: Vec<Sym>,
    /// The variable `x`.
    pub x: Sym,
    /// The value of each expression, in order.
    pub values: Vec<RealValue>,
}

/// The simplest rational strictly between `a < b` (smallest denominator,
/// then smallest size), by the Stern–Brocot descent: `x = ⌊a⌋ + 1/y` with
/// `y` the simplest strictly between `1/(b − ⌊a⌋)` and `1/(a − ⌊a⌋)`.
fn simplest_strictly_between(a: &Rational, b: &Rational) -> Rational {
    let zero = Rational::new();
    if *a < zero && *b > zero {
        return zero;
    }
    if *b <= zero {
        return -simplest_strictly_between(&-b.clone(), &-a.clone());
    }
    let next = a.clone().floor() + 1u32;
    if next < *b {
        return next;
    }
    // a < b ≤ next: both in [next − 1, next]
    let floor = next - 1u32;
    let lo = Rational::from(1) / (b.clone() - &floor);
    let y = if *a == floor {
        lo.floor() + 1u32
    } else {
        simplest_strictly_between(&lo, &(Rational::from(1) / (a.clone() - &floor)))
    };
    floor + Rational::from(1) / y
}

/// The simplest value of an axis (its open ends excluded).
fn simplest(axis: &Axis) -> Rational {
    if axis.lo == axis.hi {
        return axis.lo.clone();
    }
    let v = simplest_between(&axis.lo, &axis.hi);
    let open = (v == axis.lo && axis.lo_open) || (v == axis.hi && axis.hi_open);
    if open {
        simplest_strictly_between(&axis.lo, &axis.hi)
    } else {
        v
    }
}

/// The values of `exprs` at one real point, the simplest there is: each
/// parameter the simplest rational of its axis (open ends excluded; in
/// units of π on a π axis), `x` the middle of the domain. Exact when every
/// atom is exact there (angles at multiples of π/12), else certified
/// enclosures; `None` when an expression is not defined there. An
/// instance of what holds everywhere, shown at a point a reader can check.
pub fn simplest_point(exprs: &[&Sym], domain: &Domain, axes: &[Axis]) -> Option<Instance> {
    let p: Vec<Rational> = axes.iter().map(simplest).collect();
    let params: Vec<Sym> = p.iter().zip(axes).map(|(q, a)| param_value(q, a)).collect();
    let half = Rational::from((1, 2));
    let x_affine = constant_at(
        &domain.start.scale(&half).plus(&domain.end.scale(&half)),
        &p,
        axes,
    );
    let x = x_affine.eval(&Sym::one(), &params);
    let exact: Option<Vec<RealValue>> = exprs
        .iter()
        .map(|f| exactly(f, domain, &params, &x_affine).map(RealValue::Exact))
        .collect();
    let values = match exact {
        Some(values) => values,
        None => {
            let coords = Coordinates::new(domain, axes);
            let mut cell = vec![(half.clone(), half.clone())];
            cell.extend(p.iter().map(|q| (q.clone(), q.clone())));
            exprs
                .iter()
                .map(|f| {
                    coords
                        .enclose(&coords.function(f), &cell)
                        .map(RealValue::Enclosure)
                })
                .collect::<Option<Vec<_>>>()?
        }
    };
    Some(Instance { params, x, values })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::q;

    /// `t ∈ [0, α]` with `E = exp(t)`, `exp(α)`.
    fn exponential() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: None,
            uses_variable: false,
            exp: Some(q(1, 1)),
            param_angles: Vec::new(),
            param_exps: vec![(0, q(1, 1))],
        }
    }

    #[test]
    fn exponential_bernstein_is_not_symmetric_at_a_real_point() {
        // b0 = (1 − w)³ against b3(α − t) = ((exp(α − t) − 1)/(exp α − 1))³
        let d = exponential();
        let (e, ea) = (Sym::var("E"), Sym::var("exp(alpha)"));
        let den = ea.clone() - &Sym::one();
        let w = (e.clone() - &Sym::one()) / &den;
        let b0 = (Sym::one() - &w) * &(Sym::one() - &w) * &(Sym::one() - &w);
        let wr = (ea.clone() / &e - &Sym::one()) / &den;
        let b3r = wr.clone() * &wr * &wr;
        let axes = vec![Axis {
            lo: q(1, 2),
            hi: q(4, 1),
            lo_open: false,
            hi_open: false,
            pi: false,
        }];
        let diff = differ(&b0, &b3r, &d, &axes).expect("a real witness");
        // certified, not exact: exp at a nonzero rational is not exact
        let (RealValue::Enclosure(l), RealValue::Enclosure(r)) = (&diff.left, &diff.right) else {
            panic!("{diff:?}")
        };
        let alpha = diff.params[0].as_rational().unwrap().to_f64();
        let t = diff.x.as_rational().unwrap().to_f64();
        assert!((0.5..=4.0).contains(&alpha) && (0.0..=alpha).contains(&t));
        let w = (t.exp() - 1.0) / (alpha.exp() - 1.0);
        let wr = ((alpha - t).exp() - 1.0) / (alpha.exp() - 1.0);
        assert!((l.lo().to_f64() - (1.0 - w).powi(3)).abs() < 1e-12);
        assert!((r.lo().to_f64() - wr.powi(3)).abs() < 1e-12);
    }

    #[test]
    fn c_curve_values_are_exact_at_multiples_of_pi() {
        // t − sin t against sin t on [0, α], α ∈ (0, π): exact at α = π/2,
        // t = π/4: π/4 − √2/2 against √2/2
        let d = Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(q(1, 1))),
            uses_variable: true,
            exp: None,
            param_angles: vec![(0, q(1, 1))],
            param_exps: Vec::new(),
        };
        let axes = vec![Axis {
            lo: q(0, 1),
            hi: q(1, 1),
            lo_open: true,
            hi_open: true,
            pi: true,
        }];
        let (t, s) = (Sym::var("t"), Sym::var("s"));
        let diff = differ(&(t - &s), &s, &d, &axes).expect("a witness");
        let (RealValue::Exact(l), RealValue::Exact(r)) = (&diff.left, &diff.right) else {
            panic!("{diff:?}")
        };
        assert_eq!(diff.params[0], Sym::pi() / &Sym::int(2));
        assert_eq!(diff.x, Sym::pi() / &Sym::int(4));
        assert_eq!(r.to_string(), "1/2*sqrt(2)");
        assert!(!(l.clone() - r).is_zero());
    }

    #[test]
    fn the_simplest_point_avoids_open_ends() {
        let axis = |lo: Rational, hi: Rational, lo_open, hi_open| Axis {
            lo,
            hi,
            lo_open,
            hi_open,
            pi: false,
        };
        assert_eq!(simplest(&axis(q(-2, 1), q(1, 1), false, false)), q(0, 1));
        assert_eq!(simplest(&axis(q(1, 1), q(101, 1), true, false)), q(2, 1));
        assert_eq!(simplest(&axis(q(0, 1), q(1, 1), true, true)), q(1, 2));
        assert_eq!(simplest(&axis(q(1, 3), q(1, 2), true, true)), q(2, 5));
        assert_eq!(simplest(&axis(q(-1, 2), q(-1, 3), true, true)), q(-2, 5));
        // e^t − 1 at α = 1 (the simplest of [1/2, 4]), t = α/2: enclosed, not exact
        let d = exponential();
        let e = Sym::var("E") - &Sym::one();
        let at =
            simplest_point(&[&e], &d, &[axis(q(1, 2), q(4, 1), false, false)]).expect("defined");
        assert_eq!(at.params, [Sym::one()]);
        let RealValue::Enclosure(v) = &at.values[0] else {
            panic!("{at:?}")
        };
        let want = 0.5f64.exp() - 1.0;
        assert!(v.lo().to_f64() <= want && want <= v.hi().to_f64());
    }
}
