//! Thesis Chapter 1, Table 1.1 (the literature survey) against the text
//! that counts it (claim T69): the paragraph after the table (1.2) and
//! the summary 2.5.
//!
//! The table is embedded as printed (`thesis_table_1_1.txt`); every count
//! is taken from its rows, and each count the text quotes is judged by
//! [`trig_judge::quoted`].

use rug::Rational;

use crate::claim::Claim;
use trig_judge::quoted::quoted_figure;
use trig_verdict::evidence::{Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T69",
    check: t69,
}];

const DATA: &str = include_str!("thesis_table_1_1.txt");

/// The row of the thesis's own spline, which the text excludes ("Among 29
/// reviewed papers, which excluded the proposed spline").
const PROPOSED: &str = "Proposed cubic trigonometric spline";

/// One reviewed paper: its degree marks (degrees 1–5), its number of shape
/// parameters, and whether it extends to surfaces.
#[derive(Debug, Clone, PartialEq)]
struct Paper {
    degrees: Vec<usize>,
    parameters: u32,
    surface: bool,
}

fn papers(data: &str) -> Result<Vec<Paper>, String> {
    let mut out = Vec::new();
    for (i, raw) in data.lines().enumerate() {
        if raw.trim().is_empty() || raw.starts_with('#') {
            continue;
        }
        let err = |why: &str| format!("thesis_table_1_1.txt line {}: {why}", i + 1);
        let f: Vec<&str> = raw
            .split('\t')
            .map(str::trim)
            .filter(|x| !x.is_empty())
            .collect();
        if f.len() < 2 + 11 + 2 {
            return Err(err(
                "a row has the number, the author, 11 marks and 2 fields",
            ));
        }
        if f[1] == PROPOSED {
            continue;
        }
        let degrees = (1..=5).filter(|d| f[1 + d] == "/").collect();
        let parameters = f[f.len() - 2]
            .parse()
            .map_err(|_| err("the number of shape parameters"))?;
        let surface = match f[f.len() - 1] {
            "Yes" => true,
            "No" => false,
            _ => return Err(err("Surface is Yes or No")),
        };
        out.push(Paper {
            degrees,
            parameters,
            surface,
        });
    }
    Ok(out)
}

/// `count(key)` for each key in `keys`, as text.
fn tally(keys: &[(&str, usize)]) -> String {
    keys.iter()
        .map(|(k, n)| format!("{k}: {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
}

fn t69() -> Verdict {
    survey(DATA)
}

/// T69 on the table `data`.
fn survey(data: &str) -> Verdict {
    let papers = match papers(data) {
        Ok(p) => p,
        Err(e) => return Verdict::not_checkable(e),
    };
    let n = papers.len();
    let surfaces = papers.iter().filter(|p| p.surface).count();
    let mut items = vec![
        quoted_figure(
            "\"29 reviewed papers\"",
            "29",
            Rational::from(n),
            "rows of Table 1.1 other than the proposed spline",
        ),
        quoted_figure(
            "\"15 papers out of 29 papers extend their work to surface construction\"",
            "15",
            Rational::from(surfaces),
            "rows with Surface = Yes",
        ),
    ];
    let by_degree: Vec<(String, usize)> = (1..=5)
        .map(|d| {
            (
                format!("degree {d}"),
                papers.iter().filter(|p| p.degrees.contains(&d)).count(),
            )
        })
        .collect();
    let cubic = by_degree[2].1;
    let plurality = by_degree
        .iter()
        .enumerate()
        .all(|(i, (_, k))| i == 2 || *k < cubic);
    let unmarked = papers.iter().filter(|p| p.degrees.is_empty()).count();
    let shown: Vec<(&str, usize)> = by_degree.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    items.push(
        Evidence::new(
            Kind::Comparison,
            format!(
                "reading: more papers mark degree 3 than any other degree; {} ({unmarked} row(s) mark no degree); degree 3 is {} half of the {n} papers",
                tally(&shown),
                if 2 * cubic > n { "more than" } else { "not more than" }
            ),
        )
        .about("\"most focus on cubic\"", status(plurality)),
    );
    type Class = (&'static str, fn(u32) -> bool);
    let classes: [Class; 4] = [
        ("two", |k| k == 2),
        ("one", |k| k == 1),
        ("three", |k| k == 3),
        ("multiple (more than three)", |k| k > 3),
    ];
    let counts: Vec<(&str, usize)> = classes
        .iter()
        .map(|(name, is)| (*name, papers.iter().filter(|p| is(p.parameters)).count()))
        .collect();
    let decreasing = counts.windows(2).all(|w| w[0].1 > w[1].1);
    let majority = 2 * counts[0].1 > n;
    items.push(
        Evidence::new(
            Kind::Comparison,
            format!(
                "reading: more than half of the {n} papers use two shape parameters, and the counts fall strictly in the printed order; {}",
                tally(&counts)
            ),
        )
        .about(
            "\"the majority … employs two shape parameters, followed by one …, three … and multiple shape parameters\"",
            status(decreasing && majority),
        ),
    );
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Verdict::new(
        st,
        "counts over the rows of Table 1.1 as printed (the proposed spline's row excluded, as the text says); quoted counts compared exactly",
        items,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_reads_29_papers_and_skips_the_proposed_row() {
        let p = papers(DATA).unwrap();
        assert_eq!(p.len(), 29);
        // row 1: cubic, two parameters, no surface (printed with one mark too many)
        assert_eq!(
            p[0],
            Paper {
                degrees: vec![3],
                parameters: 2,
                surface: false
            }
        );
    }

    #[test]
    fn a_changed_row_changes_the_verdict() {
        assert_eq!(survey(DATA).status, Status::Holds);
        // one more surface paper: "15 papers out of 29" no longer holds
        let flipped = DATA.replacen("\t2\tNo", "\t2\tYes", 1);
        assert_eq!(survey(&flipped).status, Status::Fails);
        assert!(papers("1.\tA\t-\t/\n").is_err());
    }
}
