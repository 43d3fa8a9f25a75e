//! The four schemes of thesis 4.3, as printed, and corrected where the print
//! is wrong. Every piece is `P_i(x) = b_0 V_i + b_1 W_i + b_2 X_i + b_3 Y_i`
//! (4.19) with `V_i = f_i`, `Y_i = f_{i+1}`; `k_i = m_i + 2`.
//!
//! * **C¹ (4.21)**: `W_i = f_i + 2h_i d_i/(π k_i)`, `X_i = f_{i+1} − 2h_i d_{i+1}/(π k_i)`,
//!   meant to give `P'(x_i) = d_i`, `P'(x_{i+1}) = d_{i+1}` (4.20).
//! * **C² (4.25)**: the *same* control points as (4.21); (4.23)/(4.24) only
//!   *compute* `D_i`, `D_{i+1}` from them. Printed variant: exactly that.
//!   Corrected variant: the `d_i` of the interior knots are no longer the
//!   arithmetic means but the solution of the `C²` conditions
//!   `P_{i−1}''(x_i) = P_i''(x_i)` (a tridiagonal system, derived from the
//!   basis through `trig_deriv`), with the arithmetic-mean end values `d_0`, `d_n`.
//! * **G¹ (4.27)**: `W_i = f_i + 2h_i n_i d_i/(π k_i)`, `X_i` as in C¹, meant to give
//!   `P'(x_i) = n_i d_i`, `P'(x_{i+1}) = d_{i+1}` (4.26).
//! * **G² (4.29)–(4.34)**: the first piece from the first-derivative conditions of
//!   (4.29), `P'(x_0) = α_0 d_0`, `P'(x_1) = d_1` (the (4.27) formula with `n = α`);
//!   every later piece from the join (4.33) with the previous one:
//!   `V^2_0 = V^1_3`, `V^2_1`, `V^2_2` forced, `V^2_3 = f_{i+1}`, with `α_i`, `β_i`
//!   of its row. Printed variant: `V^2_1`, `V^2_2` by (4.34) as printed (one `m`
//!   in the print; read as the new piece's `m_i`). Corrected variant: `V^2_1`,
//!   `V^2_2` solved from (4.33) in `x` (`d/dx`, lengths `h_{i−1}`, `h_i`, each piece
//!   its own `m`). The derivative estimates after `d_1` are not used by (4.34).
//!
//! The corrected variants of C¹ and G¹ solve the printed end conditions
//! through the basis (no printed formula); they equal the printed ones
//! exactly when T20/T22 hold.

use rug::Rational;
use trig_core::Ring;
use trig_deriv::{End, Wrt};

use crate::InterpError;
use crate::data::DataSet;
use crate::kind::{Scheme, Variant};
use crate::piece::{Condition, Piece, derivatives_of, inner_points};
use crate::slopes::arithmetic_mean;

/// An assembled interpolant.
#[derive(Debug, Clone, PartialEq)]
pub struct Spline<T> {
    pub data: DataSet,
    pub scheme: Scheme,
    pub variant: Variant,
    /// The derivative values `d_0 … d_n` the pieces were built from.
    pub slopes: Vec<T>,
    pub pieces: Vec<Piece<T>>,
}

impl<T> Spline<T> {
    /// Intervals whose `m_i` lies outside the basis range `[−2, 1]` of (3.7)
    /// or equals the excluded `−2` of 4.2.1 (`m ∈ (−2, 1]`).
    pub fn m_outside_range(&self) -> Vec<(usize, Rational)> {
        self.pieces
            .iter()
            .enumerate()
            .filter(|(_, p)| p.m <= -2 || p.m > 1)
            .map(|(i, p)| (i, p.m.clone()))
            .collect()
    }
}

/// `2h d/(π(m+2))`, the common term of (4.21), (4.25), (4.27).
fn tangent_term<T: Ring>(h: &T, d: &T, m: &T) -> Result<T, InterpError> {
    let k = m.clone() + &m.int(2);
    let den = h.pi() * &k;
    if den.is_zero() {
        return Err(InterpError::Singular(
            "π(m + 2) = 0 in (4.21): m = −2".into(),
        ));
    }
    Ok(h.int(2) * h * d / &den)
}

/// (4.21) as printed: `(W_i, X_i) = (2h_i d_i/(π(m_i+2)) + f_i, −2h_i d_{i+1}/(π(m_i+2)) + f_{i+1})`.
pub fn printed_c1<T: Ring>(
    f0: &T,
    f1: &T,
    d0: &T,
    d1: &T,
    h: &T,
    m: &T,
) -> Result<(T, T), InterpError> {
    Ok((tangent_term(h, d0, m)? + f0, -tangent_term(h, d1, m)? + f1))
}

