//! The ends of a maximal parameter range beyond the polynomial engine
//! ([`crate::analytic_range`]): the problem they are searched on (a
//! basis, its domain, the parameter's units), the typed ends ([`End`]),
//! the equation a certified end solves ([`Equation`]) and the witnesses
//! beyond an end. Shared by the search ([`crate::analytic_range`]), the
//! certification of an end ([`crate::transcendental`]) and its exact value
//! by elimination ([`crate::elimination`]).

use rug::Rational;
use trig_core::Domain;
use trig_symbolic::Sym;

use crate::algebraic::{Algebraic, decimal};
use crate::atoms::{param_atoms, reflect, value};
use crate::branch::{Axis, Outcome};
use crate::factors;

/// A parameter value where a function is certified negative at a point.
#[derive(Debug, Clone, PartialEq)]
pub struct Witness {
    /// The parameter (in units of π on a π axis).
    pub param: Rational,
    /// The function, by its index in the basis.
    pub function: usize,
    /// The point `x = a + Lτ`: `τ` exactly, `x` to f64.
    pub tau: Rational,
    pub x: f64,
    /// A certified enclosure of the value of the function's numerator
    /// (denominators of fixed sign taken out), `hi < 0`.
    pub value: (f64, f64),
}

/// The value of an exact end.
#[derive(Debug, Clone, PartialEq)]
pub enum ExactValue {
    /// A rational (in units of π on a π axis).
    Rational(Rational),
    /// A real algebraic number (a root of a polynomial factor in the
    /// parameter alone).
    Algebraic(Algebraic),
}

/// One end of the maximal interval.
#[derive(Debug, Clone, PartialEq)]
pub enum End {
    /// An exact end: the basis is not defined there (open), or an
    /// equation vanishes exactly there (closed when the functions are `≥ 0`
    /// at it).
    Exact {
        value: ExactValue,
        closed: bool,
        why: String,
        /// An admissible value next to it (proved with the interval).
        inside: Rational,
        /// The certified negative value just beyond it, when found.
        outside: Option<Witness>,
    },
    /// The unique root of `equation` in `[lo, hi]`, certified (a Krawczyk
    /// or interval Newton step), transcendental or at least not found
    /// exact: never called exact. The functions are `≥ 0` at the root
    /// (the end belongs to the interval).
    Certified {
        lo: Rational,
        hi: Rational,
        equation: Equation,
        inside: Rational,
        outside: Witness,
    },
    /// The end lies in `(ok, bad)`; it could not be certified (`why`).
    Bracket {
        ok: Rational,
        bad: Rational,
        outside: Witness,
        why: String,
    },
    /// Admissible at every value tested up to the search limit `upto`
    /// (the interval up to it proved as a whole): no end found.
    Beyond { upto: Rational },
    /// A point test could not be decided.
    Undecided { at: Rational, why: String },
}

impl End {
    /// The end as mathematics (no verdict): `symbol` names the parameter,
    /// `names` the functions; values in units of π on a π axis.
    pub fn describe(&self, problem: &Problem<'_>, symbol: &str, names: &[String]) -> String {
        let value = |q: &Rational| value_text(q, problem.pi);
        match self {
            End::Exact {
                value: ExactValue::Rational(v),
                closed,
                why,
                ..
            } => format!(
                "{symbol} = {} exactly ({}; {why})",
                value(v),
                if *closed { "included" } else { "excluded" }
            ),
            End::Exact {
                value: ExactValue::Algebraic(a),
                why,
                ..
            } => format!("{} (exact; {why})", a.describe(symbol, 12)),
            End::Certified {
                lo,
                hi,
                equation,
                inside,
                outside,
            } => {
                let enclosure = if problem.pi {
                    let (a, b) = times_pi(lo, hi);
                    format!(
                        "{symbol}/π ∈ [{}, {}], {symbol} ∈ [{}, {}]",
                        decimal(lo, DIGITS, false),
                        decimal(hi, DIGITS, true),
                        decimal(&a, DIGITS, false),
                        decimal(&b, DIGITS, true)
                    )
                } else {
                    format!(
                        "{symbol} ∈ [{}, {}]",
                        decimal(lo, DIGITS, false),
                        decimal(hi, DIGITS, true)
                    )
                };
                format!(
                    "the unique root of {} with {enclosure} (certified enclosure by a Krawczyk step, transcendental or at least not found exact: not called exact; included); just inside {symbol} = {} is admissible (proved), just outside {symbol} = {} {} < 0 at {} ≈ {:.6} (its numerator in [{:.6e}, {:.6e}], certified)",
                    equation.describe(problem.domain, names),
                    value(inside),
                    value(&outside.param),
                    names[outside.function],
                    problem.domain.name,
                    outside.x,
                    outside.value.0,
                    outside.value.1
                )
            }
            End::Bracket { ok, bad, why, .. } => format!(
                "between {} and {} (a bracket, not certified: {why})",
                value(ok),
                value(bad)
            ),
            End::Beyond { upto } => format!(
                "not below {}: every value up to the search limit {} is admissible",
                value(upto),
                value(upto)
            ),
            End::Undecided { at, why } => {
                format!("not decided (at {symbol} = {}: {why})", value(at))
            }
        }
    }
}

