//! Total positivity of a basis by a totally positive factorisation, and its
//! refutation by a collocation matrix with a negative minor.
//!
//! A basis `(b₀, …, b_{n−1})` on an interval is *totally positive* (TP) when
//! every collocation matrix `K = (b_j(x_i))`, `x₀ < x₁ < ⋯ < x_m`, has all
//! minors `≥ 0`; a normalized TP basis (also `Σ bⱼ = 1`) is variation
//! diminishing and gives convexity preserving planar curves (Goodman;
//! Carnicer & Peña).
//!
//! **Certificate.** With `z = tan(θ/2)` (or `z = t`), an increasing change of
//! variable onto `[0, 1]`, every function becomes `bⱼ = σⱼNⱼ(z)/(D(z)·|qⱼ|)`:
//! `D` the common denominator in `z` (powers of `1 + z²` and any factor
//! proved of one strict sign on the domain × parameter set), `qⱼ` a
//! `z`-free factor of one strict sign, `σⱼ = ±1`. Write the numerators in
//! the Bernstein basis of degree `d`: `σⱼNⱼ = Σₖ C_{jk} B^d_k(z)`. The
//! Bernstein basis is TP on `[0, 1]`, and by Cauchy–Binet every minor of a
//! collocation matrix of `(σⱼNⱼ)` is a sum of products of minors of `C` and
//! of Bernstein collocation minors; positive row and column factors (`1/D`,
//! `1/|qⱼ|`) keep signs. So all minors of `C` `≥ 0` proves TP. Elevating the
//! degree (`C ↦ C·E`, `E` TP) can only enlarge the set where it works.
//! With one shape parameter `p`, every minor of `C` is a polynomial in `p`;
//! the set where all are `≥ 0` is decided exactly in [`crate::tp_set`].
//!
//! **Refutation.** A collocation matrix at exact rational points with a
//! negative minor (a `1×1` minor is a negative value).

use rug::Rational;
use trig_symbolic::{Poly, Sym};

use crate::domain::{ParamBox, in_z};
use crate::minors::{MinorOf, TooLarge, all_minors, binomial, elevate_rows, power_to_bernstein};
use crate::neville::Bidiagonal;
use crate::nonneg::{Certificate, definite_sign};
use crate::sturm::UPoly;
use crate::tp_set::{NonnegativeSet, nonnegative_set};

/// Degree elevations tried after the degree of the numerators.
pub const MAX_ELEVATION: usize = 4;

/// Most minor positions `Σₖ C(rows, k)·C(cols, k) = C(rows + cols, rows) − 1`
/// the enumeration of all minors visits (a 10 × 10 matrix has 184 755).
pub const MAX_MINORS: u64 = 1_000_000;

/// Without a parameter, matrices with more minor positions than this are
/// tried by Neville elimination before their minors are enumerated.
pub const PREFER_NEVILLE: u64 = 100_000;

/// Most rows and columns of a matrix whose minors are enumerated (index
/// sets are bit masks of one word).
pub const MAX_SIDE: usize = 31;

/// Why the certificate was not formed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TpError {
    /// The functions are not written over one Bernstein basis (the reason).
    #[error("{0}")]
    Factorisation(String),
    /// The coefficient matrix is too large for the enumeration of its
    /// minors ([`crate::minors::MAX_SIDE`], [`crate::minors::MAX_MINORS`]).
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
}

/// The numerators' Bernstein coefficient matrix `C` (rows: functions,
/// columns: Bernstein index), each entry a polynomial in the parameter
/// (a constant without one).
#[derive(Debug, Clone, PartialEq)]
pub struct Factorisation {
    /// The degree `d` of the Bernstein basis.
    pub degree: usize,
    /// `C_{jk}`, `n × (d + 1)`.
    pub rows: Vec<Vec<UPoly>>,
    /// The positive common factor `D` that was divided out, as text.
    pub common: String,
}

/// One minor of a matrix: its row and column indices and its value.
pub type Minor = MinorOf<UPoly>;

/// The positive common factor `1 + z²` of the Weierstrass substitution.
fn one_plus_z2() -> Poly {
    Poly::var("z") * &Poly::var("z") + &Poly::one()
}

