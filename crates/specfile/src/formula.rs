//! Formulas of spec files, lowered from their syntax tree (`ast.rs`)
//! into the exact ring [`Sym`] — so f64, MPFR, jets and the symbolic ring
//! all evaluate the one lowered value, with no second evaluator.
//!
//! Names: the shape parameters (ASCII name or printed symbol), the
//! functions and definitions of the file (in any order: resolved on use,
//! cycles refused), `pi` (or `π`), the variable, the shorthands `s`, `c`
//! for the declared angle of the legacy variables, and extra symbols the
//! caller allows (control points of join formulas).
//!
//! Calls, each kept in the exact ring ([`trig_core::Domain`] holds the
//! base rates found in the whole file, [`crate::frequencies`]):
//! * `sin`, `cos` of `k·ωx + Σ kᵢbᵢpᵢ + qπ` (integers `k`, `kᵢ`): multiple
//!   angles of the atoms `s = sin ωx`, `c = cos ωx` and `sin(bᵢpᵢ)`,
//!   `cos(bᵢpᵢ)`, combined by the sum formula; `qπ` a multiple of π/12;
//! * `exp`, `sinh`, `cosh` of `k·κx + Σ kᵢbᵢpᵢ`: powers of `E = exp(κx)`
//!   and `exp(bᵢpᵢ)`, `sinh z = (eᶻ − e⁻ᶻ)/2`;
//! * `sqrt` of a rational whose square-free part is a product of 2, 3, 5, 7.
//!
//! The cost of a formula is bounded as a whole: every intermediate value
//! has at most [`MAX_TERMS`] terms, degree [`MAX_DEGREE`] and coefficients
//! of [`MAX_BITS`] bits, and the multiplications of one formula (powers
//! included) at most [`MAX_WORK`] term products — checked before each
//! product is formed.

use rug::Rational;
use trig_core::angles::{angle_sum, multiple_angle};
use trig_core::{Affine, Domain, Ring};
use trig_symbolic::Sym;

use crate::ast::{self, Expr, Func, Node};
use crate::budget::Budget;
use crate::error::FormulaError;

pub use crate::budget::{MAX_BITS, MAX_DEGREE, MAX_TERMS, MAX_WORK};

/// The ring names of the atoms: `t` is the variable (whatever its printed
/// name), `E = exp(κx)`.
pub const T: &str = "t";
/// See [`T`].
pub const E: &str = "E";

/// What names mean while lowering one formula.
pub struct Scope<'a> {
    /// The domain with its base rates.
    pub domain: &'a Domain,
    /// The variable's name in formulas (`u`, `t`, `x`, …).
    pub var_name: &'a str,
    /// For the legacy variables, `k` with the declared angle `= k·ω`: the
    /// shorthands `s`, `c` are its sine and cosine.
    pub shorthand: Option<i64>,
    /// Shape parameters: (ASCII name, printed symbol).
    pub params: &'a [(String, String)],
    /// The functions and definitions of the file, by name.
    pub resolve: &'a dyn Fn(&str) -> Option<Result<Sym, String>>,
    /// Further symbols allowed as themselves (e.g. control points `P0`).
    pub extra: &'a [String],
    /// Decides whether division by a value is allowed (`Err` says why not).
    pub divisor: &'a dyn Fn(&Sym) -> Result<(), String>,
}

impl std::fmt::Debug for Scope<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Scope")
            .field("domain", &self.domain)
            .field("params", &self.params)
            .finish_non_exhaustive()
    }
}

/// Parses and lowers `text` in `scope`.
pub fn parse(text: &str, scope: &Scope<'_>) -> Result<Sym, FormulaError> {
    lower(&ast::parse(text)?, scope)
}

/// Lowers a syntax tree in `scope`.
pub fn lower(e: &Expr, scope: &Scope<'_>) -> Result<Sym, FormulaError> {
    Lowering {
        scope,
        budget: Budget::default(),
    }
    .value(e)
}

/// An argument `x·(a + bπ) + rest`, linear in the variable and the
/// parameters (the argument of `sin`, `exp`, …, a symmetry map, a domain
/// end).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Linear {
    /// The coefficient of the variable, `a + bπ`.
    pub x: Affine,
    /// Constant and parameter part.
    pub rest: Affine,
}

