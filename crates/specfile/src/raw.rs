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

/// `knots = { coefficients = "…", values = ["0", "1", …], span = 8 }`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawKnots {
    pub coefficients: String,
    pub values: Vec<String>,
    pub span: i64,
}

/// `[[claims]]`: common fields, then the fields of each kind of check.
#[derive(Debug, Clone, Deserialize)]
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
    /// `check = "nonnegative"`: the functions bounded below by it (`f ≥ margin`).
    pub margin: Option<Spanned<String>>,
    pub functions: Option<Vec<Spanned<String>>>,
    pub map: Option<Spanned<String>>,
    pub index: Option<Spanned<String>>,
    pub at: Option<BTreeMap<String, Spanned<String>>>,
    /// A knot vector and a span of it (`crate::knots`).
    pub knots: Option<Spanned<RawKnots>>,
    /// `check = "knot-coefficients"`: the printed coefficient matrix, a
    /// row per segment function.
    pub matrix: Option<Vec<Vec<Spanned<String>>>>,
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
    /// `check = "join"`: the `G` factors as printed (`["omega", "beta"]`).
    pub factors: Option<Vec<Spanned<String>>>,
    /// `check = "join"`: `"reversed"` when the printed factors give the
    /// first segment's derivatives from the second's.
    pub orientation: Option<Spanned<String>>,
    pub parameter: Option<Spanned<String>>,
    pub direction: Option<Spanned<String>>,
    /// `check = "shape-effect"`: printed control polygons (each a list of
    /// points `"(x, y)"`), shown with their distance from the curve.
    pub polygons: Option<Vec<Vec<Spanned<String>>>>,
    /// `check = "shape-effect"` with `polygons`: the point of the variable
    /// where the curve point is taken, by its atoms (`s`, `c` or `t`).
    #[serde(rename = "curve-at")]
    pub curve_at: Option<BTreeMap<String, Spanned<String>>>,
    pub control: Option<Spanned<String>>,
    pub scope: Option<Spanned<String>>,
    pub segments: Option<Vec<i64>>,
    /// `check = "local-control"`: another reading of `scope`, decided for
    /// information.
    #[serde(rename = "also-scope")]
    pub also_scope: Option<Spanned<String>>,
    /// `check = "local-control"`: the index of segment 0's first control
    /// point (`0` unless given).
    #[serde(rename = "first-point")]
    pub first_point: Option<i64>,
    /// `check = "local-control"` with `weights = true`: the printed name of
    /// the control points (`P` unless given).
    pub point: Option<Spanned<String>>,
    /// `for = "some value"` or `"no value"`.
    #[serde(rename = "for")]
    pub quantifier: Option<Spanned<String>>,
    /// `check = "all"`: the ids of the claims it is the umbrella of.
    pub claims: Option<Vec<Spanned<String>>>,
    /// `check = "all"`: the parts are reported as claims of their own.
    pub brief: Option<bool>,
    /// `check = "not-printed"`: what the copy does not print.
    pub reason: Option<Spanned<String>>,
    /// `check = "interpolant-nonnegative"`: the table file (relative to
    /// the claim's file) and the scheme (`c1`, `c2`, `g1`, `g2`; the
    /// table's own unless given).
    pub data: Option<Spanned<String>>,
    pub scheme: Option<Spanned<String>>,
    /// `check = "table-quotes"` (or `"table-count"`: the counts file): the quotes file (relative to the claim's
    /// file): the statements in words about the tables of `data`.
    pub quotes: Option<Spanned<String>>,
    /// `check = "fourier-span"`: the printed span, one harmonic each.
    pub span: Option<Vec<Spanned<String>>>,
    /// `check = "identity"`: the printed identities `lhs = rhs`.
    pub identities: Option<Vec<Spanned<String>>>,
    /// `check = "identity"`: the printed name of the curve `Σ bᵢPᵢ`.
    pub curve: Option<Spanned<String>>,
    /// `check = "identity"`: further free symbols of the identities (a
    /// translation `q`, the entries of a matrix), constants of the ring;
    /// `check = "endpoint-derivatives"`: the printed parameters' names
    /// (`m1` in `Q2'(0; m1)`).
    pub symbols: Option<Vec<Spanned<String>>>,
    /// `check = "identity"`: symbols the claim's conditions make positive
    /// (`λ, μ > 0`): a witness of a failure gives them positive values.
    pub positive: Option<Vec<Spanned<String>>>,
    /// `check = "identity"`: readings of printed identities.
    pub readings: Option<Vec<RawReading>>,
    /// `check = "identity"`: the correction of a print that fails.
    pub correction: Option<RawCorrection>,
    /// `check = "end-direction"`: the printed difference `"P1 - P0"`.
    pub along: Option<Spanned<String>>,
    /// `check = "end-direction"`: the factor's sign, `positive` or `nonzero`.
    pub sign: Option<Spanned<String>>,
    /// `check = "end-direction"`: the factor tends to 0 as the parameter
    /// tends to `inf` (or `-inf`).
    pub limit: Option<Spanned<String>>,
    /// `check = "identity"`: the curve is rational, `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`.
    pub weights: Option<bool>,
    /// `check = "same-basis"`: the other basis (a spec file, relative to
    /// the claim's file).
    pub other: Option<Spanned<String>>,
    /// `check = "identity"` or `"endpoint-derivatives"`: curves with printed control points,
    /// `[{ name = "P", points = ["f0", "f0 + 2*h*d0/(pi*(m + 2))", …] }]`.
    pub curves: Option<Vec<RawCurve>>,
    /// `check = "identity"`: a change of variable, `{ x = "(x - x_i)/h_i" }`.
    pub change: Option<BTreeMap<String, Spanned<String>>>,
    /// `check = "surface-join"`: the seams, `"label: A | B"` (B beside A)
    /// or `"label: A ; B"` (B below A), nets of the listing.
    pub seams: Option<Vec<Spanned<String>>>,
    /// `check = "cylinder"`: the radius of the cylinder `x² + y² = r²`.
    pub radius: Option<Spanned<String>>,
    /// `check = "identity"`: names the identities use, `"NAME = formula"`
    /// in order (a shorthand of the print, a function built from the
    /// basis's, applied like one).
    #[serde(rename = "let")]
    pub lets: Option<Vec<Spanned<String>>>,
    /// The statement is the negation of the check ("is not C⁴").
    pub negated: Option<bool>,
    /// Remarks shown after the evidence (how a print is read, what the
    /// document says beside the claim).
    pub notes: Option<Vec<String>>,
    /// In a document file: the basis the claim is about (a name of its
    /// `[bases]`).
    pub basis: Option<Spanned<String>>,
    /// In a document file, `check = "all"`: the parts of the umbrella, each
    /// a claim of its own basis (`[[claims.parts]]`).
    pub parts: Option<Vec<RawClaim>>,
    /// A part shown for information (its verdict never decides the umbrella).
    pub shown: Option<bool>,
    /// A figure supporting the verdict (`[claims.figure]`).
    pub figure: Option<RawFigure>,
    /// `check = "shape-effect"`: several parameters changed concurrently
    /// (instead of `parameter`).
    pub parameters: Option<Vec<Spanned<String>>>,
    /// `check = "shape-effect"`: the functions whose weights rise (the
    /// curve approaches their control points; instead of `direction`).
    pub onto: Option<Vec<Spanned<String>>>,
    /// `check = "shape-effect"`: printed "as `p` increases (or decreases)".
    pub either: Option<bool>,
    /// `check = "end-curvature"`: the rational curves compared, each
    /// `{ label, name, basis, weights }`.
    pub curvatures: Option<Vec<RawCurvature>>,
}

