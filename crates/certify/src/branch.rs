//! Signs of functions that are not polynomial in `sin`, `cos` or the
//! variable — `t` beside `sin t` (C-curves), `sinh`, `exp`, sines of
//! parameters, domains `[0, α]` — by branch and bound with rigorous
//! enclosures, so every `holds` is a proof.
//!
//! The variable is normalised, `x = a(p) + L(p)·τ` with `τ ∈ [0, 1]`; a
//! box is `τ ∈ [τ₀, τ₁]` times an interval for each parameter. On a box:
//!
//! 1. the function is enclosed by a Taylor model of its exact formula
//!    ([`crate::enclosure`]; intersected with plain interval evaluation,
//!    which is exact at faces where the model keeps a rounding remainder):
//!    a lower end `≥ 0` proves it there, an upper end `< 0` is a certified
//!    counterexample (the box's rational centre); a side along which the
//!    function is proved monotone is replaced by its lower end;
//! 2. on a box touching a face of the whole region (`τ = 0`, `τ = 1`, a
//!    parameter's range end) — where basis functions vanish and enclosures
//!    cannot decide — by the face arguments (`branch/faces.rs`): a function
//!    zero on the face to order `m` has the sign of its `m`-th derivative
//!    into the box (Taylor's theorem: the removable zero divided out), and
//!    otherwise it is `≥ 0` when it is `≥ 0` on the face and its derivative
//!    into the box is `≥ 0` (derivatives are exact, by the chain rule
//!    `∂τ = L·∂x`, `∂pᵢ = ∂pᵢ|ₓ + (aᵢ + Lᵢτ)·∂x`);
//! 3. otherwise the box is split along its widest side.
//!
//! A function of the variable alone is decided on the union of the
//! domains, one dimension instead of `1 + d`. Strict signs (for divisors)
//! use the same steps; at an open range end the face itself is excluded,
//! so `α − sin α > 0` on `(0, π)` is proved from `(α − sin α)‴ = cos α > 0`
//! near `α = 0`. The budget is counted in boxes, never timed, so a verdict
//! does not depend on the machine; a decision that does not finish within
//! it is undecided, never a failure.

use std::cell::RefCell;
use std::rc::Rc;

use rug::Rational;
use trig_core::{Affine, Domain, End, Interval, ParamRange};
use trig_symbolic::Sym;

pub use crate::coordinates::Axis;
use crate::coordinates::{BoxFunction, Coordinates};

mod faces;

/// Most box evaluations of one decision: the budget is counted, not timed,
/// so a verdict never depends on the machine's load.
const BUDGET: usize = 12_000;
/// Deepest chain of face arguments (derivative order).
const MAX_ORDER: usize = 8;
/// Deepest subdivision.
const MAX_DEPTH: usize = 40;
/// Most box evaluations of one face argument before it is abandoned.
const ATTEMPT: usize = 3_000;
/// Most subdivisions of one face argument below the box it starts on (the
/// outer search splits further and tries again).
const ATTEMPT_DEPTH: usize = 10;

impl Axis {
    /// A published range as an axis, when it is bounded.
    pub fn from_range(r: &ParamRange) -> Option<Axis> {
        Some(Axis {
            lo: r.lo.value()?.clone(),
            hi: r.hi.value()?.clone(),
            lo_open: matches!(r.lo, End::Open(_)),
            hi_open: matches!(r.hi, End::Open(_)),
            pi: r.pi,
        })
    }
}

/// The decision about one sign question.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Proved, after this many box evaluations.
    Proved { boxes: usize },
    /// The function is negative on a whole box: at its centre `τ`
    /// (`x = a + Lτ`) and parameters (in units of π on π axes), its value
    /// lies in `[lo, hi]`, `hi < 0`.
    Negative {
        tau: Rational,
        params: Vec<Rational>,
        x: f64,
        value: (f64, f64),
    },
    /// Not decided (the reason).
    Undecided(String),
}

/// An expression with its first derivatives along each coordinate, formed
/// on first use (the monotonicity test and the face arguments share them).
struct Fun {
    e: BoxFunction,
    d: RefCell<Vec<Option<Rc<Fun>>>>,
}

