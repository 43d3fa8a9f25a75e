//! `sin θ` and `cos θ` of many f64 angles at once: a branch-free
//! polynomial kernel the compiler vectorises (SSE2 on every x86-64, AVX2
//! where the processor has it), with a proved error bound.
//!
//! **Method.** Reduction by a multiple of `π/2`: `k = round(θ·2/π)`,
//! `r = (θ − k·P₁) − k·P₁ₜ` with fdlibm's split `P₁ + P₁ₜ ≈ π/2` (`P₁` has
//! 33 significant bits, so `k·P₁` is exact for `|k| < 2²⁰`), then
//! `|r| ≤ π/4 (1 + 2⁻⁵⁰)` and
//!
//! * `sin r = r + r·z·S(z)`, `z = r²`, `S` of degree 5,
//! * `cos r = (1 − z/2) + z²·C(z)`, `C` of degree 5,
//!
//! with fdlibm's minimax coefficients (`k_sin.c`, `k_cos.c`, the kernels
//! of most C libraries' `sin` and `cos`); the quadrant `k mod 4` swaps and
//! negates them.
//!
//! **Error bound** (absolute, `u = 2⁻⁵³`, for `|θ| ≤ 2²⁰`; larger angles
//! go through the platform's `sin_cos` one by one):
//!
//! * reduction: `θ − k·P₁` is exact (Sterbenz: `θ` and `k·P₁` are within
//!   a factor 2), the second step rounds twice (`≤ u·|r| + |k|·P₁ₜ·u`),
//!   and `|π/2 − P₁ − P₁ₜ| < 2⁻⁸⁵` adds `|k|·2⁻⁸⁵`: in all `< 0.8u`,
//!   which `|sin′|, |cos′| ≤ 1` carry over unchanged;
//! * approximation: `≤ 2⁻⁵⁸ < 0.04u` for both polynomials (fdlibm's
//!   bounds, which the tests confirm against MPFR);
//! * rounding: Horner's scheme in `z ≤ 0.62` with 5 steps on a polynomial
//!   whose condition number `Σ|aⱼ|zʲ / |Σ aⱼ zʲ|` is below 1.1 has
//!   relative error below `12u`, and forming `z`, `r·z` (`z²`) and the
//!   product adds `3u`; the
//!   correction terms are small (`|r·z·S| ≤ 0.081`, `|z²·C| ≤ 0.016`), so
//!   they contribute `≤ 1.6u` and `≤ 0.3u`; `z/2` is exact and off by
//!   `≤ 0.31u` through `z`; each final addition (results in `[1/2, 1)` or
//!   smaller) rounds by at most `0.5u`.
//!
//! Total: `|ŝ − sin θ| ≤ (0.8 + 0.04 + 1.6 + 0.5)u < 3u` and
//! `|ĉ − cos θ| ≤ (0.8 + 0.04 + 0.31 + 0.5 + 0.3 + 0.5)u < 3u`
//! (≈ 3.3·10⁻¹⁶). The tests check this bound against 256-bit MPFR on
//! points spread over the domain, near the multiples of `π/4`, and up to
//! `|θ| = 2²⁰`.

/// Largest `|θ|` the kernel reduces itself (`|k| < 2²⁰`).
const REDUCE_LIMIT: f64 = 1_048_576.0;

/// fdlibm's `pio2_1`: the first 33 bits of `π/2`.
const PIO2_1: f64 = 1.5707963267341256;
/// fdlibm's `pio2_1t`: `π/2 − pio2_1`, rounded.
const PIO2_1T: f64 = 6.077100506506192e-11;
/// `1.5·2⁵²`: adding it rounds to an integer (ties to even) and leaves
/// that integer in the low bits of the mantissa.
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// fdlibm's `k_sin.c` coefficients `S1…S6`: on `|x| ≤ π/4`,
/// `|sin x / x − (1 + x²·S(x²))| ≤ 2⁻⁵⁸` (the bound stated with them).
const SIN_COEFFS: [f64; 6] = [
    -0.16666666666666632,
    0.00833333333332249,
    -0.0001984126982985795,
    2.7557313707070068e-06,
    -2.5050760253406863e-08,
    1.58969099521155e-10,
];

