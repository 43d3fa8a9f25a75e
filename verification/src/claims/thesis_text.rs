//! Thesis Chapter 6, the text against its tables (claims T67, T68): the
//! order of the methods 6.8.13 and 6.9 state, and the tables of one letter
//! against the set-up of 6.6, recomputed from the printed cells.
//!
//! The tables are those of claim T32 (`documents/thesis/tables-6.2-6.17.txt`, each cell an
//! exact rational read from its printed decimal). A quoted figure is judged
//! by [`trig_judge::quoted`]: it holds when it is the exact recomputed value
//! rounded to the quoted decimals.

use rug::Rational;
use trig_core::Family;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::IDENTITY;
use trig_judge::quoted::{QUOTED, quoted_figure, quoted_order};
use trig_judge::recomputed::{Recomputed, decimal};
use trig_judge::same_basis::same_basis;
use trig_judge::table_arithmetic::{SCHEMES, Table, parse, summary_row};
use trig_judge::table_quotes::{AFTER, BEFORE, Segment, pair, segments, status};
use trig_verdict::evidence::{Evidence, Kind, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The tables of claim T32 (the table file beside the thesis's document file).
const DATA: &str = include_str!("../../../documents/thesis/tables-6.2-6.17.txt");

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T67",
        check: t67,
    },
    Claim {
        id: "T68",
        check: t68,
    },
];

fn tables() -> Result<Vec<Table>, String> {
    parse(DATA).map_err(|e| e.to_string())
}

/// The names the thesis uses for the four schemes of the summary tables.
const NAMES: [&str; 4] = ["proposed", "Majeed & Qayyum", "Han", "Usman"];

fn summary<'a>(tables: &'a [Table], letter: &str) -> Result<&'a Table, String> {
    tables
        .iter()
        .find(|t| t.scheme == "summary" && t.letter == letter)
        .ok_or_else(|| format!("no summary table for {letter}"))
}

/// The cells of `row` of the summary table `t`, by scheme (the witness
/// symbols `proposed`, `Majeed`, `Han`, `Usman`).
fn row_entries(t: &Table, row: &str) -> Result<Vec<(&'static str, Recomputed)>, String> {
    let cells = summary_row(t, row)?;
    Ok(NAMES
        .iter()
        .copied()
        .zip(
            cells
                .iter()
                .zip(SCHEMES)
                .map(|(c, symbol)| Recomputed::cell(c.cell(symbol))),
        )
        .collect())
}

/// The scheme of least value in `row` of `t`.
fn least(t: &Table, row: &str) -> Result<(&'static str, Recomputed), String> {
    row_entries(t, row)?
        .into_iter()
        .min_by(|a, b| a.1.value.cmp(&b.1.value))
        .ok_or_else(|| format!("Table {}: empty row {row}", t.number))
}

fn t67() -> Verdict {
    let tables = match tables() {
        Ok(t) => t,
        Err(e) => return Verdict::not_checkable(e),
    };
    let order = || -> Result<Verdict, String> {
        let delta = summary(&tables, "Delta")?;
        let printed = ["Han", "proposed", "Majeed & Qayyum", "Usman"];
        let mut items = vec![quoted_order(
            "order by average error (6.8.13: \"the lowest average error, followed by …\")",
            &format!("Ave. Error of Table {}", delta.number),
            &row_entries(delta, "Ave. Error")?,
            &printed,
        )];
        for row in ["Total Error", "Max. Error", "Bad points (>1.5)"] {
            let e = quoted_order(row, row, &row_entries(delta, row)?, &printed);
            items.push(Evidence::note(format!(
                "for comparison (not the criterion the text names), {row}: {}",
                e.text
            )));
        }
        let st = Status::conjunction(items.iter().filter_map(|e| e.status));
        Ok(Verdict::new(st, QUOTED, items))
    };
    let precise = || -> Result<Verdict, String> {
        let mut items = Vec::new();
        for letter in ["Epsilon", "Delta", "ع"] {
            let t = summary(&tables, letter)?;
            let (best, v) = least(t, "Ave. Error")?;
            let proposed = Recomputed::cell(summary_row(t, "Ave. Error")?[0].cell(SCHEMES[0]));
            let ok = best == "proposed";
            items.push(
                Evidence::new(
                    Kind::Comparison,
                    format!(
                        "smallest average error in Table {}: {best} ({}); proposed {}",
                        t.number,
                        decimal(&v.value),
                        decimal(&proposed.value)
                    ),
                )
                .about(format!("{letter}: proposed most precise"), status(ok))
                .witnessed(if ok {
                    None
                } else {
                    pair(
                        format!("Table {}, Ave. Error", t.number),
                        Relation::AtLeast,
                        (best, &v),
                        ("proposed", &proposed),
                    )
                }),
            );
        }
        let st = Status::conjunction(items.iter().filter_map(|e| e.status));
        Ok(Verdict::new(
            st,
            "reading: \"most precise to the real image\" = the smallest average error (the measure 6.8.13 and Table 6.17 rank by), in each of Tables 6.14–6.16",
            items,
        ))
    };
    let run = |f: &dyn Fn() -> Result<Verdict, String>| f().unwrap_or_else(Verdict::not_checkable);
    Verdict::all(
        QUOTED,
        vec![
            (
                "Table 6.15: Han, then proposed, Majeed & Qayyum, Usman".into(),
                run(&order),
            ),
            ("6.9: most precise to the real image".into(), run(&precise)),
            (
                "6.9: nearest to the control polygon".into(),
                Verdict::not_checkable(
                    "no table measures it: Tables 6.2–6.16 give distances from the fitted curves to the data points only, none from a curve to its control polygon",
                ),
            ),
        ],
    )
}

