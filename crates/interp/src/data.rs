//! The thesis's data sets, Tables 4.1–4.6 of section 4.3, exactly as printed.
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

/// One printed table.
#[derive(Debug, Clone, Copy)]
pub struct Table {
    /// Name on the command line, `thesis-table-4.1` …
    pub name: &'static str,
    /// The table's caption as printed.
    pub caption: &'static str,
    /// Where it is printed and the source the thesis cites for it.
    pub citation: &'static str,
    /// The scheme of the section the table illustrates.
    pub scheme: Scheme,
    /// Column headers after `i, x_i, f_i` (e.g. `["m", "n"]`).
    pub columns: &'static [&'static str],
    /// Rows as printed: `x_i, f_i`, then one entry per column (`-` on the last row).
    pub rows: &'static [&'static [&'static str]],
}

const DUBE_SINGH: &str =
    "real positive data from Dube & Singh (2014), as cited by the thesis (4.3.1)";

/// Tables 4.1–4.6 in order.
pub const TABLES: [Table; 6] = [
    Table {
        name: "thesis-table-4.1",
        caption: "Table 4.1 Positive Data Set (I)",
        citation: DUBE_SINGH,
        scheme: Scheme::C1,
        columns: &["m"],
        rows: &[
            &["1", "3", "0.5"],
            &["2", "6", "1"],
            &["3", "5", "-0.5"],
            &["4", "8", "-1"],
            &["5", "1", "-"],
        ],
    },
    Table {
        name: "thesis-table-4.2",
        caption: "Table 4.2 Positive Data Set (II)",
        citation: DUBE_SINGH,
        scheme: Scheme::C2,
        columns: &["m"],
        rows: &[
            &["1", "3", "0.5"],
            &["2", "6", "-1"],
            &["3", "5", "0.1"],
            &["4", "8", "-0.5"],
            &["5", "1", "-"],
        ],
    },
    Table {
        name: "thesis-table-4.3",
        caption: "Table 4.3 Positive Data Set (III)",
        citation: DUBE_SINGH,
        scheme: Scheme::G1,
        columns: &["m", "n"],
        rows: &[
            &["1", "3", "1", "0.1"],
            &["2", "6", "0.6", "2"],
            &["3", "5", "0.5", "3"],
            &["4", "8", "-1", "1.5"],
            &["5", "1", "-", "-"],
        ],
    },
    Table {
        name: "thesis-table-4.4",
        caption: "Table 4.4 Positive Data Set (IV)",
        citation: DUBE_SINGH,
        scheme: Scheme::G2,
        columns: &["m", "alpha", "beta"],
        rows: &[
            &["1", "3", "0.5", "0.5", "4"],
            &["2", "6", "-1", "1", "5"],
            &["3", "5", "-1", "2", "0.15"],
            &["4", "8", "0.2", "2", "3"],
            &["5", "1", "-", "-", "-"],
        ],
    },
    Table {
        name: "thesis-table-4.5",
        caption: "Table 4.5 Positive Data Set (V)",
        citation: "thesis 4.3.5 (G² scheme, Figure 4.14); the thesis cites no source for this near-zero data set",
        scheme: Scheme::G2,
        columns: &["m", "alpha", "beta"],
        rows: &[
            &["0", "12", "0.8", "0.5", "5"],
            &["1", "0.1", "-1", "0.04", "0.5"],
            &["2", "1", "0.5", "2", "0.15"],
            &["3", "13", "-", "-", "-"],
        ],
    },
    Table {
        name: "thesis-table-4.6",
        caption: "Table 4.6 Positive Data Set (V1) [sic, VI]",
        citation: "thesis 4.3.5 (G¹ scheme, Figure 4.15); the thesis cites no source for this near-zero data set",
        scheme: Scheme::G1,
        columns: &["m", "n"],
        rows: &[
            &["0", "12", "1", "0.1"],
            &["1", "0.1", "0.9", "0.001"],
            &["2", "1", "1", "1.5"],
            &["3", "13", "-", "-"],
        ],
    },
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
    pub params: Vec<(&'static str, Vec<Rational>)>,
}

impl PartialEq for Table {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

impl DataSet {
    /// The data set named `name` (`thesis-table-4.1` …).
    pub fn named(name: &str) -> Result<DataSet, InterpError> {
        let table = TABLES
            .iter()
            .find(|t| t.name == name)
            .ok_or_else(|| InterpError::UnknownData(name.to_string()))?;
        DataSet::read(table)
    }

    /// Reads a table exactly.
    pub fn read(table: &Table) -> Result<DataSet, InterpError> {
        let num = |s: &str| {
            parse_exact(s).map_err(|e| InterpError::Malformed(format!("{}: {e}", table.name)))
        };
        let x = table
            .rows
            .iter()
            .map(|r| num(r[0]))
            .collect::<Result<Vec<_>, _>>()?;
        let f = table
            .rows
            .iter()
            .map(|r| num(r[1]))
            .collect::<Result<Vec<_>, _>>()?;
        if x.windows(2).any(|w| w[0] >= w[1]) {
            return Err(InterpError::Malformed(format!(
                "{}: the abscissae are not increasing",
                table.name
            )));
        }
        let intervals = table.rows.len() - 1;
        let params = table
            .columns
            .iter()
            .enumerate()
            .map(|(k, name)| {
                let column = table.rows[..intervals]
                    .iter()
                    .map(|r| num(r[2 + k]))
                    .collect::<Result<Vec<_>, _>>()?;
                Ok((*name, column))
            })
            .collect::<Result<Vec<_>, InterpError>>()?;
        Ok(DataSet {
            table: *table,
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
        for t in &TABLES {
            let d = DataSet::read(t).unwrap();
            assert_eq!(d.column("m", t.scheme).unwrap().len(), d.intervals());
            assert!(d.f.iter().all(|f| *f > 0), "{}: data are positive", t.name);
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
}
