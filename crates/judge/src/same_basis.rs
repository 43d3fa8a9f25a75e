//! "This basis is that one under a change of parameter and variable"
//! (`check = "same-basis"`): `bᵢ(x; p) = gᵢ(x′; q(p))` for every `i`,
//! decided exactly in the ring `Q(p)[s, c]/(s² + c² − 1)`.
//!
//! The other basis's parameters `q` are printed as formulas in this
//! basis's parameters (`λ = m`, `η = m + 1`), substituted at once. The
//! variables are identified through the ring's atoms: two trigonometric
//! bases through their common angle `θ = ωx = ω′x′` (the thesis's
//! `θ = πu/2` on `u ∈ [0, 1]` and Majeed & Qayyum's `θ = t` on
//! `t ∈ [0, π/2]`), two polynomial bases through `t = t′`; the change of
//! variable is a change of variable of the bases only when it maps one
//! domain onto the other, which is checked on the ends (constant ends).
//! Bases in other atoms, parameter atoms (`sin α`) of the other basis, or
//! domains that do not correspond are `not-checkable`, with the reason.

use rug::Rational;
use trig_core::range::End;
use trig_core::{Affine, Domain, ParamRange};
use trig_symbolic::Sym;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::exact::{ExactBasis, IDENTITY, identity_item};

/// Decides `bᵢ = gᵢ` for each function, `other`'s parameters replaced by
/// `params` (`(name, formula in this basis's parameters)`, every one of
/// `other`'s), `params_text` as printed.
pub fn same_basis<A: ExactBasis, B: ExactBasis>(
    this: &A,
    other: &B,
    params: &[(String, Sym)],
    params_text: &str,
) -> Verdict {
    let (here, there) = (this.domain(), other.domain());
    let variables = match identified(&here, &there) {
        Ok(text) => text,
        Err(why) => return Verdict::not_checkable(why),
    };
    if !there.param_angles.is_empty() || !there.param_exps.is_empty() {
        return Verdict::not_checkable(format!(
            "{} has parameters inside sines or exponentials: a formula cannot be substituted for them in the exact ring",
            other.id()
        ));
    }
    let (f, g) = (this.exact_functions(), other.exact_functions());
    let (names, other_names) = (this.function_names(), other.function_names());
    if f.len() != g.len() {
        return Verdict::new(
            Status::Fails,
            IDENTITY,
            [format!(
                "{} has {} functions, {} has {}: no change of parameter makes them one basis",
                this.id(),
                f.len(),
                other.id(),
                g.len()
            )],
        );
    }
    let substituted: Vec<Sym> = g.iter().map(|gi| substitute(gi, params)).collect();
    let items: Vec<Evidence> = (0..f.len())
        .map(|i| {
            identity_item(
                &format!(
                    "{} − {} {} ({params_text})",
                    names[i],
                    other.id(),
                    other_names[i]
                ),
                &f[i],
                &substituted[i],
            )
        })
        .collect();
    let status = Status::conjunction(items.iter().filter_map(|e| e.status));
    let mut v = Verdict::new(status, IDENTITY, items);
    v.evidence.insert(0, Evidence::note(variables));
    if status == Status::Holds {
        v.evidence
            .push(Evidence::note(ranges(this, other, params, params_text)));
    }
    v
}

/// Each of `other`'s parameters replaced by its formula, simultaneously
/// (through fresh names, so `λ = μ, μ = λ` exchanges them).
fn substitute(g: &Sym, params: &[(String, Sym)]) -> Sym {
    let fresh = |i: usize| format!("same-basis#{i}");
    let renamed = params
        .iter()
        .enumerate()
        .fold(g.clone(), |acc, (i, (name, _))| {
            acc.subs(name, &Sym::var(&fresh(i)))
        });
    params
        .iter()
        .enumerate()
        .fold(renamed, |acc, (i, (_, value))| acc.subs(&fresh(i), value))
}

/// How the ring identifies the two variables, or why it does not: both
/// trigonometric (one angle `θ`) or both polynomial (one `t`), no other
/// atoms, constant ends that correspond.
fn identified(here: &Domain, there: &Domain) -> Result<String, String> {
    let other_atoms = |d: &Domain| d.exp.is_some() || (d.angle.is_some() && d.uses_variable);
    if other_atoms(here) || other_atoms(there) {
        return Err("a basis in exponentials or in the variable beside its sines: the ring's atoms do not identify the two variables".into());
    }
    let ends = |d: &Domain, w: &Affine| -> Option<(Affine, Affine)> {
        if !d.start.params.is_empty() || !d.end.params.is_empty() {
            return None;
        }
        Some((d.start.times(w)?, d.end.times(w)?))
    };
    let one = Affine::rational(Rational::from(1));
    let (w, w2) = match (&here.angle, &there.angle) {
        (Some(w), Some(w2)) => (w.clone(), w2.clone()),
        (None, None) => (one.clone(), one),
        _ => {
            return Err(
                "one basis is trigonometric, the other polynomial: the ring does not identify their variables"
                    .into(),
            );
        }
    };
    let atom = if here.angle.is_some() { "θ" } else { "t" };
    let shown = |d: &Domain, w: &Affine| {
        let x = &d.name;
        let names = &d.param_names;
        let rate = w.text(names);
        let of = if rate == "1" {
            x.clone()
        } else {
            format!("{rate}·{x}")
        };
        format!(
            "{atom} = {of} on {x} ∈ [{}, {}]",
            d.start.text(names),
            d.end.text(names)
        )
    };
    let text = format!(
        "the variables identified through the ring's {}: {}; {}",
        if atom == "θ" {
            "angle θ"
        } else {
            "variable t"
        },
        shown(here, &w),
        shown(there, &w2)
    );
    match (ends(here, &w), ends(there, &w2)) {
        (Some(a), Some(b)) if a == b => Ok(text),
        (Some(_), Some(_)) => Err(format!(
            "{text}: the two domains do not correspond, so the functions are not one basis under this change of variable"
        )),
        _ => Err(format!(
            "{text}: an end that depends on a parameter is not compared"
        )),
    }
}

