//! Thesis Chapter 6, the text against its tables (claims T66, T67, T68,
//! T71): every figure and every statement in words that the paragraphs of
//! 6.8 and 6.9 derive from Tables 6.2–6.16, recomputed from the printed
//! cells.
//!
//! The tables are those of claim T32 (`documents/thesis/tables-6.2-6.17.txt`, each cell an
//! exact rational read from its printed decimal); the statements in words
//! are `thesis_text_quotes.txt`, each with the reading it is decided under.
//! A quoted figure is judged by [`trig_judge::quoted`]: it holds when it
//! is the exact recomputed value rounded to the quoted decimals.

use rug::Rational;
use trig_core::Family;
use trig_symbolic::Sym;

use trig_judge::table_arithmetic::{Num, SCHEMES, SYMBOLS, Table, parse, summary_row, total_row};

/// The tables of claim T32 (the table file beside the thesis's document file).
const DATA: &str = include_str!("../../../documents/thesis/tables-6.2-6.17.txt");
use crate::claim::Claim;
use trig_judge::exact::IDENTITY;
use trig_judge::quoted::{QUOTED, quoted_figure, quoted_order};
use trig_judge::recomputed::decimal;
use trig_judge::recomputed::{self, Cell, Recomputed};
use trig_judge::same_basis::same_basis;
use trig_verdict::evidence::{Evidence, Kind, Relation, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T66",
        check: t66,
    },
    Claim {
        id: "T67",
        check: t67,
    },
    Claim {
        id: "T68",
        check: t68,
    },
];

const QUOTES: &str = include_str!("thesis_text_quotes.txt");

/// How T66 is decided, as the report states it.
const T66_METHOD: &str = "exact rational arithmetic on the printed cells; a quoted figure with d decimals holds when it is the recomputed value rounded to d places (before/after: the TOTAL row; increment: TOTAL after − TOTAL before; maximum/minimum: over the segment rows; average: the TOTAL row and the mean of the segment averages, the convention of Tables 6.2–6.9 and of the summary Tables 6.14–6.16); statements in words under the reading stated with each";

/// The columns of a segment table.
const BEFORE: usize = 0;
const AFTER: usize = 1;
const MAX: usize = 2;
const MIN: usize = 3;
const AVE: usize = 4;

/// One segment row: its number and its five cells.
struct Segment<'a> {
    number: usize,
    cells: &'a [Num],
}

impl Segment<'_> {
    /// The printed cell of `column` (the witness symbol `after3`, …).
    fn cell(&self, column: usize) -> Cell {
        self.cells[column].cell(format!("{}{}", SYMBOLS[column], self.number))
    }
    /// `column` as it is printed.
    fn printed(&self, column: usize) -> Recomputed {
        Recomputed::cell(self.cell(column))
    }
    /// `after − before`.
    fn increase(&self) -> Recomputed {
        let (b, a) = (self.cell(BEFORE), self.cell(AFTER));
        let formula = Sym::var(&a.symbol) - &Sym::var(&b.symbol);
        Recomputed::of(&formula, vec![b, a]).expect("a difference of cells")
    }
    /// `after/before`, when `before ≠ 0`.
    fn ratio(&self) -> Option<Recomputed> {
        let (b, a) = (self.cell(BEFORE), self.cell(AFTER));
        let formula = Sym::var(&a.symbol) / &Sym::var(&b.symbol);
        Recomputed::of(&formula, vec![b, a])
    }
}

fn segments(t: &Table) -> Result<Vec<Segment<'_>>, String> {
    t.rows
        .iter()
        .filter(|(label, _)| label != "TOTAL")
        .map(|(label, cells)| {
            let number = label
                .parse()
                .map_err(|_| format!("Table {}: row label {label} is not a segment", t.number))?;
            if cells.len() != 5 {
                return Err(format!(
                    "Table {}: segment {number} needs 5 cells",
                    t.number
                ));
            }
            Ok(Segment { number, cells })
        })
        .collect()
}

