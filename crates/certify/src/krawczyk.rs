//! Certified zeros of one or two exact functions of the box coordinates:
//! the Krawczyk operator (R. Krawczyk, "Newton-Algorithmen zur Bestimmung
//! von Nullstellen mit Fehlerschranken", Computing 4 (1969); R. E. Moore,
//! "A test for existence of solutions to nonlinear systems", SIAM J.
//! Numer. Anal. 14 (1977)), which for one unknown is the interval Newton
//! step.
//!
//! For `G(X) = 0` on a box `X` with midpoint `m`, any real matrix `Y` and
//! the interval Jacobian `J(X)`,
//!
//! `K(X) = m − Y·G(m) + (I − Y·J(X))·(X − m)`;
//!
//! if `K(X)` lies in the interior of `X`, then `G` has exactly one zero in
//! `X`, and it lies in `K(X)` (Moore, loc. cit.; Rump's refinement for
//! uniqueness). `Y` is an approximate inverse of `J(m)` with exact
//! rational entries, `G(m)` and `J(X)` are enclosures ([`Coordinates`]),
//! and all arithmetic is MPFR intervals with outward rounding. Iterating
//! `X ← X ∩ K(X)` shrinks the enclosure.
//!
//! The unknowns are some of the box coordinates (`τ` and a parameter, or
//! the parameter alone with `τ` fixed); along a π axis the coordinate is
//! `y` with `p = π·y`, so its derivatives are scaled by π.

use rug::float::Round;
use rug::{Float, Rational};
use trig_core::{Interval, Ring};

use crate::coordinates::{BoxFunction, Coordinates};

const PREC: u32 = 128;

/// A box of the coordinates (`τ`, then the parameters).
pub type Cell = Vec<(Rational, Rational)>;

fn interval(lo: &Rational, hi: &Rational) -> Interval {
    Interval::from_ends(
        PREC,
        &Float::with_val_round(PREC, lo, Round::Down).0,
        &Float::with_val_round(PREC, hi, Round::Up).0,
    )
}

fn rational(x: &Float) -> Option<Rational> {
    x.to_rational()
}

/// The system: functions `g`, their derivatives `jacobian[i][j]` along the
/// unknown coordinates `unknowns[j]`.
#[derive(Debug)]
pub struct System<'c, 'a> {
    coords: &'c Coordinates<'a>,
    unknowns: Vec<usize>,
    g: Vec<BoxFunction>,
    jacobian: Vec<Vec<BoxFunction>>,
}

impl<'c, 'a> System<'c, 'a> {
    /// `g = 0` in the unknown coordinates `unknowns` (as many as functions).
    pub fn new(coords: &'c Coordinates<'a>, g: Vec<BoxFunction>, unknowns: Vec<usize>) -> Self {
        let jacobian = g
            .iter()
            .map(|gi| unknowns.iter().map(|&k| coords.derivative(gi, k)).collect())
            .collect();
        System {
            coords,
            unknowns,
            g,
            jacobian,
        }
    }

    /// The factor of a derivative along coordinate `k` (π on a π axis).
    fn scale(&self, k: usize, like: &Interval) -> Interval {
        if k > 0 && self.coords.axes[k - 1].pi {
            like.pi()
        } else {
            like.int(1)
        }
    }

    fn values(&self, cell: &Cell) -> Option<Vec<Interval>> {
        self.g
            .iter()
            .map(|g| self.coords.enclose(g, cell))
            .collect()
    }

    fn jacobian_on(&self, cell: &Cell) -> Option<Vec<Vec<Interval>>> {
        self.jacobian
            .iter()
            .map(|row| {
                row.iter()
                    .zip(&self.unknowns)
                    .map(|(d, &k)| {
                        let v = self.coords.enclose(d, cell)?;
                        let s = self.scale(k, &v);
                        Some(v * &s)
                    })
                    .collect()
            })
            .collect()
    }

