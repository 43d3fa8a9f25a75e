//! Seed 000 (Majeed et al. 2020): uniform partition of unity and its proof
//! (Appendix A), the printed non-uniform coefficients in the uniform case, and
//! the rational basis (Theorems 5, 6).

use rug::Rational;
use trig_core::families::seed000::{blending, s_of_xi, uniform_normaliser};
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::{Family, Ring};
use trig_symbolic::Sym;

use crate::certify::evidence::nonnegative_on;
use crate::certify::nonneg::ParamBox;
use crate::claim::{Claim, Seed};
use crate::exact::{IDENTITY, basis, identities, residual_verdict, sum};
use crate::verdict::{Status, Verdict};

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "M1",
        seed: Seed::S000,
        source: "Appendix A, Theorem 1",
        statement: "uniform case: Σ_k l_k(t)/(6ζ² − 6ζ + 10) = 1, and each printed step of the proof",
        check: m1,
    },
    Claim {
        id: "M2",
        seed: Seed::S000,
        source: "Theorem 2, Appendix B",
        statement: "F_j(n) > 0 (shape parameter ζ ∈ [0, 4])",
        check: m2,
    },
    Claim {
        id: "M3b",
        seed: Seed::S000,
        source: "(2)–(3)",
        statement: "for uniform knots the printed coefficients reduce to those Appendix A uses (1/(6ζ² − 6ζ + 10))",
        check: m3b,
    },
    Claim {
        id: "M6",
        seed: Seed::S000,
        source: "Theorems 5, 6",
        statement: "rational basis: Q_j = F_j when all w_j = 1; Σ Q_j = 1",
        check: m6,
    },
];

fn zeta() -> Sym {
    Sym::var("zeta")
}

fn m1() -> Verdict {
    let (s, c, z) = (Sym::var("s"), Sym::var("c"), zeta());
    let k = s_of_xi(&z);
    let one = Sym::one();
    let l = blending(&s, &c, &z);
    let total = sum(&l);
    let d = uniform_normaliser(&z);
    // Each l_k expanded as printed: S ∓ (1 + 2S)x + (2 + S)x² ∓ x³ with x = sin or cos.
    let expanded = |x: &Sym, sign: i64| {
        let sg = Sym::int(sign);
        k.clone()
            + &(sg.clone() * &(one.clone() + &(Sym::int(2) * &k)) * x)
            + &((Sym::int(2) + &k) * &x.square())
            + &(sg * &x.powi(3))
    };
    let z2 = z.square();
    let printed_step =
        Sym::int(4) * &z2 - &(Sym::int(4) * &z) + &Sym::int(8) + &(Sym::int(2) * &z2) - &z
            + &Sym::int(2);
    let corrected_step = printed_step.clone() - &z;
    let mut parts = vec![
        (
            "(A1) Σ_k F_k − 1".to_string(),
            sum(&basis(Family::Seed000Uniform)),
            one.clone(),
        ),
        ("expansion of l0".into(), expanded(&s, -1), l[0].clone()),
        ("expansion of l1".into(), expanded(&c, 1), l[1].clone()),
        ("expansion of l2".into(), expanded(&s, 1), l[2].clone()),
        ("expansion of l3".into(), expanded(&c, -1), l[3].clone()),
        (
            "[4(ζ²−ζ+1) + (2+ζ²−ζ+1) + (2+ζ²−ζ+1)] − Σ l_k".into(),
            Sym::int(4) * &k + &(Sym::int(2) * &(Sym::int(2) + &k)),
            total.clone(),
        ),
        (
            "[4ζ² − 4ζ + 4 + 4 + 2ζ² − ζ + 2] − Σ l_k".into(),
            printed_step,
            total.clone(),
        ),
        ("[6ζ² − 6ζ + 10] − Σ l_k".into(), d, total.clone()),
    ];
    let v = identities(parts.clone());
    if v.status == Status::Holds {
        return v;
    }
    parts[6] = (
        "corrected step [4ζ² − 4ζ + 4 + 4 + 2ζ² − 2ζ + 2] − Σ l_k".into(),
        corrected_step,
        total,
    );
    let corrected = identities(parts);
    if corrected.status != Status::Holds {
        return v;
    }
    let mut evidence = v.evidence;
    evidence.extend(
        corrected
            .evidence
            .into_iter()
            .filter(|e| e.starts_with("corrected")),
    );
    Verdict::new(Status::HoldsAfterCorrection, IDENTITY, evidence).with_correction(
        "the theorem holds; in the proof's step \"4ζ² − 4ζ + 4 + 4 + 2ζ² − ζ + 2\" the term −ζ must be −2ζ (2(2 + ζ² − ζ + 1) = 2ζ² − 2ζ + 6)",
    )
}