fn find<'a>(tables: &'a [Table], letter: &str, scheme: &str) -> Result<&'a Table, String> {
    tables
        .iter()
        .find(|t| t.letter == letter && t.scheme == scheme)
        .ok_or_else(|| format!("no {scheme} table for {letter}"))
}

/// Per segment, whether two tables print the same value in `column`.
fn same(a: &[Segment], b: &[Segment], column: usize) -> Result<Vec<bool>, String> {
    if a.len() != b.len() {
        return Err("the tables have different segment counts".into());
    }
    Ok(a.iter()
        .zip(b)
        .map(|(x, y)| x.cells[column].value == y.cells[column].value)
        .collect())
}

/// The printed count of T68: "proposed ≠ Han and M&Q = Han in 10 of 11
/// epsilon segments" (the Before columns).
const T68_COUNT: &str = "10";

/// T28, the premise of T68: (3.7) is (6.2) with `λ = m` and (6.1) with
/// `η = m + 1`, decided by the same-basis judge.
fn t28() -> Verdict {
    let m = Sym::var("m");
    let same = |other: Family, name: &str, value: Sym, text: &str| {
        same_basis(&Family::ThesisCubic, &other, &[(name.into(), value)], text)
    };
    Verdict::all(
        IDENTITY,
        vec![
            (
                "(6.2)".into(),
                same(Family::Han, "lambda", m.clone(), "λ = m"),
            ),
            (
                "(6.1)".into(),
                same(Family::MajeedQayyum, "eta", m + &Sym::one(), "η = m + 1"),
            ),
        ],
    )
}

fn t68() -> Verdict {
    let t28 = t28();
    let Some(t28) = Some(t28).filter(|v| v.status == Status::Holds) else {
        return Verdict::not_checkable(
            "T28 (the identities (3.7)(m) ≡ (6.2)(λ = m) ≡ (6.1)(η = m + 1)) does not hold, so the expected equalities have no basis",
        );
    };
    let tables = match tables() {
        Ok(t) => t,
        Err(e) => return Verdict::not_checkable(e),
    };
    let run = || -> Result<Vec<Evidence>, String> {
        let mut items = vec![Evidence::note(format!(
            "T28 {}: (3.7) at m = 0.6 is (6.2) at λ = 0.6, and (6.1) at η = 0.6 is (6.2) at λ = −0.4; 6.6 fixes the parameter at 0.6 for every method, so the proposed and Han fits of the same data are the same curves and their errors must be equal, while Majeed & Qayyum fits with another basis",
            t28.status
        ))];
        for letter in ["Epsilon", "Delta", "ع"] {
            let [p, m, h] = ["proposed", "Majeed", "Han"].map(|s| find(&tables, letter, s));
            let (p, m, h) = (p?, m?, h?);
            let (sp, sm, sh) = (segments(p)?, segments(m)?, segments(h)?);
            for (column, name) in [(BEFORE, "Before"), (AFTER, "After")] {
                let ph = same(&sp, &sh, column)?;
                let mh = same(&sm, &sh, column)?;
                let n = ph.len();
                let k = ph.iter().filter(|x| **x).count();
                let first = sp.iter().zip(&sh).zip(&ph).find(|(_, eq)| !**eq);
                let witness = first.and_then(|((a, b), _)| {
                    let cell = |s: &Segment, scheme: &str| {
                        Recomputed::cell(s.cells[column].cell(format!("{scheme}{}", s.number)))
                    };
                    pair(
                        format!("segment {}, {name} total error", a.number),
                        Relation::Equal,
                        (
                            &format!("Table {} (proposed)", p.number),
                            &cell(a, "proposed"),
                        ),
                        (&format!("Table {} (Han)", h.number), &cell(b, "Han")),
                    )
                });
                let kmh = mh.iter().filter(|x| **x).count();
                items.push(
                    Evidence::new(
                        Kind::Comparison,
                        format!(
                            "proposed = Han in {k} of {n} segments (Tables {} and {}); Majeed & Qayyum = Han in {kmh} of {n} (Table {})",
                            p.number, h.number, m.number
                        ),
                    )
                    .about(format!("{letter}, {name}: proposed = Han"), status(k == n))
                    .witnessed(witness),
                );
                if letter == "Epsilon" && column == BEFORE {
                    let both = ph.iter().zip(&mh).filter(|(a, b)| !**a && **b).count();
                    items.push(quoted_figure(
                        "the claim's count: Epsilon Before segments with proposed ≠ Han and Majeed & Qayyum = Han",
                        T68_COUNT,
                        Rational::from(both),
                        &format!("count over the {n} segments"),
                    ));
                }
            }
        }
        Ok(items)
    };
    match run() {
        Ok(items) => Verdict::new(
            Status::conjunction(items.iter().filter_map(|e| e.status)),
            "exact comparison of the printed cells (equal means the same rational); expected from T28 and the set-up of 6.6: proposed = Han in every segment, Before and After",
            items,
        ),
        Err(why) => Verdict::not_checkable(why),
    }
}
