//! Printed join formulas against the join conditions they claim to solve.
//!
//! A printed formula (e.g. thesis (4.7) `P₅ = [(m₂+2)P₃ − (m₁+2)P₃ − (m₂+2)P₂]/(m₁+2)`)
//! is stored as printed — its terms over its denominator — and substituted into
//! the conditions of its join kind ([`trig_deriv::JoinSetup::residuals`]); the
//! forced points it does not print take the values [`trig_deriv::solve_join`]
//! derives, so each claim is judged on its own formula. The verdict, in
//! order of preference:
//!
//! 1. holds in the paper's convention (derivatives in the angle θ);
//! 2. holds after flipping the sign of one printed term (a named sign typo);
//! 3. holds in another convention (`u`, or `x` with interval lengths `h₁`, `h₂`);
//! 4. fails, with the exact residual and the derived correct formula.
//!
//! A surface join in one direction of two tensor patches with the same
//! parameter across the boundary reduces column by column to the curve join:
//! `∂ᵏS₂(u, 0) − target = Σᵢ Bᵢ(u; m₁)·rᵢ,ₖ` where `rᵢ,ₖ` is the curve residual of
//! column `i`; [`audit_surface`] builds the columns symbolically and decides
//! the whole residual as an identity in `u` (the evidence shows one column's
//! residual, in the printed names).

use trig_core::Family;
use trig_deriv::{JoinKind, JoinSetup, Wrt, solve_join, vanishing};
use trig_symbolic::Sym;

use crate::evidence::{Evidence, Expr, Kind};
use crate::exact::{basis, sum};
use crate::status::Status;
use crate::verdict::Verdict;
use crate::witness;

/// How printed joins are decided, as the report states it.
pub const METHOD: &str = "printed formula substituted into the join conditions, residual decided exactly in the symbolic ring; conventions θ (angle), u (θ = πu/2), x (θ = π(x − x_i)/(2h_i), h₁ ≠ h₂)";

/// One printed control-point formula: `point = (Σ terms) / denominator`.
#[derive(Debug, Clone)]
pub struct Printed {
    /// Index of the point in the second segment.
    pub point: usize,
    pub terms: Vec<Sym>,
    pub denominator: Sym,
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
        }
    }

    fn value(&self) -> Sym {
        sum(&self.terms) / &self.denominator
    }

    /// The same formula with term `k`'s sign flipped.
    fn flipped(&self, k: usize) -> Printed {
        let mut terms = self.terms.clone();
        terms[k] = -terms[k].clone();
        Printed::over(self.point, terms, self.denominator.clone())
    }
}

/// A printed join of two segments of `family`.
#[derive(Debug, Clone)]
pub struct PrintedJoin {
    pub family: Family,
    pub kind: JoinKind,
    pub first_params: Vec<Sym>,
    pub second_params: Vec<Sym>,
    /// Control points of the first segment (symbols).
    pub first: Vec<Sym>,
    /// Control points of the second segment (symbols).
    pub second: Vec<Sym>,
    /// The printed formulas.
    pub printed: Vec<Printed>,
}

