//! Seeds 002 and 004, thesis T32: the verdicts the audit computes for
//! their claims, and independent MPFR re-checks of the two-parameter certifier.

use proptest::prelude::*;
use rug::{Float, Rational};
use trig_certify::ParamBox;
use trig_certify::maxima::{Maximum, profile};
use trig_certify::nonneg::{BoxCertificate, certify_box};
use trig_core::{Family, Mpfr, Real};
use trig_judge::exact::basis;
use trig_verification::{Status, Verdict, run};

const PREC: u32 = 256;

fn verdict(id: &str) -> Verdict {
    let mut o = run(None, Some(id)).expect("the document files");
    assert_eq!(o.len(), 1, "{id}");
    o.remove(0).verdict
}

fn has(v: &Verdict, needle: &str) -> bool {
    v.evidence.iter().any(|e| e.contains(needle))
}

/// The EH bases at `t` in 256-bit MPFR through the catalog's numeric path.
fn eh_at(lambda: &Rational, mu: &Rational, t: &Rational) -> Vec<Mpfr> {
    let x = Mpfr(Float::with_val(PREC, t));
    Family::Eh
        .eval_at(&x, &[lambda.clone(), mu.clone()], true)
        .expect("finite")
}

#[test]
fn seed002_verdicts() {
    assert_eq!(verdict("D4").status, Status::Holds);
    assert_eq!(verdict("D11").status, Status::Holds);
    let d6 = verdict("D6");
    assert_eq!(d6.status, Status::Fails);
    assert!(has(&d6, "29*P0*w1^2/w0^2"), "{:?}", d6.evidence);
    assert_eq!(verdict("D6b").status, Status::Holds);
    let d7 = verdict("D7");
    assert_eq!(d7.status, Status::NotCheckable);
    assert_eq!(
        d7.evidence
            .iter()
            .filter(|e| e.contains("orders 0–2") && e.contains("exactly 0"))
            .count(),
        3
    );
}

