//! `trig-audit eval`: every function of a family at one point, exact
//! input, certified output: f64 with a proved error bound per value, or the
//! proved digits of interval arithmetic at a chosen precision (`--prec`) or
//! to a requested number of digits (`--digits`).

use std::fmt::Write;

use clap::Args;
use rug::Rational;
use serde_json::json;
use trig_core::certified::{
    self, CheckedF64, F64_CHECK_DIGITS, MAX_BITS, MAX_DIGITS, Stop, WORK_BUDGET, at_bits,
    check_domain, check_f64, to_digits, to_significant_digits,
};
use trig_core::decimal::max_digits;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::knots::check_increasing;
use trig_core::{
    Affine, Basis, CoreError, Described, Family, Interval, Real, SEED000_NONUNIFORM, echo,
    parse_exact, parse_point, piecewise,
};
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use super::{CliError, CmdResult, range_hint};
use crate::digits;
use crate::format::{TextOrJson, json};

mod points;

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

/// What `eval` computes, for any scalar built from the exact inputs: the
/// functions of a basis at a point, the uniform B-spline basis function on
/// one of its pieces, or seed 000's non-uniform segment functions on one
/// span. Points, pieces and spans are located on the exact input.
enum Problem {
    Basis {
        subject: AnyBasis,
        /// The point: a rational or a rational multiple of π.
        x: Affine,
        /// Each a rational or a rational multiple of π.
        params: Vec<Affine>,
    },
    Piecewise {
        family: Family,
        piece: usize,
        local: Rational,
        params: Vec<Affine>,
    },
    NonUniform {
        knots: Vec<Rational>,
        span: usize,
        local: Rational,
        zeta: Rational,
    },
}

impl Problem {
    /// The exact inputs with their names (checked to fit f64 in f64 mode).
    fn inputs<'a>(&'a self, names: &[String], at: &str) -> Vec<(String, &'a Rational)> {
        let named = |params: &'a [Affine]| -> Vec<(String, &'a Rational)> {
            names
                .iter()
                .zip(params)
                .flat_map(|(n, p)| [(n.clone(), &p.constant), (n.clone(), &p.pi)])
                .collect()
        };
        match self {
            Problem::Basis { x, params, .. } => {
                let mut v = named(params);
                v.push((format!("the point {}", echo(at)), &x.constant));
                v.push((format!("the point {}", echo(at)), &x.pi));
                v
            }
            Problem::Piecewise { params, .. } => named(params),
            Problem::NonUniform { knots, zeta, .. } => knots
                .iter()
                .enumerate()
                .map(|(i, k)| (format!("knot n_{i}"), k))
                .chain([("zeta".to_string(), zeta)])
                .collect(),
        }
    }

    /// The values in the scalar `make` builds from exact rationals.
    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>, CoreError> {
        match self {
            Problem::Basis { subject, x, params } => {
                let zero = make(&Rational::new());
                let x = x.eval(&zero, &[]);
                let p: Vec<T> = params.iter().map(|a| a.eval(&zero, &[])).collect();
                Ok(subject.eval(&subject.domain().atoms(&x), &p))
            }
            Problem::Piecewise {
                family,
                piece,
                local,
                params,
            } => {
                let local = make(local);
                let x = local.clone() * &family.info().variable.end(&local);
                let p: Vec<T> = params.iter().map(|a| a.eval(&local, &[])).collect();
                let values = family.eval(&family.info().variable.atoms(&x), &p);
                Ok(vec![values[piecewise::segment_function(*piece)].clone()])
            }
            Problem::NonUniform {
                knots,
                span,
                local,
                zeta,
            } => {
                let local = make(local);
                let theta = local.clone() * &SEED000_NONUNIFORM.variable.end(&local);
                let (s, c) = theta.sin_cos();
                let formulas = NonUniform::new(knots.iter().map(make).collect(), make(zeta));
                Ok(formulas.segment(*span as i64, &s, &c)?.to_vec())
            }
        }
    }
}

/// The arithmetic of an evaluation.
#[derive(Debug, Clone, Copy)]
pub enum Mode {
    /// f64, each value with a certified error bound (or replaced by the
    /// certified value when f64 is off).
    F64,
    /// Intervals at a fixed precision: the digits that precision proves.
    Bits(u32),
    /// Intervals at increasing precision until this many digits are proved.
    Digits(usize),
}

impl Mode {
    fn of(args: &EvalArgs) -> Result<Mode, CliError> {
        precision_mode(args.prec, args.digits)
    }

