//! A formula over named symbols, without a spec file: read by the one
//! formula parser ([`crate::ast`]) in either [`Grammar`], every name checked
//! against the symbols the caller declares, shorthands substituted as
//! formulas, and evaluated exactly — at rational values of the symbols
//! (cheap, whatever the formula's size) or in the exact ring [`Sym`] (its
//! cost bounded as for spec files, [`crate::formula::MAX_WORK`]).
//!
//! This is how the printed formulas of a paper are read:
//!
//! ```
//! use rug::Rational;
//! use trig_specfile::{Expression, Grammar};
//! let y = Expression::parse("4(S + 1)b1", Grammar::Printed, &["S", "b1"]).unwrap();
//! let at = |name: &str| Some(Rational::from(if name == "S" { 3 } else { 2 }));
//! assert_eq!(y.at(&at).unwrap(), 32);
//! // a shorthand of the print, replaced by its definition
//! let s = Expression::parse("zeta^2 - zeta + 1", Grammar::Printed, &["zeta"]).unwrap();
//! assert_eq!(y.substitute("S", &s).variables().len(), 2);
//! ```
//!
//! Names are symbols and `pi` (or `π`, read as `pi`); functions (`sin`, …)
//! need a spec file's variable and are refused here. In the ring, `pi` is
//! [`Sym::pi`] and every other symbol [`Sym::var`] of its name. The ring
//! value is formed operation by operation as written (`a / b²` divides by
//! `b·b`), so equal texts give identical values.

use std::collections::BTreeSet;

use rug::Rational;
use rug::ops::Pow;
use trig_symbolic::{Residue, Sym};

use crate::ast::{self, Expr, Func, Grammar, Node};
use crate::budget::{Budget, MAX_BITS, bits, too_large};
use crate::error::FormulaError;

/// A formula read over declared symbols: its syntax tree, positions kept.
#[derive(Debug, Clone, PartialEq)]
pub struct Expression {
    tree: Expr,
}

impl Expression {
    /// Reads `text` in `grammar`; every name must be one of `symbols` or
    /// `pi`/`π`.
    pub fn parse(text: &str, grammar: Grammar, symbols: &[&str]) -> Result<Self, FormulaError> {
        let mut tree = ast::parse_in(text, grammar)?;
        declared(&mut tree, symbols)?;
        Ok(Expression { tree })
    }

    /// The formula with every occurrence of the symbol `name` replaced by
    /// `by` (a shorthand of a print and its definition). Positions inside
    /// `by` keep referring to `by`'s text.
    pub fn substitute(self, name: &str, by: &Expression) -> Expression {
        Expression {
            tree: replace(self.tree, name, &by.tree),
        }
    }

    /// The names of the symbols that occur (`pi` included).
    pub fn variables(&self) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        self.tree.walk(&mut |e| {
            if let Node::Name(n) = &e.node {
                out.insert(n.clone());
            }
        });
        out
    }

    /// The exact value at rational values of the symbols (`pi` among them:
    /// it is asked for like any symbol). Errors name the position of a
    /// symbol without value, of a division by zero, or of a value too large
    /// to form.
    pub fn at(&self, value: &dyn Fn(&str) -> Option<Rational>) -> Result<Rational, FormulaError> {
        evaluate(&self.tree, &Rationals, &|name, pos| {
            value(name).ok_or_else(|| unbound(name, pos))
        })
    }

    /// The image modulo a prime ([`Residue`]) of the value at rational values
    /// of the symbols (as [`Expression::at`]); `None` for a symbol without
    /// value or where the image is undefined (a denominator divisible by
    /// the prime). Images that differ prove values that differ.
    pub fn at_mod(&self, value: &dyn Fn(&str) -> Option<Rational>) -> Option<Residue> {
        evaluate(&self.tree, &Residues, &|name, pos| {
            value(name)
                .map(|q| Residue::of(&q))
                .ok_or_else(|| unbound(name, pos))
        })
        .ok()
        .flatten()
    }

    /// The value in the exact ring at values of the symbols given as ring
    /// elements (`π` may stay a symbol: give [`Sym::pi`] for `pi`).
    pub fn at_sym(&self, value: &dyn Fn(&str) -> Option<Sym>) -> Result<Sym, FormulaError> {
        evaluate(&self.tree, &Ring::default(), &|name, pos| {
            value(name).ok_or_else(|| unbound(name, pos))
        })
    }

    /// The value in the exact ring, every symbol as itself.
    pub fn to_sym(&self) -> Result<Sym, FormulaError> {
        evaluate(&self.tree, &Ring::default(), &|name, _| {
            Ok(if name == "pi" {
                Sym::pi()
            } else {
                Sym::var(name)
            })
        })
    }
}

