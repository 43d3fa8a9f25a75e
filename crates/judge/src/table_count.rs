//! Counts a document's text quotes from a printed table of rows — a survey
//! with one row per paper ("15 papers out of 29 extend to surface", "most
//! focus on cubic", "the majority employ two shape parameters, followed by
//! one, three and multiple") — recomputed from the rows as printed
//! (`check = "table-count"`).
//!
//! A **row table file**: `#` comment lines (where the table is printed, how
//! it is transcribed), the fields `name: …`, `label: …` (how the report
//! names it, `Table 1.1`), `caption: …`, `citation: …`, then the header line
//! of tab-separated column names and one tab-separated row per printed row,
//! each with as many cells as the header.
//!
//! A **counts file**: `#` comment lines, then one statement a line, four
//! tab-separated fields `KIND  CLASSES  ARGUMENT  the printed words`.
//! A class is `*` (every row), `COLUMN = TEXT` (the cell is `TEXT`),
//! `COLUMN > X` or `COLUMN < X` (the cell is a number above / below the
//! decimal `X`, compared exactly); several classes are separated by ` ; `.
//!
//! | kind | classes | argument | reading |
//! |---|---|---|---|
//! | `exclude` | one | `-` | the rows of the class are left out of every count ("which excluded the proposed spline") |
//! | `count` | one | a count | the number of rows of the class is the quoted count |
//! | `most` | several | `-` | the first class has more rows than each other class (a plurality) |
//! | `order` | several | `majority` or `-` | the counts fall strictly in the printed order; with `majority` the first class also has more than half of the rows |

use std::fmt;

use rug::Rational;

use crate::quoted::quoted_figure;
use trig_verdict::evidence::{Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// A malformed line of a row table or counts file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CountError {
    pub file: &'static str,
    pub line: usize,
    pub reason: String,
}

impl fmt::Display for CountError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} line {}: {}", self.file, self.line, self.reason)
    }
}

impl std::error::Error for CountError {}

/// A printed table of rows, its cells as printed (trimmed).
#[derive(Debug, Clone)]
pub struct RowTable {
    pub label: String,
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// Reads a row table file.
pub fn rows(text: &str) -> Result<RowTable, CountError> {
    let err = |line: usize, reason: String| CountError {
        file: "the row table",
        line,
        reason,
    };
    let mut label = None;
    let mut header: Option<Vec<String>> = None;
    let mut rows = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        let cells: Vec<String> = raw.split('\t').map(|c| c.trim().to_string()).collect();
        match &header {
            None if cells.len() == 1 => {
                let (key, value) = raw
                    .split_once(':')
                    .ok_or_else(|| err(i + 1, "expected `field: value` or the header".into()))?;
                match key.trim() {
                    "label" => label = Some(value.trim().to_string()),
                    "name" | "caption" | "citation" => {}
                    other => return Err(err(i + 1, format!("unknown field `{other}`"))),
                }
            }
            None => header = Some(cells),
            Some(h) if cells.len() != h.len() => {
                return Err(err(
                    i + 1,
                    format!("{} cells, the header has {}", cells.len(), h.len()),
                ));
            }
            Some(_) => rows.push(cells),
        }
    }
    let header = header.ok_or_else(|| err(0, "no header line".into()))?;
    let label = label.ok_or_else(|| err(0, "no `label:` field".into()))?;
    Ok(RowTable {
        label,
        header,
        rows,
    })
}

/// How a class compares a cell.
#[derive(Debug, Clone, PartialEq)]
enum Test {
    Every,
    Is(String),
    Above(Rational),
    Below(Rational),
}

/// A class of rows: a column and a test of its cell.
#[derive(Debug, Clone, PartialEq)]
struct Class {
    text: String,
    column: usize,
    test: Test,
}

impl Class {
    fn parse(text: &str, header: &[String]) -> Result<Class, String> {
        let text = text.trim();
        if text == "*" {
            return Ok(Class {
                text: text.into(),
                column: 0,
                test: Test::Every,
            });
        }
        let (name, op, value) = [" = ", " > ", " < "]
            .iter()
            .filter_map(|op| text.split_once(op).map(|(a, b)| (a, *op, b)))
            .min_by_key(|(a, _, _)| a.len())
            .ok_or_else(|| {
                format!("`{text}`: expected `*`, `COLUMN = TEXT`, `COLUMN > X` or `COLUMN < X`")
            })?;
        let column = header
            .iter()
            .position(|h| h == name.trim())
            .ok_or_else(|| format!("`{text}`: no column `{}`", name.trim()))?;
        let number = || {
            trig_core::parse_exact(value.trim())
                .map_err(|e| format!("`{text}`: {} is not a decimal: {e}", value.trim()))
        };
        let test = match op {
            " = " => Test::Is(value.trim().to_string()),
            " > " => Test::Above(number()?),
            _ => Test::Below(number()?),
        };
        Ok(Class {
            text: text.into(),
            column,
            test,
        })
    }

