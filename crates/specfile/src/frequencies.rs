//! The base rates of a spec file's atoms, found from every formula before
//! any is lowered: the exact ring keeps one pair `s = sin ωx`, `c = cos ωx`
//! with `ω` the greatest common divisor of every angle rate of the variable
//! (`sin(t/2)` and `cos(3t/2)` give `ω = 1/2`; the legacy variables include
//! their declared angle), one atom `E = exp(κx)`, and one pair or atom per
//! parameter inside `sin`/`cos`/`exp` — so every angle is an integer
//! multiple of its base and the normal form stays canonical.

use rug::{Integer, Rational};
use trig_core::{Affine, Domain};

use crate::ast::{Expr, Node};
use crate::error::FormulaError;
use crate::formula::{Linear, linear};

/// What the formulas of a file use, collected from their syntax trees.
#[derive(Debug, Clone, Default)]
pub struct Usage {
    /// Rates of the variable inside `sin`/`cos` (`a + bπ`).
    pub angle_rates: Vec<Affine>,
    /// Rates of the variable inside `exp`/`sinh`/`cosh`.
    pub exp_rates: Vec<Rational>,
    /// `(parameter, rate)` inside `sin`/`cos`.
    pub param_angles: Vec<(usize, Rational)>,
    /// `(parameter, rate)` inside `exp`/`sinh`/`cosh`.
    pub param_exps: Vec<(usize, Rational)>,
    /// The variable occurs outside every call.
    pub uses_variable: bool,
}

impl Usage {
    /// Records the calls and variable occurrences of one formula.
    pub fn scan(
        &mut self,
        e: &Expr,
        var_name: &str,
        params: &[(String, String)],
    ) -> Result<(), FormulaError> {
        match &e.node {
            Node::Name(n) if n == var_name => self.uses_variable = true,
            Node::Number(_) | Node::Name(_) => {}
            Node::Neg(a) | Node::Pow(a, _) => self.scan(a, var_name, params)?,
            Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
                self.scan(a, var_name, params)?;
                self.scan(b, var_name, params)?;
            }
            Node::Call(f, arg) if f.is_trigonometric() || f.is_exponential() => {
                let what = format!("the argument of {}", f.name());
                let l = linear(arg, Some(var_name), params, &what)?;
                self.record(&l, f.is_trigonometric(), arg.pos)?;
            }
            Node::Call(_, arg) => self.scan(arg, var_name, params)?,
        }
        Ok(())
    }

    fn record(&mut self, l: &Linear, trig: bool, pos: usize) -> Result<(), FormulaError> {
        let params = l.rest.params.iter().cloned();
        if trig {
            if l.x != Affine::default() {
                self.angle_rates.push(l.x.clone());
            }
            self.param_angles.extend(params);
        } else {
            if l.x.pi != 0 || l.rest.pi != 0 {
                return Err(FormulaError::new(
                    pos,
                    "the argument of exp/sinh/cosh may not involve pi",
                ));
            }
            if l.x.constant != 0 {
                self.exp_rates.push(l.x.constant.clone());
            }
            self.param_exps.extend(params);
        }
        Ok(())
    }
}

/// `gcd(a, b)` of two positive rationals: the largest `g` with `a/g`, `b/g`
/// integers.
pub fn rational_gcd(a: &Rational, b: &Rational) -> Rational {
    let num = Integer::from(a.numer() * b.denom()).gcd(&Integer::from(b.numer() * a.denom()));
    Rational::from((num, Integer::from(a.denom() * b.denom())))
}

fn gcd_all<'a>(values: impl IntoIterator<Item = &'a Rational>) -> Option<Rational> {
    values
        .into_iter()
        .filter(|q| **q != 0)
        .map(|q| Rational::from(q.abs_ref()))
        .reduce(|a, b| rational_gcd(&a, &b))
}

