//! Second-list claims about printed formulas, decided exactly: the
//! Hermite-type interpolants of seed 004 (E19, E23: interpolation
//! conditions and the `C¹` join of consecutive segments), the rational
//! "curve" of seed 000's Definition 2 (M21), the ends of the thesis's
//! quadratic curve (T45) and its chord-length parameters (T63).

use trig_core::Family;
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_symbolic::Sym;

use super::seed004::{hermite_segment, interpolation_conditions};
use trig_judge::exact::IDENTITY;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// `t = (x − x_i)/h_i` on segment `i` (the reading of E1cb: the printed
/// `t = (x_{i+1} − x_i)/h_i` is the constant 1).
fn local_t() -> Sym {
    (Sym::var("x") - &Sym::var("x_i")) / &Sym::var("h_i")
}

/// The jumps of value and first derivative at `x_{i+1} = x_i + h_i` between
/// segment `i` and segment `i + 1` (`t = (x − x_{i+1})/h_{i+1}`) of a
/// Hermite-type spline whose derivative data `d_{i+1}`, `d_{i+2}` carry the
/// factors `hd.0`, `hd.1`.
fn c1_jumps(family: Family, params: &[Sym], hd: (&str, &str)) -> Vec<(String, Sym, Sym)> {
    let x1 = Sym::var("x_i") + &Sym::var("h_i");
    let next_t = (Sym::var("x") - &x1) / &Sym::var("h_i1");
    let left = hermite_segment(family, params, &local_t(), &Sym::var(hd.0), 0);
    let right = hermite_segment(family, params, &next_t, &Sym::var(hd.1), 1);
    let at = |f: &Sym| f.subs("x", &x1);
    vec![
        (
            "H_{i+1}(x_{i+1}) − H_i(x_{i+1})".into(),
            at(&right),
            at(&left),
        ),
        (
            "H_{i+1}'(x_{i+1}) − H_i'(x_{i+1})".into(),
            at(&right.diff("x")),
            at(&left.diff("x")),
        ),
    ]
}

/// The EH interpolant on `[x_i, x_{i+1}]` for symbolic `λ`, `μ`: its four
/// interpolation conditions, and the `C¹` join with the next segment.
pub(super) fn e19() -> Verdict {
    let params = [Sym::var("lambda"), Sym::var("mu")];
    let mut parts = interpolation_conditions(Family::Eh, &params, &local_t(), &Sym::var("h_i"));
    parts.extend(c1_jumps(Family::Eh, &params, ("h_i", "h_i1")));
    let mut v = trig_judge::exact::identities(parts);
    v.evidence.insert(
        0,
        "t = (x − x_i)/h_i, x_{i+1} = x_i + h_i; the next segment has t = (x − x_{i+1})/h_{i+1} and its own data y_{i+2}, d_{i+2}, h_{i+1}; λ, μ symbolic (every value)",
    );
    v
}

/// The §II spline with the printed factor `h_{i+1}` of `d_{i+1}` (E1c, E1cb):
/// the derivative jumps at `x_{i+1}` unless `h_{i+1} = h_i`; with `h_i d_{i+1}`
/// (E1cb's correction) the spline is `C¹`.
pub(super) fn e23() -> Verdict {
    let printed = trig_judge::exact::identities(c1_jumps(Family::Hermite, &[], ("h_i1", "h_i2")));
    let note = "read as E1cb: t = (x − x_i)/h_i (the printed t = (x_{i+1} − x_i)/h_i is the constant 1, which makes H_i the constant y_{i+1}); x_{i+1} = x_i + h_i; segment i + 1 has t = (x − x_{i+1})/h_{i+1}";
    if printed.status == Status::Holds {
        let mut v = printed;
        v.evidence.insert(0, note);
        return v;
    }
    let corrected = trig_judge::exact::identities(c1_jumps(Family::Hermite, &[], ("h_i", "h_i1")));
    let mut evidence = printed.evidence;
    evidence.insert(0, note.to_string());
    let status = if corrected.status == Status::Holds {
        Status::HoldsAfterCorrection
    } else {
        Status::Fails
    };
    evidence.extend(corrected.into_part("with h_i d_{i+1} (and h_{i+1} d_{i+2})"));
    let v = Verdict::new(status, IDENTITY, evidence);
    if status == Status::HoldsAfterCorrection {
        v.with_correction("β1(t) h_i d_{i+1} instead of β1(t) h_{i+1} d_{i+1} in H_i (as E1cb): then H_i'(x_{i+1}) = d_{i+1} = H_{i+1}'(x_{i+1})")
    } else {
        v
    }
}

