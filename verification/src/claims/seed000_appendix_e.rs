//! Seed 000, Appendix E: the rational basis `Q_i = w_i F_i / Σ w_k F_k` on
//! the span `[n_j, n_{j+1})` (times its control point `H_i`, as printed):
//! its second and third derivatives at `n_j^+` and `n_{j+1}^−` with general
//! coefficients (A20)–(A35) (M15). (The values, first derivatives and the
//! uniform case are identities of the document file; M15 stays here because
//! the identity check forms the third derivative of the general quotient
//! symbolically, minutes where these jets take a second.)
//!
//! Computed with Taylor jets of the catalog's blending functions `l_k`
//! (`F₀ = d l₀`, `F₁ = Σ b_k l_k`, `F₂ = Σ c_k l_k`, `F₃ = a l₃`, eq. (5),
//! coefficients as symbols), derivatives in `n` with
//! `t = π(n − n_j)/(2q_j)` (factor `(π/(2q_j))^k`, as printed).

use trig_core::Family;
use trig_deriv::table::{end_atoms, rate};
use trig_deriv::{End, Jet, Wrt};
use trig_symbolic::Sym;

use super::seed000_appendix_print::{Shorthand, printed_part, zeta};
use crate::claim::Claim;
use trig_deriv::continuity::quotient_derivatives;
use trig_judge::exact::{IDENTITY, symbols};
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "M15",
    check: m15,
}];

/// Orders 0–3.
const THIRD: usize = 4;

