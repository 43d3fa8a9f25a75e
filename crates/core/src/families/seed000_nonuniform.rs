//! Seed 000, non-uniform knots: the coefficient formulas (2)–(3) exactly as
//! printed, for a given knot vector `n₀ < n₁ < …` and shape parameter `ξ`.
//!
//! Every quantity is computed on demand from the printed formula. Where a
//! formula needs a knot outside the vector, the result is
//! [`CoreError::Undefined`] naming the quantity; where a denominator
//! vanishes, [`CoreError::DivisionByZero`] naming it. (For uniform knots
//! `c_{j,0} = 0`, so the printed `c_{j,2}`, which divides by `c_{j,0}`, is
//! undefined — the audit reports this.)

use rug::Rational;

use crate::error::{CoreError, Result};
use crate::evaluation::Computation;
use crate::families::seed000::blending;
use crate::family::SEED000_NONUNIFORM;
use crate::scalar::{Real, Ring};

/// The printed coefficient formulas over one knot vector.
#[derive(Debug, Clone)]
pub struct NonUniform<T> {
    knots: Vec<T>,
    xi: T,
}

/// The coefficients of the four segment functions on `[n_j, n_{j+1})`, eq. (5).
#[derive(Debug, Clone, PartialEq)]
pub struct SpanCoefficients<T> {
    pub a: T,
    pub b: [T; 4],
    pub c: [T; 4],
    pub d: T,
}

impl<T: Ring> NonUniform<T> {
    /// Formulas over `knots` with parameter `xi`. Knots must be strictly
    /// increasing; the caller checks that for numeric input
    /// ([`crate::knots::check_knots`]).
    pub fn new(knots: Vec<T>, xi: T) -> Self {
        NonUniform { knots, xi }
    }

    fn knot(&self, i: i64, quantity: &str) -> Result<T> {
        usize::try_from(i)
            .ok()
            .and_then(|i| self.knots.get(i))
            .cloned()
            .ok_or_else(|| CoreError::Undefined {
                quantity: quantity.to_string(),
                needs: format!("n_{i}"),
            })
    }

    fn div(num: T, den: T, quantity: String) -> Result<T> {
        if den.is_zero() {
            Err(CoreError::DivisionByZero { quantity })
        } else {
            Ok(num / &den)
        }
    }

    fn int(&self, n: i64) -> T {
        self.xi.int(n)
    }

    /// `q_j = n_{j+1} − n_j`.
    pub fn q(&self, j: i64) -> Result<T> {
        let name = format!("q_{j}");
        Ok(self.knot(j + 1, &name)? - &self.knot(j, &name)?)
    }

    /// `α_j = 1/(q_{j+1} + q_j)`.
    pub fn alpha(&self, j: i64) -> Result<T> {
        Self::div(
            self.int(1),
            self.q(j + 1)? + &self.q(j)?,
            format!("alpha_{j}"),
        )
    }

    /// `β_j = 1/(q_{j−1} + q_{j−2})`.
    pub fn beta(&self, j: i64) -> Result<T> {
        Self::div(
            self.int(1),
            self.q(j - 1)? + &self.q(j - 2)?,
            format!("beta_{j}"),
        )
    }

    /// `γ_j = 2/(q_{j−1} + q_j + q_{j+1})`.
    pub fn gamma(&self, j: i64) -> Result<T> {
        let den = self.q(j - 1)? + &self.q(j)? + &self.q(j + 1)?;
        Self::div(self.int(2), den, format!("gamma_{j}"))
    }

    /// `ψ_j = 6ξ²α_{j−1}q_{j−1}² − 3ξq_j + 10β_{j+1}q_{j+1}²`.
    pub fn psi(&self, j: i64) -> Result<T> {
        let xi = &self.xi;
        Ok(
            self.int(6) * &xi.square() * &self.alpha(j - 1)? * &self.q(j - 1)?.square()
                - &(self.int(3) * xi * &self.q(j)?)
                + &(self.int(10) * &self.beta(j + 1)? * &self.q(j + 1)?.square()),
        )
    }

    /// `φ_j = ψ_{j−2}(q_{j+1} + 1) / (2(β_{j−1}q_{j−1}³ + α_j q_{j+1}²))`.
    pub fn phi(&self, j: i64) -> Result<T> {
        let num = self.psi(j - 2)? * &(self.q(j + 1)? + &self.int(1));
        let den = self.int(2)
            * &(self.beta(j - 1)? * &self.q(j - 1)?.powi(3)
                + &(self.alpha(j)? * &self.q(j + 1)?.square()));
        Self::div(num, den, format!("phi_{j}"))
    }

