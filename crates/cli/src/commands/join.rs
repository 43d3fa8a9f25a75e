//! `trig-audit join`: the control points of a second segment that a C⁰–C³,
//! G¹ or G² join forces, derived exactly (`trig_deriv::solve_join`).

use clap::{Args, ValueEnum};
use serde_json::json;
use trig_core::Described;
use trig_deriv::{JoinKind, JoinSetup, Wrt, solve_join, vanishing};
use trig_symbolic::Sym;

use super::table::WrtArg;
use super::{CliError, CmdResult};
use crate::cell::Cell;
use crate::format;
use trig_specfile::AnyBasis;

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
}

pub fn run(args: &JoinArgs) -> CmdResult {
    let family = AnyBasis::open(args.family.as_deref(), args.spec.as_deref())?;
    let kind: JoinKind = args
        .kind
        .parse()
        .map_err(|e: trig_deriv::JoinError| CliError::Usage(e.to_string()))?;
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
    let param_names = family.param_names();
    let names = |suffix: &str| -> Vec<Sym> {
        param_names
            .iter()
            .map(|p| Sym::var(&format!("{p}{suffix}")))
            .collect()
    };
    let (first_params, second_params) = match params {
        ParamsArg::Same => (names(""), names("")),
        ParamsArg::Different => (names("1"), names("2")),
    };
    let n = family.function_names().len();
    let first: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("P{i}"))).collect();
    let second: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("Q{i}"))).collect();
    let factors = family.join_factors();
    let setup = JoinSetup {
        basis: &family,
        first_params: &first_params,
        second_params: &second_params,
        wrt,
        h: (Sym::var("h1"), Sym::var("h2")),
        factors,
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

fn conditions(kind: JoinKind) -> &'static str {
    match kind {
        JoinKind::C(0) => "Q(0) = P(1)",
        JoinKind::C(1) => "Q⁽ʲ⁾(0) = P⁽ʲ⁾(1), j = 0, 1",
        JoinKind::C(2) => "Q⁽ʲ⁾(0) = P⁽ʲ⁾(1), j = 0, 1, 2",
        JoinKind::C(_) => "Q⁽ʲ⁾(0) = P⁽ʲ⁾(1), j = 0…3",
        JoinKind::G1 => "Q(0) = P(1), Q'(0) = α P'(1)",
        JoinKind::G2 => "Q(0) = P(1), Q'(0) = α P'(1), Q''(0) = α² P''(1) + β P'(1)",
    }
}

fn header(s: &Solved) -> Vec<String> {
    vec![
        format!("family: {} ({})", s.family.id(), s.family.citation()),
        format!("join: {} — {}", s.kind, conditions(s.kind)),
        format!("derivatives: {}", s.wrt.describe_on(&s.family.domain())),
        format!(
            "first segment P(·) = Σ b_i P_i, parameters: {}",
            params_text(&s.first_params)
        ),
        format!(
            "second segment Q(·) = Σ b_i Q_i, parameters: {}",
            params_text(&s.second_params)
        ),
    ]
}

fn text(s: &Solved) -> String {
    let mut out = header(s).join("\n");
    out.push_str("\n\nforced control points:\n");
    for (point, value, singular) in &s.forced {
        let formula = value.combination(&s.names).unicode;
        out.push_str(&format!("  {} = {formula}\n", point.to_unicode()));
        if !singular.is_empty() {
            out.push_str(&format!("    singular where {}\n", singular.join(", ")));
        }
    }
    out
}

fn tex(s: &Solved) -> String {
    let mut out: String = header(s).iter().map(|l| trig_tex::comment(l)).collect();
    let equations: Vec<(String, String)> = s
        .forced
        .iter()
        .map(|(point, value, _)| (point.to_latex(), value.combination(&s.names).latex))
        .collect();
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
        "forced": s.forced.iter().map(|(point, value, singular)| json!({
            "point": point.to_string(),
            "formula": value.to_string(),
            "latex": value.combination(&s.names).latex,
            "singular_where": singular,
        })).collect::<Vec<_>>(),
    })
}
