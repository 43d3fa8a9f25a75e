//! Tables that may break across pages (`longtable`): the column types, a
//! caption, a head repeated on every page, the body and a foot; and how a
//! column is named in its head.

use std::fmt;

use crate::math::inline_math;
use crate::text::prose;

/// A column of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    /// Left-aligned, as wide as its widest entry (`l`).
    Left,
    /// Right-aligned, as wide as its widest entry (`r`).
    Right,
    /// Ragged-right text wrapping at this width (a `p` column of the
    /// `array` package: `>{\raggedright\arraybackslash}p{width}`).
    Wrap(&'static str),
}

impl fmt::Display for Column {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Column::Left => f.write_str("l"),
            Column::Right => f.write_str("r"),
            Column::Wrap(width) => write!(f, r">{{\raggedright\arraybackslash}}p{{{width}}}"),
        }
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

    /// Appends a row of the body.
    pub fn row(&mut self, cells: Vec<String>) {
        self.body.push(cells);
    }

    /// Appends a row of the foot (after a rule below the body: totals).
    pub fn foot(&mut self, cells: Vec<String>) {
        self.foot.push(cells);
    }
}

fn row(f: &mut fmt::Formatter<'_>, cells: &[String]) -> fmt::Result {
    writeln!(f, "{} \\\\", cells.join(" & "))
}

impl fmt::Display for LongTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.small {
            writeln!(f, "{{\\small")?;
        }
        let columns: String = self.columns.iter().map(Column::to_string).collect();
        writeln!(f, "\\begin{{longtable}}{{{columns}}}")?;
        let star = if self.numbered { "" } else { "*" };
        writeln!(f, "\\caption{star}{{{}}}\\\\\n\\toprule", self.caption)?;
        row(f, &self.head)?;
        writeln!(f, "\\midrule\n\\endhead")?;
        for cells in &self.body {
            row(f, cells)?;
        }
        if !self.foot.is_empty() {
            writeln!(f, "\\midrule")?;
            for cells in &self.foot {
                row(f, cells)?;
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
            "{\\small\n\\begin{longtable}{lr>{\\raggedright\\arraybackslash}p{2cm}}\n\\caption*{T}\\\\\n\\toprule\na & b & c \\\\\n\\midrule\n\\endhead\n1 & 2 & 3 \\\\\n\\midrule\nx & y & z \\\\\n\\bottomrule\n\\end{longtable}\n}\n"
        );
        assert_eq!(column_name("b0"), "$b_{0}$");
        assert_eq!(column_name("derivative"), "derivative");
    }
}