/// `curvatures = [{ label = "the quintic Bézier curve", name = "quintic",
/// basis = "bernstein-5.toml", weights = ["1", …] }]`: `basis` a spec file
/// relative to the claim's file (the claim's own basis when absent),
/// `weights` all 1 when absent.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCurvature {
    pub label: String,
    pub name: Option<String>,
    pub basis: Option<Spanned<String>>,
    pub weights: Option<Vec<Spanned<String>>>,
}

/// `[claims.figure]`: `file` (relative to the claim's file), `caption`, and
/// `plot`, the `trig-audit plot` arguments that draw it.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFigure {
    pub file: Spanned<String>,
    pub caption: String,
    pub plot: String,
}

/// `curves = [{ name = "P", points = ["f0", …] }]`: the curve `Σ bᵢ·pointᵢ`
/// of printed control points, one formula per function (`identity`;
/// `endpoint-derivatives`: `curves = [{ name = "Q2", points = ["P4", …] }]`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCurve {
    pub name: Spanned<String>,
    pub points: Vec<Spanned<String>>,
    /// `identity` with a `change`: the curve's own variable, a formula in
    /// the claim's new variable (a spline's next segment).
    pub change: Option<Spanned<String>>,
}

/// `correction = { says = "…", identities = ["…"] }`: a correction of a
/// print that fails (`identity`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCorrection {
    pub says: Spanned<String>,
    pub identities: Vec<Spanned<String>>,
}

/// `readings = [{ of = "printed identity", as = "its reading" }]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawReading {
    pub of: Spanned<String>,
    #[serde(rename = "as")]
    pub read: Spanned<String>,
}
