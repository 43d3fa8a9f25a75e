//! Outline data: closed contours of points read from a `contour,x,y` file.
//!
//! Format (as written by `examples/extract_glyphs.rs`): lines starting with
//! `#` are provenance comments, one header line `contour,x,y`, then one point
//! per line; contours are numbered from 0 and listed in order, each closed
//! (its last point joins its first). Points are numbered globally in file
//! order; that global index is what explicit corners refer to.

use std::path::Path;

use nalgebra::Point2;
use trig_core::echo;
use trig_core::input::{MAX_TEXT_BYTES, Source, read_text};

use crate::error::{FitError, Result};

/// A point of the plane.
pub type P2 = Point2<f64>;

/// Largest coordinate magnitude accepted: squared distances of up to a
/// million points stay far inside the range of f64.
pub const MAX_COORDINATE: f64 = 1e100;

/// A glyph outline: closed contours with their provenance comments.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// File stem (`epsilon`), or the name given to [`Outline::parse`].
    pub name: String,
    /// The `#` comment lines, without the `#`.
    pub provenance: Vec<String>,
    /// Closed contours, in file order.
    pub contours: Vec<Vec<P2>>,
}

impl Outline {
    /// Reads a data file.
    pub fn read(path: &Path) -> Result<Outline> {
        // bounded, a byte-order mark dropped: the same reader as every input
        let text = read_text(&Source::File(path.to_path_buf()), MAX_TEXT_BYTES).map_err(|e| {
            FitError::Read {
                what: "outline data",
                path: path.display().to_string(),
                reason: e.reason(),
            }
        })?;
        let name = path.file_stem().map_or_else(
            || "outline".to_string(),
            |s| s.to_string_lossy().into_owned(),
        );
        Outline::parse(&text, &name, &path.display().to_string())
    }

    /// Parses the text of a data file; `origin` names it in errors.
    pub fn parse(text: &str, name: &str, origin: &str) -> Result<Outline> {
        let text = text.strip_prefix(trig_core::input::BOM).unwrap_or(text);
        let bad = |line: usize, reason: String| FitError::Malformed {
            origin: origin.to_string(),
            line,
            reason,
        };
        let mut provenance = Vec::new();
        let mut contours: Vec<Vec<P2>> = Vec::new();
        let mut header = false;
        for (i, raw) in text.lines().enumerate() {
            let line = raw.trim();
            let number = i + 1;
            if let Some(comment) = line.strip_prefix('#') {
                provenance.push(comment.trim().to_string());
                continue;
            }
            if line.is_empty() {
                continue;
            }
            if !header {
                if line.replace(' ', "") != "contour,x,y" {
                    return Err(bad(
                        number,
                        format!("expected the header `contour,x,y`, found `{}`", echo(line)),
                    ));
                }
                header = true;
                continue;
            }
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            let [c, x, y] = fields[..] else {
                return Err(bad(
                    number,
                    format!("expected `contour,x,y`, found `{}`", echo(line)),
                ));
            };
            let c: usize = c.parse().map_err(|_| {
                bad(
                    number,
                    format!("contour `{}` is not a nonnegative integer", echo(c)),
                )
            })?;
            let coord = |s: &str| -> Result<f64> {
                let v = s
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| bad(number, format!("`{}` is not a finite number", echo(s))))?;
                if v.abs() > MAX_COORDINATE {
                    return Err(bad(
                        number,
                        format!(
                            "coordinate `{}` is larger than {MAX_COORDINATE:e} in magnitude (squared errors and chord lengths must stay finite)",
                            echo(s)
                        ),
                    ));
                }
                Ok(v)
            };
            let p = P2::new(coord(x)?, coord(y)?);
            match c.cmp(&contours.len()) {
                std::cmp::Ordering::Less if c + 1 == contours.len() => contours[c].push(p),
                std::cmp::Ordering::Equal => contours.push(vec![p]),
                _ => {
                    return Err(bad(
                        number,
                        format!(
                            "contour {c} out of order (contours are listed 0, 1, 2, … in turn)"
                        ),
                    ));
                }
            }
        }
        if contours.is_empty() {
            return Err(bad(text.lines().count(), "no data points".into()));
        }
        Ok(Outline {
            name: name.to_string(),
            provenance,
            contours,
        })
    }

    /// Number of points over all contours.
    pub fn point_count(&self) -> usize {
        self.contours.iter().map(Vec::len).sum()
    }

    /// Global index of the first point of each contour.
    pub fn contour_offsets(&self) -> Vec<usize> {
        self.contours
            .iter()
            .scan(0, |acc, c| {
                let at = *acc;
                *acc += c.len();
                Some(at)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_contours_and_provenance() {
        let o = Outline::parse("# font: x\ncontour,x,y\n0,1,2\n0,3,4\n1,5,6\n", "g", "t").unwrap();
        assert_eq!(o.provenance, vec!["font: x"]);
        assert_eq!(o.contours.len(), 2);
        assert_eq!(o.contours[1][0], P2::new(5.0, 6.0));
        assert_eq!(o.point_count(), 3);
        assert_eq!(o.contour_offsets(), vec![0, 2]);
    }

    #[test]
    fn rejects_malformed_lines() {
        for (text, line) in [
            ("x,y\n0,1,2\n", 1),
            ("contour,x,y\n0,1\n", 2),
            ("contour,x,y\n0,1,nan\n", 2),
            ("contour,x,y\n0,1,2\n2,1,2\n", 3),
            ("contour,x,y\n", 1),
            ("contour,x,y\n0,1e308,2\n", 2),
        ] {
            match Outline::parse(text, "g", "t") {
                Err(FitError::Malformed { line: l, .. }) => assert_eq!(l, line, "{text}"),
                other => panic!("{text}: {other:?}"),
            }
        }
    }

    #[test]
    fn missing_file_is_a_read_error() {
        let e = Outline::read(Path::new("/nonexistent/outline.csv")).unwrap_err();
        assert!(matches!(e, FitError::Read { .. }), "{e}");
    }
}