/// (4.27) as printed: `W_i = 2h_i d_i n_i/(π(m_i+2)) + f_i`, `X_i` as (4.21).
pub fn printed_g1<T: Ring>(
    f0: &T,
    f1: &T,
    d0: &T,
    d1: &T,
    h: &T,
    m: &T,
    n: &T,
) -> Result<(T, T), InterpError> {
    Ok((
        tangent_term(h, d0, m)? * n + f0,
        -tangent_term(h, d1, m)? + f1,
    ))
}

/// (4.34) as printed: `(V^2_1, V^2_2)` from `V^1_1, V^1_2, V^1_3`.
pub fn printed_g2_join<T: Ring>(v1: &T, v2: &T, v3: &T, m: &T, alpha: &T, beta: &T) -> (T, T) {
    let two_over_pi = v1.int(2) / &v1.pi();
    let a2 = alpha.square();
    let w1 = (v3.clone() - v2) * alpha + v3;
    let w2 = a2.clone() * v1
        + &(m.int(2) * &(m.int(-1) - m) * &(a2.clone() + alpha) * v2)
        + &(two_over_pi.clone() * &(m.int(-1) - &(m.clone() / &m.int(2))) * beta * v2)
        + &(m.int(2) * &(m.int(1) + m) * &(alpha.clone() + &m.int(1)) * v3)
        + &(m.int(2) * &(m.ratio(1, 2) + m) * &a2 * v3)
        + &(two_over_pi * &(m.int(1) + &(m.clone() / &m.int(2))) * beta * v3);
    (w1, w2)
}

/// The G² join (4.33) solved through the basis: the inner points of the next
/// piece (parameter `m2`, length `h2`, `V_0 = prev(end)`, `V_3 = v3`) with
/// `P₂'(0) = α P₁'(1)`, `P₂''(0) = α² P₁''(1) + β P₁'(1)`, derivatives in `wrt`.
#[allow(clippy::too_many_arguments)]
pub fn derived_g2_join<T: Ring>(
    prev: &[T; 4],
    m1: &Rational,
    h1: &Rational,
    m2: &Rational,
    h2: &Rational,
    v3: &T,
    alpha: &T,
    beta: &T,
    wrt: Wrt,
) -> Result<(T, T), InterpError> {
    let e = derivatives_of(prev, m1, h1, End::End, wrt);
    let conditions = [
        Condition {
            end: End::Start,
            order: 1,
            target: alpha.clone() * &e[1],
        },
        Condition {
            end: End::Start,
            order: 2,
            target: alpha.square() * &e[2] + &(beta.clone() * &e[1]),
        },
    ];
    inner_points(m2, h2, wrt, &e[0], v3, conditions)
}

/// Builds the interpolant of `scheme` on `data` in the ring of `like`.
pub fn build<T: Ring>(
    data: &DataSet,
    scheme: Scheme,
    variant: Variant,
    like: &T,
) -> Result<Spline<T>, InterpError> {
    let q = |r: &Rational| like.rational(r);
    let n = data.intervals();
    let m = data.column("m", scheme)?;
    let amm: Vec<T> = arithmetic_mean(&data.x, &data.f)?.iter().map(q).collect();
    let slopes = match (scheme, variant) {
        (Scheme::C2, Variant::Corrected) => c2_slopes(data, m, &amm)?,
        _ => amm,
    };
    let factor = match scheme {
        Scheme::G1 => Some(data.column("n", scheme)?),
        Scheme::G2 => Some(data.column("alpha", scheme)?),
        _ => None,
    };
    let beta = match scheme {
        Scheme::G2 => Some(data.column("beta", scheme)?),
        _ => None,
    };
    let mut pieces: Vec<Piece<T>> = Vec::with_capacity(n);
    for i in 0..n {
        let (f0, f1, h) = (q(&data.f[i]), q(&data.f[i + 1]), data.h(i));
        let (d0, d1) = (&slopes[i], &slopes[i + 1]);
        let start_factor = factor.map_or_else(|| like.int(1), |c| q(&c[i]));
        let (w, x) = match (scheme, variant, i) {
            (Scheme::G2, _, 1..) => {
                let prev = &pieces[i - 1];
                let (alpha, b) = (
                    q(&factor.expect("G2 has α")[i]),
                    q(&beta.expect("G2 has β")[i]),
                );
                match variant {
                    Variant::Printed => Ok(printed_g2_join(
                        &prev.points[1],
                        &prev.points[2],
                        &prev.points[3],
                        &q(&m[i]),
                        &alpha,
                        &b,
                    )),
                    Variant::Corrected => derived_g2_join(
                        &prev.points,
                        &prev.m,
                        &prev.h,
                        &m[i],
                        &h,
                        &f1,
                        &alpha,
                        &b,
                        Wrt::X,
                    ),
                }
            }
            (Scheme::C1 | Scheme::C2, Variant::Printed, _) => {
                printed_c1(&f0, &f1, d0, d1, &q(&h), &q(&m[i]))
            }
            (Scheme::G1 | Scheme::G2, Variant::Printed, _) => {
                printed_g1(&f0, &f1, d0, d1, &q(&h), &q(&m[i]), &start_factor)
            }
            (_, Variant::Corrected, _) => inner_points(
                &m[i],
                &h,
                Wrt::X,
                &f0,
                &f1,
                [
                    Condition {
                        end: End::Start,
                        order: 1,
                        target: start_factor.clone() * d0,
                    },
                    Condition {
                        end: End::End,
                        order: 1,
                        target: d1.clone(),
                    },
                ],
            ),
        }?;
        pieces.push(Piece {
            x0: data.x[i].clone(),
            h,
            m: m[i].clone(),
            points: [f0, w, x, f1],
        });
    }
    Ok(Spline {
        data: data.clone(),
        scheme,
        variant,
        slopes,
        pieces,
    })
}