/// A statement in words of `thesis_text_quotes.txt`.
enum Words {
    Largest(Vec<usize>),
    Increase(Vec<usize>),
    Increased(Vec<usize>),
    Unchanged(Vec<usize>),
    MostIncreased,
    MostlyBelow(Num),
}

struct Quote {
    table: String,
    words: Words,
    printed: String,
}

fn quotes(data: &str) -> Result<Vec<Quote>, String> {
    let mut out = Vec::new();
    for (i, raw) in data.lines().enumerate() {
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        let err = |why: &str| format!("thesis_text_quotes.txt line {}: {why}", i + 1);
        let f: Vec<&str> = raw.split('\t').collect();
        let [table, kind, arg, printed] = f[..] else {
            return Err(err("four tab-separated fields"));
        };
        let segs = || -> Result<Vec<usize>, String> {
            arg.split_whitespace()
                .map(|s| s.parse().map_err(|_| err("segment numbers")))
                .collect()
        };
        let words = match kind {
            "largest" => Words::Largest(segs()?),
            "increase" => Words::Increase(segs()?),
            "increased" => Words::Increased(segs()?),
            "unchanged" => Words::Unchanged(segs()?),
            "most-increased" => Words::MostIncreased,
            "mostly-below" => {
                Words::MostlyBelow(Num::parse(arg, i + 1).map_err(|e| e.to_string())?)
            }
            other => return Err(err(&format!("unknown kind {other}"))),
        };
        out.push(Quote {
            table: table.into(),
            words,
            printed: printed.into(),
        });
    }
    Ok(out)
}

fn list(segs: &[usize]) -> String {
    segs.iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// A two-value witness: `stated` fails for `a` against `b`, exact.
fn pair(
    note: String,
    stated: Relation,
    a: (&str, &Recomputed),
    b: (&str, &Recomputed),
) -> Option<Witness> {
    Some(recomputed::witness(Some(note), stated, &[a, b]))
}

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
}

/// "The named segments stand above every other one by `key`": the smallest
/// named value against the largest other one.
fn stands_out(
    segs: &[Segment],
    named: &[usize],
    key: &dyn Fn(&Segment) -> Option<Recomputed>,
) -> Result<(bool, Option<Witness>, String), String> {
    let keyed = |inside: bool| -> Result<Vec<(usize, Recomputed)>, String> {
        segs.iter()
            .filter(|s| named.contains(&s.number) == inside)
            .map(|s| {
                key(s)
                    .map(|v| (s.number, v))
                    .ok_or_else(|| format!("segment {} has no value", s.number))
            })
            .collect()
    };
    let (inside, outside) = (keyed(true)?, keyed(false)?);
    if inside.len() != named.len() {
        return Err(format!("the table has no segment among {}", list(named)));
    }
    let low = inside
        .iter()
        .min_by(|a, b| a.1.value.cmp(&b.1.value))
        .expect("named");
    let Some(high) = outside.iter().max_by(|a, b| a.1.value.cmp(&b.1.value)) else {
        return Ok((true, None, "no other segment".into()));
    };
    let ok = low.1.value > high.1.value;
    let text = format!(
        "lowest named: segment {} ({}); highest other: segment {} ({})",
        low.0,
        decimal(&low.1.value),
        high.0,
        decimal(&high.1.value)
    );
    // stated: every other segment below every named one
    let witness = (!ok).then(|| {
        pair(
            format!("segment {} is not named, segment {} is", high.0, low.0),
            Relation::Less,
            (&format!("segment {}", high.0), &high.1),
            (&format!("segment {}", low.0), &low.1),
        )
    });
    Ok((ok, witness.flatten(), text))
}