impl Fun {
    fn new(e: BoxFunction, dims: usize) -> Rc<Fun> {
        Rc::new(Fun {
            e,
            d: RefCell::new(vec![None; dims]),
        })
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Goal {
    NonNegative,
    /// `> 0` except on the region's open faces.
    Positive,
}

struct Engine<'a> {
    coords: Coordinates<'a>,
    evaluations: usize,
    /// The evaluation count at which the current attempt gives up.
    limit: usize,
    /// The depth at which the current attempt stops splitting.
    floor: usize,
    /// Set to the order of a derivative certified negative somewhere: the
    /// face argument that needs it `≥ 0` is doomed, its search stops.
    doomed: Option<usize>,
    /// The ends of the variable's domain are excluded (`τ ∈ (0, 1)`): the
    /// faces `τ = 0`, `τ = 1` are open, like an open range end.
    open_variable: bool,
}

/// `−f` (its derivatives formed anew).
fn negate(f: &Fun, dims: usize) -> Rc<Fun> {
    Fun::new(f.e.negated(), dims)
}

impl Engine<'_> {
    fn out_of_budget(&self) -> bool {
        self.evaluations >= self.limit.min(BUDGET)
    }

    /// True when side `k` of the box is at most a quarter of the region's.
    fn narrow(&self, bx: &[(Rational, Rational)], k: usize) -> bool {
        let global = if k == 0 {
            Rational::from(1)
        } else {
            Rational::from(&self.coords.axes[k - 1].hi - &self.coords.axes[k - 1].lo)
        };
        Rational::from(&bx[k].1 - &bx[k].0) * 4u32 <= global
    }

    /// The enclosure of `e` on the box (one evaluation of the budget).
    fn enclose(&mut self, e: &BoxFunction, bx: &[(Rational, Rational)]) -> Option<Interval> {
        self.evaluations += 1;
        self.coords.enclose(e, bx)
    }

    /// `∂/∂(coordinate k)` of `f`, formed once (along a π axis the factor
    /// π > 0 is left out: only signs are used).
    fn derived(&self, f: &Rc<Fun>, k: usize) -> Rc<Fun> {
        if let Some(d) = &f.d.borrow()[k] {
            return d.clone();
        }
        let d = Fun::new(self.coords.derivative(&f.e, k), f.d.borrow().len());
        f.d.borrow_mut()[k] = Some(d.clone());
        d
    }

    /// Decides the goal for `e` on the box; `order` counts face arguments.
    fn decide(
        &mut self,
        f: &Rc<Fun>,
        bx: &[(Rational, Rational)],
        goal: Goal,
        order: usize,
        depth: usize,
    ) -> Outcome {
        let e = &f.e;
        if self.out_of_budget() {
            return Outcome::Undecided(format!(
                "the interval search stopped at its budget of {BUDGET} boxes"
            ));
        }
        if e.is_zero() {
            return match goal {
                Goal::NonNegative => Outcome::Proved {
                    boxes: self.evaluations,
                },
                Goal::Positive => Outcome::Undecided("identically zero".into()),
            };
        }
        if let Some(v) = self.enclose(e, bx) {
            let proved = match goal {
                Goal::NonNegative => *v.lo() >= 0,
                Goal::Positive => *v.lo() > 0,
            };
            if proved {
                return Outcome::Proved {
                    boxes: self.evaluations,
                };
            }
            if *v.hi() < 0 {
                return if order == 0 {
                    self.negative_at(bx, &v)
                } else {
                    self.doomed = Some(order);
                    Outcome::Undecided(
                        "a derivative is negative: the face argument does not apply".into(),
                    )
                };
            }
        }
        // face arguments on the faces of the whole region, on boxes near them
        for k in 0..bx.len() {
            if bx[k].0 == bx[k].1 || !self.narrow(bx, k) {
                continue;
            }
            for lower in [true, false] {
                if order >= MAX_ORDER {
                    break;
                }
                if let Some(out) = self.face_argument(f, bx, goal, order, depth, k, lower) {
                    return out;
                }
            }
        }
        if depth >= MAX_DEPTH.min(self.floor) {
            return Outcome::Undecided("subdivision depth limit".into());
        }
        // split the widest side
        let Some(k) = (0..bx.len())
            .filter(|&k| bx[k].0 != bx[k].1)
            .max_by(|&i, &j| {
                let w = |k: usize| Rational::from(&bx[k].1 - &bx[k].0);
                w(i).cmp(&w(j))
            })
        else {
            return Outcome::Undecided("not decided at a point".into());
        };
        let mid = Rational::from(&bx[k].0 + &bx[k].1) / 2u32;
        let mut result = Outcome::Proved { boxes: 0 };
        for half in [
            (bx[k].0.clone(), mid.clone()),
            (mid.clone(), bx[k].1.clone()),
        ] {
            let mut child = bx.to_vec();
            child[k] = half;
            // a negative box anywhere decides; an undecided one is kept
            // while the other half is searched for one
            let out = self.decide(f, &child, goal, order, depth + 1);
            if self.doomed == Some(order) {
                return out;
            }
            match out {
                Outcome::Proved { boxes } => {
                    if let Outcome::Proved { .. } = result {
                        result = Outcome::Proved { boxes };
                    }
                }
                negative @ Outcome::Negative { .. } => return negative,
                undecided => result = undecided,
            }
        }
        result
    }

