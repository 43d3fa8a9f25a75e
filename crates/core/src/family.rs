//! The catalog: every family with its id, citation, variable, parameters and
//! one generic evaluation.

use rug::Rational;

use crate::basis::{Basis, Described};
use crate::domain::{Affine, Domain};
use crate::error::{CoreError, Result};
use crate::families::{reference, seed000, seed002, seed004, thesis};
use crate::param::{Bound, ParamSpec, Parameter, Range, read_params};
use crate::scalar::{Real, Ring};
use crate::variable::{Atoms, Variable};

/// A family of basis functions of the catalog.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    ThesisQuadratic,
    ThesisCubic,
    Han,
    MajeedQayyum,
    Usman,
    HanListing,
    Seed000Blending,
    Seed000Uniform,
    Seed002Quartic,
    Eh,
    Hermite,
    Bernstein3,
    BSpline3,
    /// Catalogued without formulas (they are missing from our copy).
    Seed003,
}

/// A family's formula: the `N` functions at the atoms `s = sin θ`,
/// `c = cos θ`, `t` and the parameters (see [`Family::with_formula`]).
pub trait Formula<T, const N: usize>: Fn(&T, &T, &T, &[T]) -> [T; N] {}

impl<T, const N: usize, F: Fn(&T, &T, &T, &[T]) -> [T; N]> Formula<T, N> for F {}

/// Receives a family's formula, whatever its number of functions
/// ([`Family::with_formula`]).
pub trait FormulaVisitor<T> {
    /// What the visitor makes of the formula.
    type Output;

    /// Uses `formula`.
    fn visit<const N: usize>(self, formula: impl Formula<T, N>) -> Self::Output;
}

/// Static description of a family.
#[derive(Debug, Clone, Copy)]
pub struct FamilyInfo {
    /// Stable id used on the command line and in reports.
    pub id: &'static str,
    /// One-line title.
    pub title: &'static str,
    /// Source: seed file and equation.
    pub citation: &'static str,
    /// The native variable.
    pub variable: Variable,
    /// Shape parameters with their published ranges.
    pub params: &'static [ParamSpec],
    /// Names of the functions, in order.
    pub functions: &'static [&'static str],
    /// True when the uniform B-spline basis function is assembled from these
    /// segment functions (piece `k` is function `3 − k`).
    pub piecewise: bool,
}

const M: ParamSpec = ParamSpec {
    name: "m",
    symbol: "m",
    range: Range::closed((-2, 1), (1, 1)),
    range_source: "thesis Definition 3.2",
};
const BETA: ParamSpec = ParamSpec {
    name: "beta",
    symbol: "β",
    range: Range {
        lo: Bound::Closed(0, 1),
        hi: Bound::Unbounded,
    },
    range_source: "thesis Definition 3.1",
};
const LAMBDA_HAN: ParamSpec = ParamSpec {
    name: "lambda",
    symbol: "λ",
    range: Range::closed((-2, 1), (1, 1)),
    range_source: "thesis 6.2, text before (6.2)",
};
const ETA: ParamSpec = ParamSpec {
    name: "eta",
    symbol: "η",
    range: Range {
        lo: Bound::Open(1, 2),
        hi: Bound::Closed(2, 1),
    },
    range_source: "thesis 6.2, text before (6.1)",
};
const ALPHA: ParamSpec = ParamSpec {
    name: "alpha",
    symbol: "α",
    range: Range {
        lo: Bound::Open(0, 1),
        hi: Bound::Open(2, 1),
    },
    range_source: "thesis 6.2, text after (6.3)",
};
const ZETA: ParamSpec = ParamSpec {
    name: "zeta",
    symbol: "ζ",
    range: Range::closed((0, 1), (4, 1)),
    range_source: "seed 000 abstract and section 2",
};
const LAMBDA_EH: ParamSpec = ParamSpec {
    name: "lambda",
    symbol: "λ",
    range: Range::closed((-1, 1), (1, 1)),
    range_source: "seed 004 III(ii) (b)-(c)",
};
const MU_EH: ParamSpec = ParamSpec {
    name: "mu",
    symbol: "μ",
    range: Range::closed((-1, 1), (1, 1)),
    range_source: "seed 004 III(ii) (b)-(c)",
};

