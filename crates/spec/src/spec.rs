//! A validated spec: the basis (variable, parameters with exact ranges,
//! functions as exact [`Sym`] values) and the claims to check.

use rug::Rational;
use toml::Spanned;
use trig_core::{Variable, parse_exact};
use trig_deriv::{End, Wrt};
use trig_symbolic::Sym;

use crate::error::{FormulaError, Location, Result, SpecError};
use crate::formula::{Scope, parse};
use crate::nonvanishing;
use crate::range::SpecRange;
use crate::raw::{RawClaim, RawSpec};

/// A shape parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct SpecParam {
    /// ASCII name (symbol name in the exact ring, `--param NAME=…`).
    pub name: String,
    /// The symbol the source prints.
    pub symbol: String,
    /// The published range.
    pub range: SpecRange,
    /// Where the range is stated.
    pub source: String,
}

/// One basis function.
#[derive(Debug, Clone, PartialEq)]
pub struct SpecFunction {
    pub name: String,
    /// The formula as written in the file.
    pub formula: String,
    /// Its exact value.
    pub value: Sym,
}

/// A printed value `name = formula` of one function.
#[derive(Debug, Clone, PartialEq)]
pub struct Printed {
    pub function: usize,
    pub text: String,
    pub value: Sym,
}

/// A printed monotonicity statement about one function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Monotone {
    pub function: usize,
    pub increasing: bool,
}

/// A printed join condition `Qk = formula in P0…, Q0…`.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Index `k` of the second segment's control point.
    pub point: usize,
    pub text: String,
    pub value: Sym,
}

/// What a claim of the file asserts, in a form the audit can decide.
#[derive(Debug, Clone, PartialEq)]
pub enum Check {
    /// `Σ bᵢ = 1`.
    Unity,
    /// Every function ≥ 0 on the domain for the parameter range (the
    /// declared one unless given); `maximal`: the range is the maximal one.
    Nonnegative {
        range: Option<SpecRange>,
        maximal: bool,
    },
    /// Each listed function monotone on the domain for the range.
    Monotone {
        items: Vec<Monotone>,
        range: Option<SpecRange>,
    },
    /// `bᵢ(x) = b_{offset−i}(map(x))`; `map` is printed in the variable,
    /// `at` gives parameter values for a numeric counterexample when the
    /// map leaves the domain.
    Symmetry {
        map_text: String,
        map: Sym,
        index_text: String,
        offset: i64,
        at: Vec<Rational>,
    },
    /// Printed function values at one end.
    EndpointValues { end: End, values: Vec<Printed> },
    /// Printed derivatives of one order at one end.
    EndpointDerivatives {
        end: End,
        order: usize,
        wrt: Wrt,
        values: Vec<Printed>,
    },
    /// Printed conditions making two segments `Σ bᵢPᵢ`, `Σ bᵢQᵢ` join `Cᵏ`.
    Join {
        order: usize,
        wrt: Wrt,
        conditions: Vec<Condition>,
    },
    /// The B-spline assembly (piece k is function 3 − k) is `Cᵏ` at its knots.
    Continuity { order: usize },
}

/// A claim of the file.
#[derive(Debug, Clone, PartialEq)]
pub struct SpecClaim {
    pub id: String,
    pub source: String,
    pub statement: String,
    pub check: Check,
}

/// A validated spec file.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// The file as given (for reports and errors).
    pub file: String,
    pub id: String,
    pub title: String,
    pub citation: String,
    pub variable: Variable,
    /// The variable's name in formulas: `u` or `t`.
    pub var_name: String,
    pub params: Vec<SpecParam>,
    pub functions: Vec<SpecFunction>,
    pub claims: Vec<SpecClaim>,
}

/// Names a parameter or function may not take.
const RESERVED: &[&str] = &[
    "s", "c", "t", "u", "x", "z", "i", "pi", "sin", "cos", "theta", "h",
];

/// Highest derivative order a claim may ask for (jets carry `0..=MAX_ORDER`).
pub const MAX_ORDER: usize = 6;

