//! Seed 000, Appendices C and D: the printed one-sided derivatives of the
//! B-spline pieces (M5) and of the curve (M9, M9b), and Theorems 3, 4, 7
//! (M4, M4b, M8) decided by the exact knot-jump computation of
//! [`crate::continuity`].

use std::sync::OnceLock;

use trig_core::Family;
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_symbolic::Sym;

use super::seed000_appendix_print::{printed_part, zeta};
use crate::claim::{Claim, shared};
use trig_deriv::continuity::{
    self, KnotContinuity, curve_jumps, nonuniform_bspline, uniform_bspline,
};
use trig_judge::continuity::{METHOD, at_least, describe, knot_witness};
use trig_judge::exact::{IDENTITY, symbols};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "M4",
        check: m4,
    },
    Claim {
        id: "M4b",
        check: m4b,
    },
    Claim {
        id: "M8",
        check: m8,
    },
    Claim {
        id: "M5",
        check: m5,
    },
    Claim {
        id: "M9",
        check: m9,
    },
    Claim {
        id: "M9b",
        check: m9b,
    },
];

/// A non-uniform knot vector with distinct integer knots and unequal
/// spacings (q = 1, 2, 1, 3, 1, 2, 3, …).
pub(super) fn nonuniform_knots() -> Vec<Sym> {
    [
        0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25, 26, 29, 30, 32, 35, 36, 38,
    ]
    .map(Sym::int)
    .to_vec()
}

/// The basis function examined on [`nonuniform_knots`].
pub(super) const NONUNIFORM_J: i64 = 8;

/// Derivatives of orders 0–6 of `l₀…l₃` at an end, in `u` (factor `(π/2)^k`,
/// the print's convention), as `[k][order]`.
fn blending_at(end: End) -> Vec<Vec<Sym>> {
    endpoint_derivatives::<Sym, 7>(Family::Seed000Blending, &[zeta()], end, Wrt::U, &Sym::one())
}

/// `Σ_k coef_k l_k^{(r)}` at `end`, orders 0–6.
fn piece_at(coef: &[Sym; 4], end: End) -> Vec<Sym> {
    let l = blending_at(end);
    (0..7)
        .map(|r| (0..4).fold(Sym::zero(), |acc, k| acc + &(coef[k].clone() * &l[k][r])))
        .collect()
}

