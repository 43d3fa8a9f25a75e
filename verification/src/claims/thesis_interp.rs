//! Seed 001, the thesis, section 4.3: the positivity-preserving
//! interpolation schemes (4.19)–(4.34) on Tables 4.1–4.6 (claims T20–T23;
//! the positivity claims T24–T24f are data, `check = "interpolant-nonnegative"`).
//!
//! The schemes are built by `trig-interp` on the catalog basis (3.7);
//! end conditions are decided exactly in the symbolic ring (derivatives in
//! `x` from `trig_deriv`, π a symbol), knot continuity by exact jumps;
//! positivity of a built-in table's interpolant (asked by other claims) is
//! the judge's, [`trig_judge::interpolant::positivity`].

use trig_core::{Family, Ring};
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_interp::piece::derivatives_of;
use trig_interp::scheme::{printed_c1, printed_c2_second, printed_g1, printed_g2_join};
use trig_interp::{DataSet, KnotJump, Scheme, Spline, Variant, knot_jumps};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, identities};
use trig_verdict::evidence::{Assignment, Evidence, EvidenceList, Expr, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T20",
        check: t20,
    },
    Claim {
        id: "T21",
        check: t21,
    },
    Claim {
        id: "T21b",
        check: t21b,
    },
    Claim {
        id: "T22",
        check: t22,
    },
    Claim {
        id: "T22b",
        check: t22b,
    },
    Claim {
        id: "T23",
        check: t23,
    },
];

fn v(name: &str) -> Sym {
    Sym::var(name)
}

/// Derivatives of orders 0…2 of `Σ b_j(·; m) P_j` at `end` in `wrt`.
pub(super) fn derivs(points: &[Sym], m: &Sym, end: End, wrt: Wrt, h: &Sym) -> Vec<Sym> {
    curve_endpoint_derivatives::<Sym, 3>(
        Family::ThesisCubic,
        std::slice::from_ref(m),
        points,
        None,
        end,
        wrt,
        h,
    )
}

/// The four end conditions of a piece with symbolic data, targets at the start `(f0, t0)` and end `(f1, t1)`.
fn end_conditions(points: &[Sym; 4], m: &Sym, h: &Sym, t0: &Sym, t1: &Sym) -> Verdict {
    let s = derivs(points, m, End::Start, Wrt::X, h);
    let e = derivs(points, m, End::End, Wrt::X, h);
    identities(vec![
        ("P(x_i) − f_i".into(), s[0].clone(), points[0].clone()),
        (
            "P(x_{i+1}) − f_{i+1}".into(),
            e[0].clone(),
            points[3].clone(),
        ),
        ("P'(x_i) − target".into(), s[1].clone(), t0.clone()),
        ("P'(x_{i+1}) − d_{i+1}".into(), e[1].clone(), t1.clone()),
    ])
}

/// Symbols `f0, f1, d0, d1, h, m` (data of one interval).
fn data_symbols() -> [Sym; 6] {
    ["f0", "f1", "d0", "d1", "h", "m"].map(v)
}

fn t20() -> Verdict {
    let [f0, f1, d0, d1, h, m] = data_symbols();
    match printed_c1(&f0, &f1, &d0, &d1, &h, &m) {
        Ok((w, x)) => end_conditions(&[f0, w, x, f1], &m, &h, &d0, &d1),
        Err(e) => Verdict::not_checkable(e.to_string()),
    }
}

fn t22() -> Verdict {
    let [f0, f1, d0, d1, h, m] = data_symbols();
    let n = v("n");
    match printed_g1(&f0, &f1, &d0, &d1, &h, &m, &n) {
        Ok((w, x)) => end_conditions(&[f0, w, x, f1], &m, &h, &(n * &d0), &d1),
        Err(e) => Verdict::not_checkable(e.to_string()),
    }
}

