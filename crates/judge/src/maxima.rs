//! The maxima judge: "each function has exactly one maximum on the
//! domain", decided by the certified count of [`trig_certify::maxima`].

use trig_certify::maxima::profile;
use trig_core::Described;
use trig_symbolic::Sym;

use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How maxima are counted, as the report states it.
pub const STURM: &str = "certified: sign changes of the derivative counted exactly — Weierstrass z = tan(θ/2) (or t), Sturm sequences over Q isolate every root of the numerator in (0, 1), signs evaluated exactly between roots";

/// Decides "each function has exactly one maximum on the domain" for the
/// given functions of `basis` (parameters already fixed), on the domains
/// `[0, π/2]` of the angle (`θ = πu/2` for `u ∈ [0, 1]`) and `[0, 1]` of
/// a polynomial variable.
pub fn exactly_one_maximum<B: Described>(basis: &B, fs: &[Sym]) -> Verdict {
    let Some(variable) = basis.variable() else {
        return Verdict::not_checkable(
            "maxima are counted on the catalog's domains only ([0, π/2] in the angle, [0, 1] in t)",
        );
    };
    let trig = variable.is_trigonometric();
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
