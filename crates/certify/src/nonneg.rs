//! Nonnegativity of a rational function on its whole domain for every
//! parameter in a box, decided by tensor Bernstein subdivision in
//! `(z, y₁, …, y_d)`, each parameter set mapped onto a unit coordinate.
//!
//! A function `f = N / D` (`D = Π Dⱼ^eⱼ`, factored by the exact ring) is
//! certified in two steps: every denominator factor `Dⱼ` is proved to keep
//! one strict sign on the domain × box (strict positivity of `±Dⱼ`, see
//! [`crate::bernstein`]), or an exact pole is exhibited (a rational point
//! where `Dⱼ = 0`, or two where it has opposite signs); then the sign of
//! `f` is that of `N · Π_{eⱼ odd} sign(Dⱼ)`, decided by the same
//! subdivision. Every counterexample is re-evaluated exactly from `f`
//! before it is returned.

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use crate::bernstein::{MAX_COEFFICIENT_WORK, SignNd, Tensor, sign_on_unit_cube};
use crate::domain::{ParamBox, in_z, unit_var};

/// Halvings allowed per test before giving up on a box: deep for a single
/// parameter value (one dimension, cheap), shallower for parameter boxes.
pub const MAX_DEPTH_POINT: u32 = 96;
/// See [`MAX_DEPTH_POINT`].
pub const MAX_DEPTH_BOX: u32 = 48;

/// Outcome of a nonnegativity test of one parameter (or none).
#[derive(Debug, Clone, PartialEq)]
pub enum Certificate {
    /// Proved `f ≥ 0` on the whole domain and parameter box.
    NonNegative { boxes: usize },
    /// `f < 0` at this exact point: parameter `p`, `z = tan(θ/2)` (or `t`),
    /// the value exact and re-evaluated.
    Counterexample {
        p: Rational,
        z: Rational,
        value: Rational,
    },
    /// `f` is not defined everywhere: a denominator vanishes (exact witness).
    Pole(String),
    /// Not decided (depth limit), with the reason.
    Undecided(String),
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
    /// `f` is not defined everywhere: a denominator vanishes (exact witness).
    Pole(String),
    /// Not decided (depth limit), with the reason.
    Undecided(String),
}

/// Exact value of `fz` (a function of `z` and the parameters) at a point.
pub fn value_at(fz: &Sym, names: &[&str], params: &[Rational], z: &Rational) -> Option<Rational> {
    fz.eval_rational(&|name: &str| {
        if name == "z" {
            return Some(z.clone());
        }
        names
            .iter()
            .position(|n| *n == name)
            .map(|k| params[k].clone())
    })
    .ok()
}

/// Tensor power coefficients of `poly(z, p₁, …, p_d)` over `[0,1]^{1+d}`
/// after mapping each parameter set to its unit coordinate, with the sign
/// `poly` has off the excluded faces. The map's denominators (`y`, `1 − y`)
/// are cleared: they keep one sign inside (the ring stores `1 − y` as
/// `y − 1`, negative there, so odd powers flip the sign).
pub fn tensor(poly: &Poly, params: &[(&str, ParamBox)]) -> Result<Tensor, String> {
    let mut e = Sym::from_poly(poly.clone());
    for (k, (name, bx)) in params.iter().enumerate() {
        e = e.subs(name, &bx.unit_map(&Sym::var(&unit_var(k)))?);
    }
    let mut negative = false;
    for (factor, exp) in e.denominator() {
        let Some(v) = unit_map_denominator(factor) else {
            return Err(format!(
                "unexpected denominator {factor} after mapping the box"
            ));
        };
        let at_half = Sym::from_poly(factor.clone())
            .subs(&v, &Sym::rational(Rational::from((1, 2))))
            .as_rational()
            .ok_or("a constant")?;
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
        t.add(&alpha, &q.to_rational());
    }
    Ok(t)
}

