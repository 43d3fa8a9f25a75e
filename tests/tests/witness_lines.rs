//! No garbled witness line: the whole Markdown, LaTeX (source text) and
//! JSON audit reports are scanned for the ways a witness or an evidence line
//! has come out wrong — an operator left dangling before `=` or at the end
//! (`P ≤ = …`, `… −`), an empty side (`left = ,`), a subject run into its
//! values without a point or a colon (`Σ b_i − 0 left = 1`), a name with an
//! underscore before a subscript digit (`y_i₁`, `P_₂`, `b1_₂`, LaTeX
//! `\mathrm{y_i}_{1}`), an interval length `0` shown as a step
//! (`h_{i+1} = 0`), a coefficient `(1)·` printed before a term, the ASCII
//! name `gamma` where `γ` is meant, a correction that repeats the printed
//! statement. Each pattern is tested on a garbled line first, so the scan
//! cannot pass by matching nothing.

use regex::Regex;

use crate::audit::{entries, json, markdown, tex};

/// A garbled pattern: its name and the regular expression that finds it.
struct Pattern {
    name: &'static str,
    regex: Regex,
    /// A garbled line it must find (the pattern is tested on it).
    example: &'static str,
}

fn patterns() -> Vec<Pattern> {
    let p = |name, re: &str, example| Pattern {
        name,
        regex: Regex::new(re).expect("a valid pattern"),
        example,
    };
    vec![
        p(
            "an operator before `=`",
            r"(≤|≥|<|>|−|\+|·|\\leq|\\geq|\\le|\\ge|-) ?\$? ?\$?=(?:[^=]|$)",
            "P ≤ = `-0.127736`",
        ),
        p(
            "a line ending in an operator",
            r"(≤|≥|=|−|\+|·|\\leq|\\geq|\\cdot)\s*(\$|`)?\s*$",
            "the residual is a −",
        ),
        p(
            "an empty side",
            r"= ?(``)? ?[,;]|= ?\$ ?\$ ?[,;]|left =\s*$",
            "left = , right = 1",
        ),
        p(
            "a subject run into its values",
            r"[^\s:,;(`] +(left|right|value|target) (=|\$=\$) ",
            "Σ b_i − 0 left = `1`, right = `0`",
        ),
        p(
            "an underscore before a subscript",
            r"_[A-Za-z0-9]*[₀-₉]|\\mathrm\{[A-Za-z0-9]*_[A-Za-z0-9]*\}",
            "at `y_i₁ = 1, P_₂ = 1, b1_₂ = 1`",
        ),
        p(
            "an interval length 0",
            r"\bh(_\{?[a-z0-9+]*\}?|[ᵢ₊₀-₉]+)? ?(=|\$=\$) ?`?\$?0\b|\bh\w* = (\w+ = )*0\b",
            "at `h_{i+1} = 0`",
        ),
        p(
            "a coefficient (1)·",
            r"\(1\) ?(·|\\cdot)",
            "(1)·P₀ + (3)·P₁",
        ),
        p(
            "ASCII gamma",
            r"\\mathrm\{gamma\}|(^|[^\\A-Za-z_])gamma([^A-Za-z(]|$)",
            "G² factor gamma = 1, \\mathrm{gamma}",
        ),
    ]
}

/// The garbled lines of `text`: `(pattern, line)`.
fn garbled<'a>(text: &'a str, patterns: &[Pattern]) -> Vec<(&'static str, &'a str)> {
    text.lines()
        .flat_map(|line| {
            patterns
                .iter()
                .filter(move |p| p.regex.is_match(line))
                .map(move |p| (p.name, line))
        })
        .collect()
}

/// The strings of a JSON report a reader sees (prose and the Unicode and
/// LaTeX forms; not the SymPy or plain forms, where `gamma` is the name).
fn json_strings(v: &serde_json::Value, key: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::String(s) if !["sympy", "plain", "symbols", "symbol"].contains(&key) => {
            out.push(s.clone())
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| json_strings(x, key, out)),
        serde_json::Value::Object(o) => o.iter().for_each(|(k, x)| json_strings(x, k, out)),
        _ => {}
    }
}