const B4: &[&str] = &["b0", "b1", "b2", "b3"];

/// Seed 000's non-uniform case: the segment functions of (5) with the
/// coefficients (2)–(3) as printed. It needs a knot vector, so it is evaluated
/// through [`crate::families::seed000_nonuniform::NonUniform`] rather than
/// [`Family::eval`].
pub const SEED000_NONUNIFORM: FamilyInfo = FamilyInfo {
    id: "seed000-nonuniform",
    title: "non-uniform segment functions F0..F3 of (5) with the printed coefficients (2)-(3)",
    citation: "seed 000, (1)-(5)",
    variable: Variable::Angle,
    params: &[ZETA],
    functions: &["F0", "F1", "F2", "F3"],
    piecewise: false,
};

/// Every entry of the catalog, in listing order: the families of
/// [`Family::ALL`] with seed 000's knot-dependent case after its uniform one.
pub fn catalog() -> Vec<FamilyInfo> {
    let mut entries: Vec<FamilyInfo> = Family::ALL.iter().map(Family::info).collect();
    let at = entries
        .iter()
        .position(|f| f.id == "seed000-uniform")
        .map_or(entries.len(), |i| i + 1);
    entries.insert(at, SEED000_NONUNIFORM);
    entries
}

impl Family {
    /// Every family of the catalog, in listing order.
    pub const ALL: [Family; 14] = [
        Family::ThesisQuadratic,
        Family::ThesisCubic,
        Family::Han,
        Family::MajeedQayyum,
        Family::Usman,
        Family::HanListing,
        Family::Seed000Blending,
        Family::Seed000Uniform,
        Family::Seed002Quartic,
        Family::Eh,
        Family::Hermite,
        Family::Bernstein3,
        Family::BSpline3,
        Family::Seed003,
    ];