fn t21b() -> Verdict {
    let [f0, f1, d0, d1, h, m] = data_symbols();
    let (Ok((w, x)), Ok((di, di1))) = (
        printed_c1(&f0, &f1, &d0, &d1, &h, &m),
        printed_c2_second(&f0, &f1, &d0, &d1, &h, &m),
    ) else {
        return Verdict::not_checkable("(4.23)–(4.25) are singular for symbolic m");
    };
    let points = [f0, w, x, f1];
    let in_x = |end| derivs(&points, &m, end, Wrt::X, &h)[2].clone();
    let in_u = |end| derivs(&points, &m, end, Wrt::U, &h)[2].clone();
    let printed = identities(vec![
        ("D_i − P''(x_i)".into(), di.clone(), in_x(End::Start)),
        ("D_{i+1} − P''(x_{i+1})".into(), di1.clone(), in_x(End::End)),
    ]);
    let h2 = h.clone() * &h;
    let corrected = identities(vec![
        (
            "D_i/h_i² − P''(x_i)".into(),
            di.clone() / &h2,
            in_x(End::Start),
        ),
        (
            "D_{i+1}/h_i² − P''(x_{i+1})".into(),
            di1.clone() / &h2,
            in_x(End::End),
        ),
        ("D_i − d²P/du²(0)".into(), di, in_u(End::Start)),
        ("D_{i+1} − d²P/du²(1)".into(), di1, in_u(End::End)),
    ]);
    reading_verdict(
        printed,
        corrected,
        "D_i, D_{i+1} of (4.23)/(4.24) are the second derivatives in u (thesis (4.30)); in x they must be divided by h_i² (the tables have h_i = 1, where both agree). (4.24) writes m for m_i.",
    )
}

/// A printed identity that fails and a named correction that holds.
fn reading_verdict(printed: Verdict, corrected: Verdict, correction: &str) -> Verdict {
    let status = match (printed.status, corrected.status) {
        (Status::Holds, _) => Status::Holds,
        (_, Status::Holds) => Status::HoldsAfterCorrection,
        _ => Status::Fails,
    };
    let mut evidence = printed.into_part("as printed");
    evidence.extend(corrected.into_part("corrected"));
    let v = Verdict::new(status, IDENTITY, evidence);
    if status == Status::Holds {
        v
    } else {
        v.with_correction(correction)
    }
}

/// f64 value of an exact expression in π (for display).
fn approx(x: &Sym) -> String {
    match x.eval(&0.0_f64, &|n: &str| {
        (n == "pi").then_some(std::f64::consts::PI)
    }) {
        Ok(value) => format!("{value:.6}"),
        Err(e) => format!("({e})"),
    }
}

/// The witness of a jump of order `r` at the knot `k`: the point sets the
/// control points `Vᵢ, Wᵢ, Xᵢ, Yᵢ` of the two pieces (piece `i` on
/// `[x_i, x_{i+1}]`), and each one-sided value records its formula — the
/// `r`-th derivative in `x` of `Σ b_j(θ; m_i)·V_j` at the end of its piece,
/// linear in the control points (`m_i`, `h_i` and `π` in its coefficients).
fn knot_witness(spline: &Spline<Sym>, k: &KnotJump<Sym>, r: usize) -> Witness {
    let primes = "'".repeat(r);
    let x = k.x.to_string();
    let mut point = vec![Assignment::exact("x", &Sym::rational(k.x.clone()))];
    let mut values = Vec::new();
    for (i, end, side, value) in [
        (k.knot - 1, End::End, "⁻", &k.left[r]),
        (k.knot, End::Start, "⁺", &k.right[r]),
    ] {
        let piece = &spline.pieces[i];
        let names = ["V", "W", "X", "Y"].map(|l| format!("{l}{i}"));
        let vars = names.clone().map(|n| Sym::var(&n));
        let formula = derivatives_of(&vars, &piece.m, &piece.h, end, Wrt::X)[r].clone();
        point.extend(
            names
                .iter()
                .zip(&piece.points)
                .map(|(n, v)| Assignment::exact(n, v)),
        );
        values.push(Value::new(format!("P{primes}({x}{side})"), Expr::new(value)).of(&formula));
    }
    Witness {
        point,
        note: Some(format!(
            "{} ({}), the pieces on either side of the knot: Vᵢ, Wᵢ, Xᵢ, Yᵢ are the control points of piece i, from the data point i (counted from 0); π kept as a symbol",
            spline.data.table.name, spline.variant
        )),
        values,
        exact: true,
        stated: None,
    }
}

