//! Thesis 6.5, (6.11)–(6.18): the least-squares normal equations for the
//! inner control points `V1`, `V2` and their Cramer solution (claim T64).
//!
//! `S = Σᵢ (V0 b0(tᵢ) + V1 b1(tᵢ) + V2 b2(tᵢ) + V3 b3(tᵢ) − Pᵢ)²` (6.8), one
//! coordinate of the points at a time (`‖·‖²` is the sum over the
//! coordinates). The values `bⱼ(tᵢ)` and `Pᵢ` are independent symbols, so
//! every identity below holds for any basis and any data; each side of
//! (6.12)–(6.16) is a sum over `i` of one expression in the `i`-th values,
//! so an identity over two data points with independent symbols is the
//! identity of the summands, i.e. it holds for every `N`. `∂S/∂V1` is
//! derived in the symbolic ring ([`trig_symbolic::Sym::diff`]). The Cramer
//! solution (6.17)–(6.18) is checked on the abbreviations `A11 … B12` of
//! (6.16) as symbols, in the field of rational functions.

use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, identities};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T64",
    check: t64,
}];

/// Data points used: two, with independent symbols (see the module docs).
const N: usize = 2;

fn v(j: usize) -> Sym {
    Sym::var(&format!("V{j}"))
}

/// `bⱼ(tᵢ)`.
fn b(j: usize, i: usize) -> Sym {
    Sym::var(&format!("b{j}_{i}"))
}

/// `Pᵢ` (one coordinate).
fn p(i: usize) -> Sym {
    Sym::var(&format!("P_{i}"))
}

/// `Σᵢ f(i)` over the data points.
fn sum(f: impl Fn(usize) -> Sym) -> Sym {
    (1..=N).fold(Sym::zero(), |acc, i| acc + &f(i))
}

/// `F(tᵢ) = Σⱼ Vⱼ bⱼ(tᵢ)` (6.6).
fn curve(i: usize) -> Sym {
    (0..4).fold(Sym::zero(), |acc, j| acc + &(v(j) * &b(j, i)))
}

/// `S` of (6.8).
fn distance() -> Sym {
    sum(|i| {
        let r = curve(i) - &p(i);
        r.clone() * &r
    })
}

/// `Σᵢ bⱼ(tᵢ) bₖ(tᵢ)`.
fn gram(j: usize, k: usize) -> Sym {
    sum(|i| b(j, i) * &b(k, i))
}

/// `Σᵢ Pᵢ bⱼ(tᵢ)`.
fn moment(j: usize) -> Sym {
    sum(|i| p(i) * &b(j, i))
}

/// The right side of the normal equation of `Vk` (k = 1, 2) as (6.13),
/// (6.14), (6.16) print it: `Σ Pᵢ bₖ − Σ V0 b0 bₖ − Σ V3 bₖ b3`.
fn right(k: usize) -> Sym {
    moment(k) - &(v(0) * &gram(0, k)) - &(v(3) * &gram(k, 3))
}

/// The right side of row 2 of (6.15) as printed: row 1 repeated,
/// `Σ Pᵢ bᵢ − Σ V0 b0 b1 − Σ V3 b1 b3` (with the garbled `bᵢ` read as `b2`,
/// the reading most favourable to the print).
fn printed_row_two_right() -> Sym {
    moment(2) - &(v(0) * &gram(0, 1)) - &(v(3) * &gram(1, 3))
}

/// The normal-equation identities: each printed form against `½ ∂S/∂Vk`.
fn normal_equations(row_two: Sym) -> Vec<(String, Sym, Sym)> {
    let s = distance();
    let half = Sym::rational(rug::Rational::from((1, 2)));
    let d1 = s.diff("V1");
    let d2 = s.diff("V2");
    let printed_first_line = Sym::int(2) * &sum(|i| b(1, i) * &curve(i));
    let second_line = sum(|i| {
        v(0) * &b(0, i) * &b(1, i)
            + &(v(1) * &b(1, i) * &b(1, i))
            + &(v(2) * &b(1, i) * &b(2, i))
            + &(v(3) * &b(1, i) * &b(3, i))
            - &(p(i) * &b(1, i))
    });
    let lhs1 = v(1) * &gram(1, 1) + &(v(2) * &gram(1, 2));
    let lhs2 = v(1) * &gram(1, 2) + &(v(2) * &gram(2, 2));
    vec![
        (
            "(6.12) first line: ∂S/∂V1 = 2 Σ b1(tᵢ)[V0b0 + V1b1 + V2b2 + V3b3] (as printed, without − Pᵢ)".into(),
            d1.clone(),
            printed_first_line,
        ),
        (
            "(6.12) second line: ½ ∂S/∂V1 = Σ [V0b0b1 + V1b1² + V2b1b2 + V3b1b3 − Pᵢb1]".into(),
            half.clone() * &d1,
            second_line,
        ),
        (
            "(6.13): ½ ∂S/∂V1 = (Σ V1b1² + Σ V2b1b2) − (Σ Pᵢb1 − Σ V0b0b1 − Σ V3b1b3)".into(),
            half.clone() * &d1,
            lhs1.clone() - &right(1),
        ),
        (
            "(6.14): ½ ∂S/∂V2 = (Σ V1b1b2 + Σ V2b2²) − (Σ Pᵢb2 − Σ V0b0b2 − Σ V3b2b3)".into(),
            half.clone() * &d2,
            lhs2.clone() - &right(2),
        ),
        (
            "(6.15) row 1 (bᵢ read as b1): ½ ∂S/∂V1 = A11V1 + A12V2 − (Σ Pᵢb1 − Σ V0b0b1 − Σ V3b1b3)".into(),
            half.clone() * &d1,
            lhs1 - &right(1),
        ),
        (
            "(6.15) row 2 as printed (right side that of row 1, bᵢ read as b2): ½ ∂S/∂V2 = A21V1 + A22V2 − (Σ Pᵢb2 − Σ V0b0b1 − Σ V3b1b3)".into(),
            half * &d2,
            lhs2 - &row_two,
        ),
    ]
}

