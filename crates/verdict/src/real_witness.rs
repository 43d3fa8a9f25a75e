//! Witnesses at real points for spec bases.
//!
//! The generic witness search ([`crate::witness`]) gives every variable its
//! own small rational. For a spec basis the variables are not independent:
//! `sin(α)`, `cos(α)`, `α`, and `t`, `s = sin t`, `c = cos t` are functions
//! of one point, and a witness at `α = 1, cos(alpha) = 0` is no point at
//! all. While a decision about a spec basis runs ([`with_real_points`]), a
//! witness of an expression in the domain's atoms is chosen as a real point
//! — the parameters in their declared sets and `x` in the domain, as exact
//! reals — and re-evaluated there ([`trig_certify::real_point::differ`]):
//! exactly when the atoms are exact there (angles at multiples of π/12),
//! else by disjoint certified enclosures. Other symbols (control points)
//! keep small rational values.

use std::cell::RefCell;
use std::collections::BTreeSet;
use std::rc::Rc;

use rug::Rational;
use trig_certify::algebraic::decimal;
use trig_certify::atoms::param_atoms;
use trig_certify::branch::Axis;
use trig_certify::real_point::{Difference, RealValue, differ, simplest_point};
use trig_core::Domain;
use trig_symbolic::Sym;

use crate::evidence::{Assignment, Expr, Relation, Value, Witness};

/// Decimal places of an enclosed value as printed.
const DIGITS: usize = 15;

/// The real points of a spec basis: its domain, one set per parameter,
/// the parameters' printed symbols.
#[derive(Debug, Clone)]
pub struct RealPoints {
    pub domain: Domain,
    pub axes: Vec<Axis>,
    pub symbols: Vec<String>,
}

thread_local! {
    static CURRENT: RefCell<Option<Rc<RealPoints>>> = const { RefCell::new(None) };
}

/// Runs `f` with witnesses taken at real points of `points` (on this
/// thread; the previous setting is restored afterwards).
pub fn with_real_points<T>(points: RealPoints, f: impl FnOnce() -> T) -> T {
    let previous = CURRENT.with(|c| c.replace(Some(Rc::new(points))));
    let out = f();
    CURRENT.with(|c| *c.borrow_mut() = previous);
    out
}

/// The witness context of this thread as text (for the memo keys of
/// `trig-judge`: a decision's witnesses depend on it).
pub fn context_key() -> String {
    format!("{:?}", current())
}

/// The current real points, if a spec decision runs.
fn current() -> Option<Rc<RealPoints>> {
    CURRENT.with(|c| c.borrow().clone())
}

/// The names that are functions of the point: the variable's atoms, the
/// parameters and their atoms.
fn point_names(points: &RealPoints) -> BTreeSet<String> {
    let mut names: BTreeSet<String> = ["s", "c", "t", "E"].iter().map(|s| s.to_string()).collect();
    names.extend(points.domain.param_names.iter().cloned());
    names.extend(param_atoms(&points.domain).into_iter().map(|a| a.name));
    names
}

/// Values tried for the other symbols (control points): attempt `k`.
fn others_at(names: &[String], k: usize) -> Vec<(String, Rational)> {
    const SMALL: [i64; 12] = [1, 2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31];
    names
        .iter()
        .enumerate()
        .map(|(i, n)| (n.clone(), Rational::from(SMALL[(i + k) % SMALL.len()])))
        .collect()
}

/// `x` with the symbols of `fixed` at their values ([`Sym::subs_all`]);
/// `None` where a denominator vanishes.
fn set(x: &Sym, fixed: &[(String, Rational)]) -> Option<Sym> {
    let values: Vec<(&str, Sym)> = fixed
        .iter()
        .map(|(n, q)| (n.as_str(), Sym::rational(q.clone())))
        .collect();
    x.subs_all(&values).ok()
}

