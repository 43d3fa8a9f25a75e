//! Property tests of the numeric evaluators: f64 against 256-bit MPFR over
//! each family's published range; curves, rational curves and surfaces
//! against direct evaluation; the matrix-form surface against the double sum.

use nalgebra::{Point2, Point3};
use proptest::prelude::*;
use rug::Rational;
use trig_core::curve::Segment;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface, thesis_matrix_form};
use trig_core::{Affine, Bound, Family, Mpfr, Real};

/// A parameter value inside `range`, from a uniform draw `x ∈ [0, 1]`.
/// Unbounded ends are capped at ±1000 (the quadratic's `β ≥ 0`).
fn in_range(range: trig_core::Range, x: f64) -> Rational {
    let lo = range.lo.value().unwrap_or(Rational::from(-1000));
    let hi = range.hi.value().unwrap_or(Rational::from(1000));
    // stay strictly inside open ends
    let open = matches!(range.lo, Bound::Open(..)) || matches!(range.hi, Bound::Open(..));
    let x = if open { 1e-6 + x * (1.0 - 2e-6) } else { x };
    let w = Rational::from_f64(x).expect("finite");
    lo.clone() + (hi - lo) * w
}

fn params_for(family: Family, draws: &[f64]) -> Vec<Rational> {
    family
        .info()
        .params
        .iter()
        .zip(draws)
        .map(|(p, &x)| in_range(p.range, x))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Error bound: every function is a sum of at most ten products of
    /// atoms bounded by 2 in magnitude (|s|, |c| ≤ 1, 1 ± s ≤ 2) with
    /// parameter factors bounded by 1 + |p| ≤ 5 (β enters only through
    /// β/(β+1) ≤ 1), so every partial sum is at most 10·2⁴·5 = 800 in size,
    /// and at most 40 roundings each commit at most u·800 with
    /// u = 2⁻⁵³ ≈ 1.1·10⁻¹⁶: |f64 − exact| ≤ 40·800·u ≈ 3.6·10⁻¹². MPFR at
    /// 256 bits is exact to that scale.
    #[test]
    fn f64_agrees_with_256_bit_mpfr(x in 0.0..=1.0f64, d1 in 0.0..=1.0f64, d2 in 0.0..=1.0f64) {
        for family in Family::ALL.into_iter().filter(Family::has_formulas) {
            let p = params_for(family, &[d1, d2]);
            let end = family.info().variable.end(&1.0);
            let at = x * end;
            let lo = family.eval_at(&at, &p, false).unwrap();
            let hi = family.eval_at(&Mpfr::from_f64(256, at), &p, false).unwrap();
            for (a, b) in lo.iter().zip(&hi) {
                prop_assert!((a - b.to_f64()).abs() <= 3.6e-12, "{family:?} {p:?} x={at}: {a} vs {b}");
            }
        }
    }

    /// A rational curve with every weight equal to `w` is the polynomial
    /// curve (Σ w b_i P_i / Σ w b_i = Σ b_i P_i when Σ b_i = 1), and every
    /// curve equals Σ b_i P_i computed directly from the basis values.
    #[test]
    fn curves_agree_with_direct_evaluation(
        x in 0.0..=1.0f64,
        m in -2.0..=1.0f64,
        w in 0.1..10.0f64,
        pts in proptest::collection::vec((-10.0..10.0f64, -10.0..10.0f64), 4),
    ) {
        let p = vec![Rational::from_f64(m).unwrap()];
        let points: Vec<Point2<f64>> = pts.iter().map(|&(a, b)| Point2::new(a, b)).collect();
        let poly = Segment::new(Family::ThesisCubic, p.clone(), points.clone()).unwrap();
        let rat = Segment::rational(Family::ThesisCubic, p.clone(), points.clone(), vec![w; 4]).unwrap();
        let b = Family::ThesisCubic.eval_at(&x, &p, false).unwrap();
        let mut direct = Point2::origin();
        for (bi, pi) in b.iter().zip(&points) {
            direct += pi.coords * *bi;
        }
        // |P| ≤ 15, four terms, Σ|b_i| ≤ 3 for m ∈ [−2,1]: rounding ≤ 1e-13.
        prop_assert!((poly.eval(&x).unwrap() - direct).norm() < 1e-12);
        prop_assert!((rat.eval(&x).unwrap() - direct).norm() < 1e-12);
    }

    /// The matrix form [T][A][V][A]ᵀ[U] (5.4) equals the double sum (5.3);
    /// both are the same bilinear form, so they differ only by rounding
    /// (16 terms of size ≤ 10·3·3: bound 1e-11).
    #[test]
    fn matrix_form_equals_double_sum(
        u in 0.0..=1.0f64,
        v in 0.0..=1.0f64,
        m in -2.0..=1.0f64,
        coords in proptest::collection::vec(-10.0..10.0f64, 48),
    ) {
        let grid: [[Point3<f64>; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let k = 3 * (4 * i + j);
                Point3::new(coords[k], coords[k + 1], coords[k + 2])
            })
        });
        let m_exact = Rational::from_f64(m).unwrap();
        let exact = |x: f64| Rational::from_f64(x).unwrap();
        let net = ControlNet::new(
            grid.iter()
                .map(|row| row.iter().map(|p| [exact(p.x), exact(p.y), exact(p.z)]).collect())
                .collect(),
        ).unwrap();
        let direction = || Direction {
            basis: Family::ThesisCubic,
            params: vec![Affine::rational(m_exact.clone())],
        };
        let surface = TensorSurface::new(direction(), direction(), net).unwrap();
        let [x, y, z] = surface.eval(&u, &v, false).unwrap();
        let sum = Point3::new(x, y, z);
        let matrix = thesis_matrix_form(m, &grid, u, v);
        prop_assert!((sum - matrix).norm() < 1e-11, "{sum} vs {matrix}");
    }
}
