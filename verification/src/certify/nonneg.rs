//! Nonnegativity of a function on its whole domain for a box of one shape
//! parameter, and the maximal interval of the parameter on which a family
//! is nonnegative.

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use super::bernstein::{Power, Sign, sign_on_unit_box};

/// Halvings allowed per test before giving up on a box: deep for a single
/// parameter value (one dimension, cheap), shallower for parameter boxes.
pub const MAX_DEPTH_POINT: u32 = 96;
/// See [`MAX_DEPTH_POINT`].
pub const MAX_DEPTH_BOX: u32 = 48;

/// A set of parameter values: a closed interval, or a half-line `[lo, ∞)`
/// (mapped to `[0, 1)` by `p = lo + y/(1 − y)`).
#[derive(Debug, Clone, PartialEq)]
pub enum ParamBox {
    Interval(Rational, Rational),
    FromTo(Rational),
}

/// Outcome of a nonnegativity test.
#[derive(Debug, Clone, PartialEq)]
pub enum Certificate {
    /// Proved `f ≥ 0` on the whole domain and parameter box.
    NonNegative { boxes: usize },
    /// `f < 0` at this exact point: parameter `p`, `z = tan(θ/2)` (or `t`),
    /// with `s`, `c` and the value, all exact.
    Counterexample {
        p: Rational,
        z: Rational,
        value: Rational,
    },
    /// Not decided (depth limit, or a denominator changing sign).
    Undecided(String),
}

/// `2z/(1+z²)`, `(1−z²)/(1+z²)`.
fn weierstrass() -> (Sym, Sym) {
    let z = Sym::var("z");
    let d = Sym::one() + &(z.clone() * &z);
    let s = Sym::int(2) * &z / &d;
    let c = (Sym::one() - &(z.clone() * &z)) / &d;
    (s, c)
}

/// `f` in `z` (and the parameter): Weierstrass for trigonometric functions,
/// `t = z` for polynomial ones.
pub fn in_z(f: &Sym, trigonometric: bool) -> Sym {
    if trigonometric {
        let (s, c) = weierstrass();
        f.subs("s", &s).subs("c", &c)
    } else {
        f.subs("t", &Sym::var("z"))
    }
}

/// Exact value of `f` at a parameter value and a `z` (exact, rational).
pub fn value_at(fz: &Sym, param: Option<&str>, p: &Rational, z: &Rational) -> Option<Rational> {
    fz.eval_rational(&|name: &str| match name {
        "z" => Some(z.clone()),
        n if Some(n) == param => Some(p.clone()),
        _ => None,
    })
    .ok()
}

/// Power coefficients of `poly(z, p)` over `[0,1]²` after mapping the box to
/// `y ∈ [0,1]`. For a half-line, the `(1 − y)` denominators are cleared
/// (they are positive on `[0, 1)`).
fn power(poly: &Poly, param: Option<&str>, bx: &ParamBox) -> Power {
    let p_of_y = |_: ()| -> Sym {
        let y = Sym::var("y");
        match bx {
            ParamBox::Interval(lo, hi) => {
                Sym::rational(lo.clone()) + &(Sym::rational(hi.clone() - lo) * &y)
            }
            ParamBox::FromTo(lo) => Sym::rational(lo.clone()) + &(y.clone() / &(Sym::one() - &y)),
        }
    };
    let mut e = Sym::from_poly(poly.clone());
    if let Some(name) = param {
        e = e.subs(name, &p_of_y(()));
    }
    let num = e.numerator().clone();
    let (n, m) = (num.degree_in("z") as usize, num.degree_in("y") as usize);
    let mut a = vec![vec![Rational::new(); m + 1]; n + 1];
    for (mono, q) in num.terms() {
        a[mono.exponent("z") as usize][mono.exponent("y") as usize] += q;
    }
    a
}

/// The parameter value at `y` of the box.
fn param_at(bx: &ParamBox, y: &Rational) -> Rational {
    match bx {
        ParamBox::Interval(lo, hi) => lo.clone() + (hi.clone() - lo) * y,
        ParamBox::FromTo(lo) => lo.clone() + y.clone() / (Rational::from(1) - y),
    }
}

