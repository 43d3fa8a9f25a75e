//! The Fourier-span judge: which trigonometric span a basis's functions lie
//! in (`check = "fourier-span"`, "the blending functions are constructed in
//! the space {1, sin t, cos t, cos 2t, …}").
//!
//! A trigonometric polynomial in `s = sin ωx`, `c = cos ωx` has an exact
//! Fourier expansion `a₀ + Σ aₖ cos kωx + bₖ sin kωx`. In the ring's normal
//! form (`s² = 1 − c²`) the monomials `cᵇ`, `s·cᵇ` are independent, and
//! `cos bωx` (`sin (b+1)ωx`) is the only harmonic whose normal form has the
//! leading monomial `cᵇ` (`s·cᵇ`) in `c`; peeling leading terms solves the
//! triangular system exactly. Each printed span element must itself be one
//! harmonic (`1`, `cos kωx`, `sin kωx`); a function lies in the printed
//! span exactly when every harmonic of its expansion is printed.

use rug::Rational;
use trig_symbolic::{Poly, Sym};
use trig_verdict::evidence::EvidenceList;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::exact::ExactBasis;

/// How the span is decided, as the report states it.
pub const METHOD: &str = "exact: Fourier expansion of each b_i in Q[s, c]/(s² + c² − 1), triangular solve on the normal-form basis c^k, s·c^k";

/// A harmonic: `1` (`k = 0`), `cos kωx` or `sin kωx`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct Harmonic {
    /// Sines after cosines (`1` is the cosine of order 0).
    pub sine: bool,
    pub k: usize,
}

impl Harmonic {
    /// As printed, `angle` the angle `ωx` (`sin 3t`, `cos t`, `1`).
    pub fn label(&self, angle: &str) -> String {
        let f = if self.sine { "sin" } else { "cos" };
        match self.k {
            0 => "1".into(),
            1 => format!("{f} {angle}"),
            k => format!("{f} {k}{angle}"),
        }
    }

    /// Its normal form in `s`, `c`, by `cos(k+1)θ = c cos kθ − s sin kθ`,
    /// `sin(k+1)θ = s cos kθ + c sin kθ`.
    fn value(&self) -> Sym {
        let (s, c) = (Sym::var("s"), Sym::var("c"));
        let (mut cos, mut sin) = (Sym::one(), Sym::zero());
        for _ in 0..self.k {
            let next = c.clone() * &cos - &(s.clone() * &sin);
            sin = s.clone() * &cos + &(c.clone() * &sin);
            cos = next;
        }
        if self.sine { sin } else { cos }
    }
}

/// The coefficient of `s^a c^b` in the normal form.
fn coeff(p: &Poly, a: u32, b: u32) -> Rational {
    p.terms()
        .find(|(m, _)| m.exponent("s") == a && m.exponent("c") == b)
        .map_or(Rational::new(), |(_, q)| q.to_rational())
}

/// The exact Fourier expansion of `f`, harmonics in order (cosines, then
/// sines, each by `k`), or why `f` is not a trigonometric polynomial with
/// rational coefficients in `s`, `c` alone.
pub fn expansion(f: &Sym) -> Result<Vec<(Harmonic, Rational)>, String> {
    if !f.denominator().is_empty() {
        return Err(format!("{f} is not a trigonometric polynomial"));
    }
    let mut rest = f.clone();
    let mut out: Vec<(Harmonic, Rational)> = Vec::new();
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
        let h = Harmonic {
            sine: a != 0,
            k: b as usize + usize::from(a != 0),
        };
        let g = h.value();
        let q = coeff(rest.numerator(), a, b) / coeff(g.numerator(), a, b);
        rest = rest - &(Sym::rational(q.clone()) * &g);
        out.push((h, q));
    }
    out.sort_by_key(|(h, _)| (h.sine, h.k));
    Ok(out)
}

/// The angle `ωx` as the labels print it (`t` when `ω = 1`).
fn angle_of<B: ExactBasis>(basis: &B) -> String {
    let domain = basis.domain();
    let omega = domain
        .angle
        .as_ref()
        .map(|w| w.eval(&Sym::zero(), &crate::domain::param_symbols(basis)));
    match omega {
        Some(w) if !(w.clone() - &Sym::one()).is_zero() => {
            format!("({}·{})", w.to_unicode(), domain.name)
        }
        _ => domain.name,
    }
}

