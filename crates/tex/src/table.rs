//! Tables that may break across pages (`longtable` with `booktabs` rules):
//! the column types, a caption, a head repeated on every page, the body and
//! a foot; how a column is named in its head; and the tables of values of
//! `table --format tex` ([`value_tables`]), laid out to fit the text width
//! of a default `article`. Only standard packages: `longtable`, `booktabs`,
//! `amsmath` — no column type of a preamble.

use std::fmt;

use crate::expr::{breakable_digits, cell_math, width};
use crate::fragment::{article, input_note};
use crate::math::inline_math;
use crate::prose::prose;

/// A column of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    /// Left-aligned, as wide as its widest entry (`l`).
    Left,
    /// Right-aligned, as wide as its widest entry (`r`).
    Right,
    /// Ragged-right text wrapping at this width (a LaTeX length): with the
    /// `array` package `>{\raggedright\arraybackslash}p{width}`, with
    /// standard packages only ([`LongTable::standard_packages`]) `p{width}`
    /// and every cell opened by `\raggedright` (in the last column
    /// `\raggedright\let\\\tabularnewline`, what `\arraybackslash` does:
    /// `\\` still ends the row).
    Wrap(&'static str),
    /// [`Column::Wrap`] at this percentage of the line width, its padding
    /// included (`\dimexpr 0.25\linewidth-2\tabcolsep\relax`): the shares
    /// of a table's columns add up to 100.
    Share(u8),
}

/// What opens a cell of a wrapping column in a table without `array`: in
/// the last column, and in the others.
const RAGGED_LAST_CELL: &str = r"\raggedright\let\\\tabularnewline ";
const RAGGED_CELL: &str = r"\raggedright ";

impl Column {
    /// The column's letter (with `array`, `>{…}` for a wrapping column).
    fn spec(&self, array: bool) -> String {
        match self {
            Column::Left => "l".into(),
            Column::Right => "r".into(),
            Column::Wrap(width) => wrap_spec(width, array),
            Column::Share(percent) => wrap_spec(
                &format!(r"\dimexpr 0.{percent:02}\linewidth-2\tabcolsep\relax"),
                array,
            ),
        }
    }

    /// Whether the column wraps its text.
    fn wraps(&self) -> bool {
        matches!(self, Column::Wrap(_) | Column::Share(_))
    }
}

/// A wrapping column of `width`: with `array` ragged right by its column
/// type, else a plain `p` column (its cells opened by [`RAGGED_CELL`]).
fn wrap_spec(width: &str, array: bool) -> String {
    if array {
        format!(r">{{\raggedright\arraybackslash}}p{{{width}}}")
    } else {
        format!("p{{{width}}}")
    }
}

/// A `longtable` with `booktabs` rules: cells are LaTeX (text mode), rows
/// as many as the columns. `Display` writes it, ending with
/// `\end{longtable}` and a line break.
#[derive(Debug, Clone)]
pub struct LongTable {
    columns: Vec<Column>,
    caption: String,
    numbered: bool,
    small: bool,
    array: bool,
    head: Vec<String>,
    body: Vec<Vec<String>>,
    foot: Vec<Vec<String>>,
}

impl LongTable {
    /// A table with a numbered caption (LaTeX) and the head row.
    pub fn new(columns: Vec<Column>, caption: String, head: Vec<String>) -> LongTable {
        LongTable {
            columns,
            caption,
            numbered: true,
            small: false,
            array: true,
            head,
            body: Vec::new(),
            foot: Vec::new(),
        }
    }

    /// The same table with an unnumbered caption (`\caption*`).
    pub fn unnumbered(mut self) -> LongTable {
        self.numbered = false;
        self
    }

    /// The same table in a small font.
    pub fn small(mut self) -> LongTable {
        self.small = true;
        self
    }

    /// The same table for a document with standard packages only
    /// (`longtable`, `booktabs`): no column type of the `array` package.
    pub fn standard_packages(mut self) -> LongTable {
        self.array = false;
        self
    }

    /// Appends a row of the body.
    pub fn row(&mut self, cells: Vec<String>) {
        self.body.push(cells);
    }

    /// Appends a row of the foot (after a rule below the body: totals).
    pub fn foot(&mut self, cells: Vec<String>) {
        self.foot.push(cells);
    }
}

