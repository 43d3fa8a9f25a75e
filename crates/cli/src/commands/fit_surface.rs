//! `trig-audit fit-surface`: a least-squares tensor-product fit of a
//! gridded height field by patches of one basis in both directions
//! (`trig_fit::surface`), for one family, the compared ones of `fit`, or a
//! spec file's basis, and several patch counts; the errors as the thesis's
//! Chapter 6 reports them for curves (maximum, mean; and RMS) per patch
//! and overall, and the error map as a picture.

use std::path::PathBuf;
use std::str::FromStr;
use std::sync::Arc;
use std::time::Instant;

use clap::{Args, ValueEnum};
use trig_core::Described;
use trig_fit::{
    Grid, Join, NumericBasis, Scope, Shape, Stats, SurfaceFit, SurfaceOptions, fit_surface,
};
use trig_plot::{PATCH_COLOURS, SurfaceFigure, SurfacePatch, View};
use trig_specfile::AnyBasis;

use super::fit::{
    SearchRange, fit_err, fixed_params, interval, parameters, searched, selected_with_params,
};
use super::plot::surface::{output_of, write as write_surface};
use super::plot::{FigureArgs, write};
use super::{CliError, CmdResult, range_hint};
use crate::cell::{Block, Rendered};
use crate::format::{TableFormat, render_blocks};

/// A fit that runs longer than this (seconds) gets a progress line.
const PROGRESS_AFTER: f64 = 1.0;

/// `PUxPV`: patches along the rows and along the columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Patches(pub usize, pub usize);

impl FromStr for Patches {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let bad = || format!("`{s}`: expected PUxPV, two whole numbers ≥ 1 such as 4x4 or 8x6");
        let (a, b) = s.split_once(['x', 'X', '×']).ok_or_else(bad)?;
        let n = |t: &str| t.trim().parse::<usize>().ok().filter(|&n| n >= 1);
        Ok(Patches(n(a).ok_or_else(bad)?, n(b).ok_or_else(bad)?))
    }
}

impl std::fmt::Display for Patches {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}×{}", self.0, self.1)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ContinuityArg {
    /// Neighbouring patches share their boundary control points.
    C0,
    /// And their first derivatives across the boundary agree.
    C1,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OptimisePer {
    /// One value for every patch of a direction.
    Direction,
    /// One value per segment of a direction: per row and per column of patches.
    Segment,
}

#[derive(Debug, Args)]
pub struct FitSurfaceArgs {
    /// Grid of heights: CSV rows of numbers, or a matrix as R writes it
    /// (data/volcano/volcano.csv); row i is u = i/(rows − 1), column j is
    /// v = j/(columns − 1).
    #[arg(long, value_name = "FILE")]
    grid: PathBuf,
    /// Family id, or `all` for the compared families of `fit` (not with --spec).
    #[arg(long, default_value = "all")]
    family: String,
    /// Fit with the basis of this spec file (four functions interpolating
    /// their end control points) instead of a family.
    #[arg(long, value_name = "FILE")]
    spec: Option<PathBuf>,
    /// Patches along the rows × along the columns, several comma separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "1x1,2x2,4x4,8x6",
        value_name = "PUxPV"
    )]
    patches: Vec<Patches>,
    /// How neighbouring patches join.
    #[arg(long, value_enum, default_value = "c1")]
    continuity: ContinuityArg,
    /// Shape parameter as name=value, read exactly (default: 0.6 for every
    /// catalog family, as the thesis; a spec file's must be given).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Parameters outside their published range.
    #[arg(long)]
    allow_outside_range: bool,
    /// Also fit with the shape parameter optimised (golden section on the
    /// total squared error), one value per direction or per segment (--optimise-per).
    #[arg(long)]
    optimise: bool,
    /// What one optimised value covers: every patch of a direction, or one
    /// segment of a direction (a row or a column of patches).
    #[arg(long, value_enum, default_value = "direction", requires = "optimise")]
    optimise_per: OptimisePer,
    /// The parameter --optimise searches (name or printed symbol), the
    /// others fixed by --param.
    #[arg(long, value_name = "NAME", requires = "optimise")]
    vary: Option<String>,
    /// Interval searched by --optimise.
    #[arg(long, value_enum, default_value = "certified")]
    range: SearchRange,
    /// The comparison table only, without the per-patch tables.
    #[arg(long)]
    summary: bool,
    /// Output format (tex: a fragment to \input).
    #[arg(long, value_enum, default_value = "md")]
    format: TableFormat,
    /// Draw the error map of the last fit of the table (one basis and one
    /// patch count; with --optimise the optimised fit) as SVG, with its
    /// pgfplots code and data beside it (NAME.tex, NAME.csv).
    #[arg(long, value_name = "FILE.svg")]
    error_map: Option<PathBuf>,
    /// Write the fitted surface of the last fit of the table (one basis and
    /// one patch count, as --error-map) through the surface writer of `plot
    /// surface`: FILE.svg (a picture, its pgfplots code beside it) or a mesh
    /// FILE.obj, FILE.ply, FILE.stl. Each patch is drawn at the grid points
    /// around it.
    #[arg(long, value_name = "FILE")]
    surface_output: Option<PathBuf>,
    /// Grid spacing for the error map's and the fitted surface's x and y
    /// (the volcano: 10 m).
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    spacing: f64,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