/// The unit coordinate `y` of a denominator factor the map of a parameter
/// set makes: `c·yᵃ(y − 1)ᵇ`, which vanishes only on the faces `y = 0`,
/// `y = 1` — `1 − y` of a half-line's `y/(1 − y)`, `y(1 − y)` of the
/// line's `(2y − 1)/(y(1 − y))`, raised to the parameter's degree (the ring
/// may keep `(1 − y)²` expanded, `y² − 2y + 1`, as one factor). `None` for
/// any other factor.
fn unit_map_denominator(factor: &Poly) -> Option<String> {
    let vars = factor.variables();
    let [v] = vars.iter().collect::<Vec<_>>()[..] else {
        return None;
    };
    if !v.starts_with("__y") {
        return None;
    }
    let low = factor.terms().map(|(m, _)| m.exponent(v)).min()?;
    let (top, lead) = factor.leading_term()?;
    let y = Poly::var(v);
    let product =
        (y.pow(low) * &(y - &Poly::one()).pow(top.exponent(v) - low)).scale(&lead.to_rational());
    (factor - &product).is_zero().then(|| v.clone())
}

/// A point of the unit cube as `(z, parameter values)`; `None` on a face at
/// infinity (never returned by the subdivision, which skips them).
fn to_params(point: &[Rational], params: &[(&str, ParamBox)]) -> Option<(Rational, Vec<Rational>)> {
    let (z, ys) = point.split_first()?;
    let values = params
        .iter()
        .zip(ys)
        .map(|((_, bx), y)| bx.at_unit(y))
        .collect::<Option<Vec<_>>>()?;
    Some((z.clone(), values))
}

/// Where `(z, p₁, …)` is, as text (`z` named as the variable it stands
/// for).
fn show_point(z: &Rational, trig: bool, names: &[&str], values: &[Rational]) -> String {
    let var = if trig { "tan(θ/2)" } else { "t" };
    names
        .iter()
        .zip(values)
        .map(|(n, v)| format!("{n} = {v}, "))
        .collect::<String>()
        + &format!("{var} = {z}")
}

/// The sign a denominator factor keeps on the domain × box.
enum FactorSign {
    Positive,
    Negative,
    /// It vanishes: the reason, with an exact witness.
    Vanishes(String),
    Undecided(String),
}

/// Whether `d` keeps one strict sign on the domain × box: `Ok(±1)`, or
/// why not — it vanishes (with an exact witness: a zero, or two points of
/// opposite signs) or the subdivision could not decide.
pub fn definite_sign(
    d: &Sym,
    trigonometric: bool,
    params: &[(&str, ParamBox)],
) -> Result<i32, String> {
    let dz = in_z(d, trigonometric);
    match factor_sign(dz.numerator(), trigonometric, params) {
        FactorSign::Positive => Ok(1),
        FactorSign::Negative => Ok(-1),
        FactorSign::Vanishes(why) | FactorSign::Undecided(why) => Err(why),
    }
}