    /// Whether `row` is of the class; a cell that is no number is of no
    /// numeric class.
    fn holds(&self, row: &[String]) -> bool {
        let cell = &row[self.column];
        let number = || trig_core::parse_exact(cell).ok();
        match &self.test {
            Test::Every => true,
            Test::Is(v) => cell == v,
            Test::Above(x) => number().is_some_and(|c| c > *x),
            Test::Below(x) => number().is_some_and(|c| c < *x),
        }
    }

    fn count(&self, rows: &[&Vec<String>]) -> usize {
        rows.iter().filter(|r| self.holds(r)).count()
    }
}

/// One statement of a counts file.
#[derive(Debug, Clone, PartialEq)]
struct Statement {
    kind: String,
    classes: Vec<Class>,
    argument: String,
    words: String,
}

fn statements(text: &str, header: &[String]) -> Result<Vec<Statement>, CountError> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        let err = |reason: String| CountError {
            file: "the counts file",
            line: i + 1,
            reason,
        };
        let f: Vec<&str> = raw.split('\t').map(str::trim).collect();
        let [kind, classes, argument, words] = f[..] else {
            return Err(err(
                "expected KIND, CLASSES, ARGUMENT and the printed words, tab-separated".into(),
            ));
        };
        let classes = classes
            .split(" ; ")
            .map(|c| Class::parse(c, header))
            .collect::<Result<Vec<_>, _>>()
            .map_err(err)?;
        let several = match kind {
            "exclude" | "count" => false,
            "most" | "order" => true,
            other => {
                return Err(err(format!(
                    "`{other}`: expected exclude, count, most or order"
                )));
            }
        };
        if several != (classes.len() > 1) {
            return Err(err(format!(
                "`{kind}` takes {} class",
                if several { "more than one" } else { "one" }
            )));
        }
        if !matches!(
            (kind, argument),
            ("exclude" | "most", "-") | ("count", _) | ("order", "majority" | "-")
        ) {
            return Err(err(format!(
                "`{kind}`: the argument `{argument}` is not one it takes"
            )));
        }
        out.push(Statement {
            kind: kind.into(),
            classes,
            argument: argument.into(),
            words: words.into(),
        });
    }
    Ok(out)
}

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
}