fn report_error(format: &str, found: &[(&str, &str)]) -> String {
    let lines: Vec<String> = found
        .iter()
        .take(20)
        .map(|(p, l)| format!("  {p}: {}", l.chars().take(240).collect::<String>()))
        .collect();
    format!(
        "{} garbled lines in the {format} report:\n{}",
        found.len(),
        lines.join("\n")
    )
}

#[test]
fn every_pattern_finds_its_example() {
    let all = patterns();
    for p in &all {
        assert!(
            p.regex.is_match(p.example),
            "{} misses {:?}",
            p.name,
            p.example
        );
    }
    // and a well-formed witness line is not garbled
    let good = "- **Witness:** Σ b\\_i − 1 at `t = 1/3`: value = `29/27`, target = `1`";
    assert!(garbled(good, &all).is_empty(), "{:?}", garbled(good, &all));
}

#[test]
fn no_garbled_line_in_the_markdown_report() {
    let md = markdown();
    let found = garbled(&md, &patterns());
    assert!(found.is_empty(), "{}", report_error("Markdown", &found));
}

#[test]
fn no_garbled_line_in_the_latex_report() {
    let tex = tex();
    let found = garbled(&tex, &patterns());
    assert!(found.is_empty(), "{}", report_error("LaTeX", &found));
}

#[test]
fn no_garbled_line_in_the_json_report() {
    let value = serde_json::to_value(json()).expect("JSON");
    let mut strings = Vec::new();
    json_strings(&value, "", &mut strings);
    let text = strings.join("\n");
    let found = garbled(&text, &patterns());
    assert!(found.is_empty(), "{}", report_error("JSON", &found));
}

/// A correction must say more than the printed formula: one identical to
/// the statement (a join that fails only at a pole) corrects nothing.
#[test]
fn no_correction_repeats_the_printed_statement() {
    let normal = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    for e in entries() {
        if let Some(c) = &e.verdict.correction {
            let printed = normal(e.statement.trim_end_matches(" (as printed)"));
            assert_ne!(
                normal(c),
                printed,
                "{}: the correction repeats the statement",
                e.id
            );
        }
        for item in e.verdict.evidence.iter() {
            if let (Some(printed), true) = (&item.printed, item.text.starts_with("correction")) {
                assert!(
                    !item.text.contains(printed.as_str()),
                    "{}: {}",
                    e.id,
                    item.text
                );
            }
        }
    }
}

/// One naming scheme in the JSON report: every symbol of the expression a
/// witness value records (`of`) is named by a coordinate of the point
/// (`symbol`, with a SymPy `sympy` value) or left free in a symbolic value
/// (control points kept as symbols), so a program substitutes the point
/// with no mapping;
/// a point in `s`, `c` gives `theta`.
#[test]
fn witness_points_name_the_symbols_of_their_expressions() {
    let value = serde_json::to_value(json()).expect("JSON");
    let mut checked = 0;
    for claim in value["claims"].as_array().expect("claims") {
        for item in claim["evidence"].as_array().into_iter().flatten() {
            let Some(w) = item.get("witness") else {
                continue;
            };
            let point: Vec<&str> = w["point"]
                .as_array()
                .expect("a point")
                .iter()
                .filter(|a| a.get("sympy").is_some())
                .filter_map(|a| a.get("symbol").and_then(|s| s.as_str()))
                .collect();
            let names: Vec<&str> = w["point"]
                .as_array()
                .expect("a point")
                .iter()
                .filter_map(|a| a["name"].as_str())
                .collect();
            if names.contains(&"s") || names.contains(&"c") {
                assert!(
                    point.contains(&"theta"),
                    "{}: no θ beside s, c",
                    claim["id"]
                );
            }
            for v in w["values"].as_array().expect("values") {
                let Some(of) = v.get("of") else {
                    continue;
                };
                let kept: Vec<&str> = v["value"]["symbols"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .filter_map(|s| s.as_str())
                    .collect();
                for s in of["symbols"].as_array().into_iter().flatten() {
                    let s = s.as_str().expect("a name");
                    assert!(
                        point.contains(&s) || !kept.is_empty(),
                        "{}: `{s}` of {} is not named by the point {point:?}",
                        claim["id"],
                        of["sympy"]
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked} values with their expression");
}