impl LongTable {
    /// A row: without `array`, the cells of wrapping columns opened by
    /// [`RAGGED_CELL`] ([`RAGGED_LAST_CELL`] in the last column).
    fn write_row(&self, f: &mut fmt::Formatter<'_>, cells: &[String]) -> fmt::Result {
        let last = self.columns.len().saturating_sub(1);
        let cells: Vec<String> = cells
            .iter()
            .zip(self.columns.iter().chain(std::iter::repeat(&Column::Left)))
            .enumerate()
            .map(|(k, (cell, column))| match column {
                c if c.wraps() && !self.array && k == last => format!("{RAGGED_LAST_CELL}{cell}"),
                c if c.wraps() && !self.array => format!("{RAGGED_CELL}{cell}"),
                _ => cell.clone(),
            })
            .collect();
        writeln!(f, "{} \\\\", cells.join(" & "))
    }
}

impl fmt::Display for LongTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.small {
            writeln!(f, "{{\\small")?;
        }
        let columns: String = self.columns.iter().map(|c| c.spec(self.array)).collect();
        writeln!(f, "\\begin{{longtable}}{{@{{}}{columns}@{{}}}}")?;
        let star = if self.numbered { "" } else { "*" };
        writeln!(f, "\\caption{star}{{{}}}\\\\\n\\toprule", self.caption)?;
        self.write_row(f, &self.head)?;
        writeln!(f, "\\midrule\n\\endhead")?;
        for cells in &self.body {
            self.write_row(f, cells)?;
        }
        if !self.foot.is_empty() {
            writeln!(f, "\\midrule")?;
            for cells in &self.foot {
                self.write_row(f, cells)?;
            }
        }
        writeln!(f, "\\bottomrule\n\\end{{longtable}}")?;
        if self.small {
            writeln!(f, "}}")?;
        }
        Ok(())
    }
}

/// A column named in a head: a function name (`b0`, `H2`) as math with its
/// index, a word (`derivative`) as prose.
pub fn column_name(name: &str) -> String {
    let digits = name.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    let letters = &name[..name.len() - digits.len()];
    if !letters.is_empty() && !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()) {
        inline_math(&format!("{letters}_{{{digits}}}"))
    } else {
        prose(name)
    }
}

/// The packages a table needs.
pub const TABLE_PACKAGES: [&str; 3] = ["booktabs", "longtable", "amsmath"];

/// The text width of a default `article` (10 pt: 345 pt), in ems.
const TEXT_WIDTH: f64 = 34.5;

/// Space between two columns (`2\tabcolsep`), in ems.
const COLUMN_GAP: f64 = 1.2;

/// The columns of a table set one entry per line: the row label, the
/// column's name, and the value taking the rest of the line.
const ENTRY_COLUMNS: [Column; 3] = [
    Column::Wrap(r"0.06\linewidth"),
    Column::Wrap(r"0.16\linewidth"),
    Column::Wrap(r"\dimexpr0.78\linewidth-4\tabcolsep\relax"),
];

/// How wide a fraction in the value column of [`ENTRY_COLUMNS`] may be
/// (ems) and still be set as `\frac`.
const ENTRY_ROOM: f64 = 18.0;

/// A table of values: a title (text), the corner and the names of the
/// columns (`b0`, `derivative`: see [`column_name`]), and labelled rows of
/// cells in LaTeX math (without `$`).
#[derive(Debug, Clone, Default)]
pub struct ValueTable {
    pub title: String,
    pub corner: String,
    pub columns: Vec<String>,
    pub rows: Vec<(String, Vec<String>)>,
}

impl ValueTable {
    /// The `longtable` of this table under `heading` (its caption is the
    /// heading and the title): rows and columns when they fit the text
    /// width of a default `article`, else one entry per line (row,
    /// column, value) with the value wrapping at its operators (and in
    /// long runs of digits) and its fractions `\frac` where they fit
    /// ([`cell_math`]).
    fn longtable(&self, heading: &str) -> LongTable {
        let caption = prose(&format!("{heading}; {}", self.title));
        let text_width = |s: &str| 0.55 * s.chars().count() as f64;
        let mut widest = vec![text_width(&self.corner)];
        widest.extend(self.columns.iter().map(|c| text_width(c)));
        for (label, cells) in &self.rows {
            widest[0] = widest[0].max(text_width(label));
            for (k, cell) in cells.iter().enumerate() {
                if let Some(w) = widest.get_mut(k + 1) {
                    *w = w.max(width(&cell_math(cell, TEXT_WIDTH)));
                }
            }
        }
        let gaps = COLUMN_GAP * (widest.len() - 1) as f64;
        if widest.iter().sum::<f64>() + gaps <= TEXT_WIDTH {
            let mut head = vec![prose(&self.corner)];
            head.extend(self.columns.iter().map(|c| column_name(c)));
            let mut t =
                LongTable::new(vec![Column::Left; widest.len()], caption, head).standard_packages();
            for (label, cells) in &self.rows {
                let mut row = vec![prose(label)];
                row.extend(cells.iter().map(|c| inline_math(&cell_math(c, TEXT_WIDTH))));
                t.row(row);
            }
            return t;
        }
        let head = vec![prose(&self.corner), "entry".into(), "value".into()];
        let mut t = LongTable::new(ENTRY_COLUMNS.to_vec(), caption, head).standard_packages();
        for (label, cells) in &self.rows {
            for (column, cell) in self.columns.iter().zip(cells) {
                t.row(vec![
                    prose(label),
                    column_name(column),
                    inline_math(&breakable_digits(&cell_math(cell, ENTRY_ROOM))),
                ]);
            }
        }
        t
    }
}