fn m3b() -> Verdict {
    let knots: Vec<Sym> = (0..=20).map(Sym::int).collect();
    let f = NonUniform::new(knots, zeta());
    let j = 10;
    let inv = Sym::one() / &uniform_normaliser(&zeta());
    let zero = Sym::zero();
    let expected_b = [zero.clone(), inv.clone(), zero.clone(), zero.clone()];
    let expected_c = [zero.clone(), zero.clone(), inv.clone(), zero];
    let mut parts: Vec<(String, Verdict)> = Vec::new();
    let mut check = |name: String, got: Result<Sym, trig_core::CoreError>, want: &Sym| {
        let v = match got {
            Ok(x) => residual_verdict(&x, want),
            Err(e) => Verdict::new(
                Status::Fails,
                IDENTITY,
                vec![format!("the printed formula is undefined: {e}")],
            ),
        };
        parts.push((name, v));
    };
    check(format!("a_{j} − 1/(6ζ²−6ζ+10)"), f.a(j), &inv);
    check(format!("d_{j} − 1/(6ζ²−6ζ+10)"), f.d(j), &inv);
    for (name, row, expected) in [("b", f.b(j), &expected_b), ("c", f.c(j), &expected_c)] {
        match row {
            Ok(row) => {
                for k in 0..4 {
                    check(
                        format!("{name}_{{{j},{k}}} − Appendix A"),
                        Ok(row[k].clone()),
                        &expected[k],
                    );
                }
            }
            Err(e) => check(
                format!("{name}_{{{j},0..3}} − Appendix A"),
                Err(e),
                &expected[0],
            ),
        }
    }
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(
        0,
        "uniform knots n_i = i (unit spacing; q_j = q_{j−1} = q_{j−2} as the paper states), span j = 10; Appendix A uses F0 = l0/D, F1 = l1/D, F2 = l2/D, F3 = l3/D with D = 6ζ² − 6ζ + 10".into(),
    );
    v
}

fn m6() -> Verdict {
    let f = basis(Family::Seed000Uniform);
    let w: Vec<Sym> = (0..4).map(|i| Sym::var(&format!("w{i}"))).collect();
    let weighted: Vec<Sym> = f.iter().zip(&w).map(|(fi, wi)| fi.clone() * wi).collect();
    let den = sum(&weighted);
    let q: Vec<Sym> = weighted.iter().map(|x| x.clone() / &den).collect();
    let one = Sym::one();
    let mut parts: Vec<(String, Sym, Sym)> = (0..4)
        .map(|j| {
            let qj = (0..4).fold(q[j].clone(), |acc, i| acc.subs(&format!("w{i}"), &one));
            (format!("Q{j}(w = 1) − F{j}"), qj, f[j].clone())
        })
        .collect();
    parts.push(("Σ Q_j − 1 (symbolic weights)".into(), sum(&q), one));
    let mut v = identities(parts);
    v.evidence.push(
        "uniform case (Appendix A basis F_j = l_j/(6ζ² − 6ζ + 10)), weights as symbols w0…w3"
            .into(),
    );
    v
}

fn m2() -> Verdict {
    let mut v = nonnegative_on(
        Family::Seed000Uniform,
        &basis(Family::Seed000Uniform),
        Some("zeta"),
        &ParamBox::Interval(Rational::new(), Rational::from(4)),
    );
    v.evidence.push(
        "the B-spline basis function F_j is F3, F2, F1, F0 on its four intervals (uniform case, Appendix A); strict positivity fails in any case at the support ends, where F3(0) = F0(π/2) = 0".into(),
    );
    if v.status == Status::Holds {
        v.status = Status::Fails;
    }
    v
}
