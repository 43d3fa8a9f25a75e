//! Seed 000, Appendix E: the rational basis `Q_i = w_i F_i / Σ w_k F_k` on
//! the span `[n_j, n_{j+1})` (times its control point `H_i`, as printed) and
//! its derivatives at `n_j^+` and `n_{j+1}^−`: general coefficients (A4)–(A35)
//! (M12, M15) and the uniform case (A36)–(A59) (M7, M10, M13).
//!
//! Computed with Taylor jets of the catalog's blending functions `l_k`
//! (general case: `F₀ = d l₀`, `F₁ = Σ b_k l_k`, `F₂ = Σ c_k l_k`, `F₃ = a l₃`,
//! eq. (5), coefficients as symbols) or of the Appendix A basis (uniform
//! case), derivatives in `n` with `t = π(n − n_j)/(2q_j)` (factor
//! `(π/(2q_j))^k`, as printed).

use std::sync::OnceLock;

use trig_core::Family;
use trig_deriv::table::{end_atoms, rate};
use trig_deriv::{End, Jet, Wrt};
use trig_symbolic::Sym;

use super::seed000_appendix_print::{Shorthand, printed_part, zeta};
use crate::claim::{Claim, Seed};
use crate::exact::{IDENTITY, symbols};
use trig_deriv::continuity::quotient_derivatives;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "M7",
        seed: Seed::S000,
        source: "Appendix E, (A36)–(A43)",
        statement: "rational basis values ⟪Q_i(n_j^+)⟫, ⟪Q_i(n_{j+1}^−)⟫ times ⟪H_i⟫, uniform knots",
        check: m7,
    },
    Claim {
        id: "M10",
        seed: Seed::S000,
        source: "Appendix E, (A44)–(A51)",
        statement: "their first derivatives, uniform knots",
        check: m10,
    },
    Claim {
        id: "M13",
        seed: Seed::S000,
        source: "Appendix E, (A52)–(A59)",
        statement: "their second derivatives, uniform knots",
        check: m13,
    },
    Claim {
        id: "M13b",
        seed: Seed::S000,
        source: "Appendix E, (A55)",
        statement: "reading of the mislabelled (A55) \"⟪Q''_2(n_j^+) = 0⟫\" (it follows (A54), which gives ⟪Q''_2⟫): ⟪Q''_3(n_j^+) = 0⟫",
        check: m13b,
    },
    Claim {
        id: "M12",
        seed: Seed::S000,
        source: "Appendix E, (A4)–(A19)",
        statement: "values and first derivatives of ⟪Q_i H_i⟫ at ⟪n_j^+⟫, ⟪n_{j+1}^−⟫ with general coefficients ⟪d_j⟫, ⟪b_{j,k}⟫, ⟪c_{j,k}⟫, ⟪a_j⟫",
        check: m12,
    },
    Claim {
        id: "M12b",
        seed: Seed::S000,
        source: "Appendix E, (A5), (A6), (A13), (A14), (A17), (A18)",
        statement: "reading of the garbled prints: (A5), (A6) with the bracket ⟪[s(ξ)(b_{j0} + b_{j2}) + 4(s(ξ)+1)b_{j1}]⟫ around the numerator's value; (A13), (A14), (A17), (A18) with the printed \"denominator\" ⟪M⟫ (resp. ⟪L⟫) as a factor of the second term and the missing denominator ⟪A²⟫ (resp. ⟪B²⟫)",
        check: m12b,
    },
    Claim {
        id: "M15",
        seed: Seed::S000,
        source: "Appendix E, (A20)–(A35)",
        statement: "second and third derivatives of ⟪Q_i H_i⟫ at ⟪n_j^+⟫, ⟪n_{j+1}^−⟫ with general coefficients",
        check: m15,
    },
];

/// Orders 0–1 (values and first derivatives, M12) and 0–3 (M7–M15); a
/// table of `K` orders is the first `K` of any longer one.
const FIRST: usize = 2;
const THIRD: usize = 4;

