//! The figures and statements in words a document's text quotes from its
//! printed error tables (`check = "table-quotes"`), recomputed from the
//! printed cells: a quoted figure holds when it is the exact recomputed
//! value rounded to the quoted decimals ([`crate::quoted`]); a statement in
//! words is decided under the reading its quotes file states with it.
//!
//! The tables are a table file of [`crate::table_arithmetic`] (each cell an
//! exact rational read from its printed decimal; the figures a paragraph
//! quotes are its `text` lines); the statements in words are a **quotes
//! file**: `#` comment lines, then one statement a line, four tab-separated
//! fields `TABLE  KIND  ARGUMENT  the printed words`, `KIND` one of
//!
//! | kind | argument | reading |
//! |---|---|---|
//! | `largest` | segments | the named segments hold the largest After totals: the smallest named above the largest other |
//! | `increase` | segments | the named segments show the largest increases, after − before or after/before (either ranking) |
//! | `increased` | segments | every named segment has after > before |
//! | `unchanged` | segments | every named segment has after = before |
//! | `most-increased` | `-` | more than half of the segments have after > before |
//! | `mostly-below` | a decimal `x` | more than half of the segment averages are below `x` |

use trig_symbolic::Sym;
use trig_verdict::evidence::{Evidence, Kind, Relation, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::quoted::{QUOTED, quoted_figure};
use crate::recomputed::{self, Cell, Recomputed, decimal};
use crate::table_arithmetic::{Num, SCHEMES, SYMBOLS, Table, parse, total_row};

/// How the quotes are decided, as the report states it.
pub const METHOD: &str = "exact rational arithmetic on the printed cells; a quoted figure with d decimals holds when it is the recomputed value rounded to d places (before/after: the TOTAL row; increment: TOTAL after − TOTAL before; maximum/minimum: over the segment rows; average: the TOTAL row and the mean of the segment averages); statements in words under the reading stated with each";

/// The columns of a segment table.
pub const BEFORE: usize = 0;
pub const AFTER: usize = 1;
const MAX: usize = 2;
const MIN: usize = 3;
const AVE: usize = 4;

/// One segment row: its number and its five cells.
#[derive(Debug, Clone, Copy)]
pub struct Segment<'a> {
    pub number: usize,
    pub cells: &'a [Num],
}

impl Segment<'_> {
    /// The printed cell of `column` (the witness symbol `after3`, …).
    pub fn cell(&self, column: usize) -> Cell {
        self.cells[column].cell(format!("{}{}", SYMBOLS[column], self.number))
    }
    /// `column` as it is printed.
    fn printed(&self, column: usize) -> Recomputed {
        Recomputed::cell(self.cell(column))
    }
    /// `after − before`.
    pub fn increase(&self) -> Recomputed {
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

pub fn segments(t: &Table) -> Result<Vec<Segment<'_>>, String> {
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

/// A statement in words of a quotes file.
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
        let err = |why: &str| format!("quotes line {}: {why}", i + 1);
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
pub fn pair(
    note: String,
    stated: Relation,
    a: (&str, &Recomputed),
    b: (&str, &Recomputed),
) -> Option<Witness> {
    Some(recomputed::witness(Some(note), stated, &[a, b]))
}

pub fn status(ok: bool) -> Status {
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

/// The quoted figures of every segment table of `tables` (a table file)
/// and the statements in words of `quotes` (a quotes file), one part per
/// table; a quote about a table the file does not have is not decided.
pub fn decide(tables: &str, quotes_text: &str) -> Verdict {
    let (tables, quotes) = match (
        parse(tables).map_err(|e| e.to_string()),
        quotes(quotes_text),
    ) {
        (Ok(t), Ok(q)) => (t, q),
        (Err(e), _) | (_, Err(e)) => return Verdict::not_checkable(e),
    };
    if let Some(q) = quotes
        .iter()
        .find(|q| !tables.iter().any(|t| t.number == q.table))
    {
        return Verdict::not_checkable(format!(
            "the quote \"{}\" is about Table {}, which the table file does not print",
            q.printed, q.table
        ));
    }
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
    Verdict::all(METHOD, parts)
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
    fn a_quote_about_a_table_not_printed_is_not_decided() {
        assert_eq!(decide(TABLE, "9.1\tlargest\t1\tw").status, Status::Holds);
        let v = decide(TABLE, "9.2\tlargest\t1\tw");
        assert_eq!(v.status, Status::NotCheckable);
        assert!(v.evidence[0].text.contains("Table 9.2"), "{:?}", v.evidence);
    }
}
