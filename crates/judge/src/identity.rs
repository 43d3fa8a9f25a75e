//! Printed identities in the functions of any basis, decided exactly: a
//! proof step, a printed value or derivative at a point, a printed
//! property of the curve `Σ bᵢPᵢ` (`check = "identity"`).
//!
//! An application `f^(k)(a·x + b)` is formed in the exact ring: the `k`-th
//! derivative in the variable `x` by the derivation `s ↦ ω·c`,
//! `c ↦ −ω·s`, `t ↦ 1`, `E ↦ κ·E` (`s = sin ωx`, `c = cos ωx`, `t = x`,
//! `E = exp κx`), then the argument substituted: the atoms at the exact
//! point `b` when `a = 0` (exact at multiples of π/12 and where `exp` is
//! exact), and for `a = ±1` by the sum formulas
//! `sin(ω(ax + b)) = a·s·cos ωb + c·sin ωb`,
//! `cos(ω(ax + b)) = c·cos ωb − a·s·sin ωb`, `t ↦ at + b`,
//! `E ↦ exp(κb)·E^a`. Each identity is then `lhs − rhs = 0` exactly, a
//! failure shown with its residual and a witness.
//!
//! A reading of a print (a garbled or mistyped identity read as the
//! document means it) is decided beside the print: where the print fails
//! and every failing print has a reading that holds, the claim holds after
//! the correction print → reading; otherwise the print's verdict stands,
//! the readings shown with it.

use trig_core::{Affine, Basis};
use trig_specfile::{Applied, Curve, Identity, Reading};
use trig_symbolic::Sym;
use trig_verdict::status::Status;

use crate::domain::param_symbols;
use crate::exact::{ExactBasis, identities, symbols};
use trig_verdict::verdict::Verdict;

/// Decides every printed identity; an application the exact ring cannot
/// form (an argument not linear with slope 0 or ±1, atoms not exact at
/// the point) leaves the claim `not-checkable` with the reason.
pub fn printed_identities<B: ExactBasis>(
    basis: &B,
    items: &[Identity],
    curve: Option<&Curve>,
    readings: &[Reading],
) -> Verdict {
    let parts = match sides(basis, items, curve) {
        Ok(parts) => parts,
        Err(v) => return v,
    };
    let printed = identities(parts);
    if printed.status == Status::Holds || readings.is_empty() {
        return printed;
    }
    let read_items: Vec<Identity> = readings.iter().map(|r| r.identity.clone()).collect();
    let read = match sides(basis, &read_items, curve) {
        Ok(read) => read,
        Err(v) => return v,
    };
    let read = read
        .into_iter()
        .zip(readings)
        .map(|((label, lhs, rhs), r)| {
            (
                format!("reading of {}: {label}", items[r.of].label),
                lhs,
                rhs,
            )
        })
        .collect();
    let decided = identities(read);
    let failing: Vec<usize> = printed
        .evidence
        .iter()
        .enumerate()
        .filter(|(_, e)| e.status == Some(Status::Fails))
        .map(|(i, _)| i)
        .collect();
    let every_failing_read = failing.iter().all(|i| readings.iter().any(|r| r.of == *i));
    let corrected = decided.status == Status::Holds && every_failing_read;
    let correction = readings
        .iter()
        .filter(|r| failing.contains(&r.of))
        .map(|r| format!("{} → {}", items[r.of].label, r.identity.label))
        .collect::<Vec<_>>()
        .join("; ");
    let mut v = printed;
    v.evidence.extend(decided.evidence);
    if corrected {
        v.status = Status::HoldsAfterCorrection;
        v = v.with_correction(format!("read {correction}"));
    }
    v
}

/// Each printed identity as `(label, lhs, rhs)` with its applications
/// formed in the exact ring; `Err` with the `not-checkable` verdict where
/// an argument is not formed exactly (a slope other than 0, ±1, atoms not
/// exact at the point).
pub fn sides<B: ExactBasis>(
    basis: &B,
    items: &[Identity],
    curve: Option<&Curve>,
) -> Result<Vec<(String, Sym, Sym)>, Verdict> {
    let functions = basis.exact_functions();
    let curve_value = curve.map(|k| curve_of(&functions, k.weighted));
    items
        .iter()
        .map(|item| {
            let (mut lhs, mut rhs) = (item.lhs.clone(), item.rhs.clone());
            for a in &item.applications {
                let f = match a.applied {
                    Applied::Function(i) => &functions[i],
                    Applied::Curve => curve_value.as_ref().expect("a curve read with its name"),
                };
                let Some(value) = applied(basis, f, a.order, &a.argument.x, &a.argument.rest)
                else {
                    return Err(Verdict::not_checkable(format!(
                        "in `{}`, the argument `{}` is not formed exactly (a slope other than 0, ±1 in the variable, or atoms not exact at that point)",
                        item.text, a.argument_text
                    )));
                };
                lhs = lhs.subs(&a.symbol, &value);
                rhs = rhs.subs(&a.symbol, &value);
            }
            Ok((item.label.clone(), lhs, rhs))
        })
        .collect()
}

