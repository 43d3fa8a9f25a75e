//! The formula language of spec files, parsed straight into the exact ring
//! [`Sym`] (so f64, MPFR, jets and the symbolic ring all evaluate the one
//! parsed value — no second evaluator).
//!
//! Grammar (usual precedence, left-associative, `^` binds tightest):
//!
//! ```text
//! expr   := term (('+' | '-') term)*
//! term   := unary (('*' | '/') unary)*
//! unary  := ('-' | '+') unary | power
//! power  := atom ('^' ['-'] integer)?
//! atom   := number | name | ('sin' | 'cos') '(' angle ')' | '(' expr ')'
//! ```
//!
//! Numbers are decimals read exactly (`0.6` = 3/5). Names: the shape
//! parameters (ASCII name or printed symbol), functions defined earlier in
//! the file, `pi` (or `π`), `s` = sin θ and `c` = cos θ for trigonometric
//! bases, the variable `t` for polynomial bases, and any extra symbols the
//! caller allows (control points of join formulas). `sin`/`cos` take the
//! declared angle (`pi*u/2` for `u ∈ [0,1]`, `t` for `t ∈ [0, π/2]`) or an
//! integer multiple of it (`cos(2*t)` expands by the multiple-angle
//! recurrences). `−`, `·`, `×` are accepted for `-`, `*`.

use rug::Rational;
use trig_core::{Ring, Variable, parse_exact};
use trig_symbolic::Sym;

use crate::error::FormulaError;

/// Longest formula accepted (characters).
pub const MAX_LEN: usize = 10_000;
/// Deepest nesting of parentheses and unary signs.
pub const MAX_DEPTH: usize = 64;
/// Largest exponent magnitude in `x^n`.
pub const MAX_EXPONENT: i64 = 64;
/// Largest multiple `k` in `sin(k θ)`.
pub const MAX_MULTIPLE: i64 = 24;

/// What names mean while parsing one formula.
pub struct Scope<'a> {
    /// The declared variable.
    pub variable: Variable,
    /// Its name in formulas: `u` or `t`.
    pub var_name: &'a str,
    /// Shape parameters: (ASCII name, printed symbol).
    pub params: &'a [(String, String)],
    /// Functions defined so far: (name, value).
    pub functions: &'a [(String, Sym)],
    /// Further symbols allowed as themselves (e.g. control points `P0`).
    pub extra: &'a [String],
    /// Decides whether division by a value is allowed (`Err` says why not).
    pub divisor: &'a dyn Fn(&Sym) -> Result<(), String>,
}

impl std::fmt::Debug for Scope<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Scope")
            .field("variable", &self.variable)
            .field("params", &self.params)
            .finish_non_exhaustive()
    }
}

