//! The join judge: printed join formulas of any basis — catalog family or
//! spec file — against the join conditions they claim to solve.
//!
//! A printed formula (e.g. thesis (4.7) `P₅ = [(m₂+2)P₃ − (m₁+2)P₃ − (m₂+2)P₂]/(m₁+2)`)
//! is stored as printed — its terms over its denominator — and substituted into
//! the conditions of its join kind ([`trig_deriv::JoinSetup::residuals`]); the
//! forced points it does not print take the values [`trig_deriv::solve_join`]
//! derives, so each claim is judged on its own formula. The verdict, in
//! order of preference:
//!
//! 1. holds in the printed convention (the thesis: derivatives in the angle θ);
//! 2. holds after flipping the sign of one printed term (a named sign typo);
//! 3. holds in another convention of the basis (`u`, `x` with interval
//!    lengths `h₁`, `h₂`, the angle, the basis variable);
//! 4. fails, with the exact residual and the derived correct formula.
//!
//! A printed formula that divides by an expression vanishing inside the
//! printed ranges (stated with the claim) gives no join there: the claim
//! fails, whatever the residuals.
//!
//! A surface join in one direction of two tensor patches with the same
//! parameter across the boundary is the curve join of one column:
//! `∂ᵏS₂(u, 0) − target = Σᵢ Bᵢ(u)·rᵢ,ₖ`, where `rᵢ,ₖ` is the curve residual
//! `rₖ` with the column's own control points `Pⱼ,ᵢ` in place of the `Pⱼ`.
//! Write `rₖ = r⁰ₖ + r¹ₖ` (`r¹ₖ` the terms with a control point): the sum
//! is `r⁰ₖ·Σᵢ Bᵢ + Σᵢ Bᵢ·r¹ₖ(Pⱼ,ᵢ)`, whose parts have disjoint monomials
//! (no point, the points of column `i`), so it vanishes identically exactly
//! when `r⁰ₖ = 0` and every `Bᵢ·r¹ₖ = 0` — that is, when `rₖ = 0`: the `Bᵢ`
//! are linearly independent, so neither a `Bᵢ` nor their sum is zero, in
//! an integral domain. So [`audit`] decides a surface join too.

use std::ops::Range;

use trig_core::{Domain, Variable};
use trig_deriv::{
    EndDerivatives, JoinKind, JoinSetup, Wrt, rate, solve_join, solve_join_for, solve_join_with,
    vanishing,
};
use trig_symbolic::Sym;

use crate::domain::{describe_wrt, param_symbols};
use crate::exact::ExactBasis;
use crate::exact::{IDENTITY, sum, symbols};
use trig_verdict::evidence::{Evidence, Expr, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

/// How printed joins of the thesis basis are decided, as the report states
/// it (other bases name their own conventions, [`PrintedJoin::method`]).
pub const METHOD: &str = "printed formula substituted into the join conditions, residual decided exactly in the symbolic ring; conventions θ (angle), u (θ = πu/2), x (θ = π(x − x_i)/(2h_i), h₁ ≠ h₂)";

/// One printed control-point formula: `point = (Σ terms) / denominator`.
#[derive(Debug, Clone)]
pub struct Printed {
    /// Index of the point in the second segment.
    pub point: usize,
    pub terms: Vec<Sym>,
    pub denominator: Sym,
    /// Ranges of `terms` printed as one bracket (`α(P3 − P2)`), whose sign
    /// is one printed sign too.
    pub brackets: Vec<Range<usize>>,
    /// Where the printed formula divides by zero inside the printed
    /// ranges (stated with the claim): it gives no join there.
    pub singular: Vec<String>,
}

impl Printed {
    /// A formula with denominator 1.
    pub fn new(point: usize, terms: Vec<Sym>) -> Self {
        Printed::over(point, terms, Sym::one())
    }

    /// A formula with a denominator.
    pub fn over(point: usize, terms: Vec<Sym>, denominator: Sym) -> Self {
        Printed {
            point,
            terms,
            denominator,
            brackets: Vec::new(),
            singular: Vec::new(),
        }
    }

    /// The same formula with the printed brackets `brackets`.
    pub fn brackets(mut self, brackets: Vec<Range<usize>>) -> Self {
        self.brackets = brackets;
        self
    }

    /// The same formula, singular where stated.
    pub fn singular(mut self, singular: Vec<String>) -> Self {
        self.singular = singular;
        self
    }

    fn value(&self) -> Sym {
        sum(&self.terms) / &self.denominator
    }

    /// The printed signs: each term, then each bracket of several terms.
    fn signs(&self) -> impl Iterator<Item = Range<usize>> + '_ {
        (0..self.terms.len())
            .map(|k| k..k + 1)
            .chain(self.brackets.iter().filter(|r| r.len() > 1).cloned())
    }

    /// The same formula with the sign of the terms `k` flipped.
    fn flipped(&self, k: Range<usize>) -> Printed {
        let mut terms = self.terms.clone();
        for t in &mut terms[k] {
            *t = -t.clone();
        }
        Printed {
            terms,
            ..self.clone()
        }
    }
}

