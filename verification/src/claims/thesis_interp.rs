//! Seed 001, the thesis, section 4.3: the positivity-preserving
//! interpolation schemes (4.19)–(4.34) on Tables 4.1–4.6 (claims T20–T23;
//! the positivity claims T24–T24f are data, `check = "interpolant-nonnegative"`).
//!
//! The schemes are built by `trig-interp` on the catalog basis (3.7);
//! end conditions are decided exactly in the symbolic ring (derivatives in
//! `x` from `trig_deriv`, π a symbol), knot continuity by exact jumps;
//! positivity of a built-in table's interpolant (asked by other claims) is
//! the judge's, [`trig_judge::interpolant::positivity`].

use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_interp::piece::derivatives_of;
use trig_interp::{DataSet, KnotJump, Scheme, Spline, Variant, knot_jumps};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_verdict::evidence::{Assignment, Evidence, EvidenceList, Expr, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T21",
        check: t21,
    },
    Claim {
        id: "T22b",
        check: t22b,
    },
];

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

/// The certified minima of the built-in table `name` with
/// `scheme`/`variant`, as a verdict (`trig_judge::interpolant::positivity`).
pub(super) fn positivity(name: &str, scheme: Scheme, variant: Variant) -> Verdict {
    match DataSet::named(name) {
        Ok(data) => trig_judge::interpolant::positivity(&data, scheme, variant),
        Err(e) => Verdict::not_checkable(e.to_string()),
    }
}
