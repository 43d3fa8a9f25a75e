//! Evidence as data: what a verdict rests on, in a form the report renders
//! to Markdown, LaTeX and JSON from one source (`trig-report`).
//!
//! An [`Evidence`] item says one thing: a prose note, an exact identity with
//! its residual, a printed value against the computed one, a certificate, …
//! ([`Kind`]). Exact expressions are kept in every form a reader or a
//! program needs ([`Expr`]: Unicode, LaTeX, SymPy syntax, plain ASCII, a
//! factored form, and their size, so that long ones can be summarised where
//! people read and given whole where programs read). A failing check carries
//! a [`Witness`]: a rational point and the exact values that differ there,
//! which a reader can re-check by hand.
//!
//! Items belong to the parts of a claim ([`Part`]: nested names with their
//! own statuses, outermost first), so a check that holds inside a part that
//! fails is shown under that part, with its own status.

use std::fmt;
use std::ops::Deref;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use trig_symbolic::{Style, Sym, combine, sympy_symbols};

use crate::status::Status;

/// An exact expression in every form.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Expr {
    /// Unicode (Greek letters, `·`, superscripts); `s = sin θ`, `c = cos θ`.
    pub unicode: String,
    /// LaTeX math (without `$`).
    pub latex: String,
    /// SymPy syntax: `**`, `sin(theta)`, `cos(theta)`, one symbol per
    /// variable (`lamda` for `λ`; a Python keyword, a SymPy one-letter name
    /// or a name the forms write, `lamda…` and a name ending in `_` get a
    /// trailing `_`: `in_`, `None_`, `lamda_`; `E_` is the atom `exp(κx)`);
    /// an enclosure is `Interval(Rational('lo'), Rational('hi'))`; parse with
    /// `sympy.parse_expr(sympy, local_dict={n: Symbol(n) for n in symbols})`.
    pub sympy: String,
    /// The SymPy symbols `sympy` uses (`pi` is SymPy's own constant), one
    /// per variable: a name is undone by stripping one trailing `_`, and
    /// `lamda…` without one is `lambda…`.
    pub symbols: Vec<String>,
    /// Plain ASCII (`*`, `^`).
    pub plain: String,
    /// Terms of the expanded numerator.
    pub terms: usize,
    /// Total degree of the numerator (every variable, `π` included).
    pub degree: u64,
    /// A factored form, when it shows more than the expanded one.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub factored: Option<Forms>,
}

/// One expression in the four text forms.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Forms {
    pub unicode: String,
    pub latex: String,
    pub sympy: String,
    pub plain: String,
}

impl Expr {
    /// The forms of `x`, factored where that shows more.
    pub fn new(x: &Sym) -> Expr {
        let f = x.factored();
        Expr {
            unicode: x.to_unicode(),
            latex: x.to_latex(),
            sympy: x.to_sympy(),
            symbols: symbols_of(x),
            plain: x.to_string(),
            terms: x.numerator().len(),
            degree: x.numerator().total_degree(),
            factored: (!f.trivial).then(|| Forms {
                unicode: f.to_unicode(),
                latex: f.to_latex(),
                sympy: f.to_sympy(),
                plain: f.to_plain(),
            }),
        }
    }

    /// `x` as a combination `Σ cᵢ·vᵢ` of the named variables (control
    /// points) when it is one, each coefficient factored; else [`Expr::new`].
    pub fn combination(x: &Sym, vars: &[String]) -> Expr {
        let Some(terms) = x.linear_in(vars) else {
            return Expr::new(x);
        };
        let factored: Vec<_> = terms.iter().map(|(_, c)| c.factored()).collect();
        let any_factored = factored.iter().any(|f| !f.trivial);
        let form = |style: Style, use_factored: bool| {
            let parts: Vec<(String, String)> = terms
                .iter()
                .zip(&factored)
                .map(|((v, c), f)| {
                    let coefficient = if use_factored && !f.trivial {
                        style.factored(f)
                    } else {
                        style.sym(c)
                    };
                    (coefficient, style.sym(&Sym::var(v)))
                })
                .collect();
            combine(&parts, style)
        };
        Expr {
            unicode: form(Style::Unicode, false),
            latex: form(Style::Latex, false),
            sympy: form(Style::Sympy, false),
            symbols: symbols_of(x),
            plain: form(Style::Plain, false),
            terms: x.numerator().len(),
            degree: x.numerator().total_degree(),
            factored: any_factored.then(|| Forms {
                unicode: form(Style::Unicode, true),
                latex: form(Style::Latex, true),
                sympy: form(Style::Sympy, true),
                plain: form(Style::Plain, true),
            }),
        }
    }

