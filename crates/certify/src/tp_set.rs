//! The set of parameter values, inside a given parameter set, where every
//! polynomial of a list (the minors of a coefficient matrix,
//! [`crate::total_positivity`]) is `≥ 0` — decided exactly.
//!
//! The distinct real roots of all the polynomials inside the set are the
//! roots of `L`, the squarefree part of their least common multiple,
//! isolated by Sturm sequences ([`crate::sturm`]). Between two consecutive
//! roots no polynomial changes sign, so one rational sample per cell decides
//! the cell; at a root `α` (a real algebraic number, [`Algebraic`]) a
//! polynomial `m` vanishes when `gcd(L, m)` has its root in `α`'s isolating
//! interval, and otherwise has the sign of its value at the interval's
//! midpoint (no other root of `m` lies there). The set is the union of the
//! admissible cells and points, with exact algebraic ends.

use rug::Rational;

use crate::algebraic::Algebraic;
use crate::domain::{Bound, ParamBox};
use crate::range::simplest_between;
use crate::sturm::UPoly;

/// One end of a piece of the set.
#[derive(Debug, Clone, PartialEq)]
pub enum PieceEnd {
    Infinite,
    At { value: Algebraic, closed: bool },
}

/// A maximal interval of the set.
#[derive(Debug, Clone, PartialEq)]
pub struct Piece {
    pub lo: PieceEnd,
    pub hi: PieceEnd,
}

/// Where one polynomial of the list is negative: a rational parameter
/// value and the index of the polynomial.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    pub p: Rational,
    pub index: usize,
}

/// The set where all polynomials are `≥ 0`, inside the given set.
#[derive(Debug, Clone, PartialEq)]
pub struct NonnegativeSet {
    pub pieces: Vec<Piece>,
    /// True when the set is the whole given set.
    pub covers: bool,
    /// One rational witness per cell or rational point outside the set.
    pub failures: Vec<Failure>,
}

/// The root `a` as an algebraic number.
fn rational_point(a: &Rational) -> Algebraic {
    Algebraic::new(
        &UPoly::new(vec![-a.clone(), Rational::from(1)]),
        a.clone(),
        a.clone(),
    )
}

/// The sign of `m` at `α` (a root of the squarefree `α.poly`, which holds
/// every root of `m` in the region searched).
fn sign_at(m: &UPoly, alpha: &Algebraic) -> i32 {
    if let Some(q) = &alpha.rational {
        return m.sign_at(q);
    }
    let g = alpha.poly.gcd(m);
    if g.degree() > 0 && g.count_roots(&alpha.lo, &alpha.hi) > 0 {
        return 0;
    }
    m.sign_at(&((alpha.lo.clone() + &alpha.hi) / 2u32))
}

/// The index of the first negative polynomial at `α`, if any.
fn first_negative(ms: &[UPoly], alpha: &Algebraic) -> Option<usize> {
    ms.iter().position(|m| sign_at(m, alpha) < 0)
}

/// One item of the walk along the parameter line: a boundary point or the
/// open cell after it.
enum Item {
    Point(usize),
    Cell(usize, Rational),
}

/// The set of `p` in `bx` with `mᵢ(p) ≥ 0` for every `i`.
pub fn nonnegative_set(ms: &[UPoly], bx: &ParamBox) -> NonnegativeSet {
    let basis = coprime_basis(ms);
    let bound = basis
        .iter()
        .map(UPoly::root_bound)
        .max()
        .unwrap_or_default()
        + Rational::from(1);
    let lo = bx.lo.value().cloned().unwrap_or_else(|| -bound.clone());
    let hi = bx.hi.value().cloned().unwrap_or(bound);
    let end = |b: &Bound| match b {
        Bound::Closed(a) => (Some(rational_point(a)), true),
        Bound::Open(a) => (Some(rational_point(a)), false),
        Bound::Infinite => (None, false),
    };
    let mut roots = Vec::new();
    if lo < hi {
        for e in &basis {
            for (a, b) in e.isolate(&lo, &hi) {
                roots.push(Algebraic::new(e, a, b));
            }
        }
    }
    separate(&mut roots);
    let mut marks: Vec<(Option<Algebraic>, bool)> = vec![end(&bx.lo)];
    marks.extend(roots.into_iter().map(|r| (Some(r), true)));
    if lo < hi || bx.hi == Bound::Infinite || bx.lo == Bound::Infinite {
        marks.push(end(&bx.hi));
    }
    separate_ends(&mut marks);
    // the walk: each included mark, then the open cell after it
    let mut items = Vec::new();
    for k in 0..marks.len() {
        if marks[k].1 {
            items.push(Item::Point(k));
        }
        if k + 1 < marks.len() {
            let sample = match (&marks[k].0, &marks[k + 1].0) {
                (Some(a), Some(b)) => {
                    let gap = Rational::from(&b.lo - &a.hi) / 4u32;
                    simplest_between(&(a.hi.clone() + &gap), &(b.lo.clone() - &gap))
                }
                (Some(a), None) => a.hi.clone() + 1u32,
                (None, Some(b)) => b.lo.clone() - 1u32,
                (None, None) => Rational::new(),
            };
            items.push(Item::Cell(k, sample));
        }
    }
    let mut pieces = Vec::new();
    let mut failures = Vec::new();
    let mut open: Option<PieceEnd> = None;
    let mut last_ok_hi: Option<PieceEnd> = None;
    for item in &items {
        let (bad, start, stop) = match item {
            Item::Point(k) => {
                let alpha = marks[*k].0.clone().expect("an included mark is finite");
                let bad = first_negative(ms, &alpha);
                if let (Some(index), Some(p)) = (bad, alpha.rational.clone()) {
                    failures.push(Failure { p, index });
                }
                let at = PieceEnd::At {
                    value: alpha,
                    closed: true,
                };
                (bad.is_some(), at.clone(), at)
            }
            Item::Cell(k, sample) => {
                let bad = ms.iter().position(|m| m.sign_at(sample) < 0);
                if let Some(index) = bad {
                    failures.push(Failure {
                        p: sample.clone(),
                        index,
                    });
                }
                let side = |m: &(Option<Algebraic>, bool)| match &m.0 {
                    Some(value) => PieceEnd::At {
                        value: value.clone(),
                        closed: false,
                    },
                    None => PieceEnd::Infinite,
                };
                (bad.is_some(), side(&marks[*k]), side(&marks[k + 1]))
            }
        };
        if bad {
            if let (Some(lo), Some(hi)) = (open.take(), last_ok_hi.take()) {
                pieces.push(Piece { lo, hi });
            }
        } else {
            if open.is_none() {
                open = Some(start);
            }
            last_ok_hi = Some(stop);
        }
    }
    if let (Some(lo), Some(hi)) = (open, last_ok_hi) {
        pieces.push(Piece { lo, hi });
    }
    NonnegativeSet {
        covers: failures.is_empty() && pieces.len() == 1,
        pieces,
        failures,
    }
}