/// Parses `text` in `scope`.
pub fn parse(text: &str, scope: &Scope<'_>) -> Result<Sym, FormulaError> {
    let chars: Vec<char> = text.chars().collect();
    if chars.len() > MAX_LEN {
        return Err(FormulaError::new(
            MAX_LEN,
            format!("formula longer than {MAX_LEN} characters"),
        ));
    }
    let tokens = lex(&chars)?;
    let mut p = Parser {
        tokens,
        at: 0,
        scope,
        depth: 0,
        angle: false,
        end: chars.len(),
    };
    let value = p.expr()?;
    match p.peek() {
        None => Ok(value),
        Some(t) => Err(FormulaError::new(
            t.pos,
            format!(
                "expected an operator (+ - * / ^) or the end, found {}",
                t.kind.describe()
            ),
        )),
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Number(String),
    Name(String),
    Op(char),
    Open,
    Close,
}

impl Kind {
    fn describe(&self) -> String {
        match self {
            Kind::Number(n) => format!("the number `{n}`"),
            Kind::Name(n) => format!("`{n}`"),
            Kind::Op(c) => format!("`{c}`"),
            Kind::Open => "`(`".into(),
            Kind::Close => "`)`".into(),
        }
    }
}

#[derive(Debug, Clone)]
struct Token {
    kind: Kind,
    pos: usize,
}

fn lex(chars: &[char]) -> Result<Vec<Token>, FormulaError> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        let start = i;
        let kind = match ch {
            c if c.is_whitespace() => {
                i += 1;
                continue;
            }
            '0'..='9' | '.' => {
                while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                    i += 1;
                }
                out.push(Token {
                    kind: Kind::Number(chars[start..i].iter().collect()),
                    pos: start,
                });
                continue;
            }
            c if c.is_alphabetic() || c == '_' => {
                while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                out.push(Token {
                    kind: Kind::Name(chars[start..i].iter().collect()),
                    pos: start,
                });
                continue;
            }
            '+' | '-' | '*' | '/' | '^' => Kind::Op(ch),
            '−' => Kind::Op('-'),
            '·' | '×' => Kind::Op('*'),
            '(' => Kind::Open,
            ')' => Kind::Close,
            other => {
                return Err(FormulaError::new(
                    start,
                    format!(
                        "unexpected character `{other}` (expected a number, a name, + - * / ^ or parentheses)"
                    ),
                ));
            }
        };
        out.push(Token { kind, pos: start });
        i += 1;
    }
    Ok(out)
}

struct Parser<'s, 'a> {
    tokens: Vec<Token>,
    at: usize,
    scope: &'s Scope<'a>,
    depth: usize,
    /// Inside the argument of `sin`/`cos`: the variable is allowed.
    angle: bool,
    end: usize,
}