/// The Fourier-span check: the quartic basis lies in the printed span of
/// D11; without `cos 4t` it does not, and the harmonic is named.
#[test]
fn a_span_without_a_harmonic_of_the_functions_is_refuted() {
    let span = |items: &str| {
        let spec = crate::common::example_with(
            "catalog/seed002-quartic",
            &format!(
                "[[claims]]\nid = \"f\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"fourier-span\"\nspan = [{items}]\n"
            ),
        );
        trig_verification::spec_audit::decide(&spec, &spec.claims[0])
    };
    let printed = r#""1", "sin(t)", "cos(t)", "cos(2*t)", "sin(3*t)", "cos(3*t)", "sin(4*t)""#;
    let short = span(printed);
    assert_eq!(short.status, Status::Fails);
    assert!(
        has(&short, "outside the printed span: cos 4t: 1/8"),
        "{:?}",
        short.evidence
    );
    assert!(has(&short, "omits sin 2t, cos 4t"), "{:?}", short.evidence);
    assert_eq!(
        span(&format!("{printed}, \"cos(4*t)\"")).status,
        Status::Holds
    );
    // an element that is not one harmonic
    assert_eq!(span(r#""sin(t)^2""#).status, Status::NotCheckable);
}

#[test]
fn unimodality_is_refuted_for_a_function_with_two_maxima() {
    // b0 + b5 of seed 002 is 1 at both ends and smaller inside
    let b = basis(Family::Seed002Quartic);
    let p = profile(&(b[0].clone() + &b[5]), true).unwrap();
    assert_eq!(p.maxima, vec![Maximum::Start, Maximum::End]);
    let p1 = profile(&b[1], true).unwrap();
    assert!(matches!(p1.maxima[..], [Maximum::Interior(..)]));
}

#[test]
fn seed004_join_and_interpolation_verdicts() {
    let e1c = verdict("E1c");
    assert_eq!(e1c.status, Status::Fails);
    assert!(has(&e1c, "-y_i + y_i1"));
    let e1cb = verdict("E1cb");
    assert_eq!(e1cb.status, Status::HoldsAfterCorrection);
    assert!(has(&e1cb, "(-d_i1*h_i + d_i1*h_i1)/h_i"));
    let e14 = verdict("E14");
    assert_eq!(e14.status, Status::Fails);
    assert!(has(&e14, "-P1 + P3"));
    assert_eq!(
        e14.correction.as_deref(),
        Some("use the derived formula: Q₀ = P₁; Q₂ = P₃")
    );
    assert_eq!(verdict("E15").status, Status::NotCheckable);
    assert_eq!(verdict("E15b").status, Status::Fails);
    assert_eq!(verdict("E16").status, Status::Fails);
    let e17 = verdict("E17");
    assert_eq!(e17.status, Status::Fails);
    assert!(has(&e17, "-P1 + P3"), "{:?}", e17.evidence);
}

/// `orientation = "reversed"`: the printed factor gives the first
/// segment's tangent from the second's (`P'(1) = ωQ'(0)`). The EH curve
/// ends at `P1` with tangent `P3` and starts at `Q0` with tangent `Q2`, so
/// `Q2 = P3/ω` is the G¹ join in that orientation and not in the judge's
/// own (`Q'(0) = ωP'(1)`).
#[test]
fn a_reversed_g1_factor_is_decided_in_the_printed_orientation() {
    let g1 = |orientation: &str| {
        let spec = crate::common::example_with(
            "catalog/eh",
            &format!(
                "[[claims]]\nid = \"g\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"join\"\njoin = \"G1\"\nfactors = [\"omega\", \"beta\"]\n{orientation}conditions = [\"Q0 = P1\", \"Q2 = P3/omega\"]\n"
            ),
        );
        trig_verification::spec_audit::decide(&spec, &spec.claims[0])
    };
    let reversed = g1("orientation = \"reversed\"\n");
    assert_eq!(reversed.status, Status::Holds, "{:?}", reversed.evidence);
    assert!(has(&reversed, "printed orientation"));
    // ω > 0: the printed division by ω is not singular
    assert!(!has(&reversed, "singular"), "{:?}", reversed.evidence);
    assert_eq!(g1("").status, Status::Fails);
}

#[test]
fn e4_is_refuted_on_the_published_box_and_the_counterexample_rechecks() {
    let e4 = verdict("E4");
    assert_eq!(e4.status, Status::Fails);
    let one = Rational::from(1);
    let unit = ParamBox::closed(-one.clone(), one);
    let b = basis(Family::Eh);
    let params = [("lambda", unit.clone()), ("mu", unit)];
    for (i, f) in b.iter().enumerate() {
        match certify_box(f, false, &params) {
            BoxCertificate::NonNegative { .. } => assert!(i < 3, "b{i}"),
            BoxCertificate::Counterexample { params, z, value } => {
                assert_eq!(i, 3);
                assert!(value < 0);
                let v = &eh_at(&params[0], &params[1], &z)[i];
                assert!(v.to_f64() < 0.0, "{v}");
            }
            other => panic!("b{i}: {other:?}"),
        }
    }
}

#[test]
fn two_parameter_boxes_both_ways() {
    // b0 = (1 − t)²(1 + 2t + λt²) ≥ 0 exactly for λ ≥ −3; μ does not enter
    let b0 = &basis(Family::Eh)[0];
    let q = |a: i64, b: i64| Rational::from((a, b));
    let inside = [
        ("lambda", ParamBox::closed(q(-3, 1), q(5, 1))),
        ("mu", ParamBox::closed(q(-7, 1), q(7, 1))),
    ];
    assert!(matches!(
        certify_box(b0, false, &inside),
        BoxCertificate::NonNegative { .. }
    ));
    let beyond = [
        ("lambda", ParamBox::closed(q(-301, 100), q(-301, 100))),
        ("mu", ParamBox::closed(q(0, 1), q(1, 1))),
    ];
    match certify_box(b0, false, &beyond) {
        BoxCertificate::Counterexample { params, z, value } => {
            assert!(value < 0);
            assert!(eh_at(&params[0], &params[1], &z)[0].to_f64() < 0.0);
        }
        other => panic!("{other:?}"),
    }
    // a half-line in λ: b0 ≥ 0 for λ ∈ [0, ∞)
    let half = [
        ("lambda", ParamBox::from_closed(q(0, 1))),
        ("mu", ParamBox::closed(q(0, 1), q(1, 1))),
    ];
    assert!(matches!(
        certify_box(b0, false, &half),
        BoxCertificate::NonNegative { .. }
    ));
}

#[test]
fn t32_table_arithmetic() {
    let t32 = verdict("T32");
    assert_eq!(t32.status, Status::Fails);
    assert!(has(
        &t32,
        "Table 6.2 (Epsilon, proposed (I)): fails — TOTAL before total"
    ));
    assert!(has(&t32, "difference 0.8023"));
    assert!(has(&t32, "Table 6.3 (Epsilon, Majeed (II)): holds"));
    assert!(has(&t32, "difference -2.3255"));
    assert!(has(&t32, "printed = 14.6171, computed = 16.9426"));
    assert!(has(&t32, "difference 0.03"));
    assert!(has(&t32, "printed = 10355.28, computed = 10355.25"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// b0, b1, b2 are certified ≥ 0 on λ, μ ∈ [−1, 1]; random points there
    /// evaluate ≥ 0 in MPFR (values O(1), 256-bit rounding far below 1e-70).
    #[test]
    fn certified_eh_region_is_nonnegative_in_mpfr(
        l in -1.0..=1.0f64, m in -1.0..=1.0f64, t in 0.0..=1.0f64
    ) {
        let r = |x: f64| Rational::from_f64(x).unwrap();
        let v = eh_at(&r(l), &r(m), &r(t));
        for (i, vi) in v.iter().take(3).enumerate() {
            prop_assert!(vi.to_f64() >= -1e-70, "b{i} = {vi}");
        }
    }
}

/// The identity check's readings: a print that fails is corrected only
/// where every failing print has a reading that holds (E9, M1), and the
/// correction names print → reading; a print without readings stays
/// refuted (D6, its reading D6b a claim of its own).
#[test]
fn identity_readings_correct_only_what_they_read() {
    for id in ["E9", "M1"] {
        let v = verdict(id);
        assert_eq!(v.status, Status::HoldsAfterCorrection, "{id}");
        assert!(
            v.correction.as_deref().is_some_and(|c| c.contains(" → ")),
            "{id}: {:?}",
            v.correction
        );
        assert!(has(&v, "reading of "), "{id}");
    }
    assert_eq!(verdict("D6").status, Status::Fails);
    assert_eq!(verdict("D6b").status, Status::Holds);
}
