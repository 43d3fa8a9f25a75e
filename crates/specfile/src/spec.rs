//! A validated spec: the basis (domain and atoms, parameters with exact
//! ranges, definitions and functions as exact [`Sym`] values) and the
//! claims to check (`claims.rs`).

use std::cell::RefCell;
use std::collections::BTreeMap;

use rug::Rational;
use toml::Spanned;
use trig_core::{Affine, Domain, Parameter, Variable};
use trig_symbolic::Sym;

use crate::ast::{self, Expr, Node};
use crate::check::{JoinSegments, SpecClaim};
use crate::error::{FormulaError, Result, SpecError};
use crate::formula::{Scope, linear, lower};
use crate::frequencies::{Usage, domain};
use crate::names::{control_point_refusal, symbol_refusal};
use crate::nonvanishing;
use crate::raw::{RawFunction, RawSpec};
use crate::source::Source;
use trig_core::ParamRange;

/// One basis function or definition.
#[derive(Debug, Clone, PartialEq)]
pub struct SpecFunction {
    pub name: String,
    /// The formula as written in the file.
    pub formula: String,
    /// Its exact value.
    pub value: Sym,
}

/// A validated spec file.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// The file as given (for reports and errors).
    pub file: String,
    pub id: String,
    pub title: String,
    pub citation: String,
    /// The domain `x ∈ [a, b]` and the atoms of the formulas.
    pub domain: Domain,
    /// The legacy variable when the file declares one (`unit-angle`,
    /// `angle`, `polynomial`): their reports keep the catalog's wording.
    pub legacy: Option<Variable>,
    /// The variable's name in formulas (`u`, `t`, …).
    pub var_name: String,
    /// For the legacy trigonometric variables, `k` with the declared angle
    /// `= k·ω`: the shorthands `s`, `c` are its sine and cosine.
    pub shorthand: Option<i64>,
    /// The functions are the segments of a uniform B-spline basis function
    /// (piece `k` is function `n − 1 − k`), as the file declares.
    pub piecewise: bool,
    pub params: Vec<Parameter>,
    /// Helper definitions (not basis functions).
    pub definitions: Vec<SpecFunction>,
    pub functions: Vec<SpecFunction>,
    pub claims: Vec<SpecClaim>,
}

/// The additive terms of `e` with their signs: `a − (b + c)` is `+a`,
/// `−b`, `−c`.
/// The printed terms of `e` (signs included, as `(negated, factors,
/// divisors, term)`): its additive pieces, and inside a bracket of control
/// points multiplied or divided by a scalar (`α(P3 − P2)`,
/// `[… − (4m1 + 4)P5]/2`) the bracket's own pieces, each with the scalar —
/// a sign typo is one printed term, wherever the print brackets it.
/// Scalars (`(m2 + 2)P3`) are never split.
type Term<'e> = (bool, Vec<&'e Expr>, Vec<&'e Expr>, &'e Expr);

/// `brackets` receives the ranges of `out` that are one printed bracket
/// (flipping a bracket's sign is one typo too).
fn printed_pieces<'e>(
    e: &'e Expr,
    points: &[String],
    out: &mut Vec<Term<'e>>,
    brackets: &mut Vec<std::ops::Range<usize>>,
) {
    let mut pieces = Vec::new();
    additive_terms(e, false, &mut pieces);
    for (negated, piece) in pieces {
        let has_point = |x: &Expr| {
            let mut found = false;
            x.walk(&mut |n| {
                if let Node::Name(name) = &n.node {
                    found |= points.contains(name);
                }
            });
            found
        };
        let bracket = |x: &Expr| {
            matches!(x.node, Node::Add(..) | Node::Sub(..) | Node::Neg(..)) && has_point(x)
        };
        let (inner, factor, divisor) = match &piece.node {
            Node::Mul(a, b) if bracket(b) && !has_point(a) => (b.as_ref(), Some(a.as_ref()), None),
            Node::Mul(a, b) if bracket(a) && !has_point(b) => (a.as_ref(), Some(b.as_ref()), None),
            Node::Div(a, b) if bracket(a) && !has_point(b) => (a.as_ref(), None, Some(b.as_ref())),
            _ => {
                out.push((negated, Vec::new(), Vec::new(), piece));
                continue;
            }
        };
        let (mut nested, mut inner_brackets) = (Vec::new(), Vec::new());
        printed_pieces(inner, points, &mut nested, &mut inner_brackets);
        let start = out.len();
        brackets.extend(
            inner_brackets
                .into_iter()
                .map(|r| r.start + start..r.end + start),
        );
        brackets.push(start..start + nested.len());
        out.extend(nested.into_iter().map(|(n, mut f, mut d, t)| {
            f.extend(factor);
            d.extend(divisor);
            (n != negated, f, d, t)
        }));
    }
}

