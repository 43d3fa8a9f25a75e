//! Seed 000's appendices print long formulas; they are transcribed here as
//! text, as close to the print as plain ASCII allows, and read into a syntax
//! tree ([`Formula`]) that is evaluated exactly, at a rational point or in
//! the symbolic ring. Grammar: `+ − * / ^`, parentheses `()`, `[]`, `{}`,
//! juxtaposition multiplies (`4(S + 1) c1`), integers, identifiers. `S`
//! stands for `s(ξ) = ξ² − ξ + 1` (the paper's `s(ξ)`), `pi` for `π`, `zeta`
//! for `ζ = ξ`; every other identifier is a symbol.
//!
//! Also: the comparison of a printed value with the computed one, whose
//! evidence shows both.

use std::collections::BTreeSet;

use rug::Rational;
use rug::ops::Pow;
use trig_core::families::seed000::s_of_xi;
use trig_symbolic::Sym;

use crate::evidence::{self, Evidence, Kind};
use crate::exact::IDENTITY;
use crate::status::Status;
use crate::verdict::Verdict;
use crate::witness::witness;

/// `ζ` as the catalog names it.
pub fn zeta() -> Sym {
    Sym::var("zeta")
}

/// `s(ξ) = ξ² − ξ + 1`.
pub fn s_xi() -> Sym {
    s_of_xi(&zeta())
}

/// A transcribed formula as read: its syntax tree, so that it can be
/// evaluated exactly at a rational point (cheap, whatever its size) or
/// built in the symbolic ring (only when needed), and so that the
/// shorthands of a print can be substituted textually ([`Formula::with`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Formula(Expr);

#[derive(Debug, Clone, PartialEq)]
enum Expr {
    Num(i64),
    /// A symbol of the print.
    Var(String),
    /// A known value (`S = s(ξ)`, or a substituted shorthand's value).
    Value(Sym),
    Neg(Box<Expr>),
    Add(Box<Expr>, Box<Expr>),
    Sub(Box<Expr>, Box<Expr>),
    Mul(Box<Expr>, Box<Expr>),
    Div(Box<Expr>, Box<Expr>),
    Pow(Box<Expr>, u32),
}

impl Formula {
    /// Reads a transcribed formula, `S` standing for `s(ξ)`.
    ///
    /// # Panics
    /// On a transcription that does not parse (a defect of the
    /// transcription, caught by the unit tests of every claim file).
    pub fn parse(text: &str) -> Formula {
        let tokens = tokenize(text);
        let mut p = Parser { t: &tokens, i: 0 };
        let e = p.expr();
        assert!(
            p.i == tokens.len(),
            "trailing input in {text:?} at token {}",
            p.i
        );
        Formula(e).with_value("S", &s_xi())
    }

    /// The formula with every occurrence of the symbol `name` replaced by
    /// the formula `by` (a shorthand of the print).
    pub fn with(self, name: &str, by: &Formula) -> Formula {
        Formula(self.0.replace(name, &by.0))
    }

    fn with_value(self, name: &str, value: &Sym) -> Formula {
        Formula(self.0.replace(name, &Expr::Value(value.clone())))
    }

    /// The value in the symbolic ring.
    ///
    /// # Panics
    /// On a division by an exactly zero quantity.
    pub fn to_sym(&self) -> Sym {
        self.0.to_sym()
    }

    /// The exact value at rational values of the symbols; `None` when a
    /// symbol has no value or a divisor vanishes there.
    pub fn at(&self, value: &dyn Fn(&str) -> Option<Rational>) -> Option<Rational> {
        self.0.at(value)
    }

    /// The value in the symbolic ring at values of the symbols given as
    /// ring elements (`π` may stay a symbol); `None` when a symbol has no
    /// value or a divisor vanishes there.
    pub fn at_sym(&self, value: &dyn Fn(&str) -> Option<Sym>) -> Option<Sym> {
        self.0.at_sym(value)
    }

    /// The names of the symbols that occur (those of substituted values
    /// included).
    pub fn variables(&self) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        self.0.collect_variables(&mut out);
        out
    }
}