/// Whether every function of `basis` lies in the printed span (`span`:
/// each element as printed, with its value in the exact ring).
pub fn in_span<B: ExactBasis>(basis: &B, span: &[(String, Sym)]) -> Verdict {
    let angle = angle_of(basis);
    let mut printed: Vec<Harmonic> = Vec::new();
    for (text, value) in span {
        match expansion(value).as_deref() {
            Ok([(h, q)]) if *q == 1 => printed.push(*h),
            _ => {
                return Verdict::not_checkable(format!(
                    "the printed span element `{text}` is not one harmonic (1, cos k{angle} or sin k{angle})"
                ));
            }
        }
    }
    let mut status = Status::Holds;
    let mut evidence = EvidenceList::default();
    let mut degree = printed.iter().map(|h| h.k).max().unwrap_or(0);
    for (f, name) in basis.exact_functions().iter().zip(basis.function_names()) {
        let terms = match expansion(f) {
            Ok(terms) => terms,
            Err(why) => {
                status = Status::NotCheckable;
                evidence.push(format!("{name}: {why}"));
                continue;
            }
        };
        degree = degree.max(terms.iter().map(|(h, _)| h.k).max().unwrap_or(0));
        let rebuilt = terms.iter().fold(Sym::zero(), |acc, (h, q)| {
            acc + &(Sym::rational(q.clone()) * &h.value())
        });
        let parts: Vec<(String, String)> = terms
            .iter()
            .map(|(h, q)| (Sym::rational(q.clone()).to_unicode(), h.label(&angle)))
            .collect();
        let expanded = trig_symbolic::combine(&parts, trig_symbolic::Style::Unicode);
        let outside: Vec<String> = terms
            .iter()
            .filter(|(h, _)| !printed.contains(h))
            .map(|(h, q)| format!("{}: {q}", h.label(&angle)))
            .collect();
        let verdict = if outside.is_empty() {
            "in the printed span".to_string()
        } else {
            status = Status::Fails;
            format!("outside the printed span: {}", outside.join(", "))
        };
        let again = if (rebuilt - f).is_zero() {
            "re-expanded it equals"
        } else {
            status = Status::NotCheckable;
            "re-expanded it differs from"
        };
        evidence.push(format!(
            "{name} = {expanded} (exact; {again} {name} identically) — {verdict}"
        ));
    }
    let missing: Vec<String> = (0..=degree)
        .flat_map(|k| [false, true].map(|sine| Harmonic { sine, k }))
        .filter(|h| (!h.sine || h.k > 0) && !printed.contains(h))
        .map(|h| h.label(&angle))
        .collect();
    let space = format!(
        "the {}-dimensional space of trigonometric polynomials of degree ≤ {degree}",
        2 * degree + 1
    );
    evidence.push(if missing.is_empty() {
        format!("the printed span is {space}")
    } else {
        format!(
            "the printed span has {} functions but omits {} from {space}",
            printed.len(),
            missing.join(", ")
        )
    });
    Verdict::new(status, METHOD, evidence)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expansion_finds_sin_two_t_and_the_cube_of_the_cosine() {
        // 2sc = sin 2t; c³ = (3 cos t + cos 3t)/4
        let (s, c) = (Sym::var("s"), Sym::var("c"));
        let h = |sine, k| Harmonic { sine, k };
        let two_sc = Sym::int(2) * &s * &c;
        assert_eq!(
            expansion(&two_sc).unwrap(),
            vec![(h(true, 2), Rational::from(1))]
        );
        let c3 = c.clone() * &c * &c;
        assert_eq!(
            expansion(&c3).unwrap(),
            vec![
                (h(false, 1), Rational::from((3, 4))),
                (h(false, 3), Rational::from((1, 4)))
            ]
        );
        assert!(expansion(&(s / &c)).is_err());
        assert_eq!(h(true, 2).label("t"), "sin 2t");
        assert_eq!(h(false, 0).label("t"), "1");
    }
}
