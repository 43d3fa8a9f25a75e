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
//! `E ↦ exp(κb)·E^a`. At a point (`a = 0`) a derivative of order 1–5 is
//! formed by Taylor jets instead ([`crate::point_jet`]: the same exact
//! value, without the symbolic derivative of a large quotient). Each identity is then `lhs − rhs = 0` exactly, a
//! failure shown with its residual and a witness.
//!
//! Under a change of variable (`change = { x = "(x - x_i)/h_i" }`, a basis
//! polynomial in its variable `t`) each application `f^(k)(a)` is
//! `dᵏ/dxᵏ f(φ(x))` at `x = a`, `φ` the printed formula, formed by
//! substitution and differentiation in the ring (the chain rule exactly);
//! a bare function name is `f(φ(x))`.
//!
//! A reading of a print (a garbled or mistyped identity read as the
//! document means it) is decided beside the print: where the print fails
//! and every failing print has a reading that holds, the claim holds after
//! the correction print → reading; otherwise the print's verdict stands,
//! the readings shown with it.

use trig_core::{Affine, Basis};
use trig_specfile::{Applied, Argument, Change, Correction, Curve, Identity, Let, Reading};
use trig_symbolic::Sym;
use trig_verdict::status::Status;

use crate::domain::param_symbols;
use crate::exact::{ExactBasis, identities_where, symbols};
use trig_verdict::verdict::Verdict;

/// An identity claim as read from its fields (`check = "identity"`).
#[derive(Debug, Clone, Copy)]
pub struct Printed<'a> {
    pub identities: &'a [Identity],
    pub curves: &'a [Curve],
    pub readings: &'a [Reading],
    pub lets: &'a [Let],
    pub change: Option<&'a Change>,
    pub correction: Option<&'a Correction>,
    /// Symbols the claim's conditions make positive: witnesses lie there.
    pub positive: &'a [String],
}

