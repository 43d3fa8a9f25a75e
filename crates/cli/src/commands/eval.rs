//! `trig-audit eval`: every function of a family at one point, in f64 or in
//! MPFR at a chosen precision.

use std::fmt::{Display, Write};

use clap::Args;
use rug::Rational;
use serde_json::json;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::knots::{check_knots, locate};
use trig_core::{
    Atoms, Basis, CoreError, Domain, Family, Mpfr, Real, Ring, SEED000_NONUNIFORM, parse_exact,
    piecewise,
};
use trig_spec::Spec;

use super::{CliError, CmdResult};
use crate::format::{TextOrJson, json};

mod points;

/// Largest precision accepted (MPFR allows more; this keeps output sane).
const MAX_PREC: u32 = 1 << 16;

#[derive(Debug, Args)]
pub struct EvalArgs {
    /// Family id (see `trig-audit list`).
    #[arg(required_unless_present = "spec", conflicts_with = "spec")]
    family: Option<String>,
    /// A spec file (TOML) defining the basis instead of a catalog family (docs/spec.md).
    #[arg(long, value_name = "FILE")]
    spec: Option<std::path::PathBuf>,
    /// Shape parameter as name=value (decimals are read exactly: 0.6 = 3/5).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Point in the family's native variable (with --piecewise or --knots: the
    /// global knot parameter).
    #[arg(
        long,
        allow_hyphen_values = true,
        required_unless_present = "at_file",
        conflicts_with = "at_file"
    )]
    at: Option<String>,
    /// Evaluate at every point listed in FILE instead (`-`: standard input):
    /// one number per line, read exactly like --at; blank lines and lines
    /// starting with `#` are skipped. All points go through one batch.
    #[arg(long, value_name = "FILE")]
    at_file: Option<std::path::PathBuf>,
    /// Evaluate in MPFR with this many bits instead of f64.
    #[arg(long)]
    prec: Option<u32>,
    /// Evaluate the uniform B-spline basis function over knots 0,1,2,3,4.
    #[arg(long)]
    piecewise: bool,
    /// Knot vector for seed000-nonuniform, comma separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    knots: Vec<String>,
    /// Evaluate outside the published parameter range or the domain.
    #[arg(long)]
    allow_outside_range: bool,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    format: TextOrJson,
}

/// Splits `name=value` arguments.
pub fn param_pairs(raw: &[String]) -> Result<Vec<(String, String)>, CliError> {
    raw.iter()
        .map(|p| {
            p.split_once('=')
                .map(|(n, v)| (n.trim().to_string(), v.trim().to_string()))
                .filter(|(n, v)| !n.is_empty() && !v.is_empty())
                .ok_or_else(|| CliError::Usage(format!("--param `{p}`: expected NAME=VALUE")))
        })
        .collect()
}

/// The catalog family `id`; `seed000-nonuniform`, whose segment functions
/// depend on a knot vector, is named with what it needs instead of being
/// called unknown.
pub fn family_by_id(id: &str) -> Result<Family, CliError> {
    if id == SEED000_NONUNIFORM.id {
        return Err(CliError::Usage(format!(
            "`{id}` needs a knot vector: its segment functions change from span to span, so only `trig-audit eval {id} --knots …` evaluates it; for the uniform case use seed000-uniform"
        )));
    }
    Ok(Family::from_id(id)?)
}

/// A basis to work on: a catalog family or a spec file's basis.
#[derive(Debug, Clone)]
pub enum Subject {
    Family(Family),
    Spec(Box<Spec>),
}

impl Subject {
    /// The family named by `family`, or the basis of the spec file.
    pub fn from_args(
        family: Option<&str>,
        spec: Option<&std::path::Path>,
    ) -> Result<Subject, CliError> {
        match (family, spec) {
            (_, Some(path)) => Spec::from_file(path)
                .map(|s| Subject::Spec(Box::new(s)))
                .map_err(|e| CliError::Usage(e.to_string().replace('\n', " "))),
            (Some(id), None) => {
                let family = family_by_id(id)?;
                if !family.has_formulas() {
                    return Err(CoreError::NoFormulas(id.into()).into());
                }
                Ok(Subject::Family(family))
            }
            (None, None) => Err(CliError::Usage(
                "expected a family id or --spec FILE".into(),
            )),
        }
    }

