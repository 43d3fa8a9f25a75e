//! `trig-audit interp`: a positivity-preserving interpolant of thesis 4.3 on
//! one of its data tables — the pieces (control points, parameters), the
//! exact derivative jumps at the interior knots, and the certified minimum
//! of every piece.

use std::fmt::Write;

use clap::{Args, ValueEnum};
use rug::Rational;
use serde_json::json;
use trig_certify::algebraic::decimal;
use trig_interp::{
    DataSet, InterpError, Interval, KnotJump, PieceMinimum, Scheme, Spline, Variant, build,
    certified_minimum, knot_jumps,
};
use trig_symbolic::Sym;

use super::{CliError, CmdResult};
use crate::format::json;

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum InterpFormat {
    Text,
    Md,
    Json,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum InterpVariant {
    /// The scheme's formulas as printed.
    Printed,
    /// Corrected where the print is wrong (C²: interior slopes from the C² conditions; G²: join solved from (4.33)).
    Corrected,
}

#[derive(Debug, Args)]
pub struct InterpArgs {
    /// Data set: thesis-table-4.1 … thesis-table-4.6.
    #[arg(long)]
    data: String,
    /// Scheme: c1, c2, g1 or g2.
    #[arg(long)]
    scheme: String,
    /// Printed formulas or the corrected scheme.
    #[arg(long, value_enum, default_value = "printed")]
    variant: InterpVariant,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    format: InterpFormat,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

fn usage(e: InterpError) -> CliError {
    CliError::Usage(e.to_string())
}

fn approx(x: &Sym) -> f64 {
    x.eval(&0.0_f64, &|n: &str| {
        (n == "pi").then_some(std::f64::consts::PI)
    })
    .unwrap_or(f64::NAN)
}

fn factors(data: &DataSet, i: usize) -> String {
    data.params
        .iter()
        .map(|(name, col)| format!("{name} = {}", col[i]))
        .collect::<Vec<_>>()
        .join(", ")
}

fn order(k: &KnotJump<Sym>) -> String {
    k.continuity_order()
        .map_or("discontinuous".to_string(), |o| format!("C{o}"))
}

fn bracket(m: &PieceMinimum) -> (String, String) {
    (
        m.lower
            .as_ref()
            .map_or("undecided".to_string(), |l| decimal(l, 6, false)),
        decimal(&m.upper, 6, true),
    )
}

fn verdict(minima: &[PieceMinimum]) -> &'static str {
    if minima.iter().all(PieceMinimum::nonnegative) {
        "certified ≥ 0 on the whole interval"
    } else if minima.iter().any(PieceMinimum::negative) {
        "certified negative somewhere"
    } else {
        "undecided"
    }
}

pub fn run(args: &InterpArgs) -> CmdResult {
    let data = DataSet::named(&args.data).map_err(usage)?;
    let scheme: Scheme = args.scheme.parse().map_err(usage)?;
    let variant = match args.variant {
        InterpVariant::Printed => Variant::Printed,
        InterpVariant::Corrected => Variant::Corrected,
    };
    let exact = build(&data, scheme, variant, &Sym::zero()).map_err(usage)?;
    let enclosed =
        build(&data, scheme, variant, &Interval::point(Rational::new())).map_err(usage)?;
    let minima = certified_minimum(&enclosed, &trig_judge::interpolant::prove).map_err(usage)?;
    let jumps = knot_jumps(&exact);
    Ok(match args.format {
        InterpFormat::Json => render_json(&exact, &jumps, &minima),
        InterpFormat::Text | InterpFormat::Md => render_text(
            &exact,
            &jumps,
            &minima,
            matches!(args.format, InterpFormat::Md),
        ),
    })
}

fn render_json(s: &Spline<Sym>, jumps: &[KnotJump<Sym>], minima: &[PieceMinimum]) -> String {
    let t = &s.data.table;
    json(&json!({
        "data": t.name,
        "caption": t.caption,
        "citation": t.citation,
        "scheme": s.scheme.to_string(),
        "scheme_source": s.scheme.source(),
        "variant": s.variant.to_string(),
        "derivative_estimates": s.slopes.iter().map(|d| json!({"exact": d.to_string(), "approx": approx(d)})).collect::<Vec<_>>(),
        "pieces": s.pieces.iter().enumerate().map(|(i, p)| json!({
            "interval": [p.x0.to_string(), (p.x0.clone() + &p.h).to_string()],
            "parameters": s.data.params.iter().map(|(n, c)| (n.to_string(), json!(c[i].to_string()))).collect::<serde_json::Map<_, _>>(),
            "control_points": p.points.iter().map(|v| json!({"exact": v.to_string(), "approx": approx(v)})).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "m_outside_range": s.m_outside_range().iter().map(|(i, m)| json!({"piece": i + 1, "m": m.to_string()})).collect::<Vec<_>>(),
        "knots": jumps.iter().map(|k| json!({
            "x": k.x.to_string(),
            "jumps": k.jumps.iter().map(|j| json!({"exact": j.to_string(), "approx": approx(j)})).collect::<Vec<_>>(),
            "continuity": order(k),
        })).collect::<Vec<_>>(),
        "minimum": minima.iter().map(|m| {
            let (lo, hi) = bracket(m);
            json!({"piece": m.piece + 1, "lower": lo, "upper": hi, "x": m.x, "z": m.z.to_string(),
                   "undecided": m.undecided})
        }).collect::<Vec<_>>(),
        "positivity": verdict(minima),
    }))
}

fn render_text(
    s: &Spline<Sym>,
    jumps: &[KnotJump<Sym>],
    minima: &[PieceMinimum],
    md: bool,
) -> String {
    let t = &s.data.table;
    let mut out = String::new();
    let heading = |out: &mut String, text: &str| {
        let _ = if md {
            writeln!(out, "\n## {text}\n")
        } else {
            writeln!(out, "\n{text}:")
        };
    };
    let _ = writeln!(
        out,
        "{}{} — {} scheme ({}), {}",
        if md { "# " } else { "" },
        t.caption,
        s.scheme,
        s.scheme.source(),
        s.variant
    );
    let _ = writeln!(
        out,
        "{}data: {} ({})",
        if md { "\n" } else { "" },
        t.name,
        t.citation
    );
    heading(
        &mut out,
        "derivative estimates d_i (arithmetic mean method)",
    );
    for (i, d) in s.slopes.iter().enumerate() {
        let _ = writeln!(
            out,
            "{}d_{} = {d} ≈ {:.6}",
            if md { "- " } else { "  " },
            i + 1,
            approx(d)
        );
    }
    heading(&mut out, "pieces (control points V_i, W_i, X_i, Y_i)");
    if md {
        let _ = writeln!(
            out,
            "| piece | interval | parameters | V_i | W_i | X_i | Y_i |\n|---|---|---|---|---|---|---|"
        );
    }
    for (i, p) in s.pieces.iter().enumerate() {
        let x1 = p.x0.clone() + &p.h;
        let pts: Vec<String> = p
            .points
            .iter()
            .map(|v| format!("{v} ≈ {:.6}", approx(v)))
            .collect();
        if md {
            let _ = writeln!(
                out,
                "| {} | [{}, {x1}] | {} | {} |",
                i + 1,
                p.x0,
                factors(&s.data, i),
                pts.join(" | ")
            );
        } else {
            let _ = writeln!(
                out,
                "  piece {} on [{}, {x1}], {}:",
                i + 1,
                p.x0,
                factors(&s.data, i)
            );
            for (name, v) in ["V", "W", "X", "Y"].iter().zip(&pts) {
                let _ = writeln!(out, "    {name} = {v}");
            }
        }
    }
    for (i, m) in s.m_outside_range() {
        let _ = writeln!(out, "  note: piece {} has m = {m}, outside (−2, 1]", i + 1);
    }
    heading(
        &mut out,
        "knot jumps (right − left) of P, P', P'', P''' in x",
    );
    for k in jumps {
        let js: Vec<String> = k
            .jumps
            .iter()
            .map(|j| {
                if j.is_zero() {
                    "0".into()
                } else {
                    format!("{j} ≈ {:.6}", approx(j))
                }
            })
            .collect();
        let _ = writeln!(
            out,
            "{}x = {}: [{}] → {}",
            if md { "- " } else { "  " },
            k.x,
            js.join("; "),
            order(k)
        );
    }
    heading(&mut out, "certified minimum per piece");
    for m in minima {
        let (lo, hi) = bracket(m);
        let _ = writeln!(
            out,
            "{}piece {}: min ∈ [{lo}, {hi}] at x ≈ {:.6} (z = tan(θ/2) = {}){}",
            if md { "- " } else { "  " },
            m.piece + 1,
            m.x,
            m.z,
            m.undecided
                .as_ref()
                .map_or(String::new(), |w| format!(" — {w}"))
        );
    }
    let _ = writeln!(
        out,
        "{}positivity: {}",
        if md { "\n" } else { "" },
        verdict(minima)
    );
    out
}