impl Expr {
    fn children(&self) -> Vec<&Expr> {
        match self {
            Expr::Num(_) | Expr::Var(_) | Expr::Value(_) => Vec::new(),
            Expr::Neg(a) | Expr::Pow(a, _) => vec![a],
            Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) => vec![a, b],
        }
    }

    fn replace(self, name: &str, by: &Expr) -> Expr {
        let r = |e: Box<Expr>| Box::new(e.replace(name, by));
        match self {
            Expr::Var(n) if n == name => by.clone(),
            Expr::Num(_) | Expr::Var(_) | Expr::Value(_) => self,
            Expr::Neg(a) => Expr::Neg(r(a)),
            Expr::Pow(a, k) => Expr::Pow(r(a), k),
            Expr::Add(a, b) => Expr::Add(r(a), r(b)),
            Expr::Sub(a, b) => Expr::Sub(r(a), r(b)),
            Expr::Mul(a, b) => Expr::Mul(r(a), r(b)),
            Expr::Div(a, b) => Expr::Div(r(a), r(b)),
        }
    }

    fn to_sym(&self) -> Sym {
        match self {
            Expr::Num(n) => Sym::rational(Rational::from(*n)),
            Expr::Var(name) => Sym::var(name),
            Expr::Value(v) => v.clone(),
            Expr::Neg(a) => -a.to_sym(),
            Expr::Add(a, b) => a.to_sym() + &b.to_sym(),
            Expr::Sub(a, b) => a.to_sym() - &b.to_sym(),
            Expr::Mul(a, b) => a.to_sym() * &b.to_sym(),
            Expr::Div(a, b) => a
                .to_sym()
                .checked_div(&b.to_sym())
                .unwrap_or_else(|| panic!("printed formula divides by zero")),
            Expr::Pow(a, k) => {
                let base = a.to_sym();
                (0..*k).fold(Sym::one(), |acc, _| acc * &base)
            }
        }
    }

    fn at(&self, value: &dyn Fn(&str) -> Option<Rational>) -> Option<Rational> {
        Some(match self {
            Expr::Num(n) => Rational::from(*n),
            Expr::Var(name) => value(name)?,
            Expr::Value(v) => v.eval_rational(value).ok()?,
            Expr::Neg(a) => -a.at(value)?,
            Expr::Add(a, b) => a.at(value)? + b.at(value)?,
            Expr::Sub(a, b) => a.at(value)? - b.at(value)?,
            Expr::Mul(a, b) => a.at(value)? * b.at(value)?,
            Expr::Div(a, b) => {
                let den = b.at(value)?;
                if den == 0 {
                    return None;
                }
                a.at(value)? / den
            }
            Expr::Pow(a, k) => a.at(value)?.pow(*k),
        })
    }

    fn at_sym(&self, value: &dyn Fn(&str) -> Option<Sym>) -> Option<Sym> {
        Some(match self {
            Expr::Num(n) => Sym::int(*n),
            Expr::Var(name) => value(name)?,
            Expr::Value(v) => v.eval(&Sym::one(), value).ok()?,
            Expr::Neg(a) => -a.at_sym(value)?,
            Expr::Add(a, b) => a.at_sym(value)? + &b.at_sym(value)?,
            Expr::Sub(a, b) => a.at_sym(value)? - &b.at_sym(value)?,
            Expr::Mul(a, b) => a.at_sym(value)? * &b.at_sym(value)?,
            Expr::Div(a, b) => a.at_sym(value)?.checked_div(&b.at_sym(value)?)?,
            Expr::Pow(a, k) => {
                let base = a.at_sym(value)?;
                (0..*k).fold(Sym::one(), |acc, _| acc * &base)
            }
        })
    }

    fn collect_variables(&self, out: &mut BTreeSet<String>) {
        match self {
            Expr::Var(name) => {
                out.insert(name.clone());
            }
            Expr::Value(v) => out.extend(v.variables()),
            _ => self
                .children()
                .into_iter()
                .for_each(|c| c.collect_variables(out)),
        }
    }
}

/// The rational test point of [`compare`]: every symbol of the appendices.
/// `π` is given a rational stand-in: it is transcendental, so a rational
/// function over ℚ that is nonzero at some value of the symbol `π` is not
/// the zero function, and neither is its value at `π` itself once the other
/// symbols are generic.
const POINT: [(&str, (i64, i64)); 28] = [
    ("zeta", (2, 1)),
    ("pi", (355, 113)),
    ("q", (3, 1)),
    ("s", (3, 5)),
    ("c", (4, 5)),
    ("w0", (2, 1)),
    ("w1", (3, 1)),
    ("w2", (5, 1)),
    ("w3", (7, 1)),
    ("H0", (11, 1)),
    ("H1", (13, 1)),
    ("H2", (17, 1)),
    ("H3", (19, 1)),
    ("a", (1, 2)),
    ("d", (1, 3)),
    ("b0", (1, 5)),
    ("b1", (2, 7)),
    ("b2", (3, 11)),
    ("b3", (5, 13)),
    ("c0", (7, 17)),
    ("c1", (11, 19)),
    ("c2", (13, 23)),
    ("c3", (17, 29)),
    ("z", (1, 2)),
    ("S0", (23, 1)),
    ("S1", (29, 1)),
    ("S2", (31, 1)),
    ("S3", (37, 1)),
];

