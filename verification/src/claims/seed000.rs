//! Seed 000 (Majeed et al. 2020): uniform partition of unity and its proof
//! (Appendix A), the printed non-uniform coefficients in the uniform case, and
//! the rational basis (Theorems 5, 6).

use rug::Rational;
use trig_core::Family;
use trig_core::families::seed000::uniform_normaliser;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_symbolic::Sym;

use super::seed000_appendix_c::{NONUNIFORM_J, nonuniform_knots};
use crate::claim::Claim;
use trig_certify::ParamBox;
use trig_judge::certificate::nonnegative_on;
use trig_judge::exact::{IDENTITY, basis, residual_verdict, sum};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "M2",
        check: m2,
    },
    Claim {
        id: "M3",
        check: m3,
    },
    Claim {
        id: "M3b",
        check: m3b,
    },
];

fn zeta() -> Sym {
    Sym::var("zeta")
}

/// Σ of the four segment functions of (5) on span `j` minus 1, exactly, or
/// the typed error of the printed formulas.
fn unity_residual(knots: Vec<Sym>, j: i64) -> Result<Sym, trig_core::CoreError> {
    let (s, c) = (Sym::var("s"), Sym::var("c"));
    let seg = NonUniform::new(knots, zeta()).segment(j, &s, &c)?;
    Ok(sum(&seg) - &Sym::one())
}

fn m3() -> Verdict {
    let knots = nonuniform_knots();
    let shown = knots
        .iter()
        .map(Sym::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let mut parts = Vec::new();
    for j in [NONUNIFORM_J, NONUNIFORM_J + 2] {
        let v = match unity_residual(knots.clone(), j) {
            Ok(r) if r.is_zero() => residual_verdict(&r, &Sym::zero()),
            Ok(r) => {
                // one exact point, re-checkable by hand: ζ = 2, z = tan(θ/2) = 1/2
                let at = r
                    .subs("zeta", &Sym::int(2))
                    .subs("s", &Sym::rational(Rational::from((4, 5))))
                    .subs("c", &Sym::rational(Rational::from((3, 5))));
                let mut v = residual_verdict(&(r + &Sym::one()), &Sym::one());
                v.evidence.push(format!(
                    "at ζ = 2, θ = 2 arctan(1/2) (s = 4/5, c = 3/5): Σ F − 1 = {at} (exact)"
                ));
                v
            }
            Err(e) => Verdict::new(
                Status::Fails,
                IDENTITY,
                vec![format!("the printed formulas are undefined: {e}")],
            ),
        };
        parts.push((
            format!("span [n_{j}, n_{}) of knots {shown}: Σ F − 1", j + 1),
            v,
        ));
    }
    let uniform: Vec<Sym> = (0..=20).map(Sym::int).collect();
    let v = match unity_residual(uniform, 10) {
        Ok(r) => residual_verdict(&(r + &Sym::one()), &Sym::one()),
        Err(e) => Verdict::new(
            Status::Fails,
            IDENTITY,
            vec![format!("the printed formulas are undefined: {e}")],
        ),
    };
    parts.push(("uniform knots n_i = i, span [n_10, n_11)".into(), v));
    Verdict::all(IDENTITY, parts)
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
        "uniform knots n_i = i (unit spacing; q_j = q_{j−1} = q_{j−2} as the paper states), span j = 10; Appendix A uses F0 = l0/D, F1 = l1/D, F2 = l2/D, F3 = l3/D with D = 6ζ² − 6ζ + 10",
    );
    v
}

/// `F_j > 0` for `ζ ∈ [0, 4]`: `F_j` is `F3, F2, F1, F0` on its four
/// intervals; each piece is certified `≥ 0` or refuted by a counterexample.
/// A negative value refutes `F_j > 0` on the open support `(n_j, n_{j+4})`
/// (the support ends have the value 0, computed here). When every piece is
/// certified, `≥ 0` does not prove `> 0`, and the exact zeros at the
/// support ends refute it on the closed support.
fn m2() -> Verdict {
    let f = basis(Family::Seed000Uniform);
    let mut v = nonnegative_on(
        &Family::Seed000Uniform,
        &f,
        Some("zeta"),
        &ParamBox::closed(Rational::new(), Rational::from(4)),
    );
    let at = |g: &Sym, s: i64, c: i64| g.subs("s", &Sym::int(s)).subs("c", &Sym::int(c));
    let (first, last) = (at(&f[3], 0, 1), at(&f[0], 1, 0));
    let mut line = format!(
        "the B-spline basis function F_j is F3, F2, F1, F0 on [n_j, n_{{j+1}}), …, [n_{{j+3}}, n_{{j+4}}) (uniform case, Appendix A); at its support ends F_j(n_j) = F3(θ = 0) = {first} and F_j(n_{{j+4}}) = F0(θ = π/2) = {last} for every ζ, so \"> 0\" can hold only on the open support (n_j, n_{{j+4}})"
    );
    if v.status == Status::Fails {
        line.push_str(
            "; the negative values above lie inside it and refute F_j > 0 there too (M11 decides the strict positivity of the middle pieces F2, F1)",
        );
    } else if first.is_zero() && last.is_zero() {
        line.push_str("; F_j ≥ 0 is certified, and F_j > 0 fails on the closed support");
        v.status = Status::Fails;
    }
    v.evidence.push(line);
    v
}
