//! The claims of a spec file as data: what is printed, decided later by a
//! judge of the audit. Read from the file by `claims.rs`.

use rug::Rational;
use trig_core::{Affine, ParamRange};
use trig_deriv::{End, JoinKind, Wrt};
use trig_interp::{DataSet, Scheme};
use trig_symbolic::Sym;

/// A printed value `name = formula` of one function.
#[derive(Debug, Clone, PartialEq)]
pub struct Printed {
    pub function: usize,
    pub text: String,
    pub value: Sym,
}

/// A constant lower bound a nonnegativity claim proves instead of `0`
/// (`margin = "1/200"`): `f − margin ≥ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct Margin {
    /// As written.
    pub text: String,
    pub value: Rational,
}

/// A printed endpoint derivative `f⁽ᵏ⁾(end) = value` of a function or of
/// a [`NamedCurve`].
#[derive(Debug, Clone, PartialEq)]
pub struct PrintedDerivative {
    pub of: Differentiated,
    pub order: usize,
    pub end: End,
    /// How the report names it (`b0'(0)`, `Condition 1, Q2(0)`); `None`:
    /// the judge's own label (function, order, end and convention).
    pub label: Option<String>,
    /// The parameters printed with it (`Q2'(0; m1)`: the basis at `m = m1`),
    /// one per parameter of the basis; `None`: the basis's own.
    pub params: Option<Vec<Sym>>,
    /// The printed value as written.
    pub printed: String,
    pub value: Sym,
}

/// What a [`PrintedDerivative`] differentiates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Differentiated {
    /// The basis function of this index.
    Function(usize),
    /// The claim's curve of this index.
    Curve(usize),
}

/// A curve `Σ bᵢPᵢ` a claim names (`Q2`), with its control points as
/// printed (`P4…P7`).
#[derive(Debug, Clone, PartialEq)]
pub struct NamedCurve {
    pub name: String,
    pub points: Vec<String>,
}

/// A control net a listing builds: `points[i][j]` is `P_{i,j}` (row `i`
/// with the functions of the first surface variable), each coordinate
/// exact (numbers, or formulas in the parameters).
#[derive(Debug, Clone, PartialEq)]
pub struct ListedNet {
    pub name: String,
    pub points: Vec<Vec<[Sym; 3]>>,
}

/// Where two patches meet: the end of net `first` and the start of net
/// `second` (indices into the claim's nets).
#[derive(Debug, Clone, PartialEq)]
pub struct Seam {
    pub label: String,
    pub first: usize,
    pub second: usize,
    pub across: Across,
}

/// The side of a seam: `Columns` (`A | B`: the last column of `A` meets
/// the first of `B`, across the second surface variable) or `Rows`
/// (`A ; B`: the last row of `A` meets the first of `B`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Across {
    Columns,
    Rows,
}

/// A printed monotonicity statement about one function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Monotone {
    pub function: usize,
    pub increasing: bool,
}

/// The direction a printed shape-parameter claim states, as the parameter
/// increases: the curve `Σ bᵢPᵢ` moves towards its control polygon (the
/// end weights `b₀`, `bₙ` decrease and the inner weights increase) or away
/// from it (the opposite).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    TowardsPolygon,
    AwayFromPolygon,
}

/// Where a shape-effect claim says the curve `Σ bᵢPᵢ` goes as its
/// parameters increase.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Towards or away from the whole control polygon.
    Polygon(Direction),
    /// Onto the control points of these indices (a segment `P_aP_b` of the
    /// polygon): their weights rise and the others' fall.
    Onto(Vec<usize>),
}

/// The control polygons a shape-effect claim prints (its figures), with
/// where their distance from the curve `Σ bᵢPᵢ` is shown: the curve point
/// at one exact point of the variable, for each printed parameter value.
/// An illustration beside the verdict; the weights decide.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygons {
    /// Each polygon's vertices, exact.
    pub polygons: Vec<Vec<(Rational, Rational)>>,
    /// The point of the variable: its atoms (`s`, `c` or `t`) and values.
    pub at: Vec<(String, Rational)>,
    /// The values of the varied parameter, in order.
    pub values: Vec<Rational>,
}