    /// A grid of points (8 steps per side, at most 4096 points) where the
    /// function is certified negative, if any: a quick counterexample.
    fn probe(&mut self, f: &Rc<Fun>, bx: &[(Rational, Rational)]) -> Option<Outcome> {
        let wide = bx.iter().filter(|(l, h)| l != h).count();
        let steps = |k: usize| -> u32 {
            match (bx[k].0 == bx[k].1, wide <= 2) {
                (true, _) => 1,
                (false, true) => 8,
                (false, false) => 4,
            }
        };
        let mut index = vec![0u32; bx.len()];
        loop {
            let point: Vec<(Rational, Rational)> = bx
                .iter()
                .zip(&index)
                .enumerate()
                .map(|(k, ((lo, hi), i))| {
                    let q = lo.clone()
                        + Rational::from(hi - lo) * Rational::from((2 * *i + 1, 2 * steps(k)));
                    (q.clone(), q)
                })
                .collect();
            if let Some(v) = self.enclose(&f.e, &point) {
                if *v.hi() < 0 {
                    return Some(self.negative_at(&point, &v));
                }
            }
            let k = (0..index.len()).find(|&k| index[k] + 1 < steps(k))?;
            index[k] += 1;
            for i in &mut index[..k] {
                *i = 0;
            }
        }
    }

    fn negative_at(&self, bx: &[(Rational, Rational)], v: &Interval) -> Outcome {
        let centre: Vec<Rational> = bx
            .iter()
            .map(|(l, h)| Rational::from(l + h) / 2u32)
            .collect();
        Outcome::Negative {
            tau: centre[0].clone(),
            params: centre[1..].to_vec(),
            x: self.coords.x_at(&centre[0], &centre[1..]),
            value: (v.lo().to_f64(), v.hi().to_f64()),
        }
    }
}

/// `f ≥ 0` for every `x` of the domain and every parameter in `axes`
/// (one axis per parameter of the domain, in order; bounded).
pub fn nonnegative(f: &Sym, domain: &Domain, axes: &[Axis]) -> Outcome {
    run(f, domain, axes, Goal::NonNegative, false)
}

/// `f > 0` on the domain for every parameter in `axes` (open ends
/// excluded).
pub fn positive(f: &Sym, domain: &Domain, axes: &[Axis]) -> Outcome {
    run(f, domain, axes, Goal::Positive, false)
}

/// `f > 0` on the open domain `a(p) < x < b(p)` for every parameter in
/// `axes` (open range ends excluded too): `f` may vanish at the ends of
/// the domain, where the face arguments need it positive only inside
/// (Taylor's theorem with Lagrange's remainder puts `ξ` strictly inside).
pub fn positive_inside(f: &Sym, domain: &Domain, axes: &[Axis]) -> Outcome {
    if let Some(why) = zero_at_closed_end(f, domain, axes) {
        return Outcome::Undecided(why);
    }
    run(f, domain, axes, Goal::Positive, true)
}

/// Why `f` cannot be positive: it vanishes identically (for every `x`) at
/// a closed end of a parameter's range, decided exactly before any search.
fn zero_at_closed_end(f: &Sym, domain: &Domain, axes: &[Axis]) -> Option<String> {
    let coords = Coordinates::new(domain, axes);
    let e = coords.function(f);
    let mut bx = vec![(Rational::new(), Rational::from(1))];
    bx.extend(axes.iter().map(|a| (a.lo.clone(), a.hi.clone())));
    for (i, a) in axes.iter().enumerate() {
        for (end, open) in [(&a.lo, a.lo_open), (&a.hi, a.hi_open)] {
            if !open && coords.zero_on_face(&e, &bx, i + 1, end) {
                let unit = if a.pi { "·π" } else { "" };
                return Some(format!(
                    "it vanishes identically at the closed range end {} = {end}{unit}",
                    domain.param_names[i]
                ));
            }
        }
    }
    None
}

