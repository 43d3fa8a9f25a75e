//! A value recomputed exactly from printed table cells, with what a reader
//! needs to recompute it: the cells it reads (each a symbol set to its
//! printed decimal) and the formula in those symbols (`seg1 + … + seg11`,
//! a mean, `max(…)`, `after4 − before4`, or one cell itself).
//!
//! Witnesses of the table judges ([`crate::quoted`]) put the cells
//! in the witness point and the formula in each value's `of`, so the value
//! is re-checked by substituting the point into the formula.

use rug::ops::Pow;
use rug::{Integer, Rational};
use trig_symbolic::Sym;

use trig_verdict::evidence::{Assignment, Expr, Relation, Value, Witness};

/// A printed cell read by a formula: the symbol naming it, its printed
/// text and exact value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cell {
    pub symbol: String,
    pub text: String,
    pub value: Rational,
}

impl Cell {
    /// The cell `symbol` printed as `text` with exact value `value`.
    pub fn new(symbol: impl Into<String>, text: &str, value: &Rational) -> Cell {
        Cell {
            symbol: symbol.into(),
            text: text.to_string(),
            value: value.clone(),
        }
    }
}

/// An exact value, with the cells and formula it was recomputed from
/// (none for a count or a figure quoted by the text).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Recomputed {
    pub value: Rational,
    /// The value as printed, when it is a printed figure.
    printed: Option<String>,
    cells: Vec<Cell>,
    formula: Option<Expr>,
}

impl From<Rational> for Recomputed {
    /// A value given as it is (a count): no formula.
    fn from(value: Rational) -> Recomputed {
        Recomputed {
            value,
            printed: None,
            cells: Vec::new(),
            formula: None,
        }
    }
}

impl Recomputed {
    /// A figure printed as `text` with exact value `value` (quoted by the
    /// text, not read from cells): no formula.
    pub fn printed(text: &str, value: &Rational) -> Recomputed {
        Recomputed {
            printed: Some(text.to_string()),
            ..Recomputed::from(value.clone())
        }
    }

    /// One cell as it is printed (its formula is its symbol).
    pub fn cell(cell: Cell) -> Recomputed {
        Recomputed {
            value: cell.value.clone(),
            printed: None,
            formula: Some(Expr::new(&Sym::var(&cell.symbol))),
            cells: vec![cell],
        }
    }

    /// `formula(cells)`, exactly; `None` where a denominator vanishes or
    /// the formula reads a symbol that is not a cell.
    pub fn of(formula: &Sym, cells: Vec<Cell>) -> Option<Recomputed> {
        let point: Vec<(String, Rational)> = cells
            .iter()
            .map(|c| (c.symbol.clone(), c.value.clone()))
            .collect();
        let value = trig_verdict::witness::at(formula, &point)?.as_rational()?;
        Some(Recomputed {
            value,
            printed: None,
            cells,
            formula: Some(Expr::new(formula)),
        })
    }

    /// The sum of the cells.
    pub fn sum(cells: Vec<Cell>) -> Option<Recomputed> {
        Recomputed::of(&sum(&cells), cells)
    }

    /// The mean of the cells.
    pub fn mean(cells: Vec<Cell>) -> Option<Recomputed> {
        let n = Sym::int(i64::try_from(cells.len()).ok()?);
        Recomputed::of(&(sum(&cells) / &n), cells)
    }

    /// The largest (`max`) or smallest cell.
    pub fn extreme(cells: Vec<Cell>, max: bool) -> Option<Recomputed> {
        let value = cells
            .iter()
            .map(|c| &c.value)
            .max_by(|a, b| if max { a.cmp(b) } else { b.cmp(a) })?
            .clone();
        let symbols: Vec<String> = cells.iter().map(|c| c.symbol.clone()).collect();
        Some(Recomputed {
            value,
            printed: None,
            formula: Some(Expr::extreme(max, &symbols)),
            cells,
        })
    }

