//! `trig-audit table`: endpoint-derivative tables, exact (parameters as
//! symbols, π symbolic) or numeric from jets.

use clap::{Args, ValueEnum};
use rug::Rational;
use trig_core::certified::CheckedF64;
use trig_core::decimal::bound_text;
use trig_core::evaluation::{self, Arithmetic, Computation, Value};
use trig_core::{Affine, Basis, CoreError, Described, Real, Ring, parse_exact};
use trig_deriv::{
    End, VanishingDenominator, Wrt, curve_endpoint_derivatives, endpoint_derivatives,
    knot_derivatives, rational_curve_endpoint_derivatives,
};
use trig_symbolic::{Sym, symbolic_atoms};

use super::eval::arithmetic_of;
use super::param_pairs;
use super::{CliError, CmdResult, range_hint};
use crate::cell::{Block, Cell, Rendered};
use crate::cost;
use crate::digits;
use crate::format::{TableFormat, render_blocks};
use crate::names::names_of;
use trig_specfile::AnyBasis;
use trig_specfile::nonvanishing::singular_where;

mod surface;

/// Highest order a table can have (the cost model).
pub const MAX_ORDER: usize = 12;

/// Highest order of an exact rational-curve table (`--curve --rational`):
/// the quotient rule's terms grow with the order (the cost model).
pub const MAX_RATIONAL_ORDER: usize = 6;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum At {
    Start,
    End,
    Both,
    Knots,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum WrtArg {
    Angle,
    U,
    X,
}

#[derive(Debug, Args)]
pub struct TableArgs {
    /// Family id (see `trig-audit list`).
    #[arg(required_unless_present = "spec", conflicts_with = "spec")]
    family: Option<String>,
    /// A spec file (TOML) defining the basis instead of a catalog family (docs/spec.md).
    #[arg(long, value_name = "FILE")]
    spec: Option<std::path::PathBuf>,
    /// Highest derivative order (0 to 12).
    #[arg(long, default_value_t = 6)]
    order: usize,
    /// Which end(s), or the knots of the uniform piecewise basis function.
    #[arg(long, value_enum, default_value = "both")]
    at: At,
    /// Variable of differentiation: `angle` (θ), `u` (θ = πu/2), `x` (a data
    /// abscissa), or the basis variable by its own name (`t` for a spec file
    /// whose variable is `t`, with half angles too).
    #[arg(long, default_value = "angle", value_name = "WRT")]
    wrt: String,
    /// Output format (tex: a fragment to \input, needing only booktabs,
    /// longtable and amsmath).
    #[arg(long, value_enum, default_value = "md")]
    format: TableFormat,
    /// With --format tex: a whole LaTeX document instead of a fragment.
    #[arg(long)]
    standalone: bool,
    /// Table of the curve Σ b_i P_i (as combinations of the control points).
    #[arg(long)]
    curve: bool,
    /// With --curve: the rational curve Σ w_i b_i P_i / Σ w_i b_i.
    #[arg(long, requires = "curve")]
    rational: bool,
    /// Numeric table from jets at the given --param values.
    #[arg(long)]
    numeric: bool,
    /// Shape parameter as name=value, read exactly (a rational or a rational
    /// multiple of pi such as alpha=pi/2): the numeric table at these values,
    /// or without --numeric the exact table at them (π symbolic; sin, cos of
    /// a parameter exact at multiples of π/12 only).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Certified MPFR interval arithmetic at this many bits for --numeric
    /// (default: f64 with a certified error bound); only proved digits are printed.
    #[arg(long, requires = "numeric")]
    prec: Option<u32>,
    /// For --numeric: this many significant digits per entry, every one
    /// proved (the working precision is raised until they are).
    #[arg(long, requires = "numeric")]
    digits: Option<usize>,
    /// For --numeric: parameters outside their published range.
    #[arg(long, requires = "numeric")]
    allow_outside_range: bool,
    /// Interval length h for --wrt x in a numeric table (exact tables keep the symbol h).
    #[arg(long, requires = "numeric", allow_hyphen_values = true)]
    h: Option<String>,
    #[command(flatten)]
    pub surface: super::surface::SurfaceArgs,
    /// With --surface: a control net file whose weights make the surface
    /// rational (the table stays in the control points P_ij; the file's
    /// points are not used).
    #[arg(long, value_name = "FILE", requires = "surface")]
    net: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

impl From<WrtArg> for Wrt {
    fn from(w: WrtArg) -> Wrt {
        match w {
            WrtArg::Angle => Wrt::Angle,
            WrtArg::U => Wrt::U,
            WrtArg::X => Wrt::X,
        }
    }
}

/// The convention `--wrt` names: `angle`, `u`, `x`, or the basis
/// variable's own name (derivatives in it, whatever angle its atoms use).
fn wrt_of(text: &str, family: &AnyBasis) -> Result<Wrt, CliError> {
    let name = family.domain().name;
    match text.trim() {
        "angle" | "theta" | "θ" => Ok(Wrt::Angle),
        "u" => Ok(Wrt::U),
        "x" => Ok(Wrt::X),
        t if t == name => Ok(Wrt::Variable),
        other => Err(CliError::Usage(format!(
            "--wrt {other}: expected angle, u, x or the basis variable {name}"
        ))),
    }
}

pub fn run(args: &TableArgs) -> CmdResult {
    if args.standalone && args.format != TableFormat::Tex {
        return Err(CliError::Usage(
            "--standalone writes a whole LaTeX document: it goes with --format tex".into(),
        ));
    }
    args.surface.check()?;
    let family = AnyBasis::open(args.family.as_deref(), args.spec.as_deref())?;
    let wrt = wrt_of(&args.wrt, &family)?;
    let id = family.id();
    if args.surface.surface {
        return surface::run(args, &family, wrt);
    }
    if args.order > MAX_ORDER {
        return Err(CoreError::Limit {
            what: format!("--order {}", args.order),
            limit: MAX_ORDER.to_string(),
        }
        .into());
    }
    if args.curve && args.rational && args.order > MAX_RATIONAL_ORDER {
        return Err(CoreError::Limit {
            what: format!("--curve --rational --order {}", args.order),
            limit: MAX_RATIONAL_ORDER.to_string(),
        }
        .into());
    }
    if args.at == At::Knots && (!family.piecewise() || args.curve) {
        return Err(CliError::Usage(format!(
            "--at knots needs a family with uniform B-spline pieces (seed000-uniform, bspline3, or a spec with four segment functions), without --curve; `{id}` is not one"
        )));
    }
    if args.curve && args.numeric {
        return Err(CliError::Usage(
            "--curve tables are exact combinations of the control points; drop --numeric".into(),
        ));
    }
    if !args.numeric {
        let params = exact_params(args, &family)?;
        let functions = family.eval(&symbolic_atoms(), &params);
        let what = format!(
            "table{} --order {}",
            if args.rational {
                " --curve --rational"
            } else {
                ""
            },
            args.order
        );
        cost::check_table(&what, &functions, args.order, args.rational)?;
    }
    let (blocks, mode) = if args.numeric {
        numeric(args, &family, wrt)?
    } else if args.params.is_empty() {
        (exact(args, &family, wrt)?, "exact".to_string())
    } else {
        let at = args.params.join(", ");
        (exact(args, &family, wrt)?, format!("exact at {at}"))
    };
    let heading = format!(
        "{id} ({}): derivatives {}, {mode}",
        family.citation(),
        wrt.describe_on(&family.domain())
    );
    render_blocks(&heading, &blocks, args.format, args.standalone)
}

/// The exact table: parameters (and `h`) as symbols, π symbolic; curve
/// tables as combinations of the control points `P0, P1, …`.
/// The parameters of an exact table: symbols, or with `--param` the exact
/// values (`q₀ + q_π·π`, π symbolic), refused with the reason where the
/// table could not stay exact — a parameter inside `sin`, `cos` away from
/// the multiples of π/12 (where both are exact), or inside `exp` away
/// from 0.
fn exact_params(args: &TableArgs, family: &AnyBasis) -> Result<Vec<Sym>, CliError> {
    exact_params_of(&args.params, family)
}

/// [`exact_params`] from the `name=value` arguments `raw`.
fn exact_params_of(raw: &[String], family: &AnyBasis) -> Result<Vec<Sym>, CliError> {
    if raw.is_empty() {
        return Ok(family.param_names().iter().map(|p| Sym::var(p)).collect());
    }
    // an exact table stays in the published range (no --allow-outside-range)
    let values = family.params_from_pairs(&param_pairs(raw)?, false)?;
    let domain = family.domain();
    let names = family.param_names();
    let twelfth = |a: &Affine| a.constant == 0 && *Rational::from(&a.pi * 12u32).denom() == 1;
    let atoms = domain
        .param_angles
        .iter()
        .map(|(i, b)| (i, b, "sin, cos", twelfth(&values[*i].scale(b))))
        .chain(domain.param_exps.iter().map(|(i, b)| {
            let x = values[*i].scale(b);
            (i, b, "exp", x.constant == 0 && x.pi == 0)
        }));
    for (i, base, kind, exact) in atoms {
        if !exact {
            let name = &names[*i];
            let argument = if *base == 1 {
                name.clone()
            } else {
                format!("{base}·{name}")
            };
            return Err(CliError::Usage(format!(
                "an exact table at {name} = {}: {kind} of {argument} is not exact there (exact at multiples of pi/12 for sin, cos, at 0 for exp); use --numeric for certified digits",
                values[*i].text(&[])
            )));
        }
    }
    Ok(values.iter().map(|a| a.eval(&Sym::one(), &[])).collect())
}

fn exact(args: &TableArgs, family: &AnyBasis, wrt: Wrt) -> Result<Vec<Block>, CliError> {
    let params = exact_params(args, family)?;
    // the length, points and weights read like none of the basis's names
    let mut namespace = names_of(family);
    let h = if wrt == Wrt::X {
        namespace.length()
    } else {
        Sym::one()
    };
    let n = family.function_names().len();
    let [points, _] = namespace.points(n);
    let names: Vec<String> = points.iter().map(ToString::to_string).collect();
    let weights = namespace.weights(n);
    let ranges: Vec<_> = family
        .parameters()
        .into_iter()
        .map(|p| (p.name.to_string(), p.range))
        .collect();
    let domain = family.domain();
    Ok(
        build(args, family, wrt, &params, &h, Some((&points, &weights)))
            .map_err(|e| CliError::Usage(e.to_string()))?
            .into_iter()
            .map(|mut b| {
                // a division by a parameter that may vanish in its range is
                // named, as the joins name theirs
                let singular = singular_where(b.cells(), &domain, &ranges);
                if !singular.is_empty() {
                    b.title = format!("{} (singular where {})", b.title, singular.join(", "));
                }
                b.map(|v| {
                    if args.curve {
                        v.combination(&names)
                    } else {
                        Rendered::of(&v)
                    }
                })
            })
            .collect(),
    )
}

/// The numeric table at exact parameter values: f64 with a certified
/// error bound (entries f64 gets wrong replaced by certified values), or
/// the proved digits of interval jets (`--prec`, `--digits`) — the
/// library's one evaluation path ([`evaluation::evaluate`]).
fn numeric(
    args: &TableArgs,
    family: &AnyBasis,
    wrt: Wrt,
) -> Result<(Vec<Block>, String), CliError> {
    let pairs = param_pairs(&args.params)?;
    let params = family
        .params_from_pairs(&pairs, args.allow_outside_range)
        .map_err(range_hint)?;
    let h = match &args.h {
        Some(text) => parse_exact(text)?,
        None => Rational::from(1),
    };
    if h <= 0 {
        return Err(CliError::Usage("--h must be positive".into()));
    }
    let arithmetic = arithmetic_of(args.prec, args.digits)?;
    let table = Derivatives {
        args,
        family,
        wrt,
        names: family.param_names(),
        params,
        h,
    };
    let what = format!("the derivatives of `{}`", family.id());
    let e = evaluation::evaluate(&table, arithmetic, &what).map_err(|e| match e {
        CoreError::NotRepresentable { .. } => {
            CliError::Usage(format!("{e} (use --digits N or --prec BITS)"))
        }
        e => e.into(),
    })?;
    // the table's shape (f64 arithmetic cannot fail on it: no curve)
    let shape = table
        .blocks(&|q: &Rational| q.to_f64())
        .map_err(|e| CliError::Usage(e.to_string()))?;
    let (mut worst, mut replaced) = (Rational::new(), 0);
    let mut values = e.values.iter();
    let blocks = shape
        .into_iter()
        .map(|b| {
            b.map(|_| match values.next() {
                Some(Value::F64(CheckedF64::Accurate { text, bound })) => {
                    if let Ok(q) = parse_exact(bound) {
                        worst = worst.clone().max(q);
                    }
                    Rendered::number(text)
                }
                Some(Value::F64(CheckedF64::Replaced { decimal, .. })) => {
                    replaced += 1;
                    Rendered::decimal(decimal)
                }
                Some(Value::Proved(decimal)) => Rendered::decimal(decimal),
                None => Rendered::number("?"),
            })
        })
        .collect();
    let arithmetic = match arithmetic {
        Arithmetic::F64 => {
            let mut note = format!(
                "f64, every entry within {} of the exact value (certified)",
                bound_text(&worst)
            );
            if replaced > 0 {
                note.push_str(&format!(
                    "; {replaced} entries where f64 is off show proved digits instead"
                ));
            }
            note
        }
        Arithmetic::Bits(bits) => format!("MPFR {bits} bits, proved digits only"),
        Arithmetic::Digits(n) => {
            let short = e.short_of(n);
            if short == 0 {
                format!("{n} significant digits, all proved (MPFR {} bits)", e.bits)
            } else {
                format!(
                    "{n} digits requested, {} of {} entries with fewer proved{} (an entry 0 ± b proves no digit: |value| ≤ b)",
                    short,
                    e.values.len(),
                    digits::shortfall(e.bits, e.stopped)
                )
            }
        }
    };
    Ok((
        blocks,
        format!("numeric ({arithmetic}, {})", args.params.join(", ")),
    ))
}

/// A numeric derivative table as a library [`Computation`]: its cells,
/// block by block, from the exact parameters and `h`.
struct Derivatives<'a> {
    args: &'a TableArgs,
    family: &'a AnyBasis,
    wrt: Wrt,
    names: Vec<String>,
    params: Vec<Affine>,
    h: Rational,
}

impl Derivatives<'_> {
    fn blocks<T: Ring>(
        &self,
        make: &dyn Fn(&Rational) -> T,
    ) -> Result<Vec<Block<T>>, VanishingDenominator> {
        let zero = make(&Rational::new());
        let p: Vec<T> = self.params.iter().map(|a| a.eval(&zero, &[])).collect();
        build(self.args, self.family, self.wrt, &p, &make(&self.h), None)
    }
}

