//! `trig-audit eval`: every function of a family at one point, exact
//! input, certified output: f64 with a proved error bound per value, or the
//! proved digits of interval arithmetic at a chosen precision (`--prec`) or
//! to a requested number of digits (`--digits`).

use std::fmt::Write;

use clap::Args;
use rug::Rational;
use serde_json::json;
use trig_core::certified::{CheckedF64, MAX_BITS, MAX_DIGITS, Stop};
use trig_core::evaluation::{self, Arithmetic, BasisAt, Computation, Value};
use trig_core::families::seed000_nonuniform::{NonUniform, SpanAt};
use trig_core::knots::{check_increasing, locate_exact};
use trig_core::piecewise::UniformAt;
use trig_core::{
    Affine, CoreError, Described, Family, Real, SEED000_NONUNIFORM, echo, parse_exact, parse_point,
};
use trig_judge::exact::{ExactBasis, at_atoms};
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use super::{CliError, CmdResult, param_pairs, range_hint};
use crate::digits;
use crate::format::{TextOrJson, json};

mod points;
mod surface;

/// Most knots `--knots` takes (the cost model).
const MAX_KNOTS: usize = 10_000;

#[derive(Debug, Args)]
pub struct EvalArgs {
    /// Family id (see `trig-audit list`).
    #[arg(required_unless_present = "spec", conflicts_with = "spec")]
    family: Option<String>,
    /// A spec file (TOML) defining the basis instead of a catalog family (docs/spec.md).
    #[arg(long, value_name = "FILE")]
    spec: Option<std::path::PathBuf>,
    /// Shape parameter as name=value, read exactly: 0.6 = 3/5, or a rational
    /// multiple of pi such as alpha=pi/2 (range checks proved).
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
    /// starting with `#` are skipped. Each value is certified as for --at.
    #[arg(long, value_name = "FILE")]
    at_file: Option<std::path::PathBuf>,
    /// Evaluate in certified MPFR interval arithmetic at this many bits
    /// (2 to 65536) instead of f64; only proved digits are printed.
    #[arg(long)]
    prec: Option<u32>,
    /// Print this many significant digits (1 to 10000), every one proved:
    /// the working precision is raised until they are (or the output says
    /// how many are).
    #[arg(long)]
    digits: Option<usize>,
    /// Evaluate the uniform B-spline basis function over knots 0,1,2,3,4.
    #[arg(long)]
    piecewise: bool,
    /// Knot vector for seed000-nonuniform, comma separated; with --surface
    /// the u knot vector of a spline surface over knot vectors (seed 004
    /// (5), docs/surfaces.md).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    knots: Vec<String>,
    /// With --surface and --knots: the v knot vector, comma separated.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "knots"
    )]
    v_knots: Vec<String>,
    /// Evaluate outside the published parameter range or the domain.
    #[arg(long)]
    allow_outside_range: bool,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    format: TextOrJson,
    #[command(flatten)]
    pub surface: super::surface::SurfaceArgs,
    /// With --surface: the control net, one point `x y z [w]` per line,
    /// net rows separated by blank lines (docs/surfaces.md).
    #[arg(long, value_name = "FILE", requires = "surface")]
    net: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

/// What `eval` computes: the functions of a basis at a point, the uniform
/// B-spline basis function on one of its pieces, or seed 000's non-uniform
/// segment functions on one span — each a library [`Computation`].
enum Problem<'a> {
    Basis(BasisAt<'a, AnyBasis>),
    Piecewise(UniformAt),
    NonUniform(SpanAt),
}

impl Computation for Problem<'_> {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        match self {
            Problem::Basis(p) => p.inputs(),
            Problem::Piecewise(p) => p.inputs(),
            Problem::NonUniform(p) => p.inputs(),
        }
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>, CoreError> {
        match self {
            Problem::Basis(p) => p.compute(make),
            Problem::Piecewise(p) => p.compute(make),
            Problem::NonUniform(p) => p.compute(make),
        }
    }
}

/// The arithmetic as the header states it; `short` values (of `total`)
/// have fewer digits than `--digits` asked.
fn describe(
    arithmetic: Arithmetic,
    bits: u32,
    (short, total): (usize, usize),
    stopped: Option<Stop>,
) -> String {
    match arithmetic {
        Arithmetic::F64 => format!("f64; ± certified error bounds, enclosures at {bits} bits"),
        Arithmetic::Bits(b) => format!("mpfr-{b}, certified: only proved digits are printed"),
        Arithmetic::Digits(n) if short == 0 => {
            format!("{n} significant digits, all proved; mpfr-{bits}")
        }
        Arithmetic::Digits(n) => format!(
            "{n} significant digits requested, proved for {} of {total} values{}; the others are marked",
            total - short,
            digits::shortfall(bits, stopped)
        ),
    }
}