/// The printed `Y(n)`: numerator and denominator are the same sum, so `Y ≡ 1`
/// wherever `Σ w_j F_j ≠ 0` — no control point enters; the curve with points
/// `H_j` depends on each of them.
pub(super) fn m21() -> Verdict {
    let f = trig_judge::exact::basis(Family::Seed000Uniform);
    let w = trig_judge::exact::symbols("w", f.len());
    let weighted: Vec<Sym> = f.iter().zip(&w).map(|(fj, wj)| wj.clone() * fj).collect();
    let total = trig_judge::exact::sum(&weighted);
    let printed = total.clone() / &total;
    let constant =
        trig_judge::exact::identity_item("Y(n) − 1 (weights symbolic)", &printed, &Sym::one());
    let points = trig_judge::exact::symbols("H", f.len());
    let curve = trig_judge::exact::combination(&weighted, &points) / &total;
    let moves = points.iter().all(|h| !curve.diff(&h.to_string()).is_zero());
    let is_one = constant.status == Some(Status::Holds);
    let mut v = Verdict::new(
        if is_one && moves {
            Status::Fails
        } else {
            Status::NotCheckable
        },
        IDENTITY,
        [constant],
    );
    v.evidence.insert(
        0,
        "w_j symbolic, F_j the segment functions of (6); Σ_j Q_j(n) = 1 is the partition of unity of the rational basis, not a curve",
    );
    let shape = if moves {
        "∂/∂H_j ≠ 0 for j = 0…3"
    } else {
        "not so: some ∂/∂H_j = 0"
    };
    v.evidence.push(
        trig_verdict::evidence::Evidence::new(
            trig_verdict::evidence::Kind::Comparison,
            format!(
                "with control points: Σ w_j F_j H_j / Σ w_j F_j depends on every H_j ({shape})"
            ),
        )
        .witnessed(trig_verdict::witness::find(
            &printed,
            &curve,
            ("printed Y(n)", "Σ w_j F_j H_j / Σ w_j F_j"),
        )),
    );
    if is_one && moves {
        v.with_correction(
            "Y(n) = Σ_j w_j F_j(n) H_j / Σ_j w_j F_j(n) (the control points H_j of (6))",
        )
    } else {
        v
    }
}