impl PrintedJoin {
    fn setup(&self, wrt: Wrt) -> JoinSetup<'_> {
        JoinSetup {
            basis: self.family,
            first_params: &self.first_params,
            second_params: &self.second_params,
            wrt,
            h: (Sym::var("h1"), Sym::var("h2")),
            factors: trig_deriv::default_factors(),
        }
    }

    fn names(&self) -> Vec<String> {
        self.first
            .iter()
            .chain(&self.second)
            .map(|p| p.to_string())
            .collect()
    }

    /// The second segment's points: printed formulas where printed, derived
    /// values for the other forced points, symbols for the free ones.
    fn second_points(&self, wrt: Wrt, printed: &[Printed]) -> Vec<Sym> {
        let setup = self.setup(wrt);
        let mut points = match solve_join(&setup, self.kind, &self.first, &self.second) {
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
        self.setup(wrt)
            .residuals(self.kind, &self.first, &self.second_points(wrt, printed))
    }

    /// The derived formulas for the printed points, in `wrt`: `(point,
    /// value, where singular)`, or why there is no solution.
    fn derived_points(&self, wrt: Wrt) -> Result<Vec<(usize, Sym, Vec<String>)>, String> {
        let setup = self.setup(wrt);
        match solve_join(&setup, self.kind, &self.first, &self.second) {
            Ok(join) => Ok(join
                .forced
                .iter()
                .filter(|f| self.printed.iter().any(|p| p.point == f.index))
                .map(|f| (f.index, f.value.clone(), vanishing(&f.pivot)))
                .collect()),
            Err(e) => Err(format!("no solution: {e}")),
        }
    }

    /// The derived formulas for the printed points, in `wrt`, as text (each
    /// coefficient factored), with the parameter values where they are
    /// singular.
    fn derived(&self, wrt: Wrt) -> String {
        let names = self.names();
        match self.derived_points(wrt) {
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
        let mut item = Evidence::new(Kind::Derived, "")
            .about(format!("derived ({})", convention(wrt)), Status::Holds);
        item.status = None;
        let points = match self.derived_points(wrt) {
            Ok(points) => points,
            Err(e) => {
                item.text = e;
                return item;
            }
        };
        let shown = self.second_points(wrt, printed);
        for (i, value, singular) in &points {
            let name = self.second[*i].to_unicode();
            item = item.with(name.clone(), Expr::combination(value, &names));
            if !singular.is_empty() {
                item.text = format!("singular where {}", singular.join(", "));
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

fn convention(wrt: Wrt) -> &'static str {
    match wrt {
        Wrt::Angle => "angle θ",
        Wrt::U => "u",
        Wrt::X => "x (h₁ ≠ h₂)",
        Wrt::Variable => "the basis variable",
    }
}

/// The residuals of one convention as an evidence item.
fn describe(wrt: Wrt, residuals: &[Sym], names: &[String]) -> Evidence {
    let nonzero: Vec<(usize, &Sym)> = residuals
        .iter()
        .enumerate()
        .filter(|(_, r)| !r.is_zero())
        .collect();
    if nonzero.is_empty() {
        return Evidence::new(Kind::Join, "every condition holds exactly")
            .about(convention(wrt), Status::Holds);
    }
    nonzero.into_iter().fold(
        Evidence::new(Kind::Join, "").about(convention(wrt), Status::Fails),
        |item, (k, r)| {
            item.with(
                format!("residual (left − right) of order {k}"),
                Expr::combination(r, names),
            )
        },
    )
}

/// True when the printed formulas of a curve join hold in the angle
/// convention (the column test of a surface join with the same `u`-basis
/// on both patches).
pub fn holds_in_angle(join: &PrintedJoin) -> bool {
    join.residuals(Wrt::Angle, &join.printed)
        .iter()
        .all(Sym::is_zero)
}

/// Decides a printed curve join.
pub fn audit(join: &PrintedJoin) -> Verdict {
    decide(join, |wrt, printed| {
        let r = join.residuals(wrt, printed);
        (r.clone(), r)
    })
}

/// Decides a printed surface join across the boundary `v = 1 | v = 0` of two
/// tensor patches `S = Σᵢ Σⱼ Bᵢ(u; u_param) Bⱼ(v; ·) Pᵢⱼ` with the same
/// `u_param` on both sides: each column `i` gets its own points `Pⱼ_i`, the
/// printed formulas apply column by column, and the cross-boundary residual
/// `Σᵢ Bᵢ(u)·rᵢ` must vanish identically in `u`.
pub fn audit_surface(join: &PrintedJoin, u_param: &Sym) -> Verdict {
    let b = basis(join.family);
    let u_basis: Vec<Sym> = b
        .iter()
        .map(|f| f.subs(join.family.info().params[0].name, u_param))
        .collect();
    decide(join, |wrt, printed| {
        let columns: Vec<Vec<Sym>> = (0..u_basis.len())
            .map(|i| {
                let column = rename_points(join, i);
                column.residuals(wrt, &rename_printed(join, printed, i))
            })
            .collect();
        let surface = (0..=join.kind.order())
            .map(|k| {
                sum(&columns
                    .iter()
                    .zip(&u_basis)
                    .map(|(r, bi)| bi.clone() * &r[k])
                    .collect::<Vec<_>>())
            })
            .collect();
        // shown: the residual of one column, in the printed names
        (surface, join.residuals(wrt, printed))
    })
}

/// Column `i`: every point `Pⱼ` renamed `Pⱼ_i`.
fn rename_points(join: &PrintedJoin, i: usize) -> PrintedJoin {
    let rename =
        |v: &[Sym]| -> Vec<Sym> { v.iter().map(|p| Sym::var(&format!("{p}_{i}"))).collect() };
    PrintedJoin {
        first: rename(&join.first),
        second: rename(&join.second),
        printed: Vec::new(),
        ..join.clone()
    }
}

fn rename_printed(join: &PrintedJoin, printed: &[Printed], i: usize) -> Vec<Printed> {
    let names = join.names();
    printed
        .iter()
        .map(|p| {
            let rename = |e: &Sym| {
                names.iter().fold(e.clone(), |acc, n| {
                    acc.subs(n, &Sym::var(&format!("{n}_{i}")))
                })
            };
            Printed::over(
                p.point,
                p.terms.iter().map(rename).collect(),
                p.denominator.clone(),
            )
        })
        .collect()
}

/// The verdict from a residual function `(convention, printed) ↦ (residuals
/// that decide, residuals shown as evidence)`.
fn decide(
    join: &PrintedJoin,
    residuals: impl Fn(Wrt, &[Printed]) -> (Vec<Sym>, Vec<Sym>),
) -> Verdict {
    let names = join.names();
    let holds = |r: &[Sym]| r.iter().all(Sym::is_zero);
    let mut evidence = Vec::new();
    let mut holding = Vec::new();
    for wrt in [Wrt::Angle, Wrt::U, Wrt::X] {
        let (r, shown) = residuals(wrt, &join.printed);
        if holds(&r) {
            holding.push(wrt);
        }
        evidence.push(describe(wrt, &shown, &names));
    }
    if holding.contains(&Wrt::Angle) {
        return Verdict::new(Status::Holds, METHOD, evidence);
    }
    evidence.push(join.derived_item(Wrt::Angle, &join.printed));
    if let Some(fix) = sign_fix(join, &residuals) {
        return Verdict::new(Status::HoldsAfterCorrection, METHOD, evidence).with_correction(fix);
    }
    if let Some(wrt) = holding.first() {
        let fix = format!(
            "read the derivatives with respect to {} instead of the angle θ",
            convention(*wrt)
        );
        return Verdict::new(Status::HoldsAfterCorrection, METHOD, evidence).with_correction(fix);
    }
    Verdict::new(Status::Fails, METHOD, evidence).with_correction(format!(
        "use the derived formula: {}",
        join.derived(Wrt::Angle)
    ))
}

/// The fewest sign flips — one term in one printed formula, else one term in
/// each of two formulas (a sign typo per formula, as when a formula reuses
/// an earlier one that has its own) — that make the printed formulas hold
/// in the angle convention, described. Pairs are screened on the shown
/// residual (for a surface, one column's: it vanishes exactly when every
/// column's does) and confirmed on the deciding one.
fn sign_fix(
    join: &PrintedJoin,
    residuals: &impl Fn(Wrt, &[Printed]) -> (Vec<Sym>, Vec<Sym>),
) -> Option<String> {
    let names = join.names();
    let flips: Vec<(usize, usize)> = join
        .printed
        .iter()
        .enumerate()
        .flat_map(|(i, p)| (0..p.terms.len()).map(move |k| (i, k)))
        .collect();
    let with = |chosen: &[(usize, usize)]| {
        let mut printed = join.printed.clone();
        for &(i, k) in chosen {
            printed[i] = printed[i].flipped(k);
        }
        printed
    };
    let zero = |r: &[Sym]| r.iter().all(Sym::is_zero);
    let singles = flips.iter().map(|f| vec![*f]);
    let pairs = flips.iter().enumerate().flat_map(|(a, f)| {
        flips[a + 1..]
            .iter()
            .filter(move |g| g.0 != f.0)
            .map(move |g| vec![*f, *g])
    });
    let found = singles.chain(pairs).find(|chosen| {
        let printed = with(chosen);
        let (r, shown) = residuals(Wrt::Angle, &printed);
        chosen.len() == 1 && zero(&r) || chosen.len() > 1 && zero(&shown) && zero(&r)
    })?;
    let terms: Vec<String> = found
        .iter()
        .map(|&(i, k)| {
            let p = &join.printed[i];
            format!(
                "the printed term {} in the formula for {}",
                p.terms[k].to_combination(&names),
                join.second[p.point].to_unicode()
            )
        })
        .collect();
    Some(format!("flip the sign of {}", terms.join(" and of ")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::symbols;

    fn bernstein_c1(printed: Vec<Sym>) -> PrintedJoin {
        PrintedJoin {
            family: Family::Bernstein3,
            kind: JoinKind::C(1),
            first_params: vec![],
            second_params: vec![],
            first: symbols("P", 4),
            second: (4..8).map(|i| Sym::var(&format!("P{i}"))).collect(),
            printed: vec![Printed::new(1, printed)],
        }
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
        assert!(wrong.evidence[0].contains("order 1"));
        // printed P₅ = 3P₃ − P₂ against 2P₃ − P₂: differ where P₃ ≠ 0
        let w = wrong.evidence[3].witness.as_ref().expect("a witness");
        assert_eq!(w.values[0].label, "printed P₅");
    }

    #[test]
    fn a_surface_join_is_decided_as_an_identity_in_u() {
        let p = symbols("P", 4);
        let join = PrintedJoin {
            family: Family::ThesisCubic,
            first_params: vec![Sym::var("m")],
            second_params: vec![Sym::var("m")],
            ..bernstein_c1(vec![Sym::int(2) * &p[3], -p[2].clone()])
        };
        assert_eq!(audit_surface(&join, &Sym::var("m")).status, Status::Holds);
        let wrong = PrintedJoin {
            printed: vec![Printed::new(1, vec![p[3].clone()])],
            ..join
        };
        let v = audit_surface(&wrong, &Sym::var("m"));
        assert_eq!(v.status, Status::Fails);
        assert!(
            v.evidence[0].contains("order 1 = (m + 2)·P₂"),
            "{:?}",
            v.evidence
        );
        let derived = v.evidence.iter().find(|e| e.kind == Kind::Derived).unwrap();
        assert!(derived.witness.is_some(), "{derived:?}");
    }
}