impl Linear {
    fn constant(&self) -> Option<&Rational> {
        (self.x == Affine::default())
            .then(|| self.rest.as_rational())
            .flatten()
    }

    fn scale(&self, q: &Rational) -> Linear {
        Linear {
            x: self.x.scale(q),
            rest: self.rest.scale(q),
        }
    }

    fn plus(&self, o: &Linear) -> Linear {
        Linear {
            x: self.x.plus(&o.x),
            rest: self.rest.plus(&o.rest),
        }
    }

    /// `q·π` alone.
    fn pi_multiple(&self) -> Option<&Rational> {
        let pure =
            self.x == Affine::default() && self.rest.constant == 0 && self.rest.params.is_empty();
        pure.then_some(&self.rest.pi)
    }

    /// Rational in everything (no π, no parameters) but the variable.
    fn rational_in_x(&self) -> bool {
        self.x.pi == 0 && self.rest.pi == 0 && self.rest.params.is_empty()
    }
}

/// Reads an argument that must be linear in the variable `var_name` (none:
/// only the parameters) and the parameters (`what` names it in errors:
/// "the argument of sin").
pub fn linear(
    e: &Expr,
    var_name: Option<&str>,
    params: &[(String, String)],
    what: &str,
) -> Result<Linear, FormulaError> {
    let refuse = |pos: usize| {
        FormulaError::new(
            pos,
            match var_name {
                Some(v) => format!(
                    "{what} must be linear in {v} and the parameters, with rational or π coefficients (e.g. {v}/2, pi*{v}/2, alpha - {v})"
                ),
                None => format!(
                    "{what} must be linear in the parameters, with rational or π coefficients (e.g. alpha, pi/2, 2*alpha + 1)"
                ),
            },
        )
    };
    let rec = |x: &Expr| linear(x, var_name, params, what);
    Ok(match &e.node {
        Node::Number(q) => Linear {
            rest: Affine::rational(q.clone()),
            ..Linear::default()
        },
        Node::Name(n) if Some(n.as_str()) == var_name => Linear {
            x: Affine::rational(Rational::from(1)),
            ..Linear::default()
        },
        Node::Name(n) if n == "pi" || n == "π" => Linear {
            rest: Affine::pi_times(Rational::from(1)),
            ..Linear::default()
        },
        Node::Name(n) => match params.iter().position(|(a, s)| a == n || s == n) {
            Some(i) => Linear {
                rest: Affine::param(i),
                ..Linear::default()
            },
            None => {
                return Err(FormulaError::new(
                    e.pos,
                    format!(
                        "`{n}` may not appear in {what}: only {}the parameters, pi and numbers",
                        var_name.map(|v| format!("{v}, ")).unwrap_or_default()
                    ),
                ));
            }
        },
        Node::Neg(a) => rec(a)?.scale(&Rational::from(-1)),
        Node::Add(a, b) => rec(a)?.plus(&rec(b)?),
        Node::Sub(a, b) => rec(a)?.plus(&rec(b)?.scale(&Rational::from(-1))),
        Node::Mul(a, b) => {
            let (l, r) = (rec(a)?, rec(b)?);
            if let Some(q) = r.constant() {
                l.scale(q)
            } else if let Some(q) = l.constant() {
                r.scale(q)
            } else {
                // q·π times something rational in the variable: π·x/2
                let (pi, other) = match (l.pi_multiple(), r.pi_multiple()) {
                    (Some(q), _) if r.rational_in_x() => (q.clone(), r),
                    (_, Some(q)) if l.rational_in_x() => (q.clone(), l),
                    _ => return Err(refuse(e.pos)),
                };
                Linear {
                    x: Affine::pi_times(Rational::from(&other.x.constant * &pi)),
                    rest: Affine::pi_times(Rational::from(&other.rest.constant * &pi)),
                }
            }
        }
        Node::Div(a, b) => match rec(b)?.constant() {
            Some(q) if *q != 0 => rec(a)?.scale(&Rational::from(q.recip_ref())),
            _ => return Err(refuse(e.pos)),
        },
        Node::Pow(a, 1) => rec(a)?,
        Node::Pow(..) | Node::Call(..) => return Err(refuse(e.pos)),
    })
}

