//! A basis on a knot vector: a claim's
//! `knots = { coefficients = "seed000-nonuniform", values = ["0", "1", "3", …], span = 8 }`.
//!
//! A non-uniform B-spline-like basis changes from span to span: on the span
//! `[n_j, n_{j+1})` its segment functions are fixed combinations
//! `F_i = Σ_k M_{ik}(n, p) f_k` of the claim's basis functions `f_k` (the
//! blending functions as printed, a spec file) whose coefficients `M_{ik}`
//! are the paper's printed knot-interval formulas (`q_j = n_{j+1} − n_j`,
//! `α_j`, …), evaluated exactly over the claim's knots. The coefficient
//! formulas are a catalog knot family's (`coefficients`, an id of
//! [`KNOT_FAMILIES`]); the knots, the span and the blending functions are
//! the claim's data. Applied before any judge runs, like a fixed value
//! ([`crate::Given`]): every check decides the segment functions of that
//! span. Where the printed formulas are undefined on the knots (a knot
//! they need lies outside the vector, a denominator vanishes), the basis
//! does not exist there: [`GivenError::Coefficients`].

use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::{CoreError, SEED000_NONUNIFORM};
use trig_symbolic::Sym;

use crate::given::GivenError;
use crate::spec::{Spec, SpecFunction};

/// The catalog's knot families: coefficient formulas over a knot vector.
pub const KNOT_FAMILIES: [&str; 1] = [SEED000_NONUNIFORM.id];

/// A knot vector, a span of it and the coefficient formulas, as a claim
/// gives them.
#[derive(Debug, Clone, PartialEq)]
pub struct Knots {
    /// The knot family whose printed coefficient formulas combine the
    /// basis functions (an id of [`KNOT_FAMILIES`]).
    pub coefficients: String,
    /// The knots as written.
    pub texts: Vec<String>,
    /// Their exact values (constants of the ring).
    pub values: Vec<Sym>,
    /// The span `[n_j, n_{j+1})`, `j`.
    pub span: i64,
}

impl Knots {
    /// `knots 0, 1, 3, …, span [n_8, n_9) (coefficients of seed000-nonuniform)`.
    pub fn describe(&self) -> String {
        format!(
            "the span [n_{}, n_{}) of the knots {} (the printed coefficient formulas of {})",
            self.span,
            self.span + 1,
            self.texts.join(", "),
            self.coefficients
        )
    }

