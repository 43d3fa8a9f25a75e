//! Table cells: how exact and numeric values print in each output format.

use trig_core::Decimal;
use trig_symbolic::{Style, Sym};
use trig_tex::expr::number;

/// A value that can stand in a table.
pub trait Cell {
    /// Plain text (CSV, JSON, terminal).
    fn text(&self) -> String;
    /// Unicode for Markdown.
    fn unicode(&self) -> String {
        self.text()
    }
    /// LaTeX math (without `$`).
    fn latex(&self) -> String {
        self.text()
    }
    /// The value as a combination `Σ coefficient·v` of the named variables
    /// it is linear in (control points); numbers print as themselves.
    fn combination(&self, _vars: &[String]) -> Rendered
    where
        Self: Sized,
    {
        Rendered::of(self)
    }
}

impl Cell for Sym {
    fn text(&self) -> String {
        self.to_string()
    }
    fn unicode(&self) -> String {
        self.to_unicode()
    }
    fn latex(&self) -> String {
        self.to_latex()
    }
    fn combination(&self, vars: &[String]) -> Rendered {
        if self.linear_in(vars).is_none() {
            return Rendered::of(self);
        }
        let join = |style: Style| {
            self.combination_in(vars, style)
                .unwrap_or_else(|| style.sym(self))
        };
        Rendered {
            text: join(Style::Plain),
            unicode: join(Style::Unicode),
            latex: join(Style::Latex),
        }
    }
}

impl Rendered {
    /// A number printed as `text` (an f64 or proved decimal digits).
    pub fn number(text: &str) -> Self {
        Rendered {
            text: text.to_string(),
            unicode: text.to_string(),
            latex: number(text),
        }
    }

    /// What an enclosure proves: digits, `0 ± bound`, or an enclosure.
    pub fn decimal(d: &Decimal) -> Self {
        let latex = match d {
            Decimal::Digits { text, .. } => number(text),
            Decimal::Small { bound } => format!("0 \\pm {}", number(bound)),
            Decimal::Range { lo, hi } => format!("[{}, {}]", number(lo), number(hi)),
            Decimal::Undefined(_) => format!("\\text{{{}}}", trig_tex::text(&d.to_string())),
        };
        Rendered {
            text: d.to_string(),
            unicode: d.to_string(),
            latex,
        }
    }
}

/// A table: a title, column headers, and labelled rows of cells — values
/// of a ring, or (by default) cells already printed in the three styles.
#[derive(Debug, Clone)]
pub struct Block<C = Rendered> {
    pub title: String,
    pub corner: String,
    pub columns: Vec<String>,
    pub rows: Vec<(String, Vec<C>)>,
}

impl<C> Block<C> {
    /// The same table with every cell mapped.
    pub fn map<D>(self, mut f: impl FnMut(C) -> D) -> Block<D> {
        Block {
            title: self.title,
            corner: self.corner,
            columns: self.columns,
            rows: self
                .rows
                .into_iter()
                .map(|(label, cells)| (label, cells.into_iter().map(&mut f).collect()))
                .collect(),
        }
    }

    /// Every cell, row by row.
    pub fn cells(&self) -> impl Iterator<Item = &C> {
        self.rows.iter().flat_map(|(_, cells)| cells.iter())
    }
}

/// One cell printed in every style.
#[derive(Debug, Clone)]
pub struct Rendered {
    pub text: String,
    pub unicode: String,
    pub latex: String,
}

impl Rendered {
    pub fn of<C: Cell>(c: &C) -> Self {
        Rendered {
            text: c.text(),
            unicode: c.unicode(),
            latex: c.latex(),
        }
    }
}