/// A printed join of two segments of one basis.
#[derive(Debug, Clone)]
pub struct PrintedJoin<B> {
    pub basis: B,
    pub kind: JoinKind,
    pub first_params: Vec<Sym>,
    pub second_params: Vec<Sym>,
    /// Control points of the first segment (symbols).
    pub first: Vec<Sym>,
    /// Control points of the second segment (symbols).
    pub second: Vec<Sym>,
    /// The printed formulas.
    pub printed: Vec<Printed>,
    /// The symbols of the `G¹`/`G²` factors.
    pub factors: [Sym; 2],
    /// The conventions tried, the printed one first ([`conventions`]).
    pub conventions: Vec<Wrt>,
    /// The printed convention is the one the claim declares (a spec's
    /// `wrt`): the claim is judged in it alone, the others are shown for
    /// information. Without it (a document that does not say), a formula
    /// that holds in another convention holds after that correction.
    pub declared: bool,
    /// Lines stated before the evidence (the printed conditions, which
    /// parameters each segment has).
    pub notes: Vec<String>,
}

/// [`EndDerivatives`] of one join in each of its conventions.
struct Ends(Vec<(Wrt, EndDerivatives)>);

impl Ends {
    fn of(&self, wrt: Wrt) -> &EndDerivatives {
        self.0
            .iter()
            .find(|(w, _)| *w == wrt)
            .map(|(_, d)| d)
            .expect("the derivatives of every convention the join is decided in")
    }
}

/// The distinct derivative conventions of `basis`, `printed` first: the
/// angle, `u`, the data abscissa `x` and the basis variable, each kept
/// when its rate differs from every earlier one's.
pub fn conventions(basis: &impl ExactBasis, printed: Wrt) -> Vec<Wrt> {
    let params: Vec<Sym> = basis.param_names().iter().map(|p| Sym::var(p)).collect();
    let h = Sym::var("h");
    let mut out: Vec<(Wrt, Sym)> = Vec::new();
    for wrt in [printed, Wrt::Angle, Wrt::U, Wrt::X, Wrt::Variable] {
        let r = rate(basis, wrt, &h, &params);
        if out.iter().all(|(_, q)| !(q.clone() - &r).is_zero()) {
            out.push((wrt, r));
        }
    }
    out.into_iter().map(|(w, _)| w).collect()
}

impl<B: ExactBasis + Clone> PrintedJoin<B> {
    /// A printed join in the basis's conventions, the angle first, with the
    /// `G` factors named apart from the parameters.
    pub fn new(
        basis: B,
        kind: JoinKind,
        params: (Vec<Sym>, Vec<Sym>),
        points: (Vec<Sym>, Vec<Sym>),
        printed: Vec<Printed>,
    ) -> Self {
        let conventions = conventions(&basis, Wrt::Angle);
        let factors = trig_deriv::factor_names(&basis.param_names()).map(|n| Sym::var(&n));
        PrintedJoin {
            basis,
            kind,
            first_params: params.0,
            second_params: params.1,
            first: points.0,
            second: points.1,
            printed,
            factors,
            conventions,
            declared: false,
            notes: Vec::new(),
        }
    }