/// A printed join condition `Qk = formula in P0…, Q0…`.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Index `k` of the second segment's control point.
    pub point: usize,
    pub text: String,
    pub value: Sym,
    /// The printed additive terms of the formula (signs included) over its
    /// printed denominator: `value = Σ terms / denominator`.
    pub terms: Vec<Sym>,
    pub denominator: Sym,
    /// Ranges of `terms` printed as one bracket of control points times a
    /// scalar (`α(P3 − P2)`): its sign is one printed sign too.
    pub brackets: Vec<std::ops::Range<usize>>,
    /// Divisions of the printed formula not proved nonzero over the ranges
    /// (why, with the witness): the formula is singular there.
    pub singular: Vec<String>,
}

/// The two segments of a printed join as the paper names them: each
/// segment's control points (`P0…`, `Q0…` unless printed otherwise) and,
/// with different parameters, each segment's own copies of the parameters
/// as printed (`p1`, `p2` unless printed otherwise).
#[derive(Debug, Clone, PartialEq)]
pub struct JoinSegments {
    pub points: [Vec<String>; 2],
    /// The copies as printed (`segment-params`); `None`: `p1`, `p2`.
    pub printed: Option<[Vec<Sym>; 2]>,
    /// Another reading of the segments' parameters (`also-params`): the
    /// printed formulas are decided under it too, for information.
    pub also: Option<[Vec<Sym>; 2]>,
}