/// How often `1 + z²` divides `f`, and the rest.
fn strip_one_plus_z2(f: &Poly) -> (u32, Poly) {
    let zz = one_plus_z2();
    let (mut k, mut rest) = (0, f.clone());
    while rest.degree_in("z") > 0 {
        match rest.exact_div(&zz) {
            Some(q) => {
                rest = q;
                k += 1;
            }
            None => break,
        }
    }
    (k, rest)
}

/// The strict sign of a denominator factor `g(z, p)` on `[0, 1]` × the
/// parameter set, or why it has none.
fn factor_sign(g: &Poly, params: &[(&str, ParamBox)]) -> Result<i32, String> {
    if let Some(k) = g.as_constant() {
        return Ok(k.cmp0() as i32);
    }
    // in t: the engine maps t ↦ z itself
    let in_t = Sym::from_poly(g.subs("z", &Poly::var("t")));
    definite_sign(&in_t, false, params)
        .map_err(|why| format!("the denominator factor {g} has no fixed sign: {why}"))
}

/// The Bernstein coefficient matrix of degree `deg(numerators)` of the
/// functions `fs` (in `s, c` or `t`, at most the parameter `param`).
pub fn factorise(
    fs: &[Sym],
    trigonometric: bool,
    param: Option<(&str, &ParamBox)>,
) -> Result<Factorisation, String> {
    let params: Vec<(&str, ParamBox)> = param.map(|(n, b)| (n, b.clone())).into_iter().collect();
    let name = param.map(|(n, _)| n);
    let common = numerators(fs, trigonometric, &params)?;
    let rows = common
        .numerators
        .iter()
        .map(|n| bernstein_row(n, common.degree, name))
        .collect::<Result<_, _>>()?;
    Ok(Factorisation {
        degree: common.degree,
        rows,
        common: common.text,
    })
}

/// The numerators of the functions over their positive common factor in
/// `z`, each with the sign that makes the factor positive.
pub(crate) struct Numerators {
    pub numerators: Vec<Poly>,
    /// Their degree in `z`.
    pub degree: usize,
    /// The common factor, as text.
    pub text: String,
}

/// [`Numerators`] of `fs` (in `s, c` or `t` and the `params`).
pub(crate) fn numerators(
    fs: &[Sym],
    trigonometric: bool,
    params: &[(&str, ParamBox)],
) -> Result<Numerators, String> {
    let zs: Vec<Sym> = fs.iter().map(|f| in_z(f, trigonometric)).collect();
    for (j, fz) in zs.iter().enumerate() {
        if let Some(other) = fz
            .variables()
            .into_iter()
            .find(|v| v != "z" && !params.iter().any(|(n, _)| n == v))
        {
            return Err(format!(
                "function {j} depends on `{other}` besides the variable and the parameters"
            ));
        }
    }
    // common denominator in z: max power of 1 + z² and of every z-factor
    let mut zz_power = 0;
    let mut common: Vec<(Poly, u32)> = Vec::new();
    let mut split = Vec::new();
    for fz in &zs {
        let (mut own_zz, mut own_z, mut sign) = (0, Vec::new(), 1);
        for (factor, e) in fz.denominator() {
            let (k, rest) = strip_one_plus_z2(factor);
            own_zz += k * e;
            let s = factor_sign(&rest, params)?;
            if e % 2 == 1 {
                sign *= s;
            }
            if rest.degree_in("z") > 0 {
                own_z.push((rest, *e));
            }
        }
        zz_power = zz_power.max(own_zz);
        for (g, e) in &own_z {
            match common.iter_mut().find(|(h, _)| h == g) {
                Some(entry) => entry.1 = entry.1.max(*e),
                None => common.push((g.clone(), *e)),
            }
        }
        split.push((own_zz, own_z, sign));
    }
    let mut numerators = Vec::new();
    for (fz, (own_zz, own_z, sign)) in zs.iter().zip(&split) {
        let mut n =
            fz.numerator().scale(&Rational::from(*sign)) * &one_plus_z2().pow(zz_power - own_zz);
        for (g, e) in &common {
            let mine = own_z.iter().find(|(h, _)| h == g).map_or(0, |(_, k)| *k);
            n = n * &g.pow(e - mine);
        }
        numerators.push(n);
    }
    let degree = numerators
        .iter()
        .map(|n| n.degree_in("z") as usize)
        .max()
        .unwrap_or(0);
    let mut text: Vec<String> = Vec::new();
    if zz_power > 0 {
        text.push(format!("(1 + z²)^{zz_power}"));
    }
    text.extend(common.iter().map(|(g, e)| format!("|{g}|^{e}")));
    Ok(Numerators {
        numerators,
        degree,
        text: if text.is_empty() {
            "1".into()
        } else {
            text.join(" · ")
        },
    })
}