fn point_value(name: &str) -> Option<Rational> {
    POINT
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, q)| Rational::from(*q))
}

/// The verdict on a printed value against the computed one: holds (exact
/// identity), or fails with the computed value and, as exact proof, the two
/// values at a rational point. Large residuals are expensive in the ring;
/// the printed formula is evaluated at the point first (from its syntax
/// tree), and built in the ring for the full identity only when it agrees
/// there.
pub fn compare(printed: &Formula, computed: &Sym) -> Verdict {
    if let (Some(p), Ok(c)) = (
        printed.at(&point_value),
        computed.eval_rational(&point_value),
    ) && p != c
    {
        let _ = (p, c);
        let item = Evidence::new(Kind::Comparison, "")
            .with("computed", evidence::Expr::new(computed))
            .witnessed(simple_witness(printed, computed));
        return Verdict::new(Status::Fails, IDENTITY, [item]);
    }
    let residual = printed.to_sym() - computed;
    if residual.is_zero() {
        Verdict::new(
            Status::Holds,
            IDENTITY,
            [Evidence::new(
                Kind::Comparison,
                "printed = computed exactly",
            )],
        )
    } else {
        let item = Evidence::new(Kind::Comparison, "")
            .with("computed", evidence::Expr::new(computed))
            .with("printed − computed", evidence::Expr::new(&residual))
            .witnessed(crate::witness::of_residual(&residual));
        Verdict::new(Status::Fails, IDENTITY, [item])
    }
}

/// The part of a claim that compares the printed `text` (read as
/// `formula`) with `computed`: named `label`, the printed text kept with
/// the evidence.
pub fn printed_part(
    label: String,
    text: &str,
    formula: &Formula,
    computed: &Sym,
) -> (String, Verdict) {
    let mut v = compare(formula, computed);
    for e in v.evidence.iter_mut() {
        e.printed = Some(text.to_string());
    }
    (label, v)
}

/// A small witness of `printed ≠ computed`: the test point of [`POINT`]
/// simplified variable by variable ([`crate::witness::search`], with `π`
/// given its rational stand-in while searching: sides that differ there
/// are different rational functions of `π`, so they differ at `π` too), the
/// two values then shown with `π` as a symbol.
fn simple_witness(printed: &Formula, computed: &Sym) -> Option<crate::Witness> {
    let (pv, cv) = (printed.variables(), computed.variables());
    let names: Vec<String> = POINT
        .iter()
        .filter(|(n, _)| *n != "pi" && (pv.contains(*n) || cv.contains(*n)))
        .map(|(n, _)| n.to_string())
        .collect();
    let pi = point_value("pi")?;
    let differ = |p: &crate::witness::Point| {
        let value = |n: &str| -> Option<Rational> {
            if n == "pi" {
                return Some(pi.clone());
            }
            p.iter().find(|(m, _)| m == n).map(|(_, q)| q.clone())
        };
        matches!(
            (printed.at(&value), computed.eval_rational(&value)),
            (Some(a), Ok(b)) if a != b
        )
    };
    let start: crate::witness::Point = names
        .iter()
        .filter_map(|n| point_value(n).map(|q| (n.clone(), q)))
        .collect();
    let point = if differ(&start) {
        crate::witness::search_from(start, &differ)
    } else {
        crate::witness::search(&names, &differ)?
    };
    let symbolic = |n: &str| -> Option<Sym> {
        if n == "pi" {
            return Some(Sym::pi());
        }
        point
            .iter()
            .find(|(m, _)| m == n)
            .map(|(_, q)| Sym::rational(q.clone()))
    };
    let p = printed.at_sym(&symbolic)?;
    let c = computed.eval(&Sym::one(), &symbolic).ok()?;
    let mut all = names;
    if pv.contains("pi") || cv.contains("pi") {
        all.push("pi".into());
    }
    Some(witness(&point, &all, vec![("printed", p), ("computed", c)]))
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(i64),
    Id(String),
    Op(char),
    Open,
    Close,
}

fn tokenize(text: &str) -> Vec<Tok> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if ch.is_whitespace() {
            i += 1;
        } else if ch.is_ascii_digit() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            out.push(Tok::Num(s.parse().expect("digits")));
        } else if ch.is_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(Tok::Id(chars[start..i].iter().collect()));
        } else {
            out.push(match ch {
                '(' | '[' | '{' => Tok::Open,
                ')' | ']' | '}' => Tok::Close,
                '+' | '-' | '*' | '/' | '^' => Tok::Op(ch),
                '−' => Tok::Op('-'),
                other => panic!("unexpected character {other:?} in {text:?}"),
            });
            i += 1;
        }
    }
    out
}

