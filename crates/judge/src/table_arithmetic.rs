//! The table-arithmetic judge: printed error tables against their own
//! arithmetic (the thesis's Tables 6.2–6.17 are `documents/thesis/tables-6.2-6.17.txt`).
//!
//! The tables are a table file (one block per table with its number, the
//! layout in the file's header comment). Every printed decimal is read as an exact
//! rational ([`trig_core::parse_exact`]), so each difference below is exact.
//! A printed value with `d` decimals stands for a true value within
//! `½·10⁻ᵈ`; a relation between printed values is *consistent* when the
//! exact difference lies within the sum of those allowances (e.g. a TOTAL
//! row against the sum of `n` segment rows: `n + 1` allowances), and
//! *inconsistent* otherwise.
//!
//! Checked per segment table (6.2–6.13): TOTAL before/after = Σ segment
//! rows; TOTAL max/min = max/min over the segments; TOTAL average = mean of
//! the segment averages (the convention the tables follow); the numbers the
//! paragraph after the table states. Per summary table (6.14–6.16): each
//! cell against the TOTAL row of its per-letter table. Table 6.17: the best
//! scheme has the smallest average error, and its printed figures.

use std::fmt;

use rug::ops::Pow;
use rug::{Integer, Rational};
use trig_symbolic::Sym;

use crate::recomputed::decimal;
use crate::recomputed::{self, Cell, Recomputed};
use trig_verdict::evidence::EvidenceList;
use trig_verdict::evidence::{Evidence, Kind, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How the tables are checked, as the report states it.
const METHOD: &str = "exact rational arithmetic on the printed decimals; a relation holds when the exact difference is within the printed rounding (½ unit in the last printed place of every value involved); relations of a segment table: TOTAL before and after total = Σ of the segments, TOTAL max and min = max and min over the segments, TOTAL average = mean of the segment averages, and each figure the text quotes = the TOTAL row; of a summary table: each entry = the TOTAL row of its per-letter table; of Table 6.17: each best scheme = the smallest average error, and its figures = the summaries";

/// A malformed line of a table file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DataError {
    pub line: usize,
    pub reason: String,
}

impl fmt::Display for DataError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.reason)
    }
}

impl std::error::Error for DataError {}

/// A printed number: its text, exact value and rounding allowance.
#[derive(Debug, Clone)]
pub struct Num {
    pub text: String,
    pub value: Rational,
    allowance: Rational,
}

impl Num {
    pub fn parse(text: &str, line: usize) -> Result<Num, DataError> {
        let value = trig_core::parse_exact(text).map_err(|e| DataError {
            line,
            reason: e.to_string(),
        })?;
        // integers (counts of bad points, an exact 0) are exact
        let allowance = match text.split_once('.') {
            Some((_, f)) => {
                Rational::from((1, 2)) / Rational::from(Integer::from(10).pow(f.len() as u32))
            }
            None => Rational::new(),
        };
        Ok(Num {
            text: text.to_string(),
            value,
            allowance,
        })
    }
}

/// One printed table.
#[derive(Debug, Clone, Default)]
pub struct Table {
    pub number: String,
    pub letter: String,
    pub scheme: String,
    column: String,
    notes: Vec<String>,
    /// Row label and cells (segment tables: segment rows, then TOTAL).
    pub rows: Vec<(String, Vec<Num>)>,
    /// Numbers the text states: key and value.
    pub texts: Vec<(String, Num)>,
    /// Summary tables: the per-letter tables of the four columns.
    of: Vec<String>,
    /// Table 6.17: letter, printed best scheme, average, bad points.
    best: Vec<(String, String, Num, Num)>,
}

pub fn parse(data: &str) -> Result<Vec<Table>, DataError> {
    let mut tables: Vec<Table> = Vec::new();
    for (i, raw) in data.lines().enumerate() {
        let line = i + 1;
        let err = |reason: &str| DataError {
            line,
            reason: reason.to_string(),
        };
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        if let Some(head) = raw.strip_prefix("== ") {
            let f: Vec<&str> = head.split(" | ").collect();
            let [number, letter, scheme, column] = f[..] else {
                return Err(err("a header has four fields"));
            };
            tables.push(Table {
                number: number.into(),
                letter: letter.into(),
                scheme: scheme.into(),
                column: column.into(),
                ..Table::default()
            });
            continue;
        }
        let t = tables
            .last_mut()
            .ok_or_else(|| err("data before the first header"))?;
        if let Some(note) = raw.strip_prefix("note ") {
            t.notes.push(note.into());
        } else if let Some(rest) = raw.strip_prefix("text ") {
            let (key, value) = rest.split_once(' ').ok_or_else(|| err("text KEY VALUE"))?;
            t.texts.push((key.into(), Num::parse(value, line)?));
        } else if let Some(rest) = raw.strip_prefix("of ") {
            t.of = rest.split_whitespace().map(String::from).collect();
        } else if let Some(rest) = raw.strip_prefix("best\t") {
            let f: Vec<&str> = rest.split('\t').collect();
            let [letter, scheme, ave, bad] = f[..] else {
                return Err(err("best has four fields"));
            };
            t.best.push((
                letter.into(),
                scheme.into(),
                Num::parse(ave, line)?,
                Num::parse(bad, line)?,
            ));
        } else {
            let mut f = raw.split('\t');
            let label = f.next().unwrap_or_default().to_string();
            let cells = f
                .map(|x| Num::parse(x, line))
                .collect::<Result<Vec<_>, _>>()?;
            t.rows.push((label, cells));
        }
    }
    Ok(tables)
}