/// A witness that `left ≠ right` at a real point, when a spec decision runs
/// and the expressions involve the point; `None` otherwise (the caller then
/// uses the generic search, which is right for expressions without atoms).
pub fn find(left: &Sym, right: &Sym, labels: (&str, &str)) -> Option<Option<Witness>> {
    let points = current()?;
    let atoms = point_names(&points);
    let names: BTreeSet<String> = left
        .variables()
        .into_iter()
        .chain(right.variables())
        .filter(|n| n != "pi" && !n.starts_with("sqrt("))
        .collect();
    if !names.iter().any(|n| atoms.contains(n)) {
        return None;
    }
    let others: Vec<String> = names
        .iter()
        .filter(|n| !atoms.contains(*n))
        .cloned()
        .collect();
    let uses_x = names
        .iter()
        .any(|n| ["s", "c", "t", "E"].contains(&n.as_str()));
    // `None` also where a value makes a denominator vanish
    let differs = |fixed: &[(String, Rational)]| {
        differ(
            &set(left, fixed)?,
            &set(right, fixed)?,
            &points.domain,
            &points.axes,
        )
    };
    // every other symbol 1 first: the simplest point, often enough
    let ones: Vec<(String, Rational)> = others
        .iter()
        .map(|n| (n.clone(), Rational::from(1)))
        .collect();
    if let Some(d) = differs(&ones) {
        return Some(Some(witness(&points, &ones, uses_x, &d, labels)));
    }
    for k in 0..3 {
        let mut fixed = others_at(&others, k);
        if let Some(mut d) = differs(&fixed) {
            // each symbol 1, one at a time, while the sides still differ (1, not
            // 0: a weight or a scale stays positive, as the claim takes it)
            for i in 0..fixed.len() {
                if fixed[i].1 == 1 {
                    continue;
                }
                let previous = std::mem::replace(&mut fixed[i].1, Rational::from(1));
                match differs(&fixed) {
                    Some(simpler) => d = simpler,
                    None => fixed[i].1 = previous,
                }
            }
            return Some(Some(witness(&points, &fixed, uses_x, &d, labels)));
        }
    }
    // no real point found where the two sides differ: no witness (the
    // residual is printed without one)
    Some(None)
}

/// An instance of what holds everywhere, when a spec decision runs: the
/// values of `exprs` (labelled) at the simplest real point of the domain
/// and the parameter sets ([`simplest_point`]; the point names the
/// variable too), paired in order — a claim that some pair differs (the
/// negation of an identity) is seen to fail there (`stated` differ). Other
/// symbols (control points) take small rational values. `None` outside a
/// spec decision or where an expression is not defined at that point.
pub fn instance(exprs: &[(&str, &Sym)]) -> Option<Witness> {
    let points = current()?;
    let atoms = point_names(&points);
    let names: BTreeSet<String> = exprs
        .iter()
        .flat_map(|(_, e)| e.variables())
        .filter(|n| n != "pi" && !n.starts_with("sqrt("))
        .collect();
    let others: Vec<String> = names
        .iter()
        .filter(|n| !atoms.contains(*n))
        .cloned()
        .collect();
    let fixed = others_at(&others, 0);
    let set = |x: &Sym| {
        fixed.iter().fold(x.clone(), |acc, (n, q)| {
            acc.subs(n, &Sym::rational(q.clone()))
        })
    };
    let values: Vec<Sym> = exprs.iter().map(|(_, e)| set(e)).collect();
    let at = simplest_point(
        &values.iter().collect::<Vec<_>>(),
        &points.domain,
        &points.axes,
    )?;
    let mut point: Vec<Assignment> = points
        .symbols
        .iter()
        .zip(&points.domain.param_names)
        .zip(&at.params)
        .map(|((symbol, name), v)| assignment(symbol, name, v))
        .collect();
    let x = &points.domain.name;
    point.push(assignment(x, x, &at.x));
    point.extend(
        fixed
            .iter()
            .map(|(n, q)| Assignment::exact(n, &Sym::rational(q.clone()))),
    );
    let exact = at.values.iter().all(|v| matches!(v, RealValue::Exact(_)));
    Some(Witness {
        point,
        note: Some(note(exact)),
        values: exprs
            .iter()
            .zip(&values)
            .zip(&at.values)
            .map(|(((label, _), of), v)| Value {
                of: Some(Expr::new(of)),
                label: label.to_string(),
                value: real_value(v),
            })
            .collect(),
        exact,
        stated: Some(Relation::Differ),
    })
}

fn witness(
    points: &RealPoints,
    fixed: &[(String, Rational)],
    uses_x: bool,
    d: &Difference,
    labels: (&str, &str),
) -> Witness {
    let mut point: Vec<Assignment> = points
        .symbols
        .iter()
        .zip(&points.domain.param_names)
        .zip(&d.params)
        .map(|((symbol, name), v)| assignment(symbol, name, v))
        .collect();
    if uses_x {
        let x = &points.domain.name;
        point.push(assignment(x, x, &d.x));
    }
    point.extend(
        fixed
            .iter()
            .map(|(n, q)| Assignment::exact(n, &Sym::rational(q.clone()))),
    );
    let exact = matches!(d.left, RealValue::Exact(_)) && matches!(d.right, RealValue::Exact(_));
    let mut note = note(exact);
    if !exact {
        note.push_str(" (disjoint)");
    }
    Witness {
        point,
        note: Some(note),
        values: vec![
            Value {
                of: None,
                label: labels.0.to_string(),
                value: real_value(&d.left),
            },
            Value {
                of: None,
                label: labels.1.to_string(),
                value: real_value(&d.right),
            },
        ],
        exact,
        stated: None,
    }
}