/// The base angle rate `ω`: the gcd of the rates (with `declared`, the
/// legacy variable's own angle, included). All rates must be rational, or
/// all rational multiples of π.
pub fn angle_base(rates: &[Affine], declared: Option<&Affine>) -> Result<Option<Affine>, String> {
    let all: Vec<&Affine> = rates.iter().chain(declared).collect();
    if all.is_empty() {
        return Ok(None);
    }
    let with_pi = all[0].pi != 0;
    if let Some(bad) = all
        .iter()
        .find(|r| (r.pi != 0) != with_pi || (r.pi != 0 && r.constant != 0))
    {
        return Err(format!(
            "the angles of sin/cos must be rational multiples of one another (found rates {} and {})",
            all[0].text(&[]),
            bad.text(&[])
        ));
    }
    let gcd = if with_pi {
        gcd_all(all.iter().map(|r| &r.pi)).map(Affine::pi_times)
    } else {
        gcd_all(all.iter().map(|r| &r.constant)).map(Affine::rational)
    };
    Ok(gcd)
}

/// The base rate of each parameter (gcd of its rates).
pub fn param_bases(uses: &[(usize, Rational)]) -> Vec<(usize, Rational)> {
    let mut out: Vec<(usize, Rational)> = Vec::new();
    for (i, q) in uses {
        let q = Rational::from(q.abs_ref());
        match out.iter_mut().find(|(j, _)| j == i) {
            Some((_, b)) => *b = rational_gcd(b, &q),
            None => out.push((*i, q)),
        }
    }
    out.sort_by_key(|(i, _)| *i);
    out
}

/// Builds the domain from the ends, the usage and (legacy variables) the
/// declared angle. The ends' own angles `ω·a`, `ω·b` and exponents `κ·a`,
/// `κ·b` join the parameter bases, so the atoms at the ends are multiples
/// of them too.
pub fn domain(
    name: &str,
    param_names: Vec<String>,
    (start, end): (Affine, Affine),
    usage: &Usage,
    declared: Option<&Affine>,
) -> Result<Domain, String> {
    let angle = angle_base(&usage.angle_rates, declared)?;
    let exp = gcd_all(&usage.exp_rates);
    let mut param_angles = usage.param_angles.clone();
    let mut param_exps = usage.param_exps.clone();
    for x in [&start, &end] {
        if let Some(w) = &angle {
            let theta = x.times(w).ok_or_else(|| {
                format!(
                    "the domain end {} times the angle rate {} is not linear (π times a parameter)",
                    x.text(&param_names),
                    w.text(&[])
                )
            })?;
            param_angles.extend(theta.params.iter().cloned());
        }
        if let Some(k) = &exp {
            param_exps.extend(x.scale(k).params.iter().cloned());
        }
    }
    Ok(Domain {
        name: name.to_string(),
        param_names,
        start,
        end,
        angle,
        uses_variable: usage.uses_variable,
        exp,
        param_angles: param_bases(&param_angles),
        param_exps: param_bases(&param_exps),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ast::parse;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn gcds_of_rates() {
        assert_eq!(rational_gcd(&q(1, 2), &q(3, 2)), q(1, 2));
        assert_eq!(rational_gcd(&q(2, 3), &q(1, 2)), q(1, 6));
        let pi = |a, b| Affine::pi_times(q(a, b));
        assert_eq!(
            angle_base(&[pi(1, 4)], Some(&pi(1, 2))).unwrap(),
            Some(pi(1, 4))
        );
        assert!(angle_base(&[Affine::rational(q(1, 1))], Some(&pi(1, 2))).is_err());
        assert_eq!(angle_base(&[], None).unwrap(), None);
    }

    #[test]
    fn usage_of_a_c_bezier_basis() {
        let params = vec![("alpha".to_string(), "α".to_string())];
        let mut u = Usage::default();
        for f in [
            "(alpha - t - sin(alpha - t))/(alpha - sin(alpha))",
            "t*cos(t/2)",
            "sinh(2*t)",
        ] {
            u.scan(&parse(f).unwrap(), "t", &params).unwrap();
        }
        assert!(u.uses_variable);
        let d = domain(
            "t",
            vec!["alpha".into()],
            (Affine::default(), Affine::param(0)),
            &u,
            None,
        )
        .unwrap();
        assert_eq!(d.angle, Some(Affine::rational(q(1, 2))));
        assert_eq!(d.exp, Some(q(2, 1)));
        // sin(α), and the end angle α/2: base α/2
        assert_eq!(d.param_angles, vec![(0, q(1, 2))]);
        assert_eq!(d.param_exps, vec![(0, q(2, 1))]);
    }
}