/// Decides `f(θ; p) ≥ 0` for every `θ ∈ [0, π/2]` (every `t ∈ [0, 1]`) and
/// every `p` in the box. `param` is `None` for families without parameters.
pub fn certify(f: &Sym, trigonometric: bool, param: Option<&str>, bx: &ParamBox) -> Certificate {
    let fz = in_z(f, trigonometric);
    // Denominator factors: powers of 1 + z² are positive; parameter factors
    // must keep one sign on the box.
    let mut flip = false;
    let zz = Poly::var("z") * &Poly::var("z") + &Poly::one();
    for (factor, e) in fz.denominator() {
        // strip the positive factor 1 + z² (the ring does not factor, so it
        // may be merged with a parameter factor)
        let mut factor = factor.clone();
        while factor.degree_in("z") > 0 {
            match factor.exact_div(&zz) {
                Some(q) => factor = q,
                None => {
                    return Certificate::Undecided(format!(
                        "denominator factor {factor} depends on z"
                    ));
                }
            }
        }
        if factor.as_constant().is_some() {
            flip ^= factor.as_constant().is_some_and(|q| q < 0) && e % 2 == 1;
            continue;
        }
        let positive = |f: &Poly| {
            matches!(
                sign_on_unit_box(&power(f, param, bx), MAX_DEPTH_BOX, true),
                Sign::NonNegative { .. }
            )
        };
        if positive(&factor) {
            continue;
        }
        if positive(&-factor.clone()) {
            flip ^= e % 2 == 1;
            continue;
        }
        return Certificate::Undecided(format!(
            "cannot fix the sign of the denominator factor {factor} on the box"
        ));
    }
    let num = if flip {
        -fz.numerator().clone()
    } else {
        fz.numerator().clone()
    };
    if num.is_zero() {
        return Certificate::NonNegative { boxes: 0 };
    }
    let a = power(&num, param, bx);
    let depth = if a[0].len() == 1 {
        MAX_DEPTH_POINT
    } else {
        MAX_DEPTH_BOX
    };
    match sign_on_unit_box(&a, depth, false) {
        Sign::NonNegative { boxes } => Certificate::NonNegative { boxes },
        Sign::Negative { z, y, .. } => {
            let p = param_at(bx, &y);
            match value_at(&fz, param, &p, &z) {
                Some(value) => Certificate::Counterexample { p, z, value },
                None => Certificate::Undecided(format!("value at z = {z}, p = {p} is undefined")),
            }
        }
        Sign::Undecided { z, y } => Certificate::Undecided(format!(
            "depth limit on z ∈ [{}, {}], box coordinate y ∈ [{}, {}]",
            z.0, z.1, y.0, y.1
        )),
    }
}

/// `(s, c) = (2z/(1+z²), (1−z²)/(1+z²))` at a rational `z`, printed.
pub fn describe_z(z: &Rational, trigonometric: bool) -> String {
    if !trigonometric {
        return format!("t = {z}");
    }
    let d = Rational::from(1) + z.clone() * z;
    let s = Rational::from(2) * z / d.clone();
    let c = (Rational::from(1) - z.clone() * z) / d;
    format!(
        "z = tan(θ/2) = {z} (θ ≈ {:.6}, s = {s}, c = {c})",
        2.0 * z.to_f64().atan()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    use crate::exact::basis;

    #[test]
    fn thesis_cubic_is_nonnegative_on_its_range_and_not_beyond() {
        let b = basis(Family::ThesisCubic);
        let inside = ParamBox::Interval(Rational::from(-2), Rational::from(1));
        for f in &b {
            assert!(matches!(
                certify(f, true, Some("m"), &inside),
                Certificate::NonNegative { .. }
            ));
        }
        // just outside: m = 1 + 1/1000 makes b0 = (1−s)²(1−ms) negative near s = 1
        let beyond = ParamBox::Interval(Rational::from((1001, 1000)), Rational::from((1001, 1000)));
        match certify(&b[0], true, Some("m"), &beyond) {
            Certificate::Counterexample { value, .. } => assert!(value < 0),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn half_lines_are_certified() {
        let h = basis(Family::ThesisQuadratic);
        for f in &h {
            let c = certify(f, true, Some("beta"), &ParamBox::FromTo(Rational::new()));
            assert!(matches!(c, Certificate::NonNegative { .. }), "{c:?}");
        }
    }
}