impl Parser<'_, '_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }

    fn pos(&self) -> usize {
        self.peek().map_or(self.end, |t| t.pos)
    }

    fn eat_op(&mut self, ops: &[char]) -> Option<(char, usize)> {
        match self.peek() {
            Some(Token {
                kind: Kind::Op(c),
                pos,
            }) if ops.contains(c) => {
                let found = (*c, *pos);
                self.at += 1;
                Some(found)
            }
            _ => None,
        }
    }

    fn enter(&mut self) -> Result<(), FormulaError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(FormulaError::new(
                self.pos(),
                format!("nested more than {MAX_DEPTH} levels deep"),
            ));
        }
        Ok(())
    }

    fn expr(&mut self) -> Result<Sym, FormulaError> {
        self.enter()?;
        let mut acc = self.term()?;
        while let Some((op, _)) = self.eat_op(&['+', '-']) {
            let rhs = self.term()?;
            acc = if op == '+' { acc + &rhs } else { acc - &rhs };
        }
        self.depth -= 1;
        Ok(acc)
    }

    fn term(&mut self) -> Result<Sym, FormulaError> {
        let mut acc = self.unary()?;
        while let Some((op, pos)) = self.eat_op(&['*', '/']) {
            let rhs = self.unary()?;
            acc = if op == '*' {
                acc * &rhs
            } else {
                self.divide(acc, &rhs, pos)?
            };
        }
        Ok(acc)
    }

    fn divide(&self, a: Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        if b.is_zero() {
            return Err(FormulaError::new(pos, "division by zero"));
        }
        if self.angle {
            if b.as_rational().is_none() {
                return Err(FormulaError::new(
                    pos,
                    "inside sin/cos only division by a nonzero number is allowed",
                ));
            }
        } else {
            (self.scope.divisor)(b).map_err(|why| FormulaError::new(pos, why))?;
        }
        a.checked_div(b)
            .ok_or_else(|| FormulaError::new(pos, "division by zero"))
    }

    fn unary(&mut self) -> Result<Sym, FormulaError> {
        if let Some((op, _)) = self.eat_op(&['-', '+']) {
            self.enter()?;
            let x = self.unary()?;
            self.depth -= 1;
            return Ok(if op == '-' { -x } else { x });
        }
        self.power()
    }

    fn power(&mut self) -> Result<Sym, FormulaError> {
        let base = self.atom()?;
        let Some((_, pos)) = self.eat_op(&['^']) else {
            return Ok(base);
        };
        let negative = self.eat_op(&['-']).is_some();
        let n = match self.peek() {
            Some(Token {
                kind: Kind::Number(text),
                ..
            }) if text.chars().all(|c| c.is_ascii_digit()) => text
                .parse::<i64>()
                .ok()
                .filter(|n| *n <= MAX_EXPONENT)
                .ok_or_else(|| {
                    FormulaError::new(pos, format!("exponent larger than {MAX_EXPONENT}"))
                })?,
            _ => {
                return Err(FormulaError::new(
                    self.pos(),
                    "expected an integer exponent after `^` (e.g. x^2, x^-1)",
                ));
            }
        };
        self.at += 1;
        let exponent = u32::try_from(n).unwrap_or(0);
        let raised = base.powi(exponent);
        if negative {
            self.divide(Sym::one(), &raised, pos)
        } else {
            Ok(raised)
        }
    }

    fn atom(&mut self) -> Result<Sym, FormulaError> {
        let Some(token) = self.peek().cloned() else {
            return Err(FormulaError::new(
                self.end,
                "unexpected end of formula (expected a number, a name or `(`)",
            ));
        };
        self.at += 1;
        match token.kind {
            Kind::Number(text) => number(&text, token.pos),
            Kind::Open => {
                let x = self.expr()?;
                match self.peek() {
                    Some(Token {
                        kind: Kind::Close, ..
                    }) => {
                        self.at += 1;
                        Ok(x)
                    }
                    _ => Err(FormulaError::new(
                        self.pos(),
                        format!("expected `)` to close the `(` at position {}", token.pos),
                    )),
                }
            }
            Kind::Name(name) => self.name(&name, token.pos),
            other => Err(FormulaError::new(
                token.pos,
                format!(
                    "expected a number, a name or `(`, found {}",
                    other.describe()
                ),
            )),
        }
    }

    fn name(&mut self, name: &str, pos: usize) -> Result<Sym, FormulaError> {
        let called = matches!(
            self.peek(),
            Some(Token {
                kind: Kind::Open,
                ..
            })
        );
        if name == "sin" || name == "cos" {
            if !called {
                return Err(FormulaError::new(
                    pos,
                    format!("expected `(` after `{name}`"),
                ));
            }
            return self.trig_call(name == "sin", pos);
        }
        if called {
            return Err(FormulaError::new(
                pos,
                format!("unknown function `{name}` (expected sin or cos)"),
            ));
        }
        let scope = self.scope;
        let trig = scope.variable.is_trigonometric();
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
        if let Some((_, value)) = scope.functions.iter().rev().find(|(n, _)| n == name) {
            return Ok(value.clone());
        }
        if scope.extra.iter().any(|e| e == name) {
            return Ok(Sym::var(name));
        }
        if name == scope.var_name {
            if !trig {
                return Ok(Sym::var("t"));
            }
            if self.angle {
                return Ok(Sym::var("__x"));
            }
            return Err(FormulaError::new(
                pos,
                format!(
                    "wrong variable: `{name}` may appear only inside sin(…)/cos(…) as the angle {}; write s, c or sin({})",
                    angle_text(scope),
                    angle_text(scope)
                ),
            ));
        }
        if name == "s" || name == "c" {
            if trig {
                return Ok(Sym::var(name));
            }
            return Err(FormulaError::new(
                pos,
                format!(
                    "wrong variable: `{name}` (sin/cos of an angle) in a basis polynomial in {}",
                    scope.var_name
                ),
            ));
        }
        if ["u", "t", "x", "theta", "θ"].contains(&name) {
            return Err(FormulaError::new(
                pos,
                format!(
                    "wrong variable: `{name}`; this basis is declared in {}",
                    scope.variable.domain()
                ),
            ));
        }
        Err(FormulaError::new(
            pos,
            format!(
                "unknown symbol `{name}` (expected {})",
                expected_names(scope)
            ),
        ))
    }

    fn trig_call(&mut self, sine: bool, pos: usize) -> Result<Sym, FormulaError> {
        let scope = self.scope;
        if !scope.variable.is_trigonometric() {
            return Err(FormulaError::new(
                pos,
                format!(
                    "wrong variable: sin/cos in a basis polynomial in {}",
                    scope.var_name
                ),
            ));
        }
        if self.angle {
            return Err(FormulaError::new(pos, "sin/cos inside sin/cos"));
        }
        self.at += 1; // `(`
        self.angle = true;
        let arg = self.expr()?;
        self.angle = false;
        match self.peek() {
            Some(Token {
                kind: Kind::Close, ..
            }) => self.at += 1,
            _ => {
                return Err(FormulaError::new(
                    self.pos(),
                    "expected `)` to close the argument of sin/cos",
                ));
            }
        }
        let unit = if scope.variable == trig_core::Variable::UnitAngle {
            Sym::pi() * &Sym::var("__x") / &Sym::int(2)
        } else {
            Sym::var("__x")
        };
        let k = (arg / &unit)
            .as_rational()
            .filter(|k| *k.denom() == 1 && *k > 0 && *k <= MAX_MULTIPLE)
            .and_then(|k| k.numer().to_i64())
            .ok_or_else(|| {
                FormulaError::new(
                    pos,
                    format!(
                        "the argument of sin/cos must be the declared angle {} (or a positive integer multiple of it, at most {MAX_MULTIPLE})",
                        angle_text(scope)
                    ),
                )
            })?;
        let (s, c) = multiple_angle(k);
        Ok(if sine { s } else { c })
    }
}