/// Second derivatives `(P_i''(x_i), P_i''(x_{i+1}))` of the C¹ piece built from `d0`, `d1`.
fn c1_second<T: Ring>(
    data: &DataSet,
    m: &Rational,
    i: usize,
    d0: &T,
    d1: &T,
) -> Result<(T, T), InterpError> {
    let (f0, f1, h) = (
        d0.rational(&data.f[i]),
        d0.rational(&data.f[i + 1]),
        data.h(i),
    );
    let conditions = [
        Condition {
            end: End::Start,
            order: 1,
            target: d0.clone(),
        },
        Condition {
            end: End::End,
            order: 1,
            target: d1.clone(),
        },
    ];
    let (w, x) = inner_points(m, &h, Wrt::X, &f0, &f1, conditions)?;
    let points = [f0, w, x, f1];
    Ok((
        derivatives_of(&points, m, &h, End::Start, Wrt::X)[2].clone(),
        derivatives_of(&points, m, &h, End::End, Wrt::X)[2].clone(),
    ))
}

/// The interior `d_1 … d_{n−1}` that make the C¹ pieces C²:
/// `P_{j−1}''(x_j) = P_j''(x_j)` for `j = 1 … n−1`, `d_0`, `d_n` kept. Each
/// piece's second derivatives are affine in its two slopes; the coefficients
/// come from the basis (evaluated at slope pairs `(0,0)`, `(1,0)`, `(0,1)`).
fn c2_slopes<T: Ring>(data: &DataSet, m: &[Rational], amm: &[T]) -> Result<Vec<T>, InterpError> {
    let like = &amm[0];
    let n = data.intervals();
    let (zero, one) = (like.int(0), like.int(1));
    // per piece: (base, ∂/∂d_i, ∂/∂d_{i+1}) at start and at end
    let mut affine = Vec::with_capacity(n);
    for (i, mi) in m.iter().enumerate() {
        let base = c1_second(data, mi, i, &zero, &zero)?;
        let a = c1_second(data, mi, i, &one, &zero)?;
        let b = c1_second(data, mi, i, &zero, &one)?;
        affine.push((
            (base.0.clone(), a.0 - &base.0, b.0 - &base.0),
            (base.1.clone(), a.1 - &base.1, b.1 - &base.1),
        ));
    }
    let size = n - 1;
    let mut mat = vec![vec![zero.clone(); size]; size];
    let mut rhs = vec![zero.clone(); size];
    for j in 1..n {
        let (bl, al, cl) = &affine[j - 1].1; // left piece at its end: bl + al d_{j−1} + cl d_j
        let (br, ar, cr) = &affine[j].0; // right piece at its start: br + ar d_j + cr d_{j+1}
        let row = j - 1;
        rhs[row] = br.clone() - bl;
        mat[row][row] = cl.clone() - ar;
        if j >= 2 {
            mat[row][row - 1] = al.clone();
        } else {
            rhs[row] = rhs[row].clone() - &(al.clone() * &amm[0]);
        }
        if j < n - 1 {
            mat[row][row + 1] = -cr.clone();
        } else {
            rhs[row] = rhs[row].clone() + &(cr.clone() * &amm[n]);
        }
    }
    let interior = solve(mat, rhs)?;
    let mut d = vec![amm[0].clone()];
    d.extend(interior);
    d.push(amm[n].clone());
    Ok(d)
}