    /// The citation.
    pub fn citation(&self) -> String {
        match self {
            Subject::Family(f) => f.info().citation.to_string(),
            Subject::Spec(s) => s.citation.clone(),
        }
    }

    /// True when the uniform B-spline basis function can be assembled from
    /// it: a catalog family marked piecewise, or a spec with four segment
    /// functions (piece k is function 3 − k).
    pub fn piecewise(&self) -> bool {
        match self {
            Subject::Family(f) => f.info().piecewise,
            Subject::Spec(s) => s.function_names().len() == 4,
        }
    }

    /// Exact parameter values from `name=value` pairs.
    pub fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Vec<Rational>, CoreError> {
        match self {
            Subject::Family(f) => f.params_from_pairs(pairs, allow_outside),
            Subject::Spec(s) => s.params_from_pairs(pairs, allow_outside),
        }
    }

    /// Numeric evaluation with typed errors.
    pub fn eval_at<T: Real>(
        &self,
        x: &T,
        p: &[Rational],
        allow_outside: bool,
    ) -> Result<Vec<T>, CoreError> {
        match self {
            Subject::Family(f) => f.eval_at(x, p, allow_outside),
            Subject::Spec(s) => s.eval_at(x, p, allow_outside),
        }
    }
}

impl Basis for Subject {
    fn id(&self) -> String {
        match self {
            Subject::Family(f) => Basis::id(f),
            Subject::Spec(s) => s.id.clone(),
        }
    }

    fn domain(&self) -> Domain {
        match self {
            Subject::Family(f) => f.domain(),
            Subject::Spec(s) => s.domain.clone(),
        }
    }

    fn param_names(&self) -> Vec<String> {
        match self {
            Subject::Family(f) => f.param_names(),
            Subject::Spec(s) => s.param_names(),
        }
    }

    fn function_names(&self) -> Vec<String> {
        match self {
            Subject::Family(f) => f.function_names(),
            Subject::Spec(s) => s.function_names(),
        }
    }

    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        match self {
            Subject::Family(f) => Basis::eval(f, x, p),
            Subject::Spec(s) => Basis::eval(s.as_ref(), x, p),
        }
    }
}

/// What was evaluated: names and values as text.
struct Evaluation {
    id: String,
    citation: String,
    param_names: Vec<String>,
    params: Vec<Rational>,
    names: Vec<String>,
    values: Vec<String>,
    note: Option<String>,
}

pub fn run(args: &EvalArgs) -> CmdResult {
    if let Some(path) = &args.at_file {
        return points::run(args, path);
    }
    let at = parse_exact(args.at.as_deref().unwrap_or_default())?;
    let eval = match args.prec {
        None => evaluate(args, &at, |q| q.to_f64())?,
        Some(bits) if (2..=MAX_PREC).contains(&bits) => {
            evaluate(args, &at, |q| Mpfr::from_rational(bits, q))?
        }
        Some(bits) => {
            return Err(CliError::Usage(format!(
                "--prec {bits}: expected a precision from 2 to {MAX_PREC} bits"
            )));
        }
    };
    Ok(render(args, &eval))
}