/// `--prec` and `--digits` as an [`Arithmetic`], checked against the limits.
pub fn arithmetic_of(prec: Option<u32>, digits: Option<usize>) -> Result<Arithmetic, CliError> {
    match (prec, digits) {
        (Some(_), Some(_)) => Err(CliError::Usage(
            "--prec and --digits exclude each other: --digits raises the precision itself".into(),
        )),
        (Some(bits), None) if (2..=MAX_BITS).contains(&bits) => Ok(Arithmetic::Bits(bits)),
        (Some(bits), None) => Err(CliError::Usage(format!(
            "--prec {bits}: expected a precision from 2 to {MAX_BITS} bits"
        ))),
        (None, Some(n)) if (1..=MAX_DIGITS).contains(&n) => Ok(Arithmetic::Digits(n)),
        (None, Some(n)) => Err(CliError::Usage(format!(
            "--digits {n}: expected 1 to {MAX_DIGITS} significant digits"
        ))),
        (None, None) => Ok(Arithmetic::F64),
    }
}

/// One printed value.
struct Shown {
    text: String,
    /// Proved bound of |printed − exact| (f64 mode).
    bound: Option<String>,
    /// Why the f64 result was replaced.
    note: Option<String>,
    /// Proved significant digits (`None`: exact).
    digits: Option<usize>,
}

/// What was evaluated: names and values as text.
struct Evaluation {
    id: String,
    citation: String,
    names: Vec<String>,
    values: Vec<Shown>,
    precision: String,
    note: Option<String>,
    /// The working precision of the last step, in bits.
    bits: u32,
}

pub fn run(args: &EvalArgs) -> CmdResult {
    args.surface.check()?;
    let arithmetic = arithmetic_of(args.prec, args.digits)?;
    if args.surface.surface {
        return surface::run(args, arithmetic);
    }
    let at_text = args.at.as_deref().unwrap_or_default();
    let at = parse_point(at_text)?;
    let eval = evaluate(args, at_text, &at, arithmetic, subject_of(args)?.as_ref())?;
    Ok(render(args, &eval))
}

/// `eval --at-file`: the rows written to `out` as they are computed.
pub fn stream(args: &EvalArgs, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let arithmetic = arithmetic_of(args.prec, args.digits)?;
    let path = args.at_file.as_deref().unwrap_or(std::path::Path::new("-"));
    points::stream(args, path, arithmetic, out)
}

/// True when the command streams its output (`--at-file`).
pub fn streams(args: &EvalArgs) -> bool {
    args.at_file.is_some() && !args.surface.surface
}

/// The problem `eval` was asked, located on the exact input, with its
/// description.
struct Setup<'a> {
    problem: Problem<'a>,
    /// Which functions are exactly zero (decided in the exact ring).
    zeros: Vec<Zero>,
    id: String,
    citation: String,
    names: Vec<String>,
    note: Option<String>,
}

/// The basis `eval` works on, read once (also for many points); `None` for
/// seed 000's non-uniform construction, which is built per knot vector.
fn subject_of(args: &EvalArgs) -> Result<Option<AnyBasis>, CliError> {
    if args.family.as_deref() == Some(SEED000_NONUNIFORM.id) && args.spec.is_none() {
        return Ok(None);
    }
    Ok(Some(AnyBasis::open(
        args.family.as_deref(),
        args.spec.as_deref(),
    )?))
}