fn run(f: &Sym, domain: &Domain, axes: &[Axis], goal: Goal, open_variable: bool) -> Outcome {
    // a function of the variable alone is decided on the union of the
    // domains, `[min a(p), max b(p)]` (one dimension instead of 1 + d; with
    // the ends excluded, the union of the open domains lies inside it)
    if let Some(hull) = variable_hull(f, domain, axes) {
        if let proved @ Outcome::Proved { .. } = search(f, &hull, &[], goal, open_variable) {
            return proved;
        }
    }
    search(f, domain, axes, goal, open_variable)
}

/// When `f` depends on the variable alone (its atoms, `π`, radicals) and
/// the domain's ends on the parameters: the domain `[min a, max b]` over
/// the parameter box, without parameters. The union of the domains
/// `[a(p), b(p)]` over a connected box is that interval (up to ends not
/// attained at open range ends), so `f ≥ 0` there is `f ≥ 0` on every
/// domain.
fn variable_hull(f: &Sym, domain: &Domain, axes: &[Axis]) -> Option<Domain> {
    let own =
        |v: &String| ["s", "c", "t", "E", "pi"].contains(&v.as_str()) || v.starts_with("sqrt(");
    if axes.is_empty()
        || !f.variables().iter().all(own)
        || domain.angle.as_ref().is_some_and(|w| !w.params.is_empty())
    {
        return None;
    }
    // an affine end at the corner that makes it least (or greatest)
    let extreme = |a: &Affine, least: bool| -> Affine {
        let mut out = Affine {
            constant: a.constant.clone(),
            pi: a.pi.clone(),
            params: Vec::new(),
        };
        for (i, q) in &a.params {
            let axis = &axes[*i];
            let at = if (*q > 0) == least {
                &axis.lo
            } else {
                &axis.hi
            };
            let v = Rational::from(q * at);
            if axis.pi {
                out.pi += v;
            } else {
                out.constant += v;
            }
        }
        out
    };
    Some(Domain {
        param_names: Vec::new(),
        start: extreme(&domain.start, true),
        end: extreme(&domain.end, false),
        param_angles: Vec::new(),
        param_exps: Vec::new(),
        ..domain.clone()
    })
}

/// A point where `f < 0`, certified, found by the search's first probe
/// alone (a grid of a few points per axis, no subdivision): a cheap
/// refutation to try before any certificate. `None` says nothing.
pub fn probe_negative(f: &Sym, domain: &Domain, axes: &[Axis]) -> Option<Outcome> {
    let (mut engine, e, bx) = prepared(f, domain, axes, false);
    engine.probe(&e, &bx)
}

fn search(f: &Sym, domain: &Domain, axes: &[Axis], goal: Goal, open_variable: bool) -> Outcome {
    let (mut engine, e, bx) = prepared(f, domain, axes, open_variable);
    if let Some(negative) = engine.probe(&e, &bx) {
        return negative;
    }
    engine.decide(&e, &bx, goal, 0, 0)
}