struct Lowering<'s, 'a> {
    scope: &'s Scope<'a>,
    budget: Budget,
}

impl Lowering<'_, '_> {
    fn params(&self) -> Vec<Sym> {
        self.scope.params.iter().map(|(n, _)| Sym::var(n)).collect()
    }

    fn bounded(&self, x: Sym, pos: usize) -> Result<Sym, FormulaError> {
        self.budget.bounded(x, pos)
    }

    fn product(&self, a: &Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        self.budget.product(a, b, pos)
    }

    /// `a / b` with the divisor checked factor by factor as written
    /// (`1/(A·g)` checks `A` and `g`, a power its base): a product is
    /// nonzero exactly when its factors are, and each is smaller to prove.
    fn quotient(&self, a: &Sym, b: &Expr, pos: usize) -> Result<Sym, FormulaError> {
        /// The factors of a product as written, with multiplicities.
        fn factors<'e>(e: &'e Expr, times: u32, out: &mut Vec<(&'e Expr, u32)>) {
            match &e.node {
                Node::Mul(x, y) => {
                    factors(x, times, out);
                    factors(y, times, out);
                }
                Node::Pow(x, n) if *n > 0 => factors(x, times * *n as u32, out),
                _ => out.push((e, times)),
            }
        }
        let mut parts = Vec::new();
        factors(b, 1, &mut parts);
        // each factor divides separately, so the value keeps them apart
        let mut q = a.clone();
        for (part, times) in parts {
            let v = self.value(part)?;
            for _ in 0..times {
                q = self.divide(&q, &v, pos)?;
            }
        }
        Ok(q)
    }

    fn divide(&self, a: &Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        if b.is_zero() {
            return Err(FormulaError::new(pos, "division by zero"));
        }
        (self.scope.divisor)(b).map_err(|why| FormulaError::new(pos, why))?;
        let q = a
            .checked_div(b)
            .ok_or_else(|| FormulaError::new(pos, "division by zero"))?;
        self.bounded(q, pos)
    }

    /// `xⁿ` by repeated squaring, every product charged.
    fn power(&self, x: &Sym, n: u32, pos: usize) -> Result<Sym, FormulaError> {
        let mut result = Sym::one();
        let mut base = x.clone();
        let mut e = n;
        while e > 0 {
            if e & 1 == 1 {
                result = self.product(&result, &base, pos)?;
            }
            e >>= 1;
            if e > 0 {
                base = self.product(&base, &base, pos)?;
            }
        }
        Ok(result)
    }

    fn value(&self, e: &Expr) -> Result<Sym, FormulaError> {
        let pos = e.pos;
        match &e.node {
            Node::Number(q) => Ok(Sym::rational(q.clone())),
            Node::Name(n) => self.name(n, pos),
            Node::Neg(a) => Ok(-self.value(a)?),
            Node::Add(a, b) => self.bounded(self.value(a)? + &self.value(b)?, pos),
            Node::Sub(a, b) => self.bounded(self.value(a)? - &self.value(b)?, pos),
            Node::Mul(a, b) => self.product(&self.value(a)?, &self.value(b)?, pos),
            Node::Div(a, b) => self.quotient(&self.value(a)?, b, pos),
            Node::Pow(a, n) => {
                let x = self.value(a)?;
                let raised = self.power(&x, n.unsigned_abs() as u32, pos)?;
                if *n < 0 {
                    self.divide(&Sym::one(), &raised, pos)
                } else {
                    Ok(raised)
                }
            }
            Node::Call(f, arg) => self.call(*f, arg, pos),
        }
    }