impl Computation for Derivatives<'_> {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        let parts = self.params.iter().flat_map(|a| [&a.constant, &a.pi]);
        let named = self.names.iter().flat_map(|n| [n.clone(), n.clone()]);
        named
            .zip(parts)
            .chain([("--h".to_string(), &self.h)])
            .collect()
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>, CoreError> {
        let blocks = self
            .blocks(make)
            // numeric tables have no curve: nothing divides by a weighted sum
            .map_err(|e| CoreError::DivisionByZero {
                quantity: e.to_string(),
            })?;
        Ok(blocks.iter().flat_map(Block::cells).cloned().collect())
    }
}

/// Control points and weights of a curve table (symbols, exact mode only).
type CurveData<'a, T> = Option<(&'a [T], &'a [T])>;

/// Builds the blocks of a numeric or exact table, choosing the jet length
/// for the requested order.
fn build<T: Ring>(
    args: &TableArgs,
    family: &AnyBasis,
    wrt: Wrt,
    params: &[T],
    h: &T,
    curve: CurveData<'_, T>,
) -> Result<Vec<Block<T>>, VanishingDenominator> {
    macro_rules! with_order {
        ($($n:literal),*) => {
            match args.order {
                $($n => blocks::<T, { $n + 1 }>(args, family, wrt, params, h, curve),)*
                _ => unreachable!("order checked against MAX_ORDER"),
            }
        };
    }
    with_order!(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12)
}

