//! Hand-checkable witnesses of failed identities: a rational point where
//! the two sides of `left = right` differ, with both values exactly.
//!
//! Every variable except `π` gets a small rational value: `s, c = sin θ,
//! cos θ` a rational point of the unit circle (`3/5, 4/5`: θ ≈ 0.6435 lies in
//! every trigonometric domain of the audit), `t` a value in `(0, 1)`, shape
//! parameters distinct fractions in `(0, 1)` (`η` in `(1, 2)`: its published
//! range is `(1/2, 2]`), every other symbol (control points, weights,
//! interval lengths, data) a distinct small integer. `π` stays a symbol, so
//! the values are exact elements of `ℚ(π)` — usually rationals. A nonzero
//! residual vanishes only on a proper algebraic subset, so one of the first
//! few points shows it; the point is rejected when a denominator vanishes
//! there or the residual happens to. The point found is then simplified
//! variable by variable (to `0`, `1`, … while it stays a witness), so that
//! a reader checks small numbers.

use rug::Rational;
use trig_symbolic::Sym;

use crate::evidence::{Assignment, Expr, Value, Witness};

/// Points tried before giving up.
const ATTEMPTS: usize = 6;

/// Rational points `(sin θ, cos θ)` of the unit circle, θ ∈ (0, π/2).
const CIRCLE: [((i64, i64), (i64, i64)); 3] =
    [((3, 5), (4, 5)), ((5, 13), (12, 13)), ((8, 17), (15, 17))];

/// Values of `t` in `(0, 1)`.
const T: [(i64, i64); 3] = [(1, 3), (2, 5), (3, 7)];

/// Fractions in `(0, 1)` for shape parameters, distinct.
const FRACTIONS: [(i64, i64); 14] = [
    (1, 2),
    (1, 3),
    (2, 3),
    (1, 4),
    (3, 4),
    (1, 5),
    (2, 5),
    (3, 5),
    (4, 5),
    (1, 6),
    (5, 6),
    (1, 7),
    (2, 7),
    (3, 7),
];

/// Small integers for other symbols, distinct.
const INTEGERS: [i64; 24] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89,
];

/// Shape-parameter names (with or without a trailing index).
const PARAMETERS: [&str; 12] = [
    "m", "beta", "lambda", "mu", "alpha", "eta", "zeta", "xi", "omega", "gamma", "k", "q",
];

fn is_parameter(name: &str) -> bool {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    PARAMETERS.contains(&stem)
}

/// A point: every variable but `π` with an exact value.
pub type Point = Vec<(String, Rational)>;

/// The value of every variable of `names` in attempt `k`.
fn assignment(names: &[String], k: usize) -> Point {
    let (mut fractions, mut integers) = (k, k);
    let (s, c) = CIRCLE[k % CIRCLE.len()];
    names
        .iter()
        .filter(|n| n.as_str() != "pi")
        .map(|n| {
            let value = match n.as_str() {
                "s" => Rational::from(s),
                "c" => Rational::from(c),
                "t" => Rational::from(T[k % T.len()]),
                _ if is_parameter(n) => {
                    let q = Rational::from(FRACTIONS[fractions % FRACTIONS.len()]);
                    fractions += 1;
                    if n.starts_with("eta") { q + 1u32 } else { q }
                }
                _ => {
                    let v = INTEGERS[integers % INTEGERS.len()];
                    integers += 1;
                    Rational::from(v)
                }
            };
            (n.clone(), value)
        })
        .collect()
}

/// Simpler values to try for a variable, simplest first (inside the
/// published ranges: `η ∈ (1/2, 2]`, `α, ω > 0`).
fn simpler(name: &str) -> &'static [(i64, i64)] {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    match stem {
        "t" => &[(0, 1), (1, 1), (1, 2)],
        // positive by definition: weights, interval lengths, knot spacings, G¹ factors
        "eta" | "alpha" | "omega" | "w" | "h" | "q" => &[(1, 1), (2, 1)],
        // interval lengths of a data set: h_i, h_{i+1} (`h_i1`), …
        _ if stem.starts_with("h_") => &[(1, 1), (2, 1)],
        _ => &[(0, 1), (1, 1), (-1, 1), (2, 1)],
    }
}