    /// Approximate Newton steps from `start` (not certified: a guess for
    /// [`System::verify`]); `None` when a step fails or leaves `within`.
    pub fn guess(&self, start: &Cell, within: &Cell, steps: usize) -> Option<Cell> {
        let mut x = start.clone();
        for _ in 0..steps {
            let point: Cell = x.iter().map(|(l, _)| (l.clone(), l.clone())).collect();
            let g = self.values(&point)?;
            let j = self.jacobian_on(&point)?;
            let mid = |i: &Interval| i.to_f64_mid();
            let gm: Vec<Float> = g.iter().map(mid).collect();
            let jm: Vec<Vec<Float>> = j.iter().map(|r| r.iter().map(mid).collect()).collect();
            let delta = solve(&jm, &gm)?;
            for (d, &k) in delta.iter().zip(&self.unknowns) {
                let step = rational(d)?;
                let next = Rational::from(&x[k].0 - &step);
                if next < within[k].0 || next > within[k].1 {
                    return None;
                }
                x[k] = (next.clone(), next);
            }
        }
        Some(x)
    }

    /// The Krawczyk test on `cell`: `Some(K ∩ cell)` when `K(cell)` lies in
    /// the interior of `cell` along every unknown (exactly one zero there,
    /// inside the returned box), `None` otherwise.
    pub fn verify(&self, cell: &Cell) -> Option<Cell> {
        let n = self.unknowns.len();
        let m: Cell = cell
            .iter()
            .map(|(l, h)| {
                let c = Rational::from(l + h) / 2u32;
                (c.clone(), c)
            })
            .collect();
        let gm = self.values(&m)?;
        let jm = self.jacobian_on(&m)?;
        let jx = self.jacobian_on(cell)?;
        let mid: Vec<Vec<Float>> = jm
            .iter()
            .map(|r| r.iter().map(Interval::to_f64_mid).collect())
            .collect();
        let y = inverse(&mid)?;
        let yq: Vec<Vec<Interval>> = y
            .iter()
            .map(|r| {
                r.iter()
                    .map(|v| {
                        let q = rational(v).unwrap_or_default();
                        interval(&q, &q)
                    })
                    .collect()
            })
            .collect();
        let like = interval(&Rational::new(), &Rational::new());
        let mut out = cell.clone();
        for i in 0..n {
            // m_i − (Y G(m))_i + Σ_j (δ_ij − (Y J)_ij)(X_j − m_j)
            let mut k = interval(&m[self.unknowns[i]].0, &m[self.unknowns[i]].0);
            for (l, g) in gm.iter().enumerate() {
                k = k - &(yq[i][l].clone() * g);
            }
            for j in 0..n {
                let mut yj = like.int(if i == j { 1 } else { 0 });
                for (l, row) in jx.iter().enumerate() {
                    yj = yj - &(yq[i][l].clone() * &row[j]);
                }
                let c = &self.unknowns[j];
                let dx = interval(
                    &Rational::from(&cell[*c].0 - &m[*c].0),
                    &Rational::from(&cell[*c].1 - &m[*c].0),
                );
                k = k + &(yj * &dx);
            }
            if !trig_core::Real::is_finite(&k) {
                return None;
            }
            let (lo, hi) = (rational(k.lo())?, rational(k.hi())?);
            let side = &cell[self.unknowns[i]];
            if !(lo > side.0 && hi < side.1) {
                return None;
            }
            out[self.unknowns[i]] = (lo, hi);
        }
        Some(out)
    }

    /// [`System::verify`], then contracted up to `rounds` times
    /// (`X ← X ∩ K(X)`, each step verified again): the box with the unique
    /// zero, rational ends.
    pub fn certify(&self, cell: &Cell, rounds: usize) -> Option<Cell> {
        let mut x = self.verify(cell)?;
        for _ in 0..rounds {
            match self.verify(&x) {
                Some(next) if next != x => x = next,
                _ => break,
            }
        }
        Some(x)
    }
}

trait Mid {
    fn to_f64_mid(&self) -> Float;
}

impl Mid for Interval {
    /// The midpoint (rounded), at the interval's precision.
    fn to_f64_mid(&self) -> Float {
        Float::with_val(self.prec(), self.lo() + self.hi()) / 2u32
    }
}

/// `J⁻¹·g` for a 1×1 or 2×2 matrix (floating point), `None` if singular.
fn solve(j: &[Vec<Float>], g: &[Float]) -> Option<Vec<Float>> {
    let inv = inverse(j)?;
    Some(
        inv.iter()
            .map(|row| {
                row.iter().zip(g).fold(Float::new(PREC), |acc, (a, b)| {
                    acc + Float::with_val(PREC, a * b)
                })
            })
            .collect(),
    )
}

