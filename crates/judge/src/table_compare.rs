//! The readings a document's text makes between the tables of different
//! schemes (`check = "table-compare"`): an order of the schemes in a
//! summary row, the scheme of least value in summary rows, two schemes'
//! segment tables printing the same values, a quoted count of segments —
//! each recomputed exactly from the printed cells (a table file of
//! [`crate::table_arithmetic`], each cell the exact rational of its
//! printed decimal).
//!
//! A **comparisons file**: `#` comment lines, then one statement a line,
//! five tab-separated fields `KIND  WHERE  WHAT  ARGUMENT  printed words`:
//!
//! | kind | where | what | argument | reading |
//! |---|---|---|---|---|
//! | `name` | a scheme | `-` | `-` | the report names the scheme by the printed words |
//! | `order` | a summary table | its rows, `; `-separated | schemes, smallest first | the first row orders the schemes as printed (the other rows are shown for comparison) |
//! | `least` | summary tables | a row | a scheme | in each table the scheme has the smallest value of the row, strictly (tied with another, it is not least) |
//! | `equal` | two schemes `A B` | columns | `-` | for each letter with segment tables of both, the two print the same value in every segment of each column (the other schemes' agreement with `B` shown) |
//! | `count` | a letter | a column | `N: A != B; C = B` | the segments of the letter where every condition holds number `N` (a quoted figure) |
//! | `unmeasured` | `-` | `-` | why | no printed table measures it: `not-checkable` with the reason |
//!
//! A column is a segment table's `before`, `after`, `max`, `min` or `ave`
//! (any case). One part per statement, named by its printed words.

use rug::Rational;
use trig_verdict::evidence::{Evidence, Kind, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::quoted::{QUOTED, quoted_figure, quoted_order};
use crate::recomputed::{Recomputed, decimal};
use crate::table_arithmetic::{SCHEMES, SYMBOLS, Table, parse, summary_row};
use crate::table_quotes::{Segment, pair, segments, status};

/// How the comparisons are decided, as the report states it.
pub const METHOD: &str = "exact comparison of the printed cells between the tables of different schemes (equal means the same rational); a quoted count holds when it is the recomputed count";

/// How `equal` is decided, as the report states it.
const EQUAL: &str =
    "exact comparison of the printed cells (equal means the same rational), segment by segment";

/// One statement of a comparisons file.
struct Line {
    kind: String,
    at: String,
    what: String,
    argument: String,
    printed: String,
}

fn lines(text: &str) -> Result<Vec<Line>, String> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        let f: Vec<&str> = raw.split('\t').collect();
        let [kind, at, what, argument, printed] = f[..] else {
            return Err(format!(
                "comparisons line {}: five tab-separated fields",
                i + 1
            ));
        };
        out.push(Line {
            kind: kind.into(),
            at: at.into(),
            what: what.into(),
            argument: argument.into(),
            printed: printed.into(),
        });
    }
    Ok(out)
}

/// The schemes' names for the report (`name` lines; a scheme without one
/// is named by its key).
struct Names(Vec<(String, String)>);

impl Names {
    fn of<'a>(&'a self, key: &'a str) -> &'a str {
        self.0
            .iter()
            .find(|(k, _)| k == key)
            .map_or(key, |(_, n)| n.as_str())
    }
}

fn table<'a>(tables: &'a [Table], number: &str) -> Result<&'a Table, String> {
    tables
        .iter()
        .find(|t| t.number == number)
        .ok_or_else(|| format!("no Table {number}"))
}

/// The segment table of `scheme` for `letter`.
fn segment_table<'a>(tables: &'a [Table], letter: &str, scheme: &str) -> Result<&'a Table, String> {
    tables
        .iter()
        .find(|t| t.letter == letter && t.scheme == scheme)
        .ok_or_else(|| format!("no {scheme} table for {letter}"))
}

/// The index of a segment table's column (`before`, `After`, …).
fn column(name: &str) -> Result<usize, String> {
    SYMBOLS
        .iter()
        .position(|s| s.eq_ignore_ascii_case(name))
        .ok_or_else(|| format!("unknown column {name}"))
}

fn scheme(key: &str) -> Result<&'static str, String> {
    SCHEMES
        .iter()
        .copied()
        .find(|s| *s == key)
        .ok_or_else(|| format!("unknown scheme {key}"))
}