/// A witness point for `differ` (true when both sides are defined and
/// differ there): the first of a few generic points, then simplified
/// variable by variable (each set to the simplest value that keeps it a
/// witness; `sin θ, cos θ` together to `0, 1` or `1, 0`), so that the values
/// stay small enough to check by hand.
pub fn search(names: &[String], differ: &dyn Fn(&Point) -> bool) -> Option<Point> {
    first_point(names, differ).map(|point| search_from(point, differ))
}

/// [`search`]'s first point, before simplification.
pub fn first_point(names: &[String], differ: &dyn Fn(&Point) -> bool) -> Option<Point> {
    (0..ATTEMPTS)
        .map(|k| assignment(names, k))
        .find(|p| differ(p))
}

/// [`search`]'s simplification from a witness point already found.
pub fn search_from(mut point: Point, differ: &dyn Fn(&Point) -> bool) -> Point {
    let set = |p: &Point, name: &str, q: &Rational| -> Point {
        p.iter()
            .map(|(n, v)| (n.clone(), if n == name { q.clone() } else { v.clone() }))
            .collect()
    };
    let has = |p: &Point, n: &str| p.iter().any(|(m, _)| m == n);
    // θ = 0 or π/2, for whichever of s, c occur (the normal form may have
    // eliminated s)
    if has(&point, "s") || has(&point, "c") {
        for (s, c) in [(0, 1), (1, 0)] {
            let candidate = set(
                &set(&point, "s", &Rational::from(s)),
                "c",
                &Rational::from(c),
            );
            if differ(&candidate) {
                point = candidate;
                break;
            }
        }
    }
    let others: Vec<String> = point
        .iter()
        .map(|(n, _)| n.clone())
        .filter(|n| n != "s" && n != "c")
        .collect();
    for name in others {
        for q in simpler(&name) {
            let candidate = set(&point, &name, &Rational::from(*q));
            if differ(&candidate) {
                point = candidate;
                break;
            }
        }
    }
    point
}

/// `x` with every variable but `π` replaced, or `None` when a denominator
/// vanishes.
pub fn at(x: &Sym, point: &[(String, Rational)]) -> Option<Sym> {
    let value = |name: &str| {
        if name == "pi" {
            return Some(Sym::pi());
        }
        point
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, q)| Sym::rational(q.clone()))
    };
    if !x.variables().contains("pi") {
        let q = x
            .eval_rational(&|n| value(n).and_then(|s| s.as_rational()))
            .ok()?;
        return Some(Sym::rational(q));
    }
    x.eval(&Sym::one(), &value).ok()
}

/// The variables of `exprs` in witness order: parameters, then the atoms,
/// then the other symbols.
pub fn ordered_names<'a>(exprs: impl IntoIterator<Item = &'a Sym>) -> Vec<String> {
    let mut names: Vec<String> = exprs
        .into_iter()
        .flat_map(|e| e.variables())
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    names.sort_by_key(|n| {
        let group = if is_parameter(n) {
            0
        } else if ["s", "c", "t"].contains(&n.as_str()) {
            1
        } else {
            2
        };
        (group, trig_symbolic::Var::new(n))
    });
    names
}

/// A witness that `left ≠ right`: a point where both sides are defined and
/// differ ([`search`]), with the two values, labelled `labels.0`, `labels.1`.
/// `None` when the identity holds at every point tried (the residual is
/// then zero or exceptional; the caller shows it without a witness), or
/// when the variables are not independent (`independent`: a point valued
/// one variable at a time would be no real point). While a spec decision
/// runs, a real point ([`crate::real_witness`]).
pub fn find(left: &Sym, right: &Sym, labels: (&str, &str)) -> Option<Witness> {
    find_where(left, right, labels, &[])
}