/// One relation `printed = computed` with its rounding allowance (the
/// witness gives the cells `computed` is read from and its formula).
fn relation(what: &str, printed: &Num, computed: Recomputed, allowance: Rational) -> Check {
    let diff = printed.value.clone() - &computed.value;
    let ok = diff.clone().abs() <= allowance;
    let text = if ok {
        format!(
            "printed {}, computed {}, difference {} (within the printed rounding; allowance ±{})",
            printed.text,
            decimal(&computed.value),
            decimal(&diff),
            decimal(&allowance)
        )
    } else {
        format!(
            "difference {} exceeds the rounding allowance ±{} (inconsistent)",
            decimal(&diff),
            decimal(&allowance)
        )
    };
    let witness = (!ok).then(|| {
        recomputed::witness(
            None,
            Relation::Equal,
            &[
                (
                    "printed",
                    &Recomputed::printed(&printed.text, &printed.value),
                ),
                ("computed", &computed),
            ],
        )
    });
    Check {
        ok,
        detail: Evidence::new(Kind::Comparison, text)
            .about(what, if ok { Status::Holds } else { Status::Fails })
            .witnessed(witness),
    }
}

/// One checked relation: whether it holds, and its evidence.
struct Check {
    ok: bool,
    detail: Evidence,
}

/// Segment-table columns: before total, after total, max, min, average.
const COLUMNS: [&str; 5] = ["before total", "after total", "max", "min", "average"];

/// The symbols naming the cells of each column in a witness (`before3`:
/// the before total of segment 3; `before`: of the TOTAL row).
pub const SYMBOLS: [&str; 5] = ["before", "after", "max", "min", "ave"];

impl Num {
    /// This printed number as the cell `symbol` of a witness.
    pub fn cell(&self, symbol: impl Into<String>) -> Cell {
        Cell::new(symbol, &self.text, &self.value)
    }
}

pub fn total_row(t: &Table) -> Result<&[Num], String> {
    t.rows
        .iter()
        .find(|(l, _)| l == "TOTAL")
        .map(|(_, c)| c.as_slice())
        .ok_or_else(|| format!("Table {} has no TOTAL row", t.number))
}