/// Bernstein coefficients of degree `d` of `n(z, p)`, each a polynomial in
/// `p`: the change of basis is linear, so it is applied to the coefficient
/// sequence of every power of `p`.
fn bernstein_row(n: &Poly, d: usize, param: Option<&str>) -> Result<Vec<UPoly>, String> {
    let by_z = n.coefficients_in("z");
    let in_p = |c: &Poly| -> Result<UPoly, String> {
        match param {
            Some(p) => UPoly::from_poly(c, p),
            None => c.as_constant().map(|q| UPoly::new(vec![q])),
        }
        .ok_or_else(|| format!("a coefficient {c} depends on more than the parameter"))
    };
    let powers: Vec<UPoly> = by_z.iter().map(in_p).collect::<Result<_, _>>()?;
    Ok(power_to_bernstein(&powers, d))
}

impl Factorisation {
    /// One degree elevation ([`elevate_rows`]).
    pub fn elevate(&self) -> Factorisation {
        Factorisation {
            degree: self.degree + 1,
            rows: elevate_rows(&self.rows, self.degree),
            common: self.common.clone(),
        }
    }
}

/// Every nonzero minor of `m` (any order), within the limits of the
/// enumeration ([`crate::minors::all_minors`]).
pub fn minors(m: &[Vec<UPoly>]) -> Result<Vec<Minor>, TpError> {
    Ok(all_minors(m)?)
}

/// A refutation: points `z₀ < ⋯` (or `t`), the functions' indices, and the
/// negative minor of the collocation matrix there.
#[derive(Debug, Clone, PartialEq)]
pub struct NegativeMinor {
    pub points: Vec<Rational>,
    pub functions: Vec<usize>,
    /// The collocation submatrix, rows the points, columns the functions.
    pub values: Vec<Vec<Rational>>,
    pub minor: Rational,
}

/// Grids `{k/g}` tried for a negative collocation minor (fewer points for
/// more functions: the number of minors grows as `C(points + n, n)`).
fn grids(functions: usize) -> &'static [u32] {
    if functions <= 4 { &[4, 8, 16] } else { &[4, 8] }
}

/// Searches a collocation matrix of `fzs` (functions of `z` only, exact)
/// at rational grid points of `[0, 1]` (and at `extra` points) for a
/// negative minor; the minor is re-evaluated as a determinant.
pub fn negative_collocation_minor(fzs: &[Sym], extra: &[Rational]) -> Option<NegativeMinor> {
    let value = |f: &Sym, z: &Rational| -> Option<Rational> {
        f.eval_rational(&|n: &str| (n == "z").then(|| z.clone()))
            .ok()
    };
    for &g in grids(fzs.len()) {
        let mut points: Vec<Rational> = (0..=g).map(|k| Rational::from((k, g))).collect();
        points.extend(extra.iter().cloned());
        points.sort();
        points.dedup();
        let table: Option<Vec<Vec<UPoly>>> = points
            .iter()
            .map(|z| {
                fzs.iter()
                    .map(|f| value(f, z).map(|v| UPoly::new(vec![v])))
                    .collect()
            })
            .collect();
        let table = table?;
        // a grid too large for the enumeration is not searched
        let Ok(all) = minors(&table) else {
            continue;
        };
        let Some(negative) = all
            .into_iter()
            .filter(|m| m.value.leading() < 0)
            .min_by_key(|m| m.rows.len())
        else {
            continue;
        };
        let values: Vec<Vec<Rational>> = negative
            .rows
            .iter()
            .map(|&i| {
                negative
                    .cols
                    .iter()
                    .map(|&j| table[i][j].leading())
                    .collect()
            })
            .collect();
        let minor = determinant(&values);
        if minor < 0 {
            return Some(NegativeMinor {
                points: negative.rows.iter().map(|&i| points[i].clone()).collect(),
                functions: negative.cols,
                values,
                minor,
            });
        }
    }
    None
}