fn additive_terms<'e>(e: &'e Expr, negated: bool, out: &mut Vec<(bool, &'e Expr)>) {
    match &e.node {
        ast::Node::Add(a, b) => {
            additive_terms(a, negated, out);
            additive_terms(b, negated, out);
        }
        ast::Node::Sub(a, b) => {
            additive_terms(a, negated, out);
            additive_terms(b, !negated, out);
        }
        ast::Node::Neg(a) => additive_terms(a, !negated, out),
        _ => out.push((negated, e)),
    }
}

/// A printed formula's terms over its denominator, with its brackets.
#[derive(Debug)]
pub struct PrintedTerms {
    pub terms: Vec<Sym>,
    pub denominator: Sym,
    /// Ranges of `terms` printed as one bracket.
    pub brackets: Vec<std::ops::Range<usize>>,
}

/// Names a parameter, function or definition may not take.
const RESERVED: &[&str] = &[
    "s", "c", "t", "u", "x", "z", "i", "E", "e", "pi", "sin", "cos", "sinh", "cosh", "exp", "sqrt",
    "theta", "h", "alpha1", "alpha2",
];

/// Highest derivative order a claim may ask for (jets carry `0..=MAX_ORDER`).
pub const MAX_ORDER: usize = 6;
/// Most shape parameters of a spec.
pub const MAX_PARAMS: usize = 8;
/// Most functions (and, separately, definitions) of a spec.
pub const MAX_FUNCTIONS: usize = 64;

impl Spec {
    /// The basis narrowed to the `functions` (indices, in order; all when
    /// empty), each less `margin` where one is given: `f − m`, named
    /// `f − m`, is `≥ 0` exactly where `f ≥ m` (a nonnegativity claim's
    /// `functions` and `margin`).
    pub fn narrowed(&self, functions: &[usize], margin: Option<&crate::check::Margin>) -> Spec {
        let mut out = self.clone();
        if !functions.is_empty() {
            out.functions = functions
                .iter()
                .map(|&i| self.functions[i].clone())
                .collect();
        }
        if let Some(m) = margin {
            let value = Sym::rational(m.value.clone());
            for f in &mut out.functions {
                f.name = format!("{} − {}", f.name, m.text);
                f.formula = format!("({}) - ({})", f.formula, m.text);
                f.value = f.value.clone() - &value;
            }
        }
        out
    }

    /// Parameter names and printed symbols, in order.
    pub fn param_pairs(&self) -> Vec<(String, String)> {
        self.params
            .iter()
            .map(|p| (p.name.clone(), p.symbol.clone()))
            .collect()
    }

    /// The functions and definitions by name, with their values.
    fn named_values(&self) -> Vec<(String, Sym)> {
        self.functions
            .iter()
            .chain(&self.definitions)
            .map(|f| (f.name.clone(), f.value.clone()))
            .collect()
    }

