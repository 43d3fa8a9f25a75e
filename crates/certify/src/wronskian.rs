//! Total positivity by Wronskians (Karlin's criterion), for bases the
//! totally positive factorisation does not take: the variable beside
//! `sin`, `cos` or `exp` (C- and H-Bézier curves), domains `[0, α]`.
//!
//! `W(b_j, …, b_l) = det[b_k⁽ⁱ⁾]` (`0 ≤ i ≤ l − j`, derivatives in the
//! variable). When every Wronskian of consecutive functions is `> 0` on
//! the open domain `(a, b)`:
//! * each run `(b_j, …, b_l)` has positive Wronskians of its initial runs,
//!   so it is an extended complete Chebyshev system on `(a, b)` (Karlin &
//!   Studden, *Tchebycheff Systems*, 1966, Ch. XI, Thm 1.1): its
//!   collocation determinant at points `x₀ < ⋯ < x_{l−j}` of `(a, b)` is
//!   `> 0`;
//! * so every collocation matrix at points of `(a, b)` has all minors of
//!   consecutive columns `> 0`, among them all minors of consecutive rows
//!   and columns, and by Fekete's criterion all its minors are `> 0`
//!   (strictly totally positive; Karlin, *Total Positivity*, 1968, Ch. 2);
//! * minors at points of `[a, b]` are limits of those: `≥ 0`, the basis is
//!   totally positive on `[a, b]`.
//!
//! Conversely a Wronskian of consecutive functions `< 0` at a point `x` of
//! `(a, b)` refutes total positivity: at coalescing points `x, x + h, …,
//! x + mh` the collocation minor of the run is
//! `h^{m(m+1)/2}·Π_{k≤m} k!⁻¹·Π_{i<i′}(i′ − i)·(W(x) + O(h))`, negative
//! for small `h`.
//!
//! Each sign is decided by the branch and bound ([`crate::branch`]) on the
//! open domain, factor by factor of the Wronskian's exact quotient: every
//! factor must keep one strict sign there.

use trig_core::Domain;
use trig_symbolic::Sym;

use crate::atoms::d_variable;
use crate::branch::{self, Axis, Outcome};
use crate::factors::{self, Sign, flip};

/// Most functions of one Wronskian (its determinant is expanded: `n!`
/// products).
pub const MAX_FUNCTIONS: usize = 6;

/// `W(f₀, …, f_m) = det[f_k⁽ⁱ⁾]`, derivatives in the variable of `domain`.
pub fn wronskian(fs: &[Sym], domain: &Domain) -> Sym {
    let mut rows = vec![fs.to_vec()];
    for _ in 1..fs.len() {
        let next = rows[rows.len() - 1]
            .iter()
            .map(|f| d_variable(f, domain))
            .collect();
        rows.push(next);
    }
    Sym::determinant(&rows)
}

/// One Wronskian of consecutive functions `b_first, …, b_last` and what was
/// decided of its sign on the open domain, for every parameter: `> 0`
/// proved, `< 0` at a certified point (the numerator of `W = N/D` times
/// the sign of `D` there), or undecided.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    pub first: usize,
    pub last: usize,
    pub wronskian: Sym,
    pub sign: Outcome,
}

/// The criterion on the whole basis: the runs decided in order of length
/// (the `1 × 1` runs are the functions), stopping at the first run not
/// proved positive.
#[derive(Debug, Clone, PartialEq)]
pub struct Criterion {
    pub runs: Vec<Run>,
}

impl Criterion {
    /// Every consecutive Wronskian proved `> 0`: totally positive.
    pub fn proved(&self, functions: usize) -> bool {
        self.runs.len() == functions * (functions + 1) / 2
            && self
                .runs
                .iter()
                .all(|r| matches!(r.sign, Outcome::Proved { .. }))
    }

    /// The run whose Wronskian is negative at a point, if any.
    pub fn refuting(&self) -> Option<&Run> {
        self.runs
            .iter()
            .find(|r| matches!(r.sign, Outcome::Negative { .. }))
    }

    /// Box evaluations spent on the proved runs.
    pub fn boxes(&self) -> usize {
        self.runs
            .iter()
            .map(|r| match r.sign {
                Outcome::Proved { boxes } => boxes,
                _ => 0,
            })
            .sum()
    }
}

/// Decides the sign of every Wronskian of consecutive functions of `fs`
/// on the open domain for every parameter in `axes`, shortest runs first
/// (a failing function is found before any determinant is expanded); `Err`
/// when a run is longer than [`MAX_FUNCTIONS`].
pub fn consecutive(fs: &[Sym], domain: &Domain, axes: &[Axis]) -> Result<Criterion, String> {
    let n = fs.len();
    if n > MAX_FUNCTIONS {
        return Err(format!(
            "the Wronskians are expanded for at most {MAX_FUNCTIONS} functions ({n} here)"
        ));
    }
    let mut runs = Vec::new();
    for len in 1..=n {
        let this: Vec<(usize, Sym)> = (0..=n - len)
            .map(|first| (first, wronskian(&fs[first..first + len], domain)))
            .collect();
        let signs = trig_core::parallel::map(&this, |(_, w)| sign_inside(w, domain, axes));
        for ((first, w), sign) in this.into_iter().zip(signs) {
            let stop = !matches!(sign, Outcome::Proved { .. });
            runs.push(Run {
                first,
                last: first + len - 1,
                wronskian: w,
                sign,
            });
            if stop {
                return Ok(Criterion { runs });
            }
        }
    }
    Ok(Criterion { runs })
}

