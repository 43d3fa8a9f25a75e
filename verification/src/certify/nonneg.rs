//! Nonnegativity of a function on its whole domain for a box of shape
//! parameters: one parameter ([`certify`], the API the maximal-range search
//! uses) or several ([`certify_box`], e.g. seed 004's `λ, μ`), both decided
//! by tensor Bernstein subdivision in `(z, y₁, …, y_d)`, each parameter box
//! mapped to a unit coordinate `yₖ ∈ [0, 1]`.

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use super::bernstein::{SignNd, Tensor, sign_on_unit_cube};

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

/// Outcome of a nonnegativity test over a box of several parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum BoxCertificate {
    /// Proved `f ≥ 0` on the whole domain and parameter box.
    NonNegative { boxes: usize },
    /// `f < 0` at these exact parameter values and `z = tan(θ/2)` (or `t`).
    Counterexample {
        params: Vec<Rational>,
        z: Rational,
        value: Rational,
    },
    /// Not decided (depth limit, or a denominator changing sign).
    Undecided(String),
}

/// The name of the unit coordinate of parameter `k`.
fn unit_var(k: usize) -> String {
    format!("__y{k}")
}

/// The parameter value as a function of its unit coordinate `y ∈ [0, 1]`.
fn param_of_unit(bx: &ParamBox, y: &Sym) -> Sym {
    match bx {
        ParamBox::Interval(lo, hi) => {
            Sym::rational(lo.clone()) + &(Sym::rational(hi.clone() - lo) * y)
        }
        ParamBox::FromTo(lo) => Sym::rational(lo.clone()) + &(y.clone() / &(Sym::one() - y)),
    }
}

/// Tensor power coefficients of `poly(z, p₁, …, p_d)` over `[0,1]^{1+d}`
/// after mapping each parameter box to its unit coordinate, with the sign
/// that `poly` has on the box. For half-lines the denominators `(1 − y)` are
/// cleared: they keep one sign on `[0, 1)` (the ring stores them as
/// `y − 1`, negative there, so odd powers flip the sign).
fn tensor(poly: &Poly, params: &[(&str, ParamBox)]) -> Result<Tensor, String> {
    let mut e = Sym::from_poly(poly.clone());
    for (k, (name, bx)) in params.iter().enumerate() {
        e = e.subs(name, &param_of_unit(bx, &Sym::var(&unit_var(k))));
    }
    let mut negative = false;
    for (factor, exp) in e.denominator() {
        let vars = factor.variables();
        if vars.len() != 1
            || factor.total_degree() != 1
            || !vars.iter().all(|v| v.starts_with("__y"))
        {
            return Err(format!(
                "unexpected denominator {factor} after mapping the box"
            ));
        }
        let v = vars.iter().next().expect("one variable");
        let at_half = Sym::from_poly(factor.clone())
            .subs(v, &Sym::rational(Rational::from((1, 2))))
            .as_rational()
            .expect("constant");
        negative ^= at_half < 0 && exp % 2 == 1;
    }
    let num = if negative {
        -e.numerator().clone()
    } else {
        e.numerator().clone()
    };
    let names: Vec<String> = std::iter::once("z".to_string())
        .chain((0..params.len()).map(unit_var))
        .collect();
    let mut t = Tensor::zeros(names.iter().map(|n| num.degree_in(n) as usize).collect());
    for (mono, q) in num.terms() {
        let alpha: Vec<usize> = names.iter().map(|n| mono.exponent(n) as usize).collect();
        if alpha.iter().sum::<usize>() as u64 != mono.degree() {
            return Err(format!(
                "{poly} depends on symbols other than z and the parameters"
            ));
        }
        t.add(&alpha, q);
    }
    Ok(t)
}

/// The parameter value at unit coordinate `y` of the box.
fn param_at(bx: &ParamBox, y: &Rational) -> Rational {
    match bx {
        ParamBox::Interval(lo, hi) => lo.clone() + (hi.clone() - lo) * y,
        ParamBox::FromTo(lo) => lo.clone() + y.clone() / (Rational::from(1) - y),
    }
}

/// Decides `f(θ; p) ≥ 0` for every `θ ∈ [0, π/2]` (every `t ∈ [0, 1]`) and
/// every `p` in the box. `param` is `None` for families without parameters.
pub fn certify(f: &Sym, trigonometric: bool, param: Option<&str>, bx: &ParamBox) -> Certificate {
    let params: Vec<(&str, ParamBox)> = param.map(|p| (p, bx.clone())).into_iter().collect();
    match certify_box(f, trigonometric, &params) {
        BoxCertificate::NonNegative { boxes } => Certificate::NonNegative { boxes },
        BoxCertificate::Counterexample { params, z, value } => Certificate::Counterexample {
            p: params
                .first()
                .cloned()
                .unwrap_or_else(|| param_at(bx, &Rational::new())),
            z,
            value,
        },
        BoxCertificate::Undecided(why) => Certificate::Undecided(why),
    }
}

/// Decides `f(θ; p₁, …, p_d) ≥ 0` for every `θ ∈ [0, π/2]` (every
/// `t ∈ [0, 1]`) and every parameter vector in the product of the boxes:
/// tensor Bernstein subdivision in `(z, y₁, …, y_d)`.
pub fn certify_box(f: &Sym, trigonometric: bool, params: &[(&str, ParamBox)]) -> BoxCertificate {
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
                    return BoxCertificate::Undecided(format!(
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
            tensor(f, params).is_ok_and(|t| {
                matches!(
                    sign_on_unit_cube(&t, MAX_DEPTH_BOX, true),
                    SignNd::NonNegative { .. }
                )
            })
        };
        if positive(&factor) {
            continue;
        }
        if positive(&-factor.clone()) {
            flip ^= e % 2 == 1;
            continue;
        }
        return BoxCertificate::Undecided(format!(
            "cannot fix the sign of the denominator factor {factor} on the box"
        ));
    }
    let num = if flip {
        -fz.numerator().clone()
    } else {
        fz.numerator().clone()
    };
    if num.is_zero() {
        return BoxCertificate::NonNegative { boxes: 0 };
    }
    let a = match tensor(&num, params) {
        Ok(a) => a,
        Err(why) => return BoxCertificate::Undecided(why),
    };
    let depth = if a.degrees[1..].iter().all(|d| *d == 0) {
        MAX_DEPTH_POINT
    } else {
        MAX_DEPTH_BOX * params.len() as u32
    };
    match sign_on_unit_cube(&a, depth, false) {
        SignNd::NonNegative { boxes } => BoxCertificate::NonNegative { boxes },
        SignNd::Negative { point, .. } => {
            let (z, ys) = point.split_first().expect("z coordinate");
            let values: Vec<Rational> = params
                .iter()
                .zip(ys)
                .map(|((_, bx), y)| param_at(bx, y))
                .collect();
            let value = fz.eval_rational(&|name: &str| {
                if name == "z" {
                    return Some(z.clone());
                }
                params
                    .iter()
                    .position(|(n, _)| *n == name)
                    .map(|k| values[k].clone())
            });
            match value {
                Ok(value) => BoxCertificate::Counterexample {
                    params: values,
                    z: z.clone(),
                    value,
                },
                Err(_) => BoxCertificate::Undecided(format!(
                    "value at z = {z}, parameters {values:?} is undefined"
                )),
            }
        }
        SignNd::Undecided { cell } => BoxCertificate::Undecided(format!(
            "depth limit on the box {}",
            cell.iter()
                .map(|(a, b)| format!("[{a}, {b}]"))
                .collect::<Vec<_>>()
                .join(" × ")
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