    /// Parses a further formula in this spec's variable and parameters
    /// (functions and definitions by name too), with `extra` symbols
    /// allowed and parameters renamed by `rename` (e.g. `lambda` ↦
    /// `lambda2` for the second segment of a join).
    pub fn parse_formula(
        &self,
        text: &str,
        extra: &[String],
    ) -> std::result::Result<Sym, FormulaError> {
        let ranges = self.ranges();
        self.parse_with(text, extra, &|d: &Sym| {
            nonvanishing::check(d, &self.domain, &ranges)
        })
    }

    /// Parses a printed claim formula: a division that cannot be proved
    /// nonzero over the ranges (`extra_ranges` give ranges to further
    /// symbols, e.g. `lambda2` of a second segment) is accepted when it is
    /// not identically zero, and reported in the second value — a printed
    /// formula singular inside the printed range is a finding, not a
    /// malformed file.
    pub fn parse_claim_formula(
        &self,
        text: &str,
        extra: &[String],
        extra_ranges: &[(String, ParamRange)],
    ) -> std::result::Result<(Sym, Vec<String>), FormulaError> {
        let mut ranges = self.ranges();
        ranges.extend(extra_ranges.iter().cloned());
        let singular = RefCell::new(Vec::new());
        let value = self.parse_with(text, extra, &|d: &Sym| {
            if let Err(why) = nonvanishing::check(d, &self.domain, &ranges) {
                singular.borrow_mut().push(why);
            }
            Ok(())
        })?;
        Ok((value, singular.into_inner()))
    }

    /// A printed claim formula `(t₁ ± t₂ ± …)/d` as printed: its additive
    /// terms (signs included; a bracket of the control points `points`
    /// times or over a scalar split into its own terms, each with the
    /// scalar, the bracket kept as a range of them) and its denominator
    /// (`1` when there is none), each exact — so that a sign typo in one
    /// printed term, or in front of one bracket, can be named.
    pub fn printed_terms(
        &self,
        text: &str,
        extra: &[String],
        points: &[String],
    ) -> std::result::Result<PrintedTerms, FormulaError> {
        let e = ast::parse(text)?;
        let (num, den) = match &e.node {
            ast::Node::Div(a, b) => (a.as_ref(), Some(b.as_ref())),
            _ => (&e, None),
        };
        let (mut terms, mut brackets) = (Vec::new(), Vec::new());
        printed_pieces(num, points, &mut terms, &mut brackets);
        let accept = |_: &Sym| Ok(());
        let lower = |x: &Expr| self.lower_with(x, extra, &accept);
        let lowered = terms
            .into_iter()
            .map(|(negated, factors, divisors, t)| {
                let mut v = lower(t)?;
                for f in factors {
                    v = lower(f)? * &v;
                }
                for d in divisors {
                    v = v / &lower(d)?;
                }
                Ok(if negated { -v } else { v })
            })
            .collect::<std::result::Result<Vec<Sym>, FormulaError>>()?;
        let den = match den {
            Some(d) => lower(d)?,
            None => Sym::one(),
        };
        Ok(PrintedTerms {
            terms: lowered,
            denominator: den,
            brackets,
        })
    }

    fn parse_with(
        &self,
        text: &str,
        extra: &[String],
        divisor: &dyn Fn(&Sym) -> std::result::Result<(), String>,
    ) -> std::result::Result<Sym, FormulaError> {
        self.lower_with(&ast::parse(text)?, extra, divisor)
    }

    fn lower_with(
        &self,
        e: &Expr,
        extra: &[String],
        divisor: &dyn Fn(&Sym) -> std::result::Result<(), String>,
    ) -> std::result::Result<Sym, FormulaError> {
        let params = self.param_pairs();
        let values = self.named_values();
        let resolve = |n: &str| {
            values
                .iter()
                .find(|(m, _)| m == n)
                .map(|(_, v)| Ok(v.clone()))
        };
        lower(
            e,
            &Scope {
                domain: &self.domain,
                var_name: &self.var_name,
                shorthand: self.shorthand,
                params: &params,
                resolve: &resolve,
                extra,
                divisor,
            },
        )
    }

