//! Seed 001, the thesis: claims about the quadratic (3.1) and cubic (3.7)
//! bases, the surface matrix form (5.4)–(5.8), the comparison bases (6.1)–(6.3)
//! and the Appendix 2 listing.

use rug::Rational;
use trig_core::families::thesis::{surface_matrix_a, surface_row_t};
use trig_core::{Family, Variable};
use trig_deriv::End;
use trig_symbolic::Sym;

use crate::claim::{Claim, Seed};
use trig_certify::ParamBox;
use trig_judge::certificate::{
    maximal_versus_published, monotone, nonnegative_on, on_published_range,
};
use trig_judge::exact::{
    at_end, basis, combination, identities, identity, residual_verdict, sum, symbols,
};
use trig_judge::numeric::{counterexample_item, differ, half_pi_minus, point, show, value};
use trig_judge::symmetry::reflection_symmetry;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// A claim of the thesis (seed 001); shared by the thesis claim files.
pub(super) const fn claim(
    id: &'static str,
    source: &'static str,
    statement: &'static str,
    check: fn() -> Verdict,
) -> Claim {
    Claim {
        id,
        seed: Seed::S001,
        source,
        statement,
        check,
    }
}

pub const CLAIMS: &[Claim] = &[
    claim("T1", "(3.1), 3.2.2 ii", "⟪H0 + H1 + H2 = 1⟫", t1),
    claim(
        "T2",
        "3.2.2 i",
        "⟪H_i(u) ≥ 0⟫ for ⟪β ≥ 0⟫, ⟪u ∈ [0, 1]⟫",
        t2,
    ),
    claim(
        "T3",
        "3.2.2 iii",
        "⟪H0⟫ decreasing, ⟪H2⟫ increasing (⟪β ≥ 0⟫)",
        t3,
    ),
    claim(
        "T4",
        "3.2.2 iv",
        "⟪H_i(u; β) = H_{2−i}(π/2 − u; β)⟫ (as printed)",
        t4,
    ),
    claim(
        "T4b",
        "3.2.2 iv, reading",
        "reading of T4: ⟪H_i(u) = H_{2−i}(1 − u)⟫",
        t4b,
    ),
    claim(
        "T5",
        "(3.3)–(3.6)",
        "⟪F(0) − P0 = (P1 − P0)/(β+1)⟫, ⟪F(1) − P2 = (P1 − P2)/(β+1)⟫",
        t5,
    ),
    claim(
        "T5b",
        "3.2.4, text after Figure 3.3",
        "the curve starts at the first control point ⟪P0⟫ and ends at the last control point ⟪P2⟫",
        t5b,
    ),
    claim("T6", "3.3.2 ii", "⟪Σ b_i(u; m) = 1⟫", t6),
    claim(
        "T7",
        "3.3.2 i",
        "⟪b_i(u; m) ≥ 0⟫ on ⟪[0, 1]⟫ exactly for ⟪m ∈ [−2, 1]⟫ (the maximal range)",
        t7,
    ),
    claim(
        "T8",
        "3.3.2 iii",
        "⟪b0⟫ decreasing and ⟪b2⟫ increasing, ⟪m ∈ [−2, 1]⟫ (as printed)",
        t8,
    ),
    claim("T8a", "3.3.2 iii", "⟪b0⟫ decreasing for ⟪m ∈ [−2, 1]⟫", t8a),
    claim(
        "T8b",
        "3.3.2 iii, proof",
        "⟪b3⟫ increasing for ⟪m ∈ [−2, 1]⟫ (as the proof says)",
        t8b,
    ),
    claim(
        "T9",
        "3.3.2 iv",
        "⟪b_i(u; m) = b_{2−i}(π/2 − u; m)⟫ (as printed)",
        t9,
    ),
    claim(
        "T9b",
        "3.3.2 iv, reading",
        "reading of T9: ⟪b_i(u) = b_{3−i}(1 − u)⟫",
        t9b,
    ),
    claim(
        "T25",
        "(5.4)–(5.8)",
        "⟪[T][A] = [B0 … B3]⟫; ⟪[T][A][V][A]^T[U]⟫ equals the double sum (5.3)",
        t25,
    ),
    claim(
        "T27",
        "5.4.1",
        "for ⟪m⟫ outside ⟪(−2, 1]⟫ \"the basis functions are not normalized\" (do not sum to 1)",
        t27,
    ),
    claim(
        "T28",
        "(3.7), (6.1), (6.2)",
        "the thesis basis, Majeed & Qayyum (6.1) and Han et al. (6.2): equal under a change of parameter?",
        t28,
    ),
    claim(
        "T29",
        "(6.1), (6.2), (6.3)",
        "partition of unity and nonnegativity of (6.1), (6.2), (6.3) on the published ranges ⟪η ∈ (1/2, 2]⟫, ⟪λ ∈ [−2, 1]⟫, ⟪α ∈ (0, 2)⟫; their maximal ranges",
        t29,
    ),
    claim(
        "T30",
        "Appendix 2",
        "the MATLAB listing computes Han's basis (6.2); its functions sum to 1",
        t30,
    ),
    claim(
        "T31",
        "6.2, text after Figure 6.3",
        "\"curves are generated out of the convex hull\" for ⟪λ = −1, −2⟫ although in range",
        t31,
    ),
    claim(
        "T33",
        "4.3.1, Step 1",
        "⟪b3(1) = 0⟫, ⟪b0(1) = b1(1) = b2(1) = 1⟫",
        t33,
    ),
    claim(
        "T37",
        "3.2.1, after (3.1)",
        "when ⟪β = 0⟫ the quadratic curve is a straight line",
        t37,
    ),
    claim(
        "T38",
        "3.2.4, Figure 3.3(a) text",
        "for ⟪β = 1⟫ the curve ends at the midpoints of the edges ⟪P0P1⟫ and ⟪P1P2⟫",
        t38,
    ),
];

