//! Total positivity by Karlin's Wronskian criterion
//! ([`trig_certify::wronskian`]), where the totally positive factorisation
//! does not reach: functions in the variable beside `sin`, `cos` or `exp`
//! (C- and H-Bézier bases), a domain `[0, α]` that moves with a parameter,
//! and parameter values where the factorisation's certificate stalls.
//!
//! Every Wronskian of consecutive functions `W(b_j, …, b_l) > 0` on the
//! open domain for every parameter of the range proves total positivity
//! (strict inside, by continuity on the closed domain); one `< 0` at a
//! point refutes it (collocation at coalescing points).

use trig_certify::branch::Axis;
use trig_certify::branch::Outcome;
use trig_certify::wronskian::{self, Run};
use trig_core::ParamRange;
use trig_symbolic::Sym;

use super::by_intervals::axes;
use crate::exact::{ExactBasis, basis_of};
use trig_verdict::evidence::{Evidence, Expr, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How the criterion decides, as the report states it.
pub const WRONSKIAN: &str = "certified: Karlin's criterion — every Wronskian of consecutive functions W(b_j, …, b_l) > 0 on the open domain for every parameter of the range (interval branch and bound, factor by factor; at a vanishing end by the first derivative that does not vanish) makes each run an extended complete Chebyshev system, so every collocation matrix inside has all minors of consecutive columns > 0 and by Fekete's criterion all minors > 0; totally positive on the closed domain by continuity. Refutation: a consecutive Wronskian < 0 at a point (certified enclosure), where collocation at coalescing points gives a negative minor";

/// Total positivity on the range (the claim's, else the declared ones)
/// by the criterion; `before` says why the factorisation did not decide.
pub fn by_wronskians<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
    before: &str,
) -> Verdict {
    let (closed, truncated) = axes(basis, range);
    let domain = basis.domain();
    let names = basis.function_names();
    let functions = basis_of(basis);
    let mut axes = closed.clone();
    let mut criterion = match wronskian::consecutive(&functions, &domain, &axes) {
        Ok(c) => c,
        Err(why) => return Verdict::not_checkable(format!("{before}; {why}")),
    };
    // a Wronskian may vanish at a closed end of a range (a function ≡ 0
    // there, or a double zero inside): proved with the ends open, total
    // positivity reaches the closed ends by continuity where the functions
    // are continuous there (every minor a limit of minors ≥ 0)
    let mut by_continuity = None;
    let opened = open_ends(&closed);
    if !criterion.proved(names.len()) && criterion.refuting().is_none() && opened != closed {
        if let Ok(c) = wronskian::consecutive(&functions, &domain, &opened) {
            if c.proved(names.len()) {
                by_continuity = Some(continuous(&functions, &domain, &closed));
                (criterion, axes) = (c, opened);
            }
        }
    }
    let mut evidence = vec![Evidence::note(format!(
        "{before}: decided by the Wronskians of consecutive functions on the open domain {}",
        open_domain(basis, &axes)
    ))];
    evidence.extend(truncated.iter().map(Evidence::note));
    let symbols: Vec<String> = basis
        .parameters()
        .iter()
        .zip(&axes)
        .map(|(p, a)| format!("{}{}", p.symbol, if a.pi { "/π" } else { "" }))
        .collect();
    for run in &criterion.runs {
        evidence.push(run_line(run, &names, &domain.name, &symbols));
    }
    if let Some(run) = criterion.refuting() {
        let functions = names[run.first..=run.last].join(", ");
        let m = run.last - run.first;
        evidence.push(Evidence::note(if m == 0 {
            format!("so the basis is not totally positive there: {functions} < 0 at that point is a negative 1 × 1 minor")
        } else {
            format!(
                "so the basis is not totally positive there: at coalescing points {} the collocation minor of ({functions}) is a positive multiple of h^{} times W(x) + O(h), negative for small h",
                if m == 1 {
                    "x, x + h".to_string()
                } else {
                    format!("x, x + h, …, x + {m}h")
                },
                m * (m + 1) / 2
            )
        }));
        return Verdict::new(Status::Fails, WRONSKIAN, evidence);
    }
    if !criterion.proved(names.len()) {
        evidence.push(Evidence::note(
            "the criterion is sufficient: a Wronskian not proved positive (it may vanish inside) leaves total positivity undecided",
        ));
        return Verdict::new(Status::NotCheckable, WRONSKIAN, evidence);
    }
    if !truncated.is_empty() {
        evidence.push(Evidence::note(
            "proved on the truncated range only: not a proof on the whole range",
        ));
        return Verdict::new(Status::NotCheckable, WRONSKIAN, evidence);
    }
    match by_continuity {
        Some(Ok(())) => evidence.push(Evidence::note(
            "the closed ends of the range by continuity: every denominator keeps one strict sign on the closed domain and range, so each collocation minor there is a limit of minors ≥ 0 from inside",
        )),
        Some(Err(why)) => {
            evidence.push(Evidence::note(format!(
                "proved with the range's ends open; the closed ends are not reached: {why}"
            )));
            return Verdict::new(Status::NotCheckable, WRONSKIAN, evidence);
        }
        None => {}
    }
    evidence.push(
        Evidence::new(
            Kind::Certificate,
            format!(
                "all {} consecutive Wronskians > 0 on the open domain ({} boxes): totally positive",
                criterion.runs.len(),
                criterion.boxes()
            ),
        )
        .about("total positivity", Status::Holds),
    );
    Verdict::new(Status::Holds, WRONSKIAN, evidence)
}