/// The cells of `row` of a summary table, by scheme (named for the report).
fn row_entries<'a>(
    t: &Table,
    row: &str,
    names: &'a Names,
) -> Result<Vec<(&'a str, Recomputed)>, String> {
    let cells = summary_row(t, row)?;
    Ok(SCHEMES
        .iter()
        .zip(cells)
        .map(|(s, c)| (names.of(s), Recomputed::cell(c.cell(*s))))
        .collect())
}

fn order(tables: &[Table], l: &Line, names: &Names) -> Result<Verdict, String> {
    let t = table(tables, &l.at)?;
    let printed: Vec<&str> = l
        .argument
        .split_whitespace()
        .map(|k| scheme(k).map(|s| names.of(s)))
        .collect::<Result<_, _>>()?;
    let mut rows = l.what.split("; ");
    let first = rows.next().unwrap_or_default();
    let mut items = vec![quoted_order(
        &format!("order by {first}"),
        &format!("{first} of Table {}", t.number),
        &row_entries(t, first, names)?,
        &printed,
    )];
    for row in rows {
        let e = quoted_order(row, row, &row_entries(t, row, names)?, &printed);
        items.push(Evidence::note(format!(
            "for comparison (not the criterion the text names), {row}: {}",
            e.text
        )));
    }
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Ok(Verdict::new(st, QUOTED, items))
}

