//! Certified number of maxima of a function on its whole domain.
//!
//! For `f(θ)` on `[0, π/2]` (or `f(t)` on `[0, 1]`), the derivative `f'` is
//! a polynomial in `s = sin θ`, `c = cos θ`. With `z = tan(θ/2)` it becomes
//! `N(z) / ((1+z²)^k)` times a positive constant, and `dθ/dz = 2/(1+z²) > 0`,
//! so `f'` has the sign of `N(z)` on `z ∈ [0, 1]`. The distinct roots of `N`
//! in `(0, 1)` are isolated exactly (Sturm sequences over ℚ,
//! [`crate::sturm`]); the sign of `N` between them is evaluated exactly at
//! rational points. `f` has a local maximum at an interior sign change
//! `+ → −`, at `θ = 0` when `f' < 0` just after it, and at `θ = π/2` when
//! `f' > 0` just before it. "Exactly one maximum" is: exactly one such point.

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use crate::sturm::UPoly;
use crate::{describe_z, in_z};

/// Where a local maximum lies.
#[derive(Debug, Clone, PartialEq)]
pub enum Maximum {
    /// At the left end of the domain (`f' < 0` just after it).
    Start,
    /// At the right end (`f' > 0` just before it).
    End,
    /// At the unique root of the derivative in `[lo, hi]` (`z` or `t`
    /// coordinates), where `f'` changes sign from `+` to `−`.
    Interior(Rational, Rational),
}

/// The sign pattern of `f'` on the open domain and the maxima of `f`.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Signs (`±1`) of `f'` on the pieces between consecutive roots.
    pub signs: Vec<i32>,
    /// Isolating intervals of the roots of `f'` in the open domain.
    pub roots: Vec<(Rational, Rational)>,
    /// The local maxima, left to right.
    pub maxima: Vec<Maximum>,
}

/// The exact numerator of `g` in `z` (trigonometric) or `t`, signed so that
/// it has the sign of `g` on the domain; an error when `g` depends on other
/// symbols or on a denominator that may vanish.
fn signed_numerator(g: &Sym, trigonometric: bool) -> Result<UPoly, String> {
    let gz = in_z(g, trigonometric);
    let zz = Poly::var("z") * &Poly::var("z") + &Poly::one();
    for factor in gz.denominator().keys() {
        if *factor != zz {
            return Err(format!("denominator factor {factor} is not 1 + z²"));
        }
    }
    UPoly::from_poly(gz.numerator(), "z")
        .ok_or_else(|| {
            format!(
                "the derivative depends on symbols other than the variable (z = tan(θ/2), or t): the maxima are counted for fixed parameter values (a claim's `at`): {gz}"
            )
        })
}

/// The derivative's sign profile and the maxima of `f` on its domain.
pub fn profile(f: &Sym, trigonometric: bool) -> Result<Profile, String> {
    let d = if trigonometric { f.d_angle() } else { f.d_t() };
    let n = signed_numerator(&d, trigonometric)?;
    if n.is_zero() {
        return Err("the function is constant: every point is a maximum".into());
    }
    let (zero, one) = (Rational::new(), Rational::from(1));
    let roots = n.isolate(&zero, &one);
    // one sample point per piece: between intervals (a shared endpoint of
    // two intervals is not a root), and inside the first and last pieces
    let mut cuts = vec![zero.clone()];
    for (lo, hi) in &roots {
        cuts.push(lo.clone());
        cuts.push(hi.clone());
    }
    cuts.push(one);
    let signs: Vec<i32> = cuts
        .chunks(2)
        .map(|w| {
            let x = if w[0] == w[1] {
                w[0].clone()
            } else {
                (w[0].clone() + &w[1]) / 2u32
            };
            n.sign_at(&x)
        })
        .collect();
    debug_assert!(signs.iter().all(|s| *s != 0));
    let mut maxima = Vec::new();
    if signs[0] < 0 {
        maxima.push(Maximum::Start);
    }
    for (k, (lo, hi)) in roots.iter().enumerate() {
        if signs[k] > 0 && signs[k + 1] < 0 {
            maxima.push(Maximum::Interior(lo.clone(), hi.clone()));
        }
    }
    if signs[signs.len() - 1] > 0 {
        maxima.push(Maximum::End);
    }
    Ok(Profile {
        signs,
        roots,
        maxima,
    })
}

impl Maximum {
    /// Where the maximum lies, in `θ` (trigonometric) or `t`.
    pub fn describe(&self, trigonometric: bool) -> String {
        let (start, end) = if trigonometric {
            ("θ = 0", "θ = π/2")
        } else {
            ("t = 0", "t = 1")
        };
        match self {
            Maximum::Start => start.into(),
            Maximum::End => end.into(),
            Maximum::Interior(lo, hi) if lo == hi => describe_z(lo, trigonometric),
            Maximum::Interior(lo, hi) => {
                let var = if trigonometric { "z = tan(θ/2)" } else { "t" };
                let at = |z: &Rational| {
                    if trigonometric {
                        2.0 * z.to_f64().atan()
                    } else {
                        z.to_f64()
                    }
                };
                format!(
                    "{var} ∈ ({lo}, {hi}) ({} ∈ ({:.6}, {:.6}))",
                    if trigonometric { "θ" } else { "t" },
                    at(lo),
                    at(hi)
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s() -> Sym {
        Sym::var("s")
    }
    fn c() -> Sym {
        Sym::var("c")
    }

    #[test]
    fn sin_two_theta_has_one_interior_maximum() {
        // 2sc = sin 2θ: maximum at θ = π/4, z = tan(π/8) = √2 − 1 (irrational)
        let p = profile(&(Sym::int(2) * &s() * &c()), true).unwrap();
        assert_eq!(p.signs, vec![1, -1]);
        match &p.maxima[..] {
            [Maximum::Interior(lo, hi)] => {
                let r = 2f64.sqrt() - 1.0;
                assert!(lo.to_f64() < r && r < hi.to_f64(), "{lo} {hi}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn one_minus_sin_two_theta_has_two_maxima() {
        // (s − c)² = 1 − sin 2θ: maxima at both ends, a minimum at π/4
        let f = (s() - &c()) * &(s() - &c());
        let p = profile(&f, true).unwrap();
        assert_eq!(p.maxima, vec![Maximum::Start, Maximum::End]);
    }

    #[test]
    fn a_double_root_of_the_derivative_is_not_a_maximum() {
        // f = (t − 1/2)³: f' = 3(t − 1/2)² ≥ 0, increasing, one maximum at t = 1
        let half = Sym::rational(Rational::from((1, 2)));
        let x = Sym::var("t") - &half;
        let p = profile(&(x.clone() * &x * &x), false).unwrap();
        assert_eq!(p.signs, vec![1, 1]);
        assert_eq!(p.maxima, vec![Maximum::End]);
        // f = −(t − 1/2)²: one interior maximum, at t = 1/2
        let q = profile(&-(x.clone() * &x), false).unwrap();
        match &q.maxima[..] {
            [Maximum::Interior(lo, hi)] => {
                assert!(*lo <= Rational::from((1, 2)) && Rational::from((1, 2)) <= *hi)
            }
            other => panic!("{other:?}"),
        }
        assert!(profile(&Sym::int(3), false).is_err());
    }
}
