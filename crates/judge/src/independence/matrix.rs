//! The coefficient matrix of a basis in the independent monomials of the
//! exact ring, and its rank by fraction-free (Bareiss) elimination.
//!
//! Over one common denominator (the factors in the variable's atoms, a
//! nonzero function, so independence is unchanged) every numerator is a
//! polynomial in `t`, `c`, `s` with `s`-degree ≤ 1 (the normal form). The
//! monomials `tᵃcᵇsᵉ`, `e ≤ 1`, are linearly independent functions, so the
//! functions are independent exactly when the matrix of their numerators'
//! coefficients has full row rank. A factor of a function's denominator
//! free of the variable scales its row only (nonzero wherever the function
//! is defined) and is kept aside.
//!
//! Bareiss elimination runs in the integral domain of the entries (the
//! polynomials in the parameters and their atoms, or the integers):
//! every division is exact, the last pivot is a maximal minor, and the
//! identity matrix carried beside records, for every row that becomes
//! zero, a dependence relation with coefficients in the same domain.

use std::collections::BTreeMap;

use rug::{Integer, Rational};
use trig_symbolic::{Poly, Sym};

use super::VARIABLE_ATOMS;

/// Why the elimination could not finish (never expected: Bareiss's
/// divisions are exact in an integral domain).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InexactDivision;

/// A monomial `tᵃcᵇsᵉ` of the variable's atoms: `(a, b, e)`.
pub type Column = (u32, u32, u32);

/// The coefficient matrix of the functions' numerators over their common
/// denominator in the variable's atoms.
#[derive(Debug, Clone)]
pub struct Coefficients {
    /// One row per function, one column per monomial (`columns`).
    pub rows: Vec<Vec<Poly>>,
    /// The monomials, in increasing order.
    pub columns: Vec<Column>,
    /// Each function's denominator factors free of the variable, multiplied
    /// out: row `j` holds the coefficients of `bⱼ·L·scales[j]`.
    pub scales: Vec<Poly>,
}

impl Coefficients {
    /// The rows with the parameter `name` set to `a` (a face or slab of the
    /// parameter box).
    pub fn rows_with(&self, name: &str, a: &rug::Rational) -> Vec<Vec<Poly>> {
        let value = Poly::constant(a.clone());
        self.rows
            .iter()
            .map(|row| row.iter().map(|e| e.subs(name, &value)).collect())
            .collect()
    }
}

fn in_variable(p: &Poly) -> bool {
    p.variables()
        .iter()
        .any(|v| VARIABLE_ATOMS.contains(&v.as_str()))
}

/// The coefficient matrix of `fs` (see the module documentation).
pub fn coefficients(fs: &[Sym]) -> Coefficients {
    let mut common: BTreeMap<Poly, u32> = BTreeMap::new();
    for f in fs {
        for (g, e) in f.denominator() {
            if in_variable(g) {
                let k = common.entry(g.clone()).or_insert(0);
                *k = (*k).max(*e);
            }
        }
    }
    let mut maps = Vec::with_capacity(fs.len());
    let mut scales = Vec::with_capacity(fs.len());
    for f in fs {
        let own = f.denominator();
        let mut num = f.numerator().clone();
        for (g, e) in &common {
            let k = own.get(g).copied().unwrap_or(0);
            if *e > k {
                num = num * &g.pow(e - k);
            }
        }
        scales.push(
            own.iter()
                .filter(|(g, _)| !in_variable(g))
                .fold(Poly::one(), |acc, (g, e)| acc * &g.pow(*e)),
        );
        let mut row: BTreeMap<Column, Poly> = BTreeMap::new();
        for (m, q) in num.terms() {
            let (rest, a) = m.split("t");
            let (rest, b) = rest.split("c");
            let (rest, e) = rest.split("s");
            let entry = row.entry((a, b, e)).or_default();
            *entry = std::mem::take(entry) + &Poly::term(rest, q.to_rational());
        }
        maps.push(row);
    }
    let mut columns: Vec<Column> = maps.iter().flat_map(|r| r.keys().copied()).collect();
    columns.sort_unstable();
    columns.dedup();
    let rows = maps
        .iter()
        .map(|r| {
            columns
                .iter()
                .map(|k| r.get(k).cloned().unwrap_or_default())
                .collect()
        })
        .collect();
    Coefficients {
        rows,
        columns,
        scales,
    }
}