/// Maps byte offsets of the file to lines and columns.
struct Source<'a> {
    file: &'a str,
    text: &'a str,
}

impl Source<'_> {
    fn at(&self, offset: usize) -> Location {
        let offset = offset.min(self.text.len());
        let before = self.text.get(..offset).unwrap_or("");
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        Location {
            file: self.file.to_string(),
            line,
            column,
        }
    }

    fn invalid<T>(&self, span: std::ops::Range<usize>, field: &str, message: String) -> Result<T> {
        Err(SpecError::Invalid {
            at: self.at(span.start),
            field: field.into(),
            message,
        })
    }

    /// A formula error at its position inside the (single-line) string.
    fn formula_error(&self, text: &Spanned<String>, error: FormulaError) -> SpecError {
        let mut at = self.at(text.span().start);
        at.column += 1 + error.position;
        SpecError::Formula {
            at,
            formula: text.get_ref().clone(),
            error,
        }
    }
}

impl Spec {
    /// Reads and validates the spec file at `path`.
    pub fn from_file(path: &std::path::Path) -> Result<Spec> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SpecError::Io {
            file: file.clone(),
            reason: e.to_string(),
        })?;
        Spec::from_str_named(&text, &file)
    }

    /// Reads and validates spec text; `file` names it in errors.
    pub fn from_str_named(text: &str, file: &str) -> Result<Spec> {
        let src = Source { file, text };
        let raw: RawSpec = toml::from_str(text).map_err(|e| SpecError::Malformed {
            at: src.at(e.span().map_or(0, |s| s.start)),
            message: e.message().trim().replace('\n', "; "),
        })?;
        build(&src, raw)
    }

    /// Parameter names and printed symbols, in order.
    pub fn param_pairs(&self) -> Vec<(String, String)> {
        self.params
            .iter()
            .map(|p| (p.name.clone(), p.symbol.clone()))
            .collect()
    }

    /// Parses a further formula in this spec's variable and parameters
    /// (functions by name too), with `extra` symbols allowed.
    pub fn parse_formula(
        &self,
        text: &str,
        extra: &[String],
    ) -> std::result::Result<Sym, FormulaError> {
        let params = self.param_pairs();
        let functions: Vec<(String, Sym)> = self
            .functions
            .iter()
            .map(|f| (f.name.clone(), f.value.clone()))
            .collect();
        let ranges = self.ranges();
        let divisor = |d: &Sym| nonvanishing::check(d, self.variable, &ranges);
        parse(
            text,
            &Scope {
                variable: self.variable,
                var_name: &self.var_name,
                params: &params,
                functions: &functions,
                extra,
                divisor: &divisor,
            },
        )
    }

    fn ranges(&self) -> Vec<(String, SpecRange)> {
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

fn build(src: &Source<'_>, raw: RawSpec) -> Result<Spec> {
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
    let (variable, var_name) = match raw.variable.get_ref().trim() {
        "unit-angle" | "u" => (Variable::UnitAngle, "u"),
        "angle" => (Variable::Angle, "t"),
        "polynomial" | "t" => (Variable::Polynomial, "t"),
        other => {
            return src.invalid(
                raw.variable.span(),
                "variable",
                format!(
                    "`{other}`: expected `unit-angle` (u ∈ [0, 1], θ = πu/2), `angle` (t ∈ [0, π/2]) or `polynomial` (t ∈ [0, 1])"
                ),
            );
        }
    };
    let mut spec = Spec {
        file: src.file.to_string(),
        id,
        title: raw.title.unwrap_or_default(),
        citation: raw.citation,
        variable,
        var_name: var_name.to_string(),
        params: Vec::new(),
        functions: Vec::new(),
        claims: Vec::new(),
    };
    for p in raw.parameters {
        let name = p.name.get_ref().trim().to_string();
        let taken = spec
            .params
            .iter()
            .any(|q| q.name == name || q.symbol == name);
        if !identifier(&name) || RESERVED.contains(&name.as_str()) || taken {
            return src.invalid(
                p.name.span(),
                "parameters.name",
                format!(
                    "`{name}`: expected a new ASCII identifier other than {}",
                    RESERVED.join(", ")
                ),
            );
        }
        let range = SpecRange::parse(p.range.get_ref())
            .or_else(|m| src.invalid(p.range.span(), "parameters.range", m))?;
        spec.params.push(SpecParam {
            symbol: p.symbol.unwrap_or_else(|| name.clone()),
            name,
            range,
            source: p.source.unwrap_or_else(|| "spec file".into()),
        });
    }
    if raw.functions.is_empty() {
        return Err(SpecError::Invalid {
            at: src.at(0),
            field: "functions".into(),
            message: "expected at least one [[functions]] entry".into(),
        });
    }
    for f in raw.functions {
        let name = f.name.get_ref().trim().to_string();
        let taken = spec.functions.iter().any(|g| g.name == name)
            || spec
                .params
                .iter()
                .any(|p| p.name == name || p.symbol == name);
        if !identifier(&name) || RESERVED.contains(&name.as_str()) || taken {
            return src.invalid(
                f.name.span(),
                "functions.name",
                format!(
                    "`{name}`: expected a new ASCII identifier (not a parameter, not reserved)"
                ),
            );
        }
        let value = spec
            .parse_formula(f.formula.get_ref(), &[])
            .map_err(|e| src.formula_error(&f.formula, e))?;
        spec.functions.push(SpecFunction {
            name,
            formula: f.formula.get_ref().clone(),
            value,
        });
    }
    for c in raw.claims {
        let claim = claim(src, &spec, c)?;
        if spec.claims.iter().any(|d| d.id == claim.id) {
            return Err(SpecError::Invalid {
                at: src.at(0),
                field: "claims.id".into(),
                message: format!("`{}` is used twice", claim.id),
            });
        }
        spec.claims.push(claim);
    }
    Ok(spec)
}

fn need<'r, T>(
    src: &Source<'_>,
    c: &'r RawClaim,
    field: &'r Option<T>,
    name: &str,
) -> Result<&'r T> {
    field.as_ref().ok_or_else(|| SpecError::Invalid {
        at: src.at(c.check.span().start),
        field: format!("claims.{name}"),
        message: format!(
            "check `{}` of claim `{}` needs the field `{name}`",
            c.check.get_ref(),
            c.id.get_ref()
        ),
    })
}