    fn setup(&self, wrt: Wrt) -> JoinSetup<'_, &B> {
        JoinSetup {
            basis: &self.basis,
            first_params: &self.first_params,
            second_params: &self.second_params,
            wrt,
            h: (Sym::var("h1"), Sym::var("h2")),
            factors: self.factors.clone(),
        }
    }

    /// The printed convention.
    fn printed_wrt(&self) -> Wrt {
        self.conventions[0]
    }

    /// The printed convention as the evidence names it (`the angle θ`).
    pub fn convention(&self) -> String {
        the(&label(&self.basis.domain(), self.printed_wrt()))
    }

    /// How the verdict is decided, as the report states it.
    pub fn method(&self) -> String {
        if self.basis.variable() == Some(Variable::UnitAngle) {
            return METHOD.into();
        }
        let domain = self.basis.domain();
        let labels: Vec<String> = self
            .conventions
            .iter()
            .map(|w| label(&domain, *w))
            .collect();
        format!(
            "printed formula substituted into the join conditions, residual decided exactly in the symbolic ring; conventions {}",
            labels.join("; ")
        )
    }

    fn names(&self) -> Vec<String> {
        self.first
            .iter()
            .chain(&self.second)
            .map(|p| p.to_string())
            .collect()
    }

    /// The basis's derivatives at the join in every convention, computed
    /// once for a decision (they do not depend on the control points).
    fn ends(&self) -> Ends {
        Ends(
            self.conventions
                .iter()
                .map(|w| (*w, self.setup(*w).end_derivatives()))
                .collect(),
        )
    }

    /// The second segment's points: printed formulas where printed, derived
    /// values for the other forced points, symbols for the free ones.
    fn second_points(&self, wrt: Wrt, printed: &[Printed]) -> Vec<Sym> {
        self.second_points_with(&self.setup(wrt).end_derivatives(), wrt, printed)
    }

    fn second_points_with(&self, ends: &EndDerivatives, wrt: Wrt, printed: &[Printed]) -> Vec<Sym> {
        let setup = self.setup(wrt);
        let mut points =
            match solve_join_with(&setup, ends, self.kind, &self.first, &self.second, &[]) {
                Ok(join) => join.second_points(&self.second),
                Err(_) => self.second.clone(),
            };
        for p in printed {
            points[p.point] = p.value();
        }
        // a printed formula may use an earlier point of its own segment (P6 in P5)
        for j in 0..points.len() {
            let (earlier, later) = points.split_at_mut(j);
            for (i, value) in earlier.iter().enumerate() {
                later[0] = later[0].subs(&self.second[i].to_string(), value);
            }
        }
        points
    }

    /// The residuals (orders `0…k`) of the printed formulas in `wrt`.
    fn residuals(&self, wrt: Wrt, printed: &[Printed]) -> Vec<Sym> {
        self.residuals_in(
            &Ends(vec![(wrt, self.setup(wrt).end_derivatives())]),
            wrt,
            printed,
        )
    }

    /// [`PrintedJoin::residuals`] with the derivatives of [`PrintedJoin::ends`].
    fn residuals_in(&self, ends: &Ends, wrt: Wrt, printed: &[Printed]) -> Vec<Sym> {
        let ends = ends.of(wrt);
        let second = self.second_points_with(ends, wrt, printed);
        self.setup(wrt)
            .residuals_with(ends, self.kind, &self.first, &second)
    }

    /// The derived formulas for the printed points, in `wrt` — for every
    /// forced point when a printed point is not one of them (the print
    /// names the wrong point) — `(point, value, where singular)`, or why
    /// there is no solution.
    fn derived_points(&self, wrt: Wrt) -> Result<Vec<(usize, Sym, Vec<String>)>, String> {
        let printed: Vec<usize> = self.printed.iter().map(|p| p.point).collect();
        self.forced_points(wrt, &printed, false)
    }

    /// The points the join forces in `wrt`, each condition solved for a
    /// point of `prefer` where it can be (the last first): those of
    /// `prefer` only, unless `all` or one of them is not forced.
    fn forced_points(
        &self,
        wrt: Wrt,
        prefer: &[usize],
        all: bool,
    ) -> Result<Vec<(usize, Sym, Vec<String>)>, String> {
        let setup = self.setup(wrt);
        let mut order = prefer.to_vec();
        order.sort_unstable_by(|a, b| b.cmp(a));
        match solve_join_for(&setup, self.kind, &self.first, &self.second, &order) {
            Ok(join) => {
                let forced = |i: usize| join.forced.iter().any(|f| f.index == i);
                let all = all || prefer.is_empty() || prefer.iter().any(|p| !forced(*p));
                Ok(join
                    .forced
                    .iter()
                    .filter(|f| all || prefer.contains(&f.index))
                    .map(|f| (f.index, f.value.clone(), vanishing(&f.pivot)))
                    .collect())
            }
            Err(e) => Err(format!("no solution: {e}")),
        }
    }

    /// The derived formulas in the printed convention, as text (each
    /// coefficient factored), with the parameter values where they are
    /// singular: of the printed points, or of every forced point when
    /// nothing is printed.
    pub fn derived_text(&self) -> String {
        self.derived(self.printed_wrt())
    }

    /// Every forced point's derived formula in the printed convention,
    /// each condition solved for a point of `points` where it can be (the
    /// points a paper prints), as text.
    pub fn derived_for(&self, points: &[usize]) -> String {
        self.show(self.forced_points(self.printed_wrt(), points, true))
    }

    /// The derived formulas for the printed points, in `wrt`, as text (each
    /// coefficient factored), with the parameter values where they are
    /// singular.
    fn derived(&self, wrt: Wrt) -> String {
        self.show(self.derived_points(wrt))
    }

    /// Derived points as text.
    fn show(&self, points: Result<Vec<(usize, Sym, Vec<String>)>, String>) -> String {
        let names = self.names();
        match points {
            Ok(points) => points
                .iter()
                .map(|(i, value, singular)| {
                    let note = if singular.is_empty() {
                        String::new()
                    } else {
                        format!(" (singular where {})", singular.join(", "))
                    };
                    format!(
                        "{} = {}{note}",
                        self.second[*i].to_unicode(),
                        Expr::combination(value, &names).best_unicode()
                    )
                })
                .collect::<Vec<_>>()
                .join("; "),
            Err(e) => e,
        }
    }

    /// The derived formulas as an evidence item, with a witness where a
    /// printed point differs from the derived one: control points and
    /// parameters at which both are evaluated exactly.
    fn derived_item(&self, wrt: Wrt, printed: &[Printed]) -> Evidence {
        let names = self.names();
        let mut item = Evidence::new(Kind::Derived, "").about(
            format!("derived ({})", label(&self.basis.domain(), wrt)),
            Status::Holds,
        );
        item.status = None;
        let points = match self.derived_points(wrt) {
            Ok(points) => points,
            Err(e) => {
                item.text = e;
                return item;
            }
        };
        let shown = self.second_points(wrt, printed);
        // every forced point's singular values, in order, each once (the
        // last point's alone would drop the earlier pivots: P₆ of a C²
        // join beside P₅'s division)
        let mut all_singular: Vec<&String> = Vec::new();
        for (i, value, singular) in &points {
            let name = self.second[*i].to_unicode();
            item = item.with(name.clone(), Expr::combination(value, &names));
            for s in singular {
                if !all_singular.contains(&s) {
                    all_singular.push(s);
                }
            }
            if !all_singular.is_empty() {
                let all: Vec<&str> = all_singular.iter().map(|s| s.as_str()).collect();
                item.text = format!("singular where {}", all.join(", "));
            }
            if item.witness.is_none() && !(shown[*i].clone() - value).is_zero() {
                item.witness = witness::find(
                    &shown[*i],
                    value,
                    (&format!("printed {name}"), &format!("derived {name}")),
                );
            }
        }
        item
    }
}