/// A gcd-free basis of the squarefree parts of the nonconstant `ms`:
/// pairwise coprime squarefree polynomials (integer coefficients) with the
/// same real roots, so that distinct elements never share a root.
fn coprime_basis(ms: &[UPoly]) -> Vec<UPoly> {
    let mut basis: Vec<UPoly> = Vec::new();
    for m in ms.iter().filter(|m| m.degree() > 0) {
        let mut p = m.squarefree().integer_primitive();
        let mut next = Vec::new();
        for q in basis {
            let g = q.gcd(&p);
            if g.degree() == 0 {
                next.push(q);
                continue;
            }
            let g = g.integer_primitive();
            let rest = q.div_rem(&g).0;
            if rest.degree() > 0 {
                next.push(rest.integer_primitive());
            }
            p = p.div_rem(&g).0.integer_primitive();
            next.push(g);
        }
        if p.degree() > 0 {
            next.push(p);
        }
        basis = next;
    }
    basis
}

/// Halves the isolating interval of `x` (nothing for an exact point).
fn halve(x: &mut Algebraic) {
    let w = Rational::from(&x.hi - &x.lo) / 2u32;
    x.refine(&w);
}

/// Sorts the roots (of pairwise coprime polynomials, so all distinct) and
/// refines their isolating intervals until each lies strictly below the
/// next.
fn separate(roots: &mut [Algebraic]) {
    loop {
        roots.sort_by(|a, b| a.lo.cmp(&b.lo).then(a.hi.cmp(&b.hi)));
        let Some(k) = (1..roots.len()).find(|&k| roots[k - 1].hi >= roots[k].lo) else {
            return;
        };
        let (left, right) = roots.split_at_mut(k);
        halve(&mut left[k - 1]);
        halve(&mut right[0]);
    }
}

/// Refines the roots next to the ends of the set until they lie strictly
/// inside.
fn separate_ends(marks: &mut [(Option<Algebraic>, bool)]) {
    let n = marks.len();
    for (end, next) in [(0, 1), (n - 1, n.saturating_sub(2))] {
        if end == next || n < 2 {
            continue;
        }
        let Some(e) = marks[end].0.clone() else {
            continue;
        };
        while let Some(x) = marks[next].0.as_mut() {
            let apart = if end == 0 { e.hi < x.lo } else { x.hi < e.lo };
            if apart {
                break;
            }
            halve(x);
        }
    }
}

impl PieceEnd {
    /// The end in words: `−∞`/`∞` for an infinite end (by `low`), else
    /// the value with `[`/`(` or `]`/`)`.
    pub fn describe(&self, var: &str, low: bool) -> String {
        match (self, low) {
            (PieceEnd::Infinite, true) => "(−∞".into(),
            (PieceEnd::Infinite, false) => "∞)".into(),
            (PieceEnd::At { value, closed }, true) => {
                format!(
                    "{}{}",
                    if *closed { "[" } else { "(" },
                    value.describe(var, 6)
                )
            }
            (PieceEnd::At { value, closed }, false) => {
                format!(
                    "{}{}",
                    value.describe(var, 6),
                    if *closed { "]" } else { ")" }
                )
            }
        }
    }
}

impl NonnegativeSet {
    /// The set in words, e.g. `[−1, 1]`, or `∅`.
    pub fn describe(&self, var: &str) -> String {
        if self.pieces.is_empty() {
            return "∅".into();
        }
        self.pieces
            .iter()
            .map(|p| {
                format!(
                    "{}, {}",
                    p.lo.describe(var, true),
                    p.hi.describe(var, false)
                )
            })
            .collect::<Vec<_>>()
            .join(" ∪ ")
    }
}
