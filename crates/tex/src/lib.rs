//! # trig-tex
//!
//! The one LaTeX writer of trig-audit: the audit report, the tables of
//! `table --format tex` and `join --format tex`, the pgfplots code of the
//! figures, and the LaTeX form of exact expressions (`trig_symbolic`'s
//! printer takes its pieces from [`expr`]) are all written with it.
//!
//! - Text: [`text`] escapes prose (the special characters, every Unicode
//!   symbol the reports print mapped, [`symbols`]); [`marked()`] sets text
//!   with explicit math markup (`⟪…⟫`, how printed statements are stored;
//!   [`plain`] is the text as printed, [`unicode`] as a reader without LaTeX
//!   sees it); [`prose`] sets generated text
//!   without markup, finding its formula-like runs ([`labelled`]: marked
//!   text whose prose may hold such runs, a figure's heading); [`breakable`] lets a
//!   long path or printed formula break.
//! - Math: [`math`], the one math writer, turns Unicode formula text
//!   (`H_{2−i}(π/2 − u; β)`, `b0'(0) = 3/A`) into LaTeX math; [`inline_math`]
//!   and [`fitted_math`] set a formula in text.
//! - Expressions: [`expr`] spells names, powers, fractions and numbers.
//! - Tables: [`LongTable`] with its [`Column`]s, [`column_name`]; the
//!   tables of values of `table --format tex`, [`value_tables`].
//! - Documents: [`PREAMBLE`], [`document`]; the report as a fragment for
//!   `\input` ([`fragment`], needing only [`FRAGMENT_PACKAGES`]); fragments
//!   to `\input` and plain articles around them ([`input_note`],
//!   [`article`]); [`comment`], [`align`]; [`compile`] runs `pdflatex` for
//!   the tests.
//!
//! The output is ASCII and compiles with pdfLaTeX (and LuaLaTeX, XeLaTeX)
//! using the packages of a basic TeX installation. The crate depends on
//! nothing, so every crate that writes LaTeX can use it.

mod compile;
mod document;
pub mod expr;
mod fragment;
pub mod marked;
mod math;
mod prose;
pub mod symbols;
mod table;
mod text;

pub use compile::{CompileLog, REQUIRE_TEX, compile};
pub use document::{
    FRAGMENT_PACKAGES, FRAGMENT_SETUP, PREAMBLE, align, comment, document, fragment,
};
pub use fragment::{article, input_note};
pub use marked::{marked, plain, unicode};
pub use math::{fitted_math, inline_math, math};
pub use prose::{labelled, prose};
pub use symbols::unmapped;
pub use table::{Column, LongTable, TABLE_PACKAGES, ValueTable, column_name, value_tables};
pub use text::{breakable, code, text};