/// The monomial `tᵃcᵇsᵉ` as printed.
pub fn column_text((a, b, e): Column) -> String {
    let mut parts = Vec::new();
    for (name, k) in [("t", a), ("c", b), ("s", e)] {
        match k {
            0 => {}
            1 => parts.push(name.to_string()),
            k => parts.push(format!("{name}^{k}")),
        }
    }
    if parts.is_empty() {
        "1".into()
    } else {
        parts.join("·")
    }
}

/// An entry of an integral domain in which Bareiss elimination runs.
pub trait Entry: Clone {
    fn zero() -> Self;
    fn one() -> Self;
    fn is_zero(&self) -> bool;
    /// Size, for choosing small pivots.
    fn weight(&self) -> usize;
    /// `a·b − c·d`.
    fn cross(a: &Self, b: &Self, c: &Self, d: &Self) -> Self;
    /// `self / d` when exact.
    fn div_exact(&self, d: &Self) -> Option<Self>;
}

impl Entry for Poly {
    fn zero() -> Self {
        Poly::zero()
    }
    fn one() -> Self {
        Poly::one()
    }
    fn is_zero(&self) -> bool {
        Poly::is_zero(self)
    }
    fn weight(&self) -> usize {
        self.len()
    }
    fn cross(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        if c.is_zero() || d.is_zero() {
            return a * b;
        }
        a * b - &(c * d)
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        if let Some(q) = d.as_constant() {
            return (q != 0).then(|| self.scale(&q.recip()));
        }
        self.exact_div(d)
    }
}

impl Entry for Integer {
    fn zero() -> Self {
        Integer::new()
    }
    fn one() -> Self {
        Integer::from(1)
    }
    fn is_zero(&self) -> bool {
        self.cmp0() == std::cmp::Ordering::Equal
    }
    fn weight(&self) -> usize {
        self.significant_bits() as usize
    }
    fn cross(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        Integer::from(a * b) - Integer::from(c * d)
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        if d.is_zero() || !self.is_divisible(d) {
            return None;
        }
        Some(Integer::from(self.div_exact_ref(d)))
    }
}

/// The result of the elimination.
#[derive(Debug, Clone)]
pub struct Echelon<E> {
    pub rank: usize,
    /// The pivot columns, in order.
    pub pivots: Vec<usize>,
    /// The last pivot: up to sign, the minor on the pivot rows and columns
    /// (`1` for rank 0).
    pub minor: E,
    /// Left kernel vectors `k` (`Σ kⱼ·rowⱼ = 0`), one per row beyond the
    /// rank, indexed by the original rows.
    pub relations: Vec<Vec<E>>,
}

/// Bareiss elimination of `rows` with the identity carried beside.
pub fn echelon<E: Entry>(rows: &[Vec<E>]) -> Result<Echelon<E>, InexactDivision> {
    let n = rows.len();
    let m = rows.first().map_or(0, Vec::len);
    let width = m + n;
    let mut a: Vec<Vec<E>> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut v = r.clone();
            v.extend((0..n).map(|j| if i == j { E::one() } else { E::zero() }));
            v
        })
        .collect();
    let (mut prev, mut r, mut pivots) = (E::one(), 0, Vec::new());
    for col in 0..m {
        if r == n {
            break;
        }
        let Some(p) = (r..n)
            .filter(|&i| !a[i][col].is_zero())
            .min_by_key(|&i| a[i][col].weight())
        else {
            continue;
        };
        a.swap(r, p);
        let (top, below) = a.split_at_mut(r + 1);
        let pivot_row = &top[r];
        for row in below.iter_mut() {
            for j in col + 1..width {
                if pivot_row[j].is_zero() && row[j].is_zero() {
                    continue;
                }
                let v = E::cross(&pivot_row[col], &row[j], &row[col], &pivot_row[j]);
                row[j] = v.div_exact(&prev).ok_or(InexactDivision)?;
            }
            row[col] = E::zero();
        }
        prev = top[r][col].clone();
        pivots.push(col);
        r += 1;
    }
    let relations = a[r..].iter().map(|row| row[m..].to_vec()).collect();
    Ok(Echelon {
        rank: r,
        pivots,
        minor: prev,
        relations,
    })
}