    /// Reads an expression linear in the variable and the parameters (a
    /// symmetry map `pi/2 - t`).
    pub fn parse_linear(
        &self,
        text: &str,
        what: &str,
    ) -> std::result::Result<crate::formula::Linear, FormulaError> {
        linear(
            &ast::parse(text)?,
            Some(&self.var_name),
            &self.param_pairs(),
            what,
        )
    }

    /// The declared parameter ranges by name.
    pub fn ranges(&self) -> Vec<(String, ParamRange)> {
        self.params
            .iter()
            .map(|p| (p.name.clone(), p.range.clone()))
            .collect()
    }
}

fn identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.starts_with("__")
}

/// The legacy variables: (variable, name, end, declared angle).
fn legacy(keyword: &str) -> Option<(Variable, &'static str)> {
    match keyword {
        "unit-angle" | "u" => Some((Variable::UnitAngle, "u")),
        "angle" => Some((Variable::Angle, "t")),
        "polynomial" => Some((Variable::Polynomial, "t")),
        _ => None,
    }
}

/// `[a, b]` of the `domain` field: exact ends linear in π and the
/// parameters, `a < b` for every parameter value of the declared ranges.
fn domain_ends(
    src: &Source<'_>,
    field: &Spanned<String>,
    params: &[(String, String)],
    ranges: &[ParamRange],
) -> Result<(Affine, Affine)> {
    let text = field.get_ref().trim();
    let expected = "expected `[a, b]` with ends in numbers, pi and the parameters (e.g. [0, alpha], [-pi/2, pi/2])";
    let inner = text
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .and_then(|t| t.split_once(','));
    let Some((a, b)) = inner else {
        return src.invalid(field.span(), "domain", format!("`{text}`: {expected}"));
    };
    let end = |s: &str| -> Result<Affine> {
        let l = ast::parse(s)
            .and_then(|e| linear(&e, None, params, "a domain end"))
            .map_err(|e| SpecError::Invalid {
                at: src.at(field.span().start),
                field: "domain".into(),
                message: format!("`{}`: {}", s.trim(), e.message),
            })?;
        Ok(l.rest)
    };
    let (a, b) = (end(a)?, end(b)?);
    let length = b.plus(&a.scale(&Rational::from(-1)));
    if !positive_on(&length, ranges) {
        return src.invalid(
            field.span(),
            "domain",
            format!("`{text}`: the end is not above the start for every parameter in its range"),
        );
    }
    Ok((a, b))
}

/// `L > 0` for every parameter value in the ranges (`L` linear: at the
/// corners of the box, with `π ∈ (3.14159, 3.14160)`; a corner at an open
/// end may give `0`, which is not attained; an unbounded parameter must
/// not occur).
fn positive_on(l: &Affine, ranges: &[ParamRange]) -> bool {
    let (pi_lo, pi_hi) = (
        Rational::from((314_159, 100_000)),
        Rational::from((314_160, 100_000)),
    );
    let pi = if l.pi >= 0 { &pi_lo } else { &pi_hi };
    let mut least = Rational::from(&l.constant + &(l.pi.clone() * pi));
    let mut open = false;
    for (i, q) in &l.params {
        let range = &ranges[*i];
        let worst = if *q > 0 { &range.lo } else { &range.hi };
        let Some(v) = worst.value() else {
            return false;
        };
        let mut contribution = Rational::from(q * v);
        if range.pi {
            contribution *= if contribution >= 0 { &pi_lo } else { &pi_hi };
        }
        least += contribution;
        open |= matches!(worst, trig_core::End::Open(_));
    }
    least > 0 || (least == 0 && open)
}

