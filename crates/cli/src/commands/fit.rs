//! `trig-audit fit`: the thesis's Chapter 6 study on an outline data file —
//! per-method tables like Tables 6.2–6.13 and the comparison like Tables
//! 6.14–6.16, for one family or all six (thesis cubic, Majeed–Qayyum, Han,
//! Usman, Han as the Appendix 2 listing computes it, Bézier).

use std::fmt::Write;
use std::path::{Path, PathBuf};

use std::sync::Arc;

use clap::{Args, ValueEnum};
use trig_certify::range::EndPoint;
use trig_core::param::read_params;
use trig_core::{Described, End, Family};
use trig_fit::optimise::search_between;
use trig_fit::{
    Continuity, CornerRule, Corners, FitError, FitOptions, Metrics, NumericBasis, Outline,
    OutlineFit, Shape, Summary, THESIS_THRESHOLD, fit_outline,
};

use super::param_pairs;
use super::{CliError, CmdResult};
use trig_specfile::AnyBasis;

/// The families of `--family all`, in the thesis's order, then the
/// listing variant and the polynomial reference.
pub const COMPARED: [Family; 6] = [
    Family::ThesisCubic,
    Family::MajeedQayyum,
    Family::Han,
    Family::Usman,
    Family::HanListing,
    Family::Bernstein3,
];