/// One fit of the table.
struct Row {
    basis: String,
    setting: String,
    optimised: bool,
    fit: SurfaceFit,
}

/// The fits to run: each basis with its fixed parameters, and with
/// `--optimise` also with the searched one optimised.
fn settings(args: &FitSurfaceArgs) -> Result<Vec<(AnyBasis, String, Shape)>, CliError> {
    let (selected, pairs) = selected_with_params(&args.family, args.spec.as_deref(), &args.params)?;
    let hinted = |e: CliError| match e {
        CliError::Core(c) => range_hint(c),
        e => e,
    };
    let mut out = Vec::new();
    let (mut searchable, mut unsearched) = (false, Vec::new());
    for subject in selected {
        let symbols: Vec<String> = parameters(&subject)
            .into_iter()
            .map(|(_, s, _)| s)
            .collect();
        let fixed =
            fixed_params(&subject, &pairs, None, args.allow_outside_range).map_err(hinted)?;
        let setting = symbols
            .iter()
            .zip(&fixed)
            .map(|(s, (_, v))| format!("{s} = {v}"))
            .collect::<Vec<_>>()
            .join(", ");
        let values = fixed.into_iter().map(|(_, v)| v).collect();
        out.push((
            subject.clone(),
            if setting.is_empty() {
                "—".into()
            } else {
                setting
            },
            Shape::Fixed(values),
        ));
        if !args.optimise {
            continue;
        }
        // a basis with no parameter to search has its fixed fit only
        // (`--family all` takes the Bernstein basis along); none at all is refused
        let Some(index) = searched(&subject, &pairs, args.vary.as_deref())? else {
            unsearched.push(match symbols.len() {
                0 => format!("`{}` has no shape parameter", subject.id()),
                n => format!("`{}` has {n} ({})", subject.id(), symbols.join(", ")),
            });
            continue;
        };
        searchable = true;
        let (lo, hi, from) = interval(&subject, index, args.range)?;
        let fixed = fixed_params(&subject, &pairs, Some(index), args.allow_outside_range)
            .map_err(hinted)?;
        let others: String = fixed
            .iter()
            .map(|(k, v)| format!(", {} = {v}", symbols[*k]))
            .collect();
        out.push((
            subject,
            format!(
                "{} optimised per {} in [{lo:.4}, {hi:.4}] ({from}){others}",
                symbols[index],
                match args.optimise_per {
                    OptimisePer::Direction => "direction",
                    OptimisePer::Segment => "segment",
                }
            ),
            Shape::Optimise { lo, hi, fixed },
        ));
    }
    if args.optimise && !searchable {
        return Err(CliError::Usage(format!(
            "--optimise searches one shape parameter (golden section); {}: fix all but one with --param NAME=VALUE (--vary NAME names the one searched), or fit with fixed values only",
            unsearched.join("; ")
        )));
    }
    Ok(out)
}