/// A convention as the evidence names it: the thesis's short names for
/// the catalog's variables (`angle θ`, `u`, `x (h₁ ≠ h₂)`; `t` for a
/// polynomial variable), the full statement for any other domain.
fn label(domain: &Domain, wrt: Wrt) -> String {
    let names: Vec<&str> = domain.param_names.iter().map(String::as_str).collect();
    let legacy = [Variable::UnitAngle, Variable::Angle, Variable::Polynomial]
        .into_iter()
        .find(|v| Domain::from_variable(*v, &names) == *domain);
    match (legacy, wrt) {
        (None, Wrt::X) => format!("{} (h₁ ≠ h₂)", wrt.describe_on(domain)),
        (None, _) => wrt.describe_on(domain),
        (Some(_), Wrt::X) => "x (h₁ ≠ h₂)".into(),
        (Some(Variable::Polynomial), _) => "t".into(),
        (Some(_), Wrt::Angle) => "angle θ".into(),
        (Some(_), Wrt::U) => "u".into(),
        (Some(_), Wrt::Variable) => "the basis variable".into(),
    }
}

/// The residuals of one convention as an evidence item.
fn describe(label: String, residuals: &[Sym], names: &[String]) -> Evidence {
    let nonzero: Vec<(usize, &Sym)> = residuals
        .iter()
        .enumerate()
        .filter(|(_, r)| !r.is_zero())
        .collect();
    if nonzero.is_empty() {
        return Evidence::new(Kind::Join, "every condition holds exactly")
            .about(label, Status::Holds);
    }
    nonzero.into_iter().fold(
        Evidence::new(Kind::Join, "").about(label, Status::Fails),
        |item, (k, r)| {
            item.with(
                format!("residual of the order-{k} condition"),
                Expr::combination(r, names),
            )
        },
    )
}