struct Parser<'a> {
    t: &'a [Tok],
    i: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }

    fn expr(&mut self) -> Expr {
        let mut acc = self.term();
        while let Some(Tok::Op(op @ ('+' | '-'))) = self.peek().cloned() {
            self.i += 1;
            let rhs = Box::new(self.term());
            acc = if op == '+' {
                Expr::Add(Box::new(acc), rhs)
            } else {
                Expr::Sub(Box::new(acc), rhs)
            };
        }
        acc
    }

    fn term(&mut self) -> Expr {
        let mut acc = self.unary();
        loop {
            acc = match self.peek() {
                Some(Tok::Op('*')) => {
                    self.i += 1;
                    Expr::Mul(Box::new(acc), Box::new(self.unary()))
                }
                Some(Tok::Op('/')) => {
                    self.i += 1;
                    Expr::Div(Box::new(acc), Box::new(self.unary()))
                }
                Some(Tok::Num(_) | Tok::Id(_) | Tok::Open) => {
                    Expr::Mul(Box::new(acc), Box::new(self.power()))
                }
                _ => return acc,
            }
        }
    }

    fn unary(&mut self) -> Expr {
        if self.peek() == Some(&Tok::Op('-')) {
            self.i += 1;
            return Expr::Neg(Box::new(self.unary()));
        }
        self.power()
    }

    fn power(&mut self) -> Expr {
        let base = self.primary();
        if self.peek() == Some(&Tok::Op('^')) {
            self.i += 1;
            match self.t.get(self.i) {
                Some(Tok::Num(k)) => {
                    self.i += 1;
                    let k = u32::try_from(*k).expect("a small exponent");
                    Expr::Pow(Box::new(base), k)
                }
                other => panic!("exponent must be an integer, got {other:?}"),
            }
        } else {
            base
        }
    }

    fn primary(&mut self) -> Expr {
        let tok = self.t.get(self.i).cloned();
        self.i += 1;
        match tok {
            Some(Tok::Num(n)) => Expr::Num(n),
            Some(Tok::Id(name)) => Expr::Var(name),
            Some(Tok::Open) => {
                let e = self.expr();
                assert_eq!(self.t.get(self.i), Some(&Tok::Close), "unbalanced brackets");
                self.i += 1;
                e
            }
            other => panic!("unexpected token {other:?}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn printed(text: &str) -> Sym {
        Formula::parse(text).to_sym()
    }

    #[test]
    fn printed_formulas_read_with_juxtaposition_and_brackets() {
        let got = printed("4(S + 1)c1 - [x/2]^2");
        let s = s_xi();
        let want = Sym::int(4) * &(s + &Sym::one()) * &Sym::var("c1")
            - &(Sym::var("x") * &Sym::var("x") / &Sym::int(4));
        assert_eq!(got, want);
        assert_eq!(printed("-2^2"), Sym::int(-4));
        assert_eq!(
            printed("(-pi/2)^3"),
            -(Sym::pi() * &Sym::pi() * &Sym::pi()) / &Sym::int(8)
        );
    }

    #[test]
    fn formulas_take_shorthands_and_evaluate_at_a_point_as_in_the_ring() {
        let f = Formula::parse("(A + S)/(x - 1)").with("A", &Formula::parse("2y"));
        let names: Vec<String> = f.variables().into_iter().collect();
        assert_eq!(names, ["x", "y", "zeta"]);
        let at = |n: &str| match n {
            "x" => Some(Rational::from(3)),
            "y" => Some(Rational::from((1, 2))),
            "zeta" => Some(Rational::from(2)),
            _ => None,
        };
        // (2·(1/2) + s(2)) / (3 − 1) = (1 + 3)/2
        assert_eq!(f.at(&at), Some(Rational::from(2)));
        assert_eq!(f.to_sym().eval_rational(&at), Ok(Rational::from(2)));
        assert_eq!(Formula::parse("1/(x - 3)").at(&at), None);
        assert_eq!(Formula::parse("z").at(&at), None);
    }

    #[test]
    fn compare_shows_computed_value_on_failure() {
        assert_eq!(
            compare(&Formula::parse("1"), &Sym::one()).status,
            Status::Holds
        );
        let v = compare(&Formula::parse("2"), &Sym::one());
        assert_eq!(v.status, Status::Fails);
        assert!(v.evidence[0].contains("computed = 1"), "{:?}", v.evidence);
    }
}