/// Tables of values under `heading` (text) as LaTeX: a fragment to
/// `\input` (standard packages only, [`TABLE_PACKAGES`]), or with
/// `standalone` a whole plain `article` around it.
pub fn value_tables(heading: &str, tables: &[ValueTable], standalone: bool) -> String {
    let mut body = input_note(heading, &TABLE_PACKAGES, &[]);
    for t in tables {
        body.push_str(&t.longtable(heading).to_string());
    }
    if standalone {
        article(&TABLE_PACKAGES, &[], &body)
    } else {
        body
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_has_caption_head_body_and_foot() {
        let mut t = LongTable::new(
            vec![Column::Left, Column::Right, Column::Wrap("2cm")],
            "T".into(),
            ["a", "b", "c"].map(String::from).to_vec(),
        )
        .unnumbered()
        .small();
        t.row(["1", "2", "3"].map(String::from).to_vec());
        t.foot(["x", "y", "z"].map(String::from).to_vec());
        assert_eq!(
            t.to_string(),
            "{\\small\n\\begin{longtable}{@{}lr>{\\raggedright\\arraybackslash}p{2cm}@{}}\n\\caption*{T}\\\\\n\\toprule\na & b & c \\\\\n\\midrule\n\\endhead\n1 & 2 & 3 \\\\\n\\midrule\nx & y & z \\\\\n\\bottomrule\n\\end{longtable}\n}\n"
        );
        let mut t = LongTable::new(vec![Column::Wrap("2cm")], "T".into(), vec!["a".into()])
            .standard_packages();
        t.row(vec!["1".into()]);
        assert!(
            t.to_string().contains("{@{}p{2cm}@{}}")
                && t.to_string()
                    .contains("\\raggedright\\let\\\\\\tabularnewline 1 \\\\\n"),
            "{t}"
        );
        assert_eq!(column_name("b0"), "$b_{0}$");
        assert_eq!(column_name("derivative"), "derivative");
    }

    fn values(cells: &[&str]) -> ValueTable {
        ValueTable {
            title: "start of the domain".into(),
            corner: "k".into(),
            columns: (0..cells.len()).map(|i| format!("b{i}")).collect(),
            rows: vec![("1".into(), cells.iter().map(|c| c.to_string()).collect())],
        }
    }

    #[test]
    fn value_tables_are_fragments_with_fractions_that_fit_the_line() {
        let narrow = values(&[r"\frac{15}{8} m \pi^{6}", "-m - 2"]);
        let tex = value_tables("b: derivatives in θ, exact", &[narrow], false);
        assert!(tex.starts_with("% b: derivatives"), "{tex}");
        assert!(!tex.contains(r"\documentclass") && !tex.contains(r"\newcolumntype"));
        assert!(tex.contains(r"\begin{longtable}{@{}lll@{}}"), "{tex}");
        assert!(tex.contains(r"& $\frac{15}{8}\, m \pi^{6}$ &"), "{tex}");
        assert!(tex.contains(r"\toprule") && tex.contains(r"\bottomrule"));
        // too wide for rows and columns: one entry per line, the value wrapping
        let sum = (0..12)
            .map(|i| format!("a_{{{i}}} w_{{{i}}}"))
            .collect::<Vec<_>>();
        let long = format!(r"\frac{{{}}}{{3}}", sum.join(" + "));
        let wide = values(&[&long, &long, &long]);
        let tex = value_tables("h", &[wide], true);
        assert!(
            tex.starts_with("\\documentclass{article}\n\\usepackage{booktabs,longtable,amsmath}\n")
        );
        assert!(
            tex.contains(r"\linewidth") && tex.contains(r"\raggedright $b_{2}$"),
            "{tex}"
        );
        assert!(tex.contains(")/3$") && !tex.contains(r"\frac"), "{tex}");
    }
}