/// What a claim of the file asserts, in a form the audit can decide.
#[derive(Debug, Clone, PartialEq)]
pub enum Check {
    /// `Σ bᵢ = 1`.
    Unity,
    /// Every function ≥ 0 on the domain for the parameter range (the
    /// declared one unless given); `maximal`: the range is the maximal one.
    Nonnegative {
        range: Option<ParamRange>,
        maximal: bool,
        /// The functions decided, by index in the basis the claim is about
        /// (after its knots): all of them when empty.
        functions: Vec<usize>,
        /// `f ≥ margin` rather than `f ≥ 0` (a positive margin proves
        /// `f > 0`).
        margin: Option<Margin>,
    },
    /// Each listed function monotone on the domain for the range.
    Monotone {
        items: Vec<Monotone>,
        range: Option<ParamRange>,
    },
    /// `bᵢ(x; p) = b_{offset−i}(A − x; σ(p))`: the map `x ↦ A − x` printed
    /// in the variable, the parameters substituted by `σ` (exchange
    /// symmetry `λ ↔ μ`; the identity unless given); `at` gives parameter
    /// values for a numeric counterexample when the map is not the
    /// reflection of the domain.
    Symmetry {
        map_text: String,
        /// `A`.
        map: Affine,
        index_text: String,
        offset: i64,
        at: Vec<Rational>,
        /// `σ(p)` for each parameter, in order.
        params: Vec<Sym>,
        /// The printed substitution (`lambda = mu, mu = lambda`), empty
        /// for the identity.
        params_text: String,
    },
    /// Printed function values at one end.
    EndpointValues { end: End, values: Vec<Printed> },
    /// Printed derivatives at the ends of the domain, each of its own
    /// order and end (and parameters, where printed): of the functions, and
    /// of curves `Σ bᵢPᵢ` named with their control points as printed.
    EndpointDerivatives {
        wrt: Wrt,
        values: Vec<PrintedDerivative>,
        curves: Vec<NamedCurve>,
    },
    /// Printed derivative of the curve `Σ bᵢPᵢ` at one end, a combination
    /// of the control points (terminal tangents `r'(0) = 3(P1 − P0)`).
    CurveDerivative {
        end: End,
        order: usize,
        wrt: Wrt,
        text: String,
        value: Sym,
    },
    /// The curve `Σ bᵢPᵢ` at one end along a difference of two control
    /// points, `Q⁽ᵏ⁾(end) − [k = 0]·Pb = c·(Pa − Pb)`, with `c` of a stated
    /// sign on the range (`range`: the claim's; `None`: the declared) and
    /// optionally `c → 0` as the parameter tends to `limit` (`∞`, `−∞`).
    EndDirection {
        end: End,
        order: usize,
        wrt: Wrt,
        along: (usize, usize),
        positive: bool,
        range: Option<ParamRange>,
        limit: Option<String>,
    },
    /// Printed conditions making two segments `Σ bᵢPᵢ` (end) and
    /// `Σ bᵢQᵢ` (start) join: `Cᵏ`, `G¹` (`Q'(0) = αP'(1)`), `G²`; with
    /// `different`, the first segment has the parameters `p1`, the second
    /// `p2`. `factors` are the names of the `G` factors `α`, `β`.
    Join {
        kind: JoinKind,
        wrt: Wrt,
        /// The claim declares `wrt` (judged there alone); without it
        /// (`wrt = "unstated"`) a formula that holds in another convention
        /// holds after that correction.
        declared: bool,
        different: bool,
        factors: [String; 2],
        /// The printed `G` factors give the first segment's derivatives
        /// from the second's (`orientation = "reversed"`: `P' = αQ'`,
        /// `P'' = α²Q'' + βQ'`), not the second's from the first's.
        reversed: bool,
        conditions: Vec<Condition>,
        segments: JoinSegments,
    },
    /// Every join of the basis (each kind, same and different parameters)
    /// breaks exactly at printed parameter values: its pivots vanish there
    /// and nowhere else.
    JoinSingular {
        wrt: Wrt,
        /// Each segment's copies of the parameters (different parameters).
        copies: [Vec<Sym>; 2],
        /// The printed values `(parameter index, value)`.
        values: Vec<(usize, Sym)>,
    },
    /// Unity and nonnegativity on the range: the convex-hull property of
    /// every curve `Σ bᵢPᵢ` (the standard sufficient condition).
    ConvexHull {
        range: Option<ParamRange>,
        /// The range is the maximal one (with unity, the maximal
        /// nonnegativity set).
        maximal: bool,
    },
    /// The curve `Σ bᵢPᵢ` with the printed control points (coordinates may
    /// depend on the parameters) satisfies the printed implicit equation
    /// in `X`, `Y` identically (a circle `X² + Y² − 1`, an ellipse, a
    /// parabola).
    Conic {
        /// `(X, Y)` of each control point, in function order.
        points: Vec<(Sym, Sym)>,
        /// The points as printed.
        points_text: Vec<String>,
        equation: Sym,
        equation_text: String,
        /// Divisions of the printed points that vanish inside the ranges.
        singular: Vec<String>,
        /// For some or for no parameter value (`for = "some value"`,
        /// `"no value"`); for every value without it.
        quantifier: Option<Quantifier>,
    },
    /// The functions are linearly independent for every parameter value of
    /// the range (the declared ranges without one).
    Independent {
        range: Option<ParamRange>,
        /// Independent exactly there within the declared ranges (dependent
        /// at every declared value outside the range).
        maximal: bool,
    },
    /// As `parameter` increases (over `range`, the declared one unless
    /// given; the other parameters over their declared ranges) the curve
    /// moves in `direction`.
    ShapeEffect {
        /// One parameter, or several changed concurrently (`pᵢ = pᵢ₀ + τ`).
        parameters: Vec<String>,
        target: Target,
        /// Printed "as `p` increases (or decreases)": holds when one of
        /// the two directions holds.
        either: bool,
        range: Option<ParamRange>,
        /// Printed polygons, shown with their distance from the curve.
        polygons: Option<Polygons>,
    },
    /// The basis is normalized totally positive (hence variation
    /// diminishing) for every parameter value of the range (the declared
    /// one unless given).
    TotalPositivity {
        range: Option<ParamRange>,
        /// The range is the maximal set of total positivity.
        maximal: bool,
    },
    /// The uniform B-spline assembled from the `n` functions (piece `k` is
    /// function `n − 1 − k`), a curve of the basis, or the B-spline on a
    /// knot vector ([`Continuous`]) is `Cᵏ` at its knots.
    Continuity { order: usize, of: Continuous },
    /// Local control of that B-spline (segment `i` is `Σ b_k P_{i+k}`):
    /// the varied control enters exactly the printed segments `j + o`,
    /// `o ∈ segments`.
    LocalControl {
        varied: Varied,
        segments: Vec<i64>,
        /// Another reading of a parameter's scope (`also-scope`), decided
        /// too, for information.
        also: Option<Varied>,
        /// The index of segment 0's first control point (segment `i` is
        /// `Σ b_k P_{i+first+k}`).
        first: i64,
        /// The curve is rational (`weights = true`), `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`:
        /// the control point and its weight are decided.
        rational: Option<RationalCurve>,
    },
    /// Every listed claim of the file, each decided as it is stated: an
    /// umbrella over printed parts (a theorem whose conditions the file
    /// states one claim each).
    All {
        claims: Vec<String>,
        /// The parts are reported as claims of their own (`brief = true`):
        /// the umbrella shows each part's verdict, and the first witness of
        /// a part that does not hold, instead of every part's evidence.
        brief: bool,
    },
    /// What this copy of the document does not print (a lost formula, an
    /// unpublished data set): `not-checkable` with the reason, as data.
    NotPrinted { reason: String },
    /// The interpolant of a printed data table (a table file, `path` as
    /// written, relative to the claim's file) by an interpolation scheme of
    /// `trig-interp` stays `≥ 0` on its whole interval.
    InterpolantNonnegative {
        path: String,
        data: DataSet,
        scheme: Scheme,
    },
    /// The interpolant of a printed data table (as for
    /// [`Check::InterpolantNonnegative`]) is `C^order` at every interior
    /// knot: the jumps of its derivatives of orders `0…order` vanish.
    InterpolantContinuity {
        path: String,
        data: DataSet,
        scheme: Scheme,
        order: usize,
    },
    /// Printed error tables (a table file, `path` as written, relative to
    /// the claim's file; `text` as read) against their own arithmetic:
    /// totals, extremes and means of the segment rows, summaries against
    /// the tables they summarise, the best scheme against the summaries.
    TableArithmetic { path: String, text: String },
    /// The figures and statements in words a document's text quotes from
    /// printed error tables (a table file, `path`; `quotes_path` a quotes
    /// file of the statements in words, each with its reading; both as
    /// written, relative to the claim's file, and as read), recomputed.
    TableQuotes {
        path: String,
        text: String,
        quotes_path: String,
        quotes: String,
    },
    /// The readings a document's text makes between the printed error
    /// tables of different schemes (a table file, `path`; `quotes_path` a
    /// comparisons file, each statement with its kind; both as written,
    /// relative to the claim's file, and as read), recomputed.
    TableCompare {
        path: String,
        text: String,
        quotes_path: String,
        quotes: String,
    },
    /// The counts a document's text quotes from a printed table of rows (a
    /// row table file, `path`; `counts_path` a counts file of the quoted
    /// counts, each with its reading; both as written, relative to the
    /// claim's file, and as read), recomputed from the rows.
    TableCount {
        path: String,
        text: String,
        counts_path: String,
        counts: String,
    },
    /// Queries on the printed values of a data table (a table file, `path`
    /// as written, relative to the claim's file): a value at a knot, how
    /// many values equal a number.
    DataValues {
        path: String,
        data: DataSet,
        queries: Vec<crate::data_query::DataQuery>,
    },
    /// What a text says about the maximum of the interpolant of a printed
    /// data table (as for [`Check::InterpolantNonnegative`]): its value
    /// ("about 55"), its place ("near x = 4.5"), a drop after it.
    InterpolantMaximum {
        path: String,
        data: DataSet,
        scheme: Scheme,
        queries: Vec<crate::data_query::MaximumQuery>,
    },
    /// Tensor-product patches of the basis (in both directions) over the
    /// control nets a printed listing builds (a listing file, `path` as
    /// written, relative to the claim's file), `Cᵏ` across each seam.
    SurfaceJoin {
        path: String,
        kind: JoinKind,
        wrt: Wrt,
        nets: Vec<ListedNet>,
        seams: Vec<Seam>,
    },
    /// A tensor-product surface of the basis (in both directions) over the
    /// one net a listing file builds (`path` as written, relative to the
    /// claim's file), against the cylinder `x² + y² = radius²` about the
    /// `z` axis (a surface of revolution).
    Cylinder {
        path: String,
        net: ListedNet,
        radius: Rational,
    },
    /// At each value of `parameter`, the curve `Σ bᵢPᵢ` of each printed
    /// polygon leaves the polygon's convex hull and the tensor-product
    /// surface over the listing's net (`net`) leaves the net's bounding box:
    /// each shown by one exact point outside.
    LeavesHull {
        parameter: String,
        values: Vec<Rational>,
        polygons: Vec<Vec<(Rational, Rational)>>,
        net: Option<ListedNet>,
    },
    /// Each function has exactly one maximum on the domain ("each bᵢ has
    /// one maximum value").
    OneMaximum,
    /// Every function lies in the printed span of harmonics
    /// (`span = ["1", "sin(t)", "cos(2*t)"]`): each element as printed,
    /// with its value in the exact ring.
    FourierSpan { span: Vec<(String, Sym)> },
    /// The coefficients of a basis on a knot vector (`check =
    /// "knot-coefficients"`, [`crate::knots`]): the matrix `M` of the span
    /// (`F_i = Σ_k M_{ik} f_k`) against the printed one (`matrix`, row `i`
    /// the coefficients of `F_i`, each as printed with its exact value).
    KnotCoefficients {
        knots: crate::knots::Knots,
        matrix: Vec<Vec<(String, Sym)>>,
    },
    /// Printed identities in the functions of the basis applied at printed
    /// arguments (`b2(t) + b3(1 - t) = 1`, `b1'(1/3) = 0`), their
    /// derivatives in the variable, and curves `Σ bᵢPᵢ` (optionally
    /// rational, `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`, or of printed control points) under
    /// printed names: each decided exactly.
    Identity {
        identities: Vec<Identity>,
        curves: Vec<Curve>,
        /// Readings of garbled or mistyped prints, each decided beside the
        /// print it reads.
        readings: Vec<Reading>,
        /// The identities are in another variable (`change`).
        change: Option<Change>,
        /// The claim's `let` names with their values (in the variable, the
        /// parameters and the claim's symbols): symbols of the sides,
        /// substituted with the applications, and applied like functions.
        lets: Vec<Let>,
        /// The correction of a print that fails (`correction`).
        correction: Option<Correction>,
        /// Symbols the claim's conditions make positive (`positive`): a
        /// witness of a failure lies where they are positive.
        positive: Vec<String>,
    },
    /// The basis equals another basis (a spec file, `path` as written,
    /// relative to the claim's file) under a change of parameter — each of
    /// the other's parameters a printed formula in this basis's — and of
    /// the variable through the ring's atoms: `bᵢ = gᵢ` for every `i`.
    SameBasis {
        path: String,
        other: Box<crate::Spec>,
        /// `(other's parameter, formula in this basis's parameters)`, one
        /// for each of the other's parameters.
        params: Vec<(String, Sym)>,
        /// The substitution as printed (`λ = m`).
        params_text: String,
    },
    /// The curvature at the common start `P0` of rational curves
    /// `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ` over one polygon: each curve of the claim's
    /// basis (`curve` its printed name) at most that of the compared curves
    /// (other bases) — a necessary condition of "lies between the other
    /// curve and the polygon".
    EndCurvature {
        curve: String,
        polygon: Vec<(Rational, Rational)>,
        curves: Vec<WeightedCurve>,
    },
}