    /// The arithmetic as the header states it; `short` values (of `total`)
    /// have fewer digits than `--digits` asked.
    fn describe(&self, bits: u32, (short, total): (usize, usize), stopped: Option<Stop>) -> String {
        match *self {
            Mode::F64 => format!("f64; ± certified error bounds, enclosures at {bits} bits"),
            Mode::Bits(b) => format!("mpfr-{b}, certified: only proved digits are printed"),
            Mode::Digits(n) if short == 0 => {
                format!("{n} significant digits, all proved; mpfr-{bits}")
            }
            Mode::Digits(n) => format!(
                "{n} significant digits requested, proved for {} of {total} values{}; the others are marked",
                total - short,
                shortfall(bits, stopped)
            ),
        }
    }
}

/// Why fewer digits than requested are proved.
pub fn shortfall(bits: u32, stopped: Option<Stop>) -> String {
    match stopped {
        Some(Stop::Budget) => {
            format!(" within the work budget of {WORK_BUDGET} units (at {bits} bits)")
        }
        _ => format!(" at the {bits}-bit limit"),
    }
}

/// `--prec` and `--digits` as a [`Mode`], checked against the limits.
pub fn precision_mode(prec: Option<u32>, digits: Option<usize>) -> Result<Mode, CliError> {
    match (prec, digits) {
        (Some(_), Some(_)) => Err(CliError::Usage(
            "--prec and --digits exclude each other: --digits raises the precision itself".into(),
        )),
        (Some(bits), None) if (2..=MAX_BITS).contains(&bits) => Ok(Mode::Bits(bits)),
        (Some(bits), None) => Err(CliError::Usage(format!(
            "--prec {bits}: expected a precision from 2 to {MAX_BITS} bits"
        ))),
        (None, Some(n)) if (1..=MAX_DIGITS).contains(&n) => Ok(Mode::Digits(n)),
        (None, Some(n)) => Err(CliError::Usage(format!(
            "--digits {n}: expected 1 to {MAX_DIGITS} significant digits"
        ))),
        (None, None) => Ok(Mode::F64),
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
    let mode = Mode::of(args)?;
    let at_text = args.at.as_deref().unwrap_or_default();
    let at = parse_point(at_text)?;
    let eval = evaluate(args, at_text, &at, mode, subject_of(args)?.as_ref())?;
    Ok(render(args, &eval))
}

/// `eval --at-file`: the rows written to `out` as they are computed.
pub fn stream(args: &EvalArgs, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let mode = Mode::of(args)?;
    let path = args.at_file.as_deref().unwrap_or(std::path::Path::new("-"));
    points::stream(args, path, mode, out)
}

/// True when the command streams its output (`--at-file`).
pub fn streams(args: &EvalArgs) -> bool {
    args.at_file.is_some()
}

/// The problem `eval` was asked, located on the exact input, with its
/// description.
struct Setup {
    problem: Problem,
    id: String,
    citation: String,
    param_names: Vec<String>,
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

fn setup(
    args: &EvalArgs,
    at_text: &str,
    at: &Affine,
    subject: Option<&AnyBasis>,
) -> Result<Setup, CliError> {
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
    let subject = subject.clone();
    let params = subject
        .params_from_pairs(&pairs, args.allow_outside_range)
        .map_err(range_hint)?;
    let (id, citation, param_names) = (subject.id(), subject.citation(), subject.param_names());
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
        let (piece, local) = locate_exact(&uniform_knots(), rational_point(at, at_text)?, at_text)?;
        return Ok(Setup {
            problem: Problem::Piecewise {
                family,
                piece,
                local,
                params,
            },
            id,
            citation,
            param_names,
            names: vec!["B(n)".into()],
            note: Some("uniform B-spline basis function on knots 0,1,2,3,4".into()),
        });
    }
    if !args.allow_outside_range {
        check_domain(&subject.domain(), at, &params, at_text).map_err(range_hint)?;
    }
    let names = subject.function_names();
    Ok(Setup {
        problem: Problem::Basis {
            subject,
            x: at.clone(),
            params,
        },
        id,
        citation,
        param_names,
        names,
        note: None,
    })
}

/// The point as a rational, for the knot-based evaluations (their knots
/// are rational; a multiple of π is an angle).
fn rational_point<'a>(at: &'a Affine, at_text: &str) -> Result<&'a Rational, CliError> {
    at.as_rational().ok_or_else(|| {
        CliError::Usage(format!(
            "`{}`: --piecewise and --knots take a rational point (a multiple of pi is an angle)",
            echo(at_text)
        ))
    })
}