/// The elimination of a matrix of polynomials: over the integers when
/// every entry is a rational constant (each row scaled to integers; the
/// relations scaled back), over the polynomials otherwise.
pub fn echelon_poly(rows: &[Vec<Poly>]) -> Result<Echelon<Poly>, InexactDivision> {
    let constants: Option<Vec<Vec<Rational>>> = rows
        .iter()
        .map(|r| r.iter().map(Poly::as_constant).collect())
        .collect();
    let Some(constants) = constants else {
        return echelon(rows);
    };
    // row j times its denominators' lcm d_j: a relation k of the scaled
    // rows is the relation (k_j·d_j) of the original ones
    let scales: Vec<Integer> = constants
        .iter()
        .map(|r| r.iter().fold(Integer::from(1), |acc, q| acc.lcm(q.denom())))
        .collect();
    let ints: Vec<Vec<Integer>> = constants
        .iter()
        .zip(&scales)
        .map(|(r, d)| {
            r.iter()
                .map(|q| q.numer() * Integer::from(d / q.denom()))
                .collect()
        })
        .collect();
    let e = echelon(&ints)?;
    let to_poly = |x: &Integer| Poly::constant(Rational::from(x.clone()));
    Ok(Echelon {
        rank: e.rank,
        pivots: e.pivots,
        minor: to_poly(&e.minor),
        relations: e
            .relations
            .iter()
            .map(|k| {
                k.iter()
                    .zip(&scales)
                    .map(|(x, d)| to_poly(&Integer::from(x * d)))
                    .collect()
            })
            .collect(),
    })
}

/// `det` of the square submatrix of `rows` on `cols` (zero when singular),
/// up to sign.
pub fn minor_on(rows: &[Vec<Poly>], cols: &[usize]) -> Result<Poly, InexactDivision> {
    let sub: Vec<Vec<Poly>> = rows
        .iter()
        .map(|r| cols.iter().map(|&j| r[j].clone()).collect())
        .collect();
    let e = echelon_poly(&sub)?;
    Ok(if e.rank == rows.len() {
        e.minor
    } else {
        Poly::zero()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Poly {
        Poly::int(n)
    }

    #[test]
    fn rank_relations_and_minor_of_a_rational_matrix() {
        // row2 = row0 + 2·row1
        let rows = vec![
            vec![q(1), q(2), q(3)],
            vec![q(0), q(1), q(4)],
            vec![q(1), q(4), q(11)],
        ];
        let e = echelon_poly(&rows).unwrap();
        assert_eq!(e.rank, 2);
        let k = &e.relations[0];
        for j in 0..3 {
            let sum = k
                .iter()
                .zip(&rows)
                .fold(Poly::zero(), |acc, (x, row)| acc + &(x * &row[j]));
            assert!(sum.is_zero());
        }
        assert!(k.iter().any(|x| !x.is_zero()));
        let full = vec![vec![q(2), q(1)], vec![q(1), q(3)]];
        let f = echelon_poly(&full).unwrap();
        // up to sign (the pivot rows were exchanged)
        let minor = f.minor.as_constant().map(Rational::abs);
        assert_eq!((f.rank, minor), (2, Some(Rational::from(5))));
    }

    #[test]
    fn a_parameter_matrix_drops_rank_where_its_minor_vanishes() {
        // [[1, l], [l, 1]]: det 1 − l²
        let l = Poly::var("l");
        let rows = vec![vec![q(1), l.clone()], vec![l.clone(), q(1)]];
        let e = echelon_poly(&rows).unwrap();
        assert_eq!(e.rank, 2);
        let det = e.minor.clone();
        assert!((det.clone() * &det - &(q(1) - &(&l * &l)).pow(2)).is_zero());
        assert_eq!(minor_on(&rows, &[0, 1]).unwrap(), det);
    }

    #[test]
    fn numerators_are_read_over_one_denominator() {
        let (t, one) = (Sym::var("t"), Sym::one());
        let d = one.clone() + &t;
        let fs = vec![
            one.clone() / &d,
            t.clone() / &d,
            Sym::var("m") / &Sym::var("k"),
        ];
        let c = coefficients(&fs);
        assert_eq!(c.columns, vec![(0, 0, 0), (1, 0, 0)]);
        assert_eq!(c.scales[2], Poly::var("k"));
        // the third function times (1 + t): m·(1 + t)
        assert_eq!(c.rows[2], vec![Poly::var("m"), Poly::var("m")]);
        assert_eq!(column_text((2, 1, 1)), "t^2·c·s");
    }
}