fn setup<'a>(
    args: &EvalArgs,
    at_text: &str,
    at: &Affine,
    subject: Option<&'a AnyBasis>,
) -> Result<Setup<'a>, CliError> {
    let pairs = param_pairs(&args.params)?;
    let Some(subject) = subject else {
        return nonuniform(args, &pairs, at_text, rational_point(at, at_text)?);
    };
    if !args.knots.is_empty() {
        return Err(CliError::Usage(format!(
            "--knots applies to {} only",
            SEED000_NONUNIFORM.id
        )));
    }
    let (id, citation) = (subject.id(), subject.citation());
    if args.piecewise {
        let AnyBasis::Family(family) = subject else {
            return Err(CliError::Usage(
                "--piecewise applies to catalog families only".into(),
            ));
        };
        if !family.info().piecewise {
            return Err(CliError::Usage(format!(
                "--piecewise needs a family with uniform B-spline segment functions (seed000-uniform, bspline3); `{id}` is not one"
            )));
        }
        let params = subject
            .params_from_pairs(&pairs, args.allow_outside_range)
            .map_err(range_hint)?;
        let piece = UniformAt::new(*family, rational_point(at, at_text)?, at_text, params)?;
        return Ok(Setup {
            zeros: Vec::new(),
            problem: Problem::Piecewise(piece),
            id,
            citation,
            names: vec!["B(n)".into()],
            note: Some("uniform B-spline basis function on knots 0,1,2,3,4".into()),
        });
    }
    let basis_at = BasisAt::new(
        subject,
        at.clone(),
        at_text,
        &pairs,
        args.allow_outside_range,
    )
    .map_err(range_hint)?;
    let zeros = exact_zeros(subject, basis_at.params(), at);
    let basis_at = basis_at.with_zeros(zeros.iter().map(|z| *z != Zero::No).collect());
    Ok(Setup {
        zeros,
        problem: Problem::Basis(basis_at),
        id,
        citation,
        names: subject.function_names(),
        note: None,
    })
}

/// Whether a function is exactly zero, decided in the exact ring.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Zero {
    No,
    /// Identically, at the parameter values.
    Identically,
    /// At the point (its atoms exact: a rational, a multiple of π/12):
    /// computed as an exact 0, printed as any exact value.
    AtPoint,
}

/// Which functions of `basis` are exactly zero, decided first in the exact
/// ring (the basis specialised at the parameter values `params`, then at
/// the point `x` when its atoms are exact): those print as an exact `0`
/// instead of an enclosure of zero that no precision decides.
fn exact_zeros(basis: &AnyBasis, params: &[Affine], x: &Affine) -> Vec<Zero> {
    let values: Vec<Sym> = params.iter().map(|a| a.eval(&Sym::zero(), &[])).collect();
    let atoms = basis.domain().atoms_at(x, &Sym::one(), &values);
    basis
        .exact_functions_at(&values)
        .iter()
        .map(|f| match (f, &atoms) {
            (Some(f), _) if f.is_zero() => Zero::Identically,
            (Some(f), Some(a)) => {
                if at_atoms(f, a).is_zero() {
                    Zero::AtPoint
                } else {
                    Zero::No
                }
            }
            _ => Zero::No,
        })
        .collect()
}

/// The point as a rational, for the knot-based evaluations (their knots
/// are rational; a multiple of π is an angle).
pub(crate) fn rational_point<'a>(at: &'a Affine, at_text: &str) -> Result<&'a Rational, CliError> {
    at.as_rational().ok_or_else(|| {
        CliError::Usage(format!(
            "`{}`: --piecewise and --knots take a rational point (a multiple of pi is an angle)",
            echo(at_text)
        ))
    })
}

/// The certified values of what `eval` was asked (the library's one
/// evaluation path), as text.
fn evaluate(
    args: &EvalArgs,
    at_text: &str,
    at: &Affine,
    arithmetic: Arithmetic,
    subject: Option<&AnyBasis>,
) -> Result<Evaluation, CliError> {
    let s = setup(args, at_text, at, subject)?;
    let what = format!("`{}` at this point", s.id);
    let e = evaluation::evaluate(&s.problem, arithmetic, &what).map_err(|e| match e {
        CoreError::NotRepresentable { .. } => {
            CliError::Usage(format!("{e} (evaluate with --digits N or --prec BITS)"))
        }
        e => e.into(),
    })?;
    let values: Vec<Shown> = e
        .values
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let note = match s.zeros.get(i) {
                Some(Zero::Identically) => {
                    "exact: identically 0 at these parameter values, decided in the exact ring"
                }
                _ => return shown(v, arithmetic),
            };
            Shown {
                text: "0".into(),
                bound: None,
                note: Some(note.into()),
                digits: None,
            }
        })
        .collect();
    let short = match arithmetic {
        Arithmetic::Digits(n) => (e.short_of(n), e.values.len()),
        _ => (0, 0),
    };
    Ok(Evaluation {
        id: s.id,
        citation: s.citation,
        names: s.names,
        values,
        precision: describe(arithmetic, e.bits, short, e.stopped),
        note: s.note,
        bits: e.bits,
    })
}