/// `F(0) − P0` and `F(1) − P2` of the quadratic curve (3.1) as multiples
/// `c·(P1 − P0)`, `c·(P1 − P2)`: the claim needs `c ≠ 0` for every `β ≥ 0`
/// (a nonzero constant numerator) and `c → 0` as `β → ∞` (numerator of
/// lower degree in `β` than the denominator).
pub(super) fn t45() -> Verdict {
    let p = trig_judge::exact::symbols("P", 3);
    let beta = [Sym::var("beta")];
    let ends = [
        (
            "F(0) − P0",
            End::Start,
            0,
            "P1 − P0",
            "F(0) = P0 only if P1 = P0",
        ),
        (
            "F(1) − P2",
            End::End,
            2,
            "P1 − P2",
            "F(1) = P2 only if P1 = P2",
        ),
    ];
    let parts = ends
        .iter()
        .map(|(label, at, end, direction, only_if)| {
            // the functions' values at the end (order 0 of their jets)
            let values: Vec<Sym> = endpoint_derivatives::<Sym, 1>(
                Family::ThesisQuadratic,
                &beta,
                *at,
                Wrt::Angle,
                &Sym::one(),
            )
            .into_iter()
            .map(|d| d[0].clone())
            .collect();
            let gap = trig_judge::exact::combination(&values, &p) - &p[*end];
            let c = gap.diff("P1");
            let shape = trig_judge::exact::identity_item(
                &format!("{label} − c·({direction}), c = ∂/∂P1"),
                &gap,
                &(c.clone() * &(p[1].clone() - &p[*end])),
            );
            let never_zero = c.numerator().as_constant().is_some_and(|k| k != 0);
            let degree = |q: &trig_symbolic::Poly| q.degree_in("beta");
            let vanishes = degree(c.numerator()) < degree(&c.denominator_poly());
            let holds = shape.status == Some(Status::Holds) && never_zero && vanishes;
            let mut v = Verdict::new(
                if holds { Status::Holds } else { Status::Fails },
                IDENTITY,
                [shape],
            );
            v.evidence.push(format!(
                "c = {}: {}; {}",
                c.to_unicode(),
                if never_zero {
                    format!("its numerator is a nonzero constant, so c ≠ 0 wherever the basis is defined (its published range β ≥ 0): {only_if}")
                } else {
                    "its numerator is not a nonzero constant".to_string()
                },
                if vanishes {
                    "numerator of lower degree in β than the denominator, so c → 0 as β → ∞"
                } else {
                    "c does not tend to 0 as β → ∞"
                }
            ));
            ((*label).to_string(), v)
        })
        .collect();
    Verdict::all(IDENTITY, parts)
}

/// (6.9) with the first distance `A = DP_1` and the rest `R = DP_2 + … + DP_N`
/// as symbols: `t_1 = A/(A + R)`, zero only when `P_2 = P_1`; `t_N = 1`, but
/// its sum uses `DP_N = ‖P_{N+1} − P_N‖`, and there is no `P_{N+1}` among
/// `P_1 … P_N`. The usual chord length `t_i = Σ_{r<i} DP_r / Σ_{r<N} DP_r`
/// gives `t_1 = 0/(A + R') = 0` and `t_N = 1` with `R' = DP_2 + … + DP_{N−1}`.
pub(super) fn t63() -> Verdict {
    let (a, r) = (Sym::var("DP1"), Sym::var("R"));
    let total = a.clone() + &r;
    let printed = trig_judge::exact::identities(vec![
        (
            "printed t_1 = DP_1/(DP_1 + R), R = DP_2 + … + DP_N".into(),
            a.clone() / &total,
            Sym::zero(),
        ),
        (
            "printed t_N = (DP_1 + R)/(DP_1 + R)".into(),
            total.clone() / &total,
            Sym::one(),
        ),
    ]);
    let usual = trig_judge::exact::identities(vec![
        (
            "t_1 = (empty sum)/(DP_1 + R'), R' = DP_2 + … + DP_{N−1}".into(),
            Sym::zero() / &(a.clone() + &Sym::var("R'")),
            Sym::zero(),
        ),
        (
            "t_N = (DP_1 + R')/(DP_1 + R')".into(),
            (a.clone() + &Sym::var("R'")) / &(a.clone() + &Sym::var("R'")),
            Sym::one(),
        ),
    ]);
    let status = printed.status;
    let mut evidence = printed.evidence;
    evidence.push(
        "the denominator Σ_{r=1}^{N} DP_r uses DP_N = ‖P_{N+1} − P_N‖: P_{N+1} is not a data point (the data are P_1 … P_N)",
    );
    let fixed = usual.status == Status::Holds;
    evidence.extend(
        usual.into_part("the usual chord length t_i = Σ_{r=1}^{i−1} DP_r / Σ_{r=1}^{N−1} DP_r"),
    );
    let v = Verdict::new(status, IDENTITY, evidence);
    if fixed && status != Status::Holds {
        v.with_correction("t_i = Σ_{r=1}^{i−1} DP_r / Σ_{r=1}^{N−1} DP_r (then t_1 = 0, t_N = 1 and only DP_1 … DP_{N−1} are used)")
    } else {
        v
    }
}
