//! `trig-audit plot`: figures of basis functions, curves with their
//! control polygons, fitted outlines, positivity interpolants and regions;
//! each written as SVG, with its pgfplots code and its data beside it.

use std::path::{Path, PathBuf};

use clap::{Args, Subcommand};
use trig_certify::ParamBox;
use trig_certify::region::CellKind;
use trig_core::{parse_exact, parse_point};
use trig_interp::{DataSet, Scheme, Variant, f64_segments};
use trig_judge::region::{Axis, classify_window};
use trig_plot::{
    CellLabels, Choice, Interpolant, PgfOptions, Picture, Plotted, RegionCell, RegionKind,
    basis_svg, basis_versus_svg, curve_svg, fit_svg, interp_svg, region_svg,
};
use trig_specfile::Spec;

use super::fit::{FitSetup, Runs, prepare};
use super::param_pairs;
use super::{CliError, CmdResult, range_hint};
use crate::format::csv_text;
use crate::output::{resolve, write_atomically, wrote};
use trig_specfile::AnyBasis;

mod revolution;
pub(crate) mod surface;

#[derive(Debug, Args)]
pub struct PlotArgs {
    #[command(subcommand)]
    what: PlotKind,
}

#[derive(Debug, Subcommand)]
enum PlotKind {
    /// The functions of a family for several parameter values (thesis Figures 3.1, 3.6).
    Basis {
        /// Family id (or --spec FILE).
        #[arg(long, required_unless_present = "spec")]
        family: Option<String>,
        #[command(flatten)]
        values: Values,
        /// Draw this family's functions too, thin over the first's wide lines, at the same values
        /// (e.g. the printed formulas beside what a listing computes).
        #[arg(long, value_name = "FAMILY")]
        versus: Option<String>,
        /// SVG file to write (its pgfplots code NAME.tex and data NAME.csv beside it).
        #[arg(long)]
        output: PathBuf,
        #[command(flatten)]
        look: FigureArgs,
    },
    /// A curve with its control polygon for several parameter values (thesis Figure 6.3).
    Curve {
        /// Family id (or --spec FILE).
        #[arg(long, required_unless_present = "spec")]
        family: Option<String>,
        #[command(flatten)]
        values: Values,
        /// Control points x0,y0,x1,y1,… (default: thesis Figure 6.3, (0,0), (1,2), (3,2), (4,0)).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        control: Vec<String>,
        /// SVG file to write (its pgfplots code NAME.tex and data NAME.csv beside it).
        #[arg(long)]
        output: PathBuf,
        #[command(flatten)]
        look: FigureArgs,
    },
    /// A fitted outline over its data, before and (with --refine) after C¹ refinement.
    Fit {
        /// Family id (or --spec FILE).
        #[arg(long, required_unless_present = "spec")]
        family: Option<String>,
        /// Optimise the shape parameter per segment.
        #[arg(long)]
        optimise: bool,
        #[command(flatten)]
        setup: FitSetup,
        /// SVG file to write (its pgfplots code NAME.tex and data NAME.csv beside it).
        #[arg(long)]
        output: PathBuf,
        #[command(flatten)]
        look: FigureArgs,
    },
    /// The region of two shape parameters where every function of a spec
    /// file's basis is nonnegative (or where the basis is totally positive):
    /// certified cells inside and outside, the undecided edge, the printed
    /// box.
    Region {
        /// Spec file (TOML, docs/spec.md) of a basis with two parameters.
        #[arg(long, value_name = "FILE")]
        spec: PathBuf,
        /// The property whose region is drawn: `nonnegative` (every function
        /// ≥ 0), `total-positivity` (inside: the factorisation's minors
        /// certified ≥ 0 on the cell; outside: a necessary condition fails on
        /// the whole cell) or `independent` (inside: a maximal minor of the
        /// coefficient matrix of one strict sign on the cell; the exceptional
        /// set lies in the undecided cells).
        #[arg(long, value_enum, default_value_t = RegionProperty::Nonnegative)]
        property: RegionProperty,
        /// SVG file to write (its pgfplots code NAME.tex and data NAME.csv beside it).
        #[arg(long)]
        output: PathBuf,
        #[command(flatten)]
        look: FigureArgs,
    },
    /// Tensor-product surface patches with their control nets (thesis
    /// Figures 5.1–5.7), as SVG with pgfplots code or as a mesh (OBJ, PLY, STL).
    Surface(Box<surface::SurfacePlotArgs>),
    /// Positivity interpolants of thesis 4.3 with their data points.
    Interp {
        /// Data set (thesis-table-4.1 … thesis-table-4.6).
        #[arg(long)]
        data: String,
        /// Scheme (c1, c2, g1, g2); default: the one the table is printed for.
        #[arg(long)]
        scheme: Option<String>,
        /// SVG file to write (its pgfplots code NAME.tex and data NAME.csv beside it).
        #[arg(long)]
        output: PathBuf,
        #[command(flatten)]
        look: FigureArgs,
    },
}

