//! The coefficients of a basis on a knot vector against the printed ones
//! (`check = "knot-coefficients"`): on the span `[n_j, n_{j+1})` the
//! segment functions are `F_i = Σ_k M_{ik} f_k` ([`trig_specfile::knots`]);
//! each coefficient `M_{ik}`, from the paper's knot-interval formulas
//! evaluated exactly on the claim's knots, is compared exactly with the
//! printed one. A row whose formulas are undefined on the knots (a
//! vanishing denominator, a knot outside the vector) fails with the
//! formula named; the other rows are decided all the same.

use trig_specfile::Spec;
use trig_specfile::knots::Knots;
use trig_symbolic::Sym;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::exact::{IDENTITY, residual_verdict};

/// Every coefficient of the span against `printed` (row `i`: the printed
/// coefficients of `F_i`, as written and exactly).
pub fn knot_coefficients(spec: &Spec, knots: &Knots, printed: &[Vec<(String, Sym)>]) -> Verdict {
    let Some((names, param)) = Knots::family(&knots.coefficients) else {
        return Verdict::not_checkable(format!("`{}`: no such knot family", knots.coefficients));
    };
    let mut parts: Vec<(String, Verdict)> = Vec::new();
    for ((name, row), printed_row) in names.iter().zip(knots.rows(&Sym::var(param))).zip(printed) {
        match row {
            Ok(row) => {
                for ((m, f), (text, want)) in row.iter().zip(&spec.functions).zip(printed_row) {
                    parts.push((
                        format!("{name}: coefficient of {} − printed {text}", f.name),
                        residual_verdict(m, want),
                    ));
                }
            }
            Err(e) => parts.push((
                format!("{name}: coefficients"),
                Verdict::new(
                    Status::Fails,
                    IDENTITY,
                    vec![format!("the printed formula is undefined: {e}")],
                ),
            )),
        }
    }
    let mut v = Verdict::all(IDENTITY, parts);
    let basis: Vec<&str> = spec.functions.iter().map(|f| f.name.as_str()).collect();
    v.evidence.insert(
        0,
        format!(
            "{}: {} = Σ_k M_ik f_k over f = ({}), each coefficient M_ik against the printed one",
            knots.describe(),
            names.join(", "),
            basis.join(", ")
        ),
    );
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_knots_decide_each_row_and_name_the_undefined_one() {
        let spec = Spec::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/catalog/seed000-blending.toml"
        )))
        .expect("the catalog's blending functions");
        let knots = Knots {
            coefficients: "seed000-nonuniform".into(),
            texts: (0..=20).map(|i: i64| i.to_string()).collect(),
            values: (0..=20).map(Sym::int).collect(),
            span: 10,
        };
        // unit spacing: d_j = 2β_{j+1}ψ_{j+2}/(α_{j+2}q_j) = 2ψ = 6ζ² − 6ζ + 10
        let zeta = Sym::var("zeta");
        let d = Sym::int(6) * &(zeta.clone() * &zeta) - &(Sym::int(6) * &zeta) + &Sym::int(10);
        let zero = || ("0".to_string(), Sym::zero());
        let diag = |i: usize, v: Sym| {
            (0..4)
                .map(|k| {
                    if k == i {
                        ("d".to_string(), v.clone())
                    } else {
                        zero()
                    }
                })
                .collect::<Vec<_>>()
        };
        let printed = vec![
            diag(0, d.clone()),
            diag(1, Sym::one()),
            diag(2, Sym::one()),
            diag(3, Sym::one()),
        ];
        let v = knot_coefficients(&spec, &knots, &printed);
        assert_eq!(v.status, Status::Fails);
        let line = |needle: &str| {
            v.evidence
                .iter()
                .find(|e| e.line().contains(needle))
                .unwrap_or_else(|| panic!("{needle}: {:?}", v.evidence))
                .status
        };
        assert_eq!(line("F0: coefficient of l0"), Some(Status::Holds));
        assert_eq!(line("F1: coefficient of l1"), Some(Status::Fails));
        assert_eq!(line("F2: coefficients"), Some(Status::Fails));
        assert!(v.evidence.iter().any(|e| e.line().contains("c_{10,2}")));
    }
}
