//! Seed 000, Appendix B (proof of Theorem 2): the coefficients `y₀…y₆` of
//! the middle piece `Σ b_{j+2,i} l_i(t)` in `z = tan(t/2)`, and the
//! conclusion that the piece is positive (M11).

use rug::Rational;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::{Family, Ring};
use trig_symbolic::Sym;

use super::seed000_appendix_print::{NONUNIFORM_J, nonuniform_knots, printed_part, zeta};
use crate::claim::Claim;
use trig_certify::nonneg::certify;
use trig_certify::{ParamBox, in_z};
use trig_judge::certificate::{CERTIFIED, describe};
use trig_judge::exact::{IDENTITY, basis, symbols};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "M11",
    check: m11,
}];

/// The printed `y_k` (Appendix B), `b_i = b_{j+2,i}`.
const PRINTED_Y: [&str; 7] = [
    "S(b0 + b2) + 4(S + 1)b1",
    "2(1 + 2S)(b2 - b0)",
    "(8 + 7S)(b0 + b2) + 4(S - 1)b1",
    "4(3 + 2S)(b2 - b0)",
    "(8 + 7S)(b0 + b2) + 4(S - 1)b3",
    "2(1 + 2S)(b2 - b0)",
    "S(b2 + b0) + 2(1 + 2S)b3 + 2b1",
];

/// `(1 + z²)³ · Σ b_i l_i` in `z`, a polynomial of degree ≤ 6; its
/// coefficients `y_k`.
pub(super) fn y_coefficients(b: &[Sym]) -> Vec<Sym> {
    let l = trig_core::families::seed000::blending(&Sym::var("s"), &Sym::var("c"), &zeta());
    let piece = (0..4).fold(Sym::zero(), |acc, i| acc + &(b[i].clone() * &l[i]));
    let z = Sym::var("z");
    let mut poly = in_z(&piece, true) * &(Sym::one() + &z.square()).powi(3);
    let mut factorial = Sym::one();
    (0..7)
        .map(|k| {
            if k > 0 {
                factorial = factorial.clone() * &Sym::int(k);
                poly = poly.diff("z");
            }
            poly.subs("z", &Sym::zero()) / &factorial
        })
        .collect()
}

fn m11() -> Verdict {
    let b = symbols("b", 4);
    let y = y_coefficients(&b);
    let mut parts: Vec<(String, Verdict)> = PRINTED_Y
        .iter()
        .enumerate()
        .map(|(k, text)| printed_part(format!("y_{k}"), text, &[], &y[k]))
        .collect();
    parts.push(("conclusion \"> 0\"".into(), conclusion()));
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(
        0,
        "b_i = b_{j+2,i} as symbols, S = s(ξ); y_k = coefficient of z^k in (1 + z²)³ Σ b_i l_i(t), sin t = 2z/(1+z²), cos t = (1−z²)/(1+z²); t ∈ [0, π/2] gives z ∈ [0, 1] (the print says t ∈ [0, 1])",
    );
    v
}

/// The conclusion, decided where the coefficients are known: the Appendix A
/// basis (uniform knots) and the printed non-uniform coefficients.
fn conclusion() -> Verdict {
    let mut parts = Vec::new();
    // uniform: the middle pieces are F1 = l1/D and F2 = l2/D; strict
    // positivity as F − 1/200 ≥ 0 (D ≤ 106 and l ≥ 3/4 on ζ ∈ [0, 4])
    let f = basis(Family::Seed000Uniform);
    let margin = Sym::rational(Rational::from((1, 200)));
    let bx = ParamBox::closed(Rational::new(), Rational::from(4));
    for (name, g) in [("F1", &f[1]), ("F2", &f[2])] {
        let what = format!("uniform (Appendix A) middle piece {name} − 1/200 ≥ 0, ζ ∈ [0, 4]");
        let shifted = g.clone() - &margin;
        let (status, line) = describe(
            &what,
            Some(&shifted),
            &certify(&shifted, true, Some("zeta"), &bx),
            true,
            Some("zeta"),
        );
        parts.push((what, Verdict::new(status, CERTIFIED, vec![line])));
    }
    // non-uniform knots, printed coefficients, ζ = 2 (inside [0, 4])
    let knots = nonuniform_knots();
    let f = NonUniform::new(knots, Sym::int(2));
    let (s, c) = (Sym::var("s"), Sym::var("c"));
    let j = NONUNIFORM_J;
    for piece in [1usize, 2] {
        let what = format!(
            "non-uniform knots (those of M3), ζ = 2: piece {piece} of F_{j} (= Σ {} l_k) ≥ 0",
            if piece == 1 { "c_{j+1,k}" } else { "b_{j+2,k}" }
        );
        let v = match f.bspline_piece(j, piece, &s, &c) {
            Ok(g) => {
                let (status, line) =
                    describe(&what, Some(&g), &certify(&g, true, None, &bx), true, None);
                Verdict::new(status, CERTIFIED, vec![line])
            }
            Err(e) => Verdict::new(
                Status::Fails,
                CERTIFIED,
                vec![format!("the printed coefficients are undefined: {e}")],
            ),
        };
        parts.push((what, v));
    }
    Verdict::all(CERTIFIED, parts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::seed000_appendix_print::read;

    fn printed(text: &str) -> Sym {
        read(text, &[]).unwrap().to_sym().unwrap()
    }

    #[test]
    fn y_coefficients_of_a_single_blending_function_are_its_expansion() {
        // b = (0, 1, 0, 0): (1+z²)³ l1 with l1(z = 0) = 4(S + 1), top coefficient l1(z → ∞) = 0
        let one = [0, 1, 0, 0].map(Sym::int);
        let y = y_coefficients(&one);
        assert_eq!(y[0], printed("4(S + 1)"));
        assert_eq!(y[6], Sym::zero());
        // printed y_6 puts 2b1 where the top coefficient has none
        assert_ne!(
            printed(PRINTED_Y[6])
                .subs("b1", &Sym::one())
                .subs("b0", &Sym::zero())
                .subs("b2", &Sym::zero())
                .subs("b3", &Sym::zero()),
            y[6]
        );
    }
}