fn points(n: usize) -> Vec<Sym> {
    symbols("P", n)
}

/// `Σ b_i P_i` with symbolic control points.
fn curve(b: &[Sym]) -> Sym {
    combination(b, &points(b.len()))
}

fn t1() -> Verdict {
    let h = basis(Family::ThesisQuadratic);
    let mut v = identity("H0 + H1 + H2 − 1", &sum(&h), &Sym::one());
    v.evidence
        .push("H1 is defined in (3.1) as 1 − H0 − H2, so the identity holds by construction");
    v
}

/// A counterexample to `f_i(x) = f_j(π/2 − x)` for a family in `u`.
fn reflection_counterexample(family: Family, param: (i64, i64), i: usize, j: usize) -> Verdict {
    let p = [Rational::from(param)];
    let x = point((1, 2));
    let y = half_pi_minus(&x);
    let (a, b) = (value(family, &p, i, &x), value(family, &p, j, &y));
    let name = family.info().params[0].symbol;
    let f = family.info().functions;
    // the two values as expressions of the exact basis, at their points
    let param = Sym::var(family.info().params[0].name).to_sympy();
    let functions = trig_judge::exact::basis(family);
    let of = |k: usize, x: &str| {
        let f = functions[k].subs(family.info().params[0].name, &Sym::rational(p[0].clone()));
        trig_judge::numeric::at_sympy(&f, trig_core::Described::variable(&family), x)
    };
    let status = if differ(&a, &b) {
        Status::Fails
    } else {
        Status::Holds
    };
    let item = counterexample_item(
        format!(
            "{name} = {}, u = 1/2: {}(1/2) = {}, but {}(π/2 − 1/2) = {} (π/2 − 1/2 ≈ 1.0708 lies outside u ∈ [0, 1])",
            p[0],
            f[i],
            show(&a),
            f[j],
            show(&b)
        ),
        &[
            (name.to_string(), param.clone(), p[0].to_string()),
            ("u".into(), "u".into(), "1/2".into()),
        ],
        [
            (format!("{}(1/2)", f[i]), &a, of(i, "1/2")),
            (format!("{}(π/2 − 1/2)", f[j]), &b, of(j, "pi/2 - (1/2)")),
        ],
    );
    Verdict::new(
        status,
        "counterexample evaluated in 256-bit MPFR (difference far above rounding)",
        [
            item,
            "the statement holds in the angle θ = πu/2 (θ ↦ π/2 − θ), i.e. for u ↦ 1 − u; see the reading".into(),
        ],
    )
}