/// The engine, the function and the box `[0, τ_end] × axes` of a search.
fn prepared<'a>(
    f: &Sym,
    domain: &'a Domain,
    axes: &'a [Axis],
    open_variable: bool,
) -> (Engine<'a>, Rc<Fun>, Vec<(Rational, Rational)>) {
    let engine = Engine {
        coords: Coordinates::new(domain, axes),
        evaluations: 0,
        limit: BUDGET,
        floor: MAX_DEPTH,
        doomed: None,
        open_variable,
    };
    // a function of the parameters alone does not depend on τ: τ = 0
    let free = !f
        .variables()
        .iter()
        .any(|v| ["s", "c", "t", "E"].contains(&v.as_str()));
    let tau_end = if free {
        Rational::new()
    } else {
        Rational::from(1)
    };
    let mut bx = vec![(Rational::new(), tau_end)];
    bx.extend(axes.iter().map(|a| (a.lo.clone(), a.hi.clone())));
    let e = Fun::new(engine.coords.function(f), bx.len());
    (engine, e, bx)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Affine;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    /// `t ∈ [0, α]` with `s, c = sin t, cos t`, `sin α`, `cos α` atoms.
    fn c_curve(exp: bool) -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(q(1, 1))),
            uses_variable: true,
            exp: exp.then(|| q(1, 1)),
            param_angles: vec![(0, q(1, 1))],
            param_exps: if exp { vec![(0, q(1, 1))] } else { Vec::new() },
        }
    }

    fn alpha(lo: Rational, hi: Rational, lo_open: bool, hi_open: bool) -> Vec<Axis> {
        vec![Axis {
            lo,
            hi,
            lo_open,
            hi_open,
            pi: false,
        }]
    }

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    #[test]
    fn c_curve_denominators_are_positive_up_to_the_open_end() {
        let d = c_curve(false);
        // (0, 3.14]: α − sin α > 0 needs the face argument at the open end 0
        let axes = alpha(q(0, 1), q(314, 100), true, false);
        let a = v("alpha") - &v("sin(alpha)");
        assert!(
            matches!(positive(&a, &d, &axes), Outcome::Proved { .. }),
            "{:?}",
            positive(&a, &d, &axes)
        );
        // 2 − 2cos α − α sin α > 0 on (0, 3.14]
        let g = Sym::int(2) - &(Sym::int(2) * &v("cos(alpha)")) - &(v("alpha") * &v("sin(alpha)"));
        assert!(matches!(positive(&g, &d, &axes), Outcome::Proved { .. }));
        // with the end 0 closed, α − sin α vanishes there: not positive
        let closed = alpha(q(0, 1), q(314, 100), false, false);
        assert!(!matches!(positive(&a, &d, &closed), Outcome::Proved { .. }));
    }

    #[test]
    fn positive_inside_excludes_the_ends_of_the_domain_only() {
        let d = c_curve(false);
        let axes = alpha(q(1, 2), q(3, 1), false, false);
        // t − sin t vanishes at t = 0 (to third order): positive inside only
        let f = v("t") - &v("s");
        assert!(matches!(
            positive_inside(&f, &d, &axes),
            Outcome::Proved { .. }
        ));
        assert!(!matches!(positive(&f, &d, &axes), Outcome::Proved { .. }));
        // sin t · sin(α − t) = sin t (sin α c − cos α s): zero at both ends
        let g = v("s") * &(v("sin(alpha)") * &v("c") - &(v("cos(alpha)") * &v("s")));
        let out = positive_inside(&g, &d, &axes);
        assert!(matches!(out, Outcome::Proved { .. }), "{out:?}");
        // cos t changes sign inside the domain for α > π/2
        assert!(matches!(
            positive_inside(&v("c"), &d, &axes),
            Outcome::Negative { .. }
        ));
        // α − t·... vanishing for every t at the closed end α = 1/2: refused
        // at once, with the reason
        let h = (v("alpha") - &Sym::rational(q(1, 2))) * &g;
        match positive_inside(&h, &d, &axes) {
            Outcome::Undecided(why) => {
                assert!(why.contains("closed range end alpha = 1/2"), "{why}")
            }
            other => panic!("{other:?}"),
        }
        // the same end open: positive inside
        let open = alpha(q(1, 2), q(3, 1), true, false);
        let out = positive_inside(&h, &d, &open);
        assert!(matches!(out, Outcome::Proved { .. }), "{out:?}");
    }

    #[test]
    fn nonnegative_with_the_variable_beside_sin() {
        let d = c_curve(false);
        let axes = alpha(q(1, 10), q(3, 1), false, false);
        // t − sin t ≥ 0 on [0, α]: zero at t = 0, derivative 1 − cos t ≥ 0
        let f = v("t") - &v("s");
        let out = nonnegative(&f, &d, &axes);
        assert!(matches!(out, Outcome::Proved { .. }), "{out:?}");
        // cos t < 0 beyond π/2: a certified negative box
        match nonnegative(&v("c"), &d, &axes) {
            Outcome::Negative { x, value, .. } => {
                assert!(x > std::f64::consts::FRAC_PI_2 && value.1 < 0.0);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn exponentials() {
        let d = c_curve(true);
        let axes = alpha(q(1, 2), q(2, 1), false, false);
        // e^t − 1 − t ≥ 0 (zero at t = 0 to second order)
        let f = v("E") - &Sym::one() - &v("t");
        assert!(matches!(nonnegative(&f, &d, &axes), Outcome::Proved { .. }));
        // exp(α) − 1 − α > 0 on (0, 2]
        let open = alpha(q(0, 1), q(2, 1), true, false);
        let g = v("exp(alpha)") - &Sym::one() - &v("alpha");
        assert!(matches!(positive(&g, &d, &open), Outcome::Proved { .. }));
    }
}
