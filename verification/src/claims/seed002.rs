//! Seed 002 (Dube & Mishra 2017): the quartic trigonometric Bézier basis and
//! the rational curve.

use rug::Rational;
use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::{Poly, Sym};

use crate::claim::Claim;
use trig_judge::exact::basis;
use trig_verdict::evidence::EvidenceList;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "D11",
    check: d11,
}];

/// `R, R', R''` (in θ) of the rational curve at `θ = 0` and `θ = π/2`, with
/// control points `P0…P5` and weights `w0…w5` as symbols.
pub(super) fn rational_ends(p: &[Sym], w: &[Sym]) -> (Vec<Sym>, Vec<Sym>) {
    let at = |end| {
        curve_endpoint_derivatives::<Sym, 3>(
            Family::Seed002Quartic,
            &[],
            p,
            Some(w),
            end,
            Wrt::Angle,
            &Sym::one(),
        )
    };
    (at(End::Start), at(End::End))
}

/// `cos kθ`, `sin kθ` for `k = 0…n` as polynomials in `s`, `c`:
/// `cos(k+1)θ = c cos kθ − s sin kθ`, `sin(k+1)θ = s cos kθ + c sin kθ`.
fn fourier_basis(n: usize) -> (Vec<Sym>, Vec<Sym>) {
    let (s, c) = (Sym::var("s"), Sym::var("c"));
    let (mut cos, mut sin) = (vec![Sym::one()], vec![Sym::zero()]);
    for k in 0..n {
        let (ck, sk) = (cos[k].clone(), sin[k].clone());
        cos.push(c.clone() * &ck - &(s.clone() * &sk));
        sin.push(s.clone() * &ck + &(c.clone() * &sk));
    }
    (cos, sin)
}

fn fourier_label(k: usize, sine: bool) -> String {
    match (k, sine) {
        (0, _) => "1".into(),
        (1, true) => "sin t".into(),
        (1, false) => "cos t".into(),
        (k, true) => format!("sin {k}t"),
        (k, false) => format!("cos {k}t"),
    }
}

/// The coefficient of `s^a c^b` in the reduced normal form.
fn coeff(p: &Poly, a: u32, b: u32) -> Rational {
    p.terms()
        .find(|(m, _)| m.exponent("s") == a && m.exponent("c") == b)
        .map_or(Rational::new(), |(_, q)| q.to_rational())
}

/// The exact Fourier expansion `Σ a_k cos kθ + b_k sin kθ` of a polynomial
/// in `s`, `c`: the normal form has basis `cᵇ`, `s·cᵇ`, and `cos bθ`
/// (`sin (b+1)θ`) is the only Fourier term whose normal form has the leading
/// monomial `cᵇ` (`s·cᵇ`); peeling leading terms solves the triangular
/// system exactly.
fn fourier(f: &Sym) -> Result<Vec<(String, Rational)>, String> {
    if !f.denominator().is_empty() {
        return Err(format!("{f} is not a trigonometric polynomial"));
    }
    let n = f.numerator().degree_in("c") as usize + 1;
    let (cos, sin) = fourier_basis(n);
    let mut rest = f.clone();
    let mut out: Vec<(String, Rational)> = Vec::new();
    while !rest.is_zero() {
        let mut lead = None;
        for (m, _) in rest.numerator().terms() {
            let (a, b) = (m.exponent("s"), m.exponent("c"));
            if u64::from(a + b) != m.degree() {
                return Err(format!("{f} depends on symbols other than s, c"));
            }
            if lead.is_none_or(|(_, lb)| b > lb) {
                lead = Some((a, b));
            }
        }
        let (a, b) = lead.expect("nonzero");
        let (k, sine) = if a == 0 {
            (b as usize, false)
        } else {
            (b as usize + 1, true)
        };
        let g = if sine { &sin[k] } else { &cos[k] };
        let q = coeff(rest.numerator(), a, b) / coeff(g.numerator(), a, b);
        rest = rest - &(Sym::rational(q.clone()) * g);
        out.push((fourier_label(k, sine), q));
    }
    out.sort_by_key(|(l, _)| {
        let k: usize = l
            .split_whitespace()
            .nth(1)
            .and_then(|x| x.trim_end_matches('t').parse().ok())
            .unwrap_or(1);
        (l.starts_with("sin"), if l == "1" { 0 } else { k })
    });
    Ok(out)
}

/// The printed span of Theorem 2 (5).
const PRINTED_SPAN: [&str; 8] = [
    "1", "sin t", "cos t", "cos 2t", "sin 3t", "cos 3t", "sin 4t", "cos 4t",
];

fn d11() -> Verdict {
    let b = basis(Family::Seed002Quartic);
    let names = Family::Seed002Quartic.info().functions;
    let mut status = Status::Holds;
    let mut evidence = EvidenceList::default();
    for (f, name) in b.iter().zip(names) {
        match fourier(f) {
            Ok(terms) => {
                // `c·l` with the sign in front, the constant term as `c`
                let parts: Vec<(String, String)> = terms
                    .iter()
                    .map(|(l, q)| (Sym::rational(q.clone()).to_unicode(), l.clone()))
                    .collect();
                let expansion = [trig_symbolic::combine(
                    &parts,
                    trig_symbolic::Style::Unicode,
                )];
                let outside: Vec<String> = terms
                    .iter()
                    .filter(|(l, _)| !PRINTED_SPAN.contains(&l.as_str()))
                    .map(|(l, q)| format!("{l}: {q}"))
                    .collect();
                let verdict = if outside.is_empty() {
                    "in the printed span".to_string()
                } else {
                    status = Status::Fails;
                    format!("outside the printed span: {}", outside.join(", "))
                };
                evidence.push(format!(
                    "{name} = {} (exact; re-expanded it equals {name} identically) — {verdict}",
                    expansion.join(" + ")
                ));
            }
            Err(why) => {
                status = Status::NotCheckable;
                evidence.push(format!("{name}: {why}"));
            }
        }
    }
    evidence.push("the printed span has 8 functions but omits sin 2t from the 9-dimensional space of trigonometric polynomials of degree ≤ 4; the rational blending functions w_i b_i / Σ w_j b_j equal b_i when all weights are equal (Σ b_j = 1, D1b), so the polynomial b_i decide the claim");
    Verdict::new(
        status,
        "exact: Fourier expansion of each b_i in Q[s, c]/(s² + c² − 1), triangular solve on the normal-form basis c^k, s·c^k",
        evidence,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fourier_expansion_finds_sin_two_t_and_rebuilds_the_function() {
        // 2sc = sin 2t lies outside the printed span; c³ = (3cos t + cos 3t)/4 inside
        let (s, c) = (Sym::var("s"), Sym::var("c"));
        let two_sc = Sym::int(2) * &s * &c;
        assert_eq!(
            fourier(&two_sc).unwrap(),
            vec![("sin 2t".to_string(), Rational::from(1))]
        );
        let c3 = c.clone() * &c * &c;
        assert_eq!(
            fourier(&c3).unwrap(),
            vec![
                ("cos t".to_string(), Rational::from((3, 4))),
                ("cos 3t".to_string(), Rational::from((1, 4)))
            ]
        );
        assert!(fourier(&(s / &c)).is_err());
    }
}