/// A rational curve `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ` of an end-curvature claim on the
/// polygon's first points (one per function).
#[derive(Debug, Clone, PartialEq)]
pub struct WeightedCurve {
    /// Short name (`quintic`, in `κ_quintic`); the label otherwise.
    pub name: String,
    /// How the report names it (`the quintic Bézier curve`).
    pub label: String,
    /// `None`: the claim's basis (a curve the claim is about); otherwise a
    /// compared basis, read from its spec file.
    pub basis: Option<Box<crate::Spec>>,
    /// One per function, exact.
    pub weights: Vec<Rational>,
}

/// A change of variable of printed identities (`change = { x = "(x - x_i)/h_i" }`):
/// the basis's variable is the printed formula `φ` in the new variable;
/// `f(ARG)` is `f(φ(ARG))` and each prime a derivative in the new variable.
#[derive(Debug, Clone, PartialEq)]
pub struct Change {
    /// The new variable.
    pub variable: String,
    /// `φ` as printed.
    pub text: String,
    /// `φ` in the new variable, the parameters and the claim's symbols.
    pub value: Sym,
}

/// A printed identity `lhs = rhs`: each side a formula in the variable,
/// the parameters, the control points and weights of the curve, and the
/// placeholder symbols of its [`Application`]s.
#[derive(Debug, Clone, PartialEq)]
pub struct Identity {
    /// As printed in the file.
    pub text: String,
    /// How the report names it: the text before `: ` when the file gives
    /// one (`"(A1): …"`), else the text.
    pub label: String,
    pub lhs: Sym,
    pub rhs: Sym,
    pub applications: Vec<Application>,
}