/// [`find`] inside the conditions of a claim: every symbol of `positive`
/// is given a positive value (a point where one is `≤ 0` is no witness;
/// the generic points give every such symbol a positive value, and the
/// simplification keeps it so — `λ = 0` is skipped for `1`, `2`, …).
pub fn find_where(
    left: &Sym,
    right: &Sym,
    labels: (&str, &str),
    positive: &[String],
) -> Option<Witness> {
    // a spec basis: a real point, re-evaluated there
    if let Some(real) = crate::real_witness::find(left, right, labels) {
        return real;
    }
    let names = ordered_names([left, right]);
    if !independent(&names) {
        // no real point can be named by valuing these one by one
        return None;
    }
    let inside = |p: &Point| {
        p.iter()
            .all(|(n, q)| *q > 0 || !positive.iter().any(|m| m == n))
    };
    let differ = |p: &Point| match (at(left, p), at(right, p)) {
        (Some(l), Some(r)) => inside(p) && !(l - &r).is_zero(),
        _ => false,
    };
    let point = search(&names, &differ)?;
    of_exprs(&point, &names, &[(labels.0, left), (labels.1, right)])
}

/// True when valuing `names` one by one (as [`search`] does) names a real
/// point: no atom that is a function of another variable or a constant —
/// a parameter's `sin(alpha)`, `cos(alpha/2)`, `exp(beta)`, the variable's
/// `E = exp(…)`, an algebraic `sqrt(2)` — and not the variable `t` beside
/// `s = sin θ`, `c = cos θ` (alone, `s, c` are valued on the unit circle,
/// which is a real θ). Such expressions get their witness at a real point
/// of their basis ([`crate::real_witness`]) or none.
fn independent(names: &[String]) -> bool {
    let dependent = |n: &String| n.contains('(') || n == "E";
    let has = |v: &str| names.iter().any(|n| n == v);
    !names.iter().any(dependent) && !(has("t") && (has("s") || has("c")))
}

/// A witness from a point already chosen and values already computed.
pub fn witness(
    point: &[(String, Rational)],
    names: &[String],
    values: Vec<(&str, Sym)>,
) -> Witness {
    with_values(
        point,
        names,
        values
            .into_iter()
            .map(|(label, v)| Value::new(label, Expr::new(&v)))
            .collect(),
    )
}

/// A witness at `point` whose values are those of `exprs` there (each
/// value records its expression, so a reader or a program re-checks it by
/// substituting the point).
pub fn of_exprs(
    point: &[(String, Rational)],
    names: &[String],
    exprs: &[(&str, &Sym)],
) -> Option<Witness> {
    // a variable the point leaves free (a control point) stays a symbol;
    // `None` where a denominator vanishes
    let value = |x: &Sym| {
        let free = x
            .variables()
            .iter()
            .any(|n| n != "pi" && !point.iter().any(|(m, _)| m == n));
        if !free {
            return at(x, point);
        }
        point.iter().try_fold(x.clone(), |acc, (n, q)| {
            acc.try_subs(n, &Sym::rational(q.clone())).ok()
        })
    };
    let values: Option<Vec<Value>> = exprs
        .iter()
        .map(|(label, x)| Some(Value::new(*label, Expr::new(&value(x)?)).of(x)))
        .collect();
    Some(with_values(point, names, values?))
}

fn with_values(point: &[(String, Rational)], names: &[String], values: Vec<Value>) -> Witness {
    let trig = names.iter().any(|n| n == "s" || n == "c");
    let pi = names.iter().any(|n| n == "pi");
    let mut notes = Vec::new();
    if trig {
        notes.push("s = sin θ, c = cos θ".to_string());
    }
    if pi {
        notes.push("π kept as a symbol".to_string());
    }
    let mut coordinates: Vec<Assignment> = point
        .iter()
        .map(|(n, q)| Assignment::exact(n, &Sym::rational(q.clone())))
        .collect();
    // the angle θ of (s, c): the variable the SymPy forms are written in
    let value = |n: &str| {
        point
            .iter()
            .find(|(m, _)| m == n)
            .map(|(_, q)| Sym::rational(q.clone()))
    };
    coordinates.extend(Assignment::angle(value("s").as_ref(), value("c").as_ref()));
    Witness {
        point: coordinates,
        note: (!notes.is_empty()).then(|| notes.join("; ")),
        values,
        exact: true,
        stated: None,
    }
}