    /// The static description.
    pub fn info(&self) -> FamilyInfo {
        let (id, title, citation, variable, params, functions, piecewise): (
            _,
            _,
            _,
            _,
            &'static [ParamSpec],
            &'static [&'static str],
            _,
        ) = match self {
            Family::ThesisQuadratic => (
                "thesis-quadratic",
                "quadratic trigonometric basis H_i(u; beta)",
                "seed 001 (thesis), (3.1)",
                Variable::UnitAngle,
                &[BETA],
                &["H0", "H1", "H2"],
                false,
            ),
            Family::ThesisCubic => (
                "thesis-cubic",
                "cubic trigonometric basis b_i(u; m)",
                "seed 001 (thesis), (3.7)",
                Variable::UnitAngle,
                &[M],
                B4,
                false,
            ),
            Family::Han => (
                "han",
                "Han et al. (2010) cubic trigonometric basis, as transcribed",
                "seed 001 (thesis), (6.2)",
                Variable::UnitAngle,
                &[LAMBDA_HAN],
                B4,
                false,
            ),
            Family::MajeedQayyum => (
                "majeed-qayyum",
                "Majeed & Qayyum (2020) cubic trigonometric basis, as transcribed",
                "seed 001 (thesis), (6.1)",
                Variable::Angle,
                &[ETA],
                &["g0", "g1", "g2", "g3"],
                false,
            ),
            Family::Usman => (
                "usman",
                "Usman et al. (2020) cubic Bernstein-like basis, as transcribed",
                "seed 001 (thesis), (6.3)",
                Variable::UnitAngle,
                &[ALPHA],
                &["a0", "a1", "a2", "a3"],
                false,
            ),
            Family::HanListing => (
                "han-listing",
                "Han basis as the thesis's MATLAB listing computes it (b20 uses sin)",
                "seed 001 (thesis), Appendix 2",
                Variable::UnitAngle,
                &[LAMBDA_HAN],
                B4,
                false,
            ),
            Family::Seed000Blending => (
                "seed000-blending",
                "blending functions l_k(t) with s(zeta) = zeta^2 - zeta + 1",
                "seed 000, (4)",
                Variable::Angle,
                &[ZETA],
                &["l0", "l1", "l2", "l3"],
                false,
            ),
            Family::Seed000Uniform => (
                "seed000-uniform",
                "uniform-knot segment functions l_k(t)/(6 zeta^2 - 6 zeta + 10)",
                "seed 000, (4), (5), Appendix A (A1)",
                Variable::Angle,
                &[ZETA],
                &["F0", "F1", "F2", "F3"],
                true,
            ),
            Family::Seed002Quartic => (
                "seed002-quartic",
                "quartic trigonometric Bezier basis (six functions)",
                "seed 002, Definition 1, (1)",
                Variable::Angle,
                &[],
                &["b0", "b1", "b2", "b3", "b4", "b5"],
                false,
            ),
            Family::Eh => (
                "eh",
                "EH interpolation-spline bases b_{i,3}(t; lambda, mu)",
                "seed 004, III(i), (1)",
                Variable::Polynomial,
                &[LAMBDA_EH, MU_EH],
                &["b0", "b1", "b2", "b3"],
                false,
            ),
            Family::Hermite => (
                "hermite",
                "standard cubic Hermite bases alpha0, alpha1, beta0, beta1",
                "seed 004, section II",
                Variable::Polynomial,
                &[],
                &["alpha0", "alpha1", "beta0", "beta1"],
                false,
            ),
            Family::Bernstein3 => (
                "bernstein3",
                "cubic Bernstein polynomials (reference)",
                "textbook reference (Farin, Curves and Surfaces for CAGD, ch. 4)",
                Variable::Polynomial,
                &[],
                &["B0", "B1", "B2", "B3"],
                false,
            ),
            Family::BSpline3 => (
                "bspline3",
                "uniform cubic B-spline segment functions (reference)",
                "textbook reference (Farin, Curves and Surfaces for CAGD, ch. 7)",
                Variable::Polynomial,
                &[],
                &["N0", "N1", "N2", "N3"],
                true,
            ),
            Family::Seed003 => (
                "seed003",
                "C3 trigonometric B-spline with shape parameter alpha: formulas missing from our copy",
                "seed 003 (eb2d8fda42cf564b), whole paper",
                Variable::UnitAngle,
                &[],
                &[],
                false,
            ),
        };
        FamilyInfo {
            id,
            title,
            citation,
            variable,
            params,
            functions,
            piecewise,
        }
    }

    /// The family with this id.
    pub fn from_id(id: &str) -> Result<Family> {
        Family::ALL
            .into_iter()
            .find(|f| f.info().id == id)
            .ok_or_else(|| CoreError::UnknownFamily(id.to_string()))
    }

    /// True when the formulas are available.
    pub fn has_formulas(&self) -> bool {
        !matches!(self, Family::Seed003)
    }

    /// Every function of the family at `x`, with parameters `p` in the order
    /// of [`FamilyInfo::params`]. Works for any [`Ring`]: numbers, jets, or
    /// exact symbols.
    ///
    /// # Panics
    /// If `p` has the wrong length or the family has no formulas: callers
    /// validate first ([`Family::params_from_pairs`]).
    pub fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        /// Collects the functions at one point.
        struct AtPoint<'a, T>(&'a Atoms<T>, &'a [T]);
        impl<T> FormulaVisitor<T> for AtPoint<'_, T> {
            type Output = Vec<T>;
            fn visit<const N: usize>(self, formula: impl Formula<T, N>) -> Vec<T> {
                let Atoms { s, c, t, .. } = self.0;
                formula(s, c, t, self.1).into()
            }
        }
        assert_eq!(p.len(), self.info().params.len(), "parameter count");
        self.with_formula(AtPoint(x, p))
    }

    /// Hands the family's formula, as a function of the atoms `s, c, t` and
    /// the parameters, to `visitor`: the one place where a family is tied
    /// to its formula, for [`Family::eval`] and the batch evaluator
    /// ([`crate::batch`]), which runs it over many points without
    /// allocating.
    ///
    /// # Panics
    /// If the family has no formulas.
    pub fn with_formula<T: Ring, V: FormulaVisitor<T>>(&self, visitor: V) -> V::Output {
        match self {
            Family::ThesisQuadratic => visitor.visit(|s, c, _, p| thesis::quadratic(s, c, &p[0])),
            Family::ThesisCubic => visitor.visit(|s, c, _, p| thesis::cubic(s, c, &p[0])),
            Family::Han => visitor.visit(|s, c, _, p| thesis::han(s, c, &p[0])),
            Family::MajeedQayyum => visitor.visit(|s, c, _, p| thesis::majeed_qayyum(s, c, &p[0])),
            Family::Usman => visitor.visit(|s, c, _, p| thesis::usman(s, c, &p[0])),
            Family::HanListing => visitor.visit(|s, c, _, p| thesis::han_listing(s, c, &p[0])),
            Family::Seed000Blending => visitor.visit(|s, c, _, p| seed000::blending(s, c, &p[0])),
            Family::Seed000Uniform => visitor.visit(|s, c, _, p| seed000::uniform(s, c, &p[0])),
            Family::Seed002Quartic => visitor.visit(|s, c, _, _| seed002::quartic(s, c)),
            Family::Eh => visitor.visit(|_, _, t, p| seed004::eh(t, &p[0], &p[1])),
            Family::Hermite => visitor.visit(|_, _, t, _| seed004::hermite(t)),
            Family::Bernstein3 => visitor.visit(|_, _, t, _| reference::bernstein3(t)),
            Family::BSpline3 => visitor.visit(|_, _, t, _| reference::bspline3(t)),
            Family::Seed003 => panic!("seed003 has no formulas"),
        }
    }

    /// Numeric evaluation at a point of the native variable, with typed
    /// errors for points outside the domain (unless `allow_outside`) and for
    /// non-finite results (a vanishing denominator).
    pub fn eval_at<T: Real>(&self, x: &T, p: &[Rational], allow_outside: bool) -> Result<Vec<T>> {
        let info = self.info();
        if !self.has_formulas() {
            return Err(CoreError::NoFormulas(info.id.to_string()));
        }
        info.variable.check_point(x, allow_outside)?;
        let params: Vec<T> = p.iter().map(|q| x.rational(q)).collect();
        let values = self.eval(&info.variable.atoms(x), &params);
        if values.iter().any(|v| !v.is_finite()) {
            let at = info
                .params
                .iter()
                .zip(p)
                .map(|(s, v)| format!("{}={}", s.name, crate::echo::echo(&v.to_string())))
                .collect::<Vec<_>>()
                .join(", ");
            let quantity = format!("`{}` at {at}", info.id);
            return Err(crate::certified::nonfinite_error(self, x, p, quantity));
        }
        Ok(values)
    }
}