/// The correction of a print that fails (`correction = { says = "…",
/// identities = ["…"] }`): decided where the print fails; the claim still
/// fails (the print is wrong, not mistyped), with `says` as its correction
/// where every corrected identity holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Correction {
    pub says: String,
    pub identities: Vec<Identity>,
}

/// A reading of a printed identity (`readings = [{ of = "…", as = "…" }]`):
/// where the print fails and every failing print's reading holds, the
/// claim holds after the correction, shown as print → reading.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The index of the printed identity it reads.
    pub of: usize,
    pub identity: Identity,
}

/// `f^(order)(argument)` in a printed identity, standing for its
/// placeholder `symbol` in the sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Application {
    pub symbol: String,
    pub applied: Applied,
    /// Derivative order in the variable (the primes printed).
    pub order: usize,
    pub argument: Argument,
    /// The argument as printed.
    pub argument_text: String,
}

/// The argument of an [`Application`].
#[derive(Debug, Clone, PartialEq)]
pub enum Argument {
    /// `a·x + b`, linear in the basis's variable `x`.
    Linear(crate::formula::Linear),
    /// Under a [`Change`] of variable: a formula in the new variable, the
    /// parameters and the claim's symbols.
    Formula(Sym),
}

/// A name an identity claim defines (`let = ["S = zeta^2 - zeta + 1"]`).
#[derive(Debug, Clone, PartialEq)]
pub struct Let {
    pub name: String,
    /// The formula read, earlier names substituted.
    pub value: Sym,
}

