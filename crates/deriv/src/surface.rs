//! Corner derivatives of a tensor-product surface `Σ_i Σ_j P_ij B_i(u) B_j(v)`
//! — or, with weights, of the rational surface
//! `Σ w_ij P_ij B_i(u) B_j(v) / Σ w_ij B_i(u) B_j(v)` — from the endpoint
//! derivatives of each direction's functions ([`crate::endpoint_derivatives`]).
//! The numerator is differentiated term by term; the rational surface is
//! the quotient of two bivariate jets (a [`Jet`] of jets), so the quotient
//! rule is the jets' division, written once.

use trig_core::Ring;

use crate::jet::Jet;

/// The weighted sum `Σ w_ij B_i(u) B_j(v)` of a rational surface is exactly
/// zero at the corner: the surface is `0/0` there.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the rational surface is not defined at this corner: its weighted sum Σ w_ij B_i(u) B_j(v) is exactly 0 there, so it has no derivatives there"
)]
pub struct VanishingWeightedSum;

/// `∂^{a+b}S/∂u^a∂v^b` at one corner for `a, b = 0..K`, as `[a][b]`. `du`
/// and `dv` are the derivatives `[function][order]` of the two directions
/// at the corner, `points` one coordinate (or symbol) per control point in
/// row order (`P_ij` at `i·n_v + j`), `weights` likewise for a rational
/// surface.
///
/// # Panics
/// If `points` (or `weights`) do not have `n_u·n_v` entries or a row of
/// derivatives has not `K` entries.
pub fn surface_corner_derivatives<T: Ring, const K: usize>(
    du: &[Vec<T>],
    dv: &[Vec<T>],
    points: &[T],
    weights: Option<&[T]>,
) -> Result<Vec<Vec<T>>, VanishingWeightedSum> {
    let nv = dv.len();
    assert_eq!(points.len(), du.len() * nv, "one point per net entry");
    let like = &points[0];
    // Σ_i Σ_j c_ij b_i^(a) b_j^(b)
    let mixed = |c: &dyn Fn(usize) -> T| -> Vec<Vec<T>> {
        (0..K)
            .map(|a| {
                (0..K)
                    .map(|b| {
                        du.iter().enumerate().fold(like.int(0), |acc, (i, bi)| {
                            dv.iter().enumerate().fold(acc, |acc, (j, bj)| {
                                acc + &(bi[a].clone() * &bj[b] * &c(i * nv + j))
                            })
                        })
                    })
                    .collect()
            })
            .collect()
    };
    let Some(w) = weights else {
        return Ok(mixed(&|k| points[k].clone()));
    };
    assert_eq!(w.len(), points.len(), "one weight per point");
    let numerator = mixed(&|k| w[k].clone() * &points[k]);
    let denominator = mixed(&|k| w[k].clone());
    if denominator[0][0].is_zero() {
        return Err(VanishingWeightedSum);
    }
    let quotient = bivariate::<T, K>(&numerator) / &bivariate::<T, K>(&denominator);
    Ok((0..K)
        .map(|a| {
            let inner = quotient.derivative(a);
            (0..K).map(|b| inner.derivative(b)).collect()
        })
        .collect())
}

/// The bivariate jet (a jet in `u` of jets in `v`) with the derivatives
/// `d[a][b]`.
fn bivariate<T: Ring, const K: usize>(d: &[Vec<T>]) -> Jet<Jet<T, K>, K> {
    let columns: Vec<Jet<T, K>> = d.iter().map(|row| Jet::from_derivatives(row)).collect();
    Jet::from_derivatives(&columns)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `B_i(u)` the linear Bernstein functions `1 − u, u` at `u = 0`:
    /// derivatives `[1, −1, 0]`, `[0, 1, 0]`.
    fn linear_at_zero() -> Vec<Vec<f64>> {
        vec![vec![1.0, -1.0, 0.0], vec![0.0, 1.0, 0.0]]
    }

    #[test]
    fn the_rational_bilinear_patch_has_the_quotient_derivatives() {
        // S = Σ w_ij P_ij B_i(u) B_j(v) / Σ w_ij B_i(u) B_j(v) with
        // P = (0, 1, 2, 3) and w = (1, 2, 3, 4) in row order, by hand:
        let d = linear_at_zero();
        let p = [0.0, 1.0, 2.0, 3.0];
        let w = [1.0, 2.0, 3.0, 4.0];
        let s = surface_corner_derivatives::<f64, 3>(&d, &d, &p, Some(&w)).unwrap();
        // N = 2(1−u)v + 6u(1−v) + 12uv = 6u + 2v + 4uv, W = 1 + 2u + v;
        // from N = S·W at 0 (S = 0): S_u = 6, S_v = 2,
        // S_uu = −2·S_u·W_u = −24, S_vv = −2·S_v·W_v = −4,
        // S_uv = N_uv − S_u·W_v − S_v·W_u = 4 − 6 − 4 = −6
        let want = [[0.0, 2.0, -4.0], [6.0, -6.0, 0.0], [-24.0, 0.0, 0.0]];
        for a in 0..3 {
            for b in 0..3 - a {
                assert!((s[a][b] - want[a][b]).abs() < 1e-12, "{a} {b}: {}", s[a][b]);
            }
        }
        // equal weights give the polynomial surface's derivatives
        let plain = surface_corner_derivatives::<f64, 3>(&d, &d, &p, None).unwrap();
        let equal = surface_corner_derivatives::<f64, 3>(&d, &d, &p, Some(&[5.0; 4])).unwrap();
        assert_eq!(plain, equal);
        assert_ne!(plain, s);
        // a weighted sum that vanishes at the corner is an error
        let zero = [0.0, 1.0, 1.0, 1.0];
        assert_eq!(
            surface_corner_derivatives::<f64, 3>(&d, &d, &p, Some(&zero)),
            Err(VanishingWeightedSum)
        );
    }
}