/// Strict sign of a polynomial `d(z, p)` on the domain × box.
fn factor_sign(d: &Poly, trig: bool, params: &[(&str, ParamBox)]) -> FactorSign {
    let names: Vec<&str> = params.iter().map(|(n, _)| *n).collect();
    let excluded: Vec<_> = std::iter::once(Default::default())
        .chain(params.iter().map(|(_, bx)| bx.excluded()))
        .collect();
    let strict = |p: &Poly| -> Result<SignNd, String> {
        let t = tensor(p, params)?;
        let depth = MAX_DEPTH_BOX * (params.len() as u32).max(1);
        Ok(sign_on_unit_cube(&t, depth, true, &excluded))
    };
    let value = |point: &[Rational]| -> Option<(Rational, Vec<Rational>, Rational)> {
        let (z, values) = to_params(point, params)?;
        let v = value_at(&Sym::from_poly(d.clone()), &names, &values, &z)?;
        Some((z, values, v))
    };
    let first = match strict(d) {
        Ok(SignNd::NonNegative { .. }) => return FactorSign::Positive,
        Ok(SignNd::Negative { point, .. }) => point,
        Ok(SignNd::Undecided { .. }) => {
            return FactorSign::Undecided(format!(
                "cannot fix the sign of {d} (subdivision depth limit)"
            ));
        }
        Ok(SignNd::OutOfBudget { boxes }) => {
            return FactorSign::Undecided(format!(
                "cannot fix the sign of {d} ({})",
                budget_spent(boxes)
            ));
        }
        Err(e) => return FactorSign::Undecided(e),
    };
    let Some((z1, v1, d1)) = value(&first) else {
        return FactorSign::Undecided(format!("{d} undefined at a witness"));
    };
    if d1 == 0 {
        return FactorSign::Vanishes(format!(
            "{d} is 0 at {} (exact)",
            show_point(&z1, trig, &names, &v1)
        ));
    }
    match strict(&-d.clone()) {
        Ok(SignNd::NonNegative { .. }) => FactorSign::Negative,
        Ok(SignNd::Negative { point, .. }) => match value(&point) {
            Some((z2, v2, d2)) if d2 == 0 || (d2 > 0) != (d1 > 0) => FactorSign::Vanishes(format!(
                "{d} changes sign: it is {d1} at {} and {d2} at {} (exact)",
                show_point(&z1, trig, &names, &v1),
                show_point(&z2, trig, &names, &v2)
            )),
            _ => FactorSign::Undecided(format!("cannot fix the sign of {d}")),
        },
        Ok(SignNd::Undecided { .. }) => FactorSign::Undecided(format!(
            "cannot fix the sign of {d} (subdivision depth limit)"
        )),
        Ok(SignNd::OutOfBudget { boxes }) => FactorSign::Undecided(format!(
            "cannot fix the sign of {d} ({})",
            budget_spent(boxes)
        )),
        Err(e) => FactorSign::Undecided(e),
    }
}

/// Why a subdivision stopped at its budget.
fn budget_spent(boxes: usize) -> String {
    format!(
        "the subdivision stopped at its budget of {MAX_COEFFICIENT_WORK} coefficient operations, {boxes} boxes proved"
    )
}

/// `p` without its factors of even multiplicity (squares, `≥ 0`), when it
/// has any: the unit times the factors of odd multiplicity, each once.
fn odd_part(p: &Poly) -> Option<Poly> {
    let f = p.factor();
    if f.factors.iter().all(|(_, e)| e % 2 == 1 && *e == 1) {
        return None;
    }
    Some(
        f.factors
            .iter()
            .filter(|(_, e)| e % 2 == 1)
            .fold(Poly::constant(f.unit.clone()), |acc, (g, _)| acc * g),
    )
}

/// Decides `f(θ; p) ≥ 0` for every `θ ∈ [0, π/2]` (every `t ∈ [0, 1]`) and
/// every `p` in the box. `param` is `None` for functions without parameters.
pub fn certify(f: &Sym, trigonometric: bool, param: Option<&str>, bx: &ParamBox) -> Certificate {
    let params: Vec<(&str, ParamBox)> = param.map(|p| (p, bx.clone())).into_iter().collect();
    match certify_box(f, trigonometric, &params) {
        BoxCertificate::NonNegative { boxes } => Certificate::NonNegative { boxes },
        BoxCertificate::Counterexample { params, z, value } => Certificate::Counterexample {
            p: params
                .first()
                .cloned()
                .or_else(|| bx.some_point())
                .unwrap_or_default(),
            z,
            value,
        },
        BoxCertificate::Pole(why) => Certificate::Pole(why),
        BoxCertificate::Undecided(why) => Certificate::Undecided(why),
    }
}

/// Decides `f(θ; p₁, …, p_d) ≥ 0` for every `θ ∈ [0, π/2]` (every
/// `t ∈ [0, 1]`) and every parameter vector in the product of the sets.
pub fn certify_box(f: &Sym, trigonometric: bool, params: &[(&str, ParamBox)]) -> BoxCertificate {
    certify_box_to_depth(f, trigonometric, params, None)
}

