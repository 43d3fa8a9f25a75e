//! The audit report: Markdown for people, JSON for machines, same content.

use std::fmt::Write;

use serde_json::json;

use crate::Outcome;
use crate::claim::Seed;
use crate::verdict::Status;

/// Counts of each status among `outcomes`.
fn counts<'a>(outcomes: impl Iterator<Item = &'a Outcome> + Clone) -> Vec<(Status, usize)> {
    Status::ALL
        .iter()
        .map(|s| {
            (
                *s,
                outcomes.clone().filter(|o| o.verdict.status == *s).count(),
            )
        })
        .collect()
}

/// The Markdown report: a summary (by verdict and by document), then one
/// section per document and one entry per claim.
pub fn markdown(outcomes: &[Outcome]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# trig-audit report\n");
    let _ = writeln!(
        out,
        "Every verdict below is computed by `trig-audit audit` from the formulas as printed in `shared/seeds/`; identities are decided exactly in the symbolic ring, counterexamples in 256-bit MPFR.\n"
    );
    let _ = writeln!(out, "## Summary\n");
    let _ = writeln!(
        out,
        "| document | claims | {} |",
        Status::ALL.map(|s| s.label()).join(" | ")
    );
    let _ = writeln!(out, "|---|---|{}", "---|".repeat(Status::ALL.len()));
    for seed in Seed::ALL {
        let of_seed = outcomes.iter().filter(|o| o.claim.seed == seed);
        let n = of_seed.clone().count();
        if n == 0 {
            continue;
        }
        let c: Vec<String> = counts(of_seed).iter().map(|(_, k)| k.to_string()).collect();
        let _ = writeln!(out, "| {} | {n} | {} |", seed.id(), c.join(" | "));
    }
    let c: Vec<String> = counts(outcomes.iter())
        .iter()
        .map(|(_, k)| k.to_string())
        .collect();
    let _ = writeln!(
        out,
        "| **all** | {} | {} |\n",
        outcomes.len(),
        c.join(" | ")
    );
    for seed in Seed::ALL {
        let of_seed: Vec<&Outcome> = outcomes.iter().filter(|o| o.claim.seed == seed).collect();
        if of_seed.is_empty() {
            continue;
        }
        let _ = writeln!(out, "## Seed {} — {}\n", seed.id(), seed.title());
        let _ = writeln!(out, "Source: `shared/seeds/{}`\n", seed.file());
        for o in of_seed {
            let (c, v) = (&o.claim, &o.verdict);
            let _ = writeln!(out, "### {} — {}\n", c.id, v.status);
            let _ = writeln!(out, "- **Source:** {}", c.source);
            let _ = writeln!(out, "- **Printed:** {}", c.statement);
            let _ = writeln!(out, "- **Verdict:** {}", v.status);
            let _ = writeln!(out, "- **How:** {}", v.method);
            if let Some(corr) = &v.correction {
                let _ = writeln!(out, "- **Correction:** {corr}");
            }
            let _ = writeln!(out, "- **Evidence:**");
            for e in &v.evidence {
                let _ = writeln!(out, "  - `{}`", e.replace('`', "'"));
            }
            out.push('\n');
        }
    }
    out
}

/// The same content as JSON.
pub fn json(outcomes: &[Outcome]) -> serde_json::Value {
    let summary: serde_json::Map<String, serde_json::Value> = counts(outcomes.iter())
        .into_iter()
        .map(|(s, n)| (s.label().to_string(), json!(n)))
        .collect();
    json!({
        "summary": summary,
        "claims": outcomes.iter().map(|o| json!({
            "id": o.claim.id,
            "seed": o.claim.seed.id(),
            "seed_file": o.claim.seed.file(),
            "source": o.claim.source,
            "statement": o.claim.statement,
            "verdict": o.verdict.status.label(),
            "method": o.verdict.method,
            "evidence": o.verdict.evidence,
            "correction": o.verdict.correction,
        })).collect::<Vec<_>>(),
    })
}