/// Gaussian elimination over the ring (pivot: first entry that is not zero).
fn solve<T: Ring>(mut a: Vec<Vec<T>>, mut b: Vec<T>) -> Result<Vec<T>, InterpError> {
    let n = b.len();
    for k in 0..n {
        let p = (k..n).find(|&r| !a[r][k].is_zero()).ok_or_else(|| {
            InterpError::Singular("the C² system for the interior slopes is singular".into())
        })?;
        a.swap(k, p);
        b.swap(k, p);
        for r in k + 1..n {
            if a[r][k].is_zero() {
                continue;
            }
            let factor = a[r][k].clone() / &a[k][k];
            let pivot_row = a[k].clone();
            for (entry, p) in a[r].iter_mut().zip(&pivot_row).skip(k) {
                *entry = entry.clone() - &(factor.clone() * p);
            }
            b[r] = b[r].clone() - &(factor * &b[k]);
        }
    }
    let mut x = b.clone();
    for k in (0..n).rev() {
        let mut v = b[k].clone();
        for c in k + 1..n {
            v = v - &(a[k][c].clone() * &x[c]);
        }
        x[k] = v / &a[k][k];
    }
    Ok(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jumps::knot_jumps;
    use trig_symbolic::Sym;

    fn table(n: &str) -> DataSet {
        DataSet::named(n).unwrap()
    }

    #[test]
    fn printed_c1_and_g1_equal_the_solved_end_conditions() {
        for (name, scheme) in [
            ("thesis-table-4.1", Scheme::C1),
            ("thesis-table-4.3", Scheme::G1),
        ] {
            let d = table(name);
            let p = build(&d, scheme, Variant::Printed, &Sym::zero()).unwrap();
            let c = build(&d, scheme, Variant::Corrected, &Sym::zero()).unwrap();
            for (a, b) in p.pieces.iter().zip(&c.pieces) {
                for (x, y) in a.points.iter().zip(&b.points) {
                    assert!((x.clone() - y).is_zero(), "{name}: {x} ≠ {y}");
                }
            }
        }
    }

    #[test]
    fn the_corrected_c2_scheme_is_c2_and_the_printed_one_is_not() {
        let d = table("thesis-table-4.2");
        let corrected = build(&d, Scheme::C2, Variant::Corrected, &Sym::zero()).unwrap();
        for k in knot_jumps(&corrected) {
            assert!(
                k.continuity_order() >= Some(2),
                "knot {}: {:?}",
                k.knot,
                k.jumps
            );
        }
        let printed = build(&d, Scheme::C2, Variant::Printed, &Sym::zero()).unwrap();
        assert!(
            knot_jumps(&printed)
                .iter()
                .any(|k| k.continuity_order() == Some(1))
        );
    }

    #[test]
    fn the_printed_g2_join_differs_from_the_solved_one_by_2m_plus_1_v3() {
        let s = |n: &str| Sym::var(n);
        let (v1, v2, v3) = (s("V1"), s("V2"), s("V3"));
        let (alpha, beta) = (s("alpha"), s("beta"));
        let m = Rational::from((3, 7));
        let ms = Sym::rational(m.clone());
        let (p1, p2) = printed_g2_join(&v1, &v2, &v3, &ms, &alpha, &beta);
        let one = Rational::from(1);
        let prev = [s("V0"), v1, v2, v3.clone()];
        let (d1, d2) =
            derived_g2_join(&prev, &m, &one, &m, &one, &s("W3"), &alpha, &beta, Wrt::U).unwrap();
        assert!((p1 - &d1).is_zero());
        let expected = (Sym::int(2) * &ms + &Sym::int(1)) * &v3;
        assert!((p2 - &d2 - &expected).is_zero());
    }

    #[test]
    fn the_corrected_g2_spline_meets_the_g2_join_in_f64() {
        for name in ["thesis-table-4.4", "thesis-table-4.5"] {
            let d = table(name);
            let sp = build(&d, Scheme::G2, Variant::Corrected, &0.0).unwrap();
            let alpha = d.column("alpha", Scheme::G2).unwrap();
            let beta = d.column("beta", Scheme::G2).unwrap();
            for (i, w) in sp.pieces.windows(2).enumerate() {
                let (l, r) = (w[0].derivatives(End::End), w[1].derivatives(End::Start));
                let (a, b) = (alpha[i + 1].to_f64(), beta[i + 1].to_f64());
                let tol = 1e-9 * (1.0 + l[2].abs() + l[1].abs());
                assert!((r[0] - l[0]).abs() < tol);
                assert!((r[1] - a * l[1]).abs() < tol, "{name} knot {i}");
                assert!((r[2] - a * a * l[2] - b * l[1]).abs() < tol * (1.0 + a * a));
            }
        }
    }

    #[test]
    fn bad_requests_are_typed_errors() {
        assert!(matches!(
            "c3".parse::<Scheme>(),
            Err(InterpError::UnknownScheme(_))
        ));
        assert_eq!("G2".parse::<Scheme>().unwrap(), Scheme::G2);
        let d = table("thesis-table-4.2");
        assert!(matches!(
            build(&d, Scheme::G2, Variant::Printed, &0.0),
            Err(InterpError::MissingColumn { .. })
        ));
    }
}