fn unbound(name: &str, pos: usize) -> FormulaError {
    FormulaError::new(pos, format!("`{name}` has no value here"))
}

fn no_function(f: Func, pos: usize) -> FormulaError {
    FormulaError::new(
        pos,
        format!(
            "`{}(…)` needs a spec file's variable: a formula over symbols has numbers, symbols, pi and + - * / ^ only",
            f.name()
        ),
    )
}

/// Checks every name against `symbols` (`π` becomes `pi`) and refuses
/// calls.
fn declared(e: &mut Expr, symbols: &[&str]) -> Result<(), FormulaError> {
    match &mut e.node {
        Node::Number(_) => Ok(()),
        Node::Name(n) if n == "pi" || n == "π" => {
            *n = "pi".into();
            Ok(())
        }
        Node::Name(n) if symbols.contains(&n.as_str()) => Ok(()),
        Node::Name(n) => {
            let mut expected = symbols.to_vec();
            expected.push("pi");
            Err(FormulaError::new(
                e.pos,
                format!("unknown symbol `{n}` (expected {})", expected.join(", ")),
            ))
        }
        Node::Call(f, _) => Err(no_function(*f, e.pos)),
        Node::Neg(a) | Node::Pow(a, _) => declared(a, symbols),
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            declared(a, symbols)?;
            declared(b, symbols)
        }
    }
}

fn replace(e: Expr, name: &str, by: &Expr) -> Expr {
    let r = |x: Box<Expr>| Box::new(replace(*x, name, by));
    let node = match e.node {
        Node::Name(n) if n == name => return by.clone(),
        Node::Neg(a) => Node::Neg(r(a)),
        Node::Pow(a, n) => Node::Pow(r(a), n),
        Node::Call(f, a) => Node::Call(f, r(a)),
        Node::Add(a, b) => Node::Add(r(a), r(b)),
        Node::Sub(a, b) => Node::Sub(r(a), r(b)),
        Node::Mul(a, b) => Node::Mul(r(a), r(b)),
        Node::Div(a, b) => Node::Div(r(a), r(b)),
        leaf @ (Node::Number(_) | Node::Name(_)) => leaf,
    };
    Expr { node, pos: e.pos }
}

/// The exact operations of one evaluation, each with the position of its
/// operator for errors.
trait Arithmetic {
    type Value;
    fn number(&self, q: &Rational) -> Self::Value;
    fn neg(&self, a: Self::Value) -> Self::Value;
    fn add(&self, a: Self::Value, b: &Self::Value, pos: usize)
    -> Result<Self::Value, FormulaError>;
    fn sub(&self, a: Self::Value, b: &Self::Value, pos: usize)
    -> Result<Self::Value, FormulaError>;
    fn mul(
        &self,
        a: &Self::Value,
        b: &Self::Value,
        pos: usize,
    ) -> Result<Self::Value, FormulaError>;
    fn div(
        &self,
        a: &Self::Value,
        b: &Self::Value,
        pos: usize,
    ) -> Result<Self::Value, FormulaError>;
    fn pow(&self, a: &Self::Value, n: u32, pos: usize) -> Result<Self::Value, FormulaError>;
}

type Leaf<'l, V> = dyn Fn(&str, usize) -> Result<V, FormulaError> + 'l;

fn evaluate<A: Arithmetic>(
    e: &Expr,
    a: &A,
    leaf: &Leaf<'_, A::Value>,
) -> Result<A::Value, FormulaError> {
    let pos = e.pos;
    let rec = |x: &Expr| evaluate(x, a, leaf);
    match &e.node {
        Node::Number(q) => Ok(a.number(q)),
        Node::Name(n) => leaf(n, pos),
        Node::Neg(x) => Ok(a.neg(rec(x)?)),
        Node::Add(x, y) => a.add(rec(x)?, &rec(y)?, pos),
        Node::Sub(x, y) => a.sub(rec(x)?, &rec(y)?, pos),
        Node::Mul(x, y) => a.mul(&rec(x)?, &rec(y)?, pos),
        Node::Div(x, y) => a.div(&rec(x)?, &rec(y)?, pos),
        Node::Pow(x, n) => {
            let raised = a.pow(&rec(x)?, n.unsigned_abs() as u32, pos)?;
            if *n < 0 {
                a.div(&a.number(&Rational::from(1)), &raised, pos)
            } else {
                Ok(raised)
            }
        }
        Node::Call(f, _) => Err(no_function(*f, pos)),
    }
}

/// Exact rationals, each numerator and denominator of at most
/// [`MAX_BITS`] bits (a tower of powers is refused, not computed).
struct Rationals;

impl Rationals {
    fn bounded(&self, q: Rational, pos: usize) -> Result<Rational, FormulaError> {
        if bits(&q) > MAX_BITS {
            return Err(too_large(pos));
        }
        Ok(q)
    }
}