    /// An exact number shown as the decimal `text` it equals (a printed
    /// table entry), with SymPy syntax `n/d`.
    pub fn decimal(q: &rug::Rational, text: &str) -> Expr {
        Expr {
            unicode: text.to_string(),
            latex: text.to_string(),
            sympy: q.to_string(),
            symbols: Vec::new(),
            plain: text.to_string(),
            terms: 1,
            degree: 0,
            factored: None,
        }
    }

    /// An exact value given as text (a vector of integers, …) with its
    /// SymPy form.
    pub fn literal(text: &str, sympy: &str) -> Expr {
        Expr {
            unicode: text.replace('-', "−"),
            latex: text.to_string(),
            sympy: sympy.to_string(),
            symbols: Vec::new(),
            plain: text.to_string(),
            terms: 1,
            degree: 0,
            factored: None,
        }
    }

    /// `max(x₁, …, xₙ)` (or `min`) of the variables `vars`.
    pub fn extreme(max: bool, vars: &[String]) -> Expr {
        let list = |style: Style| {
            vars.iter()
                .map(|v| style.sym(&Sym::var(v)))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let (f, latex, sympy) = if max {
            ("max", "\\max", "Max")
        } else {
            ("min", "\\min", "Min")
        };
        Expr {
            unicode: format!("{f}({})", list(Style::Unicode)),
            latex: format!("{latex}({})", list(Style::Latex)),
            sympy: format!("{sympy}({})", list(Style::Sympy)),
            symbols: sympy_symbols(vars.iter().map(String::as_str)),
            plain: format!("{f}({})", list(Style::Plain)),
            terms: 1,
            degree: 1,
            factored: None,
        }
    }

    /// `num/den^(p/q)` — a quotient by a rational power, which the exact
    /// ring does not hold (a curvature `(x′y″ − y′x″)/(x′² + y′²)^{3/2}`).
    pub fn over_power(num: &Sym, den: &Sym, (p, q): (u32, u32)) -> Expr {
        let form = |style: Style, open: &str, close: &str| {
            format!(
                "({})/({}){open}{p}/{q}{close}",
                style.sym(num),
                style.sym(den)
            )
        };
        let mut symbols = symbols_of(num);
        symbols.extend(symbols_of(den));
        symbols.sort();
        symbols.dedup();
        Expr {
            unicode: form(Style::Unicode, "^(", ")"),
            latex: format!(
                "\\frac{{{}}}{{\\left({}\\right)^{{{p}/{q}}}}}",
                num.to_latex(),
                den.to_latex()
            ),
            sympy: form(Style::Sympy, "**(", ")"),
            symbols,
            plain: form(Style::Plain, "^(", ")"),
            terms: num.numerator().len(),
            degree: num.numerator().total_degree(),
            factored: None,
        }
    }

    /// A certified enclosure `[lo, hi]` of a value (decimal ends, rounded
    /// outward), in SymPy `Interval(Rational('lo'), Rational('hi'))`: the
    /// ends exactly as printed.
    pub fn enclosure(lo: &str, hi: &str) -> Expr {
        let end = |x: &str| match x.trim_start_matches(['-', '+']) {
            "inf" | "@Inf@" => format!("{}oo", if x.starts_with('-') { "-" } else { "" }),
            y if y.starts_with(|c: char| c.is_ascii_digit()) && y.parse::<f64>().is_ok() => {
                format!("Rational('{x}')")
            }
            _ => "nan".to_string(),
        };
        let text = format!("[{lo}, {hi}]");
        Expr {
            sympy: format!("Interval({}, {})", end(lo), end(hi)),
            ..Expr::numeric(&text)
        }
    }

    /// A decimal value from a numeric evaluation (not exact).
    pub fn numeric(text: &str) -> Expr {
        Expr {
            unicode: text.replace('-', "−"),
            latex: text.to_string(),
            sympy: format!("Float('{text}', 30)"),
            symbols: Vec::new(),
            plain: text.to_string(),
            terms: 1,
            degree: 0,
            factored: None,
        }
    }

    /// The shortest Unicode form: factored when given and not longer.
    pub fn best_unicode(&self) -> &str {
        match &self.factored {
            Some(f) if f.unicode.chars().count() <= self.unicode.chars().count() => &f.unicode,
            _ => &self.unicode,
        }
    }

    /// The LaTeX form matching [`Expr::best_unicode`].
    pub fn best_latex(&self) -> &str {
        match &self.factored {
            Some(f) if f.unicode.chars().count() <= self.unicode.chars().count() => &f.latex,
            _ => &self.latex,
        }
    }

    /// The SymPy form matching [`Expr::best_unicode`].
    pub fn best_sympy(&self) -> &str {
        match &self.factored {
            Some(f) if f.unicode.chars().count() <= self.unicode.chars().count() => &f.sympy,
            _ => &self.sympy,
        }
    }
}

fn symbols_of(x: &Sym) -> Vec<String> {
    let vars = x.variables();
    sympy_symbols(vars.iter().map(String::as_str))
}

/// One coordinate of a witness point: `name = value`, exactly.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Assignment {
    /// The variable as the report prints it (Unicode; `s`, `c` for sin θ, cos θ).
    pub name: String,
    /// Its exact value (a rational, or an exact description).
    pub value: String,
    /// `name = value` in LaTeX math.
    pub latex: String,
    /// The variable as the expressions' SymPy forms name it (`P0`,
    /// `lamda`, `theta`): one of their `symbols`. Absent for `s`, `c`
    /// (they are `sin(theta)`, `cos(theta)` there; `theta` is given too).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub symbol: Option<String>,
    /// The value in SymPy syntax (`3/5`, `pi/2`, `atan2(3, 4)`).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub sympy: Option<String>,
}