impl Described for Family {
    fn id(&self) -> String {
        self.info().id.to_string()
    }

    fn title(&self) -> String {
        self.info().title.to_string()
    }

    fn citation(&self) -> String {
        self.info().citation.to_string()
    }

    fn domain(&self) -> Domain {
        let info = self.info();
        let names: Vec<&str> = info.params.iter().map(|p| p.name).collect();
        Domain::from_variable(info.variable, &names)
    }

    fn variable(&self) -> Option<Variable> {
        Some(self.info().variable)
    }

    fn variable_name(&self) -> String {
        self.info().variable.name().to_string()
    }

    fn parameters(&self) -> Vec<Parameter> {
        self.info()
            .params
            .iter()
            .map(ParamSpec::parameter)
            .collect()
    }

    fn function_names(&self) -> Vec<String> {
        self.info()
            .functions
            .iter()
            .map(|f| f.to_string())
            .collect()
    }

    fn piecewise(&self) -> bool {
        self.info().piecewise
    }

    /// As for every basis, after checking that the family has formulas.
    fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Vec<Affine>> {
        if !self.has_formulas() {
            return Err(CoreError::NoFormulas(self.info().id.to_string()));
        }
        read_params(self.info().id, &self.parameters(), pairs, allow_outside)
    }
}