/// The thesis's fixed shape parameter for every method (6.6).
const THESIS_PARAMETER: &str = "0.6";

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FitFormat {
    Md,
    Csv,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Refine {
    /// C¹ in each segment's own parameter t ∈ [0,1] (thesis (4.5)).
    C1,
    /// C¹ in the global chord-length parameter.
    C1Arc,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SearchRange {
    /// The published range of the parameter.
    Published,
    /// The published range intersected with the certified maximal
    /// nonnegativity interval (trig-judge).
    Certified,
}

/// The outline and how to fit it: shared by `fit` and `plot fit`.
#[derive(Debug, Args)]
pub struct FitSetup {
    /// Outline data file (`contour,x,y`, see data/glyphs/).
    #[arg(long)]
    glyph: PathBuf,
    /// Fit with the basis of this spec file (TOML, docs/spec.md; four
    /// functions interpolating their end control points) instead of a family.
    #[arg(long, value_name = "FILE")]
    pub spec: Option<PathBuf>,
    /// Shape parameter as name=value, read exactly (a rational or a rational
    /// multiple of pi such as alpha=pi/2; default: 0.6 for every family, as the thesis).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// The parameter --optimise searches per segment (name or printed
    /// symbol), the others fixed by --param (a catalog family's at 0.6);
    /// default: a basis's one parameter, or the one --param leaves free.
    #[arg(long, value_name = "NAME")]
    vary: Option<String>,
    /// Interval searched by --optimise.
    #[arg(long, value_enum, default_value = "certified")]
    range: SearchRange,
    /// C¹ refinement of the joined segments.
    #[arg(long, value_enum)]
    refine: Option<Refine>,
    /// Bad-point threshold on the squared error (thesis: 1.5).
    #[arg(long, default_value_t = THESIS_THRESHOLD, allow_hyphen_values = true)]
    threshold: f64,
    /// Explicit corners as global point indices (file order), comma separated;
    /// default: the automatic rule.
    #[arg(long, value_delimiter = ',')]
    corners: Vec<usize>,
    /// Automatic corners: minimum turning angle, degrees.
    #[arg(long, default_value_t = 45.0)]
    corner_angle: f64,
    /// Automatic corners: window, in points.
    #[arg(long, default_value_t = 3)]
    corner_window: usize,
    /// Longest run of points per segment (0: segments only at corners).
    #[arg(long, default_value_t = 50)]
    max_points: usize,
}

#[derive(Debug, Args)]
pub struct FitArgs {
    /// Family id, or `all` for the six compared families (not with --spec).
    #[arg(long, default_value = "all")]
    family: String,
    /// Also fit with the shape parameter optimised per segment (golden section;
    /// a basis with one shape parameter — with several, fit at fixed --param values).
    #[arg(long)]
    optimise: bool,
    #[command(flatten)]
    setup: FitSetup,
    /// Output format.
    #[arg(long, value_enum, default_value = "md")]
    format: FitFormat,
}

pub fn fit_err(e: FitError) -> CliError {
    match e {
        FitError::Core(c) => CliError::Core(c),
        other => CliError::Usage(other.to_string()),
    }
}

/// The bases selected by `--family` or `--spec`.
/// `--param NAME=VALUE` pairs, as read.
pub type ParamPairs = Vec<(String, String)>;

/// The selected bases ([`subjects`]) and the `--param NAME=VALUE` pairs,
/// each naming a parameter of at least one of them.
pub fn selected_with_params(
    id: &str,
    spec: Option<&Path>,
    params: &[String],
) -> Result<(Vec<AnyBasis>, ParamPairs), CliError> {
    let pairs = param_pairs(params)?;
    let selected = subjects(id, spec)?;
    for (name, _) in &pairs {
        if !selected.iter().any(|s| {
            parameters(s)
                .iter()
                .any(|(n, symbol, _)| n == name || symbol == name)
        }) {
            return Err(CliError::Usage(format!(
                "--param {name}: no selected basis has a parameter `{name}`"
            )));
        }
    }
    Ok((selected, pairs))
}

pub fn subjects(id: &str, spec: Option<&Path>) -> Result<Vec<AnyBasis>, CliError> {
    if let Some(path) = spec {
        if id != "all" {
            return Err(CliError::Usage(
                "--family and --spec exclude each other: give one basis".into(),
            ));
        }
        return Ok(vec![AnyBasis::open(None, Some(path))?]);
    }
    if id == "all" {
        Ok(COMPARED.iter().map(|f| AnyBasis::Family(*f)).collect())
    } else {
        Ok(vec![AnyBasis::Family(AnyBasis::family(id)?)])
    }
}

/// The parameters of `subject`: ASCII name, printed symbol, published range
/// as the closed search interval's ends `(value, open)` when bounded.
pub fn parameters(subject: &AnyBasis) -> Vec<(String, String, Option<SearchEnds>)> {
    subject
        .parameters()
        .into_iter()
        .map(|p| {
            let scale = if p.range.pi {
                std::f64::consts::PI
            } else {
                1.0
            };
            let end = |e: &End| {
                e.value()
                    .map(|v| (v.to_f64() * scale, matches!(e, End::Open(_))))
            };
            let ends = end(&p.range.lo).zip(end(&p.range.hi));
            (p.name, p.symbol, ends)
        })
        .collect()
}

/// A published range's ends for the search: `((lo, open), (hi, open))`.
pub type SearchEnds = ((f64, bool), (f64, bool));

/// Fixed parameters of `subject` from `--param` pairs (a catalog family's
/// default 0.6, as the thesis; a spec file's parameters must be given),
/// each checked against its published range: every parameter but
/// `except` (the one searched), by index; outside it only when
/// `allow_outside`.
pub fn fixed_params(
    subject: &AnyBasis,
    pairs: &[(String, String)],
    except: Option<usize>,
    allow_outside: bool,
) -> Result<Vec<(usize, f64)>, CliError> {
    let mut out = Vec::new();
    for (k, p) in subject.parameters().into_iter().enumerate() {
        if Some(k) == except {
            continue;
        }
        let (name, symbol) = (p.name.clone(), p.symbol.clone());
        let given = pairs
            .iter()
            .rev()
            .find(|(n, _)| *n == name || *n == symbol)
            .map(|(_, v)| v.clone());
        let value = match (given, subject.as_family()) {
            (Some(v), _) => v,
            (None, Some(_)) => THESIS_PARAMETER.to_string(),
            (None, None) => {
                return Err(CliError::Usage(format!(
                    "`{}`: give --param {name}=VALUE (a spec file's parameters have no default)",
                    subject.id()
                )));
            }
        };
        let value = read_params(&subject.id(), &[p], &[(name, value)], allow_outside)?;
        out.extend(value.iter().map(|v| (k, v.to_f64())));
    }
    Ok(out)
}

/// The parameter `--optimise` searches in `subject`: `--vary`'s (its
/// `--param` value, if any, is the fixed fit's), else its one parameter,
/// else the one `--param` leaves free (none when several are, or none).
pub fn searched(
    subject: &AnyBasis,
    pairs: &[(String, String)],
    vary: Option<&str>,
) -> Result<Option<usize>, CliError> {
    let params = parameters(subject);
    let named = |name: &str, k: usize| params[k].0 == name || params[k].1 == name;
    let fixed = |k: usize| pairs.iter().any(|(n, _)| named(n, k));
    if let Some(name) = vary {
        return match (0..params.len()).find(|&k| named(name, k)) {
            Some(k) => Ok(Some(k)),
            None => Err(CliError::Usage(format!(
                "--vary {name}: `{}` has no parameter `{name}`",
                subject.id()
            ))),
        };
    }
    let free: Vec<usize> = (0..params.len()).filter(|&k| !fixed(k)).collect();
    Ok(match (params.len(), free.as_slice()) {
        (1, _) => Some(0),
        (_, [k]) => Some(*k),
        _ => None,
    })
}

/// The search interval of `--optimise` for the parameter `index`, and
/// where it comes from.
pub fn interval(
    subject: &AnyBasis,
    index: usize,
    range: SearchRange,
) -> Result<(f64, f64, &'static str), CliError> {
    let mut params = parameters(subject);
    let several = params.len() > 1;
    let (name, _, ends) = params.swap_remove(index);
    let Some((lo, hi)) = ends else {
        return Err(CliError::Usage(format!(
            "`{}`: the range of {name} is unbounded: no search interval",
            subject.id()
        )));
    };
    let (lo, hi) = search_between(lo, hi);
    let family = match (subject, range) {
        (_, SearchRange::Published) => return Ok((lo, hi, "published range")),
        (_, SearchRange::Certified) if several => {
            return Ok((
                lo,
                hi,
                "published range: certified ranges are computed for one-parameter catalog families",
            ));
        }
        (AnyBasis::Spec(_), SearchRange::Certified) => {
            return Ok((
                lo,
                hi,
                "published range: certified ranges are computed for catalog families",
            ));
        }
        (AnyBasis::Family(f), SearchRange::Certified) => *f,
    };
    let (certified, _) = trig_judge::certificate::maximal_versus_published(&family);
    // the certified side of each end (an irrational end by the inner side
    // of its isolating interval)
    let end = |e: &EndPoint| match e {
        EndPoint::Exact { inside, value, .. } => Some(
            value
                .rational
                .as_ref()
                .map_or_else(|| inside.to_f64(), |q| q.to_f64()),
        ),
        EndPoint::Bracket { ok, .. } => Some(ok.to_f64()),
        EndPoint::Unbounded | EndPoint::Undecided { .. } => None,
    };
    let clo = end(&certified.lo).map_or(lo, |v| v.max(lo));
    let chi = end(&certified.hi).map_or(hi, |v| v.min(hi));
    if clo > chi {
        return Err(CliError::Usage(format!(
            "`{}`: the certified nonnegativity interval does not meet the published range {}",
            family.info().id,
            family.info().params[0].range
        )));
    }
    Ok((clo, chi, "certified range"))
}

/// One fitted method: basis, how its parameter was chosen, the fit.
#[derive(Debug)]
pub struct Method {
    pub label: String,
    pub setting: String,
    /// The parameter shown per segment: the one searched, or the first
    /// (its index and printed symbol; none without parameters).
    pub shown: Option<(usize, String)>,
    /// The printed symbols of every shape parameter, in order.
    pub symbols: Vec<String>,
    pub fit: OutlineFit,
}

/// Which fits to run: the fixed parameter, the optimised one, or both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Runs {
    Fixed,
    Optimised,
    Both,
}

/// Reads the outline and fits it with every selected basis.
pub fn prepare(
    setup: &FitSetup,
    family: &str,
    runs: Runs,
) -> Result<(Outline, Vec<Method>), CliError> {
    let outline = Outline::read(&setup.glyph).map_err(fit_err)?;
    let (selected, pairs) = selected_with_params(family, setup.spec.as_deref(), &setup.params)?;
    if setup.corners.is_empty() && (setup.corner_window == 0 || !setup.corner_angle.is_finite()) {
        return Err(CliError::Usage(
            "--corner-window must be ≥ 1 and --corner-angle finite".into(),
        ));
    }
    let corners = if setup.corners.is_empty() {
        Corners::Auto(CornerRule {
            window: setup.corner_window,
            min_angle_deg: setup.corner_angle,
        })
    } else {
        Corners::Explicit(setup.corners.clone())
    };
    let options = |shape: Shape| FitOptions {
        corners: corners.clone(),
        max_points: setup.max_points,
        threshold: setup.threshold,
        refine: setup.refine.map(|r| match r {
            Refine::C1 => Continuity::Local,
            Refine::C1Arc => Continuity::ArcLength,
        }),
        shape,
    };
    if setup.vary.is_some() && runs == Runs::Fixed {
        return Err(CliError::Usage(
            "--vary chooses the parameter --optimise searches: give --optimise".into(),
        ));
    }
    let mut found = Vec::new();
    for s in &selected {
        found.push(searched(s, &pairs, setup.vary.as_deref())?);
    }
    // the golden-section search optimises one shape parameter: say so
    // rather than print no optimised fit
    if runs != Runs::Fixed && found.iter().all(Option::is_none) {
        let why: Vec<String> = selected
            .iter()
            .map(|s| {
                let symbols: Vec<String> = parameters(s)
                    .iter()
                    .map(|(_, sym, _)| sym.clone())
                    .collect();
                match symbols.len() {
                    0 => format!("`{}` has no shape parameter", s.id()),
                    n => format!("`{}` has {n} ({})", s.id(), symbols.join(", ")),
                }
            })
            .collect();
        return Err(CliError::Usage(format!(
            "--optimise searches one shape parameter per segment (golden section); {}: fix all but one with --param NAME=VALUE (--vary NAME names the one searched), or fit with fixed values only",
            why.join("; ")
        )));
    }
    let mut methods = Vec::new();
    for (subject, searched) in selected.into_iter().zip(found) {
        let params = parameters(&subject);
        let symbols: Vec<String> = params.iter().map(|(_, s, _)| s.clone()).collect();
        let basis: Arc<dyn NumericBasis> = Arc::new(subject.clone());
        let optimise = (runs != Runs::Fixed).then_some(searched).flatten();
        if runs != Runs::Optimised || optimise.is_none() {
            let fixed: Vec<f64> = fixed_params(&subject, &pairs, None, false)?
                .into_iter()
                .map(|(_, v)| v)
                .collect();
            let setting = params
                .iter()
                .zip(&fixed)
                .map(|((_, s, _), v)| format!("{s} = {v}"))
                .collect::<Vec<_>>()
                .join(", ");
            methods.push(Method {
                label: subject.id(),
                setting: if setting.is_empty() {
                    "—".into()
                } else {
                    setting
                },
                shown: symbols.first().map(|s| (0, s.clone())),
                symbols: symbols.clone(),
                fit: fit_outline(&outline, basis.clone(), &options(Shape::Fixed(fixed)))
                    .map_err(fit_err)?,
            });
        }
        if let Some(index) = optimise {
            let (lo, hi, from) = interval(&subject, index, setup.range)?;
            let fixed = fixed_params(&subject, &pairs, Some(index), false)?;
            let others: Vec<String> = fixed
                .iter()
                .map(|(k, v)| format!(", {} = {v}", symbols[*k]))
                .collect();
            methods.push(Method {
                label: subject.id(),
                setting: format!(
                    "{} optimised in [{lo}, {hi}] ({from}){}",
                    symbols[index],
                    others.concat()
                ),
                shown: Some((index, symbols[index].clone())),
                symbols,
                fit: fit_outline(&outline, basis, &options(Shape::Optimise { lo, hi, fixed }))
                    .map_err(fit_err)?,
            });
        }
    }
    Ok((outline, methods))
}

pub fn run(args: &FitArgs) -> CmdResult {
    let runs = if args.optimise {
        Runs::Both
    } else {
        Runs::Fixed
    };
    let (outline, methods) = prepare(&args.setup, &args.family, runs)?;
    match args.format {
        FitFormat::Md => Ok(markdown(&args.setup, &outline, &methods)),
        FitFormat::Csv => csv(&methods),
        FitFormat::Json => Ok(json(&args.setup, &outline, &methods)),
    }
}

fn g(x: f64) -> String {
    format!("{x:.4}")
}

fn corner_text(args: &FitSetup) -> String {
    if args.corners.is_empty() {
        format!(
            "automatic (turning angle ≥ {}° over a window of {} points)",
            args.corner_angle, args.corner_window
        )
    } else {
        format!("explicit {:?}", args.corners)
    }
}

fn markdown(args: &FitSetup, outline: &Outline, methods: &[Method]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Fit of `{}` ({})\n",
        outline.name,
        args.glyph.display()
    );
    for line in &outline.provenance {
        let _ = writeln!(out, "> {line}  ");
    }
    let first = &methods[0].fit;
    let corners = first
        .segments
        .iter()
        .filter(|s| s.span.start_corner)
        .count();
    let _ = writeln!(
        out,
        "\n{} points in {} contour(s); {} segments; corners: {} — {} found; at most {} points per segment; squared errors ‖F(tᵢ) − Pᵢ‖² (6.7); bad points: > {}; refinement: {}.\n",
        outline.point_count(),
        outline.contours.len(),
        first.segments.len(),
        corner_text(args),
        corners,
        args.max_points,
        args.threshold,
        match first.continuity {
            None => "none",
            Some(Continuity::Local) => "C¹ in each segment's parameter (thesis (4.5))",
            Some(Continuity::ArcLength) => "C¹ in the chord-length parameter",
        }
    );
    for m in methods {
        let _ = writeln!(out, "## {} ({})\n", m.label, m.setting);
        let refined = m.fit.after.is_some();
        let mut head = vec!["Segment", "Points"];
        if let Some((_, p)) = &m.shown {
            head.push(p);
        }
        head.extend(["Total (C⁰)", "Max (C⁰)", "Ave (C⁰)", "Bad (C⁰)"]);
        if refined {
            head.extend(["Total (C¹)", "Max (C¹)", "Min (C¹)", "Ave (C¹)", "Bad (C¹)"]);
        }
        let _ = writeln!(out, "| {} |", head.join(" | "));
        let _ = writeln!(out, "|{}", "---|".repeat(head.len()));
        for (k, s) in m.fit.segments.iter().enumerate() {
            let mut row = vec![(k + 1).to_string(), s.metrics.points.to_string()];
            if let Some((j, _)) = &m.shown {
                row.push(format!("{:.4}", s.params[*j]));
            }
            row.extend(metric_cells(&s.metrics));
            if let Some((_, a)) = &s.refined {
                row.extend(after_cells(a));
            }
            let _ = writeln!(out, "| {} |", row.join(" | "));
        }
        let mut total = vec!["TOTAL".to_string(), m.fit.before.points.to_string()];
        if m.shown.is_some() {
            total.push(String::new());
        }
        total.extend(summary_cells(&m.fit.before, false));
        if let Some(a) = &m.fit.after {
            total.extend(summary_cells(a, true));
        }
        let _ = writeln!(out, "| {} |\n", total.join(" | "));
    }
    let _ = writeln!(out, "## Comparison\n");
    let _ = writeln!(
        out,
        "Ave = mean of the segment averages (the thesis's TOTAL rows and Tables 6.14–6.16); Ave/pt = total / points.\n"
    );
    let _ = writeln!(
        out,
        "| Method | Parameter | Stage | Total | Max | Min | Ave | Ave/pt | Bad (> {}) |",
        args.threshold
    );
    let _ = writeln!(out, "|---|---|---|---|---|---|---|---|---|");
    for m in methods {
        for (stage, s) in stages(&m.fit) {
            let _ = writeln!(
                out,
                "| {} | {} | {stage} | {} | {} | {} | {} | {} | {} |",
                m.label,
                m.setting,
                g(s.total),
                g(s.max),
                g(s.min),
                g(s.mean_segment_average),
                g(s.average),
                s.bad
            );
        }
    }
    out
}