/// The item deciding one statement in words about table `t`.
fn words_item(t: &Table, q: &Quote) -> Result<Evidence, String> {
    let segs = segments(t)?;
    let n = segs.len();
    let subject = format!("\"{}\"", q.printed);
    let item = |ok: bool, reading: &str, text: String, witness: Option<Witness>| {
        Evidence::new(Kind::Comparison, format!("reading: {reading}; {text}"))
            .about(subject.clone(), status(ok))
            .witnessed(witness)
    };
    let after = |s: &Segment| Some(s.printed(AFTER));
    Ok(match &q.words {
        Words::Largest(named) => {
            let (ok, w, text) = stands_out(&segs, named, &after)?;
            let (before_ok, _, _) =
                stands_out(&segs, named, &|s: &Segment| Some(s.printed(BEFORE)))?;
            item(
                ok,
                &format!(
                    "segment(s) {} hold the largest After total errors",
                    list(named)
                ),
                format!(
                    "{text} (the Before column {})",
                    if before_ok { "agrees" } else { "does not" }
                ),
                w,
            )
        }
        Words::Increase(named) => {
            let (abs_ok, abs_w, abs_text) =
                stands_out(&segs, named, &|s: &Segment| Some(s.increase()))?;
            let (rel_ok, _, rel_text) = stands_out(&segs, named, &|s: &Segment| s.ratio())?;
            item(
                abs_ok || rel_ok,
                &format!(
                    "segment(s) {} have the largest increases, after − before or after/before",
                    list(named)
                ),
                format!("after − before: {abs_text}; after/before: {rel_text}"),
                abs_w,
            )
        }
        Words::Increased(named) | Words::Unchanged(named) => {
            let rise = matches!(q.words, Words::Increased(_));
            let bad = segs.iter().find(|s| {
                named.contains(&s.number)
                    && if rise {
                        s.increase().value <= 0
                    } else {
                        s.increase().value != 0
                    }
            });
            let text = match bad {
                Some(s) => format!(
                    "segment {}: before {}, after {}",
                    s.number, s.cells[BEFORE].text, s.cells[AFTER].text
                ),
                None => format!("every one of segment(s) {}", list(named)),
            };
            let w = bad.and_then(|s| {
                pair(
                    format!("segment {}", s.number),
                    if rise {
                        Relation::Less
                    } else {
                        Relation::Equal
                    },
                    ("before", &s.printed(BEFORE)),
                    ("after", &s.printed(AFTER)),
                )
            });
            let reading = if rise {
                "after > before"
            } else {
                "after = before"
            };
            item(bad.is_none(), reading, text, w)
        }
        Words::MostIncreased => {
            let k = segs.iter().filter(|s| s.increase().value > 0).count();
            item(
                2 * k > n,
                "more than half of the segments have after > before",
                format!("{k} of {n}"),
                None,
            )
        }
        Words::MostlyBelow(x) => {
            let k = segs.iter().filter(|s| s.cells[AVE].value < x.value).count();
            item(
                2 * k > n,
                &format!(
                    "more than half of the segment averages are below {}",
                    x.text
                ),
                format!("{k} of {n}"),
                None,
            )
        }
    })
}

/// The items of the quoted figures of table `t` (its `text` lines).
fn figure_items(t: &Table) -> Result<Vec<Evidence>, String> {
    let total = total_row(t)?;
    let segs = segments(t)?;
    let column = |k: usize| segs.iter().map(move |s| s.cell(k)).collect::<Vec<_>>();
    let total_cell = |k: usize| Recomputed::cell(total[k].cell(SYMBOLS[k]));
    let no_segments = || format!("Table {}: no segments", t.number);
    let mut out = Vec::new();
    for (key, v) in &t.texts {
        let mut compare = |what: &str, r: Recomputed, from: &str| {
            out.push(quoted_figure(what, &v.text, r, from));
        };
        match key.as_str() {
            "before" => compare("total error before", total_cell(BEFORE), "TOTAL before"),
            "after" => compare("total error after", total_cell(AFTER), "TOTAL after"),
            "increment" => {
                let formula = Sym::var(SYMBOLS[AFTER]) - &Sym::var(SYMBOLS[BEFORE]);
                let cells = vec![
                    total[BEFORE].cell(SYMBOLS[BEFORE]),
                    total[AFTER].cell(SYMBOLS[AFTER]),
                ];
                compare(
                    "increase of the total error",
                    Recomputed::of(&formula, cells).ok_or_else(no_segments)?,
                    "TOTAL after − TOTAL before",
                )
            }
            "max" => compare(
                "maximum error",
                Recomputed::extreme(column(MAX), true).ok_or_else(no_segments)?,
                "max over the segments",
            ),
            "min" => compare(
                "minimum error",
                Recomputed::extreme(column(MIN), false).ok_or_else(no_segments)?,
                "min over the segments",
            ),
            "ave" => {
                compare("average error", total_cell(AVE), "TOTAL average");
                compare(
                    "average error",
                    Recomputed::mean(column(AVE)).ok_or_else(no_segments)?,
                    "mean of the segment averages",
                );
            }
            other => return Err(format!("Table {}: unknown text key {other}", t.number)),
        }
    }
    Ok(out)
}

