//! The TOML layout of a spec file, as read by serde before validation.
//! Strings that can be wrong in ways TOML cannot see keep their span, so
//! errors point at the line and column.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

/// A whole spec file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSpec {
    pub id: Spanned<String>,
    pub title: Option<String>,
    pub citation: String,
    pub variable: Spanned<String>,
    pub domain: Option<Spanned<String>>,
    #[serde(default)]
    pub piecewise: bool,
    #[serde(default)]
    pub parameters: Vec<RawParam>,
    #[serde(default)]
    pub definitions: Vec<RawFunction>,
    pub functions: Vec<RawFunction>,
    #[serde(default)]
    pub claims: Vec<RawClaim>,
}

/// `[[parameters]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawParam {
    pub name: Spanned<String>,
    pub symbol: Option<Spanned<String>>,
    pub range: Spanned<String>,
    pub source: Option<String>,
}

/// `[[functions]]` and `[[definitions]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFunction {
    pub name: Spanned<String>,
    pub formula: Spanned<String>,
}

/// `[[claims]]`: common fields, then the fields of each kind of check.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawClaim {
    pub id: Spanned<String>,
    pub source: String,
    pub statement: Spanned<String>,
    pub check: Spanned<String>,
    pub range: Option<Spanned<String>>,
    pub ranges: Option<BTreeMap<String, Spanned<String>>>,
    /// A region by linear inequalities (`"lambda >= 0, mu >= 0, lambda + mu <= 4"`).
    pub region: Option<Spanned<String>>,
    pub maximal: Option<bool>,
    pub functions: Option<Vec<Spanned<String>>>,
    pub map: Option<Spanned<String>>,
    pub index: Option<Spanned<String>>,
    pub at: Option<BTreeMap<String, Spanned<String>>>,
    pub params: Option<BTreeMap<String, Spanned<String>>>,
    pub end: Option<Spanned<String>>,
    pub order: Option<Spanned<i64>>,
    pub wrt: Option<Spanned<String>>,
    pub values: Option<Vec<Spanned<String>>>,
    pub value: Option<Spanned<String>>,
    pub join: Option<Spanned<String>>,
    pub different: Option<bool>,
    pub conditions: Option<Vec<Spanned<String>>>,
    /// `check = "join"`: the two segments' control points as printed.
    pub points: Option<Vec<Vec<Spanned<String>>>>,
    /// `check = "join"`, `different = true`: each segment's parameters as
    /// printed (`[{ m = "m2" }, { m = "m1" }]`).
    #[serde(rename = "segment-params")]
    pub segment_params: Option<Vec<BTreeMap<String, Spanned<String>>>>,
    /// Another reading of `segment-params`, decided for information.
    #[serde(rename = "also-params")]
    pub also_params: Option<Vec<BTreeMap<String, Spanned<String>>>>,
    pub parameter: Option<Spanned<String>>,
    pub direction: Option<Spanned<String>>,
    pub control: Option<Spanned<String>>,
    pub scope: Option<Spanned<String>>,
    pub segments: Option<Vec<i64>>,
    /// `check = "local-control"`: another reading of `scope`, decided for
    /// information.
    #[serde(rename = "also-scope")]
    pub also_scope: Option<Spanned<String>>,
    /// `for = "some value"` or `"no value"`.
    #[serde(rename = "for")]
    pub quantifier: Option<Spanned<String>>,
    /// `check = "all"`: the ids of the claims it is the umbrella of.
    pub claims: Option<Vec<Spanned<String>>>,
    /// `check = "not-printed"`: what the copy does not print.
    pub reason: Option<Spanned<String>>,
    /// The statement is the negation of the check ("is not C⁴").
    pub negated: Option<bool>,
    /// Remarks shown after the evidence (how a print is read, what the
    /// document says beside the claim).
    pub notes: Option<Vec<String>>,
    /// In a document file: the basis the claim is about (a name of its
    /// `[bases]`).
    pub basis: Option<Spanned<String>>,
}