/// The axes with their finite closed ends opened.
fn open_ends(axes: &[Axis]) -> Vec<Axis> {
    axes.iter()
        .map(|a| Axis {
            lo_open: true,
            hi_open: true,
            ..a.clone()
        })
        .collect()
}

/// Every denominator factor of every function of one strict sign on the
/// closed domain and the closed ranges: the functions are continuous there.
pub(crate) fn continuous(
    functions: &[Sym],
    domain: &trig_core::Domain,
    axes: &[Axis],
) -> Result<(), String> {
    for f in functions {
        for factor in f.denominator().keys() {
            let g = Sym::from_poly(factor.clone());
            trig_certify::factors::sign_of(&g, domain, axes, true).map_err(|why| {
                format!("the denominator factor {g} is not proved nonzero there ({why})")
            })?;
        }
    }
    Ok(())
}

/// The criterion's verdict at one parameter vector only (a single point of
/// each axis), for the maximal-set judges: `Some(true)` proved totally
/// positive there, `Some(false)` refuted, `None` undecided.
pub fn at_point(fs: &[Sym], domain: &trig_core::Domain, axes: &[Axis]) -> Option<bool> {
    let c = wronskian::consecutive(fs, domain, axes).ok()?;
    if c.refuting().is_some() {
        Some(false)
    } else {
        c.proved(fs.len()).then_some(true)
    }
}

/// `(a, b)` with the parameters' ranges: `t ∈ (0, α), α ∈ [1/2, 3]`.
fn open_domain<B: ExactBasis>(basis: &B, axes: &[Axis]) -> String {
    let d = basis.domain();
    let params = basis.parameters();
    let mut text = format!(
        "{} ∈ ({}, {})",
        d.name,
        d.start.text(&d.param_names),
        d.end.text(&d.param_names)
    );
    let end = |q: &rug::Rational, pi: bool| match (pi, q.to_string().as_str()) {
        (false, t) => t.to_string(),
        (true, "0") => "0".to_string(),
        (true, "1") => "π".to_string(),
        (true, t) => format!("{t}·π"),
    };
    for (p, a) in params.iter().zip(axes) {
        text.push_str(&format!(
            ", {} ∈ {}{}, {}{}",
            p.symbol,
            if a.lo_open { "(" } else { "[" },
            end(&a.lo, a.pi),
            end(&a.hi, a.pi),
            if a.hi_open { ")" } else { "]" }
        ));
    }
    text
}

/// One run: its Wronskian and what was decided of its sign.
fn run_line(run: &Run, names: &[String], var: &str, symbols: &[String]) -> Evidence {
    let label = format!("W({})", names[run.first..=run.last].join(", "));
    let (text, status) = match &run.sign {
        Outcome::Proved { boxes } => (
            format!("{label} > 0 on the open domain (proved, {boxes} boxes)"),
            Status::Holds,
        ),
        Outcome::Negative {
            tau,
            params,
            x,
            value,
        } => (
            format!(
                "{label} < 0 at {var} ≈ {x} (τ = {tau} of the domain){}: with W = N/D in the exact ring's normal form (N, D as shown), N times the sign of D there lies in [{:e}, {:e}] (certified)",
                if params.is_empty() {
                    String::new()
                } else {
                    format!(
                        ", {}",
                        symbols
                            .iter()
                            .zip(params)
                            .map(|(s, p)| format!("{s} = {p}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                },
                value.0,
                value.1
            ),
            Status::Fails,
        ),
        Outcome::Undecided(why) => (
            format!("{label}: its sign on the open domain was not decided ({why})"),
            Status::NotCheckable,
        ),
    };
    Evidence::new(Kind::Certificate, text)
        .with(label.as_str(), Expr::new(&run.wronskian))
        .about("total positivity", status)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Domain, Variable};

    fn point(q: i64) -> Vec<Axis> {
        vec![Axis {
            lo: rug::Rational::from(q),
            hi: rug::Rational::from(q),
            lo_open: false,
            hi_open: false,
            pi: false,
        }]
    }

    /// Continuity at a range end is what carries total positivity to it:
    /// a denominator vanishing there must refuse it.
    #[test]
    fn continuity_needs_every_denominator_nonzero() {
        let domain = Domain::from_variable(Variable::Polynomial, &["alpha"]);
        let f = Sym::var("t") / &(Sym::var("alpha") + &Sym::one());
        assert!(continuous(std::slice::from_ref(&f), &domain, &point(0)).is_ok());
        let why = continuous(&[f], &domain, &point(-1)).expect_err("1/(α + 1) at α = −1");
        assert!(why.contains("not proved nonzero"), "{why}");
    }
}
