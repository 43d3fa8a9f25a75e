//! Bases of the thesis (seed `001_cf6c2ede0355a863.txt`), each written once
//! in `s = sin θ`, `c = cos θ`.

use crate::scalar::Ring;

/// Thesis (3.1), quadratic basis with `β ≥ 0`, `u ∈ [0,1]`, `θ = πu/2`:
///
/// `H₀ = β/(β+1) − 2β/(β+1)·s + β/(β+1)·s²`,
/// `H₂ = β/(β+1) − 2β/(β+1)·c + β/(β+1)·c²`,
/// `H₁ = 1 − H₀ − H₂` (defined through the other two, as printed).
pub fn quadratic<T: Ring>(s: &T, c: &T, beta: &T) -> [T; 3] {
    let k = beta.clone() / &(beta.clone() + &beta.int(1));
    let two_k = k.clone() * &k.int(2);
    let h0 = k.clone() - &(two_k.clone() * s) + &(k.clone() * &s.square());
    let h2 = k.clone() - &(two_k * c) + &(k * &c.square());
    let h1 = s.int(1) - &h0 - &h2;
    [h0, h1, h2]
}

/// Thesis (3.7), cubic basis with `m ∈ [−2, 1]`, `u ∈ [0,1]`, `θ = πu/2`:
///
/// `b₀ = (1−s)²(1−ms)`, `b₁ = ms(1−s)² − 2s(s−1)`,
/// `b₂ = mc(1−c)² − 2c(c−1)`, `b₃ = (1−c)²(1−mc)`.
pub fn cubic<T: Ring>(s: &T, c: &T, m: &T) -> [T; 4] {
    let one = s.int(1);
    let two = s.int(2);
    let oms = one.clone() - s;
    let omc = one.clone() - c;
    let ms = m.clone() * s;
    let mc = m.clone() * c;
    // (1−s)², (1−c)² formed once each (the same values in every ring)
    let oms2 = oms.square();
    let omc2 = omc.square();
    let b0 = oms2.clone() * &(one.clone() - &ms);
    let b1 = ms * &oms2 - &(two.clone() * s * &(s.clone() - &one));
    let b2 = mc.clone() * &omc2 - &(two * c * &(c.clone() - &one));
    let b3 = omc2 * &(one - &mc);
    [b0, b1, b2, b3]
}

/// Han et al. (2010) as transcribed in the thesis, (6.2), `λ ∈ [−2, 1]`,
/// `t ∈ [0,1]`, angle `πt/2`:
///
/// `b₀ = (1−s)²(1−λs)`, `b₁ = s(1−s)(2+λ−λs)`,
/// `b₂ = c(1−c)(2+λ−λc)`, `b₃ = (1−c)²(1−λc)`.
pub fn han<T: Ring>(s: &T, c: &T, lambda: &T) -> [T; 4] {
    han_with_third_factor_atom(s, c, lambda, c)
}

/// Han's basis exactly as the thesis's Appendix 2 MATLAB listing computes it:
/// `b20 = cos(πt/2)(1−cos(πt/2))(2+m−m·sin(πt/2))` — the last factor uses
/// `sin` where (6.2) has `cos`. The other three lines agree with (6.2).
pub fn han_listing<T: Ring>(s: &T, c: &T, lambda: &T) -> [T; 4] {
    han_with_third_factor_atom(s, c, lambda, s)
}

/// Han's four functions with the atom `x` in the last factor of `b₂`
/// (`c` in (6.2), `s` in the Appendix 2 listing).
fn han_with_third_factor_atom<T: Ring>(s: &T, c: &T, lambda: &T, x: &T) -> [T; 4] {
    let one = s.int(1);
    let two_plus = s.int(2) + lambda;
    let oms = one.clone() - s;
    let omc = one.clone() - c;
    let b0 = oms.square() * &(one.clone() - &(lambda.clone() * s));
    let b1 = s.clone() * &oms * &(two_plus.clone() - &(lambda.clone() * s));
    let b2 = c.clone() * &omc * &(two_plus - &(lambda.clone() * x));
    let b3 = omc.square() * &(one - &(lambda.clone() * c));
    [b0, b1, b2, b3]
}

/// Majeed & Qayyum (2020) as transcribed in the thesis, (6.1),
/// `η ∈ (1/2, 2]`, `t ∈ [0, π/2]`:
///
/// `g₀ = (1−s)²(1+(1−η)s)`, `g₁ = (2−(1−η)(1−s))·s·(1−s)`,
/// `g₂ = (2−(1−η)(1−c))·c·(1−c)`, `g₃ = (1−c)²(1+(1−η)c)`.
pub fn majeed_qayyum<T: Ring>(s: &T, c: &T, eta: &T) -> [T; 4] {
    let one = s.int(1);
    let two = s.int(2);
    let k = one.clone() - eta;
    let oms = one.clone() - s;
    let omc = one.clone() - c;
    let g0 = oms.square() * &(one.clone() + &(k.clone() * s));
    let g1 = (two.clone() - &(k.clone() * &oms)) * s * &oms;
    let g2 = (two - &(k.clone() * &omc)) * c * &omc;
    let g3 = omc.square() * &(one + &(k * c));
    [g0, g1, g2, g3]
}

/// Usman et al. (2020) as transcribed in the thesis, (6.3), `α ∈ (0, 2)`,
/// `η ∈ [0,1]`, `S = sin(πη/2)`, `U = cos(πη/2)`:
///
/// `a₀ = αS² − αS + U²`, `a₁ = α(S − S²)`, `a₂ = α(S² + U − 1)`,
/// `a₃ = (1−α)S² − αU + α`.
pub fn usman<T: Ring>(s: &T, c: &T, alpha: &T) -> [T; 4] {
    let one = s.int(1);
    let s2 = s.square();
    let a0 = alpha.clone() * &s2 - &(alpha.clone() * s) + &c.square();
    let a1 = alpha.clone() * &(s.clone() - &s2);
    let a2 = alpha.clone() * &(s2.clone() + c - &one);
    let a3 = (one - alpha) * &s2 - &(alpha.clone() * c) + alpha;
    [a0, a1, a2, a3]
}

/// Matrix `[A]` of thesis (5.6): `[T][A] = [b₀ b₁ b₂ b₃]` with
/// `[T] = [1 s s² s³ c c² c³]` (5.5). Rows as printed.
pub fn surface_matrix_a<T: Ring>(m: &T) -> [[T; 4]; 7] {
    let z = m.int(0);
    let one = m.int(1);
    let m2 = m.clone() + &m.int(2);
    let two_m1 = (m.clone() + &one) * &m.int(2);
    let one_2m = one.clone() + &(m.clone() * &m.int(2));
    [
        [one.clone(), z.clone(), z.clone(), one],
        [-m2.clone(), m2.clone(), z.clone(), z.clone()],
        [one_2m.clone(), -two_m1.clone(), z.clone(), z.clone()],
        [-m.clone(), m.clone(), z.clone(), z.clone()],
        [z.clone(), z.clone(), m2.clone(), -m2],
        [z.clone(), z.clone(), -two_m1, one_2m],
        [z.clone(), z, m.clone(), -m.clone()],
    ]
}

/// Row `[T]` of thesis (5.5): `[1 s s² s³ c c² c³]`.
pub fn surface_row_t<T: Ring>(s: &T, c: &T) -> [T; 7] {
    [
        s.int(1),
        s.clone(),
        s.square(),
        s.powi(3),
        c.clone(),
        c.square(),
        c.powi(3),
    ]
}