fn t4() -> Verdict {
    trig_judge::exact::defined_by(
        reflection_counterexample(Family::ThesisQuadratic, (1, 1), 0, 2),
        &Family::ThesisQuadratic,
    )
}

fn t4b() -> Verdict {
    reflection_symmetry(&Family::ThesisQuadratic, 0..3)
}

fn quadratic_curve_ends() -> (Sym, Sym) {
    let f = curve(&basis(Family::ThesisQuadratic));
    (at_end(&f, End::Start), at_end(&f, End::End))
}

fn t5() -> Verdict {
    let (f0, f1) = quadratic_curve_ends();
    let k = Sym::one() / &(Sym::var("beta") + &Sym::one());
    let [p0, p1, p2]: [Sym; 3] = points(3).try_into().expect("three points");
    identities(vec![
        (
            "F(0) − P0 = (P1 − P0)/(β+1)".into(),
            f0 - &p0,
            (p1.clone() - &p0) * &k,
        ),
        (
            "F(1) − P2 = (P1 − P2)/(β+1)".into(),
            f1 - &p2,
            (p1 - &p2) * &k,
        ),
    ])
}

fn t5b() -> Verdict {
    let (f0, f1) = quadratic_curve_ends();
    let [p0, _, p2]: [Sym; 3] = points(3).try_into().expect("three points");
    let mut v = identities(vec![
        ("F(0) = P0".into(), f0, p0),
        ("F(1) = P2".into(), f1, p2),
    ]);
    v.evidence.push(
        "the residuals are (P1 − P0)/(β+1) and (P1 − P2)/(β+1): nonzero for every finite β ≥ 0 unless P1 coincides with the end point; e.g. β = 1, P0 = (0,0), P1 = (1.5,1.5) (3.2.3) gives F(0) = (0.75, 0.75)",
    );
    v
}

fn t6() -> Verdict {
    identity("Σ b_i − 1", &sum(&basis(Family::ThesisCubic)), &Sym::one())
}

fn t9() -> Verdict {
    let mut v = reflection_counterexample(Family::ThesisCubic, (0, 1), 0, 2);
    v.evidence
        .push("as printed the index 2 − i is also out of range for i = 3 (b_{−1} does not exist)");
    trig_judge::exact::defined_by(v, &Family::ThesisCubic)
}

