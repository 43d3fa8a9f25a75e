//! Resultants in one variable of polynomials whose coefficients are
//! polynomials in the others: the determinant of the Sylvester matrix,
//! computed by Bareiss' fraction-free elimination (every division exact).
//!
//! `Res_z(A, B)` vanishes at every parameter value where `A` and `B` have a
//! common root in `z` (with formal degrees; it also vanishes where both
//! leading coefficients do). With `B = ∂A/∂z` this is the discriminant
//! condition: a double root of `A` in `z`.

use trig_symbolic::{Monomial, Poly};

/// `Σ cᵢ varⁱ` from coefficients.
pub fn from_coefficients(cs: &[Poly], var: &str) -> Poly {
    cs.iter().enumerate().fold(Poly::zero(), |acc, (i, c)| {
        let power = Poly::term(
            Monomial::var(trig_symbolic::Var::new(var), i as u32),
            rug::Rational::from(1),
        );
        acc + &(c * &power)
    })
}

/// `Res_var(a, b)` (degrees as they are; zero when either is zero).
pub fn resultant(a: &Poly, b: &Poly, var: &str) -> Poly {
    let (ca, cb) = (a.coefficients_in(var), b.coefficients_in(var));
    let (m, n) = (ca.len() - 1, cb.len() - 1);
    if a.is_zero() || b.is_zero() {
        return Poly::zero();
    }
    if m == 0 {
        return a.pow(n as u32);
    }
    if n == 0 {
        return b.pow(m as u32);
    }
    let size = m + n;
    // rows 0..n: shifts of a; rows n..n+m: shifts of b; highest power first
    let mut rows = vec![vec![Poly::zero(); size]; size];
    for (i, row) in rows.iter_mut().enumerate().take(n) {
        for (k, c) in ca.iter().rev().enumerate() {
            row[i + k] = c.clone();
        }
    }
    for i in 0..m {
        for (k, c) in cb.iter().rev().enumerate() {
            rows[n + i][i + k] = c.clone();
        }
    }
    determinant(rows)
}

/// Bareiss' fraction-free determinant.
fn determinant(mut a: Vec<Vec<Poly>>) -> Poly {
    let size = a.len();
    let mut sign = false;
    let mut prev = Poly::one();
    for k in 0..size {
        let Some(pivot) = (k..size).find(|&i| !a[i][k].is_zero()) else {
            return Poly::zero();
        };
        if pivot != k {
            a.swap(pivot, k);
            sign = !sign;
        }
        for i in k + 1..size {
            for j in k + 1..size {
                let num = &a[k][k] * &a[i][j] - &(&a[i][k] * &a[k][j]);
                a[i][j] = num.exact_div(&prev).expect("Bareiss division is exact");
            }
            a[i][k] = Poly::zero();
        }
        prev = a[k][k].clone();
    }
    let det = a[size - 1][size - 1].clone();
    if sign { -det } else { det }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Poly {
        Poly::var(n)
    }

    #[test]
    fn discriminant_of_a_quadratic() {
        // a = z² + p z + 1: Res(a, a') = −(p² − 4) up to the sign convention
        let z = v("z");
        let a = &z * &z + &(&v("p") * &z) + &Poly::one();
        let r = resultant(&a, &a.diff("z"), "z");
        let expected = &v("p") * &v("p") - &Poly::int(4);
        assert!(r == expected || r == -expected.clone(), "{r}");
    }

    #[test]
    fn common_roots_make_the_resultant_vanish() {
        // (z − p)(z − 1) and (z − 2): resultant (2 − p)(2 − 1) up to sign
        let z = v("z");
        let a = (&z - &v("p")) * &(&z - &Poly::one());
        let b = &z - &Poly::int(2);
        let r = resultant(&a, &b, "z");
        let expected = Poly::int(2) - &v("p");
        assert!(r == expected || r == -expected.clone(), "{r}");
        assert_eq!(from_coefficients(&a.coefficients_in("z"), "z"), a);
    }
}