impl Assignment {
    /// The variable `var` (as the exact ring names it) set to `value`.
    pub fn exact(var: &str, value: &Sym) -> Assignment {
        let trig = var == "s" || var == "c";
        Assignment {
            name: Sym::var(var).to_unicode(),
            value: value.to_unicode(),
            latex: format!("{} = {}", Sym::var(var).to_latex(), value.to_latex()),
            symbol: (!trig).then(|| Sym::var(var).to_sympy()),
            sympy: Some(value.to_sympy()),
        }
    }

    /// The variable `var` set to a printed decimal: `text` as printed, its
    /// exact value `q` in SymPy syntax (`n/d`).
    pub fn printed(var: &str, q: &rug::Rational, text: &str) -> Assignment {
        Assignment {
            name: Sym::var(var).to_unicode(),
            value: text.to_string(),
            latex: format!("{} = {text}", Sym::var(var).to_latex()),
            symbol: Some(Sym::var(var).to_sympy()),
            sympy: Some(q.to_string()),
        }
    }

    /// The angle `θ ∈ [0, π/2]` of a point `(s, c) = (sin θ, cos θ)` of the
    /// unit circle, exactly, from the coordinates the point gives:
    /// `atan2(s, c)`, `asin(s)` or `acos(c)` (`0`, `π/2` where that is what
    /// it is).
    pub fn angle(s: Option<&Sym>, c: Option<&Sym>) -> Option<Assignment> {
        let is = |x: Option<&Sym>, v: i32| x.and_then(Sym::as_rational).is_some_and(|q| q == v);
        let (unicode, sympy, latex) = if is(s, 0) || is(c, 1) {
            ("0".to_string(), "0".to_string(), "0".to_string())
        } else if is(s, 1) || is(c, 0) {
            ("π/2".to_string(), "pi/2".to_string(), "\\pi/2".to_string())
        } else {
            let (f, args): (&str, Vec<&Sym>) = match (s, c) {
                (Some(s), Some(c)) => ("atan2", vec![s, c]),
                (Some(s), None) => ("asin", vec![s]),
                (None, Some(c)) => ("acos", vec![c]),
                (None, None) => return None,
            };
            let join =
                |g: fn(&Sym) -> String| args.iter().map(|x| g(x)).collect::<Vec<_>>().join(", ");
            (
                format!("{f}({})", join(Sym::to_unicode)),
                format!("{f}({})", join(Sym::to_sympy)),
                format!("\\operatorname{{{f}}}({})", join(Sym::to_latex)),
            )
        };
        Some(Assignment {
            name: "θ".into(),
            value: unicode,
            latex: format!("\\theta = {latex}"),
            symbol: Some("theta".into()),
            sympy: Some(sympy),
        })
    }
}