impl Basis for Family {
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        Family::eval(self, x, p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Mpfr;

    /// Hand-derived values at both ends of the domain, as exact rationals
    /// (`"3/22"`), one row per family: (family, parameters, left, right).
    /// Derivations: at the left end `s = 0, c = 1, t = 0`; at the right end
    /// `s = 1, c = 0, t = 1` — e.g. thesis (3.7) at `u = 0`: `b₀ = (1−0)²(1−0) = 1`,
    /// `b₂ = m·1·0 − 2·1·0 = 0`; seed 000 (4) with `ζ = 2`, `s(ζ) = 3`:
    /// `l₁(0) = (1+1)²(3+1) = 16`, normaliser `6·4 − 12 + 10 = 22`.
    #[allow(clippy::type_complexity)]
    const ENDS: &[(Family, &[(i64, i64)], &[&str], &[&str])] = &[
        (
            Family::ThesisQuadratic,
            &[(1, 1)],
            &["1/2", "1/2", "0"],
            &["0", "1/2", "1/2"],
        ),
        (
            Family::ThesisQuadratic,
            &[(3, 1)],
            &["3/4", "1/4", "0"],
            &["0", "1/4", "3/4"],
        ),
        (
            Family::ThesisCubic,
            &[(-2, 1)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::ThesisCubic,
            &[(3, 5)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::Han,
            &[(1, 2)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::HanListing,
            &[(1, 2)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::MajeedQayyum,
            &[(3, 2)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::Usman,
            &[(1, 2)],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::Seed000Blending,
            &[(2, 1)],
            &["3", "16", "3", "0"],
            &["0", "3", "16", "3"],
        ),
        (
            Family::Seed000Uniform,
            &[(2, 1)],
            &["3/22", "16/22", "3/22", "0"],
            &["0", "3/22", "16/22", "3/22"],
        ),
        (
            Family::Seed002Quartic,
            &[],
            &["1", "0", "0", "0", "0", "0"],
            &["0", "0", "0", "0", "0", "1"],
        ),
        (
            Family::Eh,
            &[(1, 2), (-1, 3)],
            &["1", "0", "0", "0"],
            &["0", "1", "0", "0"],
        ),
        (
            Family::Hermite,
            &[],
            &["1", "0", "0", "0"],
            &["0", "1", "0", "0"],
        ),
        (
            Family::Bernstein3,
            &[],
            &["1", "0", "0", "0"],
            &["0", "0", "0", "1"],
        ),
        (
            Family::BSpline3,
            &[],
            &["1/6", "4/6", "1/6", "0"],
            &["0", "1/6", "4/6", "1/6"],
        ),
    ];

    #[test]
    fn endpoint_values_match_hand_derivations_at_256_bits() {
        let tol = Mpfr::from_f64(256, 2f64.powi(-250));
        for (family, params, left, right) in ENDS {
            let p: Vec<Rational> = params.iter().map(|&r| Rational::from(r)).collect();
            let x0 = Mpfr::from_f64(256, 0.0);
            let x1 = family.info().variable.end(&x0);
            for (x, expected) in [(x0, left), (x1, right)] {
                let got = family.eval_at(&x, &p, false).unwrap();
                assert_eq!(got.len(), expected.len());
                for (g, e) in got.iter().zip(expected.iter()) {
                    let e: Rational = e.parse().unwrap();
                    let diff = g.clone() - &g.rational(&e);
                    let abs = if diff < x.int(0) { -diff } else { diff };
                    assert!(abs < tol, "{family:?} at {x}: got {g}, expected {e}");
                }
            }
        }
    }

    #[test]
    fn every_family_with_formulas_has_a_row_above() {
        for f in Family::ALL.iter().filter(|f| f.has_formulas()) {
            assert!(ENDS.iter().any(|(g, ..)| g == f), "{f:?}");
        }
    }

    #[test]
    fn params_are_validated() {
        let pairs = |v: &[(&str, &str)]| -> Vec<(String, String)> {
            v.iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        };
        let cubic = Family::ThesisCubic;
        assert_eq!(
            cubic
                .params_from_pairs(&pairs(&[("m", "0.6")]), false)
                .unwrap(),
            vec![Affine::rational(Rational::from((3, 5)))]
        );
        assert!(matches!(
            cubic.params_from_pairs(&pairs(&[("m", "1.5")]), false),
            Err(CoreError::OutOfRange { .. })
        ));
        assert!(
            cubic
                .params_from_pairs(&pairs(&[("m", "1.5")]), true)
                .is_ok()
        );
        assert!(matches!(
            Family::MajeedQayyum.params_from_pairs(&pairs(&[("eta", "1/2")]), false),
            Err(CoreError::OutOfRange { .. })
        ));
        assert!(matches!(
            cubic.params_from_pairs(&pairs(&[]), false),
            Err(CoreError::MissingParameter { .. })
        ));
        assert!(matches!(
            Family::Seed003.params_from_pairs(&pairs(&[]), false),
            Err(CoreError::NoFormulas(_))
        ));
    }
}