/// The spec of `raw` with its functions read and validated, without its
/// claims (read next by [`crate::claims::attach`]).
pub(crate) fn build(src: &Source<'_>, raw: &RawSpec) -> Result<Spec> {
    let id = raw.id.get_ref().trim().to_string();
    if id.is_empty()
        || !id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
    {
        return src.invalid(
            raw.id.span(),
            "id",
            format!("`{id}`: expected a nonempty id of letters, digits, `-`, `_`, `.`"),
        );
    }
    let keyword = raw.variable.get_ref().trim();
    let (legacy, var_name) = match legacy(keyword) {
        Some((v, name)) => (Some(v), name.to_string()),
        None if identifier(keyword) && !RESERVED[4..].contains(&keyword) => {
            (None, keyword.to_string())
        }
        None => {
            return src.invalid(
                raw.variable.span(),
                "variable",
                format!(
                    "`{keyword}`: expected `unit-angle` (u ∈ [0, 1], θ = πu/2), `angle` (t ∈ [0, π/2]), `polynomial` (t ∈ [0, 1]), or the name of the variable (e.g. `t`) with a `domain`"
                ),
            );
        }
    };
    let params = read_params(src, raw, &var_name)?;
    let pairs: Vec<(String, String)> = params
        .iter()
        .map(|p| (p.name.clone(), p.symbol.clone()))
        .collect();
    let ranges: Vec<ParamRange> = params.iter().map(|p| p.range.clone()).collect();
    let (ends, declared) = match (legacy, &raw.domain) {
        (Some(v), None) => {
            let d = Domain::from_variable(v, &[]);
            ((d.start, d.end), d.angle)
        }
        (Some(_), Some(d)) => {
            return src.invalid(
                d.span(),
                "domain",
                format!("the variable `{keyword}` fixes its domain; declare `variable = \"t\"` (any name) to give your own"),
            );
        }
        (None, Some(d)) => (domain_ends(src, d, &pairs, &ranges)?, None),
        (None, None) => {
            return src.invalid(
                raw.variable.span(),
                "domain",
                format!("the variable `{keyword}` needs a domain, e.g. domain = \"[0, 1]\""),
            );
        }
    };
    // every formula's tree, then the base rates of the whole file
    let entries = read_entries(src, raw, &pairs, &var_name)?;
    let mut usage = Usage::default();
    for (entry, e) in &entries {
        usage
            .scan(e, &var_name, &pairs)
            .map_err(|err| src.formula_error(&entry.formula, err))?;
    }
    if legacy == Some(Variable::Polynomial)
        && !(usage.angle_rates.is_empty() && usage.exp_rates.is_empty())
    {
        return src.invalid(
            raw.variable.span(),
            "variable",
            "sin/cos/exp of the variable in a basis declared `polynomial`; declare `variable = \"t\"` with a `domain` instead".into(),
        );
    }
    let names: Vec<String> = params.iter().map(|p| p.name.clone()).collect();
    let domain = domain(&var_name, names, ends, &usage, declared.as_ref())
        .or_else(|m| src.invalid(raw.variable.span(), "variable", m))?;
    let shorthand = match (&declared, &domain.angle) {
        (Some(decl), Some(base)) => {
            crate::formula::ratio(decl, base).and_then(|k| k.numer().to_i64())
        }
        _ => None,
    };
    let symbols: Vec<Sym> = params.iter().map(|p| Sym::var(&p.name)).collect();
    for (end, x) in [("start", &domain.start), ("end", &domain.end)] {
        if domain.atoms_at(x, &Sym::one(), &symbols).is_none() {
            return src.invalid(
                raw.domain.as_ref().map_or(raw.variable.span(), |d| d.span()),
                "domain",
                format!(
                    "at the {end} {} the atoms are not exact (sin/cos of a constant angle must be at a multiple of pi/12, exp of a nonzero constant is not supported): choose the domain or the angle rate so they are",
                    x.text(&domain.param_names)
                ),
            );
        }
    }
    let mut spec = Spec {
        file: src.file.to_string(),
        id,
        title: raw.title.clone().unwrap_or_default(),
        citation: raw.citation.clone(),
        domain,
        legacy,
        var_name,
        shorthand,
        piecewise: raw.piecewise,
        params,
        definitions: Vec::new(),
        functions: Vec::new(),
        claims: Vec::new(),
    };
    let values = lower_all(src, &spec, &entries)?;
    let n_definitions = raw.definitions.len();
    for ((entry, _), value) in entries.iter().zip(values) {
        let f = SpecFunction {
            name: entry.name.get_ref().trim().to_string(),
            formula: entry.formula.get_ref().clone(),
            value,
        };
        if spec.definitions.len() < n_definitions {
            spec.definitions.push(f);
        } else {
            spec.functions.push(f);
        }
    }
    Ok(spec)
}