/// The determinant of a square rational matrix (exact elimination).
pub fn determinant(a: &[Vec<Rational>]) -> Rational {
    let mut m = a.to_vec();
    let n = m.len();
    let mut det = Rational::from(1);
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| m[r][col] != 0) else {
            return Rational::new();
        };
        if pivot != col {
            m.swap(pivot, col);
            det = -det;
        }
        det *= &m[col][col];
        let (top, below) = m.split_at_mut(col + 1);
        let pivot_row = &top[col];
        for row in below {
            let f = Rational::from(&row[col] / &pivot_row[col]);
            for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                *x -= Rational::from(&f * p);
            }
        }
    }
    det
}

/// The certificate: the coefficient matrix at the degree where it went
/// furthest, its nonzero minors, and the parameter set where all are `≥ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct TpCertificate {
    /// The degree of the numerators (before elevation).
    pub first_degree: usize,
    pub factorisation: Factorisation,
    /// The number of nonzero minors checked at the final degree.
    pub minors: usize,
    /// Inside the given parameter set (the whole line without a parameter).
    pub set: NonnegativeSet,
    /// Without a parameter, beyond the enumeration of minors: the
    /// bidiagonal factorisation (Neville elimination, every factor `≥ 0`)
    /// that proved the matrix totally positive instead ([`crate::neville`]).
    pub neville: Option<Bidiagonal>,
}

impl TpCertificate {
    /// The parameter values of `bx` where every minor of this certificate
    /// (at its degree, no further elevation) is `≥ 0`.
    pub fn set_within(&self, bx: &ParamBox) -> Result<NonnegativeSet, TpError> {
        let values: Vec<UPoly> = minors(&self.factorisation.rows)?
            .into_iter()
            .map(|m| m.value)
            .collect();
        Ok(nonnegative_set(&values, bx))
    }
}

/// The certificate of [`factorise`] with up to [`MAX_ELEVATION`] degree
/// elevations, stopping as soon as all minors are `≥ 0` on the whole set
/// (or when an elevation would pass the limits of the enumeration: the
/// last degree within them is kept).
pub fn certify(
    fs: &[Sym],
    trigonometric: bool,
    param: Option<(&str, &ParamBox)>,
) -> Result<TpCertificate, TpError> {
    let whole = ParamBox {
        lo: crate::domain::Bound::Infinite,
        hi: crate::domain::Bound::Infinite,
    };
    let bx = param.map_or(&whole, |(_, b)| b);
    let mut f = factorise(fs, trigonometric, param).map_err(TpError::Factorisation)?;
    let first_degree = f.degree;
    let mut last: Option<TpCertificate> = None;
    loop {
        // without a parameter, a large matrix is tried by Neville
        // elimination first (milliseconds where the minors take seconds)
        let rows = f.rows.len();
        let positions = binomial(rows + f.degree + 1, rows);
        if param.is_none()
            && positions.is_none_or(|p| p > PREFER_NEVILLE)
            && let Some(cert) = by_neville(f.clone(), first_degree, bx)
        {
            return Ok(cert);
        }
        let ms = match minors(&f.rows) {
            Ok(ms) => ms,
            Err(too_large) if param.is_none() => {
                return by_neville(f, first_degree, bx).or(last).ok_or(too_large);
            }
            Err(too_large) => return last.ok_or(too_large),
        };
        let values: Vec<UPoly> = ms.iter().map(|m| m.value.clone()).collect();
        let set = nonnegative_set(&values, bx);
        let done = set.covers || f.degree >= first_degree + MAX_ELEVATION;
        let cert = TpCertificate {
            first_degree,
            factorisation: f,
            minors: ms.len(),
            set,
            neville: None,
        };
        if done {
            return Ok(cert);
        }
        f = cert.factorisation.elevate();
        last = Some(cert);
    }
}