fn jump_lines(spline: &Spline<Sym>, orders: usize) -> (bool, Vec<Evidence>) {
    let mut ok = true;
    let lines = knot_jumps(spline)
        .iter()
        .map(|k| {
            let order = k.continuity_order();
            let enough = order.is_some_and(|o| o + 1 >= orders);
            ok &= enough;
            // a jump below the claimed order: the two one-sided values, exact
            let witness = k
                .jumps
                .iter()
                .take(orders)
                .position(|j| !j.is_zero())
                .filter(|_| !enough)
                .map(|r| knot_witness(spline, k, r));
            let jumps: Vec<String> = k
                .jumps
                .iter()
                .map(|j| {
                    if j.is_zero() {
                        "0".into()
                    } else {
                        format!("{j} ≈ {}", approx(j))
                    }
                })
                .collect();
            let achieved = order.map_or("discontinuous".to_string(), |o| format!("C{o}"));
            Evidence::note(format!(
                "{} ({}), knot x = {}: jumps of P, P', P'', P''' = [{}] → {achieved}",
                spline.data.table.name,
                spline.variant,
                k.x,
                jumps.join("; ")
            ))
            .witnessed(witness)
        })
        .collect();
    (ok, lines)
}

pub(super) fn sym_spline(
    name: &str,
    scheme: Scheme,
    variant: Variant,
) -> Result<Spline<Sym>, String> {
    let data = DataSet::named(name).map_err(|e| e.to_string())?;
    trig_judge::interpolant::exact_spline(&data, scheme, variant)
}

const JUMPS: &str = "exact one-sided derivatives in x at the interior knots (trig-deriv jets, π symbolic), jump = right − left";

fn t21() -> Verdict {
    let (printed, corrected) = match (
        sym_spline("thesis-table-4.2", Scheme::C2, Variant::Printed),
        sym_spline("thesis-table-4.2", Scheme::C2, Variant::Corrected),
    ) {
        (Ok(p), Ok(c)) => (p, c),
        (Err(e), _) | (_, Err(e)) => return Verdict::not_checkable(e),
    };
    let (ok, evidence) = jump_lines(&printed, 3);
    let mut evidence = EvidenceList::from(evidence);
    let (fixed, lines) = jump_lines(&corrected, 3);
    evidence.push("(4.25) uses the control points of (4.21) unchanged: D_i are computed, not imposed, so P'' jumps wherever the two pieces' D_i differ");
    evidence.extend(lines);
    let status = if ok { Status::Holds } else { Status::Fails };
    let v = Verdict::new(status, JUMPS, evidence);
    if ok || !fixed {
        v
    } else {
        v.with_correction("choose the interior d_i by the C² conditions P_{i−1}''(x_i) = P_i''(x_i) (a tridiagonal system; arithmetic-mean d_0, d_n) instead of the arithmetic means: the spline is then C² at every knot (corrected lines above)")
    }
}

fn t22b() -> Verdict {
    let mut all_ok = true;
    let mut evidence = EvidenceList::default();
    for name in ["thesis-table-4.3", "thesis-table-4.6"] {
        match sym_spline(name, Scheme::G1, Variant::Printed) {
            Ok(s) => {
                let (ok, lines) = jump_lines(&s, 2);
                all_ok &= ok;
                evidence.extend(lines);
            }
            Err(e) => return Verdict::not_checkable(e),
        }
    }
    evidence.push("for the graph y = P(x), tangent continuity is continuity of P'; at x_{i+1} the left piece ends with slope d_{i+1} (4.26) and the right piece starts with n_{i+1} d_{i+1}, so the slope jumps by (n_{i+1} − 1) d_{i+1}");
    let status = if all_ok { Status::Holds } else { Status::Fails };
    let v = Verdict::new(status, JUMPS, evidence);
    if all_ok {
        v
    } else {
        v.with_correction("n_i = 1 at every interior knot (then the scheme is the C¹ scheme)")
    }
}

