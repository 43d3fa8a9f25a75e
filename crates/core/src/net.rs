//! Control nets of tensor-product surfaces, read exactly from a plain file.
//!
//! The layout: one control point per line, `x y z` or `x y z w` (a
//! rational surface's weight), the numbers separated by spaces, tabs or
//! commas and read exactly (`0.6` is `3/5`); the points of one net row
//! `P_{i,0} … P_{i,n_v−1}` on consecutive lines, net rows separated by one
//! or more blank lines. Lines starting with `#` are comments (they neither
//! hold a point nor separate rows). Every row has the same number of
//! points, and either every point has a weight or none has.

use rug::Rational;

use crate::error::CoreError;
use crate::input::{InputError, MAX_TEXT_BYTES, Source, read_text};
use crate::knots::{check_increasing, locate_exact};
use crate::number::parse_exact;

/// Why a control net cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NetError {
    #[error(transparent)]
    Input(#[from] InputError),
    #[error(
        "{input} line {line}: `{text}` is not a control point ({reason}); expected `x y z` or `x y z w`, separated by spaces or commas"
    )]
    Malformed {
        input: String,
        line: usize,
        text: String,
        reason: String,
    },
    #[error("{input} line {line}: `{text}` is not a finite number")]
    NotFinite {
        input: String,
        line: usize,
        text: String,
    },
    #[error(
        "{input}: net row {row} (from line {line}) has {got} points, expected {expected} like row 0 (net rows are separated by blank lines)"
    )]
    Ragged {
        input: String,
        row: usize,
        line: usize,
        expected: usize,
        got: usize,
    },
    #[error(
        "{input} line {line}: {got} numbers where line {first} has {expected}: either every point has a weight or none has"
    )]
    MixedWeights {
        input: String,
        line: usize,
        first: usize,
        expected: usize,
        got: usize,
    },
    #[error("{input} line {line}: weight {value} is not positive")]
    NonPositiveWeight {
        input: String,
        line: usize,
        value: String,
    },
    #[error("{input}: {what}")]
    Computed { input: String, what: String },
    #[error("{input} holds no control point")]
    Empty { input: String },
}

/// A rectangular net of exact control points `P_{i,j}` (row `i`, column
/// `j`), optionally with positive weights `w_{i,j}`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ControlNet {
    points: Vec<Vec<[Rational; 3]>>,
    weights: Option<Vec<Vec<Rational>>>,
}

impl ControlNet {
    /// A polynomial net from its rows (rectangular, nonempty; checked).
    pub fn new(points: Vec<Vec<[Rational; 3]>>) -> Result<Self, NetError> {
        let rows = points
            .into_iter()
            .map(|r| r.into_iter().map(|p| (p, None)).collect())
            .collect();
        Self::from_rows("the control net", rows, &[])
    }

    /// A net from its rows with a weight per point when `weights` is
    /// `Some` (rectangular and nonempty, checked; each weight positive, a
    /// weight ≤ 0 is refused naming `input`).
    pub fn with_weights(
        points: Vec<Vec<[Rational; 3]>>,
        weights: Option<Vec<Vec<Rational>>>,
        input: &str,
    ) -> Result<Self, NetError> {
        let Some(weights) = weights else {
            return Self::new(points);
        };
        if let Some(w) = weights.iter().flatten().find(|w| **w <= 0) {
            return Err(NetError::Computed {
                input: input.into(),
                what: format!("weight {w} is not positive"),
            });
        }
        let rows = points
            .into_iter()
            .zip(weights)
            .map(|(r, w)| r.into_iter().zip(w).map(|(p, w)| (p, Some(w))).collect())
            .collect();
        Self::from_rows(input, rows, &[])
    }

    /// The net in `source` (see the module's layout).
    pub fn read(source: &Source) -> Result<Self, NetError> {
        Self::parse(&read_text(source, MAX_TEXT_BYTES)?, &source.name())
    }

