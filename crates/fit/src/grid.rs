//! Gridded height data `z(x, y)` read from a CSV file: the Maungawhau grid
//! of `data/volcano/` (R's `datasets::volcano`, written as R writes a
//! matrix: a header row `"",V1,…,Vn`, then rows `"i",z₁,…,zₙ`), or plain
//! rows of numbers. Lines starting with `#` are comments; every row must
//! have as many heights as the first, each a finite number.

use std::path::Path;

use trig_core::echo;
use trig_core::input::{MAX_TEXT_BYTES, Source, read_text};

use crate::data::MAX_COORDINATE;
use crate::error::{FitError, Result};

/// Heights on a rectangular grid, row-major: `z[i·cols + j]` is row `i`,
/// column `j`.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// File stem (`volcano`), or the name given to [`Grid::parse`].
    pub name: String,
    pub rows: usize,
    pub cols: usize,
    pub z: Vec<f64>,
}

impl Grid {
    /// Reads a grid file.
    pub fn read(path: &Path) -> Result<Grid> {
        let text = read_text(&Source::File(path.to_path_buf()), MAX_TEXT_BYTES).map_err(|e| {
            FitError::Read {
                what: "grid",
                path: path.display().to_string(),
                reason: e.reason(),
            }
        })?;
        let name = path
            .file_stem()
            .map_or_else(|| "grid".to_string(), |s| s.to_string_lossy().into_owned());
        Grid::parse(&text, &name, &path.display().to_string())
    }

    /// Parses the text of a grid file; `origin` names it in errors.
    pub fn parse(text: &str, name: &str, origin: &str) -> Result<Grid> {
        let text = text.strip_prefix(trig_core::input::BOM).unwrap_or(text);
        let bad = |line: usize, reason: String| FitError::Malformed {
            origin: origin.to_string(),
            line,
            reason,
        };
        let mut z = Vec::new();
        let mut cols = None;
        let mut rows = 0;
        for (i, raw) in text.lines().enumerate() {
            let line = raw.trim();
            let number = i + 1;
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let mut fields: Vec<&str> = line.split(',').map(str::trim).collect();
            // R's header row, and R's quoted row names
            if fields[0] == "\"\"" {
                continue;
            }
            if fields[0].starts_with('"') {
                fields.remove(0);
            }
            let mut row = Vec::with_capacity(fields.len());
            for (k, f) in fields.iter().enumerate() {
                let v: f64 = f.parse().map_err(|_| {
                    bad(
                        number,
                        format!("height {} `{}` is not a number", k + 1, echo(f)),
                    )
                })?;
                if !v.is_finite() {
                    return Err(FitError::NonFinite {
                        origin: origin.to_string(),
                        line: number,
                        column: k + 1,
                    });
                }
                if v.abs() > MAX_COORDINATE {
                    return Err(bad(
                        number,
                        format!(
                            "height {} is {v:e}, beyond ±{MAX_COORDINATE:e}: its squared errors would overflow",
                            k + 1
                        ),
                    ));
                }
                row.push(v);
            }
            let expected = *cols.get_or_insert(row.len());
            if row.len() != expected {
                return Err(FitError::GridShape {
                    origin: origin.to_string(),
                    line: number,
                    expected,
                    got: row.len(),
                });
            }
            z.extend(row);
            rows += 1;
        }
        let cols = cols.unwrap_or(0);
        if rows < 2 || cols < 2 {
            return Err(bad(
                text.lines().count().max(1),
                format!(
                    "a grid needs at least 2 rows and 2 columns of heights, found {rows} × {cols}"
                ),
            ));
        }
        Ok(Grid {
            name: name.to_string(),
            rows,
            cols,
            z,
        })
    }

    /// The height at row `i`, column `j`.
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.z[i * self.cols + j]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_r_matrix_and_plain_rows() {
        let r = "\"\",\"V1\",\"V2\"\n\"1\",100,101\n\"2\",102,103.5\n";
        let g = Grid::parse(r, "r", "r.csv").unwrap();
        assert_eq!((g.rows, g.cols, g.at(1, 1)), (2, 2, 103.5));
        let plain = "# comment\n1,2,3\n4,5,6\n";
        let g = Grid::parse(plain, "p", "p.csv").unwrap();
        assert_eq!((g.rows, g.cols, g.at(1, 0)), (2, 3, 4.0));
    }

    #[test]
    fn bad_grids_get_typed_errors_with_their_line() {
        assert_eq!(
            Grid::parse("1,2,3\n4,5\n", "g", "g.csv"),
            Err(FitError::GridShape {
                origin: "g.csv".into(),
                line: 2,
                expected: 3,
                got: 2
            })
        );
        assert_eq!(
            Grid::parse("1,2\n# c\n4,NaN\n", "g", "g.csv"),
            Err(FitError::NonFinite {
                origin: "g.csv".into(),
                line: 3,
                column: 2
            })
        );
        assert!(matches!(
            Grid::parse("1,2\n4,x\n", "g", "g.csv"),
            Err(FitError::Malformed { line: 2, .. })
        ));
        assert!(matches!(
            Grid::parse("1,2\n4,-1e200\n", "g", "g.csv"),
            Err(FitError::Malformed { line: 2, .. })
        ));
        assert!(matches!(
            Grid::parse("1,2\n", "g", "g.csv"),
            Err(FitError::Malformed { .. })
        ));
    }

    #[test]
    fn the_volcano_is_87_by_61_metres_94_to_195() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/volcano/volcano.csv");
        let g = Grid::read(&path).unwrap();
        assert_eq!((g.rows, g.cols), (87, 61));
        let lo = g.z.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = g.z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!((lo, hi), (94.0, 195.0));
    }
}