fn read_params(src: &Source<'_>, raw: &RawSpec, var_name: &str) -> Result<Vec<Parameter>> {
    let mut params: Vec<Parameter> = Vec::new();
    if raw.parameters.len() > MAX_PARAMS {
        return src.invalid(
            raw.parameters[MAX_PARAMS].name.span(),
            "parameters",
            format!("more than {MAX_PARAMS} parameters (the limit of a spec)"),
        );
    }
    for p in &raw.parameters {
        let name = p.name.get_ref().trim().to_string();
        let taken = params.iter().any(|q| q.name == name || q.symbol == name);
        if let Some(why) = control_point_refusal(&name) {
            return src.invalid(p.name.span(), "parameters.name", why);
        }
        if !identifier(&name) || RESERVED.contains(&name.as_str()) || name == var_name || taken {
            return src.invalid(
                p.name.span(),
                "parameters.name",
                format!(
                    "`{name}`: expected a new ASCII identifier other than the variable and {}",
                    RESERVED.join(", ")
                ),
            );
        }
        let range = ParamRange::parse(p.range.get_ref())
            .or_else(|m| src.invalid(p.range.span(), "parameters.range", m))?;
        let symbol = p
            .symbol
            .as_ref()
            .map_or_else(|| name.clone(), |s| s.get_ref().trim().to_string());
        let others: Vec<(&str, &str)> = raw
            .parameters
            .iter()
            .filter(|q| !std::ptr::eq(*q, p))
            .map(|q| {
                let n = q.name.get_ref().trim();
                (n, q.symbol.as_ref().map_or(n, |s| s.get_ref().trim()))
            })
            .collect();
        if let Some(why) = symbol_refusal(&symbol, &name, var_name, RESERVED, &others) {
            let span = p.symbol.as_ref().map_or(p.name.span(), |s| s.span());
            return src.invalid(span, "parameters.symbol", why);
        }
        params.push(Parameter {
            symbol,
            name,
            range,
            source: p.source.clone().unwrap_or_else(|| "spec file".into()),
        });
    }
    Ok(params)
}

/// The definitions, then the functions, each with its syntax tree; names
/// checked.
fn read_entries<'r>(
    src: &Source<'_>,
    raw: &'r RawSpec,
    params: &[(String, String)],
    var_name: &str,
) -> Result<Vec<(&'r RawFunction, Expr)>> {
    if raw.functions.is_empty() {
        return Err(SpecError::Invalid {
            at: src.at(0),
            field: "functions".into(),
            message: "expected at least one [[functions]] entry".into(),
        });
    }
    for (list, what) in [
        (&raw.functions, "functions"),
        (&raw.definitions, "definitions"),
    ] {
        if list.len() > MAX_FUNCTIONS {
            return src.invalid(
                list[MAX_FUNCTIONS].name.span(),
                what,
                format!("more than {MAX_FUNCTIONS} {what} (the limit of a spec)"),
            );
        }
    }
    let mut out: Vec<(&RawFunction, Expr)> = Vec::new();
    for (f, what) in raw
        .definitions
        .iter()
        .map(|f| (f, "definitions"))
        .chain(raw.functions.iter().map(|f| (f, "functions")))
    {
        let name = f.name.get_ref().trim();
        let taken = out.iter().any(|(g, _)| g.name.get_ref().trim() == name)
            || params.iter().any(|(p, s)| p == name || s == name);
        if !identifier(name) || RESERVED.contains(&name) || name == var_name || taken {
            return src.invalid(
                f.name.span(),
                &format!("{what}.name"),
                format!("`{name}`: expected a new ASCII identifier (not a parameter, the variable, another function or definition, or reserved)"),
            );
        }
        let e = ast::parse(f.formula.get_ref()).map_err(|e| src.formula_error(&f.formula, e))?;
        out.push((f, e));
    }
    Ok(out)
}