/// The sign of `w` on the open domain: every denominator factor of one
/// strict sign on the closed domain (the quotient is defined), every
/// numerator factor of one strict sign on the open domain, the product
/// `+`; a factor found negative where the product should be positive gives
/// the whole numerator's counterexample.
fn sign_inside(w: &Sym, domain: &Domain, axes: &[Axis]) -> Outcome {
    if w.is_zero() {
        return Outcome::Undecided("the Wronskian vanishes identically".into());
    }
    let mut denominator = Sign::Plus;
    let mut boxes = 0;
    for (factor, e) in w.denominator() {
        let g = Sym::from_poly(factor.clone());
        match factors::sign_of(&g, domain, axes, true) {
            Ok((s, b)) => {
                boxes += b;
                if e % 2 == 1 && s == Sign::Minus {
                    denominator = flip(denominator);
                }
            }
            Err(why) => {
                return Outcome::Undecided(format!(
                    "the sign of its denominator factor {g} was not proved: {why}"
                ));
            }
        }
    }
    let q = Sym::from_poly(w.numerator().clone()).factored();
    let mut sign = if q.unit < 0 {
        flip(denominator)
    } else {
        denominator
    };
    for (factor, e) in &q.num {
        let g = Sym::from_poly(factor.clone());
        let s = match branch::positive_inside(&g, domain, axes) {
            Outcome::Proved { boxes: b } => {
                boxes += b;
                Sign::Plus
            }
            up => match branch::positive_inside(&-g.clone(), domain, axes) {
                Outcome::Proved { boxes: b } => {
                    boxes += b;
                    Sign::Minus
                }
                Outcome::Undecided(why) => return undecided_factor(&g, &why),
                Outcome::Negative { .. } => match up {
                    Outcome::Undecided(why) => return undecided_factor(&g, &why),
                    // the factor changes sign inside: where the whole
                    // numerator is negative, if anywhere, is searched once
                    _ => return whole_numerator(w, denominator, domain, axes),
                },
            },
        };
        if e % 2 == 1 && s == Sign::Minus {
            sign = flip(sign);
        }
    }
    if sign == Sign::Plus {
        Outcome::Proved { boxes }
    } else {
        // every factor strictly signed and the product negative: `W < 0`
        // everywhere inside; the whole numerator gives the point
        whole_numerator(w, denominator, domain, axes)
    }
}

/// A factor whose sign was not decided, named when it is short.
fn undecided_factor(g: &Sym, why: &str) -> Outcome {
    let text = g.to_unicode();
    let named = if text.chars().count() <= 60 {
        format!("its factor {text}")
    } else {
        "a factor of its numerator".to_string()
    };
    Outcome::Undecided(format!("the sign of {named}: {why}"))
}

/// The numerator of `w`, signed by its denominator (`sign`), decided as a
/// whole: positive inside, or a certified negative point.
fn whole_numerator(w: &Sym, sign: Sign, domain: &Domain, axes: &[Axis]) -> Outcome {
    let n = Sym::from_poly(w.numerator().clone());
    let signed = if sign == Sign::Minus { -n } else { n };
    branch::positive_inside(&signed, domain, axes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Ring, Variable};

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    fn poly() -> Domain {
        Domain::from_variable(Variable::Polynomial, &[])
    }

    fn bernstein(n: u32) -> Vec<Sym> {
        let t = v("t");
        let u = Sym::one() - &t;
        (0..=n)
            .map(|i| {
                let c = (0..i).fold(1u64, |c, k| c * u64::from(n - k) / u64::from(k + 1));
                Sym::int(c as i64) * &t.powi(i) * &u.powi(n - i)
            })
            .collect()
    }

    #[test]
    fn the_wronskian_of_the_monomials_is_the_product_of_factorials() {
        let t = v("t");
        let fs = vec![Sym::one(), t.clone(), t.powi(2), t.powi(3)];
        assert!(wronskian(&fs, &poly()).equals(&Sym::int(12)));
    }

    #[test]
    fn bernstein_bases_are_totally_positive_by_their_wronskians() {
        for n in [2, 3, 5] {
            let c = consecutive(&bernstein(n), &poly(), &[]).expect("small basis");
            assert!(c.proved(n as usize + 1), "degree {n}: {c:?}");
            assert!(c.refuting().is_none());
        }
    }

    #[test]
    fn a_negative_wronskian_refutes_and_stops() {
        // b1 = t(t − 1/2) < 0 on (0, 1/2): a negative 1 × 1 run, found
        // before any longer Wronskian is decided
        let t = v("t");
        let half = Sym::rational(rug::Rational::from((1, 2)));
        let fs = vec![Sym::one() - &t, t.clone() * &(t.clone() - &half)];
        let c = consecutive(&fs, &poly(), &[]).expect("small basis");
        let run = c.refuting().expect("t² − t/2 < 0 near t = 0");
        assert_eq!((run.first, run.last), (1, 1));
        assert!(!c.proved(2));
    }

    #[test]
    fn a_dependent_pair_is_undecided_not_refuted() {
        let t = v("t");
        let fs = vec![t.clone(), t.clone() * &Sym::int(2)];
        let c = consecutive(&fs, &poly(), &[]).expect("small basis");
        assert!(c.refuting().is_none() && !c.proved(2));
        assert!(
            matches!(c.runs.last().map(|r| &r.sign), Some(Outcome::Undecided(why)) if why.contains("identically"))
        );
    }

    #[test]
    fn seven_functions_are_refused_with_the_limit() {
        let why = consecutive(&bernstein(6), &poly(), &[]).expect_err("7 functions");
        assert!(why.contains("at most 6"), "{why}");
    }
}
