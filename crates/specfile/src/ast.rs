//! The formula language of spec files, read into a syntax tree with the
//! position of every node (so later errors point at the exact place).
//!
//! Grammar (usual precedence, left-associative, `^` binds tightest):
//!
//! ```text
//! expr   := term (('+' | '-') term)*
//! term   := unary (('*' | '/') unary)*
//! unary  := ('-' | '+') unary | power
//! power  := atom ('^' ['-'] integer)?
//! atom   := number | name | name '(' expr ')' | '(' expr ')'
//! ```
//!
//! Numbers are decimals read exactly (`0.6` = 3/5); `−`, `·`, `×` are
//! accepted for `-`, `*`. Two operands side by side (`2 s`, `2(1 − t)`,
//! `(1 − t)(1 + t)`) are refused with "expected `*`": a missing sign is
//! never guessed.
//!
//! Printed formulas ([`Grammar::Printed`], transcribed from a paper) are
//! read by the same parser with two additions: juxtaposition multiplies,
//! binding as `*` does (`term := unary (('*' | '/') unary | power)*`, so
//! `4(S + 1)b1` is `4·(S + 1)·b1` and `a/2 b` is `(a/2)·b`), and `[ ]`,
//! `{ }` group as `( )` does (each closed by its own kind).

use rug::Rational;
use trig_core::parse_exact;

use crate::error::FormulaError;

/// Longest formula accepted (characters).
pub const MAX_LEN: usize = 10_000;
/// Deepest nesting of parentheses, calls and unary signs.
pub const MAX_DEPTH: usize = 64;
/// Most operations on any path of the syntax tree (`a - b - c` is two
/// deep), so that every walk of the tree stays well inside a thread's
/// stack; real formulas are far below it.
pub const MAX_HEIGHT: usize = 512;
/// Largest exponent magnitude in `x^n` (the formula's total cost is bounded
/// separately, see [`crate::lower`]).
pub const MAX_EXPONENT: i64 = 64;

/// The functions a formula may call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    Sin,
    Cos,
    Sinh,
    Cosh,
    Exp,
    Sqrt,
}

impl Func {
    fn from_name(name: &str) -> Option<Func> {
        Some(match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "sinh" => Func::Sinh,
            "cosh" => Func::Cosh,
            "exp" => Func::Exp,
            "sqrt" => Func::Sqrt,
            _ => return None,
        })
    }

    /// The name as written.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Exp => "exp",
            Func::Sqrt => "sqrt",
        }
    }

    /// True for `sin`, `cos` (an angle argument).
    pub fn is_trigonometric(self) -> bool {
        matches!(self, Func::Sin | Func::Cos)
    }

    /// True for `sinh`, `cosh`, `exp` (an exponential argument).
    pub fn is_exponential(self) -> bool {
        matches!(self, Func::Sinh | Func::Cosh | Func::Exp)
    }
}

/// How formula text is read: the two grammars share everything but
/// juxtaposition and brackets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Grammar {
    /// Spec files: every product has its sign (`2*s`; `2 s` is refused
    /// with "expected `*`"), and only `( )` group.
    #[default]
    Spec,
    /// Printed formulas as transcribed from a paper: juxtaposition
    /// multiplies (`2S`, `4(S + 1)b1`, `(1 + t)(1 - t)`), and `[ ]`, `{ }`
    /// group as `( )` does. A function name followed by `(` is still a call.
    Printed,
}

/// The names of the functions, for messages.
pub const FUNCTIONS: &str = "sin, cos, sinh, cosh, exp, sqrt";

/// A node of the syntax tree.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    Number(Rational),
    Name(String),
    Neg(Box<Expr>),
    Add(Box<Expr>, Box<Expr>),
    Sub(Box<Expr>, Box<Expr>),
    Mul(Box<Expr>, Box<Expr>),
    Div(Box<Expr>, Box<Expr>),
    Pow(Box<Expr>, i64),
    Call(Func, Box<Expr>),
}

/// A node with the 0-based character position of its operator or first
/// character.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    pub node: Node,
    pub pos: usize,
}

impl Expr {
    /// Every node, depth first (the node itself first).
    pub fn walk<'e>(&'e self, visit: &mut dyn FnMut(&'e Expr)) {
        visit(self);
        match &self.node {
            Node::Number(_) | Node::Name(_) => {}
            Node::Neg(a) | Node::Pow(a, _) | Node::Call(_, a) => a.walk(visit),
            Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
                a.walk(visit);
                b.walk(visit);
            }
        }
    }
}

/// Reads `text` of a spec file into a syntax tree ([`Grammar::Spec`]).
pub fn parse(text: &str) -> Result<Expr, FormulaError> {
    parse_in(text, Grammar::Spec)
}