fn angle_text(scope: &Scope<'_>) -> String {
    if scope.variable == trig_core::Variable::UnitAngle {
        format!("pi*{}/2", scope.var_name)
    } else {
        scope.var_name.to_string()
    }
}

fn expected_names(scope: &Scope<'_>) -> String {
    let mut names: Vec<String> = scope.params.iter().map(|(n, _)| n.clone()).collect();
    names.extend(scope.functions.iter().map(|(n, _)| n.clone()));
    names.extend(scope.extra.iter().cloned());
    if scope.variable.is_trigonometric() {
        names.extend(["s", "c", "sin(…)", "cos(…)"].map(String::from));
    } else {
        names.push(scope.var_name.to_string());
    }
    names.push("pi".into());
    names.join(", ")
}

fn number(text: &str, pos: usize) -> Result<Sym, FormulaError> {
    let q: Rational = parse_exact(text).map_err(|_| {
        FormulaError::new(
            pos,
            format!("`{text}` is not a number (expected e.g. 3, 0.6)"),
        )
    })?;
    Ok(Sym::rational(q))
}

/// `(sin kθ, cos kθ)` in `s`, `c`: `sₖ = 2c·sₖ₋₁ − sₖ₋₂`, `cₖ = 2c·cₖ₋₁ − cₖ₋₂`.
fn multiple_angle(k: i64) -> (Sym, Sym) {
    let (s, c) = (Sym::var("s"), Sym::var("c"));
    let two_c = Sym::int(2) * &c;
    let (mut s0, mut s1) = (Sym::zero(), s);
    let (mut c0, mut c1) = (Sym::one(), c);
    for _ in 1..k {
        let s2 = two_c.clone() * &s1 - &s0;
        let c2 = two_c.clone() * &c1 - &c0;
        (s0, s1, c0, c1) = (s1, s2, c1, c2);
    }
    (s1, c1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scope_with<'a>(
        variable: Variable,
        var_name: &'a str,
        params: &'a [(String, String)],
        functions: &'a [(String, Sym)],
    ) -> Scope<'a> {
        Scope {
            variable,
            var_name,
            params,
            functions,
            extra: &[],
            divisor: &|_| Ok(()),
        }
    }

    fn m() -> Vec<(String, String)> {
        vec![("m".into(), "m".into()), ("lambda".into(), "λ".into())]
    }

    #[test]
    fn thesis_cubic_b0_parses_to_the_catalog_value() {
        let params = m();
        let scope = scope_with(Variable::UnitAngle, "u", &params, &[]);
        let b0 = parse("(1 - sin(pi*u/2))^2 * (1 - m*s)", &scope).unwrap();
        let catalog =
            trig_core::Family::ThesisCubic.eval(&trig_symbolic::symbolic_atoms(), &[Sym::var("m")]);
        assert_eq!(b0, catalog[0]);
        assert_ne!(b0, catalog[1]);
        // decimals are exact, Greek symbols name parameters
        let x = parse("0.6*λ − 3/5·lambda", &scope).unwrap();
        assert!(x.is_zero());
    }

    #[test]
    fn multiple_angles_expand() {
        let params = m();
        let scope = scope_with(Variable::Angle, "t", &params, &[]);
        let c2 = parse("cos(2*t)", &scope).unwrap();
        assert_eq!(c2, parse("c^2 - s^2", &scope).unwrap());
        let s3 = parse("sin(t*3)", &scope).unwrap();
        assert_eq!(s3, parse("3*s - 4*s^3", &scope).unwrap());
    }

    #[test]
    fn errors_name_the_position_and_what_was_expected() {
        let params = m();
        let fns = vec![("b0".to_string(), Sym::var("s"))];
        let trig = scope_with(Variable::UnitAngle, "u", &params, &fns);
        let poly = scope_with(Variable::Polynomial, "t", &params, &[]);
        let err = |text: &str, scope: &Scope<'_>| parse(text, scope).unwrap_err();
        assert_eq!(err("1 + q", &trig).position, 4);
        assert!(err("1 + q", &trig).message.contains("unknown symbol `q`"));
        assert!(err("u*s", &trig).message.contains("wrong variable"));
        assert!(err("t + s", &trig).message.contains("wrong variable"));
        assert!(err("sin(t)", &poly).message.contains("wrong variable"));
        assert!(err("sin(u)", &trig).message.contains("declared angle"));
        assert!(
            err("sin(m*pi*u/2)", &trig)
                .message
                .contains("declared angle")
        );
        assert_eq!(err("(1 + s", &trig).position, 6);
        assert!(err("2 s", &trig).message.contains("expected an operator"));
        assert!(err("1/(s - s)", &trig).message.contains("division by zero"));
        assert!(err("s^m", &trig).message.contains("integer exponent"));
        assert!(err("tan(u)", &trig).message.contains("unknown function"));
        assert!(err("1 # 2", &trig).message.contains("unexpected character"));
        assert!(err("", &trig).message.contains("unexpected end"));
        assert!(err(&"(".repeat(100), &trig).message.contains("nested"));
        // defined functions and t in polynomial bases
        assert_eq!(parse("b0*2", &trig).unwrap(), Sym::int(2) * &Sym::var("s"));
        assert_eq!(parse("t^2", &poly).unwrap(), Sym::var("t") * &Sym::var("t"));
    }

    #[test]
    fn divisions_go_through_the_scope_check() {
        let params = m();
        let scope = Scope {
            divisor: &|d: &Sym| {
                if d.variables().contains("m") {
                    Err("can vanish".into())
                } else {
                    Ok(())
                }
            },
            ..scope_with(Variable::UnitAngle, "u", &params, &[])
        };
        let e = parse("s/(m + 2)", &scope).unwrap_err();
        assert_eq!((e.position, e.message.as_str()), (1, "can vanish"));
        assert!(parse("s/(lambda + 2)", &scope).is_ok());
        assert!(parse("m^-1", &scope).is_err());
    }
}