/// An item of a convention the claim does not declare, for information:
/// no status, prefixed with what it is.
fn information(mut item: Evidence, declared: &str) -> Evidence {
    let convention = item.subject.take().unwrap_or_default();
    let outcome = match item.status.take() {
        Some(Status::Holds) => "would hold",
        _ => "would not hold",
    };
    item.kind = Kind::Note;
    item.text = format!(
        "for information, not a verdict (the claim declares {declared}): with derivatives in {convention} the printed formulas {outcome}{}",
        if item.text.is_empty() || item.exprs.is_empty() {
            String::new()
        } else {
            format!("; {}", item.text)
        }
    );
    item
}

/// True when the printed formulas of a curve join hold in the printed
/// convention (the column test of a surface join with the same `u`-basis
/// on both patches).
pub fn holds_as_printed<B: ExactBasis + Clone>(join: &PrintedJoin<B>) -> bool {
    join.residuals(join.printed_wrt(), &join.printed)
        .iter()
        .all(Sym::is_zero)
}

/// Decides a printed curve join, or a surface join by one column (see the
/// [module documentation](self)).
pub fn audit<B: ExactBasis + Clone>(join: &PrintedJoin<B>) -> Verdict {
    let ends = join.ends();
    decide(join, &|wrt, printed| join.residuals_in(&ends, wrt, printed))
}

/// A residual function `(convention, printed) ↦ residuals`.
type ResidualFn<'a> = &'a dyn Fn(Wrt, &[Printed]) -> Vec<Sym>;

/// The verdict from the join's residuals.
fn decide<B: ExactBasis + Clone>(join: &PrintedJoin<B>, residuals: ResidualFn<'_>) -> Verdict {
    let verdict = decide_residuals(join, residuals);
    let singular: Vec<String> = join
        .printed
        .iter()
        .flat_map(|p| p.singular.iter().cloned())
        .collect();
    let mut v = if singular.is_empty() {
        verdict
    } else {
        exceptional(join, verdict, &singular)
    };
    v.evidence.prepend(join.notes.clone());
    v
}