/// `other`'s declared ranges, each mapped back to this basis's parameter
/// where its formula is `a·p + b` in one parameter `p` (rational `a ≠ 0`,
/// `b`), beside this basis's declared ranges.
fn ranges<A: ExactBasis, B: ExactBasis>(
    this: &A,
    other: &B,
    params: &[(String, Sym)],
    params_text: &str,
) -> String {
    let own: Vec<String> = this
        .parameters()
        .iter()
        .map(|p| format!("{} ∈ {}", p.symbol, p.range))
        .collect();
    let mapped: Vec<String> = other
        .parameters()
        .iter()
        .map(|q| {
            let back = params
                .iter()
                .find(|(n, _)| *n == q.name)
                .and_then(|(_, f)| pulled_back(f, &q.range, this));
            match back {
                Some((symbol, r)) => format!("{} ∈ {} (that is {symbol} ∈ {r})", q.symbol, q.range),
                None => format!("{} ∈ {}", q.symbol, q.range),
            }
        })
        .collect();
    format!(
        "so the two are one basis with {params_text}; declared ranges: {} here, {} for {}",
        own.join(", "),
        mapped.join(", "),
        other.id()
    )
}

/// The range `{p : a·p + b ∈ r}` when `f = a·p + b`.
fn pulled_back<A: ExactBasis>(f: &Sym, r: &ParamRange, this: &A) -> Option<(String, ParamRange)> {
    if r.pi {
        return None;
    }
    let vars = f.variables();
    let [name] = vars.iter().collect::<Vec<_>>()[..] else {
        return None;
    };
    let p = this.parameters().into_iter().find(|p| &p.name == name)?;
    let b = f.subs(name, &Sym::zero()).as_rational()?;
    let a = Rational::from(&f.subs(name, &Sym::one()).as_rational()? - &b);
    let affine = Sym::rational(a.clone()) * &Sym::var(name) + &Sym::rational(b.clone());
    if a == 0 || !(f.clone() - &affine).is_zero() {
        return None;
    }
    let back = |e: &End| match e {
        End::Closed(q) => End::Closed(Rational::from(q - &b) / &a),
        End::Open(q) => End::Open(Rational::from(q - &b) / &a),
        End::Unbounded => End::Unbounded,
    };
    let (lo, hi) = if a > 0 {
        (back(&r.lo), back(&r.hi))
    } else {
        (back(&r.hi), back(&r.lo))
    };
    Some((p.symbol, ParamRange { lo, hi, pi: false }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    #[test]
    fn the_thesis_cubic_is_han_and_majeed_qayyum_under_a_change_of_parameter() {
        let m = Sym::var("m");
        let han = same_basis(
            &Family::ThesisCubic,
            &Family::Han,
            &[("lambda".into(), m.clone())],
            "λ = m",
        );
        assert_eq!(han.status, Status::Holds, "{:?}", han.evidence);
        let mq = same_basis(
            &Family::ThesisCubic,
            &Family::MajeedQayyum,
            &[("eta".into(), m.clone() + &Sym::one())],
            "η = m + 1",
        );
        assert_eq!(mq.status, Status::Holds, "{:?}", mq.evidence);
        let last = &mq.evidence.last().unwrap().text;
        assert!(last.contains("(1/2, 2] (that is m ∈ (-1/2, 1])"), "{last}");
        // a wrong change of parameter fails with a witness
        let wrong = same_basis(
            &Family::ThesisCubic,
            &Family::MajeedQayyum,
            &[("eta".into(), m)],
            "η = m",
        );
        assert_eq!(wrong.status, Status::Fails);
        assert!(wrong.evidence.iter().any(|e| e.witness.is_some()));
    }

    #[test]
    fn bases_whose_variables_do_not_correspond_are_not_decided() {
        let v = same_basis(&Family::ThesisCubic, &Family::Bernstein3, &[], "");
        assert_eq!(v.status, Status::NotCheckable);
    }
}