/// Runs every fit, with a progress line on standard error once the work
/// has taken more than [`PROGRESS_AFTER`] seconds.
fn fits(args: &FitSurfaceArgs, grid: &Grid) -> Result<Vec<Row>, CliError> {
    let join = match args.continuity {
        ContinuityArg::C0 => Join::C0,
        ContinuityArg::C1 => Join::C1,
    };
    let settings = settings(args)?;
    let total = settings.len() * args.patches.len();
    let start = Instant::now();
    let mut rows = Vec::with_capacity(total);
    for (subject, setting, shape) in settings {
        let basis: Arc<dyn NumericBasis> = Arc::new(subject.clone());
        for &Patches(pu, pv) in &args.patches {
            let options = SurfaceOptions {
                patches: (pu, pv),
                join,
                shape: shape.clone(),
                scope: match args.optimise_per {
                    OptimisePer::Direction => Scope::Direction,
                    OptimisePer::Segment => Scope::Segment,
                },
            };
            let fit = fit_surface(grid, basis.clone(), &options).map_err(fit_err)?;
            let elapsed = start.elapsed().as_secs_f64();
            if elapsed > PROGRESS_AFTER {
                eprintln!(
                    "fit-surface: {}/{total} fits ({}, {pu}×{pv} patches) after {elapsed:.1} s",
                    rows.len() + 1,
                    subject.id()
                );
            }
            rows.push(Row {
                basis: subject.id(),
                setting: setting.clone(),
                optimised: matches!(shape, Shape::Optimise { .. }),
                fit,
            });
        }
    }
    Ok(rows)
}

pub fn run(args: &FitSurfaceArgs) -> CmdResult {
    if args.error_map.is_some() && !(args.spacing.is_finite() && args.spacing > 0.0) {
        return Err(CliError::Usage(format!(
            "--spacing {}: a positive number",
            args.spacing
        )));
    }
    let grid = Grid::read(&args.grid).map_err(fit_err)?;
    let rows = fits(args, &grid)?;
    if let Some(path) = &args.error_map {
        let last = one_fit(&rows, args, "--error-map")?;
        let picture =
            trig_plot::error_map_svg(&title_of(&grid, last, "|error|"), &last.fit, args.spacing)
                .map_err(|e| CliError::Usage(e.to_string()))?;
        write(path, picture, &FigureArgs::default())?;
    }
    if let Some(path) = &args.surface_output {
        let last = one_fit(&rows, args, "--surface-output")?;
        let (output, mesh) = output_of(path)?;
        let figure = fitted_figure(
            title_of(&grid, last, "fitted surface"),
            &last.fit,
            args.spacing,
        );
        write_surface(
            &output,
            mesh,
            &figure,
            &FigureArgs::default(),
            "fit-surface",
        )?;
    }
    let heading = format!(
        "Surface fit of `{}` ({} × {} heights), patches joined {:?}",
        grid.name, grid.rows, grid.cols, args.continuity
    );
    render_blocks(&heading, &blocks(args, &rows), args.format, false)
}

/// The one fit `option` draws: the last of the table, which must hold one
/// basis and one patch count.
fn one_fit<'a>(rows: &'a [Row], args: &FitSurfaceArgs, option: &str) -> Result<&'a Row, CliError> {
    let last = rows
        .last()
        .ok_or_else(|| CliError::Usage("nothing fitted".into()))?;
    if rows.iter().any(|r| r.basis != last.basis) || args.patches.len() != 1 {
        return Err(CliError::Usage(format!(
            "{option} draws one fit: give one --family (or --spec) and one --patches"
        )));
    }
    Ok(last)
}

/// `volcano: WHAT of BASIS (SETTING), PU×PV patches, JOIN`.
fn title_of(grid: &Grid, row: &Row, what: &str) -> String {
    format!(
        "{}: {what} of {} ({}), {} patches, {:?}",
        grid.name,
        row.basis,
        row.setting,
        Patches(row.fit.patches.0, row.fit.patches.1),
        row.fit.join
    )
}

