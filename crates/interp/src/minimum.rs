//! Certified minimum of each piece of an interpolant.
//!
//! The control points contain `1/π`; the spline is built over rational
//! [`Interval`]s (`π ∈ [PI_LO, PI_HI]`), giving `V_j ∈ [mid_j − r, mid_j + r]`
//! with `r` the largest radius. For `m ∈ [−2, 1]` the basis is nonnegative
//! and sums to 1 (thesis 3.3.2, certified as T6/T7), so on the whole piece
//! `|P − P_mid| ≤ r` with `P_mid = Σ b_j mid_j`, a function with rational
//! coefficients. The minimum of `P_mid` is located in f64, at a rational
//! `z* = tan(θ*/2)` (so `s`, `c` are rational and `P_mid(z*)` is exact), and
//! `P_mid − (P_mid(z*) − δ) ≥ 0` is proved on the whole piece by the
//! caller's prover (the audit's Weierstrass + Bernstein certificate). Then
//! `min P ∈ [P_mid(z*) − δ − r, P_mid(z*) + r]`. A prover's counterexample
//! is a better point: the search restarts from it.

use rug::Rational;
use trig_core::Family;
use trig_symbolic::{Sym, symbolic_atoms};

use crate::InterpError;
use crate::interval::Interval;
use crate::piece::Piece;
use crate::scheme::Spline;

/// What a nonnegativity prover says about `f(s, c) ≥ 0` on `θ ∈ [0, π/2]`.
#[derive(Debug, Clone, PartialEq)]
pub enum Proof {
    NonNegative,
    /// `f < 0` at `z = tan(θ/2)`.
    Negative {
        z: Rational,
    },
    Undecided(String),
}

/// The certified minimum of one piece.
#[derive(Debug, Clone, PartialEq)]
pub struct PieceMinimum {
    pub piece: usize,
    /// `min P ≥ lower` (`None` when the prover could not decide).
    pub lower: Option<Rational>,
    /// `P(x*) ≤ upper`, hence `min P ≤ upper`.
    pub upper: Rational,
    /// The point: `z* = tan(θ*/2)`, `θ* = π(x* − x_i)/(2h_i)`.
    pub z: Rational,
    /// `x*` (f64, for display).
    pub x: f64,
    /// Why it is undecided, if it is.
    pub undecided: Option<String>,
}

impl PieceMinimum {
    /// Certified `≥ 0` on the piece.
    pub fn nonnegative(&self) -> bool {
        self.lower.as_ref().is_some_and(|l| *l >= 0)
    }

    /// Certified `< 0` somewhere on the piece.
    pub fn negative(&self) -> bool {
        self.upper < 0
    }
}

/// Attempts to refine the point before giving up.
const RESTARTS: usize = 8;

/// `(s, c)` at a rational `z`.
fn circle_point(z: &Rational) -> (Rational, Rational) {
    let d = Rational::from(1) + z.clone() * z;
    (
        Rational::from(2) * z / d.clone(),
        (Rational::from(1) - z.clone() * z) / d,
    )
}

fn value_at(f: &Sym, z: &Rational) -> Result<Rational, InterpError> {
    let (s, c) = circle_point(z);
    f.eval_rational(&|n: &str| match n {
        "s" => Some(s.clone()),
        "c" => Some(c.clone()),
        _ => None,
    })
    .map_err(|e| InterpError::Enclosure(format!("cannot evaluate the piece at z = {z}: {e}")))
}

/// The `u ∈ [0, 1]` minimising the f64 piece (grid of 2000, then golden section).
fn locate(piece: &Piece<f64>) -> f64 {
    let (x0, h) = (piece.x0.to_f64(), piece.h.to_f64());
    let at = |u: f64| piece.eval(&(x0 + h * u));
    let n = 2000;
    let best = (0..=n)
        .map(|k| k as f64 / n as f64)
        .min_by(|a, b| at(*a).total_cmp(&at(*b)))
        .unwrap_or(0.0);
    let (mut a, mut b) = (
        (best - 1.0 / n as f64).max(0.0),
        (best + 1.0 / n as f64).min(1.0),
    );
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..80 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if at(c) < at(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let u = (a + b) / 2.0;
    [0.0, 1.0, u]
        .into_iter()
        .min_by(|p, q| at(*p).total_cmp(&at(*q)))
        .unwrap_or(u)
}

/// A rational `z` near `tan(πu/4)` (exact at the ends).
fn rational_z(u: f64) -> Rational {
    if u <= 0.0 {
        return Rational::new();
    }
    if u >= 1.0 {
        return Rational::from(1);
    }
    let z = (std::f64::consts::PI * u / 4.0).tan();
    let scale = 1u64 << 40;
    Rational::from(((z * scale as f64).round() as i64, scale))
}

/// The certified minimum of every piece of `spline` (built over [`Interval`]).
pub fn certified_minimum(
    spline: &Spline<Interval>,
    prove: &dyn Fn(&Sym) -> Proof,
) -> Result<Vec<PieceMinimum>, InterpError> {
    spline
        .pieces
        .iter()
        .enumerate()
        .map(|(i, piece)| piece_minimum(i, piece, prove))
        .collect()
}

fn piece_minimum(
    i: usize,
    piece: &Piece<Interval>,
    prove: &dyn Fn(&Sym) -> Proof,
) -> Result<PieceMinimum, InterpError> {
    if piece.m < -2 || piece.m > 1 {
        return Err(InterpError::Enclosure(format!(
            "piece {i}: m = {} is outside [−2, 1], where the basis is not nonnegative",
            piece.m
        )));
    }
    let mut mids = Vec::with_capacity(4);
    let mut radius = Rational::new();
    for v in &piece.points {
        let (lo, hi) = v.bounds().ok_or_else(|| {
            InterpError::Enclosure(format!("piece {i}: a control point is undefined"))
        })?;
        mids.push((lo.clone() + hi) / 2u32);
        radius = radius.max((hi.clone() - lo) / 2u32);
    }
    let b = Family::ThesisCubic.eval(&symbolic_atoms(), &[Sym::rational(piece.m.clone())]);
    let p_mid = b.iter().zip(&mids).fold(Sym::zero(), |acc, (bj, v)| {
        acc + &(bj.clone() * &Sym::rational(v.clone()))
    });
    let numeric = Piece {
        x0: piece.x0.clone(),
        h: piece.h.clone(),
        m: piece.m.clone(),
        points: [0, 1, 2, 3].map(|j| mids[j].to_f64()),
    };
    let mut z = rational_z(locate(&numeric));
    let mut undecided = None;
    let mut lower = None;
    for _ in 0..RESTARTS {
        let v = value_at(&p_mid, &z)?;
        let delta = (Rational::from(1) + v.clone().abs()) / Rational::from(1u64 << 24);
        let l = v - &delta;
        match prove(&(p_mid.clone() - &Sym::rational(l.clone()))) {
            Proof::NonNegative => {
                lower = Some(l - &radius);
                undecided = None;
                break;
            }
            Proof::Negative { z: better } => z = better,
            Proof::Undecided(why) => {
                undecided = Some(why);
                break;
            }
        }
    }
    if lower.is_none() && undecided.is_none() {
        undecided = Some(format!("no certificate after {RESTARTS} refinements"));
    }
    let upper = value_at(&p_mid, &z)? + &radius;
    let theta = 2.0 * z.to_f64().atan();
    let x = piece.x0.to_f64() + piece.h.to_f64() * theta / std::f64::consts::FRAC_PI_2;
    Ok(PieceMinimum {
        piece: i,
        lower,
        upper,
        z,
        x,
        undecided,
    })
}
