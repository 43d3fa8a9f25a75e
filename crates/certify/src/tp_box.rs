//! Total positivity for every parameter vector of a box — any number of
//! shape parameters.
//!
//! The same factorisation as [`crate::total_positivity`]: with
//! `z = tan(θ/2)` (or `t`) the numerators over their positive common
//! factor are written in the Bernstein basis of their degree,
//! `σⱼNⱼ = Σₖ C_{jk} B^d_k(z)`, and all minors of `C` `≥ 0` prove total
//! positivity (Cauchy–Binet with the totally positive Bernstein basis).
//! Here each entry `C_{jk}` is a polynomial in all the parameters, and so
//! is each minor; each nonzero minor is certified `≥ 0` on the box by
//! exact Bernstein subdivision in the parameters ([`crate::nonneg`]), or a
//! rational parameter vector where it is negative is found — where the
//! certificate fails, and where a negative collocation minor may refute.

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use crate::domain::ParamBox;
use crate::minors::{all_minors, elevate_rows, power_to_bernstein};
use crate::nonneg::{BoxCertificate, certify_box};
use crate::total_positivity::{MAX_ELEVATION, numerators};

/// What the minors of the certificate say on the box.
#[derive(Debug, Clone, PartialEq)]
pub enum BoxOutcome {
    /// Every nonzero minor is `≥ 0` on the whole box (proved).
    Covers { boxes: usize },
    /// The minor of these rows and columns is negative at `point` (the
    /// parameters in order): the certificate fails there.
    Negative {
        rows: Vec<usize>,
        cols: Vec<usize>,
        point: Vec<Rational>,
        value: Rational,
    },
    /// A minor could not be decided (the reason).
    Undecided(String),
}

/// The certificate at the degree where it went furthest.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxTpCertificate {
    /// The degree of the numerators (before elevation).
    pub first_degree: usize,
    /// The degree of the Bernstein basis of the final matrix.
    pub degree: usize,
    /// Rows (functions) of the coefficient matrix.
    pub functions: usize,
    /// The positive common factor divided out, as text.
    pub common: String,
    /// The nonzero minors checked at the final degree.
    pub minors: usize,
    pub outcome: BoxOutcome,
}

/// Bernstein coefficients of degree `d` of `n(z, p)`, each a polynomial in
/// the parameters.
fn bernstein_row(n: &Poly, d: usize) -> Vec<Poly> {
    power_to_bernstein(&n.coefficients_in("z"), d)
}

/// Decides every minor of the factorisation of `fs` on the product of
/// `params`, elevating the degree up to [`MAX_ELEVATION`] times while a
/// minor is negative somewhere.
pub fn certify(
    fs: &[Sym],
    trigonometric: bool,
    params: &[(&str, ParamBox)],
) -> Result<BoxTpCertificate, String> {
    let common = numerators(fs, trigonometric, params)?;
    let first_degree = common.degree;
    let mut degree = first_degree;
    let mut rows: Vec<Vec<Poly>> = common
        .numerators
        .iter()
        .map(|n| bernstein_row(n, degree))
        .collect();
    loop {
        let ms = all_minors(&rows).map_err(|e| e.to_string())?;
        let mut outcome = BoxOutcome::Covers { boxes: 0 };
        let mut total = 0;
        // the smallest minors first: they are cheapest and fail first
        for m in &ms {
            match certify_box(&Sym::from_poly(m.value.clone()), false, params) {
                BoxCertificate::NonNegative { boxes } => total += boxes,
                BoxCertificate::Counterexample { params, value, .. } => {
                    outcome = BoxOutcome::Negative {
                        rows: m.rows.clone(),
                        cols: m.cols.clone(),
                        point: params,
                        value,
                    };
                    break;
                }
                BoxCertificate::Pole(why) | BoxCertificate::Undecided(why) => {
                    outcome = BoxOutcome::Undecided(format!(
                        "the minor of rows {:?} and columns {:?} ({}) was not decided: {why}",
                        m.rows, m.cols, m.value
                    ));
                    break;
                }
            }
        }
        if let BoxOutcome::Covers { boxes } = &mut outcome {
            *boxes = total;
        }
        let done = matches!(outcome, BoxOutcome::Covers { .. });
        if done || degree >= first_degree + MAX_ELEVATION {
            return Ok(BoxTpCertificate {
                first_degree,
                degree,
                functions: rows.len(),
                common: common.text,
                minors: ms.len(),
                outcome,
            });
        }
        rows = elevate_rows(&rows, degree);
        degree += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    /// `b0 = B0 + a·B1`, `b1 = (1 − a − b)·B1`, `b2 = B2 + b·B1` in the
    /// quadratic Bernstein basis `Bₖ`: the coefficient matrix
    /// `[[1, a, 0], [0, 1 − a − b, 0], [0, b, 1]]` has the nonzero minors
    /// `1, a, b, 1 − a − b` (and their products), all `≥ 0` exactly on the
    /// triangle `a, b ≥ 0, a + b ≤ 1`.
    fn two_parameter_basis() -> Vec<Sym> {
        let t = Sym::var("t");
        let u = Sym::one() - &t;
        let (a, b) = (Sym::var("a"), Sym::var("b"));
        let b1 = Sym::int(2) * &t * &u;
        vec![
            u.clone() * &u + &(a.clone() * &b1),
            (Sym::one() - &a - &b) * &b1,
            t.clone() * &t + &(b * &b1),
        ]
    }

    #[test]
    fn bernstein_rows_reproduce_the_polynomial() {
        // t² in degree 2: (0, 0, 1)
        let row = bernstein_row(&(Poly::var("z") * &Poly::var("z")), 2);
        assert_eq!(row, vec![Poly::zero(), Poly::zero(), Poly::one()]);
        // 1 in degree 3: all ones
        let row = bernstein_row(&Poly::one(), 3);
        assert!(row.iter().all(|c| *c == Poly::one()));
    }

    #[test]
    fn two_parameters_decided_on_a_box() {
        let fs = two_parameter_basis();
        let square = |hi: Rational| {
            certify(
                &fs,
                false,
                &[
                    ("a", ParamBox::closed(q(0, 1), hi.clone())),
                    ("b", ParamBox::closed(q(0, 1), hi)),
                ],
            )
            .expect("factorisation")
        };
        let inside = square(q(1, 2));
        assert!(
            matches!(inside.outcome, BoxOutcome::Covers { .. }),
            "{inside:?}"
        );
        // on [0, 1]² the minor 1 − a − b is negative at a point with a + b > 1
        let outside = square(q(1, 1));
        let BoxOutcome::Negative { point, value, .. } = &outside.outcome else {
            panic!("{outside:?}");
        };
        assert!(*value < 0);
        assert!(Rational::from(&point[0] + &point[1]) > 1, "{point:?}");
    }
}