/// Reads `text` into a syntax tree in `grammar`.
pub fn parse_in(text: &str, grammar: Grammar) -> Result<Expr, FormulaError> {
    let chars: Vec<char> = text.chars().collect();
    if chars.len() > MAX_LEN {
        return Err(FormulaError::new(
            MAX_LEN,
            format!("formula longer than {MAX_LEN} characters"),
        ));
    }
    let tokens = lex(&chars, grammar)?;
    let mut p = Parser {
        tokens,
        at: 0,
        depth: 0,
        end: chars.len(),
        grammar,
    };
    let value = p.expr()?;
    match p.peek() {
        None => match deeper_than(&value, MAX_HEIGHT) {
            None => Ok(value),
            Some(pos) => Err(FormulaError::new(
                pos,
                format!("more than {MAX_HEIGHT} operations deep (split the formula)"),
            )),
        },
        Some(t) if starts_operand(&t.kind) => Err(FormulaError::new(
            t.pos,
            format!(
                "expected `*` before {} (a product needs its sign)",
                t.kind.describe()
            ),
        )),
        Some(t) => Err(FormulaError::new(
            t.pos,
            format!(
                "expected an operator (+ - * / ^) or the end, found {}",
                t.kind.describe()
            ),
        )),
    }
}

/// The position of an operation with `max` operations above it in `e`, if
/// any (the walk stops there, so it stays shallow itself).
fn deeper_than(e: &Expr, max: usize) -> Option<usize> {
    match &e.node {
        Node::Number(_) | Node::Name(_) => None,
        _ if max == 0 => Some(e.pos),
        Node::Neg(a) | Node::Pow(a, _) | Node::Call(_, a) => deeper_than(a, max - 1),
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            deeper_than(a, max - 1).or_else(|| deeper_than(b, max - 1))
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Number(String),
    Name(String),
    Op(char),
    /// `(`, or in printed formulas `[`, `{`.
    Open(char),
    /// The closing bracket of its kind.
    Close(char),
}

impl Kind {
    fn describe(&self) -> String {
        match self {
            Kind::Number(n) => format!("the number `{n}`"),
            Kind::Name(n) => format!("`{n}`"),
            Kind::Op(c) | Kind::Open(c) | Kind::Close(c) => format!("`{c}`"),
        }
    }
}

fn starts_operand(k: &Kind) -> bool {
    matches!(k, Kind::Number(_) | Kind::Name(_) | Kind::Open(_))
}

/// The bracket closing `open`.
fn closing(open: char) -> char {
    match open {
        '[' => ']',
        '{' => '}',
        _ => ')',
    }
}

#[derive(Debug, Clone)]
struct Token {
    kind: Kind,
    pos: usize,
}

fn lex(chars: &[char], grammar: Grammar) -> Result<Vec<Token>, FormulaError> {
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
            '(' => Kind::Open('('),
            ')' => Kind::Close(')'),
            '[' | '{' if grammar == Grammar::Printed => Kind::Open(ch),
            ']' | '}' if grammar == Grammar::Printed => Kind::Close(ch),
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

struct Parser {
    tokens: Vec<Token>,
    at: usize,
    depth: usize,
    end: usize,
    grammar: Grammar,
}

fn boxed(node: Node, pos: usize) -> Expr {
    Expr { node, pos }
}

impl Parser {
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

    fn expr(&mut self) -> Result<Expr, FormulaError> {
        self.enter()?;
        let mut acc = self.term()?;
        while let Some((op, pos)) = self.eat_op(&['+', '-']) {
            let rhs = self.term()?;
            let (a, b) = (Box::new(acc), Box::new(rhs));
            acc = boxed(
                if op == '+' {
                    Node::Add(a, b)
                } else {
                    Node::Sub(a, b)
                },
                pos,
            );
        }
        self.depth -= 1;
        Ok(acc)
    }

    fn term(&mut self) -> Result<Expr, FormulaError> {
        let mut acc = self.unary()?;
        loop {
            if let Some(t) = self.peek().filter(|t| starts_operand(&t.kind)) {
                if self.grammar == Grammar::Printed {
                    let pos = t.pos;
                    let rhs = self.power()?;
                    acc = boxed(Node::Mul(Box::new(acc), Box::new(rhs)), pos);
                    continue;
                }
                return Err(FormulaError::new(
                    t.pos,
                    format!(
                        "expected `*` before {} (a product needs its sign)",
                        t.kind.describe()
                    ),
                ));
            }
            let Some((op, pos)) = self.eat_op(&['*', '/']) else {
                return Ok(acc);
            };
            let rhs = self.unary()?;
            let (a, b) = (Box::new(acc), Box::new(rhs));
            acc = boxed(
                if op == '*' {
                    Node::Mul(a, b)
                } else {
                    Node::Div(a, b)
                },
                pos,
            );
        }
    }

    fn unary(&mut self) -> Result<Expr, FormulaError> {
        if let Some((op, pos)) = self.eat_op(&['-', '+']) {
            self.enter()?;
            let x = self.unary()?;
            self.depth -= 1;
            return Ok(if op == '-' {
                boxed(Node::Neg(Box::new(x)), pos)
            } else {
                x
            });
        }
        self.power()
    }

    fn power(&mut self) -> Result<Expr, FormulaError> {
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
        Ok(boxed(
            Node::Pow(Box::new(base), if negative { -n } else { n }),
            pos,
        ))
    }

    fn atom(&mut self) -> Result<Expr, FormulaError> {
        let Some(token) = self.peek().cloned() else {
            return Err(FormulaError::new(
                self.end,
                "unexpected end of formula (expected a number, a name or `(`)",
            ));
        };
        self.at += 1;
        match token.kind {
            Kind::Number(text) => {
                let q = parse_exact(&text).map_err(|_| {
                    FormulaError::new(
                        token.pos,
                        format!("`{text}` is not a number (expected e.g. 3, 0.6)"),
                    )
                })?;
                Ok(boxed(Node::Number(q), token.pos))
            }
            Kind::Open(open) => self.parenthesised(token.pos, open),
            Kind::Name(name) => {
                let called = matches!(
                    self.peek(),
                    Some(Token {
                        kind: Kind::Open('('),
                        ..
                    })
                );
                match (Func::from_name(&name), called) {
                    (Some(f), true) => {
                        self.at += 1;
                        self.enter()?;
                        let arg = self.parenthesised(token.pos + name.chars().count(), '(')?;
                        self.depth -= 1;
                        Ok(boxed(Node::Call(f, Box::new(arg)), token.pos))
                    }
                    (Some(_), false) => Err(FormulaError::new(
                        token.pos,
                        format!("expected `(` after `{name}`"),
                    )),
                    (None, true) if self.grammar == Grammar::Spec => Err(FormulaError::new(
                        token.pos,
                        format!(
                            "unknown function `{name}` (expected {FUNCTIONS}), or `*` after `{name}`"
                        ),
                    )),
                    (None, _) => Ok(boxed(Node::Name(name), token.pos)),
                }
            }
            other => Err(FormulaError::new(
                token.pos,
                format!(
                    "expected a number, a name or `(`, found {}",
                    other.describe()
                ),
            )),
        }
    }

    /// The inside of `( … )` (or `[ … ]`, `{ … }`) whose opening bracket
    /// `open` is at `at` (already consumed).
    fn parenthesised(&mut self, at: usize, open: char) -> Result<Expr, FormulaError> {
        let x = self.expr()?;
        let close = closing(open);
        match self.peek() {
            Some(Token {
                kind: Kind::Close(c),
                ..
            }) if *c == close => {
                self.at += 1;
                Ok(x)
            }
            _ => Err(FormulaError::new(
                self.pos(),
                format!("expected `{close}` to close the `{open}` at position {at}"),
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> FormulaError {
        parse(text).unwrap_err()
    }

    #[test]
    fn precedence_and_positions() {
        let e = parse("1 - 2*t^2").unwrap();
        let Node::Sub(a, b) = &e.node else {
            panic!("{e:?}")
        };
        assert_eq!(
            (e.pos, a.node.clone()),
            (2, Node::Number(Rational::from(1)))
        );
        let Node::Mul(_, p) = &b.node else {
            panic!("{b:?}")
        };
        assert!(matches!(p.node, Node::Pow(_, 2)));
        assert!(matches!(
            parse("sin(t/2)").unwrap().node,
            Node::Call(Func::Sin, _)
        ));
        assert!(matches!(parse("x^-1").unwrap().node, Node::Pow(_, -1)));
    }

    #[test]
    fn a_missing_multiplication_sign_is_named() {
        for (text, at) in [
            ("2 s", 2),
            ("2(1 - t)", 1),
            ("(1 - t)(1 + t)", 7),
            ("t sin(t)", 2),
        ] {
            let e = err(text);
            assert!(e.message.starts_with("expected `*`"), "{text}: {e:?}");
            assert_eq!(e.position, at, "{text}");
        }
        assert!(err("tan(u)").message.contains("unknown function `tan`"));
        assert!(err("sin t").message.contains("expected `(` after `sin`"));
        assert_eq!(err("(1 + s").position, 6);
        assert!(err("1 # 2").message.contains("unexpected character"));
        assert!(err("").message.contains("unexpected end"));
        assert!(err(&"(".repeat(100)).message.contains("nested"));
        assert!(parse(&format!("{}s", "s - ".repeat(MAX_HEIGHT))).is_ok());
        let e = err(&format!("{}s", "s - ".repeat(MAX_HEIGHT + 1)));
        assert_eq!(e.position, 2);
        assert!(e.message.contains("operations deep"), "{e:?}");
        assert!(err("s^m").message.contains("integer exponent"));
        assert!(err("s^65").message.contains("exponent larger"));
        // brackets other than `( )` belong to printed formulas only
        assert!(err("[1 + s]").message.contains("unexpected character `[`"));
    }

    fn printed(text: &str) -> Result<Expr, FormulaError> {
        parse_in(text, Grammar::Printed)
    }

    /// The tree with every position zeroed, to compare shapes.
    fn shape(text: &str, grammar: Grammar) -> Expr {
        fn unplaced(e: Expr) -> Expr {
            let b = |x: Box<Expr>| Box::new(unplaced(*x));
            let node = match e.node {
                Node::Neg(a) => Node::Neg(b(a)),
                Node::Add(x, y) => Node::Add(b(x), b(y)),
                Node::Sub(x, y) => Node::Sub(b(x), b(y)),
                Node::Mul(x, y) => Node::Mul(b(x), b(y)),
                Node::Div(x, y) => Node::Div(b(x), b(y)),
                Node::Pow(a, n) => Node::Pow(b(a), n),
                Node::Call(f, a) => Node::Call(f, b(a)),
                leaf => leaf,
            };
            Expr { node, pos: 0 }
        }
        unplaced(parse_in(text, grammar).unwrap())
    }

    #[test]
    fn printed_formulas_multiply_by_juxtaposition_and_group_with_brackets() {
        for (print, spec) in [
            ("4(S + 1)b1", "4*(S + 1)*b1"),
            ("2S", "2*S"),
            ("(1 - t)(1 + t)", "(1 - t)*(1 + t)"),
            ("a/2 b", "a/2*b"),
            ("-2^2 x", "-2^2*x"),
            ("x y^2", "x*y^2"),
            ("[x/2]^2", "(x/2)^2"),
            (
                "(pi/2)^3 {(2S - 5)[d S0 + b1]}",
                "(pi/2)^3*((2*S - 5)*(d*S0 + b1))",
            ),
            ("2sin(t)", "2*sin(t)"),
        ] {
            assert_eq!(
                shape(print, Grammar::Printed),
                shape(spec, Grammar::Spec),
                "{print}"
            );
        }
        // a juxtaposed product is placed at its second operand
        let e = printed("2 s").unwrap();
        assert!(matches!(e.node, Node::Mul(..)) && e.pos == 2, "{e:?}");
        // each bracket is closed by its own kind
        let e = printed("[1 + s)").unwrap_err();
        assert_eq!(e.position, 6);
        assert!(
            e.message
                .contains("expected `]` to close the `[` at position 0")
        );
        assert!(printed("{1").unwrap_err().message.contains("expected `}`"));
        assert!(
            printed("sin t")
                .unwrap_err()
                .message
                .contains("after `sin`")
        );
        assert!(
            printed("2 ^ s")
                .unwrap_err()
                .message
                .contains("integer exponent")
        );
        assert!(
            printed("1 + ")
                .unwrap_err()
                .message
                .contains("unexpected end")
        );
        assert!(printed(")").unwrap_err().message.contains("found `)`"));
    }

    proptest::proptest! {
        /// Any text, in either grammar, is read or refused with a position
        /// inside it (or at its end): never a panic.
        #[test]
        fn no_input_panics(text in "\\PC{0,80}", printed_grammar: bool) {
            let grammar = if printed_grammar { Grammar::Printed } else { Grammar::Spec };
            if let Err(e) = parse_in(&text, grammar) {
                proptest::prop_assert!(e.position <= text.chars().count());
            }
        }

        /// Texts made of the grammar's own tokens (the inputs most likely to
        /// reach deep into the parser).
        #[test]
        fn no_token_soup_panics(
            tokens in proptest::collection::vec(
                proptest::sample::select(vec![
                    "1", "2.5", ".", "1.2.3", "99999999999999999999", "x", "S0", "pi", "sin",
                    "sqrt", "+", "-", "−", "*", "·", "/", "^", "^-", "(", ")", "[", "]", "{",
                    "}", " ", "64", "65",
                ]),
                0..40,
            ),
            printed_grammar: bool,
        ) {
            let text = tokens.concat();
            let grammar = if printed_grammar { Grammar::Printed } else { Grammar::Spec };
            if let Err(e) = parse_in(&text, grammar) {
                proptest::prop_assert!(e.position <= text.chars().count());
            }
        }
    }
}