/// How a figure is written, for every kind of plot.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// Width of the pgfplots figure, a LaTeX length (tick and axis labels
    /// included; the height follows).
    #[arg(long, default_value = r"\linewidth", value_name = "LENGTH")]
    width: String,
    /// Leave out the title (the caption of a paper says what a figure shows).
    #[arg(long)]
    no_title: bool,
    /// Write the pgfplots code as a whole LaTeX document instead of a
    /// fragment to \input.
    #[arg(long)]
    standalone: bool,
}

/// The defaults of the command line: as wide as the line, with the title, a fragment.
impl Default for FigureArgs {
    fn default() -> Self {
        FigureArgs {
            width: r"\linewidth".into(),
            no_title: false,
            standalone: false,
        }
    }
}

impl FigureArgs {
    /// The width, checked: a LaTeX length without braces or other
    /// characters that would end the option list.
    fn options(&self) -> Result<PgfOptions, CliError> {
        let width = self.width.trim();
        let valid = !width.is_empty()
            && width
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '\\' | '-' | '*' | ' '));
        if !valid {
            return Err(CliError::Usage(format!(
                "--width {width}: expected a LaTeX length such as \\linewidth, 0.8\\linewidth or 8cm"
            )));
        }
        Ok(PgfOptions {
            width: width.to_string(),
            standalone: self.standalone,
        })
    }
}

#[derive(Debug, Args)]
struct Values {
    /// Draw the basis of this spec file (TOML, docs/spec.md) instead of a family.
    #[arg(long, value_name = "FILE")]
    spec: Option<PathBuf>,
    /// Fix a parameter, as name=value (name or printed symbol; read exactly
    /// as `eval --param` reads it: 0.6 = 3/5, 1/2, or a rational multiple
    /// of pi such as alpha=pi/2); repeatable. With every parameter but
    /// one fixed, that one is varied.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    params: Vec<String>,
    /// The parameter whose values are drawn (name or printed symbol);
    /// default: the one parameter not fixed by --param.
    #[arg(long, value_name = "NAME")]
    vary: Option<String>,
    /// Values of the varied parameter, comma separated (read exactly:
    /// rationals, or rational multiples of pi such as pi/2); default: five
    /// values evenly spread over the published range (open ends left out)
    /// when it is bounded with rational ends; otherwise give them.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    values: Vec<String>,
    /// Allow values (fixed or varied) outside the published ranges.
    #[arg(long)]
    allow_outside_range: bool,
}

impl Values {
    /// The parameters to fix and to vary, read as every command reads a
    /// parameter value.
    fn choice(&self) -> Result<Choice, CliError> {
        Ok(Choice {
            fixed: param_pairs(&self.params)?,
            vary: self.vary.clone(),
            values: self
                .values
                .iter()
                .map(|v| parse_point(v))
                .collect::<Result<_, _>>()?,
            allow_outside: self.allow_outside_range,
        })
    }
}

/// What `plot basis` and `plot curve` draw: the family or spec file's
/// basis, for the parameters `v` fixes and the values of the one it
/// varies (checked against the published ranges unless
/// `--allow-outside-range`).
fn plotted(family: Option<&str>, v: &Values, what: &str) -> Result<Plotted, CliError> {
    let choice = v.choice()?;
    match AnyBasis::open(family, v.spec.as_deref())? {
        AnyBasis::Family(family) => Plotted::new(family, &choice, what),
        AnyBasis::Spec(spec) => Plotted::new(*spec, &choice, what),
    }
    .map_err(plot_err_hinted)
}