/// A labelled value of a witness.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Value {
    /// What the value is (`value`, `target`, `printed`, `computed`, …).
    pub label: String,
    pub value: Expr,
    /// The expression whose value at the point this is, when it is one
    /// (substitute the point's `symbol = sympy` pairs into its SymPy form to re-check).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub of: Option<Expr>,
}

impl Value {
    /// A labelled value.
    pub fn new(label: impl Into<String>, value: Expr) -> Value {
        Value {
            label: label.into(),
            value,
            of: None,
        }
    }

    /// The same value, as the value of `expr` at the point.
    pub fn of(mut self, expr: &Sym) -> Value {
        self.of = Some(Expr::new(expr));
        self
    }

    /// The same value, as the value of `expr` (given in its forms) at the point.
    pub fn of_expr(mut self, expr: Expr) -> Value {
        self.of = Some(expr);
        self
    }
}

/// What a check states of its witness values — the first against the
/// second, or against `0` when there is one value — which is false at the
/// witness point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Relation {
    /// `first = second`.
    Equal,
    /// `first < second`.
    Less,
    /// `first ≤ second`.
    AtMost,
    /// `first > second`.
    Greater,
    /// `first ≥ second`.
    AtLeast,
    /// Some pair differs (the values paired in order: first with second,
    /// third with fourth, …): false when every pair agrees.
    Differ,
}

/// A point where a claim can be seen to fail by hand: every variable set to
/// an exact value, and the values that differ there.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Witness {
    pub point: Vec<Assignment>,
    /// What the point means or keeps symbolic (e.g. `π` stays a symbol).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub note: Option<String>,
    pub values: Vec<Value>,
    /// True when the values are exact; false for a numeric witness
    /// (decimal values of a high-precision evaluation, differing far above
    /// their rounding).
    pub exact: bool,
    /// What the check states of the values, when it is not that they are
    /// equal (absent: `equal`, the values differ at the point).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub stated: Option<Relation>,
}

impl Witness {
    /// One line: `at m = 1/2, P₂ = 3: printed = 5/2, computed = 3`.
    pub fn line(&self) -> String {
        let point: Vec<String> = self
            .point
            .iter()
            .map(|a| format!("{} = {}", a.name, a.value))
            .collect();
        let values: Vec<String> = self
            .values
            .iter()
            .map(|v| format!("{} = {}", v.label, v.value.best_unicode()))
            .collect();
        let note = self
            .note
            .as_ref()
            .map_or(String::new(), |n| format!(" ({n})"));
        let exact = if self.exact { "exact" } else { "numeric" };
        format!(
            "at {}{note}: {} ({exact})",
            point.join(", "),
            values.join(", ")
        )
    }
}

/// A named part of a claim with its own status.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Part {
    pub name: String,
    pub status: Status,
}

/// What an evidence item is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Prose: a definition, a convention, a reading, a conclusion.
    Note,
    /// An identity decided exactly: its residual (value − target).
    Identity,
    /// A printed value against the computed one.
    Comparison,
    /// A certified sign (nonnegativity, monotonicity) or its counterexample.
    Certificate,
    /// A printed join formula in one convention: the residuals by order.
    Join,
    /// A formula derived exactly (the correct one).
    Derived,
    /// A value evaluated numerically (high-precision MPFR).
    Numeric,
}