/// `Q_i H_i` derivatives `[end][i][order]` (end 0 = `n_j^+`, 1 = `n_{j+1}^−`)
/// from segment functions given as jets: `Q_i H_i = w_i F_i H_i / Σ_k w_k F_k`
/// by [`quotient_derivatives`], then the factor `(π/(2q))^k`.
fn rational_table<const K: usize>(
    segments: impl Fn(End) -> Vec<Jet<Sym, K>>,
) -> Vec<Vec<Vec<Sym>>> {
    let (w, h) = (symbols("w", 4), symbols("H", 4));
    let q = Sym::var("q");
    let dt = rate(Family::Seed000Blending, Wrt::X, &q, &[zeta()]);
    [End::Start, End::End]
        .into_iter()
        .map(|end| {
            let weighted: Vec<Jet<Sym, K>> = segments(end)
                .into_iter()
                .zip(&w)
                .map(|(fi, wi)| fi * &Jet::constant(wi.clone()))
                .collect();
            let total = weighted[1..]
                .iter()
                .fold(weighted[0].clone(), |acc, x| acc + x);
            let numerators: Vec<Vec<Sym>> = weighted
                .iter()
                .zip(&h)
                .map(|(wf, hi)| (wf.clone() * &Jet::constant(hi.clone())).derivatives())
                .collect();
            let refs: Vec<&[Sym]> = numerators.iter().map(Vec::as_slice).collect();
            quotient_derivatives(&refs, &total.derivatives())
                .into_iter()
                .map(|qh| {
                    let mut factor = Sym::one();
                    qh.into_iter()
                        .map(|d| {
                            let v = d * &factor;
                            factor = factor.clone() * &dt;
                            v
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// Jets of `l₀…l₃` at an end of the span.
fn blending_jets<const K: usize>(end: End) -> Vec<Jet<Sym, K>> {
    let atoms = end_atoms::<Sym, K>(Family::Seed000Blending, end, &Sym::one(), &[zeta()]);
    Family::Seed000Blending.eval(&atoms, &[Jet::constant(zeta())])
}

/// General coefficients as symbols: `F₀ = d l₀`, `F₁ = Σ b_k l_k`,
/// `F₂ = Σ c_k l_k`, `F₃ = a l₃` (eq. (5)).
fn general<const K: usize>() -> Vec<Vec<Vec<Sym>>> {
    rational_table::<K>(|end| {
        let l = blending_jets::<K>(end);
        let combo = |prefix: &str| {
            let coef = symbols(prefix, 4);
            (0..4).fold(Jet::constant(Sym::zero()), |acc, k| {
                acc + &(l[k].clone() * &Jet::constant(coef[k].clone()))
            })
        };
        vec![
            l[0].clone() * &Jet::constant(Sym::var("d")),
            combo("b"),
            combo("c"),
            l[3].clone() * &Jet::constant(Sym::var("a")),
        ]
    })
}

/// One printed entry: equation, function `i`, end (0 = `n_j^+`), order, text.
type Entry = (&'static str, usize, usize, usize, String);

/// The printed entries of Appendix E, claim by claim (the file's header
/// says how they are written).
const PRINTED: &str = include_str!("seed000_appendix_e.txt");

/// The printed entries of `claim` in [`PRINTED`], abbreviations expanded.
fn entries(claim: &str) -> Result<Vec<Entry>, String> {
    entries_in(PRINTED, claim)
}

/// The printed entries of `claim` in `data` (written as [`PRINTED`]).
fn entries_in(data: &'static str, claim: &str) -> Result<Vec<Entry>, String> {
    // longest name first, so that `$FA` is never read as `$F` and an `A`
    let mut abbreviations: Vec<(String, &str)> = Vec::new();
    let mut out = Vec::new();
    let mut current = None;
    for (n, line) in data.lines().enumerate() {
        let bad = |what: &str| format!("seed000_appendix_e.txt line {}: {what}", n + 1);
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(id) = line.strip_prefix("== ") {
            current = Some(id.trim());
        } else if current.is_none() {
            let Some((name, text)) = line.split_once(" := ") else {
                return Err(bad("before the first `== CLAIM` only `NAME := text` lines"));
            };
            abbreviations.push((format!("${}", name.trim()), text.trim()));
            abbreviations.sort_by_key(|(name, _)| std::cmp::Reverse(name.len()));
        } else if current == Some(claim) {
            let fields: Vec<&str> = line.splitn(5, '|').map(str::trim).collect();
            let [eq, i, end, order, text] = fields[..] else {
                return Err(bad("not `equation | i | end | order | formula`"));
            };
            let number = |f: &str| {
                f.parse::<usize>()
                    .map_err(|_| bad("i or order not a number"))
            };
            let end = match end {
                "+" => 0,
                "-" => 1,
                _ => return Err(bad("end not + or -")),
            };
            let text = abbreviations
                .iter()
                .fold(text.to_string(), |t, (name, by)| t.replace(name, by));
            if text.contains('$') {
                return Err(bad(
                    "an abbreviation `$NAME` that no `NAME :=` line defines",
                ));
            }
            out.push((eq, number(i)?, end, number(order)?, text));
        }
    }
    if out.is_empty() {
        return Err(format!("seed000_appendix_e.txt has no entries for {claim}"));
    }
    Ok(out)
}

/// The shorthands of Appendix E, substituted after reading a print.
const SHORTHANDS: [Shorthand; 8] = [
    (
        "A",
        "S d w0 + [S(b0 + b2) + 4(S + 1)b1]w1 + [S(c0 + c2) + 4(S + 1)c1]w2",
    ),
    (
        "B",
        "[S(b1 + b3) + 4(S + 1)b2]w1 + [S(c1 + c3) + 4(S + 1)c2]w2 + S a w3",
    ),
    ("J", "d w0 + (b0 - 2b1 + b2)w1 + (c0 - 2c1 + c2)w2"),
    ("M", "-d w0 + (b2 - b0)w1 + (c2 - c0)w2"),
    ("K", "(b1 - 2(b2) + b3)w1 + (c1 - 2(c2) + c3)w2 + a w3"),
    ("L", "(b3 - b1)w1 + (c3 - c1)w2 + a w3"),
    ("g", "2(2S - 5)"),
    ("e", "(1 + 2S)^3"),
];

fn decide(entries: &[Entry], table: &[Vec<Vec<Sym>>], preamble: &str) -> Verdict {
    let ends = ["n_j^+", "n_{j+1}^-"];
    let parts = entries
        .iter()
        .map(|(eq, i, end, order, text)| {
            let label = format!("{eq} Q_{i}{}({}) H_{i}", "'".repeat(*order), ends[*end]);
            match table.get(*end).and_then(|f| f.get(*i)).and_then(|d| d.get(*order)) {
                Some(computed) => printed_part(label, text, &SHORTHANDS, computed),
                None => (
                    label,
                    Verdict::not_checkable(format!(
                        "{eq}: no computed Q_{i} of order {order} (the table has functions 0–3 and the orders this claim prints)"
                    )),
                ),
            }
        })
        .collect();
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(0, preamble.to_string());
    v
}

const GENERAL: &str = "general coefficients as symbols: d = d_j, b_k = b_{j,k}, c_k = c_{j,k}, a = a_j; weights w0…w3, control points H0…H3, q = q_j; S = s(ξ); shorthands A, B, J, M, K, L, g(ξ), e(ξ) as defined in Appendix E; derivatives in n (factor (π/(2q_j))^k)";

/// The claim's printed entries decided against `table`.
fn printed(claim: &str, table: &[Vec<Vec<Sym>>], preamble: &str) -> Verdict {
    match entries(claim) {
        Ok(entries) => decide(&entries, table, preamble),
        Err(e) => Verdict::not_checkable(e),
    }
}

fn m15() -> Verdict {
    let mut v = printed("M15", &general::<THIRD>(), GENERAL);
    v.evidence.insert(
        1,
        "garbled print: \"A^-\" in (A20) and \"B^-\" in (A27) are read as \"A −\", \"B −\"; the outer bracket of (A28) encloses all three terms as printed; m(ξ)² is defined but never used",
    );
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_verdict::status::Status;

    #[test]
    fn every_claim_has_its_printed_entries() {
        let counts: Vec<usize> = CLAIMS
            .iter()
            .map(|c| entries(c.id).map_or(0, |e| e.len()))
            .collect();
        // (A20)–(A35)
        assert_eq!(counts, [16]);
        let m15 = entries("M15").unwrap();
        assert_eq!(m15[0].0, "(A20)");
        assert_eq!((m15[0].1, m15[0].2, m15[0].3), (0, 0, 2));
        assert!(!m15.iter().any(|e| e.4.contains('$')));
    }

    #[test]
    fn malformed_entries_are_errors_not_panics() {
        let err = |data: &'static str| entries_in(data, "X").unwrap_err();
        assert!(err("== X\n(A1) | 0 | + | 0\n").contains("line 2"));
        assert!(err("== X\n(A1) | 0 | x | 0 | 0\n").contains("end not + or -"));
        assert!(err("== X\n(A1) | one | + | 0 | 0\n").contains("not a number"));
        assert!(err("== Y\n(A1) | 0 | + | 0 | 0\n").contains("no entries for X"));
        assert!(err("(A1) | 0 | + | 0 | 0\n== X\n").contains("line 1"));
        assert!(err("== X\n(A1) | 0 | + | 0 | $D\n").contains("no `NAME :=` line"));
        // the longest name first; fields trimmed
        assert_eq!(
            entries_in(
                "F := [f]\nFA := [fa]\n== X\n(A1)  | 1 |- | 2 | $FA $F\n",
                "X"
            ),
            Ok(vec![("(A1)", 1, 1, 2, "[fa] [f]".to_string())])
        );
        assert_eq!(
            entries_in("D := [w]\n== X\n(A1) | 1 | - | 2 | $D/2\n", "X"),
            Ok(vec![("(A1)", 1, 1, 2, "[w]/2".to_string())])
        );
    }

    #[test]
    fn every_block_names_a_claim_of_this_file_and_fits_its_table() {
        for line in PRINTED.lines() {
            if let Some(id) = line.strip_prefix("== ") {
                assert!(CLAIMS.iter().any(|c| c.id == id), "unknown claim {id}");
            }
        }
        // an entry past the computed table is not checkable, not a panic
        let table = [vec![vec![Sym::zero()]; 4]];
        let v = decide(&[("(A0)", 4, 0, 0, "0".into())], &table, GENERAL);
        assert_eq!(v.status, Status::NotCheckable);
    }

    #[test]
    fn printed_values_that_are_right_hold_and_wrong_ones_fail() {
        let v = m15();
        let line = |eq: &str| {
            v.evidence
                .iter()
                .map(|l| l.line())
                .find(|l| l.starts_with(eq))
                .unwrap()
        };
        // (A23): Q_3''(n_j^+) = 0 as printed; (A20) is not the computed value
        assert!(line("(A23)").contains(": holds"));
        assert!(line("(A20)").contains(": fails"));
        assert_eq!(v.status, Status::Fails);
    }
}