/// A verdict whose printed formulas divide by zero inside the printed
/// ranges (at `singular`). Formulas that hold identically equal the derived
/// ones as rational functions: where the derived formulas are singular too,
/// no join of general control points exists there and the claim `holds`
/// with those exceptional values named; where only the print divides by
/// zero, it holds after excluding them from the ranges. A claim that fails
/// (or holds after another correction) keeps its status, the poles named.
fn exceptional<B: ExactBasis + Clone>(
    join: &PrintedJoin<B>,
    mut v: Verdict,
    singular: &[String],
) -> Verdict {
    let poles = singular.join("; ");
    if v.status != Status::Holds {
        v.evidence.push(format!(
            "the printed formulas are singular inside the printed ranges, where they give no join: {poles}"
        ));
        return v;
    }
    let derived: Vec<String> = join
        .derived_points(join.printed_wrt())
        .unwrap_or_default()
        .into_iter()
        .flat_map(|(_, _, s)| s)
        .collect();
    if derived.is_empty() {
        v.evidence.push(format!(
            "the printed formulas are singular inside the printed ranges, where the derived ones are not: {poles}"
        ));
        v.status = Status::HoldsAfterCorrection;
        return v.with_correction(format!(
            "the printed formulas hold wherever they are defined; exclude the poles {poles} from the printed ranges (or cancel the vanishing factor)"
        ));
    }
    v.evidence.push(format!(
        "exceptional values: the printed formulas hold wherever they are defined; they divide by zero inside the printed ranges at {poles}, where the derived formulas are singular too ({}): no {} join of general control points exists there",
        derived.join("; "),
        join.kind
    ));
    v
}

fn decide_residuals<B: ExactBasis + Clone>(
    join: &PrintedJoin<B>,
    residuals: ResidualFn<'_>,
) -> Verdict {
    let names = join.names();
    let domain = join.basis.domain();
    let method = join.method();
    let holds = |r: &[Sym]| r.iter().all(Sym::is_zero);
    let mut evidence = Vec::new();
    let mut holding = Vec::new();
    let printed_wrt = join.printed_wrt();
    for wrt in &join.conventions {
        let r = residuals(*wrt, &join.printed);
        if holds(&r) {
            holding.push(*wrt);
        }
        let item = describe(label(&domain, *wrt), &r, &names);
        evidence.push(if join.declared && *wrt != printed_wrt {
            information(item, &label(&domain, printed_wrt))
        } else {
            item
        });
    }
    if join.declared {
        holding.retain(|w| *w == printed_wrt);
    }
    if holding.contains(&printed_wrt) {
        return Verdict::new(Status::Holds, method, evidence);
    }
    evidence.push(join.derived_item(printed_wrt, &join.printed));
    if let Some(fix) = sign_fix(join, residuals) {
        return Verdict::new(Status::HoldsAfterCorrection, method, evidence).with_correction(fix);
    }
    if let Some(wrt) = holding.first() {
        let fix = format!(
            "read the derivatives with respect to {} instead of {}",
            label(&domain, *wrt),
            the(&label(&domain, printed_wrt))
        );
        return Verdict::new(Status::HoldsAfterCorrection, method, evidence).with_correction(fix);
    }
    Verdict::new(Status::Fails, method, evidence).with_correction(format!(
        "use the derived formula: {}",
        join.derived(printed_wrt)
    ))
}

/// `the angle θ` for the short label `angle θ`; other labels as they are.
fn the(label: &str) -> String {
    if label == "angle θ" {
        "the angle θ".into()
    } else {
        label.into()
    }
}

/// The fewest sign flips — one term in one printed formula, else one term in
/// each of two formulas (a sign typo per formula, as when a formula reuses
/// an earlier one that has its own) — that make the printed formulas hold
/// in the printed convention, described.
fn sign_fix<B: ExactBasis + Clone>(
    join: &PrintedJoin<B>,
    residuals: ResidualFn<'_>,
) -> Option<String> {
    let names = join.names();
    let wrt = join.printed_wrt();
    let flips: Vec<(usize, Range<usize>)> = join
        .printed
        .iter()
        .enumerate()
        .flat_map(|(i, p)| p.signs().map(move |k| (i, k)))
        .collect();
    let with = |chosen: &[(usize, Range<usize>)]| {
        let mut printed = join.printed.clone();
        for (i, k) in chosen {
            printed[*i] = printed[*i].flipped(k.clone());
        }
        printed
    };
    let zero = |r: &[Sym]| r.iter().all(Sym::is_zero);
    let singles = flips.iter().map(|f| vec![f.clone()]);
    let pairs = flips.iter().enumerate().flat_map(|(a, f)| {
        flips[a + 1..]
            .iter()
            .filter(move |g| g.0 != f.0)
            .map(move |g| vec![f.clone(), g.clone()])
    });
    let found = singles
        .chain(pairs)
        .find(|chosen| zero(&residuals(wrt, &with(chosen))))?;
    let terms: Vec<String> = found
        .iter()
        .map(|(i, k)| {
            let p = &join.printed[*i];
            format!(
                "the printed term {} in the formula for {}",
                sum(&p.terms[k.clone()]).to_combination(&names),
                join.second[p.point].to_unicode()
            )
        })
        .collect();
    Some(format!("flip the sign of {}", terms.join(" and of ")))
}