/// The Cramer identities on the abbreviations of (6.16): the inverse and
/// the solution (6.17)–(6.18) substituted into the system.
fn cramer() -> Vec<(String, Sym, Sym)> {
    let [a11, a12, a22, b11, b12] = ["A11", "A12", "A22", "B11", "B12"].map(Sym::var);
    let a21 = a12.clone(); // (6.16): A12 = A21
    let det = a11.clone() * &a22 - &(a12.clone() * &a12);
    let v1 = a22.clone() * &b11 / &det - &(a12.clone() * &b12 / &det);
    let v2 = a11.clone() * &b12 / &det - &(a21.clone() * &b11 / &det);
    let inv = [
        [a22.clone() / &det, -(a12.clone() / &det)],
        [-(a21.clone() / &det), a11.clone() / &det],
    ];
    // the columns of A
    let columns = [[a11.clone(), a21.clone()], [a12.clone(), a22.clone()]];
    let mut out = Vec::new();
    for (r, inv_row) in inv.iter().enumerate() {
        for (c, column) in columns.iter().enumerate() {
            let entry = inv_row[0].clone() * &column[0] + &(inv_row[1].clone() * &column[1]);
            let id = if r == c { Sym::one() } else { Sym::zero() };
            out.push((
                format!(
                    "A⁻¹ = [[A22, −A12], [−A21, A11]]/(A11A22 − A12²): (A⁻¹A) entry ({}, {})",
                    r + 1,
                    c + 1
                ),
                entry,
                id,
            ));
        }
    }
    out.push((
        "(6.17)–(6.18) in row 1: A11V1 + A12V2 = B11".into(),
        a11 * &v1 + &(a12 * &v2.clone()),
        b11,
    ));
    out.push((
        "(6.17)–(6.18) in row 2: A21V1 + A22V2 = B12".into(),
        a21 * &v1 + &(a22 * &v2),
        b12,
    ));
    out
}

fn t64() -> Verdict {
    let printed = identities(
        normal_equations(printed_row_two_right())
            .into_iter()
            .chain(cramer())
            .collect(),
    );
    if printed.status == Status::Holds {
        return printed;
    }
    // the corrections: − Pᵢ in the first line of (6.12), B12 as the right side of row 2 of (6.15)
    let mut corrected = normal_equations(right(2));
    corrected[0].0 =
        "(6.12) first line with − Pᵢ: ∂S/∂V1 = 2 Σ b1(tᵢ)[V0b0 + V1b1 + V2b2 + V3b3 − Pᵢ]".into();
    corrected[0].2 = Sym::int(2) * &sum(|i| b(1, i) * &(curve(i) - &p(i)));
    corrected[5].0 = "(6.15) row 2 with B12 on the right: ½ ∂S/∂V2 = A21V1 + A22V2 − (Σ Pᵢb2 − Σ V0b0b2 − Σ V3b2b3)".into();
    corrected.retain(|(label, _, _)| label.contains("with"));
    let corrected = identities(corrected);
    let status = if corrected.status == Status::Holds {
        Status::HoldsAfterCorrection
    } else {
        Status::Fails
    };
    let mut evidence = printed.evidence;
    evidence.insert(
        0,
        "symbols: bj_i stands for bⱼ(tᵢ) and P_i for Pᵢ (one coordinate), i = 1, 2: independent values, so each identity is that of the summands and holds for every N",
    );
    evidence.extend(
        corrected
            .evidence
            .into_vec()
            .into_iter()
            .map(|e| e.in_part("corrected", corrected.status)),
    );
    Verdict::new(status, IDENTITY, evidence).with_correction(
        "(6.12), first line: 2 Σ b1(tᵢ)[V0b0(tᵢ) + V1b1(tᵢ) + V2b2(tᵢ) + V3b3(tᵢ) − Pᵢ] = 0; (6.15), right side of row 2: Σ Pᵢb2(tᵢ) − Σ V0b0(tᵢ)b2(tᵢ) − Σ V3b2(tᵢ)b3(tᵢ) (= B12 of (6.16)); bᵢ(tᵢ) in (6.15) read as b1 (row 1), b2 (row 2)",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_normal_equations_are_the_gradient() {
        let ids = identities(normal_equations(right(2)));
        // only the printed first line of (6.12) (without − Pᵢ) fails
        let failing: Vec<&str> = ids
            .evidence
            .iter()
            .filter(|e| e.status == Some(Status::Fails))
            .filter_map(|e| e.subject.as_deref())
            .collect();
        assert_eq!(failing.len(), 1, "{failing:?}");
        assert!(failing[0].starts_with("(6.12) first line"));
        assert_eq!(identities(cramer()).status, Status::Holds);
    }

    #[test]
    fn a_wrong_cramer_sign_fails() {
        let [a11, a12, a22, b11, b12] = ["A11", "A12", "A22", "B11", "B12"].map(Sym::var);
        let det = a11.clone() * &a22 - &(a12.clone() * &a12);
        // V1 with + A12B12: not the solution
        let v1 = (a22.clone() * &b11 + &(a12.clone() * &b12)) / &det;
        let v2 = (a11.clone() * &b12 - &(a12.clone() * &b11)) / &det;
        let row1 = a11 * &v1 + &(a12 * &v2);
        assert!(!(row1 - &b11).is_zero());
    }
}