/// Decimal digits of a certified enclosure as printed (rounded outward).
const DIGITS: usize = 24;

/// `[lo·π, hi·π]` enclosed by rationals (π between two 256-bit floats).
fn times_pi(lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    use rug::Float;
    use rug::float::{Constant, Round};
    let bound = |round| {
        Float::with_val_round(256, Constant::Pi, round)
            .0
            .to_rational()
            .expect("π is finite")
    };
    let (p_lo, p_hi) = (bound(Round::Down), bound(Round::Up));
    let products = [
        Rational::from(lo * &p_lo),
        Rational::from(lo * &p_hi),
        Rational::from(hi * &p_lo),
        Rational::from(hi * &p_hi),
    ];
    let min = products.iter().min().cloned().unwrap_or_default();
    let max = products.iter().max().cloned().unwrap_or_default();
    (min, max)
}

/// `q`, or `q·π` on a π axis.
pub fn value_text(q: &Rational, pi: bool) -> String {
    if pi {
        format!("{q}·π")
    } else {
        q.to_string()
    }
}

/// Why a parameter value is not (known to be) admissible.
#[derive(Debug, Clone, PartialEq)]
pub enum Outside {
    Negative(Witness),
    /// A denominator vanishes identically there: the basis is not defined.
    Undefined,
    Undecided(String),
}

/// What the search works on.
#[derive(Debug)]
pub struct Problem<'a> {
    pub functions: &'a [Sym],
    pub domain: &'a Domain,
    /// The parameter is measured in units of π.
    pub pi: bool,
    /// `mirror[j] = Some(k)`, `k < j`, when `f_j(x) = f_k(a + b − x)`
    /// exactly: the reflection maps the domain onto itself, so `f_j ≥ 0`
    /// exactly when `f_k ≥ 0`, and `f_j` is not decided again.
    mirror: Vec<Option<usize>>,
}

impl<'a> Problem<'a> {
    /// The functions of a basis on `domain`, one parameter (in units of π
    /// when `pi`).
    pub fn new(functions: &'a [Sym], domain: &'a Domain, pi: bool) -> Problem<'a> {
        let mirror = (0..functions.len())
            .map(|j| {
                let r = reflect(&functions[j], domain)?;
                (0..j).find(|&k| r == functions[k])
            })
            .collect();
        Problem {
            functions,
            domain,
            pi,
            mirror,
        }
    }

    /// The parameter value where the domain shrinks to a point
    /// (`b(p) − a(p) = 0`), when it depends on the parameter and the value
    /// is exact in the axis' units.
    pub fn empty_domain_at(&self) -> Option<Rational> {
        let d = self.domain;
        let length = d.end.plus(&d.start.scale(&Rational::from(-1)));
        let q = length.params.iter().find(|(i, _)| *i == 0)?.1.clone();
        if q == 0 {
            return None;
        }
        // length = constant + π·pi + q·p, p = π·y on a π axis
        let root = if self.pi {
            (length.constant == 0).then(|| -Rational::from(&length.pi / &q))
        } else {
            (length.pi == 0).then(|| -Rational::from(&length.constant / &q))
        }?;
        Some(root)
    }

    /// The functions to decide (a mirror image of an earlier one is not).
    pub(crate) fn decided(&self) -> impl Iterator<Item = (usize, &Sym)> {
        self.functions
            .iter()
            .enumerate()
            .filter(|(j, _)| self.mirror[*j].is_none())
    }

    /// The single-parameter axis `[lo, hi]`.
    pub fn axis(&self, lo: &Rational, hi: &Rational, lo_open: bool, hi_open: bool) -> Vec<Axis> {
        vec![Axis {
            lo: lo.clone(),
            hi: hi.clone(),
            lo_open,
            hi_open,
            pi: self.pi,
        }]
    }

    /// All functions `≥ 0` at the parameter value `p`, or why not.
    pub fn admissible(&self, p: &Rational) -> Result<(), Outside> {
        if self.undefined_at(p) {
            return Err(Outside::Undefined);
        }
        let axis = self.axis(p, p, false, false);
        for (i, f) in self.decided() {
            match factors::nonnegative(f, self.domain, &axis) {
                Outcome::Proved { .. } => {}
                Outcome::Negative { tau, x, value, .. } => {
                    return Err(Outside::Negative(Witness {
                        param: p.clone(),
                        function: i,
                        tau,
                        x,
                        value,
                    }));
                }
                Outcome::Undecided(why) => return Err(Outside::Undecided(why)),
            }
        }
        Ok(())
    }

    /// True when a denominator factor of some function vanishes
    /// identically at `p` (the parameter and its atoms substituted
    /// exactly; `false` when an atom is not exact there).
    pub fn undefined_at(&self, p: &Rational) -> bool {
        let atoms = param_atoms(self.domain);
        let at = [if self.pi {
            Sym::rational(p.clone()) * &Sym::pi()
        } else {
            Sym::rational(p.clone())
        }];
        let symbols = trig_symbolic::symbolic_atoms();
        let name = &self.domain.param_names[0];
        self.functions.iter().any(|f| {
            f.denominator().keys().any(|factor| {
                let mut v = Sym::from_poly(factor.clone()).subs(name, &at[0]);
                for a in atoms.iter().filter(|a| a.param == 0) {
                    if !v.variables().contains(&a.name) {
                        continue;
                    }
                    match value(&a.name, self.domain, &symbols, &at, &atoms) {
                        Some(e) => v = v.subs(&a.name, &e),
                        None => return false,
                    }
                }
                v.is_zero()
            })
        })
    }

    /// The proof that every function is `≥ 0` for the parameter in the
    /// axis (factor by factor), with the total boxes.
    pub fn prove(&self, axis: &[Axis]) -> Outcome {
        let decided: Vec<&Sym> = self.decided().map(|(_, f)| f).collect();
        let outcomes =
            trig_core::parallel::map(&decided, |f| factors::nonnegative(f, self.domain, axis));
        let mut boxes = 0;
        for outcome in outcomes {
            match outcome {
                Outcome::Proved { boxes: b } => boxes += b,
                other => return other,
            }
        }
        Outcome::Proved { boxes }
    }
}