/// A witness for a residual alone (`residual ≠ 0`): its value at the point.
pub fn of_residual(residual: &Sym) -> Option<Witness> {
    find(residual, &Sym::zero(), ("residual", "0")).map(|mut w| {
        w.values.truncate(1);
        w
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_false_identity_has_an_exact_witness() {
        let (m1, m2, p2, p3) = (
            Sym::var("m1"),
            Sym::var("m2"),
            Sym::var("P2"),
            Sym::var("P3"),
        );
        // printed (m₂ + 2)P₃/(m₁ + 2) against P₃: differ unless m₁ = m₂
        let printed = (m2.clone() + &Sym::int(2)) * &p3 / &(m1.clone() + &Sym::int(2));
        let w = find(&printed, &p3, ("printed", "required")).expect("a witness");
        assert!(w.exact);
        let names: Vec<&str> = w.point.iter().map(|a| a.name.as_str()).collect();
        assert_eq!(names, ["m₁", "m₂", "P₃"]);
        // simplified to m₁ = 0, m₂ = 1, P₃ = 1: (1 + 2)·1/(0 + 2) = 3/2 against 1
        let values: Vec<&str> = w.point.iter().map(|a| a.value.as_str()).collect();
        assert_eq!(values, ["0", "1", "1"]);
        assert_eq!(w.values[0].value.unicode, "3/2");
        assert_eq!(w.values[1].value.unicode, "1");
        assert!(find(&(p2.clone() + &p3), &(p3 + &p2), ("a", "b")).is_none());
    }

    #[test]
    fn a_witness_keeps_positive_symbols_positive() {
        let (lambda, a) = (Sym::var("lambda"), Sym::var("a1"));
        // λ·a₁ = a₁ fails at λ = 0 unless λ is positive: then at λ = 2
        let left = lambda * &a;
        let w = find(&left, &a, ("value", "target")).expect("a witness");
        assert_eq!(w.point[0].value, "0");
        let positive = ["lambda".to_string()];
        let w = find_where(&left, &a, ("value", "target"), &positive).expect("a witness");
        let values: Vec<(&str, &str)> = w
            .point
            .iter()
            .map(|p| (p.name.as_str(), p.value.as_str()))
            .collect();
        assert_eq!(values, [("λ", "2"), ("a₁", "1")]);
    }

    #[test]
    fn pi_stays_a_symbol_and_trig_atoms_lie_on_the_circle() {
        let x = Sym::pi() * &Sym::var("s") * &Sym::var("s") + &(Sym::var("c") * &Sym::var("c"));
        let w = find(&x, &Sym::one(), ("left", "right")).expect("a witness");
        // simplified to s = 1, c = 0: π against 1
        assert_eq!(w.values[0].value.unicode, "π");
        assert!(
            w.note
                .as_deref()
                .unwrap_or("")
                .contains("π kept as a symbol")
        );
    }

    /// Variables that are functions of one another are never valued one by
    /// one: `α = 1, cos(alpha) = 0`, `t = 0, s = 1` or `sqrt(2) = 2` would
    /// be printed as a point although no real point has those values.
    #[test]
    fn dependent_atoms_get_no_point_valued_one_by_one() {
        let (a, ca, t, s) = (
            Sym::var("alpha"),
            Sym::var("cos(alpha)"),
            Sym::var("t"),
            Sym::var("s"),
        );
        let one = Sym::one();
        for x in [
            a.clone() * &ca,
            t.clone() - &s,
            Sym::var("sqrt(2)") * &a,
            Sym::var("E") - &one,
        ] {
            assert!(find(&x, &Sym::zero(), ("left", "right")).is_none(), "{x}");
        }
        // independent variables keep their witness: α·s ≠ 0 at α = 1, s = 1, c = 0
        assert!(find(&(a * &s), &Sym::zero(), ("left", "right")).is_some());
        assert!(find(&(t - &one), &Sym::zero(), ("left", "right")).is_some());
    }
}