    /// `a_j = 2α_{j−1}β_{j−2}q_j³ / ψ_{j−2}`.
    pub fn a(&self, j: i64) -> Result<T> {
        let num = self.int(2) * &self.alpha(j - 1)? * &self.beta(j - 2)? * &self.q(j)?.powi(3);
        Self::div(num, self.psi(j - 2)?, format!("a_{j}"))
    }

    /// `d_j = 2β_{j+1}ψ_{j+2} / (α_{j+2}q_j)`.
    pub fn d(&self, j: i64) -> Result<T> {
        let num = self.int(2) * &self.beta(j + 1)? * &self.psi(j + 2)?;
        Self::div(num, self.alpha(j + 2)? * &self.q(j)?, format!("d_{j}"))
    }

    /// `b_{j,k}`, k = 0…3, as printed in (2):
    /// `b_{j,0} = [1 − (ξ² − 3ξ − 1)d_{j+1}]γ_{j+1}(q_{j−1} − q_j)`,
    /// `b_{j,1} = 3γ_{j+1}q_{j−1}²α_j / (2φ_{j−3})`,
    /// `b_{j,2} = (1 − 2ξ)β_{j−1}q_{j−1}b_{j,0} / φ_{j+1}`,
    /// `b_{j,3} = 4ξ[q_{j+1} − q_j]γ_j / (α_{j+2}q_j)`.
    pub fn b(&self, j: i64) -> Result<[T; 4]> {
        let xi = &self.xi;
        let k = xi.square() - &(self.int(3) * xi) - &self.int(1);
        let b0 = (self.int(1) - &(k * &self.d(j + 1)?))
            * &self.gamma(j + 1)?
            * &(self.q(j - 1)? - &self.q(j)?);
        let b1 = Self::div(
            self.int(3) * &self.gamma(j + 1)? * &self.q(j - 1)?.square() * &self.alpha(j)?,
            self.int(2) * &self.phi(j - 3)?,
            format!("b_{{{j},1}}"),
        )?;
        let b2 = Self::div(
            (self.int(1) - &(self.int(2) * xi)) * &self.beta(j - 1)? * &self.q(j - 1)? * &b0,
            self.phi(j + 1)?,
            format!("b_{{{j},2}}"),
        )?;
        let b3 = Self::div(
            self.int(4) * xi * &(self.q(j + 1)? - &self.q(j)?) * &self.gamma(j)?,
            self.alpha(j + 2)? * &self.q(j)?,
            format!("b_{{{j},3}}"),
        )?;
        Ok([b0, b1, b2, b3])
    }

    /// `c_{j,k}`, k = 0…3, as printed in (2):
    /// `c_{j,0} = (q_{j+2} − q_{j+1})α_{j+1}d_{j−1}`,
    /// `c_{j,1} = 12γ_jα_{j+1}q_j³ψ_{j−1}c_{j,0} / φ_{j+1}²`,
    /// `c_{j,2} = 3γ_{j+1}q_{j+1} / (12γ_jα_{j+1}q_j³ψ_{j−1}c_{j,0})`,
    /// `c_{j,3} = −3β_{j−1}(q_{j+2} − q_{j−1})[γ_{j+2}q_{j+1} + α_{j+1}q_j]a_{j+2} / (4φ_{j−1})`.
    pub fn c(&self, j: i64) -> Result<[T; 4]> {
        let c0 = (self.q(j + 2)? - &self.q(j + 1)?) * &self.alpha(j + 1)? * &self.d(j - 1)?;
        let common = self.int(12)
            * &self.gamma(j)?
            * &self.alpha(j + 1)?
            * &self.q(j)?.powi(3)
            * &self.psi(j - 1)?
            * &c0;
        let c1 = Self::div(
            common.clone(),
            self.phi(j + 1)?.square(),
            format!("c_{{{j},1}}"),
        )?;
        let c2 = Self::div(
            self.int(3) * &self.gamma(j + 1)? * &self.q(j + 1)?,
            common,
            format!("c_{{{j},2}}"),
        )?;
        let c3 = Self::div(
            -(self.int(3)
                * &self.beta(j - 1)?
                * &(self.q(j + 2)? - &self.q(j - 1)?)
                * &(self.gamma(j + 2)? * &self.q(j + 1)? + &(self.alpha(j + 1)? * &self.q(j)?))
                * &self.a(j + 2)?),
            self.int(4) * &self.phi(j - 1)?,
            format!("c_{{{j},3}}"),
        )?;
        Ok([c0, c1, c2, c3])
    }

    /// The coefficients of (5) on the span `[n_j, n_{j+1})`.
    pub fn span(&self, j: i64) -> Result<SpanCoefficients<T>> {
        Ok(SpanCoefficients {
            a: self.a(j)?,
            b: self.b(j)?,
            c: self.c(j)?,
            d: self.d(j)?,
        })
    }