/// [`certify_box`] with a smaller depth limit for the numerator's
/// subdivision (`None`: the default), for callers that subdivide the
/// parameter box themselves.
pub fn certify_box_to_depth(
    f: &Sym,
    trigonometric: bool,
    params: &[(&str, ParamBox)],
    max_depth: Option<u32>,
) -> BoxCertificate {
    let fz = in_z(f, trigonometric);
    let names: Vec<&str> = params.iter().map(|(n, _)| *n).collect();
    let zz = Poly::var("z") * &Poly::var("z") + &Poly::one();
    let mut flip = false;
    for (factor, e) in fz.denominator() {
        // the positive factor 1 + z² of the Weierstrass substitution
        let mut factor = factor.clone();
        while factor.degree_in("z") > 0 {
            match factor.exact_div(&zz) {
                Some(q) => factor = q,
                None => break,
            }
        }
        if let Some(k) = factor.as_constant() {
            flip ^= k < 0 && e % 2 == 1;
            continue;
        }
        match factor_sign(&factor, trigonometric, params) {
            FactorSign::Positive => {}
            FactorSign::Negative => flip ^= e % 2 == 1,
            FactorSign::Vanishes(why) => {
                return BoxCertificate::Pole(format!("the denominator factor {why}"));
            }
            FactorSign::Undecided(why) => return BoxCertificate::Undecided(why),
        }
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
    let depth = max_depth.unwrap_or(if a.degrees[1..].iter().all(|d| *d == 0) {
        MAX_DEPTH_POINT
    } else {
        MAX_DEPTH_BOX * params.len() as u32
    });
    let excluded: Vec<_> = std::iter::once(Default::default())
        .chain(params.iter().map(|(_, bx)| bx.excluded()))
        .collect();
    let mut outcome = sign_on_unit_cube(&a, depth, false, &excluded);
    if matches!(outcome, SignNd::Undecided { .. }) {
        // a square factor touching 0 inside stalls the subdivision; it
        // never changes the sign, so the odd part decides (a witness is
        // still re-evaluated from f itself below)
        if let Some(odd) = odd_part(&num) {
            if let Ok(b) = tensor(&odd, params) {
                outcome = sign_on_unit_cube(&b, depth, false, &excluded);
            }
        }
    }
    match outcome {
        SignNd::NonNegative { boxes } => BoxCertificate::NonNegative { boxes },
        SignNd::Negative { point, .. } => {
            let Some((z, values)) = to_params(&point, params) else {
                return BoxCertificate::Undecided("a witness at infinity".into());
            };
            // the witness is re-evaluated from f itself before it is shown
            match value_at(&fz, &names, &values, &z) {
                Some(value) if value < 0 => BoxCertificate::Counterexample {
                    params: values,
                    z,
                    value,
                },
                _ => BoxCertificate::Undecided(format!(
                    "the candidate witness {} did not re-evaluate to a negative value",
                    show_point(&z, trigonometric, &names, &values)
                )),
            }
        }
        SignNd::OutOfBudget { boxes } => BoxCertificate::Undecided(budget_spent(boxes)),
        SignNd::Undecided { cell } => BoxCertificate::Undecided(format!(
            "depth limit on the box {}",
            cell.iter()
                .map(|(a, b)| format!("[{a}, {b}]"))
                .collect::<Vec<_>>()
                .join(" × ")
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    fn poly_var(n: &str) -> Sym {
        Sym::var(n)
    }

    /// The rational quadratic Bernstein basis with weight `w`.
    fn rational_quadratic() -> [Sym; 3] {
        let (t, w) = (poly_var("t"), poly_var("w"));
        let u = Sym::one() - &t;
        let d = u.clone() * &u + &(Sym::int(2) * &w * &t * &u) + &(t.clone() * &t);
        [
            u.clone() * &u / &d,
            Sym::int(2) * &w * &t * &u / &d,
            t.clone() * &t / &d,
        ]
    }

    #[test]
    fn thesis_cubic_b0_is_nonnegative_on_its_range_and_not_beyond() {
        // b0 = (1 − s)²(1 − m s)
        let (s, m) = (poly_var("s"), poly_var("m"));
        let one_minus = Sym::one() - &s;
        let b0 = one_minus.clone() * &one_minus * &(Sym::one() - &(m * &s));
        let inside = ParamBox::closed(Rational::from(-2), Rational::from(1));
        assert!(matches!(
            certify(&b0, true, Some("m"), &inside),
            Certificate::NonNegative { .. }
        ));
        let beyond = ParamBox::point(q(1001, 1000));
        match certify(&b0, true, Some("m"), &beyond) {
            Certificate::Counterexample { value, p, .. } => {
                assert!(value < 0);
                assert_eq!(p, q(1001, 1000));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn quotients_on_half_lines_and_wide_ranges() {
        let b = rational_quadratic();
        let half_line = ParamBox::from_closed(Rational::new());
        for f in &b {
            let c = certify(f, false, Some("w"), &half_line);
            assert!(matches!(c, Certificate::NonNegative { .. }), "{c:?}");
        }
        // w ∈ [−1/10, 1000]: the denominator stays positive, b1 < 0 for w < 0
        let wide = ParamBox::closed(q(-1, 10), Rational::from(1000));
        assert!(matches!(
            certify(&b[0], false, Some("w"), &wide),
            Certificate::NonNegative { .. }
        ));
        match certify(&b[1], false, Some("w"), &wide) {
            Certificate::Counterexample { p, z, value } => {
                assert!(p < 0 && value < 0, "{p} {z} {value}");
            }
            other => panic!("{other:?}"),
        }
        // w ∈ [−2, 0]: the denominator 1 + 2(w − 1)t(1 − t) vanishes
        let poles = ParamBox::closed(Rational::from(-2), Rational::new());
        assert!(matches!(
            certify(&b[0], false, Some("w"), &poles),
            Certificate::Pole(_)
        ));
    }

    #[test]
    fn a_parameter_of_higher_degree_on_a_half_line_maps_to_powers_of_one_minus_y() {
        // Barsky's Beta-spline divides by δ = 2β1³ + 4β1² + 4β1 + β2 + 2 on
        // β1, β2 ≥ 0: mapped, β1 = y/(1 − y) leaves (1 − y)³ in the
        // denominator, which the ring may keep expanded (it was refused as
        // "unexpected denominator")
        let (b1, b2, t) = (poly_var("beta1"), poly_var("beta2"), poly_var("t"));
        let delta = Sym::int(2) * &b1 * &b1 * &b1
            + &(Sym::int(4) * &b1 * &b1)
            + &(Sym::int(4) * &b1)
            + &b2
            + &Sym::int(2);
        let f = Sym::int(2) * &t * &t * &t / &delta;
        let half = ParamBox::from_closed(Rational::new());
        let c = certify_box(
            &f,
            false,
            &[("beta1", half.clone()), ("beta2", half.clone())],
        );
        assert!(matches!(c, BoxCertificate::NonNegative { .. }), "{c:?}");
        // on the other half-line too, and a function of one sign below 0
        // is refuted at a finite point: −β1² − β2² − 1 < 0
        let g = -(b1.clone() * &b1) - &Sym::one() - &(b2.clone() * &b2);
        match certify_box(
            &g,
            false,
            &[("beta1", ParamBox::up_to(Rational::new())), ("beta2", half)],
        ) {
            BoxCertificate::Counterexample { value, .. } => assert!(value < 0),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn counterexamples_far_out_on_a_half_line_are_finite() {
        // 1 − p/10⁹ ≥ 0 fails only beyond 10⁹
        let p = poly_var("p");
        let f = Sym::one() - &(p / &Sym::int(1_000_000_000));
        match certify(
            &f,
            false,
            Some("p"),
            &ParamBox::from_closed(Rational::new()),
        ) {
            Certificate::Counterexample { p, value, .. } => {
                assert!(p > 1_000_000_000 && value < 0);
            }
            other => panic!("{other:?}"),
        }
    }
}