/// Lowers every definition and function, each on first use (any order;
/// cycles are refused), every error located in its own formula.
fn lower_all(src: &Source<'_>, spec: &Spec, entries: &[(&RawFunction, Expr)]) -> Result<Vec<Sym>> {
    let lowerer = Lowerer {
        spec,
        entries,
        index: entries
            .iter()
            .enumerate()
            .map(|(i, (f, _))| (f.name.get_ref().trim(), i))
            .collect(),
        states: RefCell::new(vec![State::Pending; entries.len()]),
        params: spec.param_pairs(),
        ranges: spec.ranges(),
    };
    (0..entries.len())
        .map(|i| match lowerer.get(i) {
            State::Done(v) => Ok(v),
            State::Failed(origin, e) => Err(src.formula_error(&entries[origin].0.formula, e)),
            State::Pending | State::InProgress => unreachable!("lowered by get"),
        })
        .collect()
}

/// The state of one name while the definitions are lowered on demand.
#[derive(Clone)]
enum State {
    Pending,
    InProgress,
    Done(Sym),
    /// The formula of entry `origin` has this error.
    Failed(usize, FormulaError),
}

struct Lowerer<'a> {
    spec: &'a Spec,
    entries: &'a [(&'a RawFunction, Expr)],
    index: BTreeMap<&'a str, usize>,
    states: RefCell<Vec<State>>,
    params: Vec<(String, String)>,
    ranges: Vec<(String, ParamRange)>,
}

impl Lowerer<'_> {
    /// Entry `i`, lowered on first request with its dependencies.
    fn get(&self, i: usize) -> State {
        let state = self.states.borrow()[i].clone();
        if !matches!(state, State::Pending) {
            return state;
        }
        self.states.borrow_mut()[i] = State::InProgress;
        let failure: RefCell<Option<(usize, FormulaError)>> = RefCell::new(None);
        let resolve = |n: &str| -> Option<std::result::Result<Sym, String>> {
            let j = *self.index.get(n)?;
            Some(match self.get(j) {
                State::Done(v) => Ok(v),
                State::InProgress => Err(format!(
                    "`{n}` is defined through itself (a circular definition)"
                )),
                State::Failed(origin, e) => {
                    *failure.borrow_mut() = Some((origin, e));
                    Err(format!("`{n}` could not be read"))
                }
                State::Pending => unreachable!("requested above"),
            })
        };
        let divisor = |d: &Sym| nonvanishing::check(d, &self.spec.domain, &self.ranges);
        let scope = Scope {
            domain: &self.spec.domain,
            var_name: &self.spec.var_name,
            shorthand: self.spec.shorthand,
            params: &self.params,
            resolve: &resolve,
            extra: &[],
            divisor: &divisor,
        };
        let result = match lower(&self.entries[i].1, &scope) {
            Ok(v) => State::Done(v),
            Err(e) => match failure.into_inner() {
                Some((origin, inner)) => State::Failed(origin, inner),
                None => State::Failed(i, e),
            },
        };
        self.states.borrow_mut()[i] = result.clone();
        result
    }
}

impl JoinSegments {
    /// Each segment's copies of the parameters of `spec` (with different
    /// parameters): as printed, else `p1` on the first and `p2` on the
    /// second for each parameter `p`.
    pub fn param_copies(&self, spec: &Spec) -> [Vec<Sym>; 2] {
        self.printed.clone().unwrap_or_else(|| {
            [1, 2].map(|k| {
                spec.params
                    .iter()
                    .map(|p| Sym::var(&format!("{}{k}", p.name)))
                    .collect()
            })
        })
    }
}