    /// The four segment functions of (5) on `[n_j, n_{j+1})` at local angle
    /// atoms `s = sin t_j`, `c = cos t_j`:
    /// `F₀ = d_j l₀`, `F₁ = Σ_k b_{j,k} l_k`, `F₂ = Σ_k c_{j,k} l_k`, `F₃ = a_j l₃`.
    pub fn segment(&self, j: i64, s: &T, c: &T) -> Result<[T; 4]> {
        let co = self.span(j)?;
        let l = blending(s, c, &self.xi);
        Ok([co.d * &l[0], dot(&co.b, &l), dot(&co.c, &l), co.a * &l[3]])
    }

    /// The B-spline basis function `F_j` of (1) on its `piece`-th interval
    /// (`0…3`: `[n_{j+piece}, n_{j+piece+1})`) at local angle atoms:
    /// `a_j l₃`, `Σ c_{j+1,k} l_k`, `Σ b_{j+2,k} l_k`, `d_{j+3} l₀`.
    pub fn bspline_piece(&self, j: i64, piece: usize, s: &T, c: &T) -> Result<T> {
        let l = blending(s, c, &self.xi);
        match piece {
            0 => Ok(self.a(j)? * &l[3]),
            1 => Ok(dot(&self.c(j + 1)?, &l)),
            2 => Ok(dot(&self.b(j + 2)?, &l)),
            3 => Ok(self.d(j + 3)? * &l[0]),
            _ => Err(CoreError::Count {
                what: "B-spline piece index".into(),
                expected: 4,
                got: piece,
            }),
        }
    }
}

/// `Σ_k w_k l_k`.
fn dot<T: Ring>(w: &[T; 4], l: &[T; 4]) -> T {
    let mut terms = w.iter().zip(l).map(|(wk, lk)| wk.clone() * lk);
    let first = terms.next().expect("four terms");
    terms.fold(first, |acc, x| acc + &x)
}

/// The four segment functions of one span at an exact local coordinate,
/// over exact knots (a [`Computation`]; the local angle is
/// `t_j = local·π/2`). The caller has checked the knots and the span's
/// printed coefficients exactly.
#[derive(Debug, Clone)]
pub struct SpanAt {
    pub knots: Vec<Rational>,
    pub span: usize,
    pub local: Rational,
    pub zeta: Rational,
}

impl Computation for SpanAt {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        self.knots
            .iter()
            .enumerate()
            .map(|(i, k)| (format!("knot n_{i}"), k))
            .chain([("zeta".to_string(), &self.zeta)])
            .collect()
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>> {
        let local = make(&self.local);
        let theta = local.clone() * &SEED000_NONUNIFORM.variable.end(&local);
        let (s, c) = theta.sin_cos();
        let formulas = NonUniform::new(self.knots.iter().map(make).collect(), make(&self.zeta));
        Ok(formulas.segment(self.span as i64, &s, &c)?.to_vec())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn uniform_knots(n: i64) -> Vec<f64> {
        (0..n).map(|k| k as f64).collect()
    }

    #[test]
    fn uniform_knots_make_c_j2_divide_by_zero_as_printed() {
        // q constant ⇒ c_{j,0} = (q_{j+2} − q_{j+1})·… = 0, and c_{j,2} divides by it.
        let f = NonUniform::new(uniform_knots(20), 1.0);
        assert_eq!(
            f.c(9).unwrap_err(),
            CoreError::DivisionByZero {
                quantity: "c_{9,2}".into()
            }
        );
        // b_{j,0} carries the factor (q_{j−1} − q_j) = 0.
        assert_eq!(f.b(9).unwrap()[0], 0.0);
    }

    #[test]
    fn formulas_reaching_outside_the_knots_are_undefined() {
        let f = NonUniform::new(uniform_knots(5), 1.0);
        assert!(matches!(f.a(0), Err(CoreError::Undefined { .. })));
        assert_eq!(f.q(2).unwrap(), 1.0);
    }

    #[test]
    fn uniform_quantities_match_hand_values() {
        // unit spacing: α = 1/2, β = 1/2, γ = 2/3, ψ = 6ξ²/2 − 3ξ + 10/2 = 3ξ² − 3ξ + 5
        let f = NonUniform::new(uniform_knots(20), 2.0);
        assert_eq!(f.alpha(9).unwrap(), 0.5);
        assert_eq!(f.beta(9).unwrap(), 0.5);
        assert!((f.gamma(9).unwrap() - 2.0 / 3.0).abs() < 1e-15);
        assert_eq!(f.psi(9).unwrap(), 11.0);
    }
}