fn t23() -> Verdict {
    let [v1, v2, v3, w3, m, alpha, beta] = ["V1", "V2", "V3", "W3", "m", "alpha", "beta"].map(v);
    let first = [v("V0"), v1.clone(), v2.clone(), v3.clone()];
    let (p1, p2) = printed_g2_join(&v1, &v2, &v3, &m, &alpha, &beta);
    let residuals = |q1: &Sym, q2: &Sym, wrt: Wrt, h: &Sym| {
        let second = [v3.clone(), q1.clone(), q2.clone(), w3.clone()];
        let e = derivs(&first, &m, End::End, wrt, h);
        let s = derivs(&second, &m, End::Start, wrt, h);
        vec![
            ("P₂(0) − P₁(1)".to_string(), s[0].clone(), e[0].clone()),
            (
                "P₂'(0) − α P₁'(1)".to_string(),
                s[1].clone(),
                alpha.clone() * &e[1],
            ),
            (
                "P₂''(0) − α² P₁''(1) − β P₁'(1)".to_string(),
                s[2].clone(),
                alpha.square() * &e[2] + &(beta.clone() * &e[1]),
            ),
        ]
    };
    let mut evidence = EvidenceList::default();
    for (wrt, h) in [
        (Wrt::U, Sym::one()),
        (Wrt::Angle, Sym::one()),
        (Wrt::X, v("h")),
    ] {
        let verdict = identities(residuals(&p1, &p2, wrt, &h));
        evidence.extend(verdict.into_part(&format!("(4.34) as printed, derivatives in {wrt}")));
    }
    // the named correction: 2(1+m)(α+1)V_3^1 → (1 + 2(1+m)α)V_3^1, i.e. subtract (2m+1)V_3^1
    let fixed = p2.clone() - &((Sym::int(2) * &m + &Sym::one()) * &v3);
    let corrected = identities(residuals(&p1, &fixed, Wrt::U, &Sym::one()));
    evidence.extend(
        corrected
            .clone()
            .into_part("corrected V_2^2, derivatives in u (4.30)"),
    );
    let printed_u = identities(residuals(&p1, &p2, Wrt::U, &Sym::one()));
    let status = match (printed_u.status, corrected.status) {
        (Status::Holds, _) => Status::Holds,
        (_, Status::Holds) => Status::HoldsAfterCorrection,
        _ => Status::Fails,
    };
    evidence.push(format!(
        "the coefficients of (4.34)'s V_2^2 sum to {} (an affine combination needs 1)",
        sum_of_coefficients(&p2, &["V1", "V2", "V3"])
    ));
    let v = Verdict::new(status, IDENTITY, evidence);
    if status == Status::Holds {
        v
    } else {
        v.with_correction("V_2^2 = α²V_1^1 − 2(1+m)(α²+α)V_2^1 − (2/π)(1+m/2)βV_2^1 + (1 + 2(1+m)α + (1+2m)α²)V_3^1 + (2/π)(1+m/2)βV_3^1: the term 2(1+m)(α+1)V_3^1 must be (1 + 2(1+m)α)V_3^1 (the (4m+2)V_0^2 term of P₂''(0) was dropped); holds with (4.30)'s u-derivatives and equal m (β is a u-convention factor: 2/π becomes 1 with angle derivatives)")
    }
}

fn sum_of_coefficients(e: &Sym, points: &[&str]) -> Sym {
    points
        .iter()
        .fold(e.clone(), |acc, p| acc.subs(p, &Sym::one()))
}

/// The certified minima of the built-in table `name` with
/// `scheme`/`variant`, as a verdict (`trig_judge::interpolant::positivity`).
pub(super) fn positivity(name: &str, scheme: Scheme, variant: Variant) -> Verdict {
    match DataSet::named(name) {
        Ok(data) => trig_judge::interpolant::positivity(&data, scheme, variant),
        Err(e) => Verdict::not_checkable(e.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wrong_control_point_fails_its_end_conditions() {
        // the printed C¹ scheme with a wrong sign in X must fail its end conditions
        let [f0, f1, d0, d1, h, m] = data_symbols();
        let (w, x) = printed_c1(&f0, &f1, &d0, &d1, &h, &m).unwrap();
        let wrong = f1.clone() * &Sym::int(2) - &x;
        let v = end_conditions(&[f0, w, wrong, f1], &m, &h, &d0, &d1);
        assert_eq!(v.status, Status::Fails);
    }
}