/// A labelled exact expression of an item (`residual`, `computed`, `order 1`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Labelled {
    pub label: String,
    pub expr: Expr,
}

/// One item of evidence.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Evidence {
    pub kind: Kind,
    /// The parts of the claim the item belongs to, outermost first.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub parts: Vec<Part>,
    /// What the item checks (`Σ b_i − 1`, `b0 ≥ 0`), when it checks one thing.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub subject: Option<String>,
    /// The printed formula the item checks, as transcribed (plain text).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub printed: Option<String>,
    /// The status of that check, when the item decides one.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub status: Option<Status>,
    /// The prose of the item (Unicode), without its expressions.
    pub text: String,
    /// The exact expressions of the item.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub exprs: Vec<Labelled>,
    /// A point where the check visibly fails, with exact values.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub witness: Option<Witness>,
}

impl Evidence {
    /// A prose note.
    pub fn note(text: impl Into<String>) -> Evidence {
        Evidence::new(Kind::Note, text)
    }

    /// An item of `kind` with its prose.
    pub fn new(kind: Kind, text: impl Into<String>) -> Evidence {
        Evidence {
            kind,
            parts: Vec::new(),
            subject: None,
            printed: None,
            status: None,
            text: text.into(),
            exprs: Vec::new(),
            witness: None,
        }
    }

    /// The same item checking `subject` with `status`.
    pub fn about(mut self, subject: impl Into<String>, status: Status) -> Evidence {
        self.subject = Some(subject.into());
        self.status = Some(status);
        self
    }

    /// The same item with an expression.
    pub fn with(mut self, label: impl Into<String>, expr: Expr) -> Evidence {
        self.exprs.push(Labelled {
            label: label.into(),
            expr,
        });
        self
    }

    /// The same item with a witness.
    pub fn witnessed(mut self, witness: Option<Witness>) -> Evidence {
        self.witness = witness;
        self
    }

    /// The same item inside the part `name` (outermost so far).
    pub fn in_part(mut self, name: impl Into<String>, status: Status) -> Evidence {
        self.parts.insert(
            0,
            Part {
                name: name.into(),
                status,
            },
        );
        self
    }

    /// The whole item as one Unicode line (every expression in full), as
    /// the plain-text views and the tests read it.
    pub fn line(&self) -> String {
        self.render(|e| e.unicode.clone())
    }

    /// The same with expressions in plain ASCII.
    pub fn plain_line(&self) -> String {
        self.render(|e| e.plain.clone())
    }

    fn render(&self, form: impl Fn(&Expr) -> String) -> String {
        let mut out = String::new();
        for p in &self.parts {
            out.push_str(&format!("{}: {} — ", p.name, p.status));
        }
        if let Some(s) = &self.subject {
            out.push_str(s);
            if let Some(p) = &self.printed {
                out.push_str(&format!(" printed {p}"));
            }
            if let Some(st) = self.status {
                out.push_str(&format!(": {st}"));
            }
            if !self.text.is_empty() || !self.exprs.is_empty() {
                out.push_str(" — ");
            }
        }
        out.push_str(&self.text);
        for (i, l) in self.exprs.iter().enumerate() {
            if i > 0 || !self.text.is_empty() {
                out.push_str("; ");
            }
            out.push_str(&format!("{} = {}", l.label, form(&l.expr)));
        }
        if let Some(w) = &self.witness {
            out.push_str(&format!("; witness: {}", w.line()));
        }
        out
    }

    /// True when the item's Unicode or plain line contains `needle`.
    pub fn contains(&self, needle: &str) -> bool {
        self.line().contains(needle) || self.plain_line().contains(needle)
    }
}

impl fmt::Display for Evidence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.line())
    }
}

impl From<String> for Evidence {
    fn from(text: String) -> Evidence {
        Evidence::note(text)
    }
}

