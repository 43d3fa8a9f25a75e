//! Table cells: how exact and numeric values print in each output format.

use trig_core::Mpfr;
use trig_symbolic::Sym;

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
        let Some(terms) = self.linear_in(vars) else {
            return Rendered::of(self);
        };
        let join = |f: &dyn Fn(&Sym) -> String, var: &dyn Fn(&Sym) -> String, dot: &str| {
            terms
                .iter()
                .map(|(v, coef)| format!("({}){dot}{}", f(coef), var(&Sym::var(v))))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        Rendered {
            text: join(&|c| c.to_string(), &|v| v.to_string(), "*"),
            unicode: join(&|c| c.to_unicode(), &|v| v.to_unicode(), "·"),
            latex: join(&|c| c.to_latex(), &|v| v.to_latex(), " "),
        }
    }
}

impl Cell for f64 {
    fn text(&self) -> String {
        self.to_string()
    }
    fn latex(&self) -> String {
        latex_number(&self.to_string())
    }
}

impl Cell for Mpfr {
    fn text(&self) -> String {
        self.to_string()
    }
    fn latex(&self) -> String {
        latex_number(&self.to_string())
    }
}

/// `1.5e-3` → `1.5 \times 10^{-3}`.
fn latex_number(s: &str) -> String {
    match s.split_once('e') {
        Some((m, e)) => format!("{m} \\times 10^{{{e}}}"),
        None => s.to_string(),
    }
}

/// A rendered table: a title, column headers, and labelled rows of cells
/// already printed in the three styles.
#[derive(Debug, Clone)]
pub struct Block {
    pub title: String,
    pub corner: String,
    pub columns: Vec<String>,
    pub rows: Vec<(String, Vec<Rendered>)>,
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