fn m5() -> Verdict {
    let z = Sym::zero();
    let v = |n: &str| Sym::var(n);
    let a = [z.clone(), z.clone(), z.clone(), v("a")];
    let c = [v("c0"), v("c1"), v("c2"), v("c3")];
    let b = [v("b0"), v("b1"), v("b2"), v("b3")];
    let d = [v("d"), z.clone(), z.clone(), z];
    // (location, piece coefficients, end of that piece, printed values by order)
    let table: [(&str, &[Sym; 4], End, [&str; 6]); 7] = [
        (
            "n_{j+1}^-",
            &a,
            End::End,
            [
                "S a",
                "(pi/2)(1 + 2S) a",
                "(pi/2)^2 (2 + S) a",
                "(pi/2)^3 (5 - 2S) a",
                "(-pi/2)^4 [8(2 + S) a]",
                "(pi/2)^5 [(2S - 59) a]",
            ],
        ),
        // "all other derivative vanishes at this knot except the fourth", and (A3)
        (
            "n_j^+",
            &a,
            End::Start,
            ["0", "0", "0", "0", "(pi/2)^4 [(6 + 6S) a]", "0"],
        ),
        (
            "n_{j+1}^+",
            &c,
            End::Start,
            [
                "S(c0 + c2) + 4(S + 1)c1",
                "(pi/2)(1 + 2S)(c2 - c0)",
                "(pi/2)^2 (2(2 + S))(c0 - 2c1 + c2)",
                "(pi/2)^3 (2S - 5)(c0 - c2)",
                "(-pi/2)^4 [8(2 + S)(c0 - c1 + c2 - c3) - 2(S + 11)(c1 - c3)]",
                "(-pi/2)^5 [(2S - 59)(c0 - c2)]",
            ],
        ),
        (
            "n_{j+2}^-",
            &c,
            End::End,
            [
                "S(c1 + c3) + 4(S + 1)c2",
                "(pi/2)(1 + 2S)(c3 - c1)",
                "(pi/2)^2 (2(2 + S))(c1 - 2c2 + c3)",
                "(pi/2)^3 (2S - 5)(c1 - c3)",
                "(-pi/2)^4 [8(2 + S)(c3 - c2 - c0) - 2(S + 11)(c2 - c0)]",
                "(-pi/2)^5 [(2S - 59)(c1 - c3)]",
            ],
        ),
        (
            "n_{j+2}^+",
            &b,
            End::Start,
            [
                "S(b0 + b2) + 4(S + 1)b1",
                "(pi/2)(1 + 2S)(b2 - b0)",
                "(pi/2)^2 (2(2 + S))(b0 - 2b1 + b2)",
                "(pi/2)^3 (2S - 5)(b0 - b2)",
                "(pi/2)^4 [8(2 + S)(b1 - b0 - b2 + b3) + 2(S + 11)(b1 - b3)]",
                "(pi/2)^5 [(2S - 59)(b2 - b0)]",
            ],
        ),
        (
            "n_{j+3}^-",
            &b,
            End::End,
            [
                "S(b1 + b3) + 4(S + 1)b2",
                "(pi/2)(1 + 2S)(b3 - b1)",
                "(pi/2)^2 (2(2 + S))(b1 - 2b2 + b3)",
                "(pi/2)^3 (2S - 5)(b1 - b3)",
                "(pi/2)^4 [8(2 + S)(b0 - b1 + b2 - b3) + 2(S + 11)(b2 - b0)]",
                "(pi/2)^5 [(2S - 59)(b3 - b1)]",
            ],
        ),
        (
            "n_{j+3}^+",
            &d,
            End::Start,
            [
                "S d",
                "(-pi/2)(1 + 2S) d",
                "(pi/2)^2 (2(2 + S)) d",
                "(pi/2)^3 (2S - 5) d",
                "(-pi/2)^4 [8(2 + S) d]",
                "(pi/2)^5 [(59 - 2S) d]",
            ],
        ),
    ];
    let mut parts = Vec::new();
    for (at, coef, end, values) in table {
        let computed = piece_at(coef, end);
        for (r, text) in values.iter().enumerate() {
            parts.push(printed_part(
                format!("F_j^({r})({at})"),
                text,
                &[],
                &computed[r],
            ));
        }
    }
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(
        0,
        "pieces of (1) with the coefficients as symbols: a = a_j (piece a_j l3 on [n_j, n_{j+1})), c_k = c_{j+1,k}, b_k = b_{j+2,k}, d = d_{j+3}; S = s(ξ) = ξ² − ξ + 1; derivatives in the local variable u = (n − n_i)/q_i, t = πu/2 (the print's factors (π/2)^k)",
    );
    v
}

/// The curve `T(n) = Σ_i F_i(n) S_i` of (6) on `[n_j, n_{j+1})`, with the
/// segment functions of (5) (`F_0 = d_j l₀`, `F_1 = Σ_k b_{j,k} l_k`,
/// `F_2 = Σ_k c_{j,k} l_k`, `F_3 = a_j l₃`, coefficients and control points
/// `S_i` as symbols): its derivatives of orders 0–6 at `end`, in `u`.
fn curve_at(end: End) -> Vec<Sym> {
    let z = Sym::zero();
    let (b, c, s) = (symbols("b", 4), symbols("c", 4), symbols("S", 4));
    let coef: [[Sym; 4]; 4] = [
        [Sym::var("d"), z.clone(), z.clone(), z.clone()],
        [b[0].clone(), b[1].clone(), b[2].clone(), b[3].clone()],
        [c[0].clone(), c[1].clone(), c[2].clone(), c[3].clone()],
        [z.clone(), z.clone(), z, Sym::var("a")],
    ];
    let pieces: Vec<Vec<Sym>> = coef.iter().map(|k| piece_at(k, end)).collect();
    (0..7)
        .map(|r| (0..4).fold(Sym::zero(), |acc, i| acc + &(pieces[i][r].clone() * &s[i])))
        .collect()
}

