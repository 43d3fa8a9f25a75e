//! The knot-continuity judge: the interpolant of a printed data table by a
//! scheme of `trig-interp` (as [`crate::interpolant`] builds it) is `Cʳ` at
//! every interior knot.
//!
//! The interpolant is built exactly (`π` a symbol); at each interior knot
//! `x_k` the one-sided derivatives in `x` of orders 0–3 of the two pieces
//! are formed by `trig-deriv` jets ([`trig_interp::knot_jumps`]), and the
//! jump `P^{(j)}(x_k⁺) − P^{(j)}(x_k⁻)` is decided exactly. The claim `Cʳ`
//! holds when the jumps of orders `0…r` vanish at every knot; a knot where
//! one does not carries the two one-sided values as its witness, each with
//! its formula in the pieces' control points. For the graph `y = P(x)`,
//! tangent continuity (G¹) is `C¹` and curvature continuity (G²) `C²`.
//!
//! A scheme whose print has a corrected variant (C², G²) is decided as
//! printed, the corrected curve's jumps reported beside it; where the
//! printed curve fails and the corrected one holds, the corrected scheme
//! is the correction.

use trig_deriv::{End, Wrt};
use trig_interp::piece::derivatives_of;
use trig_interp::{DataSet, KnotJump, Scheme, Spline, Variant, knot_jumps};
use trig_symbolic::Sym;
use trig_verdict::evidence::{Assignment, Evidence, EvidenceList, Expr, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::exact::ExactBasis;
use crate::interpolant::{exact_spline, other_basis};

/// How the jumps are decided, as the report states it.
pub const JUMPS: &str = "exact one-sided derivatives in x at the interior knots (trig-deriv jets, π symbolic), jump = right − left";

/// "The interpolant of `data` by `scheme` is `C^order` at every interior
/// knot", about `basis`.
pub fn continuity<B: ExactBasis>(
    basis: &B,
    data: &DataSet,
    scheme: Scheme,
    order: usize,
) -> Verdict {
    if let Some(why) = other_basis(basis) {
        return Verdict::not_checkable(why);
    }
    let printed = match exact_spline(data, scheme, Variant::Printed) {
        Ok(s) => s,
        Err(e) => return Verdict::not_checkable(e),
    };
    let (ok, lines) = jump_lines(&printed, order + 1);
    let mut evidence = EvidenceList::from(lines);
    let mut fixed = false;
    if let Some(correction) = scheme.correction() {
        let corrected = match exact_spline(data, scheme, Variant::Corrected) {
            Ok(s) => s,
            Err(e) => return Verdict::not_checkable(e),
        };
        let (holds, lines) = jump_lines(&corrected, order + 1);
        fixed = holds;
        evidence.push(format!(
            "decided on the printed scheme (what the thesis computes and plots); the corrected scheme ({correction}) on the same table, for comparison: {}",
            if holds { Status::Holds } else { Status::Fails }
        ));
        evidence.extend(lines);
    }
    let status = if ok { Status::Holds } else { Status::Fails };
    let v = Verdict::new(status, JUMPS, evidence);
    match scheme.correction() {
        Some(correction) if !ok && fixed => v.with_correction(format!(
            "the corrected scheme ({correction}): C{order} at every knot (corrected lines above)"
        )),
        _ => v,
    }
}

/// One line per interior knot (the jumps of orders 0–3 and the order they
/// show), and whether the jumps of orders below `orders` vanish at every
/// knot.
fn jump_lines(spline: &Spline<Sym>, orders: usize) -> (bool, Vec<Evidence>) {
    let mut ok = true;
    let lines = knot_jumps(spline)
        .iter()
        .map(|k| {
            let order = k.continuity_order();
            let enough = order.is_some_and(|o| o + 1 >= orders);
            ok &= enough;
            // a jump below the claimed order: the two one-sided values, exact
            let witness = k
                .jumps
                .iter()
                .take(orders)
                .position(|j| !j.is_zero())
                .filter(|_| !enough)
                .map(|r| knot_witness(spline, k, r));
            let jumps: Vec<String> = k
                .jumps
                .iter()
                .map(|j| {
                    if j.is_zero() {
                        "0".into()
                    } else {
                        format!("{j} ≈ {}", approx(j))
                    }
                })
                .collect();
            let achieved = order.map_or("discontinuous".to_string(), |o| format!("C{o}"));
            Evidence::note(format!(
                "{} ({}), knot x = {}: jumps of P, P', P'', P''' = [{}] → {achieved}",
                spline.data.table.name,
                spline.variant,
                k.x,
                jumps.join("; ")
            ))
            .witnessed(witness)
        })
        .collect();
    (ok, lines)
}

/// The witness of a jump of order `r` at the knot `k`: the point sets the
/// control points `Vᵢ, Wᵢ, Xᵢ, Yᵢ` of the two pieces (piece `i` on
/// `[x_i, x_{i+1}]`), and each one-sided value records its formula — the
/// `r`-th derivative in `x` of `Σ b_j(θ; m_i)·V_j` at the end of its piece,
/// linear in the control points (`m_i`, `h_i` and `π` in its coefficients).
fn knot_witness(spline: &Spline<Sym>, k: &KnotJump<Sym>, r: usize) -> Witness {
    let primes = "'".repeat(r);
    let x = k.x.to_string();
    let mut point = vec![Assignment::exact("x", &Sym::rational(k.x.clone()))];
    let mut values = Vec::new();
    for (i, end, side, value) in [
        (k.knot - 1, End::End, "⁻", &k.left[r]),
        (k.knot, End::Start, "⁺", &k.right[r]),
    ] {
        let piece = &spline.pieces[i];
        let names = ["V", "W", "X", "Y"].map(|l| format!("{l}{i}"));
        let vars = names.clone().map(|n| Sym::var(&n));
        let formula = derivatives_of(&vars, &piece.m, &piece.h, end, Wrt::X)[r].clone();
        point.extend(
            names
                .iter()
                .zip(&piece.points)
                .map(|(n, v)| Assignment::exact(n, v)),
        );
        values.push(Value::new(format!("P{primes}({x}{side})"), Expr::new(value)).of(&formula));
    }
    Witness {
        point,
        note: Some(format!(
            "{} ({}), the pieces on either side of the knot: Vᵢ, Wᵢ, Xᵢ, Yᵢ are the control points of piece i, from the data point i (counted from 0); π kept as a symbol",
            spline.data.table.name, spline.variant
        )),
        values,
        exact: true,
        stated: None,
    }
}

/// f64 value of an exact expression in π (for display).
fn approx(x: &Sym) -> String {
    match x.eval(&0.0_f64, &|n: &str| {
        (n == "pi").then_some(std::f64::consts::PI)
    }) {
        Ok(value) => format!("{value:.6}"),
        Err(e) => format!("({e})"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;
    use trig_core::Family;

    fn table(name: &str) -> DataSet {
        DataSet::named(name).unwrap()
    }

    #[test]
    fn the_c1_scheme_is_c1_and_not_c2() {
        let data = table("thesis-table-4.1");
        let c1 = continuity(&Family::ThesisCubic, &data, Scheme::C1, 1);
        assert_eq!(c1.status, Status::Holds, "{:?}", c1.evidence);
        let c2 = continuity(&Family::ThesisCubic, &data, Scheme::C1, 2);
        assert_eq!(c2.status, Status::Fails);
        // the failing knots carry their one-sided values
        assert!(c2.evidence.iter().any(|e| e.witness.is_some()));
    }

    #[test]
    fn the_printed_c2_scheme_fails_and_its_corrected_variant_is_the_correction() {
        let v = continuity(
            &Family::ThesisCubic,
            &table("thesis-table-4.2"),
            Scheme::C2,
            2,
        );
        assert_eq!(v.status, Status::Fails);
        assert!(v.correction.is_some());
        assert!(
            v.evidence
                .iter()
                .any(|e| e.text.contains("(corrected), knot x = 4") && e.text.ends_with("→ C2"))
        );
    }

    #[test]
    fn equal_g1_factors_of_one_make_the_g1_scheme_c1() {
        let mut data = table("thesis-table-4.3");
        let v = continuity(&Family::ThesisCubic, &data, Scheme::G1, 1);
        assert_eq!(v.status, Status::Fails);
        let (_, n) = data.params.iter_mut().find(|(c, _)| c == "n").unwrap();
        n.iter_mut().for_each(|v| *v = Rational::from(1));
        let v = continuity(&Family::ThesisCubic, &data, Scheme::G1, 1);
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
    }
}