fn table_part(t: &Table, quotes: &[Quote]) -> Verdict {
    let mut items = match figure_items(t) {
        Ok(items) => items,
        Err(why) => return Verdict::not_checkable(why),
    };
    for q in quotes.iter().filter(|q| q.table == t.number) {
        match words_item(t, q) {
            Ok(item) => items.push(item),
            Err(why) => return Verdict::not_checkable(why),
        }
    }
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Verdict::new(st, QUOTED, items)
}

fn tables() -> Result<Vec<Table>, String> {
    parse(DATA).map_err(|e| e.to_string())
}

fn t66() -> Verdict {
    let (tables, quotes) = match (tables(), quotes(QUOTES)) {
        (Ok(t), Ok(q)) => (t, q),
        (Err(e), _) | (_, Err(e)) => return Verdict::not_checkable(e),
    };
    let parts = tables
        .iter()
        .filter(|t| SCHEMES.contains(&t.scheme.as_str()))
        .map(|t| {
            (
                format!("Table {} ({}, {})", t.number, t.letter, t.scheme),
                table_part(t, &quotes),
            )
        })
        .collect();
    Verdict::all(T66_METHOD, parts)
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

#[cfg(test)]
mod tests {
    use super::*;

    const TABLE: &str = "== 9.1 | x | proposed | (I)\n\
        1\t10\t30\t3\t0\t1\n\
        2\t10\t20\t4\t0\t2\n\
        3\t10\t10\t2\t0\t3\n\
        TOTAL\t30\t60\t4\t0\t2\n\
        text increment 30\n\
        text ave 2\n";

    fn quote(line: &str) -> Quote {
        quotes(line).unwrap().pop().unwrap()
    }

    #[test]
    fn the_quoted_figures_of_a_table_are_recomputed() {
        let t = &parse(TABLE).unwrap()[0];
        let v = table_part(t, &[]);
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
        let bad = TABLE.replace("text ave 2", "text ave 2.1");
        let v = table_part(&parse(&bad).unwrap()[0], &[]);
        assert_eq!(v.status, Status::Fails);
    }

    #[test]
    fn statements_in_words_follow_their_reading() {
        let t = &parse(TABLE).unwrap()[0];
        let decide = |line: &str| words_item(t, &quote(line)).unwrap().status;
        assert_eq!(decide("9.1\tlargest\t1\tw"), Some(Status::Holds));
        assert_eq!(decide("9.1\tlargest\t2\tw"), Some(Status::Fails));
        assert_eq!(decide("9.1\tincrease\t1 2\tw"), Some(Status::Holds));
        assert_eq!(decide("9.1\tincrease\t1 3\tw"), Some(Status::Fails));
        assert_eq!(decide("9.1\tunchanged\t3\tw"), Some(Status::Holds));
        assert_eq!(decide("9.1\tincreased\t3\tw"), Some(Status::Fails));
        assert_eq!(decide("9.1\tmost-increased\t-\tw"), Some(Status::Holds));
        assert_eq!(decide("9.1\tmostly-below\t2\tw"), Some(Status::Fails));
        assert_eq!(decide("9.1\tmostly-below\t2.5\tw"), Some(Status::Holds));
        assert!(quotes("9.1\tsmallest\t1\tw").is_err());
    }

    #[test]
    fn every_quote_names_an_embedded_table() {
        let tables = tables().unwrap();
        for q in quotes(QUOTES).unwrap() {
            assert!(tables.iter().any(|t| t.number == q.table), "{}", q.table);
        }
    }
}