/// One printed line of Appendix D: its label as printed, the end of the
/// span, the order it stands for in its list, the value as printed, and why
/// it cannot be checked as printed (if so).
#[derive(Clone, Copy)]
struct DLine {
    label: &'static str,
    end: End,
    order: usize,
    text: &'static str,
    garbled: Option<&'static str>,
}

const MISLABELLED: &str = "garbled label: T_{j+1}''(n_j^-) names neither the knot of its list (n_{j+1}^-) nor the segment T_j of this appendix (n_j^- lies outside [n_j, n_{j+1}), and T_{j+1} is not given); M9b checks the reading T''(n_{j+1}^-)";

/// Appendix D as printed (`S` = s(ξ); `d, b_k, c_k, a` = `d_j, b_{j,k},
/// c_{j,k}, a_j`; control points `S0…S3`).
const APPENDIX_D: [DLine; 12] = [
    DLine {
        label: "T(n_j^+)",
        end: End::Start,
        order: 0,
        text: "S d S0 + [S b0 + 4(S + 1)b1 + S b2]S1 + [S c0 + 4(S + 1)c1 + S c2]S2",
        garbled: None,
    },
    DLine {
        label: "T_j'(n_j^+)",
        end: End::Start,
        order: 1,
        text: "(pi/2){(1 + 2S)[-d S0 + (b2 - b0)S1 + (c2 - c0)S2]}",
        garbled: None,
    },
    DLine {
        label: "T_j''(n_j^+)",
        end: End::Start,
        order: 2,
        text: "(pi/2)^2 {2((2 + S))[d S0 + (b0 - 2b1 + b2)S1 + (c0 - 2c1 + c2)S2]}",
        garbled: None,
    },
    DLine {
        label: "T_j'''(n_j^+)",
        end: End::Start,
        order: 3,
        text: "(pi/2)^3 {(5 + 2S)[d S0 + (b0 - b2)S1 + (c0 - c2)S2]}",
        garbled: None,
    },
    DLine {
        label: "T_j^iv(n_j^+)",
        end: End::Start,
        order: 4,
        text: "-(pi/2)^4 {[8(2 + S)(d S0 + (b0 - b1 + b2 - b3)S1 + (c0 - c1 + c2 - c3)S2 + a S3) + 2(S + 11)[(b1 - b3)S1 + (c1 - c3)S2 - a S3]]}",
        garbled: None,
    },
    DLine {
        label: "T_j^v(n_j^+)",
        end: End::Start,
        order: 5,
        text: "-(pi/2)^5 {[(59 - 2S)(d S0 + (b0 - b2)S1 + (c0 - c2 + c2)S2)]}",
        garbled: None,
    },
    DLine {
        label: "T(n_{j+1}^-)",
        end: End::End,
        order: 0,
        text: "[S b1 + 4(S + 1)b2 + S b3]S1 + [S c1 + 4(S + 1)c2 + S c3]S2 + S a S3",
        garbled: None,
    },
    DLine {
        label: "T_j'(n_{j+1}^-)",
        end: End::End,
        order: 1,
        text: "(pi/2){(1 + 2S)[(b3 - b1)S1 + (c3 - c1)S2 + a S3]}",
        garbled: None,
    },
    DLine {
        label: "T_{j+1}''(n_j^-)",
        end: End::End,
        order: 2,
        text: "(pi/2)^2 {2((2 + S))[(b1 - 2b2 + b3)S1 + (c1 - 2c2 + c3)S2 + a S3]}",
        garbled: Some(MISLABELLED),
    },
    DLine {
        label: "T_j'''(n_{j+1}^-)",
        end: End::End,
        order: 3,
        text: "(pi/2)^3 {(1 + 2S)[(b1 - b3)S1 + (c1 - c3)S2 + a S3]}",
        garbled: None,
    },
    DLine {
        label: "T_j^iv(n_{j+1}^-)",
        end: End::End,
        order: 4,
        text: "(pi/2)^4 {[8(2 + S)(d S0 + (b0 - b1 + b2 - b3)S1 + (c0 - c1 + c2 - c3)S2 - a S3) + 2(S + 11)[d S0 + (b2 - b0)S1 + (c2 - c0)S2]]}",
        garbled: None,
    },
    DLine {
        label: "T_j^v(n_{j+1}^-)",
        end: End::End,
        order: 5,
        text: "(pi/2)^5 {[(2S - 59)((b3 - b1)S1 + (c3 - c1)S2) + a S3]}",
        garbled: None,
    },
];