/// The fitted surface as patches for the surface writer: patch `(a, b)` is
/// the fitted heights at the grid points around it (`u = i/(r − 1)` from the
/// last at or before `a/p_u` to the first at or after `(a + 1)/p_u`,
/// likewise `v`), at `x = i·spacing`,
/// `y = j·spacing`; no control net is drawn (the fit's control heights
/// have no positions in the plane).
fn fitted_figure(title: String, fit: &SurfaceFit, spacing: f64) -> SurfaceFigure {
    let (r, c) = fit.fitted.shape();
    let (pu, pv) = fit.patches;
    // from the grid line at or before the patch's start to the one at or
    // after its end, so neighbouring patches meet without a gap
    let covered = |n: usize, p: usize, k: usize| -> Vec<usize> {
        let (first, last) = (k * (n - 1) / p, ((k + 1) * (n - 1)).div_ceil(p));
        (first..=last).collect()
    };
    let patches = (0..pu)
        .flat_map(|a| (0..pv).map(move |b| (a, b)))
        .zip(PATCH_COLOURS.iter().cycle())
        .map(|((a, b), rgb)| SurfacePatch {
            grid: covered(r, pu, a)
                .into_iter()
                .map(|i| {
                    covered(c, pv, b)
                        .into_iter()
                        .map(|j| [i as f64 * spacing, j as f64 * spacing, fit.fitted[(i, j)]])
                        .collect()
                })
                .collect(),
            net: Vec::new(),
            rgb: *rgb,
        })
        .collect();
    SurfaceFigure {
        title,
        patches,
        view: View::default(),
    }
}

fn number(x: f64) -> Rendered {
    Rendered::number(&format!("{x:.4}"))
}

fn words(s: &str) -> Rendered {
    Rendered {
        text: s.to_string(),
        unicode: s.to_string(),
        latex: format!("\\text{{{}}}", trig_tex::text(s)),
    }
}

fn stats_cells(s: &Stats) -> Vec<Rendered> {
    vec![
        Rendered::number(&s.points.to_string()),
        number(s.max),
        number(s.mean),
        number(s.rms),
    ]
}

/// The comparison, then (unless `--summary`) one table per fit with its
/// patches.
fn blocks(args: &FitSurfaceArgs, rows: &[Row]) -> Vec<Block> {
    let comparison = Block {
        title: "Comparison: |S(uᵢ, vⱼ) − zᵢⱼ| over the whole grid".into(),
        corner: "Basis".into(),
        columns: [
            "Parameters",
            "Patches",
            "Coefficients",
            "Points",
            "Max",
            "Mean",
            "RMS",
        ]
        .map(String::from)
        .to_vec(),
        rows: rows
            .iter()
            .map(|r| {
                let mut cells = vec![
                    words(&chosen(r)),
                    words(&Patches(r.fit.patches.0, r.fit.patches.1).to_string()),
                    Rendered::number(&r.fit.coefficients.to_string()),
                ];
                cells.extend(stats_cells(&r.fit.overall));
                (r.basis.clone(), cells)
            })
            .collect(),
    };
    let mut out = vec![comparison];
    if args.summary {
        return out;
    }
    for r in rows {
        let mut patches: Vec<(String, Vec<Rendered>)> = r
            .fit
            .per_patch
            .iter()
            .map(|p| {
                (
                    format!("({}, {})", p.patch.0 + 1, p.patch.1 + 1),
                    stats_cells(&p.stats),
                )
            })
            .collect();
        patches.push(("TOTAL".into(), stats_cells(&r.fit.overall)));
        out.push(Block {
            title: format!(
                "{} ({}), {} patches",
                r.basis,
                chosen(r),
                Patches(r.fit.patches.0, r.fit.patches.1)
            ),
            corner: "Patch (along u, along v)".into(),
            columns: ["Points", "Max", "Mean", "RMS"].map(String::from).to_vec(),
            rows: patches,
        });
    }
    out
}

/// The setting, with the values an optimisation chose: per direction one
/// set of values (when every segment has the same), else each segment's,
/// separated by ` / `.
fn chosen(r: &Row) -> String {
    if !r.optimised {
        return r.setting.clone();
    }
    let show = |segments: &[Vec<f64>]| {
        let each: Vec<String> = segments
            .iter()
            .map(|p| {
                p.iter()
                    .map(|v| format!("{v:.4}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            })
            .collect();
        if each.iter().all(|e| *e == each[0]) {
            each[0].clone()
        } else {
            each.join(" / ")
        }
    };
    let (pu, pv) = &r.fit.params;
    format!("{}: u {}, v {}", r.setting, show(pu), show(pv))
}