impl<'a> Printed<'a> {
    /// The fields of an identity claim's check; `None` for another check.
    pub fn of(check: &'a trig_specfile::Check) -> Option<Printed<'a>> {
        let trig_specfile::Check::Identity {
            identities,
            curves,
            readings,
            lets,
            change,
            correction,
            positive,
        } = check
        else {
            return None;
        };
        Some(Printed {
            identities,
            curves,
            readings,
            lets,
            change: change.as_ref(),
            correction: correction.as_ref(),
            positive,
        })
    }
}

/// Decides every printed identity (the claim's `let` names substituted
/// with the applications); an application the exact ring cannot
/// form (an argument not linear with slope 0 or ±1, atoms not exact at
/// the point) leaves the claim `not-checkable` with the reason.
pub fn printed_identities<B: ExactBasis>(basis: &B, claim: &Printed<'_>) -> Verdict {
    let v = read_identities(basis, claim);
    match claim.correction {
        Some(correction) if v.status == Status::Fails => corrected(basis, v, correction, claim),
        _ => v,
    }
}

/// A print that fails with its correction decided beside it: the claim
/// still fails (the print is wrong, not mistyped); the correction's
/// identities are shown as its part, and where every one holds the
/// correction is named.
fn corrected<B: ExactBasis>(
    basis: &B,
    mut v: Verdict,
    correction: &Correction,
    claim: &Printed<'_>,
) -> Verdict {
    let decided = match sides(
        basis,
        &correction.identities,
        claim.curves,
        claim.lets,
        claim.change,
    ) {
        Ok(parts) => identities_where(parts, claim.positive),
        Err(not_formed) => not_formed,
    };
    let holds = decided.status == Status::Holds;
    v.evidence.extend(decided.into_part(&correction.says));
    if holds {
        v.with_correction(correction.says.clone())
    } else {
        v
    }
}

/// The printed identities with their readings.
fn read_identities<B: ExactBasis>(basis: &B, claim: &Printed<'_>) -> Verdict {
    let Printed {
        identities: items,
        curves,
        readings,
        lets,
        change,
        positive,
        ..
    } = *claim;
    let parts = match sides(basis, items, curves, lets, change) {
        Ok(parts) => parts,
        Err(v) => return v,
    };
    let printed = identities_where(parts, positive);
    if printed.status == Status::Holds || readings.is_empty() {
        return with_change(printed, change);
    }
    let read_items: Vec<Identity> = readings.iter().map(|r| r.identity.clone()).collect();
    let read = match sides(basis, &read_items, curves, lets, change) {
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
    let decided = identities_where(read, positive);
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
    with_change(v, change)
}

/// Each printed identity as `(label, lhs, rhs)` with its applications
/// (and the claim's `let` names) formed in the exact ring; `Err` with the
/// `not-checkable` verdict where an argument is not formed exactly (a
/// slope other than 0, ±1, atoms not exact at the point), a denominator
/// vanishes once the functions are applied, or a change of variable is
/// asked of a basis not polynomial in its variable.
pub fn sides<B: ExactBasis>(
    basis: &B,
    items: &[Identity],
    curves: &[Curve],
    lets: &[Let],
    change: Option<&Change>,
) -> Result<Vec<(String, Sym, Sym)>, Verdict> {
    let functions = basis.exact_functions();
    let domain = basis.domain();
    if change.is_some() && (domain.angle.is_some() || domain.exp.is_some()) {
        return Err(Verdict::not_checkable(
            "a change of variable is formed exactly for a basis polynomial in its variable only",
        ));
    }
    let curve_values: Vec<Sym> = curves.iter().map(|k| curve_of(&functions, k)).collect();
    // the identities formed side by side (a long print's sides are the
    // audit's costliest exact work: Appendix E's sixteen, M15)
    trig_core::parallel::map(items, |item| {
                let mut values: Vec<(&str, Sym)> = lets
                    .iter()
                    .map(|l| (l.name.as_str(), l.value.clone()))
                    .collect();
                for a in &item.applications {
                    let f = match a.applied {
                        Applied::Function(i) => &functions[i],
                        Applied::Curve(k) => &curve_values[k],
                        Applied::Let(i) => &lets[i].value,
                    };
                    // a curve with its own change of variable (a spline's next segment)
                    let own = match a.applied {
                        Applied::Curve(k) => curves[k].change.as_ref(),
                        _ => None,
                    };
                    let value = match (&a.argument, change) {
                        (Argument::Formula(x), Some(change)) => Some(match own {
                            Some(own) => changed(f, a.order, &Change { value: own.clone(), ..change.clone() }, x),
                            None => changed(f, a.order, change, x),
                        }),
                        (Argument::Linear(l), None) => applied(basis, f, a.order, &l.x, &l.rest),
                        _ => None,
                    };
                    let Some(value) = value else {
                        return Err(Verdict::not_checkable(format!(
                            "in `{}`, the argument `{}` is not formed exactly (a slope other than 0, ±1 in the variable, or atoms not exact at that point)",
                            item.text, a.argument_text
                        )));
                    };
                    values.push((&a.symbol, value));
                }
                let (mut lhs, mut rhs) = match (
                    item.lhs.subs_all(&values),
                    item.rhs.subs_all(&values),
                ) {
                    (Ok(lhs), Ok(rhs)) => (lhs, rhs),
                    (Err(e), _) | (_, Err(e)) => {
                        return Err(Verdict::not_checkable(format!(
                            "in `{}`, a denominator vanishes identically once the functions are applied: {e}",
                            item.text
                        )));
                    }
                };
                if let Some(change) = change {
                    lhs = lhs.subs(VARIABLE, &change.value);
                    rhs = rhs.subs(VARIABLE, &change.value);
                }
                Ok((item.label.clone(), lhs, rhs))
    })
    .into_iter()
    .collect()
}

/// The verdict with the change of variable stated first.
fn with_change(mut v: Verdict, change: Option<&Change>) -> Verdict {
    if let Some(change) = change {
        v.evidence.insert(
            0,
            format!(
                "change of variable: {VARIABLE} = {} = {} in {x}, derivatives in {x}",
                change.text,
                change.value.to_unicode(),
                x = change.variable
            ),
        );
    }
    v
}

/// The ring's symbol of the variable of a basis polynomial in it.
const VARIABLE: &str = "t";

/// `dᵏ/dxᵏ f(φ(x))` at `x = at` (`x` the new variable of the change, `φ`
/// its printed formula), for `f` polynomial in the variable.
fn changed(f: &Sym, order: usize, change: &Change, at: &Sym) -> Sym {
    let x = change.variable.as_str();
    let composed = f.subs(VARIABLE, &change.value);
    (0..order).fold(composed, |g, _| g.diff(x)).subs(x, at)
}

/// `Σ bᵢPᵢ`, `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`, or `Σ bᵢ·pointᵢ` of printed points.
fn curve_of(functions: &[Sym], curve: &Curve) -> Sym {
    let n = functions.len();
    let weighted = curve.weighted;
    let (p, w) = match &curve.points {
        Some(points) => (points.clone(), Vec::new()),
        None => (symbols("P", n), symbols("w", n)),
    };
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
    if !slope.params.is_empty() || slope.pi != 0 {
        return None;
    }
    let a = slope.constant.clone();
    if a == 0 {
        let atoms = domain.atoms_at(at, &Sym::one(), &params)?;
        // a derivative at a point: by Taylor jets (crate::point_jet)
        if let Some(v) = (order > 0)
            .then(|| {
                crate::point_jet::derivative_at(f, order, &atoms, omega.as_ref(), kappa.as_ref())
            })
            .flatten()
        {
            return Some(v);
        }
        let derivative = (0..order).fold(f.clone(), |g, _| g.derive(&rules));
        return Some(crate::exact::at_atoms(&derivative, &atoms));
    }
    let derivative = (0..order).fold(f.clone(), |g, _| g.derive(&rules));
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

    /// The catalog basis `file` with one identity claim of the fields
    /// `fields`, decided.
    fn identity_claim(file: &str, fields: &str) -> Verdict {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog")
            .join(file);
        let text = std::fs::read_to_string(path).unwrap();
        let spec = trig_specfile::Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"c\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"identity\"\n{fields}\n"
            ),
            "c.toml",
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let printed = Printed::of(&spec.claims[0].check).expect("an identity claim");
        printed_identities(&spec, &printed)
    }

    /// The subjects of the failing items of `v`.
    fn failing(v: &Verdict) -> Vec<&str> {
        v.evidence
            .iter()
            .filter(|e| e.status == Some(Status::Fails))
            .filter_map(|e| e.subject.as_deref())
            .collect()
    }

    /// The thesis cubic with one identity claim about the piece of printed
    /// control points `points` (the C¹ interpolant (4.21) of seed 001).
    fn piece_claim(points: &str) -> Verdict {
        identity_claim(
            "thesis-cubic.toml",
            &format!(
                "symbols = [\"f0\", \"f1\", \"d0\", \"d1\", \"h\"]\ncurves = [{{ name = \"P\", points = [{points}] }}]\nidentities = [\"P(0) = f0\", \"P(1) = f1\", \"P'(0)/h = d0\", \"P'(1)/h = d1\"]"
            ),
        )
    }

    #[test]
    fn a_curve_of_printed_control_points_is_decided_through_them() {
        let c1 = r#""f0", "2*h*d0/(pi*(m + 2)) + f0", "-2*h*d1/(pi*(m + 2)) + f1", "f1""#;
        assert_eq!(piece_claim(c1).status, Status::Holds);
        // a sign flipped in X fails the end slope
        let wrong = r#""f0", "2*h*d0/(pi*(m + 2)) + f0", "2*h*d1/(pi*(m + 2)) + f1", "f1""#;
        let v = piece_claim(wrong);
        assert_eq!(v.status, Status::Fails);
        assert_eq!(failing(&v), ["P'(1)/h = d1"]);
    }

    /// The Hermite basis (seed 004 §II) with one identity claim `claim`.
    fn hermite_claim(claim: &str) -> Verdict {
        identity_claim("hermite.toml", claim)
    }

    #[test]
    fn a_curve_with_its_own_change_is_the_next_segment() {
        // segment i on [x_i, x_i + h], segment i + 1 with its own t = (x − x_i − h)/k:
        // C¹ at the knot exactly when the end slopes carry the same factor
        let claim = |factor: &str| {
            format!(
                "symbols = [\"x_i\", \"h\", \"k\", \"y0\", \"y1\", \"y2\", \"d0\", \"d1\", \"d2\"]\nchange = {{ x = \"(x - x_i)/h\" }}\ncurves = [{{ name = \"A\", points = [\"y0\", \"y1\", \"h*d0\", \"{factor}*d1\"] }}, {{ name = \"B\", points = [\"y1\", \"y2\", \"k*d1\", \"k*d2\"], change = \"(x - x_i - h)/k\" }}]\nidentities = [\"B(x_i + h) = A(x_i + h)\", \"B'(x_i + h) = A'(x_i + h)\"]"
            )
        };
        assert_eq!(hermite_claim(&claim("h")).status, Status::Holds);
        let v = hermite_claim(&claim("k"));
        assert_eq!(v.status, Status::Fails);
        assert_eq!(failing(&v), ["B'(x_i + h) = A'(x_i + h)"]);
    }

    #[test]
    fn a_witness_lies_where_the_claim_makes_its_symbols_positive() {
        // λ·α₀(0) = 2 fails; its simplest witness is λ = 0 unless the
        // claim's conditions make λ positive
        let point = |positive: &str| {
            let v = hermite_claim(&format!(
                "symbols = [\"lambda\"]\n{positive}\nidentities = [\"lambda*alpha_0(0) = 2\"]"
            ));
            assert_eq!(v.status, Status::Fails);
            let w = v.evidence[0].witness.clone().expect("a witness");
            w.point[0].value.clone()
        };
        assert_eq!(point(""), "0");
        assert_eq!(point("positive = [\"lambda\"]"), "1");
    }

    #[test]
    fn a_correction_leaves_the_print_failing_and_is_named_where_it_holds() {
        let claim = |corrected: &str| {
            format!(
                "identities = [\"alpha_0(1) = 1\", \"alpha_1(1) = 1\"]\ncorrection = {{ says = \"alpha_0(1) = 0\", identities = [\"{corrected}\"] }}"
            )
        };
        let v = hermite_claim(&claim("alpha_0(1) = 0"));
        assert_eq!(v.status, Status::Fails);
        assert_eq!(v.correction.as_deref(), Some("alpha_0(1) = 0"));
        // a correction that fails too is shown, never named
        let v = hermite_claim(&claim("alpha_0(1) = 2"));
        assert_eq!(v.status, Status::Fails);
        assert_eq!(v.correction, None);
        assert!(
            v.evidence
                .iter()
                .any(|e| e.subject.as_deref() == Some("alpha_0(1) = 2"))
        );
        // a print that holds leaves the correction undecided
        let v = hermite_claim(
            "identities = [\"alpha_1(1) = 1\"]\ncorrection = { says = \"x\", identities = [\"alpha_0(1) = 2\"] }",
        );
        assert_eq!((v.status, v.evidence.len()), (Status::Holds, 1));
    }
}