    /// The names of the segment functions and the parameter the
    /// coefficient formulas take, for [`KNOT_FAMILIES`] entry `id`.
    pub fn family(id: &str) -> Option<(&'static [&'static str], &'static str)> {
        (id == SEED000_NONUNIFORM.id).then(|| {
            let info = SEED000_NONUNIFORM;
            (info.functions, "zeta")
        })
    }

    /// The rows of the coefficient matrix of the span one by one, each
    /// with the typed error of the printed formulas where they are
    /// undefined on the knots (seed 000: `d_j`, `b_{j,·}`, `c_{j,·}`, `a_j`).
    pub fn rows(&self, param: &Sym) -> Vec<Result<Vec<Sym>, CoreError>> {
        (0..4).map(|i| self.row(i, param)).collect()
    }

    /// Row `i` of the coefficient matrix of the span alone (segment
    /// function `F_i`), with the typed error where its printed formulas are
    /// undefined on the knots.
    pub fn row(&self, i: usize, param: &Sym) -> Result<Vec<Sym>, CoreError> {
        let f = NonUniform::new(self.values.clone(), param.clone());
        let j = self.span;
        let zero = Sym::zero();
        match i {
            0 => f
                .d(j)
                .map(|d| vec![d, zero.clone(), zero.clone(), zero.clone()]),
            1 => f.b(j).map(|b| b.to_vec()),
            2 => f.c(j).map(|c| c.to_vec()),
            3 => f
                .a(j)
                .map(|a| vec![zero.clone(), zero.clone(), zero.clone(), a]),
            _ => Err(CoreError::Count {
                what: "segment function index".into(),
                expected: 4,
                got: i,
            }),
        }
    }

    /// The coefficient matrix `M` of the span (row `i`: `F_i = Σ_k M_{ik} f_k`),
    /// exactly, with the family's parameter as the symbol `param`.
    /// Seed 000, eq. (5): `F₀ = d_j l₀`, `F₁ = Σ b_{j,k} l_k`,
    /// `F₂ = Σ c_{j,k} l_k`, `F₃ = a_j l₃`, the coefficients (2)–(3).
    fn matrix(&self, param: &Sym) -> Result<Vec<Vec<Sym>>, CoreError> {
        self.rows(param).into_iter().collect()
    }

    /// The basis of `spec` on the span: its functions replaced by the
    /// segment functions `F_i = Σ_k M_{ik} f_k`.
    pub fn apply(&self, spec: &Spec) -> Result<Spec, GivenError> {
        let refused = |why: String| GivenError::Refused {
            what: self.describe(),
            why,
        };
        let (names, param) = Self::family(&self.coefficients)
            .ok_or_else(|| refused("no such knot family".into()))?;
        if !spec.params.iter().any(|p| p.name == param) {
            return Err(refused(format!(
                "the coefficient formulas take the parameter `{param}`, which the basis does not declare"
            )));
        }
        let matrix = self
            .matrix(&Sym::var(param))
            .map_err(|e| GivenError::Coefficients {
                knots: self.describe(),
                why: e.to_string(),
            })?;
        if spec.functions.len() != matrix[0].len() {
            return Err(refused(format!(
                "the coefficient formulas combine {} functions, the basis has {}",
                matrix[0].len(),
                spec.functions.len()
            )));
        }
        let mut out = spec.clone();
        out.citation = format!(
            "{}, combined on the span [n_{}, n_{}) by the printed coefficient formulas of {}",
            spec.citation,
            self.span,
            self.span + 1,
            self.coefficients
        );
        out.functions = names
            .iter()
            .zip(&matrix)
            .map(|(name, row)| {
                let mut value = Sym::zero();
                let mut formula = Vec::new();
                for (m, f) in row.iter().zip(&spec.functions) {
                    if !m.is_zero() {
                        value = value + &(m.clone() * &f.value);
                        formula.push(format!("({m})*{}", f.name));
                    }
                }
                SpecFunction {
                    name: name.to_string(),
                    formula: formula.join(" + "),
                    value,
                }
            })
            .collect();
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blending() -> Spec {
        Spec::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/catalog/seed000-blending.toml"
        )))
        .expect("the catalog's blending functions")
    }

    fn knots(values: &[i64], span: i64) -> Knots {
        Knots {
            coefficients: SEED000_NONUNIFORM.id.into(),
            texts: values.iter().map(i64::to_string).collect(),
            values: values.iter().map(|v| Sym::int(*v)).collect(),
            span,
        }
    }

    #[test]
    fn segment_functions_are_the_printed_combinations_of_the_blending_functions() {
        let spec = blending();
        let k = knots(&[0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25], 8);
        let on = k.apply(&spec).unwrap();
        let names: Vec<&str> = on.functions.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["F0", "F1", "F2", "F3"]);
        // F3 = a_j l3 with the printed a_j
        let a = NonUniform::new(k.values.clone(), Sym::var("zeta"))
            .a(8)
            .unwrap();
        assert_eq!(on.functions[3].value, a * &spec.functions[3].value);
    }

    #[test]
    fn undefined_coefficients_and_foreign_bases_are_refused() {
        let spec = blending();
        // uniform knots: c_{j,2} divides by c_{j,0} = 0
        let uniform: Vec<i64> = (0..=20).collect();
        let e = knots(&uniform, 10).apply(&spec).unwrap_err();
        assert!(
            matches!(&e, GivenError::Coefficients { why, .. } if why.contains("c_{10,2}")),
            "{e}"
        );
        // a knot the formulas need lies outside the vector
        let e = knots(&[0, 1, 3, 4], 1).apply(&spec).unwrap_err();
        assert!(matches!(e, GivenError::Coefficients { .. }), "{e}");
        let mut other = knots(&uniform, 10);
        other.coefficients = "bspline3".into();
        assert!(matches!(
            other.apply(&spec),
            Err(GivenError::Refused { .. })
        ));
    }
}