/// What an [`Application`] applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Applied {
    /// The basis function of this index.
    Function(usize),
    /// The curve of the claim of this index.
    Curve(usize),
    /// The claim's `let` name of this index.
    Let(usize),
}

/// The curve a printed identity names: `Σ bᵢPᵢ` with control points
/// `P0, P1, …`, or with `weighted` the rational `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ` with
/// weights `w0, w1, …`; or with `points` the curve `Σ bᵢ·pointᵢ` of
/// printed control points (formulas in the parameters and free symbols).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub name: String,
    pub weighted: bool,
    /// The printed control points, one per function; `None`: the free
    /// `P0, P1, …`.
    pub points: Option<Vec<Sym>>,
    /// Under a claim's change of variable, the curve's own: the basis's
    /// variable as a formula in the new variable (a spline's next segment,
    /// `(x - x_i - h_i)/h_i1`); `None`: the claim's.
    pub change: Option<Sym>,
}

/// How a printed identity is quantified over the parameter values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantifier {
    /// "for some value of λ".
    Some,
    /// "for no value of λ".
    No,
}

/// The printed names of a rational local-control curve: the curve (`Z`)
/// and its control points (`H`; the weights are `w`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RationalCurve {
    pub curve: String,
    pub point: String,
}

/// What a local-control claim varies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Varied {
    /// The control point `P_j`.
    Point,
    /// The parameter `name`: one value per segment (`per_segment`, segment
    /// `j` has its own `name_j`) or one for the whole curve.
    Parameter { name: String, per_segment: bool },
}

