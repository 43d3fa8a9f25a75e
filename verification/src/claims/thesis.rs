//! Seed 001, the thesis: claims about the quadratic (3.1) and cubic (3.7)
//! bases, the surface matrix form (5.4)–(5.8), the comparison bases (6.1)–(6.3)
//! and the Appendix 2 listing.

use rug::Rational;
use trig_core::families::thesis::{surface_matrix_a, surface_row_t};
use trig_core::{Family, Variable};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_certify::ParamBox;
use trig_judge::certificate::nonnegative_on;
use trig_judge::exact::{basis, identities, residual_verdict, sum, symbols};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T31",
        check: t31,
    },
    Claim {
        id: "T25",
        check: t25,
    },
    Claim {
        id: "T28",
        check: t28,
    },
    Claim {
        id: "T30",
        check: t30,
    },
    Claim {
        id: "T37",
        check: t37,
    },
];

fn points(n: usize) -> Vec<Sym> {
    symbols("P", n)
}

fn t25() -> Verdict {
    let (s, c, m) = (Sym::var("s"), Sym::var("c"), Sym::var("m"));
    let t = surface_row_t(&s, &c);
    let a = surface_matrix_a(&m);
    let b = basis(Family::ThesisCubic);
    let mut v = identities(
        (0..4)
            .map(|col| {
                let entry = (0..7).fold(Sym::zero(), |acc, r| acc + &(t[r].clone() * &a[r][col]));
                (format!("([T][A])_{col} − b{col}"), entry, b[col].clone())
            })
            .collect(),
    );
    if v.status == Status::Holds {
        v.evidence.push(
            "hence [T][A][V][A]^T[U] = [b(u)] V [b(v)]^T = Σ_i Σ_j b_i(u) b_j(v) V_{ij}, the double sum (5.3) with P_{i,j} = V_{ij}",
        );
    }
    v
}

fn t28() -> Verdict {
    let cubic = basis(Family::ThesisCubic);
    let han = basis(Family::Han);
    let mq = basis(Family::MajeedQayyum);
    let m = Sym::var("m");
    let mut parts = Vec::new();
    for i in 0..4 {
        parts.push((
            format!("thesis b{i}(u; m) − Han b{i}(u; λ = m)"),
            cubic[i].clone(),
            han[i].subs("lambda", &m),
        ));
        parts.push((
            format!("thesis b{i}(u; m) − g{i}(πu/2; η = m + 1)"),
            cubic[i].clone(),
            mq[i].subs("eta", &(m.clone() + &Sym::one())),
        ));
    }
    let mut v = identities(parts);
    debug_assert_eq!(Family::MajeedQayyum.info().variable, Variable::Angle);
    v.evidence.push(
        "so (3.7), (6.2) and (6.1) are one family: m = λ = η − 1 (with t = πu/2 for (6.1)); the published ranges m ∈ [−2, 1], λ ∈ [−2, 1], η ∈ (1/2, 2] correspond to m ∈ [−2, 1], [−2, 1] and (−1/2, 1]",
    );
    v
}

fn t30() -> Verdict {
    let han = basis(Family::Han);
    let listing = basis(Family::HanListing);
    let mut parts: Vec<(String, Sym, Sym)> = (0..4)
        .map(|i| {
            (
                format!("listing b{i}0 − (6.2) b{i}"),
                listing[i].clone(),
                han[i].clone(),
            )
        })
        .collect();
    parts.push(("Σ listed functions − 1".into(), sum(&listing), Sym::one()));
    identities(parts).with_correction(
        "line b20 of the listing must use cos((pi/2)*t) in its last factor: (2+m-(m.*cos((pi/2)*t)))",
    )
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

/// For (6.2) at λ = −1, −2: nonnegative and summing to 1 (so every curve
/// stays in the convex hull of its control points); the Appendix 2 listing
/// that drew Figure 6.3 sums to something else.
fn t31() -> Verdict {
    let mut parts = Vec::new();
    let zero = Rational::new();
    for l in [-1i64, -2] {
        let x = Sym::int(l);
        for (family, label) in [
            (Family::Han, "(6.2)"),
            (Family::HanListing, "Appendix 2 listing"),
        ] {
            let fs: Vec<Sym> = basis(family).iter().map(|f| f.subs("lambda", &x)).collect();
            parts.push((
                format!("{label}, λ = {l}: Σ − 1"),
                residual_verdict(&sum(&fs), &Sym::one()),
            ));
            parts.push((
                format!("{label}, λ = {l}: nonnegativity"),
                nonnegative_on(
                    &family,
                    &fs,
                    None,
                    &ParamBox::closed(zero.clone(), zero.clone()),
                ),
            ));
        }
    }
    let formula = parts[..2]
        .iter()
        .chain(&parts[4..6])
        .all(|(_, v)| v.status == Status::Holds);
    let evidence = Verdict::all(trig_judge::certificate::CERTIFIED, parts).evidence;
    let mut v = Verdict::new(
        if formula {
            Status::Fails
        } else {
            Status::Holds
        },
        trig_judge::certificate::CERTIFIED,
        evidence,
    );
    v.evidence.push(
        "with (6.2) the basis is nonnegative and sums to 1 at λ = −1, −2, so every curve lies in the convex hull: the printed observation does not hold for (6.2); the listing's functions do not sum to 1 (T30), which is what Figure 6.3 shows",
    );
    v
}