/// What a real point's values are.
fn note(exact: bool) -> String {
    if exact {
        "a real point: every atom computed from it, values exact".into()
    } else {
        "a real point: every atom computed from it, values enclosed in 128-bit MPFR with outward rounding".into()
    }
}

/// A value at a real point as printed: exact, or its enclosure rounded
/// outward (every printed digit is certified).
fn real_value(v: &RealValue) -> Expr {
    match v {
        RealValue::Exact(x) => Expr::new(x),
        RealValue::Enclosure(i) => {
            let end = |f: &rug::Float, up: bool| {
                f.to_rational()
                    .map_or_else(|| f.to_string(), |q| decimal(&q, DIGITS, up))
            };
            Expr::enclosure(&end(i.lo(), false), &end(i.hi(), true))
        }
    }
}

/// `printed = v`, the variable `name` of the expressions.
fn assignment(printed: &str, name: &str, v: &Sym) -> Assignment {
    Assignment {
        name: printed.to_string(),
        value: v.to_unicode(),
        latex: format!("{} = {}", trig_tex::math(printed), v.to_latex()),
        symbol: Some(Sym::var(name).to_sympy()),
        sympy: Some(v.to_sympy()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Affine;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    /// `t ∈ [0, α]`, `α ∈ (0, π)`, with `sin t`, `cos t`, `sin α`, `cos α`.
    fn c_curve() -> RealPoints {
        RealPoints {
            domain: Domain {
                name: "t".into(),
                param_names: vec!["alpha".into()],
                start: Affine::default(),
                end: Affine::param(0),
                angle: Some(Affine::rational(q(1, 1))),
                uses_variable: true,
                exp: None,
                param_angles: vec![(0, q(1, 1))],
                param_exps: Vec::new(),
            },
            axes: vec![Axis {
                lo: q(0, 1),
                hi: q(1, 1),
                lo_open: true,
                hi_open: true,
                pi: true,
            }],
            symbols: vec!["α".into()],
        }
    }

    #[test]
    fn a_jump_in_cos_alpha_is_witnessed_at_a_real_alpha() {
        // the C-B-spline's third-derivative jump α²(cos α + 1)/(cos α − 1):
        // the generic search printed `α = 1, cos(alpha) = 0`, no point at all
        let (a, ca) = (Sym::var("alpha"), Sym::var("cos(alpha)"));
        let jump = a.clone() * &a * &(ca.clone() + &Sym::one()) / &(ca - &Sym::one());
        let w = with_real_points(c_curve(), || {
            crate::witness::find(&jump, &Sym::zero(), ("jump", "0"))
        })
        .expect("a witness");
        let names: Vec<&str> = w.point.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["α"]);
        assert!(w.exact);
        // α = π/2: cos α = 0, the jump is −π²/4
        assert_eq!(w.values[0].value.best_unicode(), "−π²/4");
        // outside a spec decision the generic search names no point: it
        // would value α and cos(alpha) one by one
        assert!(crate::witness::find(&jump, &Sym::zero(), ("jump", "0")).is_none());
    }

    #[test]
    fn control_points_keep_rational_values_beside_a_real_point() {
        // (sin t − t)·P1 against 0 on [0, α]: a real t, P1 rational
        let (s, t, p1) = (Sym::var("s"), Sym::var("t"), Sym::var("P1"));
        let x = (s - &t) * &p1;
        let w = with_real_points(c_curve(), || {
            crate::witness::find(&x, &Sym::zero(), ("left", "right"))
        })
        .expect("a witness");
        let names: Vec<&str> = w.point.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["α", "t", "P₁"]);
    }

    #[test]
    fn other_symbols_are_one_where_that_separates_the_sides() {
        // (P1 + P2 + P3)·s against 3·s: every other symbol 1 makes them
        // equal, so the small values 1, 2, 3 are tried, then each symbol set
        // to 1 while they still differ: P2 = 1 kept, P3 = 1 undone
        let (s, p) = (Sym::var("s"), ["P1", "P2", "P3"].map(Sym::var));
        let left = (p[0].clone() + &p[1] + &p[2]) * &s;
        let witness = |right: i64| {
            with_real_points(c_curve(), || {
                crate::witness::find(&left, &(Sym::int(right) * &s), ("left", "right"))
            })
            .expect("a witness")
        };
        let values = |w: &Witness| -> Vec<String> {
            ["P₁", "P₂", "P₃"]
                .iter()
                .map(|n| {
                    w.point
                        .iter()
                        .find(|a| a.name == *n)
                        .expect(n)
                        .value
                        .clone()
                })
                .collect()
        };
        assert_eq!(values(&witness(3)), ["1", "1", "3"]);
        // where 1 already separates them, every other symbol is 1
        assert_eq!(values(&witness(2)), ["1", "1", "1"]);
    }
}
