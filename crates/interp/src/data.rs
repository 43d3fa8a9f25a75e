//! Printed data tables for interpolation, read exactly from table files:
//! the thesis's Tables 4.1–4.6 of section 4.3 are `documents/thesis/table-4.*.tsv`
//! (built in, by name, for the commands); a claim names any such file.
//!
//! Each table lists `i, x_i, f_i` and, per interval `[x_i, x_{i+1}]`, the
//! shape parameter `m_i` and the scheme's factors (`n_i` for G¹, `α_i`, `β_i`
//! for G²); the last row prints `-` for them. Decimals are read exactly
//! (`0.15` is `3/20`). The thesis chooses the parameters "through empirical
//! adjustment" (4.3.3): the printed rule for the shape parameters *is* the
//! table, so the tables are the parameters the schemes use.

use rug::Rational;
use trig_core::parse_exact;

use crate::InterpError;
use crate::kind::Scheme;

/// What a table file says of its table besides the rows.
#[derive(Debug, Clone)]
pub struct Table {
    /// Name on the command line, `thesis-table-4.1` …
    pub name: String,
    /// The table's caption as printed.
    pub caption: String,
    /// Where it is printed and the source the document cites for it.
    pub citation: String,
    /// The scheme of the section the table illustrates.
    pub scheme: Scheme,
}

/// The table files of the thesis's Tables 4.1–4.6 (`documents/thesis/`),
/// the data sets the commands know by name.
pub const BUILT_IN: [&str; 6] = [
    include_str!("../../../documents/thesis/table-4.1.tsv"),
    include_str!("../../../documents/thesis/table-4.2.tsv"),
    include_str!("../../../documents/thesis/table-4.3.tsv"),
    include_str!("../../../documents/thesis/table-4.4.tsv"),
    include_str!("../../../documents/thesis/table-4.5.tsv"),
    include_str!("../../../documents/thesis/table-4.6.tsv"),
];

/// A table read exactly: knots, values and per-interval parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct DataSet {
    pub table: Table,
    /// `x_0 < x_1 < … < x_n`.
    pub x: Vec<Rational>,
    /// `f_0 … f_n`.
    pub f: Vec<Rational>,
    /// Per-interval columns by header (`m`, `n`, `alpha`, `beta`), `n` entries each.
    pub params: Vec<(String, Vec<Rational>)>,
}

impl PartialEq for Table {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

/// The header fields a table file gives before its columns.
const FIELDS: [&str; 4] = ["name", "caption", "citation", "scheme"];

impl DataSet {
    /// The built-in data set named `name` (`thesis-table-4.1` …).
    pub fn named(name: &str) -> Result<DataSet, InterpError> {
        for text in BUILT_IN {
            let data = DataSet::parse(text)?;
            if data.table.name == name {
                return Ok(data);
            }
        }
        Err(InterpError::UnknownData(name.to_string()))
    }

    /// Reads a table file exactly. The layout: `#` comment lines (where the
    /// table is printed), the fields `name: …`, `caption: …`, `citation: …`,
    /// `scheme: c1` (the scheme the table illustrates), then tab-separated
    /// rows under a header `i  x  f  <parameters…>`: `i` the printed row
    /// number (1, 2, …), `x_i`, `f_i`, and one column per parameter of the
    /// interval `[x_i, x_{i+1}]`, printed `-` on the last row.
    pub fn parse(text: &str) -> Result<DataSet, InterpError> {
        let mut fields: Vec<(&str, &str)> = Vec::new();
        let mut header: Option<Vec<&str>> = None;
        let mut rows: Vec<(usize, Vec<&str>)> = Vec::new();
        for (k, line) in text.lines().enumerate() {
            let line_no = k + 1;
            let bad = |why: String| InterpError::Malformed(format!("line {line_no}: {why}"));
            let line = line.trim_end();
            if line.trim().is_empty() || line.starts_with('#') {
                continue;
            }
            if header.is_none() && !line.contains('\t') {
                let (key, value) = line.split_once(':').ok_or_else(|| {
                    bad(format!(
                        "`{line}`: expected `FIELD: value` or the tab-separated header"
                    ))
                })?;
                let key = key.trim();
                if !FIELDS.contains(&key) || fields.iter().any(|(k, _)| *k == key) {
                    return Err(bad(format!(
                        "`{key}`: expected each of {} once",
                        FIELDS.join(", ")
                    )));
                }
                fields.push((key, value.trim()));
                continue;
            }
            let cells: Vec<&str> = line.split('\t').map(str::trim).collect();
            match &header {
                None => {
                    if cells.len() < 3 || cells[..3] != ["i", "x", "f"] {
                        return Err(bad("the header starts with the columns i, x, f".into()));
                    }
                    header = Some(cells);
                }
                Some(h) if cells.len() != h.len() => {
                    return Err(bad(format!(
                        "{} cells under {} columns",
                        cells.len(),
                        h.len()
                    )));
                }
                Some(_) => rows.push((line_no, cells)),
            }
        }
        let field = |key: &str| {
            fields
                .iter()
                .find(|(k, _)| *k == key)
                .map(|(_, v)| v.to_string())
                .ok_or_else(|| InterpError::Malformed(format!("no `{key}:` line")))
        };
        let table = Table {
            name: field("name")?,
            caption: field("caption")?,
            citation: field("citation")?,
            scheme: field("scheme")?.parse()?,
        };
        let header = header.ok_or_else(|| InterpError::Malformed("no header row".into()))?;
        if rows.len() < 2 {
            return Err(InterpError::Malformed(format!(
                "{}: a table needs at least two rows",
                table.name
            )));
        }
        let num = |line: usize, s: &str| {
            parse_exact(s)
                .map_err(|e| InterpError::Malformed(format!("{}, line {line}: {e}", table.name)))
        };
        for (k, (line, cells)) in rows.iter().enumerate() {
            if cells[0] != (k + 1).to_string() {
                return Err(InterpError::Malformed(format!(
                    "{}, line {line}: row number {} where {} is next",
                    table.name,
                    cells[0],
                    k + 1
                )));
            }
        }
        let column = |c: usize, take: usize| {
            rows[..take]
                .iter()
                .map(|(line, cells)| num(*line, cells[c]))
                .collect::<Result<Vec<_>, _>>()
        };
        let x = column(1, rows.len())?;
        let f = column(2, rows.len())?;
        if x.windows(2).any(|w| w[0] >= w[1]) {
            return Err(InterpError::Malformed(format!(
                "{}: the abscissae are not increasing",
                table.name
            )));
        }
        let intervals = rows.len() - 1;
        let params = header[3..]
            .iter()
            .enumerate()
            .map(|(k, name)| Ok((name.to_string(), column(3 + k, intervals)?)))
            .collect::<Result<Vec<_>, InterpError>>()?;
        Ok(DataSet {
            table,
            x,
            f,
            params,
        })
    }