    fn name(&self, name: &str, pos: usize) -> Result<Sym, FormulaError> {
        let scope = self.scope;
        if name == "pi" || name == "π" {
            return Ok(Sym::pi());
        }
        if let Some((p, _)) = scope
            .params
            .iter()
            .find(|(n, symbol)| n == name || symbol == name)
        {
            return Ok(Sym::var(p));
        }
        if let Some(found) = (scope.resolve)(name) {
            return found.map_err(|why| FormulaError::new(pos, why));
        }
        if scope.extra.iter().any(|e| e == name) {
            return Ok(Sym::var(name));
        }
        if name == scope.var_name {
            return Ok(Sym::var(T));
        }
        if let ("s" | "c", Some(k)) = (name, scope.shorthand) {
            let (s, c) = multiple_angle(&Sym::var("s"), &Sym::var("c"), k);
            return Ok(if name == "s" { s } else { c });
        }
        if ["u", "t", "x", "theta", "θ"].contains(&name) {
            return Err(FormulaError::new(
                pos,
                format!(
                    "wrong variable: `{name}`; this basis is declared in {}",
                    scope.domain
                ),
            ));
        }
        let hint = if ["s", "c"].contains(&name) {
            format!(
                "; `{name}` is a shorthand of the legacy variables only: write sin({v}) or cos({v})",
                v = scope.var_name
            )
        } else {
            String::new()
        };
        Err(FormulaError::new(
            pos,
            format!(
                "unknown symbol `{name}` (expected {}){hint}",
                expected_names(scope)
            ),
        ))
    }

    fn call(&self, f: Func, arg: &Expr, pos: usize) -> Result<Sym, FormulaError> {
        let scope = self.scope;
        if f == Func::Sqrt {
            let x = self.value(arg)?;
            return x
                .as_rational()
                .and_then(|q| Sym::rational(q).try_sqrt())
                .ok_or_else(|| {
                    FormulaError::new(
                        pos,
                        "sqrt takes a number whose square-free part is a product of 2, 3, 5, 7 (e.g. sqrt(2), sqrt(3/4))",
                    )
                });
        }
        let what = format!("the argument of {}", f.name());
        let l = linear(arg, Some(scope.var_name), scope.params, &what)?;
        let params = self.params();
        let domain = scope.domain;
        let multiple = |coef: &Affine,
                        base: Option<&Affine>,
                        kind: &str|
         -> Result<i64, FormulaError> {
            if *coef == Affine::default() {
                return Ok(0);
            }
            let k = base
                .and_then(|b| ratio(coef, b))
                .filter(|k| *k.denom() == 1);
            k.and_then(|k| k.numer().to_i64())
                .filter(|k| k.unsigned_abs() <= 64)
                .ok_or_else(|| {
                    FormulaError::new(
                        arg.pos,
                        format!(
                            "the {kind} rate of {} is not an integer multiple (at most 64) of the base rate found in the file",
                            scope.var_name
                        ),
                    )
                })
        };
        if f.is_trigonometric() {
            let k = multiple(&l.x, domain.angle.as_ref(), "angle")?;
            let (s, c) = (Sym::var("s"), Sym::var("c"));
            let rest = domain
                .sin_cos_of(&l.rest, &Sym::one(), &params)
                .ok_or_else(|| {
                    FormulaError::new(
                        arg.pos,
                        format!(
                            "sin/cos of {} cannot be formed exactly: constant angles must be multiples of pi/12",
                            l.rest.text(&names(scope.params))
                        ),
                    )
                })?;
            let (sin, cos) = angle_sum(&multiple_angle(&s, &c, k), &rest);
            let value = if f == Func::Sin { sin } else { cos };
            return self.bounded(value, pos);
        }
        // exp, sinh, cosh
        let kappa = domain.exp.clone().map(Affine::rational);
        let k = multiple(&l.x, kappa.as_ref(), "exponential")?;
        let rest = domain
            .exp_of(&l.rest, &Sym::one(), &params)
            .ok_or_else(|| {
                FormulaError::new(
                    arg.pos,
                    format!(
                        "exp of {} cannot be formed exactly: the argument may hold the variable and parameters, no nonzero constant or pi",
                        l.rest.text(&names(scope.params))
                    ),
                )
            })?;
        let e = Sym::var(E);
        let ek = if k >= 0 {
            self.power(&e, k as u32, pos)?
        } else {
            Sym::one() / &self.power(&e, k.unsigned_abs() as u32, pos)?
        };
        let up = self.product(&ek, &rest, pos)?;
        let down = Sym::one() / &up;
        let value = match f {
            Func::Exp => up,
            Func::Sinh => (up - &down) / &Sym::int(2),
            _ => (up + &down) / &Sym::int(2),
        };
        self.bounded(value, pos)
    }
}

