//! `trig-audit join`: the control points of a second segment that a C⁰–C³,
//! G¹ or G² join forces, derived exactly (`trig_deriv::solve_join`).

use clap::{Args, ValueEnum};
use serde_json::json;
use trig_core::Described;
use trig_deriv::{End, JoinKind, JoinSetup, Wrt, solve_join, vanishing};
use trig_judge::domain::end_text;
use trig_symbolic::{Style, Sym};

use super::table::WrtArg;
use super::{CliError, CmdResult};
use crate::cell::Cell;
use crate::format;
use crate::names::{names_of, segment_copies};
use trig_specfile::AnyBasis;

pub mod cylinder;
pub mod surface;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ParamsArg {
    /// One parameter value shared by both segments.
    Same,
    /// Each segment has its own parameters (suffix 1 for the first, 2 for the second).
    Different,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum JoinFormat {
    Text,
    Tex,
    Json,
}

#[derive(Debug, Args)]
pub struct JoinArgs {
    /// Family id (see `trig-audit list`).
    #[arg(required_unless_present = "spec", conflicts_with = "spec")]
    family: Option<String>,
    /// A spec file (TOML) defining the basis instead of a catalog family (docs/spec.md).
    #[arg(long, value_name = "FILE")]
    spec: Option<std::path::PathBuf>,
    /// Join kind: c0, c1, c2, c3, g1 (Q₂'(0) = α Q₁'(1)) or g2 (and Q₂''(0) = α² Q₁''(1) + β Q₁'(1)).
    #[arg(long)]
    kind: String,
    /// Shape parameters of the two segments.
    #[arg(long, value_enum, default_value = "same")]
    params: ParamsArg,
    /// Derivative convention: angle θ, u (θ = πu/2), or x with interval lengths h1, h2.
    #[arg(long, value_enum, default_value = "angle")]
    wrt: WrtArg,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    format: JoinFormat,
    #[command(flatten)]
    pub surface: super::surface::SurfaceArgs,
    /// With --surface: the boundary the patches share (u: u = 1 of the
    /// first is u = 0 of the second; v likewise).
    #[arg(long, value_enum, default_value = "u", requires = "surface")]
    across: surface::Across,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

/// The solved join, ready to print.
struct Solved {
    family: AnyBasis,
    kind: JoinKind,
    wrt: Wrt,
    first_params: Vec<Sym>,
    second_params: Vec<Sym>,
    /// `(point, formula, singular where)`.
    forced: Vec<(Sym, Sym, Vec<String>)>,
    names: Vec<String>,
    /// The letters of the two segments' control points (`P`, `Q`).
    curves: [String; 2],
    /// The symbols of the `G` factors (`α`, `β`).
    factors: [Sym; 2],
    /// The symbols of the interval lengths (`h₁`, `h₂`; used in `x`).
    lengths: [Sym; 2],
    /// The `G²` factor `β` and the value a condition without a free control
    /// point fixes (`trig_deriv::Join::factor`).
    factor: Option<(Sym, Sym)>,
}

/// The letter of control points `P0, P1, …`.
fn letter(points: &[Sym]) -> String {
    points.first().map_or_else(String::new, |p| {
        p.to_string()
            .trim_end_matches(|c: char| c.is_ascii_digit())
            .to_string()
    })
}

pub fn run(args: &JoinArgs) -> CmdResult {
    args.surface.check()?;
    let family = AnyBasis::open(args.family.as_deref(), args.spec.as_deref())?;
    let kind: JoinKind = args
        .kind
        .parse()
        .map_err(|e: trig_deriv::JoinError| CliError::Usage(e.to_string()))?;
    if args.surface.surface {
        return surface::run(args, family, kind);
    }
    let solved = solve(family, kind, args.params, args.wrt.into())?;
    Ok(match args.format {
        JoinFormat::Text => text(&solved),
        JoinFormat::Tex => tex(&solved),
        JoinFormat::Json => format::json(&json_value(&solved)),
    })
}

fn solve(
    family: AnyBasis,
    kind: JoinKind,
    params: ParamsArg,
    wrt: Wrt,
) -> Result<Solved, CliError> {
    // every symbol below reads differently from the basis's own names
    let mut namespace = names_of(&family);
    let (first_params, second_params) = match params {
        ParamsArg::Same => {
            let p: Vec<Sym> = family.param_names().iter().map(|p| Sym::var(p)).collect();
            (p.clone(), p)
        }
        ParamsArg::Different => (
            segment_copies(&mut namespace, &family, 1)?,
            segment_copies(&mut namespace, &family, 2)?,
        ),
    };
    crate::cost::check_join(&family, kind, &first_params, &second_params)?;
    let n = family.function_names().len();
    let [first, second] = namespace.points(n);
    let factors = namespace.factors();
    let [h1, h2] = namespace.lengths();
    let setup = JoinSetup {
        basis: &family,
        first_params: &first_params,
        second_params: &second_params,
        wrt,
        h: (h1.clone(), h2.clone()),
        factors: factors.clone(),
    };
    let join =
        solve_join(&setup, kind, &first, &second).map_err(|e| CliError::Usage(e.to_string()))?;
    let names = first.iter().chain(&second).map(|p| p.to_string()).collect();
    let forced = join
        .forced
        .iter()
        .map(|f| {
            (
                second[f.index].clone(),
                f.value.clone(),
                vanishing(&f.pivot),
            )
        })
        .collect();
    Ok(Solved {
        family,
        kind,
        wrt,
        first_params,
        second_params,
        forced,
        names,
        curves: [letter(&first), letter(&second)],
        factors,
        lengths: [h1, h2],
        factor: join.factor,
    })
}

fn params_text(p: &[Sym]) -> String {
    if p.is_empty() {
        "none".to_string()
    } else {
        p.iter()
            .map(|x| x.to_unicode())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The conditions of `kind` between the curves `P`, `Q` with the `G`
/// factors `α`, `β` (as named in this output).
/// The conditions of `kind` at the ends `(a, b)` of the domain, the first
/// segment `p` ending where the second `q` starts.
fn conditions(
    kind: JoinKind,
    [p, q]: &[String; 2],
    [a, b]: &[String; 2],
    (start, end): (&str, &str),
) -> String {
    let (p1, q0) = (format!("{p}({end})"), format!("{q}({start})"));
    let d = |curve: &str, primes: &str, at: &str| format!("{curve}{primes}({at})");
    match kind {
        JoinKind::C(0) => format!("{q0} = {p1}"),
        JoinKind::C(k) => {
            let orders = match k {
                1 => "0, 1".to_string(),
                2 => "0, 1, 2".to_string(),
                _ => "0…3".to_string(),
            };
            format!(
                "{} = {}, j = {orders}",
                d(q, "⁽ʲ⁾", start),
                d(p, "⁽ʲ⁾", end)
            )
        }
        JoinKind::G1 => format!("{q0} = {p1}, {} = {a} {}", d(q, "'", start), d(p, "'", end)),
        JoinKind::G2 => format!(
            "{q0} = {p1}, {} = {a} {}, {} = {a}² {} + {b} {}",
            d(q, "'", start),
            d(p, "'", end),
            d(q, "''", start),
            d(p, "''", end),
            d(p, "'", end)
        ),
    }
}

fn header(s: &Solved) -> Vec<String> {
    let [p, q] = &s.curves;
    vec![
        format!("family: {} ({})", s.family.id(), s.family.citation()),
        format!(
            "join: {} — {}",
            s.kind,
            conditions(
                s.kind,
                &s.curves,
                &s.factors.clone().map(|f| f.to_unicode()),
                (
                    &end_text(&s.family, End::Start),
                    &end_text(&s.family, End::End)
                ),
            )
        ),
        format!("derivatives: {}", s.wrt.describe_on(&s.family.domain())),
        format!(
            "first segment {p}(·) = Σ b_i {p}_i, parameters: {}",
            params_text(&s.first_params)
        ),
        format!(
            "second segment {q}(·) = Σ b_i {q}_i, parameters: {}",
            params_text(&s.second_params)
        ),
    ]
}

/// Formulas with more characters (Unicode, on one line) are set one
/// control point per line, each coefficient factored (`Sym::combination_lines`).
const LONG_FORMULA: usize = 100;

/// The lines of a forced point's formula in `style`: one line, or one term
/// per line when the formula is longer than [`LONG_FORMULA`].
fn formula_lines(value: &Sym, s: &Solved, style: Style) -> Vec<String> {
    let names = &s.names;
    let one = value.combination(names);
    let factors: Vec<String> = s.factors.iter().map(ToString::to_string).collect();
    if one.unicode.chars().count() > LONG_FORMULA
        && let Some(lines) = value.combination_lines(names, &factors, style)
    {
        return lines;
    }
    vec![match style {
        Style::Latex => one.latex,
        Style::Plain => one.text,
        _ => one.unicode,
    }]
}

fn text(s: &Solved) -> String {
    let mut out = header(s).join("\n");
    out.push_str("\n\nforced control points:\n");
    for (point, value, singular) in &s.forced {
        let name = point.to_unicode();
        let indent = " ".repeat(name.chars().count() + 3);
        let formula = formula_lines(value, s, Style::Unicode).join(&format!("\n  {indent}"));
        out.push_str(&format!("  {name} = {formula}\n"));
        if !singular.is_empty() {
            out.push_str(&format!("    singular where {}\n", singular.join(", ")));
        }
    }
    if let Some((beta, value)) = &s.factor {
        out.push_str(&format!(
            "\n{FACTOR_NOTE}:\n  {} = {}\n",
            beta.to_unicode(),
            value.shortest_in(Style::Unicode)
        ));
    }
    out
}

/// What the line of a factor fixed by the join says.
const FACTOR_NOTE: &str = "the factor the join fixes (a condition with no free control point of the second segment, met for every control point by this value)";

fn tex(s: &Solved) -> String {
    let mut out: String = header(s).iter().map(|l| trig_tex::comment(l)).collect();
    let equations: Vec<(String, String)> = s
        .forced
        .iter()
        .map(|(point, value, _)| {
            let lines = formula_lines(value, s, Style::Latex);
            (point.to_latex(), lines.join(" \\\\\n&\\quad "))
        })
        .chain(
            s.factor
                .iter()
                .map(|(beta, value)| (beta.to_latex(), value.shortest_in(Style::Latex))),
        )
        .collect();
    if s.factor.is_some() {
        out.push_str(&trig_tex::comment(&format!("last line: {FACTOR_NOTE}")));
    }
    out.push_str(&trig_tex::align(&equations));
    for (point, _, singular) in &s.forced {
        if !singular.is_empty() {
            out.push_str(&trig_tex::comment(&format!(
                "{point}: singular where {}",
                singular.join(", ")
            )));
        }
    }
    out
}

fn json_value(s: &Solved) -> serde_json::Value {
    json!({
        "family": s.family.id(),
        "kind": s.kind.to_string(),
        "wrt": s.wrt.to_string(),
        "first_params": s.first_params.iter().map(|p| p.to_string()).collect::<Vec<_>>(),
        "second_params": s.second_params.iter().map(|p| p.to_string()).collect::<Vec<_>>(),
        "factors": s.factors.iter().map(|p| p.to_string()).collect::<Vec<_>>(),
        "lengths": if s.wrt == Wrt::X { json!(s.lengths.iter().map(|p| p.to_string()).collect::<Vec<_>>()) } else { json!(null) },
        "forced": s.forced.iter().map(|(point, value, singular)| json!({
            "point": point.to_string(),
            "formula": value.to_string(),
            "latex": value.combination(&s.names).latex,
            "lines": formula_lines(value, s, Style::Unicode),
            "latex_lines": formula_lines(value, s, Style::Latex),
            "singular_where": singular,
        })).collect::<Vec<_>>(),
        "factor": s.factor.as_ref().map(|(beta, value)| json!({
            "symbol": beta.to_string(),
            "formula": value.to_string(),
            "latex": value.shortest_in(Style::Latex),
            "note": FACTOR_NOTE,
        })),
    })
}