/// fdlibm's `k_cos.c` coefficients `C1…C6`: on `|x| ≤ π/4`,
/// `|cos x − (1 − x²/2 + x⁴·C(x²))| ≤ 2⁻⁵⁸`.
const COS_COEFFS: [f64; 6] = [
    0.0416666666666666,
    -0.001388888888887411,
    2.480158728947673e-05,
    -2.7557314351390663e-07,
    2.087572321298175e-09,
    -1.1359647557788195e-11,
];

/// `(sin θ, cos θ)` for `|θ| ≤ 2²⁰`, branch-free, for `LANES` angles
/// (every step is a loop over the lanes, which the compiler vectorises);
/// the polynomials by Horner's scheme.
#[inline(always)]
fn reduced<const LANES: usize>(theta: &mut [f64; LANES], cos: &mut [f64; LANES]) {
    let mut quadrant = [0u64; LANES];
    let mut r = [0.0; LANES];
    for l in 0..LANES {
        let shifted = theta[l] * std::f64::consts::FRAC_2_PI + ROUNDER;
        quadrant[l] = shifted.to_bits() & 3;
        let k = shifted - ROUNDER;
        r[l] = (theta[l] - k * PIO2_1) - k * PIO2_1T;
    }
    let z = r.map(|r| r * r);
    let mut ps = [SIN_COEFFS[SIN_COEFFS.len() - 1]; LANES];
    for &coeff in SIN_COEFFS.iter().rev().skip(1) {
        for l in 0..LANES {
            ps[l] = ps[l] * z[l] + coeff;
        }
    }
    let mut pc = [COS_COEFFS[COS_COEFFS.len() - 1]; LANES];
    for &coeff in COS_COEFFS.iter().rev().skip(1) {
        for l in 0..LANES {
            pc[l] = pc[l] * z[l] + coeff;
        }
    }
    for l in 0..LANES {
        let sin = r[l] + r[l] * z[l] * ps[l];
        let cos_r = (1.0 - 0.5 * z[l]) + z[l] * z[l] * pc[l];
        // Quadrant k mod 4 by bit operations (they vectorise where 64-bit
        // compares do not): odd k swaps sine and cosine, k ≡ 2, 3 negates
        // the sine, k ≡ 1, 2 the cosine.
        let q = quadrant[l];
        let swap = 0u64.wrapping_sub(q & 1);
        let (sin, cos_r) = (sin.to_bits(), cos_r.to_bits());
        let s = (sin & !swap) | (cos_r & swap);
        let c = (cos_r & !swap) | (sin & swap);
        theta[l] = f64::from_bits(s ^ ((q & 2) << 62));
        cos[l] = f64::from_bits(c ^ (((q + 1) & 2) << 62));
    }
}

/// Replaces every angle `theta[i]` by `sin theta[i]` and writes
/// `cos theta[i]` to `cos[i]` (error `≤ 3·2⁻⁵³`, see the module
/// documentation). Non-finite angles give NaN.
///
/// On x86-64 processors with AVX2 (detected at run time) the same
/// operations run four angles per instruction instead of two; the results
/// are identical, since no operation is fused or reordered.
///
/// # Panics
/// If the slices differ in length.
pub fn sin_cos_in_place(theta: &mut [f64], cos: &mut [f64]) {
    assert_eq!(theta.len(), cos.len(), "one cosine per angle");
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (checked just above), the one
        // condition for calling a function compiled to use it.
        #[allow(unsafe_code)]
        unsafe {
            sin_cos_avx2(theta, cos);
        }
        return;
    }
    // two 2-wide SSE2 vectors in flight
    sin_cos_lanes::<4>(theta, cos);
}

/// [`sin_cos_lanes`] compiled for AVX2: two 4-wide vectors in flight.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn sin_cos_avx2(theta: &mut [f64], cos: &mut [f64]) {
    sin_cos_lanes::<8>(theta, cos);
}