    /// Number of intervals `n`.
    pub fn intervals(&self) -> usize {
        self.x.len() - 1
    }

    /// `h_i = x_{i+1} − x_i`.
    pub fn h(&self, i: usize) -> Rational {
        self.x[i + 1].clone() - &self.x[i]
    }

    /// The per-interval column `name`, or an error naming the scheme that needs it.
    pub fn column(&self, name: &str, scheme: Scheme) -> Result<&[Rational], InterpError> {
        self.params
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.as_slice())
            .ok_or_else(|| InterpError::MissingColumn {
                data: self.table.name.to_string(),
                column: name.to_string(),
                scheme,
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_read_exactly() {
        let t5 = DataSet::named("thesis-table-4.5").unwrap();
        assert_eq!(t5.f[1], Rational::from((1, 10)));
        assert_eq!(
            t5.column("beta", Scheme::G2).unwrap()[2],
            Rational::from((3, 20))
        );
        let t6 = DataSet::named("thesis-table-4.6").unwrap();
        assert_eq!(
            t6.column("n", Scheme::G1).unwrap()[1],
            Rational::from((1, 1000))
        );
        for text in BUILT_IN {
            let d = DataSet::parse(text).unwrap();
            assert_eq!(d.column("m", d.table.scheme).unwrap().len(), d.intervals());
            assert!(
                d.f.iter().all(|f| *f > 0),
                "{}: data are positive",
                d.table.name
            );
        }
        assert!(matches!(
            DataSet::named("thesis-table-9"),
            Err(InterpError::UnknownData(_))
        ));
        let t1 = DataSet::named("thesis-table-4.1").unwrap();
        assert!(matches!(
            t1.column("n", Scheme::G1),
            Err(InterpError::MissingColumn { .. })
        ));
    }

    #[test]
    fn malformed_table_files_are_refused_with_the_line() {
        let head = "name: t\ncaption: c\ncitation: s\nscheme: c1\n";
        let ok = format!("{head}i\tx\tf\tm\n1\t0\t1\t1/2\n2\t1\t2\t-\n");
        let d = DataSet::parse(&ok).unwrap();
        assert_eq!(
            d.params,
            vec![("m".to_string(), vec![Rational::from((1, 2))])]
        );
        let e = |text: &str| DataSet::parse(text).unwrap_err().to_string();
        assert!(e(&ok.replace("2\t1\t2", "2\t0\t2")).contains("not increasing"));
        assert!(e(&ok.replace("2\t1\t2\t-", "3\t1\t2\t-")).contains("line 7: row number 3"));
        assert!(e(&ok.replace("1\t0\t1\t1/2", "1\t0\t1")).contains("line 6: 3 cells under 4"));
        assert!(e(&ok.replace("scheme: c1\n", "")).contains("no `scheme:` line"));
        assert!(e(&ok.replace("1/2", "x")).contains("line 6"));
        assert!(e(&format!("nam: t\n{ok}")).contains("line 1: `nam`"));
    }
}