/// `a/b` when it is rational (both rational, or both rational multiples of
/// π; no parameters).
pub(crate) fn ratio(a: &Affine, b: &Affine) -> Option<Rational> {
    if !a.params.is_empty() || !b.params.is_empty() {
        return None;
    }
    match (a.as_rational(), b.as_rational()) {
        (Some(x), Some(y)) if *y != 0 => Some(Rational::from(x / y)),
        _ if a.constant == 0 && b.constant == 0 && b.pi != 0 => Some(Rational::from(&a.pi / &b.pi)),
        _ => None,
    }
}

fn names(params: &[(String, String)]) -> Vec<String> {
    params.iter().map(|(n, _)| n.clone()).collect()
}

fn expected_names(scope: &Scope<'_>) -> String {
    let mut names: Vec<String> = scope.params.iter().map(|(n, _)| n.clone()).collect();
    names.extend(scope.extra.iter().cloned());
    names.push(scope.var_name.to_string());
    if scope.shorthand.is_some() {
        names.extend(["s", "c"].map(String::from));
    }
    names.push("pi".into());
    names.push(format!("{}(…)", ast::FUNCTIONS));
    names.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Variable;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    fn params() -> Vec<(String, String)> {
        vec![("m".into(), "m".into()), ("lambda".into(), "λ".into())]
    }

    fn with<R>(domain: &Domain, shorthand: Option<i64>, f: impl FnOnce(&Scope<'_>) -> R) -> R {
        let params = params();
        let scope = Scope {
            domain,
            var_name: &domain.name,
            shorthand,
            params: &params,
            resolve: &|n| (n == "b0").then(|| Ok(Sym::var("s"))),
            extra: &[],
            divisor: &|_| Ok(()),
        };
        f(&scope)
    }

    fn domain(v: Variable) -> Domain {
        Domain::from_variable(v, &["m", "lambda"])
    }

    #[test]
    fn thesis_cubic_b0_parses_to_the_catalog_value() {
        let d = domain(Variable::UnitAngle);
        let b0 = with(&d, Some(1), |s| parse("(1 - sin(pi*u/2))^2 * (1 - m*s)", s)).unwrap();
        let catalog =
            trig_core::Family::ThesisCubic.eval(&trig_symbolic::symbolic_atoms(), &[Sym::var("m")]);
        assert_eq!(b0, catalog[0]);
        assert_ne!(b0, catalog[1]);
        // decimals are exact, Greek symbols name parameters
        let x = with(&d, Some(1), |s| parse("0.6*λ − 3/5·lambda", s)).unwrap();
        assert!(x.is_zero());
    }

    #[test]
    fn multiple_and_half_angles_and_sums() {
        let d = domain(Variable::Angle);
        let p = |text: &str| with(&d, Some(1), |s| parse(text, s)).unwrap();
        assert_eq!(p("cos(2*t)"), p("c^2 - s^2"));
        assert_eq!(p("sin(t*3)"), p("3*s - 4*s^3"));
        assert_eq!(p("sin(pi/2 - t)"), p("c"));
        assert_eq!(p("cos(t + pi)"), p("-c"));
        // half angles: with base ω = 1/2 the shorthand s is sin(2·(t/2))
        let half = Domain {
            angle: Some(Affine::rational(q(1, 2))),
            ..domain(Variable::Angle)
        };
        let h = |text: &str| with(&half, Some(2), |s| parse(text, s)).unwrap();
        assert_eq!(h("sin(t)"), h("2*sin(t/2)*cos(t/2)"));
        assert_eq!(h("s"), h("sin(t)"));
        assert_eq!(h("cos(3*t/2)"), h("4*cos(t/2)^3 - 3*cos(t/2)"));
        // sin of π/4 is exact
        assert_eq!(h("sin(pi/4)^2"), Sym::rational(q(1, 2)));
    }

    #[test]
    fn exponentials_and_the_variable_outside_sin() {
        let d = Domain {
            exp: Some(q(1, 1)),
            uses_variable: true,
            ..domain(Variable::Polynomial)
        };
        let p = |text: &str| with(&d, None, |s| parse(text, s)).unwrap();
        assert_eq!(p("cosh(t)^2 - sinh(t)^2"), Sym::one());
        assert_eq!(p("exp(2*t)*exp(-t)"), p("exp(t)"));
        assert_eq!(p("t*exp(t)"), Sym::var("t") * &Sym::var(E));
        let e = with(&d, None, |s| parse("exp(1)", s)).unwrap_err();
        assert!(e.message.contains("cannot be formed exactly"), "{e:?}");
        assert_eq!(p("sqrt(12)"), Sym::int(2) * &Sym::var("sqrt(3)"));
    }

    #[test]
    fn errors_name_the_position_and_what_was_expected() {
        let d = domain(Variable::UnitAngle);
        let err = |text: &str| with(&d, Some(1), |s| parse(text, s)).unwrap_err();
        assert_eq!(err("1 + q").position, 4);
        assert!(err("1 + q").message.contains("unknown symbol `q`"));
        assert!(
            err("t + s")
                .message
                .contains("wrong variable: `t`; this basis is declared in u in [0, 1]")
        );
        assert!(err("sin(m*u)").message.contains("must be linear"));
        assert!(
            err("sin(pi*u/3)")
                .message
                .contains("not an integer multiple")
        );
        assert!(err("2 s").message.contains("expected `*`"));
        assert!(err("1/(s - s)").message.contains("division by zero"));
        // a formula's cost is bounded as a whole, not per power
        assert!(err("((1 + s + c)^64)^8").message.contains("degree"));
        assert!(err("(((7^64)^64)^64)^64").message.contains("bits"));
        assert!(err("cos(24*pi*u/2)^64").message.contains("degree"));
        // defined names and the variable outside sin
        assert_eq!(
            with(&d, Some(1), |s| parse("b0*2", s)).unwrap(),
            Sym::int(2) * &Sym::var("s")
        );
        assert_eq!(
            with(&d, Some(1), |s| parse("u^2", s)).unwrap(),
            Sym::var(T) * &Sym::var(T)
        );
    }

    #[test]
    fn divisions_go_through_the_scope_check() {
        let d = domain(Variable::UnitAngle);
        let params = params();
        let scope = Scope {
            domain: &d,
            var_name: "u",
            shorthand: Some(1),
            params: &params,
            resolve: &|_| None,
            extra: &[],
            divisor: &|x: &Sym| {
                if x.variables().contains("m") {
                    Err("can vanish".into())
                } else {
                    Ok(())
                }
            },
        };
        let e = parse("s/(m + 2)", &scope).unwrap_err();
        assert_eq!((e.position, e.message.as_str()), (1, "can vanish"));
        assert!(parse("s/(lambda + 2)", &scope).is_ok());
        assert!(parse("m^-1", &scope).is_err());
    }

    #[test]
    fn the_deepest_formula_read_lowers_on_a_test_thread() {
        let d = domain(Variable::UnitAngle);
        let text = format!("{}s", "s - ".repeat(ast::MAX_HEIGHT));
        let x = with(&d, Some(1), |s| parse(&text, s)).unwrap();
        assert_eq!(x, Sym::int(1 - ast::MAX_HEIGHT as i64) * &Sym::var("s"));
    }

    #[test]
    fn linear_arguments() {
        let p = params();
        let l = linear(
            &ast::parse("pi*u/2 - lambda/3 + 1").unwrap(),
            Some("u"),
            &p,
            "x",
        )
        .unwrap();
        assert_eq!(l.x, Affine::pi_times(q(1, 2)));
        assert_eq!(l.rest.text(&["m".into(), "lambda".into()]), "-lambda/3 + 1");
        assert!(linear(&ast::parse("u*u").unwrap(), Some("u"), &p, "x").is_err());
        assert!(linear(&ast::parse("sin(u)").unwrap(), Some("u"), &p, "x").is_err());
    }
}