fn t9b() -> Verdict {
    reflection_symmetry(&Family::ThesisCubic, 0..4)
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

fn t27() -> Verdict {
    let residual = sum(&basis(Family::ThesisCubic)) - &Sym::one();
    let (status, reading) = if residual.is_zero() {
        (
            Status::Fails,
            "identically in m: the functions sum to 1 for every real m; outside [−2, 1] what can fail is nonnegativity, not normalisation",
        )
    } else {
        (Status::Holds, "not identically zero in m")
    };
    // at a parameter outside the range, the sum is 1 at every point
    let two = Rational::from(2);
    let point = [
        ("m".to_string(), two.clone()),
        ("s".to_string(), Rational::from((3, 5))),
        ("c".to_string(), Rational::from((4, 5))),
    ];
    let total = sum(&basis(Family::ThesisCubic));
    let witness = trig_verdict::witness::of_exprs(
        &point,
        &["m".into(), "s".into(), "c".into()],
        &[("Σ b_i (claimed ≠ 1)", &total)],
    );
    Verdict::new(
        status,
        trig_judge::exact::IDENTITY,
        [Evidence::note(format!("Σ b_i − 1 = {residual}, {reading}"))
            .witnessed(witness.filter(|_| status == Status::Fails))],
    )
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

fn t33() -> Verdict {
    let b = basis(Family::ThesisCubic);
    let values: Vec<Sym> = b.iter().map(|bi| at_end(bi, End::End)).collect();
    let printed = [1, 1, 1, 0]; // b3(1) = 0, b0(1) = b1(1) = b2(1) = 1
    let parts = (0..4)
        .map(|i| {
            (
                format!("b{i}(1) = {}", printed[i]),
                values[i].clone(),
                Sym::int(printed[i]),
            )
        })
        .collect();
    // the computed values, grouped as the print groups them
    let with = |v: i64| -> Vec<String> {
        (0..4)
            .filter(|&i| values[i] == Sym::int(v))
            .map(|i| format!("b{i}(1)"))
            .collect()
    };
    trig_judge::exact::defined_by(identities(parts), &Family::ThesisCubic).with_correction(format!(
        "{} = 0 and {} = 1 (the computed values)",
        with(0).join(" = "),
        with(1).join(" = ")
    ))
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

fn t38() -> Verdict {
    let (f0, f1) = quadratic_curve_ends();
    let one = Sym::one();
    let [p0, p1, p2]: [Sym; 3] = points(3).try_into().expect("three points");
    let half = Sym::rational(Rational::from((1, 2)));
    identities(vec![
        (
            "F(0; β=1) − (P0 + P1)/2".into(),
            f0.subs("beta", &one),
            (p0 + &p1) * &half,
        ),
        (
            "F(1; β=1) − (P1 + P2)/2".into(),
            f1.subs("beta", &one),
            (p1 + &p2) * &half,
        ),
    ])
}

fn t2() -> Verdict {
    nonnegative_on(
        &Family::ThesisQuadratic,
        &basis(Family::ThesisQuadratic),
        Some("beta"),
        &ParamBox::from_closed(Rational::new()),
    )
}

fn t7() -> Verdict {
    maximal_versus_published(&Family::ThesisCubic).1
}

fn t29() -> Verdict {
    let mut parts = Vec::new();
    for family in [Family::MajeedQayyum, Family::Han, Family::Usman] {
        let id = family.info().id;
        parts.push((
            format!("{id}: Σ − 1"),
            residual_verdict(&sum(&basis(family)), &Sym::one()),
        ));
        parts.push((
            format!("{id}: nonnegative on the published range"),
            on_published_range(&family),
        ));
        let (_, maximal) = maximal_versus_published(&family);
        // the maximal range is evidence, not a condition of this claim
        let note = if maximal.status == Status::Holds {
            "the published range is the maximal one"
        } else {
            "the published range is not the maximal one"
        };
        let mut m = maximal;
        m.status = Status::Holds;
        m.evidence.push(note);
        parts.push((format!("{id}: maximal range (evidence)"), m));
    }
    Verdict::all(trig_judge::certificate::CERTIFIED, parts)
}

fn beta_half_line() -> ParamBox {
    ParamBox::from_closed(Rational::new())
}

fn m_range() -> ParamBox {
    ParamBox::closed(Rational::from(-2), Rational::from(1))
}

fn t3() -> Verdict {
    Verdict::all(
        trig_judge::certificate::CERTIFIED,
        vec![
            (
                "H0".into(),
                monotone(
                    &Family::ThesisQuadratic,
                    0,
                    false,
                    Some("beta"),
                    &beta_half_line(),
                ),
            ),
            (
                "H2".into(),
                monotone(
                    &Family::ThesisQuadratic,
                    2,
                    true,
                    Some("beta"),
                    &beta_half_line(),
                ),
            ),
        ],
    )
}

fn t8() -> Verdict {
    let v = Verdict::all(
        trig_judge::certificate::CERTIFIED,
        vec![
            (
                "b0".into(),
                monotone(&Family::ThesisCubic, 0, false, Some("m"), &m_range()),
            ),
            (
                "b2".into(),
                monotone(&Family::ThesisCubic, 2, true, Some("m"), &m_range()),
            ),
        ],
    );
    trig_judge::exact::defined_by(v, &Family::ThesisCubic)
}

fn t8a() -> Verdict {
    monotone(&Family::ThesisCubic, 0, false, Some("m"), &m_range())
}

fn t8b() -> Verdict {
    monotone(&Family::ThesisCubic, 3, true, Some("m"), &m_range())
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