/// A claim of the file.
#[derive(Debug, Clone, PartialEq)]
pub struct SpecClaim {
    pub id: String,
    pub source: String,
    pub statement: String,
    pub check: Check,
    /// Parameter values the claim fixes and ranges it narrows
    /// (`at = { lambda = "0" }`, `range = "[0, 0]"`,
    /// `ranges = { mu = "[0, 1]" }`): applied before deciding.
    pub given: Given,
    /// The paper states the check's negation ("is not C⁴", "is not
    /// totally positive"): the claim holds where the check fails.
    pub negated: bool,
    /// Remarks of the file shown after the evidence (`notes = […]`): how a
    /// print is read, what the document says beside the claim; they never
    /// change the verdict.
    pub notes: Vec<String>,
    /// A figure supporting the verdict (`[claims.figure]`).
    pub figure: Option<ClaimFigure>,
}

/// A figure supporting a claim's verdict: an SVG drawn by `trig-audit
/// plot`, with its data (`.csv`) and pgfplots code (`.tex`) beside it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ClaimFigure {
    /// Where the figure is: the claim's file's directory joined with the
    /// path written (`../../docs/figures/T7.svg`), not simplified.
    pub path: std::path::PathBuf,
    /// What it shows.
    pub caption: String,
    /// The arguments of `trig-audit plot` that draw it, without the output
    /// (`basis --family thesis-cubic --values=-2.5,0,1.5`).
    pub plot: String,
}

/// A parameter value fixed by a claim.
#[derive(Debug, Clone, PartialEq)]
pub struct Fixed {
    /// The parameter's ASCII name.
    pub name: String,
    /// The value as written (`0`, `sqrt(2)/2`, `pi/3`).
    pub text: String,
    /// Its exact value: a constant of the exact ring (rationals, `π`,
    /// radicals).
    pub value: Sym,
}

/// The parameter values and ranges a claim gives, in the file's terms.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Given {
    /// Values substituted before deciding.
    pub fixed: Vec<Fixed>,
    /// Ranges replacing the declared ones for this claim (by parameter
    /// name): the claim is about that box.
    pub ranges: Vec<(String, ParamRange)>,
    /// Ranges whose ends are linear in other parameters (a triangle
    /// `λ ∈ [0, 4]`, `μ ∈ [0, 4 − λ]`).
    pub between: Vec<Between>,
    /// Ranges with an end beyond the rationals (`[-1, 2 + 2*sqrt(2)]`):
    /// decided through rational ranges next to them and, at the end
    /// itself, exactly (`trig_judge::exact_ends`).
    pub exact: Vec<crate::ExactRange>,
    /// A knot vector and a span of it (`knots = { … }`): the basis's
    /// functions combined by a knot family's printed coefficients there
    /// ([`crate::knots`]).
    pub knots: Option<crate::knots::Knots>,
}

/// A parameter between two ends linear in the others: `μ ∈ [lo, hi]`.
/// Decided as `μ = lo + μ′·(hi − lo)` with a new parameter `μ′ ∈ [0, 1]`
/// (named `{name}_u`): a polynomial change of parameters whose image is
/// exactly the region, so every exact and certified judge keeps its
/// meaning, and a witness names `μ′`, from which `μ` is one line away.
#[derive(Debug, Clone, PartialEq)]
pub struct Between {
    pub name: String,
    /// The range as written (`[0, 4 - lambda]`).
    pub text: String,
    pub lo: Sym,
    pub hi: Sym,
}

/// What `check = "continuity"` examines at its knots.
#[derive(Debug, Clone, PartialEq)]
pub enum Continuous {
    /// The uniform B-spline assembled from the functions (unit spacing).
    Bspline,
    /// The uniform curve `Σ bᵢ P_{s+i}` (with `weights`, `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`)
    /// on the consecutive `segments` `s` (control points `point0, point1, …`
    /// as symbols), at the knots between them.
    Curve {
        point: String,
        weights: bool,
        segments: Vec<i64>,
    },
    /// The B-spline basis function `F_j`, `j` the knots' span, on the knot
    /// vector: piece `i` on `[n_{j+i}, n_{j+i+1})` is the segment function
    /// `n − 1 − i` of that span ([`crate::knots`]).
    Knots(crate::knots::Knots),
}