/// `Q_i H_i` derivatives `[end][i][order]` (end 0 = `n_j^+`, 1 = `n_{j+1}^−`)
/// from segment functions given as jets: `Q_i H_i = w_i F_i H_i / Σ_k w_k F_k`
/// by [`quotient_derivatives`], then the factor `(π/(2q))^k`.
fn rational_table<const K: usize>(
    segments: impl Fn(End) -> Vec<Jet<Sym, K>>,
) -> Vec<Vec<Vec<Sym>>> {
    let (w, h) = (symbols("w", 4), symbols("H", 4));
    let q = Sym::var("q");
    let dt = rate(Family::Seed000Blending, Wrt::X, &q, &[zeta()]);
    [End::Start, End::End]
        .into_iter()
        .map(|end| {
            let weighted: Vec<Jet<Sym, K>> = segments(end)
                .into_iter()
                .zip(&w)
                .map(|(fi, wi)| fi * &Jet::constant(wi.clone()))
                .collect();
            let total = weighted[1..]
                .iter()
                .fold(weighted[0].clone(), |acc, x| acc + x);
            let numerators: Vec<Vec<Sym>> = weighted
                .iter()
                .zip(&h)
                .map(|(wf, hi)| (wf.clone() * &Jet::constant(hi.clone())).derivatives())
                .collect();
            let refs: Vec<&[Sym]> = numerators.iter().map(Vec::as_slice).collect();
            quotient_derivatives(&refs, &total.derivatives())
                .into_iter()
                .map(|qh| {
                    let mut factor = Sym::one();
                    qh.into_iter()
                        .map(|d| {
                            let v = d * &factor;
                            factor = factor.clone() * &dt;
                            v
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// Jets of `l₀…l₃` at an end of the span.
fn blending_jets<const K: usize>(end: End) -> Vec<Jet<Sym, K>> {
    let atoms = end_atoms::<Sym, K>(Family::Seed000Blending, end, &Sym::one(), &[zeta()]);
    Family::Seed000Blending.eval(&atoms, &[Jet::constant(zeta())])
}

/// General coefficients as symbols: `F₀ = d l₀`, `F₁ = Σ b_k l_k`,
/// `F₂ = Σ c_k l_k`, `F₃ = a l₃` (eq. (5)).
fn general<const K: usize>() -> Vec<Vec<Vec<Sym>>> {
    rational_table::<K>(|end| {
        let l = blending_jets::<K>(end);
        let combo = |prefix: &str| {
            let coef = symbols(prefix, 4);
            (0..4).fold(Jet::constant(Sym::zero()), |acc, k| {
                acc + &(l[k].clone() * &Jet::constant(coef[k].clone()))
            })
        };
        vec![
            l[0].clone() * &Jet::constant(Sym::var("d")),
            combo("b"),
            combo("c"),
            l[3].clone() * &Jet::constant(Sym::var("a")),
        ]
    })
}

/// [`general`] to the first order, computed once (M12 and M12b share it).
fn general_first() -> &'static [Vec<Vec<Sym>>] {
    static TABLE: OnceLock<Vec<Vec<Vec<Sym>>>> = OnceLock::new();
    TABLE.get_or_init(general::<FIRST>)
}

/// The uniform case: the Appendix A basis `F_i = l_i/(6ζ² − 6ζ + 10)`,
/// computed once (M7, M10, M13 and M13b share it).
fn uniform() -> &'static [Vec<Vec<Sym>>] {
    static TABLE: OnceLock<Vec<Vec<Vec<Sym>>>> = OnceLock::new();
    TABLE.get_or_init(|| {
        rational_table(|end| {
            let atoms =
                end_atoms::<Sym, THIRD>(Family::Seed000Uniform, end, &Sym::one(), &[zeta()]);
            Family::Seed000Uniform.eval(&atoms, &[Jet::constant(zeta())])
        })
    })
}

/// One printed entry: equation, function `i`, end (0 = `n_j^+`), order, text.
type Entry = (&'static str, usize, usize, usize, String);

/// The shorthands of Appendix E, substituted after reading a print.
const SHORTHANDS: [Shorthand; 8] = [
    (
        "A",
        "S d w0 + [S(b0 + b2) + 4(S + 1)b1]w1 + [S(c0 + c2) + 4(S + 1)c1]w2",
    ),
    (
        "B",
        "[S(b1 + b3) + 4(S + 1)b2]w1 + [S(c1 + c3) + 4(S + 1)c2]w2 + S a w3",
    ),
    ("J", "d w0 + (b0 - 2b1 + b2)w1 + (c0 - 2c1 + c2)w2"),
    ("M", "-d w0 + (b2 - b0)w1 + (c2 - c0)w2"),
    ("K", "(b1 - 2(b2) + b3)w1 + (c1 - 2(c2) + c3)w2 + a w3"),
    ("L", "(b3 - b1)w1 + (c3 - c1)w2 + a w3"),
    ("g", "2(2S - 5)"),
    ("e", "(1 + 2S)^3"),
];

fn decide(entries: &[Entry], table: &[Vec<Vec<Sym>>], preamble: &str) -> Verdict {
    let ends = ["n_j^+", "n_{j+1}^-"];
    let parts = entries
        .iter()
        .map(|(eq, i, end, order, text)| {
            let label = format!("{eq} Q_{i}{}({}) H_{i}", "'".repeat(*order), ends[*end]);
            printed_part(label, text, &SHORTHANDS, &table[*end][*i][*order])
        })
        .collect();
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(0, preamble.to_string());
    v
}

const GENERAL: &str = "general coefficients as symbols: d = d_j, b_k = b_{j,k}, c_k = c_{j,k}, a = a_j; weights w0…w3, control points H0…H3, q = q_j; S = s(ξ); shorthands A, B, J, M, K, L, g(ξ), e(ξ) as defined in Appendix E; derivatives in n (factor (π/(2q_j))^k)";
const UNIFORM: &str = "uniform case: Appendix A basis F_i = l_i/(6ζ²−6ζ+10); weights w0…w3, control points H0…H3, q = q_j; S = s(ξ); derivatives in n (factor (π/(2q_j))^k)";

fn e(eq: &'static str, i: usize, end: usize, order: usize, text: impl Into<String>) -> Entry {
    (eq, i, end, order, text.into())
}

const DA: &str = "[S(w0 + w2) + 4(S + 1)w1]";
const DB: &str = "[S(w1 + w3) + 4(S + 1)w2]";

fn m7() -> Verdict {
    let entries = [
        e("(A36)", 0, 0, 0, format!("S w0 H0 / {DA}")),
        e("(A37)", 1, 0, 0, format!("4(S + 1)w1 H1 / {DA}")),
        e("(A38)", 2, 0, 0, format!("4(S + 1)w2 H2 / {DA}")),
        e("(A39)", 3, 0, 0, "0"),
        e("(A40)", 0, 1, 0, "0"),
        e("(A41)", 1, 1, 0, format!("4(S + 1)w1 H1 / {DB}")),
        e("(A42)", 2, 1, 0, format!("4(S + 1)w2 H2 / {DB}")),
        e("(A43)", 3, 1, 0, format!("(S)w3 H3 / {DB}")),
    ];
    decide(&entries, uniform(), UNIFORM)
}

fn m10() -> Verdict {
    let entries = [
        e(
            "(A44)",
            0,
            0,
            1,
            format!("(-pi/(2q))(1 + 2S)[({DA} + S(-w0 + w2)) / {DA}^2] w0 H0"),
        ),
        e(
            "(A45)",
            1,
            0,
            1,
            format!("(pi/2)[(1 + 2S)[-4(S + 1)(-w0 + w2)]w1 H1 / {DA}^2]"),
        ),
        e(
            "(A46)",
            2,
            0,
            1,
            format!("(pi/(2q))(1 + 2S)[({DA} - S(-w0 + w2)) / {DA}^2] w2 H2"),
        ),
        // printed "Q_3(n_j^+) = 0" in the first-derivative list
        e("(A47)", 3, 0, 1, "0"),
        // printed "Q_0(n_{j+1}^-) = 0" in the first-derivative list
        e("(A48)", 0, 1, 1, "0"),
        e(
            "(A49)",
            1,
            1,
            1,
            format!("(pi/(2q))(1 + 2S)[({DB} - S(-w1 + w3)) / {DB}^2] w1 H1"),
        ),
        e(
            "(A50)",
            2,
            1,
            1,
            format!("(pi/2)[(1 + 2S)[-4(S + 1)(-w1 + w3)]w2 H2 / {DB}^2]"),
        ),
        e(
            "(A51)",
            3,
            1,
            1,
            format!("(pi/(2q))(1 + 2S)[({DB} - S(-w1 + w3)) / {DB}^2] w3 H3"),
        ),
    ];
    decide(&entries, uniform(), UNIFORM)
}

fn m13() -> Verdict {
    let p2 = "(pi/(2q))^2";
    let entries = [
        e(
            "(A52)",
            0,
            0,
            2,
            format!(
                "{p2} (2(S + 2))[({DA} - S[(2S - 5)(w0 - w2)]) / {DA}^2] w0 H0 + 2{p2} (1 + 2S)(-w0 + w2)[({DA} - S(-w0 + w2)) / {DA}^3] w0 H0"
            ),
        ),
        e(
            "(A53)",
            1,
            0,
            2,
            format!(
                "{p2} (2(S + 2))[(-2{DA} - 4(S + 1)[(w0 - 2w1 + w2)]) / {DA}^2] w1 H1 - 2{p2} (1 + 2S)(-w0 + w2)[-4(S + 1)(-w0 + w2) / {DA}^3] w1 H1"
            ),
        ),
        e(
            "(A54)",
            2,
            0,
            2,
            format!(
                "{p2} (2(S + 2))[({DA} - S[(w0 - 2w1 + w2)]) / {DA}^2] w2 H2 - 2{p2} (1 + 2S)(-w0 + w2)[{DA} / {DA}^3] w2 H2"
            ),
        ),
        // printed "Q''_2(n_j^+) = 0" (label as printed; see M13b)
        e("(A55)", 2, 0, 2, "0"),
        e("(A56)", 0, 1, 2, "0"),
        e(
            "(A57)",
            1,
            1,
            2,
            format!(
                "{p2} (2(S + 2))[({DB} - 4(S + 1)[(w1 - 2w2 + w3)]) / {DB}^2] w1 H1 - 2{p2} (1 + 2S)(-w1 + w3)[({DB} - [(-1 + 2S) - (S(-w1 + w3))]) / {DB}^3] w1 H1"
            ),
        ),
        e(
            "(A58)",
            2,
            1,
            2,
            format!(
                "{p2} (2(S + 2))[(-2[S(w3 + w1) + 4(S + 1)w2] - 4(S + 1)[(w1 - 2w2 + w3)]) / {DB}^2] w2 H2 - 2{p2} (1 + 2S)(-w1 + w3)[[4(S + 1)(-w1 + w3)] / {DB}^3] w2 H2"
            ),
        ),
        e(
            "(A59)",
            3,
            1,
            2,
            format!(
                "{p2} (2(S + 2))[({DB} - S[(2S - 5)(w1 + w3)]) / {DB}^2] w3 H3 + 2{p2} (1 + 2S)(-w1 + w3)[({DB} - S(-w1 + w3)) / {DB}^3] w3 H3"
            ),
        ),
    ];
    decide(&entries, uniform(), UNIFORM)
}

fn m13b() -> Verdict {
    decide(
        &[e("(A55) read as Q''_3", 3, 0, 2, "0")],
        uniform(),
        UNIFORM,
    )
}

const FA: &str = "(S d w0 + [S(b0 + b2) + 4(S + 1)b1]w1 + [S(c0 + c2) + 4(S + 1)c1]w2)";
const FB: &str = "([S(b1 + b3) + 4(S + 1)b2]w1 + [S(c1 + c3) + 4(S + 1)c2]w2 + S a w3)";

fn m12_entries() -> Vec<Entry> {
    let p = "(pi/(2q))";
    vec![
        e("(A4)", 0, 0, 0, format!("S d w0 H0 / {FA}")),
        e(
            "(A5)",
            1,
            0,
            0,
            format!("(S(b0 + b2) + 4(S + 1)b1 w1 H1) / {FA}"),
        ),
        e(
            "(A6)",
            2,
            0,
            0,
            format!("(S(c0 + c2) + 4(S + 1)c1 w2 H2) / {FA}"),
        ),
        e("(A7)", 3, 0, 0, "0"),
        e("(A8)", 0, 1, 0, "0"),
        e(
            "(A9)",
            1,
            1,
            0,
            format!("[S(b1 + b3) + 4(S + 1)b2]w1 H1 / {FB}"),
        ),
        e(
            "(A10)",
            2,
            1,
            0,
            format!("[S(c1 + c3) + 4(S + 1)c2]w2 H2 / {FB}"),
        ),
        e("(A11)", 3, 1, 0, format!("S a w3 H3 / {FB}")),
        e(
            "(A12)",
            0,
            0,
            1,
            "[-pi/(2q)](1 + 2S)[A + S(-d w0 + (b2 - b0)w1 + (c2 - c0)w2)] d w0 H0 / A^2",
        ),
        e(
            "(A13)",
            1,
            0,
            1,
            format!(
                "{p}(1 + 2S)[((b2 - b0)A - [S(b0 + b2) + 4(S + 1)b1]) / [-d w0 + (b2 - b0)w1 + (c2 - c0)w2]] w1 H1"
            ),
        ),
        e(
            "(A14)",
            2,
            0,
            1,
            format!(
                "{p}(1 + 2S)[((c2 - c0)A - [S(c0 + c2) + 4(S + 1)c1]) / [-d w0 + (b2 - b0)w1 + (c2 - c0)w2]] w2 H2"
            ),
        ),
        e("(A15)", 3, 0, 1, "0"),
        e("(A16)", 0, 1, 1, "0"),
        e(
            "(A17)",
            1,
            1,
            1,
            format!(
                "{p}(1 + 2S)[((b3 - b1)B - [S(b1 + b3) + 4(S + 1)b2]) / [(b3 - b1)w1 + (c3 - c1)w2 + a w3]] w1 H1"
            ),
        ),
        e(
            "(A18)",
            2,
            1,
            1,
            format!(
                "{p}(1 + 2S)[((c3 - c1)B - [S(c1 + c3) + 4(S + 1)c2]) / [(b3 - b1)w1 + (c3 - c1)w2 + a w3]] w2 H2"
            ),
        ),
        e(
            "(A19)",
            3,
            1,
            1,
            "[pi/(2q)](1 + 2S)[B - S((b3 - b1)w1 + (c3 - c1)w2 + a w3)] a w3 H3 / B^2",
        ),
    ]
}

fn m12() -> Verdict {
    decide(&m12_entries(), general_first(), GENERAL)
}

fn m12b() -> Verdict {
    let p = "(pi/(2q))";
    let entries = [
        e(
            "(A5) read",
            1,
            0,
            0,
            format!("[S(b0 + b2) + 4(S + 1)b1] w1 H1 / {FA}"),
        ),
        e(
            "(A6) read",
            2,
            0,
            0,
            format!("[S(c0 + c2) + 4(S + 1)c1] w2 H2 / {FA}"),
        ),
        e(
            "(A13) read",
            1,
            0,
            1,
            format!("{p}(1 + 2S)[((b2 - b0)A - [S(b0 + b2) + 4(S + 1)b1] M) / A^2] w1 H1"),
        ),
        e(
            "(A14) read",
            2,
            0,
            1,
            format!("{p}(1 + 2S)[((c2 - c0)A - [S(c0 + c2) + 4(S + 1)c1] M) / A^2] w2 H2"),
        ),
        e(
            "(A17) read",
            1,
            1,
            1,
            format!("{p}(1 + 2S)[((b3 - b1)B - [S(b1 + b3) + 4(S + 1)b2] L) / B^2] w1 H1"),
        ),
        e(
            "(A18) read",
            2,
            1,
            1,
            format!("{p}(1 + 2S)[((c3 - c1)B - [S(c1 + c3) + 4(S + 1)c2] L) / B^2] w2 H2"),
        ),
    ];
    decide(&entries, general_first(), GENERAL)
}

fn m15() -> Verdict {
    let p2 = "(pi/(2q))^2";
    let p3 = "(pi/(2q))^3";
    let entries = [
        // "A^-" in the print read as "A −"
        e(
            "(A20)",
            0,
            0,
            2,
            format!(
                "{p2}(2S + 2)[(A - [S(2S - 5)(d w0 + (b0 - b2)w1 + (c0 - c2)w2)]) / A^2] d w0 H0 + 2{p2}(1 + 2S)[[-d w0 + (b2 - b0)w1 + (c2 - c0)w2] / [A + [S(-d w0 + (b2 - b0)w1 + (c2 - c0)w2)]]] d w0 H0"
            ),
        ),
        e(
            "(A21)",
            1,
            0,
            2,
            format!(
                "{p2}(2S + 2)[(A[b0 - 2b1 + b2] - J[S(b0 + b2) + 4(S + 1)b1]) / A^2] w1 H1 - 2{p2}(1 + 2S) M [A[(1 + 2S)(b2 - b0)] / [M[S(b0 + b2) + 4(S + 1)b1]]] w1 H1"
            ),
        ),
        e(
            "(A22)",
            2,
            0,
            2,
            format!(
                "{p2}(2S + 2)[(A[c0 - 2c1 + c2] - [S(c0 + c2) + 4(S + 1)c1]J) / A^2] w2 H2 - 2{p2}(1 + 2S) M [A[(1 + 2S)(c2 - c0)] / [M[S(c0 + c2) + 4(S + 1)c1]]] w2 H2"
            ),
        ),
        e("(A23)", 3, 0, 2, "0"),
        e("(A24)", 0, 1, 2, "0"),
        e(
            "(A25)",
            1,
            1,
            2,
            format!(
                "{p2}(2S + 2)[(B[b1 - 2b2 + b3] - K[S(b1 + b3) + 4(S + 1)b2]) / B^2] w1 H1 - 2{p2}(1 + 2S) L [B[(1 + 2S)(b3 - b1)] / [L[S(b1 + b3) + 4(S + 1)b2]]] w1 H1"
            ),
        ),
        e(
            "(A26)",
            2,
            1,
            2,
            format!(
                "{p2}(2S + 2)[(B[c1 - 2c2 + c3] - K[S(c1 + c3) + 4(S + 1)c2]) / B^2] w2 H2 - 2{p2}(1 + 2S) L [B[(1 + 2S)(c3 - c1)] / [L[S(c1 + c3) + 4(S + 1)c2]]] w2 H2"
            ),
        ),
        // "B^-" in the print read as "B −"
        e(
            "(A27)",
            3,
            1,
            2,
            format!(
                "{p2}(2S + 2)[(B - [S(2S - 5)][(b1 - b3)w1 + (c1 - c3)w2 + a w3]) / B^2] a w3 H3 - 2{p2}(1 + 2S) L [(B - [S L]) / B^3] a w3 H3"
            ),
        ),
        e(
            "(A28)",
            0,
            0,
            3,
            format!(
                "{p3} g d w0 H0 [([(S b2 + 2(S + 1)b1)w1 + (S c2 + 2(S + 1)c1)w2] + [4(2S + 1)(S + 2)[(b2 - b1)w1 + (c2 - c1)w2]]) / A^2 - 8{p3}(S)^2 d w0 H0 [((2 + 3S)M(b1 w1 + c1 w2) - 2J[(S b2 + 2(S + 1)b1)w1 + (S c2 + 2(S + 1)c1)w2]) / A^3] - 12{p3} e d w0 H0 [M[(S b2 + 2(S + 1)b1)w1 + (S c2 + 2(S + 1)c1)w2] / A^4]]"
            ),
        ),
        e(
            "(A29)",
            1,
            0,
            3,
            format!(
                "{p3} d w0 w1 H1 [[(-2S b2 - 4(S + 1)b1)(2S - 5) - 4(2S + 1)(S + 2)((b2 - b1))] / A^2] - 2{p3}[(2M[A(b0 - 2b1 + b2) - (S(b0 + b2) + 4(S + 1)b1)J] - 2J[A(b2 - b0) - (S(b0 + b2) + 4(S + 1)b1)M]) / A^3] w1 H1 + 6{p3}(1 + 2S)^3 M^2 [[A(b2 - b0) - (S(b0 + b2) + 4(S + 1)b1)M] / A^3] w1 H1"
            ),
        ),
        e(
            "(A30)",
            2,
            0,
            3,
            format!(
                "{p3} d w0 w2 H2 [[(-2S c2 - 4(S + 1)c1)(2S - 5) - 4(2S + 1)(S + 2)((c2 - c1))] / A^2] - 2{p3}[(2M[A(c0 - 2c1 + c2) - (S(c0 + c2) + 4(S + 1)c1)J] - 2J[A(c2 - c0) - (S(c0 + c2) + 4(S + 1)c1)M]) / A^3] w2 H2 + 6{p3}(1 + 2S)^3 M^2 [[A(c2 - c0) - (S(c0 + c2) + 4(S + 1)c1)M] / A^4] w2 H2"
            ),
        ),
        e("(A31)", 3, 0, 3, "0"),
        e("(A32)", 0, 1, 3, "0"),
        e(
            "(A33)",
            1,
            1,
            3,
            format!(
                "{p3} a w3 w1 H1 [[(-2S b3 - 4(S + 1)b2)(2S - 5) + 4(2S + 1)(S + 2)((b1 - b2))] / B^2] - 2{p3}[(2L[B(b1 - 2b2 + b3) - (S(b1 + b3) + 4(S + 1)b2)K] - 2K[B(b3 - b1) - (S(b1 + b3) + 4(S + 1)b2)L]) / B^3] w1 H1 + 6{p3}(1 + 2S)^3 L^2 [[B(b3 - b1) - (S(b1 + b3) + 4(S + 1)b2)L] / B^4] w1 H1"
            ),
        ),
        e(
            "(A34)",
            2,
            1,
            3,
            format!(
                "{p3} a w3 w2 H2 [[(-2S c3 - 4(S + 1)c2)(2S - 5) + 4(2S + 1)(S + 2)((c1 - c2))] / B^2] - 2{p3}[(2L[B(c1 - 2c2 + c3) - [(S(c1 + c3) + 4(S + 1)c2)K]] - 2K[B(c3 - c1) - (S(c1 + c3) + 4(S + 1)c2)L]) / B^3] w2 H2 + 6{p3}(1 + 2S)^3 L^2 [[B(c3 - c1) - (S(c1 + c3) + 4(S + 1)c2)L] / B^4] w2 H2"
            ),
        ),
        e(
            "(A35)",
            3,
            1,
            3,
            format!(
                "{p3} g a w3 H3 [([(S b3 + 2(S + 1)b2)w1 + (S c3 + 2(S + 1)c2)w2] + [4(2S + 1)(S + 2)[(b3 - b2)w1 + (c3 - c2)w2]]) / B^2] - 8{p3}(S)^2 a w3 H3 [((2 + 3S)L(b2 w1 + c2 w2) - 2K[(S b3 + 2(S + 1)b2)w1 + (S c3 + 2(S + 1)c2)w2]) / B^3] - 12{p3} e a w3 H3 [L[(S b3 + 2(S + 1)b2)w1 + (S c3 + 2(S + 1)c2)w2] / B^4]"
            ),
        ),
    ];
    let mut v = decide(&entries, &general::<THIRD>(), GENERAL);
    v.evidence.insert(
        1,
        "garbled print: \"A^-\" in (A20) and \"B^-\" in (A27) are read as \"A −\", \"B −\"; the outer bracket of (A28) encloses all three terms as printed; m(ξ)² is defined but never used",
    );
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_verdict::status::Status;

    #[test]
    fn printed_values_that_are_right_hold_and_wrong_ones_fail() {
        let v = m7();
        let line = |eq: &str| {
            v.evidence
                .iter()
                .map(|l| l.line())
                .find(|l| l.starts_with(eq))
                .unwrap()
        };
        assert!(line("(A36)").contains(": holds"));
        assert!(line("(A37)").contains(": holds"));
        // (A38): Q_2(n_j^+) is S w2 H2 / den, not 4(S + 1) w2 H2 / den
        assert!(line("(A38)").contains(": fails"));
        assert_eq!(m12b().status, Status::Holds);
        assert_eq!(m13b().status, Status::Holds);
    }
}