/// Writes the picture (SVG) and, beside it, its pgfplots code
/// (`NAME.tex`, text mapped to LaTeX as in the report) and its data
/// (`NAME.csv`: series, point, x, y), each atomically; the notes on
/// standard error (standard output stays empty).
pub fn write(output: &Path, picture: Picture, look: &FigureArgs) -> CmdResult {
    let pgf_options = look.options()?;
    let picture = if look.no_title {
        picture.without_title().map_err(plot_err)?
    } else {
        picture
    };
    let output = resolve(output)?;
    let output = output.as_path();
    if std::fs::metadata(output).is_ok_and(|m| !m.is_file()) {
        return Err(CliError::Usage(format!(
            "{}: not a regular file; a picture is written with its pgfplots code and data beside it (NAME.tex, NAME.csv), so only to a regular file",
            output.display()
        )));
    }
    if !output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
    {
        return Err(CliError::Usage(format!(
            "{}: the picture is written as SVG: give a name ending in .svg (its pgfplots code goes to NAME.tex, its data to NAME.csv)",
            output.display()
        )));
    }
    let (tex, data) = (output.with_extension("tex"), output.with_extension("csv"));
    if tex == output || data == output {
        return Err(CliError::Usage(format!(
            "{}: the picture needs another extension than .tex or .csv (its pgfplots code goes to NAME.tex, its data to NAME.csv)",
            output.display()
        )));
    }
    let rows = picture.rows();
    let csv = csv_text(
        &Picture::HEADER,
        rows.iter().map(|r| r.iter().map(String::as_str)),
    )?;
    let pgf = picture.pgf(&pgf_options);
    write_atomically(output, picture.svg.as_bytes())?;
    write_atomically(&tex, pgf.as_bytes())?;
    write_atomically(&data, csv.as_bytes())?;
    wrote(output, &format!("{} bytes", picture.svg.len()));
    wrote(&tex, "pgfplots");
    wrote(&data, &format!("{} points", rows.len()));
    Ok(String::new())
}

fn plot_err(e: trig_plot::PlotError) -> CliError {
    match e {
        trig_plot::PlotError::Core(c) => CliError::Core(c),
        other => CliError::Usage(other.to_string()),
    }
}

/// [`plot_err`] for the plots that take `--allow-outside-range`.
fn plot_err_hinted(e: trig_plot::PlotError) -> CliError {
    match e {
        trig_plot::PlotError::Core(c) => range_hint(c),
        other => plot_err(other),
    }
}

pub fn run(args: &PlotArgs) -> CmdResult {
    match &args.what {
        PlotKind::Basis {
            family,
            values: v,
            versus,
            output,
            look,
        } => {
            let plot = plotted(family.as_deref(), v, "basis")?;
            let picture = match versus {
                None => basis_svg(&plot),
                Some(other) => {
                    // the same values, without the spec file of the first basis
                    let same = Values {
                        spec: None,
                        params: v.params.clone(),
                        vary: v.vary.clone(),
                        values: v.values.clone(),
                        allow_outside_range: v.allow_outside_range,
                    };
                    let other = plotted(Some(other), &same, "basis")?;
                    basis_versus_svg(&plot, &other)
                }
            };
            write(output, picture.map_err(plot_err_hinted)?, look)
        }
        PlotKind::Curve {
            family,
            values: v,
            control,
            output,
            look,
        } => {
            let control_default = control.is_empty();
            let plot = plotted(family.as_deref(), v, "curve")?;
            let control = control_points(control)?;
            if control.len() != plot.functions.len() && control_default {
                return Err(CliError::Usage(format!(
                    "`{}` has {} functions; the default polygon (thesis Figure 6.3) has 4 points: give --control with {} x,y pairs",
                    plot.id,
                    plot.functions.len(),
                    plot.functions.len()
                )));
            }
            write(
                output,
                curve_svg(&plot, &control).map_err(plot_err_hinted)?,
                look,
            )
        }
        PlotKind::Fit {
            family,
            optimise,
            setup,
            output,
            look,
        } => {
            let family = family.as_deref().unwrap_or("all");
            if family == "all" && setup.spec.is_none() {
                return Err(CliError::Usage(
                    "plot fit draws one family: give its id".into(),
                ));
            }
            let runs = if *optimise {
                Runs::Optimised
            } else {
                Runs::Fixed
            };
            let (outline, methods) = prepare(setup, family, runs)?;
            let method = methods
                .first()
                .ok_or_else(|| CliError::Usage("nothing fitted".into()))?;
            let searched = method
                .fit
                .optimised
                .then(|| method.shown.as_ref().map(|(k, _)| *k))
                .flatten();
            write(
                output,
                fit_svg(&outline, &method.fit, &method.symbols, searched).map_err(plot_err)?,
                look,
            )
        }
        PlotKind::Region {
            spec,
            property,
            output,
            look,
        } => write(output, region(spec, *property)?, look),
        PlotKind::Surface(args) => surface::run(args),
        PlotKind::Interp {
            data,
            scheme,
            output,
            look,
        } => {
            let set = DataSet::named(data).map_err(|e| CliError::Usage(e.to_string()))?;
            let scheme = match scheme {
                Some(s) => s
                    .parse::<Scheme>()
                    .map_err(|e| CliError::Usage(e.to_string()))?,
                None => set.table.scheme,
            };
            let mut curves = Vec::new();
            for variant in [Variant::Printed, Variant::Corrected] {
                let pieces = f64_segments(data, scheme, variant)
                    .map_err(|e| CliError::Usage(e.to_string()))?;
                curves.push(Interpolant {
                    label: format!("{scheme} interpolant, {variant} formulas"),
                    pieces: pieces.iter().map(|p| p.sample(60)).collect(),
                });
            }
            let points: Vec<(f64, f64)> = set
                .x
                .iter()
                .zip(&set.f)
                .map(|(x, f)| (x.to_f64(), f.to_f64()))
                .collect();
            let title = format!("{} — {scheme} scheme (thesis 4.3)", set.table.caption);
            write(
                output,
                interp_svg(&title, &points, &curves).map_err(plot_err)?,
                look,
            )
        }
    }
}