    /// The net in `text`; `input` names it in errors.
    pub fn parse(text: &str, input: &str) -> Result<Self, NetError> {
        let mut rows: Vec<Vec<([Rational; 3], Option<Rational>)>> = vec![Vec::new()];
        let mut starts = vec![0];
        let mut arity: Option<(usize, usize)> = None;
        for (index, raw) in text.lines().enumerate() {
            let line = index + 1;
            let trimmed = raw.trim();
            if trimmed.starts_with('#') {
                continue;
            }
            if trimmed.is_empty() {
                if rows.last().is_some_and(|r| !r.is_empty()) {
                    rows.push(Vec::new());
                    starts.push(0);
                }
                continue;
            }
            let numbers = numbers(trimmed, input, line)?;
            let &mut (first, expected) = arity.get_or_insert((line, numbers.len()));
            if numbers.len() != expected {
                return Err(NetError::MixedWeights {
                    input: input.into(),
                    line,
                    first,
                    expected,
                    got: numbers.len(),
                });
            }
            let mut numbers = numbers.into_iter();
            let mut next = || numbers.next().expect("three or four numbers");
            let point = [next(), next(), next()];
            let weight = (expected == 4).then(next);
            if let Some(w) = &weight
                && *w <= 0
            {
                return Err(NetError::NonPositiveWeight {
                    input: input.into(),
                    line,
                    value: w.to_string(),
                });
            }
            let row = rows.last_mut().expect("a row");
            if row.is_empty() {
                *starts.last_mut().expect("a start") = line;
            }
            row.push((point, weight));
        }
        if rows.last().is_some_and(Vec::is_empty) {
            rows.pop();
            starts.pop();
        }
        Self::from_rows(input, rows, &starts)
    }

    fn from_rows(
        input: &str,
        rows: Vec<Vec<([Rational; 3], Option<Rational>)>>,
        starts: &[usize],
    ) -> Result<Self, NetError> {
        let expected = rows.first().map_or(0, Vec::len);
        if expected == 0 {
            return Err(NetError::Empty {
                input: input.into(),
            });
        }
        if let Some((row, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != expected) {
            return Err(NetError::Ragged {
                input: input.into(),
                row,
                line: starts.get(row).copied().unwrap_or(0),
                expected,
                got: r.len(),
            });
        }
        let rational = rows[0][0].1.is_some();
        let weights = rational.then(|| {
            rows.iter()
                .map(|r| {
                    r.iter()
                        .map(|(_, w)| w.clone().unwrap_or_default())
                        .collect()
                })
                .collect()
        });
        let points = rows
            .into_iter()
            .map(|r| r.into_iter().map(|(p, _)| p).collect())
            .collect();
        Ok(ControlNet { points, weights })
    }

    /// The `rows × columns` window of the net starting at row `row`, column
    /// `column` (the points one span of a uniform B-spline surface uses);
    /// `None` when it does not fit.
    pub fn window(&self, row: usize, column: usize, rows: usize, columns: usize) -> Option<Self> {
        if rows == 0
            || columns == 0
            || row + rows > self.rows()
            || column + columns > self.columns()
        {
            return None;
        }
        Some(ControlNet {
            points: window_of(&self.points, (row, rows), (column, columns)),
            weights: self
                .weights
                .as_deref()
                .map(|w| window_of(w, (row, rows), (column, columns))),
        })
    }

    /// The span of a tensor-product spline over knot vectors that holds the
    /// point `(u, v)`: its window of the net and the local coordinates
    /// there — seed 004's EH B-spline surface (5),
    /// `R(u, v) = R_{i,j}((u − u_i)/Δu_i, (v − v_j)/Δv_j)` on
    /// `[u_i, u_{i+1}] × [v_j, v_{j+1}]`, the piece over the window of rows
    /// `i − k + 1 … i` and columns `j − l + 1 … j` (`k`, `l` the numbers of
    /// functions of each direction, `sizes`). A net of `r` rows takes a knot
    /// vector of `r + k − 1` knots `u_0 … u_{r+k−2}` (seed 004: `n + 4` for
    /// `n + 1` points and `k = 4`) whose spans `[u_{k−1}, u_r]` are used and
    /// must be strictly increasing; `at` is the point as printed, for errors.
    pub fn span_at(
        &self,
        knots: [&[Rational]; 2],
        sizes: (usize, usize),
        point: [&Rational; 2],
        at: [&str; 2],
    ) -> crate::error::Result<(ControlNet, Rational, Rational)> {
        let locate = |d: usize,
                      count: usize,
                      k: usize|
         -> crate::error::Result<(usize, Rational)> {
            let name = ["u", "v"][d];
            let expected = count + k - 1;
            if count < k || knots[d].len() != expected {
                return Err(CoreError::Knots(format!(
                    "the {name} knot vector: a net of {count} points along {name} and {k} functions take {expected} knots ({name}_0 … {name}_{}), got {}",
                    expected - 1,
                    knots[d].len()
                )));
            }
            let used = &knots[d][k - 1..=count];
            check_increasing(used, 2, |i| {
                format!("{} (knot {name}_{})", used[i], i + k - 1)
            })?;
            locate_exact(used, point[d], at[d])
        };
        let (row, u) = locate(0, self.rows(), sizes.0)?;
        let (column, v) = locate(1, self.columns(), sizes.1)?;
        let window = self
            .window(row, column, sizes.0, sizes.1)
            .ok_or_else(|| CoreError::Knots("the span's window lies outside the net".into()))?;
        Ok((window, u, v))
    }

    /// The net checked against the numbers of functions of the `u` basis
    /// (rows) and the `v` basis (columns), each named by its id.
    pub fn check_size(&self, u: (&str, usize), v: (&str, usize)) -> crate::error::Result<()> {
        for ((id, expected), what, got) in
            [(u, "rows", self.rows()), (v, "columns", self.columns())]
        {
            if expected != got {
                return Err(crate::error::CoreError::Count {
                    what: format!(
                        "control-net {what} for `{id}` (the net is {} × {})",
                        self.rows(),
                        self.columns()
                    ),
                    expected,
                    got,
                });
            }
        }
        Ok(())
    }

    /// The number of net rows (`n_u`).
    pub fn rows(&self) -> usize {
        self.points.len()
    }

    /// The number of points in a row (`n_v`).
    pub fn columns(&self) -> usize {
        self.points[0].len()
    }

    /// The points, `[i][j] = P_{i,j}`.
    pub fn points(&self) -> &[Vec<[Rational; 3]>] {
        &self.points
    }

    /// The weight `w_{i,j}` of a rational net.
    pub fn weight(&self, i: usize, j: usize) -> Option<&Rational> {
        self.weights.as_ref().map(|w| &w[i][j])
    }

    /// True when the net has weights.
    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    /// The exact numbers with their names (`P_{i,j}` coordinates, weights).
    pub fn inputs(&self) -> Vec<(String, &Rational)> {
        let mut out = Vec::new();
        for (i, row) in self.points.iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                for (axis, q) in ["x", "y", "z"].iter().zip(p) {
                    out.push((format!("P{i}{j}.{axis}"), q));
                }
                if let Some(w) = self.weight(i, j) {
                    out.push((format!("w{i}{j}"), w));
                }
            }
        }
        out
    }
}