impl Arithmetic for Rationals {
    type Value = Rational;

    fn number(&self, q: &Rational) -> Rational {
        q.clone()
    }

    fn neg(&self, a: Rational) -> Rational {
        -a
    }

    fn add(&self, a: Rational, b: &Rational, pos: usize) -> Result<Rational, FormulaError> {
        self.bounded(a + b, pos)
    }

    fn sub(&self, a: Rational, b: &Rational, pos: usize) -> Result<Rational, FormulaError> {
        self.bounded(a - b, pos)
    }

    fn mul(&self, a: &Rational, b: &Rational, pos: usize) -> Result<Rational, FormulaError> {
        self.bounded(Rational::from(a * b), pos)
    }

    fn div(&self, a: &Rational, b: &Rational, pos: usize) -> Result<Rational, FormulaError> {
        if *b == 0 {
            return Err(FormulaError::new(pos, "division by zero"));
        }
        self.bounded(Rational::from(a / b), pos)
    }

    fn pow(&self, a: &Rational, n: u32, pos: usize) -> Result<Rational, FormulaError> {
        if u64::from(bits(a)) * u64::from(n) > u64::from(MAX_BITS) {
            return Err(too_large(pos));
        }
        Ok(a.clone().pow(n))
    }
}

/// Residues modulo a prime ([`Residue`]); `None` where undefined (a
/// denominator divisible by the prime), and undefined stays undefined.
struct Residues;

impl Arithmetic for Residues {
    type Value = Option<Residue>;

    fn number(&self, q: &Rational) -> Option<Residue> {
        Residue::of(q)
    }

    fn neg(&self, a: Option<Residue>) -> Option<Residue> {
        a.map(|a| -a)
    }

    fn add(&self, a: Self::Value, b: &Self::Value, _: usize) -> Result<Self::Value, FormulaError> {
        Ok(a.zip(*b).map(|(a, b)| a + b))
    }

    fn sub(&self, a: Self::Value, b: &Self::Value, _: usize) -> Result<Self::Value, FormulaError> {
        Ok(a.zip(*b).map(|(a, b)| a - b))
    }

    fn mul(&self, a: &Self::Value, b: &Self::Value, _: usize) -> Result<Self::Value, FormulaError> {
        Ok(a.zip(*b).map(|(a, b)| a * b))
    }

    fn div(&self, a: &Self::Value, b: &Self::Value, _: usize) -> Result<Self::Value, FormulaError> {
        Ok(a.zip(*b).and_then(|(a, b)| a.checked_div(b)))
    }

    fn pow(&self, a: &Self::Value, n: u32, _: usize) -> Result<Self::Value, FormulaError> {
        Ok(a.map(|a| a.pow(n)))
    }
}

/// The exact ring, every product charged to one [`Budget`].
#[derive(Default)]
struct Ring {
    budget: Budget,
}

impl Arithmetic for Ring {
    type Value = Sym;

    fn number(&self, q: &Rational) -> Sym {
        Sym::rational(q.clone())
    }

    fn neg(&self, a: Sym) -> Sym {
        -a
    }

    fn add(&self, a: Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        self.budget.bounded(a + b, pos)
    }

    fn sub(&self, a: Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        self.budget.bounded(a - b, pos)
    }

    fn mul(&self, a: &Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        self.budget.product(a, b, pos)
    }

    fn div(&self, a: &Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        let q = a
            .checked_div(b)
            .ok_or_else(|| FormulaError::new(pos, "division by zero"))?;
        self.budget.bounded(q, pos)
    }