/// The equation an end solves (the factor signed so that it is `≥ 0`
/// inside).
#[derive(Debug, Clone, PartialEq)]
pub enum Equation {
    /// `factor(p) = 0`, a factor in the parameter alone.
    Parameter { function: usize, factor: Sym },
    /// `factor(x, p) = 0` at the end `x = start` (`at_end` false) or
    /// `x = end` of the domain; `value` is the factor there, exactly — or,
    /// when the factor vanishes there identically, its derivative of order
    /// `order` into the domain (the first that does not).
    EndValue {
        function: usize,
        factor: Sym,
        order: u32,
        at_end: bool,
        value: Sym,
    },
    /// `factor(x, p) = 0` and `derivative = ∂ₓfactor = 0`: the minimum over
    /// `x` touches 0 inside the domain, at `τ ∈ tau` (`x = a + Lτ`).
    Stationary {
        function: usize,
        factor: Sym,
        derivative: Sym,
        tau: (Rational, Rational),
    },
}

impl Equation {
    /// The equation as printed: the variable's atoms named after it
    /// (`sin(t)`, `exp(t)` when their rate is 1), `names` the functions.
    pub fn describe(&self, domain: &Domain, names: &[String]) -> String {
        let show = |f: &Sym| shown(f, domain);
        let var = &domain.name;
        match self {
            Equation::Parameter { function, factor } => {
                format!("{} = 0 (a factor of {})", show(factor), names[*function])
            }
            Equation::EndValue {
                function,
                factor,
                order,
                at_end,
                value,
            } => {
                let end = if *at_end { &domain.end } else { &domain.start };
                let what = match order {
                    0 => String::new(),
                    1 => "the derivative into the domain of ".into(),
                    k => format!("the derivative of order {k} into the domain of "),
                };
                format!(
                    "{} = 0 ({what}the factor {} of {} at {var} = {})",
                    show(value),
                    show(factor),
                    names[*function],
                    end.text(&domain.param_names)
                )
            }
            Equation::Stationary {
                function,
                factor,
                derivative,
                ..
            } => format!(
                "{} = 0 and {} = 0 in ({var}, {}) (the factor of {} and its derivative in {var}: where its minimum over {var} touches 0)",
                show(factor),
                show(derivative),
                domain.param_names[0],
                names[*function]
            ),
        }
    }
}

/// `f` printed with the variable's atoms named after it when their rate
/// is 1 (`s` as `sin(t)`, `E` as `exp(t)`), Unicode.
fn shown(f: &Sym, domain: &Domain) -> String {
    let greek = |text: String| {
        domain.param_names.iter().fold(text, |text, n| {
            let u = Sym::var(n).to_unicode();
            text.replace(&format!("({n}"), &format!("({u}"))
        })
    };
    let var = &domain.name;
    let unit = |rate: Option<Rational>| rate.is_some_and(|r| r == 1);
    let mut g = f.clone();
    if unit(domain.angle.as_ref().and_then(|w| w.as_rational().cloned())) {
        g = g
            .subs("s", &Sym::var(&format!("sin({var})")))
            .subs("c", &Sym::var(&format!("cos({var})")));
    }
    if unit(domain.exp.clone()) {
        g = g.subs("E", &Sym::var(&format!("exp({var})")));
    }
    if var != "t" {
        g = g.subs("t", &Sym::var(var));
    }
    greek(g.to_unicode())
}