/// The kernel over `LANES` angles at a time: independent lanes keep the
/// vector units busy while each lane's Horner chain waits on its previous
/// step. Angles beyond the reduction range (or NaN) go through the
/// platform's `sin_cos`.
#[inline(always)]
fn sin_cos_lanes<const LANES: usize>(theta: &mut [f64], cos: &mut [f64]) {
    for (t, c) in theta.chunks_mut(LANES).zip(cos.chunks_mut(LANES)) {
        let mut lanes = [0.0; LANES];
        let mut lanes_cos = [0.0; LANES];
        let mut far = false;
        for (lane, &x) in lanes.iter_mut().zip(t.iter()) {
            // NaN fails the comparison too
            let near = x.abs() <= REDUCE_LIMIT;
            far |= !near;
            *lane = if near { x } else { 0.0 };
        }
        reduced(&mut lanes, &mut lanes_cos);
        for (((ti, ci), &s), &co) in t.iter_mut().zip(c.iter_mut()).zip(&lanes).zip(&lanes_cos) {
            let x = *ti;
            let near = x.abs() <= REDUCE_LIMIT;
            (*ti, *ci) = if far && !near { x.sin_cos() } else { (s, co) };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    /// `3·2⁻⁵³`, the bound of the module documentation.
    const BOUND: f64 = 3.0 / 9_007_199_254_740_992.0;

    fn check(angles: &[f64]) {
        let mut s = angles.to_vec();
        let mut c = vec![0.0; angles.len()];
        sin_cos_in_place(&mut s, &mut c);
        for ((&theta, &si), &ci) in angles.iter().zip(&s).zip(&c) {
            let (es, ec) = Float::with_val(256, theta).sin_cos(Float::new(256));
            let ds = (Float::with_val(256, si) - &es).abs().to_f64();
            let dc = (Float::with_val(256, ci) - &ec).abs().to_f64();
            assert!(ds <= BOUND && dc <= BOUND, "θ = {theta:e}: {ds:e} {dc:e}");
        }
    }

    #[test]
    fn within_three_units_in_the_last_place_over_the_domain() {
        let n = 20_000;
        let grid: Vec<f64> = (0..=n)
            .map(|i| std::f64::consts::FRAC_PI_2 * f64::from(i) / f64::from(n))
            .collect();
        check(&grid);
    }

    #[test]
    fn within_the_bound_near_multiples_of_a_quarter_turn_and_far_out() {
        let mut angles = Vec::new();
        for j in -40_i32..=40 {
            let centre = f64::from(j) * std::f64::consts::FRAC_PI_4;
            let mut x = centre;
            for _ in 0..20 {
                angles.extend([x, -x]);
                x = x.next_up();
            }
            angles.extend([centre + 1e-9, centre - 1e-9]);
        }
        for e in 0..=20 {
            let big = f64::from(1 << e) * 0.987_654_321;
            angles.extend([big, -big, REDUCE_LIMIT, -REDUCE_LIMIT]);
        }
        angles.extend([0.0, -0.0, 1e-300, 5e-324]);
        check(&angles);
    }

    #[test]
    fn every_vector_width_gives_the_same_bits() {
        let angles: Vec<f64> = (0..1000).map(|i| f64::from(i) * 0.0123 - 3.0).collect();
        let run = |f: fn(&mut [f64], &mut [f64])| {
            let mut s = angles.clone();
            let mut c = vec![0.0; s.len()];
            f(&mut s, &mut c);
            (s, c)
        };
        let portable = run(sin_cos_lanes::<4>);
        assert_eq!(run(sin_cos_lanes::<8>), portable);
        assert_eq!(run(sin_cos_in_place), portable);
    }

    #[test]
    fn huge_and_non_finite_angles() {
        let mut s = vec![1e10, 3.0, f64::NAN, f64::INFINITY];
        let mut c = vec![0.0; 4];
        sin_cos_in_place(&mut s, &mut c);
        assert_eq!((s[0], c[0]), 1e10_f64.sin_cos());
        assert_eq!((s[1], c[1]), 3.0_f64.sin_cos());
        assert!(s[2].is_nan() && c[2].is_nan() && s[3].is_nan() && c[3].is_nan());
    }
}