const APPENDIX_D_SETUP: &str = "curve T(n) = Σ_i F_i(n) S_i of (6) on [n_j, n_{j+1}) with F_0 = d l0, F_1 = Σ b_k l_k, F_2 = Σ c_k l_k, F_3 = a l3 of (5); coefficients d = d_j, b_k = b_{j,k}, c_k = c_{j,k}, a = a_j and control points S0…S3 as symbols; S = s(ξ); derivatives in the local variable u (the print's factors (π/2)^k, as in Appendix C)";

/// Each line whose label is readable compared with the computed derivative
/// of its order at its end; the others recorded as not checkable.
fn appendix_d(lines: impl Iterator<Item = DLine>, label: impl Fn(&DLine) -> String) -> Verdict {
    let computed = [curve_at(End::Start), curve_at(End::End)];
    let (mut parts, mut garbled) = (Vec::new(), Vec::new());
    for line in lines {
        match line.garbled {
            None => {
                let at = usize::from(line.end == End::End);
                parts.push(printed_part(
                    label(&line),
                    line.text,
                    &[],
                    &computed[at][line.order],
                ));
            }
            Some(reason) => garbled.push((
                format!("{} printed {}", label(&line), line.text),
                Verdict::not_checkable(reason),
            )),
        }
    }
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(0, APPENDIX_D_SETUP);
    v.evidence.extend(Verdict::all(IDENTITY, garbled).evidence);
    v
}

fn m9() -> Verdict {
    let mut v = appendix_d(APPENDIX_D.into_iter(), |l| l.label.to_string());
    v.evidence.insert(
        1,
        "read as printed: the stray comma in \"S_1, + [...]S_2\" of T(n_j^+) is punctuation; the unmatched \"[\" opening both T^iv values is closed before \"}\" (it groups a sum: any closing gives the same value); \"(c_{j,0} − c_{j,2} + c_{j,2})\" in T^v(n_j^+) is kept as printed",
    );
    v
}

fn m9b() -> Verdict {
    appendix_d(
        APPENDIX_D
            .into_iter()
            .filter(|l| l.garbled.is_some())
            .map(|l| DLine { garbled: None, ..l }),
        |l| format!("{} read as T''(n_{{j+1}}^-)", l.label),
    )
}

/// The claim "C⁵ for ξ ≠ 1": it fails when some knot is below C⁵ for
/// generic ξ (then every ξ outside the finitely many exceptions is a
/// counterexample); the exceptional values where C⁵ holds are listed.
fn c5_except_one(label: &str, knots: &[KnotContinuity]) -> Verdict {
    let mut evidence = trig_verdict::evidence::EvidenceList::from(vec![format!(
        "{label}: C^5 claimed for every ξ ≠ 1"
    )]);
    for k in knots.iter().filter(|k| !k.smoothness.is_at_least(5)) {
        let good: Vec<String> = k
            .exceptions
            .iter()
            .filter(|e| e.smoothness.is_at_least(5))
            .map(|e| e.value.to_string())
            .collect();
        evidence.push(
            trig_verdict::evidence::Evidence::note(format!(
                "knot {}: {} for every ξ except ξ ∈ {{{}}}, where it is C^5",
                k.knot,
                k.smoothness,
                good.join(", ")
            ))
            .witnessed(knot_witness(k)),
        );
    }
    let ok = knots.iter().all(|k| k.smoothness.is_at_least(5));
    Verdict::new(
        if ok { Status::Holds } else { Status::Fails },
        METHOD,
        evidence,
    )
}