/// The control points the join forces, as printed lines (with where each
/// formula is singular).
fn forced_lines<B: ExactBasis>(
    basis: &B,
    s: &JoinSetup<'_, &B>,
    kind: JoinKind,
) -> Result<Vec<Evidence>, String> {
    let n = basis.function_names().len();
    let (p, q) = (symbols("P", n), symbols("Q", n));
    let points: Vec<String> = p.iter().map(ToString::to_string).collect();
    let join = solve_join(s, kind, &p, &q).map_err(|e| e.to_string())?;
    Ok(join
        .forced
        .iter()
        .flat_map(|f| {
            let name = Sym::var(&format!("Q{}", f.index)).to_unicode();
            let singular = vanishing(&f.pivot);
            let note = (!singular.is_empty()).then(|| {
                Evidence::note(format!("{name} is singular where {}", singular.join(", ")))
            });
            std::iter::once(
                Evidence::new(Kind::Derived, "").with(name, Expr::combination(&f.value, &points)),
            )
            .chain(note)
        })
        .collect())
}

/// The standard battery's `Cᵏ` join: the second segment's points forced by
/// the join (solved exactly). Holds when every order can be met.
pub fn derived_join<B: ExactBasis>(basis: &B, order: usize) -> Verdict {
    let p = param_symbols(basis);
    let wrt = if basis.variable().is_some() {
        Wrt::Angle
    } else {
        Wrt::Variable
    };
    let s = JoinSetup {
        basis,
        first_params: &p,
        second_params: &p,
        wrt,
        h: (Sym::one(), Sym::one()),
        factors: trig_deriv::default_factors(),
    };
    let head = format!(
        "conditions Q^(k)(start) = P^(k)(end), k ≤ {order}, {}, solved exactly for the second segment's control points",
        describe_wrt(basis, wrt)
    );
    match forced_lines(basis, &s, JoinKind::C(order as u8)) {
        Ok(lines) => {
            let mut evidence = vec![Evidence::note(head)];
            evidence.extend(lines);
            Verdict::new(Status::Holds, IDENTITY, evidence)
        }
        Err(why) => Verdict::new(
            Status::Fails,
            IDENTITY,
            vec![head, format!("a C{order} join cannot be met: {why}")],
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::symbols;
    use trig_core::Family;

    fn bernstein_c1(printed: Vec<Sym>) -> PrintedJoin<Family> {
        PrintedJoin::new(
            Family::Bernstein3,
            JoinKind::C(1),
            (vec![], vec![]),
            (
                symbols("P", 4),
                (4..8).map(|i| Sym::var(&format!("P{i}"))).collect(),
            ),
            vec![Printed::new(1, printed)],
        )
    }

    #[test]
    fn a_true_join_holds_a_sign_typo_is_named_a_wrong_one_fails() {
        let p = symbols("P", 4);
        let two = Sym::int(2);
        let ok = audit(&bernstein_c1(vec![two.clone() * &p[3], -p[2].clone()]));
        assert_eq!(ok.status, Status::Holds);
        let typo = audit(&bernstein_c1(vec![two.clone() * &p[3], p[2].clone()]));
        assert_eq!(typo.status, Status::HoldsAfterCorrection);
        assert!(typo.correction.unwrap().contains("P₂"));
        let wrong = audit(&bernstein_c1(vec![Sym::int(3) * &p[3], -p[2].clone()]));
        assert_eq!(wrong.status, Status::Fails);
        assert!(wrong.evidence[0].contains("order-1 condition"));
        // printed P₅ = 3P₃ − P₂ against 2P₃ − P₂: differ where P₃ ≠ 0 (the
        // conventions of a polynomial basis: t and x, then the derivation)
        let w = wrong.evidence[2].witness.as_ref().expect("a witness");
        assert_eq!(w.values[0].label, "printed P₅");
    }

    #[test]
    fn a_join_is_decided_by_its_residuals() {
        let p = symbols("P", 4);
        let join = PrintedJoin::new(
            Family::ThesisCubic,
            JoinKind::C(1),
            (vec![Sym::var("m")], vec![Sym::var("m")]),
            (
                symbols("P", 4),
                (4..8).map(|i| Sym::var(&format!("P{i}"))).collect(),
            ),
            vec![Printed::new(1, vec![Sym::int(2) * &p[3], -p[2].clone()])],
        );
        assert_eq!(audit(&join).status, Status::Holds);
        let wrong = PrintedJoin {
            printed: vec![Printed::new(1, vec![p[3].clone()])],
            ..join
        };
        let v = audit(&wrong);
        assert_eq!(v.status, Status::Fails);
        assert!(
            v.evidence[0].contains("order-1 condition = (m + 2)·P₂"),
            "{:?}",
            v.evidence
        );
        let derived = v.evidence.iter().find(|e| e.kind == Kind::Derived).unwrap();
        assert!(derived.witness.is_some(), "{derived:?}");
    }

    /// The derived item of a C² join names the singular values of every
    /// forced point, not the last one's alone: the generalized Bernstein
    /// basis of degree 3 (`examples/gb3-three-shape.toml`) forces `P₅` with
    /// the pivot `3 + v₁` and `P₆` with `2(3 + v₂)` (second segment `v`).
    #[test]
    fn the_derived_item_names_every_forced_points_singular_values() {
        let text = "id = \"gb3\"\ncitation = \"test\"\nvariable = \"t\"\ndomain = \"[0, 1]\"\n\
            [[parameters]]\nname = \"l1\"\nrange = \"[-3, 1]\"\n\
            [[parameters]]\nname = \"l2\"\nrange = \"[-3, 3]\"\n\
            [[parameters]]\nname = \"l3\"\nrange = \"[-3, 1]\"\n\
            [[functions]]\nname = \"b0\"\nformula = \"(1 - t)^3*(1 - l1*t)\"\n\
            [[functions]]\nname = \"b1\"\nformula = \"t*(1 - t)^2*(3 + l1 - l1*t - l2*t)\"\n\
            [[functions]]\nname = \"b2\"\nformula = \"t^2*(1 - t)*(3 + l2 - l2*t + l3*t)\"\n\
            [[functions]]\nname = \"b3\"\nformula = \"t^3*(1 - l3 + l3*t)\"\n";
        let spec = trig_specfile::Spec::from_str_named(text, "gb3.toml").expect("spec");
        let p = symbols("P", 4);
        let vars = |names: [&str; 3]| names.iter().map(|n| Sym::var(n)).collect::<Vec<_>>();
        let join = PrintedJoin::new(
            spec,
            JoinKind::C(2),
            (vars(["u1", "u2", "u3"]), vars(["v1", "v2", "v3"])),
            (
                symbols("P", 4),
                (4..8).map(|i| Sym::var(&format!("P{i}"))).collect(),
            ),
            // the Bézier rules P₅ = 2P₃ − P₂, P₆ = P₁ − 4P₂ + 4P₃: wrong here
            vec![
                Printed::new(1, vec![Sym::int(2) * &p[3], -p[2].clone()]),
                Printed::new(
                    2,
                    vec![p[1].clone(), Sym::int(-4) * &p[2], Sym::int(4) * &p[3]],
                ),
            ],
        );
        let v = audit(&join);
        assert_eq!(v.status, Status::Fails);
        let derived = v.evidence.iter().find(|e| e.kind == Kind::Derived).unwrap();
        assert!(
            derived.text.contains("v₁ = −3") && derived.text.contains("v₂ = −3"),
            "{derived:?}"
        );
    }
}