fn evaluate(
    args: &EvalArgs,
    at_text: &str,
    at: &Affine,
    mode: Mode,
    subject: Option<&AnyBasis>,
) -> Result<Evaluation, CliError> {
    let s = setup(args, at_text, at, subject)?;
    let what = format!("`{}` at this point", s.id);
    let enclose = |bits: u32| {
        s.problem
            .compute(&|q: &Rational| Interval::from_rational(bits, q))
    };
    let (values, bits, short, stopped) = match mode {
        Mode::F64 => {
            for (name, q) in s.problem.inputs(&s.param_names, at_text) {
                certified::to_f64(q, &name).map_err(|e| {
                    CliError::Usage(format!("{e} (evaluate with --digits N or --prec BITS)"))
                })?;
            }
            let exact = to_digits(F64_CHECK_DIGITS, &what, enclose)?;
            // f64 failures (a rounded divisor that is exactly zero) leave
            // the certified values in place
            let f64_values = s
                .problem
                .compute(&|q: &Rational| q.to_f64())
                .unwrap_or_else(|_| vec![f64::NAN; exact.values.len()]);
            let shown = check_f64(&f64_values, &exact.values)
                .into_iter()
                .map(|c| match c {
                    CheckedF64::Accurate { text, bound } => Shown {
                        text,
                        bound: Some(bound),
                        note: None,
                        digits: None,
                    },
                    CheckedF64::Replaced { decimal, f64_error } => Shown {
                        digits: Some(decimal.digits()),
                        text: decimal.to_string(),
                        bound: None,
                        note: Some(match f64_error {
                            Some(e) => {
                                format!("certified value; the f64 result is off by up to {e}")
                            }
                            None => "certified value; the f64 result is not finite".into(),
                        }),
                    },
                })
                .collect();
            (shown, exact.bits, (0, 0), None)
        }
        Mode::Bits(bits) => {
            let mut f = enclose;
            let e = at_bits(bits, &what, &mut f)?;
            let max = max_digits(bits);
            (decimals(&e.values, max), bits, (0, 0), None)
        }
        Mode::Digits(n) => {
            let e = to_significant_digits(n, &what, enclose)?;
            let mut shown = decimals(&e.values, n);
            let proved: Vec<_> = e.values.iter().map(|x| x.decimal(n)).collect();
            for (v, d) in shown.iter_mut().zip(&proved) {
                v.note = digits::note(d, n);
            }
            let short = (digits::short(&proved, n), proved.len());
            (shown, e.bits, short, e.stopped)
        }
    };
    Ok(Evaluation {
        id: s.id,
        citation: s.citation,
        names: s.names,
        values,
        precision: mode.describe(bits, short, stopped),
        note: s.note,
        bits,
    })
}

/// The proved decimals of enclosures, at most `max` digits each.
fn decimals(values: &[Interval], max: usize) -> Vec<Shown> {
    values
        .iter()
        .map(|v| {
            let d = v.decimal(max);
            Shown {
                digits: Some(d.digits()),
                text: d.to_string(),
                bound: None,
                note: None,
            }
        })
        .collect()
}

/// Knots `0, 1, 2, 3, 4` of the uniform B-spline basis function.
fn uniform_knots() -> Vec<Rational> {
    (0..=piecewise::PIECES as i64).map(Rational::from).collect()
}

/// The span `i` with `knots[i] ≤ x < knots[i+1]` (the last span closed)
/// and the exact local coordinate, for strictly increasing exact knots.
fn locate_exact(
    knots: &[Rational],
    x: &Rational,
    input: &str,
) -> Result<(usize, Rational), CoreError> {
    let last = knots.len() - 1;
    if *x < knots[0] || *x > knots[last] {
        return Err(CoreError::PointOutsideDomain {
            value: echo(input),
            domain: format!("[{}, {}]", knots[0], knots[last]),
        });
    }
    let i = knots[1..last].iter().take_while(|k| *k <= x).count();
    let local = Rational::from(x - &knots[i]) / Rational::from(&knots[i + 1] - &knots[i]);
    Ok((i, local))
}

fn nonuniform(
    args: &EvalArgs,
    pairs: &[(String, String)],
    at_text: &str,
    n: &Rational,
) -> Result<Setup, CliError> {
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
    let (span, local) = locate_exact(&knots, n, at_text)?;
    // The printed coefficients exactly first: a denominator that vanishes
    // is named (a division by zero), one that does not is then proved
    // nonzero by enclosures at a high enough precision.
    let sym = |q: &Rational| Sym::rational(q.clone());
    NonUniform::new(knots.iter().map(sym).collect(), sym(&zeta)).span(span as i64)?;
    let note = format!("span j = {span}, local angle t_j = ({local})·π/2");
    Ok(Setup {
        problem: Problem::NonUniform {
            knots,
            span,
            local,
            zeta,
        },
        id: info.id.to_string(),
        citation: info.citation.to_string(),
        param_names: info.params.iter().map(|p| p.name.to_string()).collect(),
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