/// The rows `row..row + rows` of `grid`, each cut to its columns
/// `column..column + columns`.
fn window_of<T: Clone>(
    grid: &[Vec<T>],
    (row, rows): (usize, usize),
    (column, columns): (usize, usize),
) -> Vec<Vec<T>> {
    grid[row..row + rows]
        .iter()
        .map(|r| r[column..column + columns].to_vec())
        .collect()
}

/// The three or four numbers of a point line.
fn numbers(text: &str, input: &str, line: usize) -> Result<Vec<Rational>, NetError> {
    let tokens: Vec<&str> = text
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    if !(3..=4).contains(&tokens.len()) {
        return Err(NetError::Malformed {
            input: input.into(),
            line,
            text: crate::echo(text),
            reason: format!("{} numbers", tokens.len()),
        });
    }
    tokens
        .iter()
        .map(|t| {
            let lower = t.trim_start_matches(['+', '-']).to_ascii_lowercase();
            if lower.starts_with("nan") || lower.starts_with("inf") {
                return Err(NetError::NotFinite {
                    input: input.into(),
                    line,
                    text: crate::echo(t),
                });
            }
            parse_exact(t).map_err(|e| NetError::Malformed {
                input: input.into(),
                line,
                text: crate::echo(text),
                reason: e.to_string(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn the_span_over_knot_vectors_is_a_window_with_local_coordinates() {
        // 5 × 4 points, cubic both ways: u knots u_0 … u_7 with the spans
        // [u_3, u_4] = [0, 1], [u_4, u_5] = [1, 3]; v knots v_0 … v_6, one span
        let points: Vec<Vec<[Rational; 3]>> = (0..5)
            .map(|i| (0..4).map(|j| [q(i), q(j), q(i * j)]).collect())
            .collect();
        let net = ControlNet::new(points).expect("a net");
        let u: Vec<Rational> = [0, 0, 0, 0, 1, 3, 3, 3].map(q).to_vec();
        let v: Vec<Rational> = [0, 0, 0, 0, 2, 2, 2].map(q).to_vec();
        let (window, lu, lv) = net
            .span_at([&u, &v], (4, 4), [&q(2), &q(1)], ["2", "1"])
            .expect("a span");
        assert_eq!((lu, lv), (Rational::from((1, 2)), Rational::from((1, 2))));
        assert_eq!(window.points()[0][0], [q(1), q(0), q(0)]);
        assert_eq!((window.rows(), window.columns()), (4, 4));
        // the first span, its right end closed only for the last span
        let (window, lu, _) = net
            .span_at([&u, &v], (4, 4), [&q(1), &q(0)], ["1", "0"])
            .expect("a span");
        assert_eq!(
            (lu, window.points()[0][0].clone()),
            (q(0), [q(1), q(0), q(0)])
        );
        let (window, lu, _) = net
            .span_at(
                [&u, &v],
                (4, 4),
                [&Rational::from((1, 2)), &q(0)],
                ["1/2", "0"],
            )
            .expect("a span");
        assert_eq!(
            (lu, window.points()[0][0].clone()),
            (Rational::from((1, 2)), [q(0), q(0), q(0)])
        );
        // refused: a knot vector of the wrong length, a zero-length span, a
        // point outside the spans
        let short = &u[..7];
        let err = net.span_at([short, &v], (4, 4), [&q(1), &q(1)], ["1", "1"]);
        assert!(err.unwrap_err().to_string().contains("take 8 knots"));
        let flat: Vec<Rational> = [0, 0, 0, 0, 1, 1, 3, 3].map(q).to_vec();
        let err = net.span_at([&flat, &v], (4, 4), [&q(1), &q(1)], ["1", "1"]);
        assert!(err.unwrap_err().to_string().contains("zero-length"));
        let err = net.span_at([&u, &v], (4, 4), [&q(4), &q(1)], ["4", "1"]);
        assert!(err.unwrap_err().to_string().contains("outside"));
    }

    #[test]
    fn rows_are_separated_by_blank_lines_and_read_exactly() {
        let net = ControlNet::parse("# net\n0 0 0\n1,0,0.5\n\n\n0 1 0\n1 1 1/3\n", "n").unwrap();
        assert_eq!((net.rows(), net.columns()), (2, 2));
        assert_eq!(net.points()[0][1][2], Rational::from((1, 2)));
        assert_eq!(net.points()[1][1][2], Rational::from((1, 3)));
        assert!(!net.is_rational());
        let weighted = ControlNet::parse("0 0 0 2\n1 0 0 1\n", "n").unwrap();
        assert_eq!(weighted.weight(0, 0), Some(&q(2)));
        assert_eq!(weighted.inputs().len(), 8);
        let w = net.window(1, 1, 1, 1).unwrap();
        assert_eq!(w.points()[0][0][2], Rational::from((1, 3)));
        assert_eq!(
            weighted.window(0, 1, 1, 1).unwrap().weight(0, 0),
            Some(&q(1))
        );
        assert!(net.window(1, 1, 2, 1).is_none());
    }

    #[test]
    fn bad_nets_are_typed_errors_with_their_line() {
        let err = |t: &str| ControlNet::parse(t, "n").unwrap_err();
        assert!(matches!(err("0 0\n"), NetError::Malformed { line: 1, .. }));
        assert!(matches!(
            err("0 0 0\n0 x 0\n"),
            NetError::Malformed { line: 2, .. }
        ));
        assert!(matches!(
            err("0 0 NaN\n"),
            NetError::NotFinite { line: 1, .. }
        ));
        assert!(matches!(
            err("0 -inf 0\n"),
            NetError::NotFinite { line: 1, .. }
        ));
        assert!(matches!(
            err("0 0 0\n0 0 0\n\n0 0 0\n"),
            NetError::Ragged {
                row: 1,
                line: 4,
                expected: 2,
                got: 1,
                ..
            }
        ));
        assert!(matches!(
            err("0 0 0 1\n0 0 0\n"),
            NetError::MixedWeights {
                line: 2,
                first: 1,
                ..
            }
        ));
        assert!(matches!(
            err("0 0 0 0\n"),
            NetError::NonPositiveWeight { line: 1, .. }
        ));
        assert!(matches!(err("# nothing\n\n"), NetError::Empty { .. }));
        assert!(err("0 0 NaN\n").to_string().contains("n line 1"));
    }
}