fn stages(fit: &OutlineFit) -> Vec<(&'static str, Summary)> {
    std::iter::once(("C⁰", fit.before))
        .chain(fit.after.map(|a| ("C¹", a)))
        .collect()
}

fn metric_cells(m: &Metrics) -> Vec<String> {
    vec![g(m.total), g(m.max), g(m.average), m.bad.to_string()]
}

fn after_cells(m: &Metrics) -> Vec<String> {
    vec![
        g(m.total),
        g(m.max),
        g(m.min),
        g(m.average),
        m.bad.to_string(),
    ]
}

fn summary_cells(s: &Summary, with_min: bool) -> Vec<String> {
    let mut v = vec![g(s.total), g(s.max)];
    if with_min {
        v.push(g(s.min));
    }
    v.extend([g(s.mean_segment_average), s.bad.to_string()]);
    v
}

fn csv(methods: &[Method]) -> CmdResult {
    let mut rows: Vec<Vec<String>> = Vec::new();
    for m in methods {
        for (k, s) in m.fit.segments.iter().enumerate() {
            let p = m
                .shown
                .as_ref()
                .map_or(String::new(), |(k, _)| s.params[*k].to_string());
            let mut stages = vec![("C0", s.metrics)];
            if let Some((_, a)) = s.refined {
                stages.push(("C1", a));
            }
            for (stage, r) in stages {
                rows.push(vec![
                    m.label.to_string(),
                    m.setting.to_string(),
                    stage.into(),
                    (k + 1).to_string(),
                    r.points.to_string(),
                    p.clone(),
                    r.total.to_string(),
                    r.max.to_string(),
                    r.min.to_string(),
                    r.average.to_string(),
                    r.bad.to_string(),
                ]);
            }
        }
        for (stage, s) in stages(&m.fit) {
            let stage = if stage == "C⁰" { "C0" } else { "C1" };
            rows.push(vec![
                m.label.to_string(),
                m.setting.to_string(),
                stage.into(),
                "total".into(),
                s.points.to_string(),
                String::new(),
                s.total.to_string(),
                s.max.to_string(),
                s.min.to_string(),
                s.mean_segment_average.to_string(),
                s.bad.to_string(),
            ]);
        }
    }
    crate::format::csv_text(
        &[
            "method",
            "setting",
            "stage",
            "segment",
            "points",
            "parameter",
            "total",
            "max",
            "min",
            "average",
            "bad",
        ],
        rows.iter().map(|r| r.iter().map(String::as_str)),
    )
}

fn json(args: &FitSetup, outline: &Outline, methods: &[Method]) -> String {
    let value = serde_json::json!({
        "glyph": args.glyph.display().to_string(),
        "provenance": outline.provenance,
        "points": outline.point_count(),
        "corners": corner_text(args),
        "threshold": args.threshold,
        "methods": methods.iter().map(|m| serde_json::json!({
            "family": m.label,
            "setting": m.setting,
            "fit": m.fit,
        })).collect::<Vec<_>>(),
    });
    crate::format::json(&value)
}
