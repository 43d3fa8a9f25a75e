//! `trig-audit table`: endpoint-derivative tables, exact (parameters as
//! symbols, π symbolic) or numeric from jets.

use clap::{Args, ValueEnum};
use rug::Rational;
use trig_core::{Basis, Mpfr, Ring, parse_exact};
use trig_deriv::{End, Wrt, curve_endpoint_derivatives, endpoint_derivatives, knot_derivatives};
use trig_symbolic::Sym;

use super::eval::{Subject, param_pairs};
use super::{CliError, CmdResult};
use crate::cell::{Block, Cell, Rendered};
use crate::format::{TableFormat, render_blocks};

/// Highest order a table can have.
pub const MAX_ORDER: usize = 12;

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
    /// Variable of differentiation: the angle θ, u with θ = πu/2, or a data abscissa x.
    #[arg(long, value_enum, default_value = "angle")]
    wrt: WrtArg,
    /// Output format.
    #[arg(long, value_enum, default_value = "md")]
    format: TableFormat,
    /// Table of the curve Σ b_i P_i (as combinations of the control points).
    #[arg(long)]
    curve: bool,
    /// With --curve: the rational curve Σ w_i b_i P_i / Σ w_i b_i.
    #[arg(long, requires = "curve")]
    rational: bool,
    /// Numeric table from jets at the given --param values.
    #[arg(long)]
    numeric: bool,
    /// Shape parameter for --numeric, as name=value.
    #[arg(long = "param", value_name = "NAME=VALUE", requires = "numeric")]
    params: Vec<String>,
    /// MPFR precision in bits for --numeric (default: f64).
    #[arg(long, requires = "numeric")]
    prec: Option<u32>,
    /// Interval length h for --wrt x in a numeric table (exact tables keep the symbol h).
    #[arg(long, requires = "numeric", allow_hyphen_values = true)]
    h: Option<String>,
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

pub fn run(args: &TableArgs) -> CmdResult {
    let family = Subject::from_args(args.family.as_deref(), args.spec.as_deref())?;
    let id = family.id();
    if args.order > MAX_ORDER {
        return Err(CliError::Usage(format!(
            "--order {}: at most {MAX_ORDER}",
            args.order
        )));
    }
    if args.at == At::Knots && (!family.piecewise() || args.curve) {
        return Err(CliError::Usage(format!(
            "--at knots needs a family with uniform B-spline pieces (seed000-uniform, bspline3, or a spec with four segment functions), without --curve; `{id}` is not one"
        )));
    }
    let wrt = Wrt::from(args.wrt);
    if args.curve && args.numeric {
        return Err(CliError::Usage(
            "--curve tables are exact combinations of the control points; drop --numeric".into(),
        ));
    }
    let blocks = if args.numeric {
        let pairs = param_pairs(&args.params)?;
        let p = family.params_from_pairs(&pairs, true)?;
        let h = match &args.h {
            Some(text) => parse_exact(text)?,
            None => Rational::from(1),
        };
        if h <= 0 {
            return Err(CliError::Usage("--h must be positive".into()));
        }
        match args.prec {
            None => build(
                args,
                &family,
                &p.iter().map(Rational::to_f64).collect::<Vec<_>>(),
                &h.to_f64(),
                None,
            ),
            Some(bits) if (2..=1 << 16).contains(&bits) => {
                let mk = |q: &Rational| Mpfr::from_rational(bits, q);
                build(
                    args,
                    &family,
                    &p.iter().map(mk).collect::<Vec<_>>(),
                    &mk(&h),
                    None,
                )
            }
            Some(bits) => {
                return Err(CliError::Usage(format!(
                    "--prec {bits}: expected 2 to 65536 bits"
                )));
            }
        }
    } else {
        let params: Vec<Sym> = family.param_names().iter().map(|p| Sym::var(p)).collect();
        let h = if wrt == Wrt::X {
            Sym::var("h")
        } else {
            Sym::one()
        };
        let n = family.function_names().len();
        let points: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("P{i}"))).collect();
        let weights: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("w{i}"))).collect();
        build(args, &family, &params, &h, Some((&points, &weights)))
    };
    let mode = if args.numeric {
        let shown: Vec<String> = args.params.clone();
        format!(
            "numeric ({}, {})",
            args.prec.map_or("f64".into(), |b| format!("MPFR {b} bits")),
            shown.join(", ")
        )
    } else {
        "exact".to_string()
    };
    let heading = format!(
        "{id} ({}): derivatives {}, {mode}",
        family.citation(),
        wrt.describe(family.domain().is_trigonometric())
    );
    Ok(render_blocks(&heading, &blocks, args.format))
}

/// Control points and weights of a curve table (symbols, exact mode only).
type CurveData<'a, T> = Option<(&'a [T], &'a [T])>;

/// Builds the blocks of a numeric or exact table, choosing the jet length
/// for the requested order.
fn build<T: Ring + Cell>(
    args: &TableArgs,
    family: &Subject,
    params: &[T],
    h: &T,
    curve: CurveData<'_, T>,
) -> Vec<Block> {
    macro_rules! with_order {
        ($($n:literal),*) => {
            match args.order {
                $($n => blocks::<T, { $n + 1 }>(args, family, params, h, curve),)*
                _ => unreachable!("order checked against MAX_ORDER"),
            }
        };
    }
    with_order!(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12)
}

fn blocks<T: Ring + Cell, const K: usize>(
    args: &TableArgs,
    family: &Subject,
    params: &[T],
    h: &T,
    curve: CurveData<'_, T>,
) -> Vec<Block> {
    let wrt = Wrt::from(args.wrt);
    let orders = || (0..K).map(|k| k.to_string());
    if args.at == At::Knots {
        let knots = knot_derivatives::<T, K>(family, params, wrt, h);
        let mut columns = Vec::new();
        let mut cols: Vec<Vec<Rendered>> = Vec::new();
        for k in &knots {
            for (side, values) in [("-", &k.left), ("+", &k.right)] {
                if let Some(v) = values {
                    columns.push(format!("n{}{side}", k.knot));
                    cols.push(v.iter().map(Rendered::of).collect());
                }
            }
        }
        let rows = orders()
            .enumerate()
            .map(|(k, label)| (label, cols.iter().map(|c| c[k].clone()).collect()))
            .collect();
        return vec![Block {
            title: "one-sided derivatives of the B-spline basis function at knots n = 0..4".into(),
            corner: "k".into(),
            columns,
            rows,
        }];
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
                let names: Vec<String> = (0..points.len()).map(|i| format!("P{i}")).collect();
                let values = curve_endpoint_derivatives::<T, K>(
                    family,
                    params,
                    points,
                    args.rational.then_some(weights),
                    end,
                    wrt,
                    h,
                );
                Block {
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
                        .map(|(l, v)| (l, vec![v.combination(&names)]))
                        .collect(),
                }
            } else {
                let table = endpoint_derivatives::<T, K>(family, params, end, wrt, h);
                Block {
                    title,
                    corner: "k".into(),
                    columns: family.function_names(),
                    rows: orders()
                        .enumerate()
                        .map(|(k, label)| {
                            (label, table.iter().map(|f| Rendered::of(&f[k])).collect())
                        })
                        .collect(),
                }
            }
        })
        .collect()
}