/// Without a parameter: the bidiagonal factorisation of the coefficient
/// matrix at its degree or one of the next elevations up to
/// [`MAX_ELEVATION`] in all, when one has every factor `≥ 0`.
fn by_neville(mut f: Factorisation, first_degree: usize, bx: &ParamBox) -> Option<TpCertificate> {
    loop {
        let rational: Option<Vec<Vec<Rational>>> = f
            .rows
            .iter()
            .map(|row| {
                row.iter()
                    .map(|u| match u.coeffs() {
                        [] => Some(Rational::new()),
                        [a] => Some(a.clone()),
                        _ => None,
                    })
                    .collect()
            })
            .collect();
        if let Some(b) = crate::neville::totally_positive(&rational?) {
            return Some(TpCertificate {
                first_degree,
                factorisation: f,
                minors: 0,
                set: nonnegative_set(&[], bx),
                neville: Some(b),
            });
        }
        if f.degree >= first_degree + MAX_ELEVATION {
            return None;
        }
        f = f.elevate();
    }
}

/// A negative collocation minor of `fs` at the parameter values `at`
/// (`(name, value)` for every parameter; none without parameters): first a
/// negative value (a `1×1` minor) found by the nonnegativity certifier,
/// then grids of rational points.
pub fn refute(fs: &[Sym], trigonometric: bool, at: &[(&str, &Rational)]) -> Option<NegativeMinor> {
    let fixed: Vec<Sym> = fs
        .iter()
        .map(|f| {
            at.iter().fold(f.clone(), |g, (name, p)| {
                g.subs(name, &Sym::rational((*p).clone()))
            })
        })
        .collect();
    let mut extra = Vec::new();
    for f in &fixed {
        if let Certificate::Counterexample { z, .. } =
            crate::nonneg::certify(f, trigonometric, None, &ParamBox::point(Rational::new()))
        {
            extra.push(z);
        }
    }
    let fzs: Vec<Sym> = fixed.iter().map(|f| in_z(f, trigonometric)).collect();
    negative_collocation_minor(&fzs, &extra)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::q;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    /// Han (2002) quadratic: (1 − s)(1 − λs), (1 + λ)(s + c − 1), (1 − c)(1 − λc).
    fn han() -> Vec<Sym> {
        let (s, c, l, one) = (v("s"), v("c"), v("lambda"), Sym::one());
        vec![
            (one.clone() - &s) * &(one.clone() - &(l.clone() * &s)),
            (one.clone() + &l) * &(s.clone() + &c - &one),
            (one.clone() - &c) * &(one - &(l * &c)),
        ]
    }

    /// The squares of Han's end functions, `b1 = 1 − b0 − b2`.
    fn squares_han() -> Vec<Sym> {
        let h = han();
        let (b0, b2) = (h[0].clone() * &h[0], h[2].clone() * &h[2]);
        vec![b0.clone(), Sym::one() - &b0 - &b2, b2]
    }

    fn tp_set(fs: &[Sym], trig: bool, bx: &ParamBox) -> TpCertificate {
        certify(fs, trig, Some(("lambda", bx))).unwrap()
    }

    #[test]
    fn han_quadratic_is_certified_exactly_on_its_range() {
        let cert = tp_set(&han(), true, &ParamBox::closed(q(-3, 1), q(3, 1)));
        assert_eq!(cert.first_degree, 4);
        assert_eq!(cert.set.describe("λ"), "[-1, 1]");
        let inside = tp_set(&han(), true, &ParamBox::closed(q(-1, 1), q(1, 1)));
        assert!(inside.set.covers);
    }

    #[test]
    fn squares_han_is_certified_only_on_minus_one_to_one() {
        let cert = tp_set(&squares_han(), true, &ParamBox::closed(q(-1, 1), q(5, 1)));
        assert!(!cert.set.covers);
        assert_eq!(cert.first_degree, 8);
        assert_eq!(cert.set.describe("λ"), "[-1, 1]");
        // nonnegative at 5/4, yet a collocation minor is negative
        let neg = refute(&squares_han(), true, &[("lambda", &q(5, 4))]).unwrap();
        assert!(neg.minor < 0);
        assert_eq!(determinant(&neg.values), neg.minor);
        assert!(neg.points.windows(2).all(|w| w[0] < w[1]));
        // and none inside the certified set
        assert!(refute(&squares_han(), true, &[("lambda", &q(1, 2))]).is_none());
    }

    #[test]
    fn degree_elevation_closes_the_gap_of_the_irrational_end_basis() {
        // k = (λ² − 4λ)/4, u = t(1 − t):
        // (1 − t)²(1 − k t²), 2u(1 + k u), t²(1 − k(1 − t)²)
        let (t, l, one) = (v("t"), v("lambda"), Sym::one());
        let k = (l.clone() * &l - &(Sym::int(4) * &l)) / &Sym::int(4);
        let u = t.clone() * &(one.clone() - &t);
        let fs = vec![
            (one.clone() - &t) * &(one.clone() - &t) * &(one.clone() - &(k.clone() * &t * &t)),
            Sym::int(2) * &u * &(one.clone() + &(k.clone() * &u)),
            t.clone() * &t * &(one.clone() - &(k * &(one.clone() - &t) * &(one - &t))),
        ];
        let bx = ParamBox::closed(q(-4, 5), q(24, 5));
        let at_four = minors(&factorise(&fs, false, Some(("lambda", &bx))).unwrap().rows).unwrap();
        let values: Vec<UPoly> = at_four.iter().map(|m| m.value.clone()).collect();
        let set4 = nonnegative_set(&values, &bx);
        assert_eq!(set4.pieces.len(), 2, "{}", set4.describe("λ"));
        let cert = tp_set(&fs, false, &bx);
        assert_eq!((cert.first_degree, cert.factorisation.degree), (4, 5));
        assert!(cert.set.covers);
    }

    #[test]
    fn minors_agree_with_determinants() {
        let m: Vec<Vec<Rational>> = vec![
            vec![q(1, 1), q(2, 1), q(0, 1)],
            vec![q(3, 1), q(1, 2), q(5, 1)],
            vec![q(-1, 1), q(4, 1), q(2, 3)],
        ];
        let as_poly: Vec<Vec<UPoly>> = m
            .iter()
            .map(|r| r.iter().map(|x| UPoly::new(vec![x.clone()])).collect())
            .collect();
        for minor in minors(&as_poly).unwrap() {
            let sub: Vec<Vec<Rational>> = minor
                .rows
                .iter()
                .map(|&i| minor.cols.iter().map(|&j| m[i][j].clone()).collect())
                .collect();
            assert_eq!(minor.value.leading(), determinant(&sub));
        }
    }

    #[test]
    fn beyond_the_enumeration_a_typed_error_or_neville_elimination() {
        let row = |n: usize| vec![UPoly::new(vec![q(1, 1)]); n];
        let wide: Vec<Vec<UPoly>> = (0..3).map(|_| row(41)).collect();
        let err = minors(&wide).unwrap_err();
        assert!(matches!(
            err,
            TpError::TooLarge(TooLarge {
                rows: 3,
                cols: 41,
                ..
            })
        ));
        assert!(
            err.to_string().contains("at most 31 rows and columns"),
            "{err}"
        );
        let square: Vec<Vec<UPoly>> = (0..12).map(|_| row(12)).collect();
        assert!(matches!(
            minors(&square),
            Err(TpError::TooLarge(TooLarge {
                minors: Some(2_704_155),
                ..
            }))
        ));
        // the squared-sine Bernstein basis of degree 10: 11 functions of
        // degree 40 in z
        let (s, c) = (v("s"), v("c"));
        let fs: Vec<Sym> = (0..=10u32)
            .map(|i| {
                (0..2 * i).fold(Sym::one(), |acc, _| acc * &s)
                    * &(0..2 * (10 - i)).fold(Sym::one(), |acc, _| acc * &c)
            })
            .collect();
        // its matrix (11 × 41) is beyond the enumeration, and Neville
        // elimination proves it totally positive
        let cert = certify(&fs, true, None).unwrap();
        assert_eq!(cert.factorisation.rows.len(), 11);
        assert!(cert.set.covers && cert.minors == 0);
        assert_eq!(cert.neville.map(|b| b.pivots), Some(11));
        // with a parameter the enumeration's limit is the answer
        let mut with_parameter = fs.clone();
        with_parameter[0] = with_parameter[0].clone() * &(Sym::one() + &v("lambda"));
        let bx = ParamBox::closed(q(0, 1), q(1, 1));
        assert!(matches!(
            certify(&with_parameter, true, Some(("lambda", &bx))),
            Err(TpError::TooLarge(TooLarge {
                rows: 11,
                cols: 41,
                ..
            }))
        ));
    }
}
