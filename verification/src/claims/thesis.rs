//! Seed 001, the thesis: claims about the quadratic (3.1) and cubic (3.7)
//! bases, the surface matrix form (5.4)–(5.8), the comparison bases (6.1)–(6.3)
//! and the Appendix 2 listing.

use rug::Rational;
use trig_core::Family;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{basis, identities, symbols};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T37",
    check: t37,
}];

fn points(n: usize) -> Vec<Sym> {
    symbols("P", n)
}

fn t37() -> Verdict {
    let h = basis(Family::ThesisQuadratic);
    let zero = Sym::zero();
    let at0: Vec<Sym> = h.iter().map(|hi| hi.subs("beta", &zero)).collect();
    let v = identities(vec![
        ("H0(u; 0)".into(), at0[0].clone(), Sym::zero()),
        ("H1(u; 0)".into(), at0[1].clone(), Sym::one()),
        ("H2(u; 0)".into(), at0[2].clone(), Sym::zero()),
    ]);
    let status = if v.status == Status::Holds {
        Status::Fails
    } else {
        Status::Holds
    };
    let mut evidence = v.evidence;
    let point = [
        ("beta".to_string(), Rational::new()),
        ("s".to_string(), Rational::from((3, 5))),
        ("c".to_string(), Rational::from((4, 5))),
    ];
    let curve = trig_judge::exact::combination(&h, &points(3));
    // the control points stay symbols: F is P1 there, whatever they are
    let witness = trig_verdict::witness::of_exprs(
        &point,
        &["beta".into(), "s".into(), "c".into()],
        &[("F (the same point P1 for every θ)", &curve)],
    );
    evidence.push(
        Evidence::note(
            "with β = 0 the curve is F(u) = P1 for every u: a single point, not a straight line (3.2.3 says the same: \"H1(u) becomes identically equal to one\")",
        )
        .witnessed(witness.filter(|_| status == Status::Fails)),
    );
    Verdict::new(status, trig_judge::exact::IDENTITY, evidence)
}