/// One certified value as printed.
fn shown(value: &Value, arithmetic: Arithmetic) -> Shown {
    match value {
        Value::F64(CheckedF64::Accurate { text, bound }) => Shown {
            text: text.clone(),
            bound: Some(bound.clone()),
            note: None,
            digits: None,
        },
        Value::F64(CheckedF64::Replaced { decimal, f64_error }) => Shown {
            digits: Some(decimal.digits()),
            text: decimal.to_string(),
            bound: None,
            note: Some(match f64_error {
                Some(e) => format!("certified value; the f64 result is off by up to {e}"),
                None => "certified value; the f64 result is not finite".into(),
            }),
        },
        Value::Proved(d) => Shown {
            digits: Some(d.digits()),
            text: d.to_string(),
            bound: None,
            note: match arithmetic {
                Arithmetic::Digits(n) => digits::note(d, n),
                _ => None,
            },
        },
    }
}

fn nonuniform<'a>(
    args: &EvalArgs,
    pairs: &[(String, String)],
    at_text: &str,
    n: &Rational,
) -> Result<Setup<'a>, CliError> {
    let info = SEED000_NONUNIFORM;
    let zeta = Family::Seed000Uniform
        .params_from_pairs(pairs, args.allow_outside_range)
        .map_err(range_hint)?;
    // the printed coefficients are checked exactly in ζ: a rational
    let zeta = zeta[0].as_rational().cloned().ok_or_else(|| {
        CliError::Usage(format!(
            "{}: zeta must be rational (the span's denominators are decided exactly in ζ)",
            info.id
        ))
    })?;
    if args.knots.len() > MAX_KNOTS {
        return Err(CoreError::Limit {
            what: format!("--knots with {} knots", args.knots.len()),
            limit: format!("{MAX_KNOTS} knots"),
        }
        .into());
    }
    let knots: Vec<Rational> = args
        .knots
        .iter()
        .map(|k| parse_exact(k))
        .collect::<Result<_, CoreError>>()?;
    check_increasing(&knots, 2, |i| echo(&args.knots[i]))?;
    let (span, local) = locate_exact(&knots, n, &echo(at_text))?;
    // The printed coefficients exactly first: a denominator that vanishes
    // is named (a division by zero), one that does not is then proved
    // nonzero by enclosures at a high enough precision.
    let sym = |q: &Rational| Sym::rational(q.clone());
    NonUniform::new(knots.iter().map(sym).collect(), sym(&zeta)).span(span as i64)?;
    let note = format!("span j = {span}, local angle t_j = ({local})·π/2");
    Ok(Setup {
        zeros: Vec::new(),
        problem: Problem::NonUniform(SpanAt {
            knots,
            span,
            local,
            zeta,
        }),
        id: info.id.to_string(),
        citation: info.citation.to_string(),
        names: info.functions.iter().map(|s| s.to_string()).collect(),
        note: Some(note),
    })
}

fn render(args: &EvalArgs, e: &Evaluation) -> String {
    // the parameters as typed (validated by now)
    let params = param_pairs(&args.params).unwrap_or_default();
    match args.format {
        TextOrJson::Json => {
            let map = |f: &dyn Fn(&Shown) -> serde_json::Value| -> serde_json::Map<_, _> {
                e.names
                    .iter()
                    .zip(&e.values)
                    .map(|(n, v)| (n.clone(), f(v)))
                    .collect()
            };
            json(&json!({
                "family": e.id,
                "citation": e.citation,
                "params": params.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "at": args.at.as_deref().unwrap_or_default(),
                "precision": e.precision,
                "note": e.note,
                "values": map(&|v| json!(v.text)),
                "error_bounds": map(&|v| json!(v.bound)),
                "proved_digits": map(&|v| json!(v.digits.filter(|d| *d != usize::MAX))),
                "notes": map(&|v| json!(v.note)),
            }))
        }
        TextOrJson::Text => {
            let mut out = String::new();
            let shown: Vec<String> = params.iter().map(|(n, v)| format!("{n}={v}")).collect();
            let _ = writeln!(
                out,
                "{} at {} [{}] ({}){}",
                e.id,
                args.at.as_deref().unwrap_or_default(),
                shown.join(", "),
                e.precision,
                e.note.as_ref().map_or(String::new(), |n| format!("; {n}"))
            );
            for (n, v) in e.names.iter().zip(&e.values) {
                let bound = v
                    .bound
                    .as_ref()
                    .map_or(String::new(), |b| format!(" ± {b}"));
                let note = v.note.as_ref().map_or(String::new(), |b| format!(" ({b})"));
                let _ = writeln!(out, "{n} = {}{bound}{note}", v.text);
            }
            out
        }
    }
}