fn blocks<T: Ring, const K: usize>(
    args: &TableArgs,
    family: &AnyBasis,
    wrt: Wrt,
    params: &[T],
    h: &T,
    curve: CurveData<'_, T>,
) -> Result<Vec<Block<T>>, VanishingDenominator> {
    let orders = || (0..K).map(|k| k.to_string());
    if args.at == At::Knots {
        let knots = knot_derivatives::<T, K>(family, params, wrt, h);
        let mut columns = Vec::new();
        let mut cols: Vec<Vec<T>> = Vec::new();
        for k in &knots {
            for (side, values) in [("-", &k.left), ("+", &k.right)] {
                if let Some(v) = values {
                    columns.push(format!("n{}{side}", k.knot));
                    cols.push(v.clone());
                }
            }
        }
        let rows = orders()
            .enumerate()
            .map(|(k, label)| (label, cols.iter().map(|c| c[k].clone()).collect()))
            .collect();
        return Ok(vec![Block {
            title: "one-sided derivatives of the B-spline basis function at knots n = 0..4".into(),
            corner: "k".into(),
            columns,
            rows,
        }]);
    }
    let ends: &[End] = match args.at {
        At::Start => &[End::Start],
        At::End => &[End::End],
        _ => &[End::Start, End::End],
    };
    ends.iter()
        .map(|&end| {
            let title = format!("{end} of the domain");
            if let (true, Some((points, weights))) = (args.curve, curve) {
                let values = if args.rational {
                    rational_curve_endpoint_derivatives::<T, K>(
                        family, params, points, weights, end, wrt, h,
                    )?
                } else {
                    curve_endpoint_derivatives::<T, K>(family, params, points, None, end, wrt, h)
                };
                Ok(Block {
                    title: format!(
                        "{title}: {}",
                        if args.rational {
                            "rational curve R"
                        } else {
                            "curve Q = Σ b_i P_i"
                        }
                    ),
                    corner: "k".into(),
                    columns: vec!["derivative".into()],
                    rows: orders()
                        .zip(values.iter())
                        .map(|(l, v)| (l, vec![v.clone()]))
                        .collect(),
                })
            } else {
                let table = endpoint_derivatives::<T, K>(family, params, end, wrt, h);
                Ok(Block {
                    title,
                    corner: "k".into(),
                    columns: family.function_names(),
                    rows: orders()
                        .enumerate()
                        .map(|(k, label)| (label, table.iter().map(|f| f[k].clone()).collect()))
                        .collect(),
                })
            }
        })
        .collect()
}