fn uniform_basis() -> Vec<KnotContinuity> {
    let pieces = uniform_bspline(&Family::Seed000Uniform, &[zeta()]);
    continuity::continuity(&pieces, true, Some("zeta"))
}

/// The interior knots of the uniform curve `Σ F_i P_i` over `spans` unit
/// spans (control points `P0…` as symbols), optionally rational with
/// weights `w0…`: at knot `k` the end of span `k − 1` meets the start of
/// span `k` (only these one-sided derivatives are computed).
pub(super) fn uniform_curve(rational: bool, spans: usize) -> Vec<KnotContinuity> {
    let p = symbols("P", spans + 3);
    let w = symbols("w", spans + 3);
    (1..spans)
        .map(|knot| {
            let (left, right) = (knot - 1..knot + 3, knot..knot + 4);
            let jumps = curve_jumps(
                Family::Seed000Uniform,
                &[zeta()],
                (&p[left.clone()], &p[right.clone()]),
                rational.then(|| (&w[left], &w[right])),
            );
            continuity::classify(knot, jumps, Some("zeta"))
        })
        .collect()
}

fn m4() -> Verdict {
    let basis = uniform_basis();
    let curve = uniform_curve(false, 3);
    let mut parts = vec![
        (
            "Theorem 3, C^3, uniform knots (Appendix A basis F_j = l_k/(6ζ²−6ζ+10) on unit knots 0…4)".to_string(),
            at_least("basis F_j", &basis, 3, Some("zeta")),
        ),
        (
            "Theorems 3/4, C^5 (\"for ξ ≠ 1\"), uniform basis".to_string(),
            c5_except_one("basis F_j", &basis),
        ),
        (
            "Theorem 4, C^3, uniform curve Σ F_i P_i (three spans, symbolic P0…P5)".to_string(),
            at_least("curve", &curve, 3, Some("zeta")),
        ),
        (
            "Theorem 4, C^5 for ξ ≠ 1, uniform curve".to_string(),
            c5_except_one("curve", &curve),
        ),
    ];
    parts.push((
        format!(
            "Theorem 3, non-uniform knots with the printed coefficients (2)–(3), F_{NONUNIFORM_J} on knots {}",
            nonuniform_knots().iter().map(|k| k.to_string()).collect::<Vec<_>>().join(", ")
        ),
        match nonuniform_bspline(&nonuniform_knots(), &zeta(), NONUNIFORM_J) {
            Ok(pieces) => at_least(
                "non-uniform F_j",
                &continuity::continuity(&pieces, true, Some("zeta")),
                3,
                Some("zeta"),
            ),
            Err(e) => Verdict::not_checkable(format!("the construction is undefined: {e}")),
        },
    ));
    Verdict::all(METHOD, parts)
}

/// Knot vectors with one knot of multiplicity `k` inside the support of
/// `F_j`, `j` = [`NONUNIFORM_J`].
fn multiple_knots(k: usize) -> Vec<Sym> {
    let mut knots = nonuniform_knots();
    let at = NONUNIFORM_J as usize + 2;
    for i in 1..k {
        knots[at + i] = knots[at].clone();
    }
    // keep the knots after the repeated one increasing
    knots
}

