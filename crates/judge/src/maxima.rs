//! The maxima judge: "each function has exactly one maximum on the
//! domain", decided by the certified count of [`trig_certify::maxima`].

use trig_certify::maxima::profile;
use trig_core::{Described, Domain};
use trig_symbolic::Sym;

use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How maxima are counted, as the report states it.
pub const STURM: &str = "certified: sign changes of the derivative counted exactly — Weierstrass z = tan(θ/2) (or t), Sturm sequences over Q isolate every root of the numerator in (0, 1), signs evaluated exactly between roots";

/// Whether a spec file's named variable is counted as one of the catalog's
/// domains: `Some(false)` for polynomials in the variable on `[0, 1]`,
/// `Some(true)` for polynomials in `s = sin ωx`, `c = cos ωx` alone on
/// `[0, b]` with `ωb = π/2` (the angle then runs over `[0, π/2]`, and the
/// derivative in `x` is `ω` times the one in the angle: the same signs);
/// `None` otherwise.
fn named_variable_is_counted(d: &Domain) -> Option<bool> {
    if d.exp.is_some() || d.start.as_rational().is_none_or(|a| *a != 0) {
        return None;
    }
    match &d.angle {
        None => d
            .end
            .as_rational()
            .is_some_and(|b| *b == 1)
            .then_some(false),
        Some(omega) => (!d.uses_variable
            && omega.times(&d.end).and_then(|e| e.quarter_turns()) == Some(1))
        .then_some(true),
    }
}

/// Decides "each function has exactly one maximum on the domain" for the
/// given functions of `basis` (parameters already fixed), on the domains
/// `[0, π/2]` of the angle (`θ = πu/2` for `u ∈ [0, 1]`) and `[0, 1]` of
/// a polynomial variable — the catalog's variables, or a spec file's named
/// variable on those domains (`variable = "t"`, `domain = "[0, 1]"`).
pub fn exactly_one_maximum<B: Described>(basis: &B, fs: &[Sym]) -> Verdict {
    let trig = match basis.variable() {
        Some(variable) => variable.is_trigonometric(),
        None => match named_variable_is_counted(&basis.domain()) {
            Some(trig) => trig,
            None => {
                return Verdict::not_checkable(
                    "maxima are counted on the catalog's domains only ([0, π/2] in the angle, [0, 1] in t)",
                );
            }
        },
    };
    let mut status = Status::Holds;
    let mut evidence = Vec::new();
    for (f, name) in fs.iter().zip(basis.function_names()) {
        let (ok, line) = match profile(f, trig) {
            Ok(p) => {
                let signs: Vec<&str> = p
                    .signs
                    .iter()
                    .map(|s| if *s > 0 { "+" } else { "−" })
                    .collect();
                let at: Vec<String> = p.maxima.iter().map(|m| m.describe(trig)).collect();
                (
                    if p.maxima.len() == 1 {
                        Status::Holds
                    } else {
                        Status::Fails
                    },
                    format!(
                        "{name}: {name}' has {} distinct root(s) inside, sign pattern ({}); {} maximum(s): {}",
                        p.roots.len(),
                        signs.join(", "),
                        p.maxima.len(),
                        at.join("; ")
                    ),
                )
            }
            Err(why) => (Status::NotCheckable, format!("{name}: {why}")),
        };
        if ok != Status::Holds && status == Status::Holds {
            status = ok;
        }
        evidence.push(line);
    }
    Verdict::new(status, STURM, evidence)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_verdict::status::Status;

    fn spec(variable_and_domain: &str, formulas: &[&str]) -> trig_specfile::Spec {
        let mut text = format!("id = \"m\"\ncitation = \"test\"\n{variable_and_domain}\n");
        for (i, f) in formulas.iter().enumerate() {
            text += &format!("[[functions]]\nname = \"b{i}\"\nformula = \"{f}\"\n");
        }
        trig_specfile::Spec::from_str_named(&text, "m.toml").expect("spec")
    }

    /// A spec file's named variable on `[0, 1]` (or an angle on `[0, π/2]`)
    /// is counted as the catalog's polynomial (angle) variable is; other
    /// domains stay not checkable.
    #[test]
    fn a_named_variable_on_a_catalog_domain_is_counted() {
        let bernstein = ["(1 - t)^2", "2*t*(1 - t)", "t^2"];
        let s = spec("variable = \"t\"\ndomain = \"[0, 1]\"", &bernstein);
        let v = exactly_one_maximum(&s, &crate::exact::basis_of(&s));
        assert_eq!(v.status, Status::Holds, "{v:?}");
        // b1 = t(1 − t)(4 − 11t)... two maxima: inside and at t = 1
        let two = ["1 - t", "t*(1 - t)*(4 - 11*t)", "t"];
        let s = spec("variable = \"t\"\ndomain = \"[0, 1]\"", &two);
        let v = exactly_one_maximum(&s, &crate::exact::basis_of(&s));
        assert_eq!(v.status, Status::Fails, "{v:?}");
        let s = spec(
            "variable = \"t\"\ndomain = \"[0, pi/2]\"",
            &["1 - sin(t)", "sin(t) + cos(t) - 1", "1 - cos(t)"],
        );
        let v = exactly_one_maximum(&s, &crate::exact::basis_of(&s));
        assert_eq!(v.status, Status::Holds, "{v:?}");
        let s = spec("variable = \"t\"\ndomain = \"[0, 2]\"", &bernstein);
        let v = exactly_one_maximum(&s, &crate::exact::basis_of(&s));
        assert_eq!(v.status, Status::NotCheckable, "{v:?}");
    }
}