fn least(tables: &[Table], l: &Line, names: &Names) -> Result<Verdict, String> {
    let named = names.of(scheme(&l.argument)?);
    let mut items = Vec::new();
    for number in l.at.split_whitespace() {
        let t = table(tables, number)?;
        let entries = row_entries(t, &l.what, names)?;
        let (best, v) = entries
            .iter()
            .min_by(|a, b| a.1.value.cmp(&b.1.value))
            .ok_or_else(|| format!("Table {}: empty row {}", t.number, l.what))?;
        let (_, mine) = entries
            .iter()
            .find(|(n, _)| *n == named)
            .expect("every scheme has a cell");
        // strictly least, as `order` reads an order: a scheme tied with
        // another for the smallest value is not "the most precise"
        let rival = entries
            .iter()
            .filter(|(n, _)| *n != named)
            .min_by(|a, b| a.1.value.cmp(&b.1.value));
        let ok = rival.is_none_or(|(_, r)| r.value > mine.value);
        let tie = rival
            .filter(|(_, r)| r.value == mine.value)
            .map_or(String::new(), |(n, _)| {
                format!(" — tied with {n}: no scheme is strictly least")
            });
        items.push(
            Evidence::new(
                Kind::Comparison,
                format!(
                    "smallest {} in Table {}: {best} ({}); {named} {}{tie}",
                    l.what,
                    t.number,
                    decimal(&v.value),
                    decimal(&mine.value)
                ),
            )
            .about(format!("{}: {named} least", t.letter), status(ok))
            .witnessed(match rival {
                Some((n, r)) if !ok => pair(
                    format!("Table {}, {}", t.number, l.what),
                    Relation::Greater,
                    (n, r),
                    (named, mine),
                ),
                _ => None,
            }),
        );
    }
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Ok(Verdict::new(
        st,
        format!(
            "reading: \"{}\" = the smallest {} of the schemes, in each of Tables {}",
            l.printed,
            l.what,
            l.at.split_whitespace().collect::<Vec<_>>().join(", ")
        ),
        items,
    ))
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

/// The letters with a segment table, in the file's order.
fn letters(tables: &[Table]) -> Vec<&str> {
    let mut out: Vec<&str> = Vec::new();
    for t in tables
        .iter()
        .filter(|t| SCHEMES.contains(&t.scheme.as_str()))
    {
        if !out.contains(&t.letter.as_str()) {
            out.push(&t.letter);
        }
    }
    out
}

fn equal(tables: &[Table], l: &Line, names: &Names) -> Result<Verdict, String> {
    let [a, b] = l.at.split_whitespace().collect::<Vec<_>>()[..] else {
        return Err(format!("`equal` names two schemes, not `{}`", l.at));
    };
    let (a, b) = (scheme(a)?, scheme(b)?);
    let mut items = Vec::new();
    for letter in letters(tables) {
        let (ta, tb) = (
            segment_table(tables, letter, a)?,
            segment_table(tables, letter, b)?,
        );
        let (sa, sb) = (segments(ta)?, segments(tb)?);
        for name in l.what.split_whitespace() {
            let k_col = column(name)?;
            let eq = same(&sa, &sb, k_col)?;
            let (n, k) = (eq.len(), eq.iter().filter(|x| **x).count());
            let first = sa.iter().zip(&sb).zip(&eq).find(|(_, e)| !**e);
            let witness = first.and_then(|((x, y), _)| {
                let cell = |s: &Segment, key: &str| {
                    Recomputed::cell(s.cells[k_col].cell(format!("{key}{}", s.number)))
                };
                pair(
                    format!("segment {}, {name}", x.number),
                    Relation::Equal,
                    (
                        &format!("Table {} ({})", ta.number, names.of(a)),
                        &cell(x, a),
                    ),
                    (
                        &format!("Table {} ({})", tb.number, names.of(b)),
                        &cell(y, b),
                    ),
                )
            });
            let mut others = Vec::new();
            for c in SCHEMES.iter().filter(|s| ![a, b].contains(s)) {
                let tc = segment_table(tables, letter, c)?;
                let k = same(&segments(tc)?, &sb, k_col)?
                    .iter()
                    .filter(|x| **x)
                    .count();
                others.push(format!(
                    "{} = {} in {k} of {n} (Table {})",
                    names.of(c),
                    names.of(b),
                    tc.number
                ));
            }
            items.push(
                Evidence::new(
                    Kind::Comparison,
                    format!(
                        "{} = {} in {k} of {n} segments (Tables {} and {}); {}",
                        names.of(a),
                        names.of(b),
                        ta.number,
                        tb.number,
                        others.join("; ")
                    ),
                )
                .about(
                    format!("{letter}, {name}: {} = {}", names.of(a), names.of(b)),
                    status(k == n),
                )
                .witnessed(witness),
            );
        }
    }
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Ok(Verdict::new(st, EQUAL, items))
}

fn count(tables: &[Table], l: &Line, names: &Names) -> Result<Verdict, String> {
    let (quoted, conditions) = l
        .argument
        .split_once(':')
        .ok_or_else(|| format!("`count` needs `N: conditions`, not `{}`", l.argument))?;
    let k_col = column(&l.what)?;
    let mut tests: Vec<(Vec<Segment>, Vec<Segment>, bool)> = Vec::new();
    let mut said = Vec::new();
    for c in conditions.split(';') {
        let (x, y, equal) = match c.split_once("!=") {
            Some((x, y)) => (x, y, false),
            None => {
                let (x, y) = c
                    .split_once('=')
                    .ok_or_else(|| format!("`{c}`: expected `A = B` or `A != B`"))?;
                (x, y, true)
            }
        };
        let (x, y) = (scheme(x.trim())?, scheme(y.trim())?);
        said.push(format!(
            "{} {} {}",
            names.of(x),
            if equal { "=" } else { "≠" },
            names.of(y)
        ));
        tests.push((
            segments(segment_table(tables, &l.at, x)?)?,
            segments(segment_table(tables, &l.at, y)?)?,
            equal,
        ));
    }
    let mut holds: Option<Vec<bool>> = None;
    for (x, y, equal) in &tests {
        let eq = same(x, y, k_col)?;
        let this: Vec<bool> = eq.iter().map(|e| *e == *equal).collect();
        holds = Some(match holds {
            None => this,
            Some(h) => h.iter().zip(&this).map(|(a, b)| *a && *b).collect(),
        });
    }
    let holds = holds.ok_or("`count` needs a condition")?;
    let n = holds.len();
    let k = holds.iter().filter(|h| **h).count();
    let item = quoted_figure(
        &format!("{} {} segments with {}", l.at, l.what, said.join(" and ")),
        quoted.trim(),
        Rational::from(k),
        &format!("count over the {n} segments"),
    );
    let st = item.status.unwrap_or(Status::NotCheckable);
    Ok(Verdict::new(st, QUOTED, [item]))
}

/// Every statement of `comparisons` (a comparisons file) about the tables
/// of `tables` (a table file), one part per statement.
pub fn decide(tables: &str, comparisons: &str) -> Verdict {
    let (tables, lines) = match (parse(tables).map_err(|e| e.to_string()), lines(comparisons)) {
        (Ok(t), Ok(l)) => (t, l),
        (Err(e), _) | (_, Err(e)) => return Verdict::not_checkable(e),
    };
    let names = Names(
        lines
            .iter()
            .filter(|l| l.kind == "name")
            .map(|l| (l.at.clone(), l.printed.clone()))
            .collect(),
    );
    let parts = lines
        .iter()
        .filter(|l| l.kind != "name")
        .map(|l| {
            let v = match l.kind.as_str() {
                "order" => order(&tables, l, &names),
                "least" => least(&tables, l, &names),
                "equal" => equal(&tables, l, &names),
                "count" => count(&tables, l, &names),
                "unmeasured" => Ok(Verdict::not_checkable(l.argument.clone())),
                other => Err(format!("unknown kind {other}")),
            };
            (l.printed.clone(), v.unwrap_or_else(Verdict::not_checkable))
        })
        .collect();
    Verdict::all(METHOD, parts)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One letter, three schemes: Han prints proposed's Before column in
    /// segment 2 only, Majeed prints Han's in both.
    const TABLES: &str = "== 9.1 | x | proposed | (I)\n\
        1\t10\t30\t3\t0\t1\n\
        2\t20\t20\t4\t0\t2\n\
        TOTAL\t30\t50\t4\t0\t1.5\n\
        == 9.2 | x | Majeed | (II)\n\
        1\t11\t30\t3\t0\t1\n\
        2\t20\t20\t4\t0\t2\n\
        TOTAL\t31\t50\t4\t0\t1.5\n\
        == 9.3 | x | Han | (III)\n\
        1\t11\t30\t3\t0\t1\n\
        2\t20\t20\t4\t0\t2\n\
        TOTAL\t31\t50\t4\t0\t1.5\n\
        == 9.4 | x | Usman | (IV)\n\
        1\t12\t30\t3\t0\t1\n\
        2\t20\t20\t4\t0\t2\n\
        TOTAL\t32\t50\t4\t0\t1.5\n\
        == 9.5 | x | summary | all\n\
        of 9.1 9.2 9.3 9.4\n\
        Ave. Error\t1.5\t1.2\t1.1\t2\n\
        Total Error\t50\t50\t50\t50\n";

    /// The verdict on one statement (with the name line, which is no part).
    fn part(line: &str) -> Verdict {
        decide(TABLES, &format!("name\tMajeed\t-\t-\tM&Q\n{line}"))
    }

    #[test]
    fn orders_and_least_values_are_read_from_a_summary_row() {
        let order = |o: &str| part(&format!("order\t9.5\tAve. Error; Total Error\t{o}\tw")).status;
        assert_eq!(order("Han Majeed proposed Usman"), Status::Holds);
        assert_eq!(order("Majeed Han proposed Usman"), Status::Fails);
        let least = |s: &str| part(&format!("least\t9.5\tAve. Error\t{s}\tw")).status;
        assert_eq!(least("Han"), Status::Holds);
        assert_eq!(least("proposed"), Status::Fails);
        // a tie for the smallest value makes no scheme least, whichever
        // column it is printed in (Total Error: all four print 50)
        let tied = |s: &str| part(&format!("least\t9.5\tTotal Error\t{s}\tw"));
        for s in ["proposed", "Han", "Usman"] {
            let v = tied(s);
            assert_eq!(v.status, Status::Fails, "{s}: {v:?}");
            assert!(
                v.evidence
                    .iter()
                    .any(|e| e.line().contains("no scheme is strictly least")),
                "{s}: {v:?}"
            );
        }
    }

    #[test]
    fn equal_tables_and_counts_of_segments_are_exact() {
        assert_eq!(
            part("equal\tMajeed Han\tBefore After\t-\tw").status,
            Status::Holds
        );
        assert_eq!(
            part("equal\tproposed Han\tAfter\t-\tw").status,
            Status::Holds
        );
        assert_eq!(
            part("equal\tproposed Han\tBefore\t-\tw").status,
            Status::Fails
        );
        let count = |a: &str| part(&format!("count\tx\tbefore\t{a}\tw")).status;
        assert_eq!(count("1: proposed != Han; Majeed = Han"), Status::Holds);
        assert_eq!(count("2: proposed != Han; Majeed = Han"), Status::Fails);
        assert_eq!(count("2: Majeed = Han"), Status::Holds);
        assert_eq!(
            part("unmeasured\t-\t-\twhy\tw").status,
            Status::NotCheckable
        );
        assert_eq!(part("between\t-\t-\t-\tw").status, Status::NotCheckable);
    }
}