    /// The witness value labelled `label`: the value, with its formula.
    fn witness_value(&self, label: &str) -> Value {
        let text = self.printed.clone().unwrap_or_else(|| decimal(&self.value));
        let value = Value::new(label, Expr::decimal(&self.value, &text));
        match &self.formula {
            Some(f) => value.of_expr(f.clone()),
            None => value,
        }
    }
}

fn sum(cells: &[Cell]) -> Sym {
    cells
        .iter()
        .fold(Sym::zero(), |acc, c| acc + &Sym::var(&c.symbol))
}

/// A witness that `stated` fails between labelled values: the point sets
/// every cell the values read (to its printed decimal), each recomputed
/// value records its formula.
pub fn witness(note: Option<String>, stated: Relation, values: &[(&str, &Recomputed)]) -> Witness {
    let mut point: Vec<Assignment> = Vec::new();
    for (_, r) in values {
        for c in &r.cells {
            if !point.iter().any(|a| a.symbol.as_deref() == Some(&c.symbol)) {
                point.push(Assignment::printed(&c.symbol, &c.value, &c.text));
            }
        }
    }
    Witness {
        point,
        note,
        values: values
            .iter()
            .map(|(label, r)| r.witness_value(label))
            .collect(),
        exact: true,
        stated: (stated != Relation::Equal).then_some(stated),
    }
}

/// An exact rational as a decimal when it terminates, else as a fraction
/// with a 6-digit approximation.
pub fn decimal(q: &Rational) -> String {
    for places in 0..=20u32 {
        let scaled = q.clone() * Rational::from(Integer::from(10).pow(places));
        if *scaled.denom() == 1 {
            let n = scaled.numer().clone();
            let digits = n.clone().abs().to_string();
            let sign = if n < 0 { "-" } else { "" };
            if places == 0 {
                return format!("{sign}{digits}");
            }
            let p = places as usize;
            let padded = format!("{digits:0>width$}", width = p + 1);
            let (int, frac) = padded.split_at(padded.len() - p);
            return format!("{sign}{int}.{frac}");
        }
    }
    format!("{q} ≈ {:.6}", q.to_f64())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn decimals_print_exactly() {
        assert_eq!(decimal(&q(-8023, 10000)), "-0.8023");
        assert_eq!(decimal(&q(3, 1)), "3");
        assert_eq!(decimal(&q(1, 3)), "1/3 ≈ 0.333333");
    }

    #[test]
    fn formulas_recompute_their_cells_and_witnesses_carry_them() {
        let cells = vec![
            Cell::new("seg1", "1.5", &q(3, 2)),
            Cell::new("seg2", "2.25", &q(9, 4)),
        ];
        let total = Recomputed::sum(cells.clone()).unwrap();
        assert_eq!(total.value, q(15, 4));
        assert_eq!(Recomputed::mean(cells.clone()).unwrap().value, q(15, 8));
        let max = Recomputed::extreme(cells.clone(), true).unwrap();
        assert_eq!(max.value, q(9, 4));
        let printed = Recomputed::printed("4.0", &q(4, 1));
        let w = witness(
            None,
            Relation::Equal,
            &[("printed", &printed), ("computed", &total)],
        );
        let point: Vec<String> = w
            .point
            .iter()
            .map(|a| format!("{} = {}", a.name, a.value))
            .collect();
        assert_eq!(point, ["seg₁ = 1.5", "seg₂ = 2.25"]);
        assert_eq!(w.point[1].sympy.as_deref(), Some("9/4"));
        assert!(w.values[0].of.is_none());
        assert_eq!(w.values[0].value.unicode, "4.0");
        assert_eq!(w.values[1].of.as_ref().unwrap().sympy, "seg1 + seg2");
        assert_eq!(w.stated, None);
        let w = witness(None, Relation::Less, &[("max", &max)]);
        assert_eq!(w.values[0].of.as_ref().unwrap().sympy, "Max(seg1, seg2)");
        assert_eq!(w.stated, Some(Relation::Less));
    }
}