/// The inverse of a 1×1 or 2×2 matrix (floating point), `None` if singular.
fn inverse(j: &[Vec<Float>]) -> Option<Vec<Vec<Float>>> {
    match j.len() {
        1 => {
            if j[0][0].is_zero() || !j[0][0].is_finite() {
                return None;
            }
            Some(vec![vec![Float::with_val(PREC, 1) / &j[0][0]]])
        }
        2 => {
            let det = Float::with_val(PREC, &j[0][0] * &j[1][1])
                - Float::with_val(PREC, &j[0][1] * &j[1][0]);
            if det.is_zero() || !det.is_finite() {
                return None;
            }
            Some(vec![
                vec![
                    Float::with_val(PREC, &j[1][1] / &det),
                    Float::with_val(PREC, -&j[0][1]) / &det,
                ],
                vec![
                    Float::with_val(PREC, -&j[1][0]) / &det,
                    Float::with_val(PREC, &j[0][0] / &det),
                ],
            ])
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coordinates::Axis;
    use crate::testing::{q, zero_to_pi};

    use trig_symbolic::Sym;

    #[test]
    fn tangency_of_one_minus_lambda_t_sin_t() {
        // 1 − λ t sin t touches 0 where tan t = −t, λ = 1/(t sin t):
        // t* = 2.028757838110434…, λ* = 0.549539…
        let d = zero_to_pi();
        let axes = vec![Axis {
            lo: q(1, 2),
            hi: q(3, 5),
            lo_open: false,
            hi_open: false,
            pi: false,
        }];
        let c = Coordinates::new(&d, &axes);
        let h = Sym::one() - &(Sym::var("lambda") * &Sym::var("t") * &Sym::var("s"));
        let hf = c.function(&h);
        let ht = c.derivative(&hf, 0);
        let sys = System::new(&c, vec![hf, ht], vec![0, 1]);
        // τ = t/π ≈ 0.6458, λ ≈ 0.5495
        let start: Cell = vec![(q(65, 100), q(65, 100)), (q(55, 100), q(55, 100))];
        let within: Cell = vec![(q(1, 2), q(4, 5)), (q(1, 2), q(3, 5))];
        let guess = sys.guess(&start, &within, 40).expect("converges");
        let r = q(1, 1_000_000_000);
        let cell: Cell = guess
            .iter()
            .map(|(x, _)| (Rational::from(x - &r), Rational::from(x + &r)))
            .collect();
        let root = sys.certify(&cell, 4).expect("certified");
        let (lo, hi) = (&root[1].0, &root[1].1);
        let expected = 0.549_539_5;
        assert!(lo.to_f64() < expected + 1e-6 && hi.to_f64() > expected - 1e-6);
        assert!(Rational::from(hi - lo) < q(1, 1_000_000_000_000));
        // τ·π = t* = 2.0287578381…
        let t = root[0].0.to_f64() * std::f64::consts::PI;
        assert!((t - 2.028_757_838_110_434).abs() < 1e-9, "{t}");
    }

    #[test]
    fn a_box_without_a_zero_is_not_certified() {
        let d = zero_to_pi();
        let axes = vec![Axis {
            lo: q(1, 2),
            hi: q(3, 5),
            lo_open: false,
            hi_open: false,
            pi: false,
        }];
        let c = Coordinates::new(&d, &axes);
        // λ − 2 has no zero for λ ∈ [1/2, 3/5]
        let g = c.function(&(Sym::var("lambda") - &Sym::int(2)));
        let sys = System::new(&c, vec![g], vec![1]);
        assert!(
            sys.verify(&vec![(q(1, 2), q(1, 2)), (q(1, 2), q(3, 5))])
                .is_none()
        );
        // λ − 11/20 has one, certified by the Newton step
        let g = c.function(&(Sym::var("lambda") - &Sym::rational(q(11, 20))));
        let sys = System::new(&c, vec![g], vec![1]);
        let root = sys
            .certify(&vec![(q(1, 2), q(1, 2)), (q(1, 2), q(3, 5))], 3)
            .unwrap();
        assert!(root[1].0 <= q(11, 20) && root[1].1 >= q(11, 20));
    }
}