    /// `aⁿ` as `n` products from 1, as written (`a·a·…·a`).
    fn pow(&self, a: &Sym, n: u32, pos: usize) -> Result<Sym, FormulaError> {
        (0..n).try_fold(Sym::one(), |acc, _| self.budget.product(&acc, a, pos))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn printed(text: &str, symbols: &[&str]) -> Expression {
        Expression::parse(text, Grammar::Printed, symbols).unwrap()
    }

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn printed_formulas_lower_into_the_ring() {
        let got = printed("4(S + 1)c1 - [x/2]^2", &["S", "c1", "x"])
            .to_sym()
            .unwrap();
        let want = Sym::int(4) * &(Sym::var("S") + &Sym::one()) * &Sym::var("c1")
            - &(Sym::var("x") * &Sym::var("x") / &Sym::int(4));
        assert_eq!(got, want);
        assert_eq!(printed("-2^2", &[]).to_sym(), Ok(Sym::int(-4)));
        assert_eq!(
            printed("(-π/2)^3", &[]).to_sym(),
            Ok(-(Sym::pi() * &Sym::pi() * &Sym::pi()) / &Sym::int(8))
        );
        assert_eq!(printed("x^-2", &["x"]).at(&|_| Some(q(1, 3))), Ok(q(9, 1)));
    }

    #[test]
    fn shorthands_substitute_and_a_point_agrees_with_the_ring() {
        let f = printed("(A + S)/(x - 1)", &["A", "S", "x"])
            .substitute("A", &printed("2y", &["y"]))
            .substitute("S", &printed("zeta^2 - zeta + 1", &["zeta"]));
        let names: Vec<String> = f.variables().into_iter().collect();
        assert_eq!(names, ["x", "y", "zeta"]);
        let at = |n: &str| match n {
            "x" => Some(Rational::from(3)),
            "y" => Some(q(1, 2)),
            "zeta" => Some(Rational::from(2)),
            _ => None,
        };
        // (2·(1/2) + s(2)) / (3 − 1) = (1 + 3)/2
        assert_eq!(f.at(&at), Ok(Rational::from(2)));
        assert_eq!(
            f.to_sym().unwrap().eval_rational(&at),
            Ok(Rational::from(2))
        );
        let sym_at = |n: &str| at(n).map(Sym::rational);
        assert_eq!(f.at_sym(&sym_at), Ok(Sym::int(2)));
        assert_eq!(f.at_mod(&at), Residue::of(&Rational::from(2)));
        // x = 1: a division by zero has no image; an unbound symbol neither
        let pole = |n: &str| {
            if n == "x" {
                Some(Rational::from(1))
            } else {
                at(n)
            }
        };
        assert_eq!(f.at_mod(&pole), None);
        assert_eq!(f.at_mod(&|_| None), None);
    }

    #[test]
    fn errors_are_typed_and_placed() {
        let parse = |text: &str| Expression::parse(text, Grammar::Printed, &["x"]);
        let e = parse("2x + y").unwrap_err();
        assert_eq!(e.position, 5);
        assert!(
            e.message.contains("unknown symbol `y` (expected x, pi)"),
            "{e}"
        );
        let e = parse("x sin(x)").unwrap_err();
        assert_eq!(e.position, 2);
        assert!(
            e.message.contains("`sin(…)` needs a spec file's variable"),
            "{e}"
        );
        // the spec grammar still wants its `*`
        let e = Expression::parse("2 x", Grammar::Spec, &["x"]).unwrap_err();
        assert!(e.message.starts_with("expected `*`"), "{e}");
        let f = parse("1/(x - 3)").unwrap();
        let three = |_: &str| Some(Rational::from(3));
        assert_eq!(f.at(&three).unwrap_err().position, 1);
        assert_eq!(
            f.at_sym(&|_| Some(Sym::int(3))).unwrap_err().message,
            "division by zero"
        );
        assert_eq!(
            parse("x + 1").unwrap().at(&|_| None).unwrap_err().position,
            0
        );
        assert!(parse("1/(x - x)").unwrap().to_sym().is_err());
        // towers are refused, not formed
        let tower = parse("((((x^64)^64)^64)^64)^64").unwrap();
        assert!(tower.at(&three).unwrap_err().message.contains("bits"));
        assert!(tower.to_sym().unwrap_err().message.contains("degree"));
        let tower = parse("((((3^64)^64)^64)^64)^64").unwrap();
        assert!(tower.to_sym().unwrap_err().message.contains("bits"));
        let wide = parse("(1 + x + x^2 + x^3)^40 (2 + x)^64").unwrap();
        assert!(wide.to_sym().is_err());
    }

    #[test]
    fn the_deepest_formula_read_evaluates_on_a_test_thread() {
        // a product chain of ast::MAX_HEIGHT operations, the deepest accepted
        let f = printed(&"x ".repeat(ast::MAX_HEIGHT + 1), &["x"]);
        assert_eq!(f.at(&|_| Some(Rational::from(1))), Ok(Rational::from(1)));
        assert!(f.to_sym().unwrap_err().message.contains("degree"));
        let f = printed(&format!("{}x", "x - ".repeat(ast::MAX_HEIGHT)), &["x"]);
        assert_eq!(
            f.to_sym(),
            Ok(Sym::int(1 - ast::MAX_HEIGHT as i64) * &Sym::var("x"))
        );
    }

    proptest::proptest! {
        /// Arbitrary text in either grammar: read or refused, and whatever
        /// is read evaluates or is refused, never a panic.
        #[test]
        fn no_input_panics(text in "[-+*/^()\\[\\]{} 0-9.xyπ]{0,60}", printed_grammar: bool) {
            let grammar = if printed_grammar { Grammar::Printed } else { Grammar::Spec };
            if let Ok(f) = Expression::parse(&text, grammar, &["x", "y"]) {
                let _ = f.at(&|_| Some(q(2, 3)));
                let _ = f.to_sym();
            }
        }
    }
}