fn segment_checks(t: &Table) -> Result<Vec<Check>, String> {
    let total = total_row(t)?;
    let segs: Vec<(&str, &[Num])> = t
        .rows
        .iter()
        .filter(|(l, _)| l != "TOTAL")
        .map(|(l, c)| (l.as_str(), c.as_slice()))
        .collect();
    if segs.is_empty() || total.len() != 5 || segs.iter().any(|(_, c)| c.len() != 5) {
        return Err(format!("Table {}: every row needs 5 cells", t.number));
    }
    let n = Rational::from(segs.len());
    let col = |k: usize| segs.iter().map(move |(_, c)| &c[k]);
    let cells = |k: usize| -> Vec<Cell> {
        segs.iter()
            .map(|(l, c)| c[k].cell(format!("{}{l}", SYMBOLS[k])))
            .collect()
    };
    let total_cell = |k: usize| Recomputed::cell(total[k].cell(SYMBOLS[k]));
    let formula =
        |r: Option<Recomputed>| r.ok_or_else(|| format!("Table {}: no segments", t.number));
    let allowances = |k: usize| col(k).fold(Rational::new(), |a, x| a + &x.allowance);
    let mut out = Vec::new();
    for (k, name) in COLUMNS.iter().enumerate().take(2) {
        out.push(relation(
            &format!("TOTAL {name} = Σ of {} segments", segs.len()),
            &total[k],
            formula(Recomputed::sum(cells(k)))?,
            allowances(k) + &total[k].allowance,
        ));
    }
    let extreme = |k: usize, max: bool| {
        col(k)
            .max_by(|a, b| {
                let o = a.value.cmp(&b.value);
                if max { o } else { o.reverse() }
            })
            .expect("segments")
    };
    for (k, max) in [(2, true), (3, false)] {
        let e = extreme(k, max);
        out.push(relation(
            &format!(
                "TOTAL {} = {} over the segments",
                COLUMNS[k],
                if max { "max" } else { "min" }
            ),
            &total[k],
            formula(Recomputed::extreme(cells(k), max))?,
            e.allowance.clone() + &total[k].allowance,
        ));
    }
    out.push(relation(
        "TOTAL average = mean of the segment averages",
        &total[4],
        formula(Recomputed::mean(cells(4)))?,
        allowances(4) / &n + &total[4].allowance,
    ));
    for (key, v) in &t.texts {
        // a TOTAL cell, or the increment after − before
        let cell = |k: usize| Ok((total_cell(k), total[k].allowance.clone()));
        let (computed, allowance) = match key.as_str() {
            "before" => cell(0),
            "after" => cell(1),
            "max" => cell(2),
            "min" => cell(3),
            "ave" => cell(4),
            "increment" => {
                let difference = Sym::var(SYMBOLS[1]) - &Sym::var(SYMBOLS[0]);
                let cells = vec![total[0].cell(SYMBOLS[0]), total[1].cell(SYMBOLS[1])];
                formula(Recomputed::of(&difference, cells))
                    .map(|r| (r, total[0].allowance.clone() + &total[1].allowance))
            }
            other => Err(format!("Table {}: unknown text key {other}", t.number)),
        }?;
        let what = match key.as_str() {
            "increment" => "text: increment = TOTAL after − TOTAL before".to_string(),
            k => format!("text: {k} = TOTAL row"),
        };
        out.push(relation(&what, v, computed, allowance + &v.allowance));
    }
    Ok(out)
}

/// Summary rows and the per-letter TOTAL column they repeat.
const SUMMARY: [(&str, usize); 4] = [
    ("Total Error", 1),
    ("Max. Error", 2),
    ("Min. Error", 3),
    ("Ave. Error", 4),
];
pub const SCHEMES: [&str; 4] = ["proposed", "Majeed", "Han", "Usman"];

fn find<'a>(tables: &'a [Table], number: &str) -> Result<&'a Table, String> {
    tables
        .iter()
        .find(|t| t.number == number)
        .ok_or_else(|| format!("no Table {number}"))
}

pub fn summary_row<'a>(t: &'a Table, label: &str) -> Result<&'a [Num], String> {
    t.rows
        .iter()
        .find(|(l, _)| l == label)
        .map(|(_, c)| c.as_slice())
        .filter(|c| c.len() == 4)
        .ok_or_else(|| format!("Table {}: no row {label} with 4 cells", t.number))
}

fn summary_checks(t: &Table, tables: &[Table]) -> Result<Vec<Check>, String> {
    let mut out = Vec::new();
    for (label, k) in SUMMARY {
        let row = summary_row(t, label)?;
        for (j, number) in t.of.iter().enumerate() {
            let total = total_row(find(tables, number)?)?;
            out.push(relation(
                &format!(
                    "{label}, {} = Table {number} TOTAL {}",
                    SCHEMES[j], COLUMNS[k]
                ),
                &row[j],
                Recomputed::cell(total[k].cell(SYMBOLS[k])),
                row[j].allowance.clone() + &total[k].allowance,
            ));
        }
    }
    Ok(out)
}

fn best_checks(t: &Table, tables: &[Table]) -> Result<Vec<Check>, String> {
    let mut out = Vec::new();
    for (letter, scheme, ave, bad) in &t.best {
        let summary = tables
            .iter()
            .find(|s| s.scheme == "summary" && s.letter == *letter)
            .ok_or_else(|| format!("no summary table for {letter}"))?;
        let aves = summary_row(summary, "Ave. Error")?;
        let bads = summary_row(summary, "Bad points (>1.5)")?;
        let j = SCHEMES
            .iter()
            .position(|s| scheme.contains(s))
            .ok_or_else(|| format!("unknown scheme {scheme}"))?;
        let lowest = (0..4)
            .min_by(|a, b| aves[*a].value.cmp(&aves[*b].value))
            .expect("four columns");
        out.push(Check {
            ok: lowest == j,
            detail: Evidence::new(
                Kind::Comparison,
                format!(
                    "printed best \"{scheme}\"; smallest average error in Table {} is {} ({})",
                    summary.number, SCHEMES[lowest], aves[lowest].text
                ),
            )
            .about(
                format!("{letter}: best"),
                if lowest == j {
                    Status::Holds
                } else {
                    Status::Fails
                },
            ),
        });
        out.push(relation(
            &format!(
                "{letter}: average error = Table {} Ave. Error, {}",
                summary.number, SCHEMES[j]
            ),
            ave,
            Recomputed::cell(aves[j].cell(SCHEMES[j])),
            ave.allowance.clone() + &aves[j].allowance,
        ));
        out.push(relation(
            &format!(
                "{letter}: bad points = Table {} Bad points, {}",
                summary.number, SCHEMES[j]
            ),
            bad,
            Recomputed::cell(bads[j].cell(SCHEMES[j])),
            Rational::new(),
        ));
    }
    Ok(out)
}