fn m4b() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        let mut parts = Vec::new();
        for k in 2..=4 {
            let knots = multiple_knots(k);
            let label = format!(
                "multiplicity {k} (claimed C^{}), printed coefficients (2)–(3), knots {}",
                3 - k as i64,
                knots
                    .iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            );
            let v = match nonuniform_bspline(&knots, &zeta(), NONUNIFORM_J) {
                Ok(pieces) => {
                    let cont = continuity::continuity(&pieces, true, Some("zeta"));
                    let want = 3 - k as i64;
                    let ok = cont.iter().all(|c| c.smoothness.rank() >= want);
                    Verdict::new(
                        if ok { Status::Holds } else { Status::Fails },
                        METHOD,
                        cont.iter().map(|c| {
                            let item = describe(c, Some("zeta"));
                            if c.smoothness.rank() >= want {
                                item
                            } else {
                                item.witnessed(knot_witness(c))
                            }
                        }),
                    )
                }
                Err(e) => Verdict::not_checkable(format!(
                    "the printed construction (2)–(3) is undefined at coincident knots: {e}"
                )),
            };
            parts.push((label, v));
        }
        let uniform = Verdict::not_checkable(
            "the uniform construction (Appendix A) has unit knot spacing only: it has no knots of multiplicity k > 1",
        );
        parts.push(("uniform reading".into(), uniform));
        let all = Verdict::all(METHOD, parts.clone());
        if parts.iter().all(|(_, v)| v.status == Status::NotCheckable) {
            Verdict::new(Status::NotCheckable, "none possible", all.evidence)
        } else {
            all
        }
    })
}

fn m8() -> Verdict {
    let curve = uniform_curve(true, 2);
    Verdict::all(
        METHOD,
        vec![
            (
                "C^3, uniform rational curve Σ w_i F_i P_i / Σ w_i F_i (two spans, symbolic P0…P4, w0…w4)".to_string(),
                at_least("rational curve", &curve, 3, Some("zeta")),
            ),
            ("C^{3−k} at knots of multiplicity k (as M4b)".to_string(), m4b()),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::seed000_appendix_print::{compare, read};
    use trig_deriv::continuity::Smoothness;

    #[test]
    fn uniform_seed000_basis_is_c3_at_its_ends_and_smooth_inside() {
        let knots = uniform_basis();
        assert_eq!(knots[0].smoothness, Smoothness::Exactly(3));
        assert_eq!(knots[4].smoothness, Smoothness::Exactly(3));
        for k in &knots[1..4] {
            assert_eq!(k.smoothness, Smoothness::AtLeast(6));
        }
        let values: Vec<String> = knots[0]
            .exceptions
            .iter()
            .map(|e| e.value.to_string())
            .collect();
        assert_eq!(values, ["0", "1"]);
        assert!(
            knots[0]
                .exceptions
                .iter()
                .all(|e| e.smoothness == Smoothness::Exactly(5))
        );
    }

    #[test]
    fn appendix_d_checks_readable_lines_and_records_the_mislabelled_one() {
        let v = m9();
        assert_eq!(v.status, Status::Fails);
        let line = |label: &str| {
            v.evidence
                .iter()
                .map(|e| e.line())
                .find(|e| e.starts_with(&format!("{label} printed")))
                .unwrap_or_else(|| panic!("{label}: {:?}", v.evidence))
        };
        assert!(line("T(n_j^+)").contains(": holds"));
        // T'''(n_j^+) = (π/2)³ (2S − 5)[…] (Appendix C's factor), printed (5 + 2S)
        assert!(line("T_j'''(n_j^+)").contains(": fails"));
        assert!(line("T_{j+1}''(n_j^-)").contains(": not-checkable — garbled label"));
        assert_eq!(m9b().status, Status::Holds);
        let want = read("(pi/2)^3 (2S - 5)[d S0 + (b0 - b2)S1 + (c0 - c2)S2]", &[]).unwrap();
        assert_eq!(
            compare(&want, &curve_at(End::Start)[3]).status,
            Status::Holds
        );
    }

    #[test]
    fn appendix_c_has_the_known_a3_misprint() {
        let v = m5();
        assert_eq!(v.status, Status::Fails);
        let a3: Vec<String> = v
            .evidence
            .iter()
            .map(|e| e.line())
            .filter(|e| e.contains("(6 + 6S)"))
            .collect();
        assert_eq!(a3.len(), 1);
        assert!(a3[0].contains(": fails"), "{a3:?}");
        // the first value at n_{j+1}^- is right
        assert!(
            v.evidence
                .iter()
                .any(|e| e.contains("F_j^(0)(n_{j+1}^-) printed S a: holds"))
        );
    }
}