/// The classified window around the printed box of a two-parameter spec.
/// The property whose region `plot region` draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum RegionProperty {
    Nonnegative,
    TotalPositivity,
    Independent,
}

fn region(path: &Path, property: RegionProperty) -> Result<Picture, CliError> {
    let spec =
        Spec::from_file(path).map_err(|e| CliError::Usage(e.to_string().replace('\n', " ")))?;
    let [p, q] = spec.params.as_slice() else {
        return Err(CliError::Usage(format!(
            "`{}` has {} parameters; plot region draws two",
            spec.id,
            spec.params.len()
        )));
    };
    fn axis(p: &trig_core::Parameter) -> Axis<'_> {
        Axis {
            name: &p.name,
            symbol: &p.symbol,
            set: ParamBox::from_range(&p.range),
            source: &p.source,
        }
    }
    let axes = [axis(p), axis(q)];
    let reg = match property {
        RegionProperty::Nonnegative => {
            let (trig, fs, names) = trig_judge::nonnegative::pieces(&spec)
                .map_err(|why| CliError::Usage(format!("plot region: {why}")))?;
            let names: Vec<&str> = names.iter().map(String::as_str).collect();
            classify_window(&fs, &names, trig, &axes)
        }
        RegionProperty::TotalPositivity => {
            trig_judge::tp_maximal_box::totally_positive_region(&spec, &axes)
                .map_err(|why| CliError::Usage(format!("plot region: {why}")))?
        }
        RegionProperty::Independent => trig_judge::independence::independence_region(&spec, &axes)
            .map_err(|why| CliError::Usage(format!("plot region: {why}")))?,
    };
    let cells: Vec<RegionCell> = reg
        .cells
        .iter()
        .map(|c| RegionCell {
            x: (c.lo[0].to_f64(), c.hi[0].to_f64()),
            y: (c.lo[1].to_f64(), c.hi[1].to_f64()),
            kind: match c.kind {
                CellKind::Inside => RegionKind::Inside,
                CellKind::Outside { .. } => RegionKind::Outside,
                CellKind::Boundary => RegionKind::Edge,
            },
        })
        .collect();
    let side = |set: &trig_certify::ParamBox| {
        (
            set.lo.value().map_or(f64::NEG_INFINITY, |v| v.to_f64()),
            set.hi.value().map_or(f64::INFINITY, |v| v.to_f64()),
        )
    };
    let (title, labels) = match property {
        RegionProperty::Nonnegative => (
            format!("{}: where every function is ≥ 0", spec.id),
            CellLabels::NONNEGATIVE,
        ),
        RegionProperty::TotalPositivity => (
            format!("{}: where the basis is totally positive", spec.id),
            CellLabels::TOTALLY_POSITIVE,
        ),
        RegionProperty::Independent => (
            format!("{}: where the functions are linearly independent", spec.id),
            CellLabels::INDEPENDENT,
        ),
    };
    region_svg(
        &title,
        (&p.symbol, &q.symbol),
        &cells,
        Some((side(&axes[0].set), side(&axes[1].set))),
        labels,
    )
    .map_err(plot_err)
}

/// `x0,y0,x1,y1,…` as points (default: thesis Figure 6.3).
fn control_points(raw: &[String]) -> Result<Vec<(f64, f64)>, CliError> {
    if raw.is_empty() {
        return Ok(vec![(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]);
    }
    if raw.len() % 2 != 0 {
        return Err(CliError::Usage(format!(
            "--control: {} numbers given; expected x,y pairs",
            raw.len()
        )));
    }
    let nums = raw
        .iter()
        .map(|v| parse_exact(v).map(|q| q.to_f64()))
        .collect::<Result<Vec<f64>, _>>()?;
    Ok(nums.chunks(2).map(|c| (c[0], c[1])).collect())
}