/// The sub-verdict of one table.
fn table_verdict(t: &Table, tables: &[Table]) -> Verdict {
    let checks = if !t.best.is_empty() {
        best_checks(t, tables)
    } else if t.scheme == "summary" {
        summary_checks(t, tables)
    } else {
        segment_checks(t)
    };
    match checks {
        Ok(checks) => {
            let ok = checks.iter().all(|c| c.ok);
            let mut evidence: EvidenceList =
                t.notes.iter().map(|n| format!("garbled: {n}")).collect();
            evidence.extend(checks.iter().filter(|c| !c.ok).map(|c| c.detail.clone()));
            let passed = checks.iter().filter(|c| c.ok).count();
            if t.scheme == "summary" {
                evidence.push("row Bad points (>1.5): not in the per-letter tables, not compared");
            }
            // the relations are listed in the method; the failing ones above
            evidence.push(if ok {
                format!("all {passed} relations consistent")
            } else {
                format!(
                    "{} consistent",
                    trig_verdict::plural(passed, "other relation", "other relations")
                )
            });
            Verdict::new(
                if ok { Status::Holds } else { Status::Fails },
                METHOD,
                evidence,
            )
        }
        Err(why) => Verdict::not_checkable(why),
    }
}

/// The arithmetic of every table of the table file `text`: one part per
/// table (segment, summary or best-scheme table), each holding when every
/// relation it prints is within the printed rounding.
pub fn decide(text: &str) -> Verdict {
    let tables = match parse(text) {
        Ok(t) => t,
        Err(e) => return Verdict::not_checkable(e.to_string()),
    };
    let parts = tables
        .iter()
        .map(|t| {
            (
                format!(
                    "Table {} ({}, {} {})",
                    t.number, t.letter, t.scheme, t.column
                ),
                table_verdict(t, &tables),
            )
        })
        .collect();
    Verdict::all(METHOD, parts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_table_6_2_to_6_17_is_read() {
        let text = include_str!("../../../documents/thesis/tables-6.2-6.17.txt");
        let tables = parse(text).unwrap();
        let numbers: Vec<&str> = tables.iter().map(|t| t.number.as_str()).collect();
        let want: Vec<String> = (2..=17).map(|k| format!("6.{k}")).collect();
        assert_eq!(numbers, want);
    }

    #[test]
    fn decimals_and_allowances_are_exact() {
        let x = Num::parse("0.000017697", 1).unwrap();
        assert_eq!(x.value, Rational::from((17697, 1_000_000_000)));
        assert_eq!(x.allowance, Rational::from((1, 2_000_000_000)));
        assert_eq!(decimal(&Rational::from((-8023, 10000))), "-0.8023");
        assert_eq!(decimal(&Rational::from((3, 1))), "3");
        assert_eq!(decimal(&Rational::from((1, 20000))), "0.00005");
    }

    #[test]
    fn a_consistent_table_holds_and_an_inconsistent_one_fails() {
        let data = "== 9.1 | x | s | (I)\n1\t1.5\t2\t3\t0\t1\n2\t2.25\t2\t4\t0\t3\nTOTAL\t3.75\t4\t4\t0\t2\n\
                    == 9.2 | x | s | (I)\n1\t1.5\t2\t3\t0\t1\n2\t2.25\t2\t4\t0\t3\nTOTAL\t3.85\t4\t3\t0\t2\n";
        let tables = parse(data).unwrap();
        assert_eq!(table_verdict(&tables[0], &tables).status, Status::Holds);
        let bad = table_verdict(&tables[1], &tables);
        assert_eq!(bad.status, Status::Fails);
        assert!(
            bad.evidence[0].contains("difference 0.1 "),
            "{:?}",
            bad.evidence
        );
        assert!(bad.evidence[1].contains("TOTAL max"), "{:?}", bad.evidence);
        assert!(
            bad.evidence[1].contains("inconsistent"),
            "{:?}",
            bad.evidence
        );
    }

    #[test]
    fn malformed_data_is_a_typed_error() {
        let e = parse("1\t2\n").unwrap_err();
        assert_eq!(e.line, 1);
        assert!(parse("== 1 | a | b | c\n1\tx\n").is_err());
    }
}