/// `class: count, …` of `classes` over `rows`.
fn tally(classes: &[Class], counts: &[usize]) -> String {
    classes
        .iter()
        .zip(counts)
        .map(|(c, n)| format!("{}: {n}", c.text))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The item of one statement (not `exclude`) over the counted rows.
fn item(s: &Statement, label: &str, left_out: &str, rows: &[&Vec<String>]) -> Evidence {
    let n = rows.len();
    let subject = format!("\"{}\"", s.words);
    let counts: Vec<usize> = s.classes.iter().map(|c| c.count(rows)).collect();
    let first = &s.classes[0].text;
    match s.kind.as_str() {
        "count" => {
            let from = match s.classes[0].test {
                Test::Every => format!("rows of {label}{left_out}"),
                _ => format!("rows with {first}"),
            };
            quoted_figure(&subject, &s.argument, Rational::from(counts[0]), &from)
        }
        "most" => {
            let plurality = counts[1..].iter().all(|k| *k < counts[0]);
            let none = rows
                .iter()
                .filter(|r| !s.classes.iter().any(|c| c.holds(r)))
                .count();
            Evidence::new(
                Kind::Comparison,
                format!(
                    "reading: more rows with {first} than with any other class; {} ({none} row(s) in no class); {first} is {} half of the {n} rows",
                    tally(&s.classes, &counts),
                    if 2 * counts[0] > n { "more than" } else { "not more than" }
                ),
            )
            .about(subject, status(plurality))
        }
        _ => {
            let majority = s.argument == "majority";
            let decreasing = counts.windows(2).all(|w| w[0] > w[1]);
            let ok = decreasing && (!majority || 2 * counts[0] > n);
            Evidence::new(
                Kind::Comparison,
                format!(
                    "reading: {}the counts fall strictly in the printed order; {}",
                    if majority {
                        format!("more than half of the {n} rows are rows with {first}, and ")
                    } else {
                        String::new()
                    },
                    tally(&s.classes, &counts)
                ),
            )
            .about(subject, status(ok))
        }
    }
}

/// The counts the statements of `counts` (a counts file) quote, against the
/// rows of `table` (a row table file).
pub fn decide(table: &str, counts: &str) -> Verdict {
    let run = || -> Result<Verdict, CountError> {
        let t = rows(table)?;
        let statements = statements(counts, &t.header)?;
        let excluded: Vec<&Class> = statements
            .iter()
            .filter(|s| s.kind == "exclude")
            .map(|s| &s.classes[0])
            .collect();
        let counted: Vec<&Vec<String>> = t
            .rows
            .iter()
            .filter(|r| !excluded.iter().any(|c| c.holds(r)))
            .collect();
        let names: Vec<&str> = excluded.iter().map(|c| c.text.as_str()).collect();
        let (left_out, method) = if names.is_empty() {
            (String::new(), String::new())
        } else {
            let names = names.join(" or ");
            (
                format!(" other than those with {names}"),
                format!(" (the rows with {names} left out, as the text says)"),
            )
        };
        let items: Vec<Evidence> = statements
            .iter()
            .filter(|s| s.kind != "exclude")
            .map(|s| item(s, &t.label, &left_out, &counted))
            .collect();
        let st = Status::conjunction(items.iter().filter_map(|e| e.status));
        Ok(Verdict::new(
            st,
            format!(
                "counts over the rows of {} as printed{method}; quoted counts compared exactly",
                t.label
            ),
            items,
        ))
    };
    run().unwrap_or_else(|e| Verdict::not_checkable(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TABLE: &str = "# a survey\nname: t\nlabel: Table 9.1\nNo.\tDegree\tParameters\tSurface\n1.\t3\t2\tYes\n2.\t3\t1\tNo\n3.\t2\t2\tYes\n4.\t3\t2\tNo\n5.\t1\t-\tYes\n";

    fn verdict(counts: &str) -> Verdict {
        decide(TABLE, counts)
    }

    #[test]
    fn counts_follow_the_rows() {
        assert_eq!(verdict("count\t*\t5\tw").status, Status::Holds);
        assert_eq!(verdict("count\tSurface = Yes\t3\tw").status, Status::Holds);
        assert_eq!(verdict("count\tSurface = Yes\t2\tw").status, Status::Fails);
        // the excluded row is left out of every count
        let v = verdict("exclude\tNo. = 5.\t-\tw\ncount\tSurface = Yes\t2\tw\ncount\t*\t4\tw");
        assert_eq!(v.status, Status::Holds);
        assert!(
            v.method.contains("rows with No. = 5. left out"),
            "{}",
            v.method
        );
    }

    #[test]
    fn pluralities_and_orders_are_strict() {
        assert_eq!(
            verdict("most\tDegree = 3 ; Degree = 2 ; Degree = 1\t-\tw").status,
            Status::Holds
        );
        assert_eq!(
            verdict("most\tDegree = 2 ; Degree = 3\t-\tw").status,
            Status::Fails
        );
        // 3 rows with two parameters of 5: a majority, then one, then more than two (none)
        let order = "order\tParameters = 2 ; Parameters = 1 ; Parameters > 2\tmajority\tw";
        assert_eq!(verdict(order).status, Status::Holds);
        // a cell that is no number (`-`) is of no numeric class
        assert_eq!(verdict("count\tParameters < 2\t1\tw").status, Status::Holds);
        let tie = "order\tDegree = 2 ; Degree = 1\t-\tw";
        assert_eq!(verdict(tie).status, Status::Fails);
    }

    #[test]
    fn malformed_files_are_not_decided() {
        let v = verdict("count\tColour = red\t1\tw");
        assert_eq!(v.status, Status::NotCheckable);
        assert!(v.evidence[0].text.contains("no column `Colour`"));
        assert!(statements("largest\t*\t1\tw", &["a".into()]).is_err());
        assert!(statements("most\t*\t-\tw", &["a".into()]).is_err());
        assert!(rows("label: T\na\tb\n1\n").is_err());
    }
}