fn evaluate<T: Real + Display>(
    args: &EvalArgs,
    at: &Rational,
    make: impl Fn(&Rational) -> T,
) -> Result<Evaluation, CliError> {
    let pairs = param_pairs(&args.params)?;
    let x = make(at);
    if args.family.as_deref() == Some(SEED000_NONUNIFORM.id) && args.spec.is_none() {
        return nonuniform(args, &pairs, &x, &make);
    }
    if !args.knots.is_empty() {
        return Err(CliError::Usage(format!(
            "--knots applies to {} only",
            SEED000_NONUNIFORM.id
        )));
    }
    let subject = Subject::from_args(args.family.as_deref(), args.spec.as_deref())?;
    let params = subject.params_from_pairs(&pairs, args.allow_outside_range)?;
    let (id, citation, param_names) = (subject.id(), subject.citation(), subject.param_names());
    if args.piecewise {
        let Subject::Family(family) = subject else {
            return Err(CliError::Usage(
                "--piecewise applies to catalog families only".into(),
            ));
        };
        let value = piecewise::eval_uniform(family, &x, &params)?;
        return Ok(Evaluation {
            id,
            citation,
            param_names,
            params,
            names: vec!["B(n)".into()],
            values: vec![value.to_string()],
            note: Some("uniform B-spline basis function on knots 0,1,2,3,4".into()),
        });
    }
    let values = subject.eval_at(&x, &params, args.allow_outside_range)?;
    Ok(Evaluation {
        id,
        citation,
        param_names,
        params,
        names: subject.function_names(),
        values: values.iter().map(|v| v.to_string()).collect(),
        note: None,
    })
}

fn nonuniform<T: Real + Display>(
    args: &EvalArgs,
    pairs: &[(String, String)],
    n: &T,
    make: &impl Fn(&Rational) -> T,
) -> Result<Evaluation, CliError> {
    let info = SEED000_NONUNIFORM;
    let zeta = Family::Seed000Uniform.params_from_pairs(pairs, args.allow_outside_range)?;
    let knots: Vec<T> = args
        .knots
        .iter()
        .map(|k| parse_exact(k).map(|q| make(&q)))
        .collect::<Result<_, CoreError>>()?;
    check_knots(&knots, 2)?;
    let (span, local) = locate(&knots, n)?;
    let theta = local * &info.variable.end(n);
    let (s, c) = theta.sin_cos();
    let formulas = NonUniform::new(knots, make(&zeta[0]));
    let values = formulas.segment(span as i64, &s, &c)?;
    if values.iter().any(|v| !v.is_finite()) {
        return Err(CoreError::DivisionByZero {
            quantity: format!("the segment functions on span {span}"),
        }
        .into());
    }
    Ok(Evaluation {
        id: info.id.to_string(),
        citation: info.citation.to_string(),
        param_names: info.params.iter().map(|p| p.name.to_string()).collect(),
        params: zeta,
        names: info.functions.iter().map(|s| s.to_string()).collect(),
        values: values.iter().map(|v| v.to_string()).collect(),
        note: Some(format!(
            "span j = {span}, local angle t_j = {}",
            theta.to_f64()
        )),
    })
}

fn render(args: &EvalArgs, e: &Evaluation) -> String {
    let precision = args.prec.map_or("f64".to_string(), |b| format!("mpfr-{b}"));
    let params: Vec<(String, String)> = e
        .param_names
        .iter()
        .zip(&e.params)
        .map(|(p, v)| (p.clone(), v.to_string()))
        .collect();
    match args.format {
        TextOrJson::Json => {
            let values: serde_json::Map<_, _> = e
                .names
                .iter()
                .zip(&e.values)
                .map(|(n, v)| (n.clone(), json!(v)))
                .collect();
            json(&json!({
                "family": e.id,
                "citation": e.citation,
                "params": params.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "at": args.at.as_deref().unwrap_or_default(),
                "precision": precision,
                "note": e.note,
                "values": values,
            }))
        }
        TextOrJson::Text => {
            let mut out = String::new();
            let shown: Vec<String> = params.iter().map(|(n, v)| format!("{n}={v}")).collect();
            let _ = writeln!(
                out,
                "{} at {} [{}] ({precision}){}",
                e.id,
                args.at.as_deref().unwrap_or_default(),
                shown.join(", "),
                e.note.as_ref().map_or(String::new(), |n| format!("; {n}"))
            );
            for (n, v) in e.names.iter().zip(&e.values) {
                let _ = writeln!(out, "{n} = {v}");
            }
            out
        }
    }
}