fn function_index(
    src: &Source<'_>,
    spec: &Spec,
    name: &Spanned<String>,
    text: &str,
) -> Result<usize> {
    spec.functions
        .iter()
        .position(|f| f.name == text.trim())
        .ok_or_else(|| SpecError::Invalid {
            at: src.at(name.span().start),
            field: "claims".into(),
            message: format!(
                "`{}`: unknown function (expected one of {})",
                text.trim(),
                spec.functions
                    .iter()
                    .map(|f| f.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })
}

/// `name = formula` entries.
fn printed(src: &Source<'_>, spec: &Spec, items: &[Spanned<String>]) -> Result<Vec<Printed>> {
    items
        .iter()
        .map(|item| {
            let Some((name, formula)) = item.get_ref().split_once('=') else {
                return src.invalid(
                    item.span(),
                    "claims.values",
                    format!("`{}`: expected `NAME = VALUE`", item.get_ref()),
                );
            };
            let function = function_index(src, spec, item, name)?;
            let value = spec.parse_formula(formula, &[]).map_err(|mut e| {
                e.position += name.chars().count() + 1;
                src.formula_error(item, e)
            })?;
            Ok(Printed {
                function,
                text: item.get_ref().trim().to_string(),
                value,
            })
        })
        .collect()
}

fn one_param_range(
    src: &Source<'_>,
    spec: &Spec,
    range: &Option<Spanned<String>>,
) -> Result<Option<SpecRange>> {
    let Some(r) = range else { return Ok(None) };
    if spec.params.len() != 1 {
        return src.invalid(
            r.span(),
            "claims.range",
            "a range is only accepted for a basis with exactly one parameter".into(),
        );
    }
    SpecRange::parse(r.get_ref())
        .map(Some)
        .or_else(|m| src.invalid(r.span(), "claims.range", m))
}

fn order_field(src: &Source<'_>, c: &RawClaim, order: &Spanned<i64>) -> Result<usize> {
    usize::try_from(*order.get_ref())
        .ok()
        .filter(|k| *k <= MAX_ORDER)
        .ok_or_else(|| SpecError::Invalid {
            at: src.at(order.span().start),
            field: "claims.order".into(),
            message: format!(
                "{}: expected an order from 0 to {MAX_ORDER} (claim `{}`)",
                order.get_ref(),
                c.id.get_ref()
            ),
        })
}

fn claim(src: &Source<'_>, spec: &Spec, c: RawClaim) -> Result<SpecClaim> {
    let id = c.id.get_ref().trim().to_string();
    if id.is_empty() {
        return src.invalid(c.id.span(), "claims.id", "expected a nonempty id".into());
    }
    let check = match c.check.get_ref().trim() {
        "unity" => Check::Unity,
        "nonnegative" => Check::Nonnegative {
            range: one_param_range(src, spec, &c.range)?,
            maximal: c.maximal.unwrap_or(false),
        },
        "monotone" => {
            let items = need(src, &c, &c.functions, "functions")?
                .iter()
                .map(|item| {
                    let text = item.get_ref();
                    let (name, dir) = text.trim().rsplit_once(' ').unwrap_or((text, ""));
                    let increasing = match dir {
                        "increasing" => true,
                        "decreasing" => false,
                        _ => {
                            return src.invalid(
                                item.span(),
                                "claims.functions",
                                format!(
                                    "`{text}`: expected `NAME increasing` or `NAME decreasing`"
                                ),
                            );
                        }
                    };
                    Ok(Monotone {
                        function: function_index(src, spec, item, name)?,
                        increasing,
                    })
                })
                .collect::<Result<Vec<_>>>()?;
            Check::Monotone {
                items,
                range: one_param_range(src, spec, &c.range)?,
            }
        }
        "symmetry" => {
            let map = need(src, &c, &c.map, "map")?;
            let in_var = Spec {
                variable: Variable::Polynomial,
                ..spec.clone()
            };
            let value = in_var
                .parse_formula(map.get_ref(), &[])
                .map_err(|e| src.formula_error(map, e))?;
            let constant = value.clone() + &Sym::var("t");
            if value.diff("t").is_zero()
                || !constant.diff("t").is_zero()
                || constant.variables().iter().any(|v| v != "pi")
            {
                return src.invalid(map.span(), "claims.map", format!("`{}`: expected a reflection `A - {}` with a constant A (e.g. 1 - u, pi/2 - t)", map.get_ref(), spec.var_name));
            }
            let index = need(src, &c, &c.index, "index")?;
            let compact: String = index
                .get_ref()
                .chars()
                .filter(|ch| !ch.is_whitespace())
                .collect();
            let offset = compact
                .strip_suffix("-i")
                .and_then(|a| a.parse::<i64>().ok())
                .ok_or_else(|| SpecError::Invalid {
                    at: src.at(index.span().start),
                    field: "claims.index".into(),
                    message: format!("`{}`: expected `N - i` with an integer N", index.get_ref()),
                })?;
            let mut at = Vec::new();
            for p in &spec.params {
                let value = match c.at.as_ref().and_then(|m| m.get(&p.name)) {
                    Some(v) => parse_exact(v.get_ref()).map_err(|e| SpecError::Invalid {
                        at: src.at(v.span().start),
                        field: "claims.at".into(),
                        message: e.to_string(),
                    })?,
                    None => p.range.interior_point(),
                };
                at.push(value);
            }
            Check::Symmetry {
                map_text: map.get_ref().trim().to_string(),
                map: value,
                index_text: index.get_ref().trim().to_string(),
                offset,
                at,
            }
        }
        "endpoint-values" => Check::EndpointValues {
            end: end_field(src, need(src, &c, &c.end, "end")?)?,
            values: printed(src, spec, need(src, &c, &c.values, "values")?)?,
        },
        "endpoint-derivatives" => Check::EndpointDerivatives {
            end: end_field(src, need(src, &c, &c.end, "end")?)?,
            order: order_field(src, &c, need(src, &c, &c.order, "order")?)?,
            wrt: wrt_field(src, spec, c.wrt.as_ref())?,
            values: printed(src, spec, need(src, &c, &c.values, "values")?)?,
        },
        "join" => {
            let kind = need(src, &c, &c.join, "join")?;
            let order = match kind.get_ref().trim() {
                "C0" => 0,
                "C1" => 1,
                "C2" => 2,
                "C3" => 3,
                other => {
                    return src.invalid(
                        kind.span(),
                        "claims.join",
                        format!("`{other}`: expected C0, C1, C2 or C3"),
                    );
                }
            };
            let n = spec.functions.len();
            let extra: Vec<String> = (0..n)
                .flat_map(|i| [format!("P{i}"), format!("Q{i}")])
                .collect();
            let conditions = need(src, &c, &c.conditions, "conditions")?
                .iter()
                .map(|item| {
                    let text = item.get_ref();
                    let Some((lhs, rhs)) = text.split_once('=') else {
                        return src.invalid(item.span(), "claims.conditions", format!("`{text}`: expected `Qk = formula in P0…P{}, Q0…`", n - 1));
                    };
                    let point = lhs.trim().strip_prefix('Q').and_then(|k| k.parse::<usize>().ok()).filter(|k| *k < n);
                    let Some(point) = point else {
                        return src.invalid(item.span(), "claims.conditions", format!("`{}`: expected a control point Q0…Q{} of the second segment on the left", lhs.trim(), n - 1));
                    };
                    let value = spec.parse_formula(rhs, &extra).map_err(|mut e| {
                        e.position += lhs.chars().count() + 1;
                        src.formula_error(item, e)
                    })?;
                    Ok(Condition { point, text: text.trim().to_string(), value })
                })
                .collect::<Result<Vec<_>>>()?;
            Check::Join {
                order,
                wrt: wrt_field(src, spec, c.wrt.as_ref())?,
                conditions,
            }
        }
        "continuity" => {
            if spec.functions.len() != 4 {
                return src.invalid(c.check.span(), "claims.check", "continuity at knots needs four segment functions (piece k of the B-spline is function 3 − k)".into());
            }
            Check::Continuity {
                order: order_field(src, &c, need(src, &c, &c.order, "order")?)?,
            }
        }
        other => {
            return src.invalid(
                c.check.span(),
                "claims.check",
                format!("`{other}`: expected unity, nonnegative, monotone, symmetry, endpoint-values, endpoint-derivatives, join or continuity"),
            );
        }
    };
    Ok(SpecClaim {
        id,
        source: c.source,
        statement: c.statement,
        check,
    })
}

fn end_field(src: &Source<'_>, end: &Spanned<String>) -> Result<End> {
    match end.get_ref().trim() {
        "start" | "0" => Ok(End::Start),
        "end" | "1" => Ok(End::End),
        other => src.invalid(
            end.span(),
            "claims.end",
            format!("`{other}`: expected `start` or `end`"),
        ),
    }
}

fn wrt_field(src: &Source<'_>, spec: &Spec, wrt: Option<&Spanned<String>>) -> Result<Wrt> {
    let Some(w) = wrt else { return Ok(Wrt::Angle) };
    match (w.get_ref().trim(), spec.variable) {
        ("angle" | "theta" | "θ", _) => Ok(Wrt::Angle),
        ("u", Variable::UnitAngle) => Ok(Wrt::U),
        ("t", Variable::Polynomial | Variable::Angle) => Ok(Wrt::Angle),
        (other, _) => src.invalid(
            w.span(),
            "claims.wrt",
            format!(
                "`{other}`: expected `angle` or the basis variable `{}`",
                spec.var_name
            ),
        ),
    }
}