/// `Σ bᵢPᵢ`, or `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`.
fn curve_of(functions: &[Sym], weighted: bool) -> Sym {
    let n = functions.len();
    let (p, w) = (symbols("P", n), symbols("w", n));
    let weight = |i: usize| {
        if weighted {
            functions[i].clone() * &w[i]
        } else {
            functions[i].clone()
        }
    };
    let numerator = (0..n).fold(Sym::zero(), |acc, i| acc + &(weight(i) * &p[i]));
    if weighted {
        let denominator = (0..n).fold(Sym::zero(), |acc, i| acc + &weight(i));
        numerator / &denominator
    } else {
        numerator
    }
}

/// `f^(order)(slope·x + at)` in the exact ring, or `None` where it cannot
/// be formed exactly.
pub fn applied<B: Basis>(
    basis: &B,
    f: &Sym,
    order: usize,
    slope: &Affine,
    at: &Affine,
) -> Option<Sym> {
    let domain = basis.domain();
    let params = param_symbols(basis);
    let zero = Sym::zero();
    let omega = domain.angle.as_ref().map(|w| w.eval(&zero, &params));
    let kappa = domain.exp.as_ref().map(|k| Sym::rational(k.clone()));
    let (s, c, t, e) = (Sym::var("s"), Sym::var("c"), Sym::var("t"), Sym::var("E"));
    let mut rules: Vec<(&str, Sym)> = vec![("t", Sym::one())];
    if let Some(w) = &omega {
        rules.push(("s", w.clone() * &c));
        rules.push(("c", -(w.clone() * &s)));
    }
    if let Some(k) = &kappa {
        rules.push(("E", k.clone() * &e));
    }
    let derivative = (0..order).fold(f.clone(), |g, _| g.derive(&rules));
    if !slope.params.is_empty() || slope.pi != 0 {
        return None;
    }
    let a = slope.constant.clone();
    if a == 0 {
        let atoms = domain.atoms_at(at, &Sym::one(), &params)?;
        return Some(crate::exact::at_atoms(&derivative, &atoms));
    }
    if a != 1 && a != -1 {
        return None;
    }
    let sign = Sym::rational(a.clone());
    // rename the atoms first: their images contain them
    let renamed = ["s", "c", "t", "E"]
        .iter()
        .fold(derivative, |g, v| g.subs(v, &Sym::var(&format!("__{v}"))));
    let mut images: Vec<(&str, Sym)> = vec![("__t", sign.clone() * &t + &at.eval(&zero, &params))];
    if let Some(w) = &domain.angle {
        let (sb, cb) = domain.sin_cos_of(&at.times(w)?, &zero, &params)?;
        images.push(("__s", sign.clone() * &s * &cb + &(c.clone() * &sb)));
        images.push(("__c", c.clone() * &cb - &(sign.clone() * &s * &sb)));
    }
    if let Some(k) = &domain.exp {
        let eb = domain.exp_of(&at.scale(k), &zero, &params)?;
        images.push(("__E", if a == 1 { eb * &e } else { eb / &e }));
    }
    Some(
        images
            .iter()
            .fold(renamed, |g, (v, image)| g.subs(v, image)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;
    use trig_core::Family;

    #[test]
    fn applications_at_points_and_reflections() {
        let family = Family::Seed002Quartic;
        let b = crate::exact::basis(family);
        let half_pi = Affine::pi_times(Rational::from((1, 2)));
        let one = Affine::rational(Rational::from(1));
        let minus = Affine::rational(Rational::from(-1));
        let zero = Affine::default();
        // b0(π/2 − t) = b5(t) (the printed symmetry of seed 002)
        let reflected = applied(&family, &b[0], 0, &minus, &half_pi).unwrap();
        assert_eq!(reflected, b[5]);
        // b0'(0) = −4, b0(π/2) = 0
        assert_eq!(
            applied(&family, &b[0], 1, &zero, &zero).unwrap(),
            Sym::int(-4)
        );
        assert_eq!(
            applied(&family, &b[0], 0, &zero, &half_pi).unwrap(),
            Sym::zero()
        );
        // the identity map leaves the function, a slope of 2 is refused
        assert_eq!(applied(&family, &b[1], 0, &one, &zero).unwrap(), b[1]);
        let two = Affine::rational(Rational::from(2));
        assert!(applied(&family, &b[1], 0, &two, &zero).is_none());
    }
}