impl From<&str> for Evidence {
    fn from(text: &str) -> Evidence {
        Evidence::note(text)
    }
}

/// The evidence of a verdict, in order. Accepts notes as strings where the
/// checkers push prose.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct EvidenceList(Vec<Evidence>);

impl EvidenceList {
    /// Appends an item.
    pub fn push(&mut self, e: impl Into<Evidence>) {
        self.0.push(e.into());
    }

    /// Inserts an item at `index`.
    pub fn insert(&mut self, index: usize, e: impl Into<Evidence>) {
        self.0.insert(index, e.into());
    }

    /// Appends items.
    pub fn extend<E: Into<Evidence>>(&mut self, items: impl IntoIterator<Item = E>) {
        self.0.extend(items.into_iter().map(Into::into));
    }

    /// Inserts items before the first.
    pub fn prepend<E: Into<Evidence>>(&mut self, items: impl IntoIterator<Item = E>) {
        let head: Vec<Evidence> = items.into_iter().map(Into::into).collect();
        self.0.splice(0..0, head);
    }

    /// The items, owned.
    pub fn into_vec(self) -> Vec<Evidence> {
        self.0
    }
}

impl Deref for EvidenceList {
    type Target = [Evidence];
    fn deref(&self) -> &[Evidence] {
        &self.0
    }
}

impl std::ops::DerefMut for EvidenceList {
    fn deref_mut(&mut self) -> &mut [Evidence] {
        &mut self.0
    }
}

impl<E: Into<Evidence>> From<Vec<E>> for EvidenceList {
    fn from(items: Vec<E>) -> Self {
        items.into_iter().collect()
    }
}

impl<E: Into<Evidence>> FromIterator<E> for EvidenceList {
    fn from_iter<I: IntoIterator<Item = E>>(iter: I) -> Self {
        EvidenceList(iter.into_iter().map(Into::into).collect())
    }
}

impl IntoIterator for EvidenceList {
    type Item = Evidence;
    type IntoIter = std::vec::IntoIter<Evidence>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'a> IntoIterator for &'a EvidenceList {
    type Item = &'a Evidence;
    type IntoIter = std::slice::Iter<'a, Evidence>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_combination_factors_its_coefficients() {
        let (m1, m2) = (Sym::var("m1"), Sym::var("m2"));
        let p2 = Sym::var("P2");
        let coefficient = (m1.clone() - &m2) * &(m2.clone() + &Sym::int(2)) / &(m1 + &Sym::int(2));
        let e = Expr::combination(&(coefficient * &p2), &["P2".to_string()]);
        assert_eq!(
            e.factored.as_ref().map(|f| f.unicode.as_str()),
            Some("(m₁ − m₂)·(m₂ + 2)/(m₁ + 2)·P₂")
        );
        let (p3, m) = (Sym::var("P3"), Sym::var("m"));
        let x = p3.clone() - &(p2.clone() * &(m.clone() + &Sym::int(2)))
            + &(Sym::int(-3) * &Sym::var("P4"));
        let names: Vec<String> = ["P2", "P3", "P4"].map(String::from).to_vec();
        assert_eq!(
            Expr::combination(&x, &names).unicode,
            "(−m − 2)·P₂ + P₃ − 3·P₄"
        );
        assert_eq!(
            Expr::combination(&x, &names).sympy,
            "(-m - 2)*P2 + P3 - 3*P4"
        );
        assert_eq!(e.symbols, ["P2", "m1", "m2"]);
    }

    #[test]
    fn lines_show_parts_subject_status_expressions_and_witness() {
        let e = Evidence::new(Kind::Identity, "")
            .about("Σ b_i − 1", Status::Fails)
            .with("residual", Expr::new(&Sym::var("t")))
            .in_part("λ = μ = 0", Status::Fails);
        assert_eq!(
            e.line(),
            "λ = μ = 0: fails — Σ b_i − 1: fails — residual = t"
        );
        assert!(e.contains("residual = t"));
        let list: EvidenceList = ["a", "b"].into_iter().collect();
        assert_eq!(list.len(), 2);
        assert!(list[1].contains("b"));
    }
}
