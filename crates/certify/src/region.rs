//! The region of two shape parameters `(p, q)` on which every function of a
//! basis is nonnegative on its whole domain, over a window of the plane.
//!
//! The window is subdivided (a quadtree). A cell is
//! * **inside** when every function is certified `≥ 0` on the domain × cell
//!   (tensor Bernstein subdivision in `(z, p, q)`);
//! * **outside** when one function is negative on the whole cell at one
//!   fixed point `z₀` of the domain: `f(z₀; p, q) < 0` strictly on the cell,
//!   certified (numerator and every denominator factor of one strict sign);
//!   `z₀` comes from an exact counterexample found in the cell;
//! * otherwise split, down to a depth limit: the cells left are the
//!   **boundary** cells, where the region's edge lies.
//!
//! The edge itself lies on the zero sets of the boundary polynomials in
//! `(p, q)` ([`crate::boundary`]): exact polynomial conditions.

use rug::Rational;
use trig_symbolic::Sym;

use crate::boundary::{Candidate, candidates};
use crate::domain::ParamBox;
use crate::nonneg::{BoxCertificate, certify_box_to_depth, definite_sign};

/// How one cell of the window was classified.
#[derive(Debug, Clone, PartialEq)]
pub enum CellKind {
    /// Every function certified `≥ 0` on the domain for the whole cell.
    Inside,
    /// Function `function` is `< 0` at `z` for every parameter in the cell
    /// (certified), e.g. `value` at the cell's witness `point`.
    Outside {
        function: usize,
        z: Rational,
        point: [Rational; 2],
        value: Rational,
    },
    /// Not decided at the depth limit.
    Boundary,
}

/// A closed cell `[lo₀, hi₀] × [lo₁, hi₁]` of the parameter plane.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    pub lo: [Rational; 2],
    pub hi: [Rational; 2],
    pub kind: CellKind,
}

impl Cell {
    /// True when the cell lies inside the closed box `[a₀, b₀] × [a₁, b₁]`.
    pub fn within(&self, lo: &[Rational; 2], hi: &[Rational; 2]) -> bool {
        (0..2).all(|k| self.lo[k] >= lo[k] && self.hi[k] <= hi[k])
    }

    /// True when the cell's interior misses the box.
    pub fn outside_of(&self, lo: &[Rational; 2], hi: &[Rational; 2]) -> bool {
        (0..2).any(|k| self.hi[k] <= lo[k] || self.lo[k] >= hi[k])
    }
}

/// The classified window.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    pub params: [String; 2],
    pub window_lo: [Rational; 2],
    pub window_hi: [Rational; 2],
    pub cells: Vec<Cell>,
    /// The boundary polynomials in the two parameters (empty when they
    /// could not be computed, with the reason in `boundary_note`).
    pub boundary: Vec<Candidate>,
    pub boundary_note: Option<String>,
}

impl Region {
    /// Cells of one kind.
    pub fn count(&self, pred: impl Fn(&CellKind) -> bool) -> usize {
        self.cells.iter().filter(|c| pred(&c.kind)).count()
    }
}

/// Depth of the Bernstein subdivision inside one cell (the quadtree does
/// the rest).
const CELL_DEPTH: u32 = 24;

/// `f(z₀; p, q) < 0` strictly on the cell.
fn negative_on_cell(f: &Sym, trig: bool, z: &Rational, boxes: &[(&str, ParamBox)]) -> bool {
    let var = if trig { "z" } else { "t" };
    let at = if trig {
        // f is in s, c: substitute the rational point of the circle
        let d = Rational::from(1) + z.clone() * z;
        let s = Rational::from(2) * z / d.clone();
        let c = (Rational::from(1) - z.clone() * z) / d;
        f.subs("s", &Sym::rational(s)).subs("c", &Sym::rational(c))
    } else {
        f.subs(var, &Sym::rational(z.clone()))
    };
    let mut sign = match definite_sign(&Sym::from_poly(at.numerator().clone()), false, boxes) {
        Ok(s) => s,
        Err(_) => return false,
    };
    for (factor, e) in at.denominator() {
        match definite_sign(&Sym::from_poly(factor.clone()), false, boxes) {
            Ok(s) if e % 2 == 1 => sign *= s,
            Ok(_) => {}
            Err(_) => return false,
        }
    }
    sign < 0
}

/// Classifies one cell (no subdivision of the cell itself).
pub fn classify(
    fs: &[Sym],
    trig: bool,
    params: [&str; 2],
    lo: &[Rational; 2],
    hi: &[Rational; 2],
) -> CellKind {
    let boxes = [
        (params[0], ParamBox::closed(lo[0].clone(), hi[0].clone())),
        (params[1], ParamBox::closed(lo[1].clone(), hi[1].clone())),
    ];
    let mut all_inside = true;
    for (i, f) in fs.iter().enumerate() {
        match certify_box_to_depth(f, trig, &boxes, Some(CELL_DEPTH)) {
            BoxCertificate::NonNegative { .. } => {}
            BoxCertificate::Counterexample {
                params: at,
                z,
                value,
            } => {
                if negative_on_cell(f, trig, &z, &boxes) {
                    return CellKind::Outside {
                        function: i,
                        z,
                        point: [at[0].clone(), at[1].clone()],
                        value,
                    };
                }
                all_inside = false;
            }
            BoxCertificate::Pole(_) | BoxCertificate::Undecided(_) => all_inside = false,
        }
    }
    if all_inside {
        CellKind::Inside
    } else {
        CellKind::Boundary
    }
}

/// Classifies the window `[lo₀, hi₀] × [lo₁, hi₁]` of the plane of
/// `params`, splitting undecided cells up to `max_depth` times. Cells
/// never straddle the lines `splits` (e.g. a claimed box's edges), so
/// each cell is inside or outside such a box.
///
/// The cells are classified by `classify` — [`classify`] for the region
/// where every function of `fs` is nonnegative, another for a property of
/// which `fs ≥ 0` are necessary conditions (the edge lies on the boundary
/// polynomials of `fs` either way).
#[allow(clippy::too_many_arguments)]
pub fn region(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    params: [&str; 2],
    window: ([Rational; 2], [Rational; 2]),
    splits: [&[Rational]; 2],
    max_depth: u32,
    classify: impl Fn(&[Rational; 2], &[Rational; 2]) -> CellKind,
) -> Region {
    let cells = quadtree(&window, splits, max_depth, classify);
    let (wlo, whi) = window;
    let (boundary, boundary_note) = match candidates(fs, names, trig) {
        Ok(c) => (dedup(c), None),
        Err(why) => (Vec::new(), Some(why)),
    };
    Region {
        params: [params[0].to_string(), params[1].to_string()],
        window_lo: wlo,
        window_hi: whi,
        cells,
        boundary,
        boundary_note,
    }
}

/// The window cut at the split lines, each cell classified by `classify`
/// and split into four while it is [`CellKind::Boundary`], down to
/// `max_depth`: the cells, sorted.
fn quadtree(
    window: &([Rational; 2], [Rational; 2]),
    splits: [&[Rational]; 2],
    max_depth: u32,
    classify: impl Fn(&[Rational; 2], &[Rational; 2]) -> CellKind,
) -> Vec<Cell> {
    let (wlo, whi) = window;
    // the initial grid: the window cut at the split lines
    let cuts = |k: usize| -> Vec<Rational> {
        let mut c = vec![wlo[k].clone()];
        c.extend(
            splits[k]
                .iter()
                .filter(|x| **x > wlo[k] && **x < whi[k])
                .cloned(),
        );
        c.push(whi[k].clone());
        c.sort();
        c.dedup();
        c
    };
    let (c0, c1) = (cuts(0), cuts(1));
    let mut stack = Vec::new();
    for a in c0.windows(2) {
        for b in c1.windows(2) {
            stack.push((
                [a[0].clone(), b[0].clone()],
                [a[1].clone(), b[1].clone()],
                0u32,
            ));
        }
    }
    let mut cells = Vec::new();
    while let Some((lo, hi, depth)) = stack.pop() {
        let kind = classify(&lo, &hi);
        if kind != CellKind::Boundary || depth >= max_depth {
            cells.push(Cell { lo, hi, kind });
            continue;
        }
        let mid = [
            Rational::from(&lo[0] + &hi[0]) / 2u32,
            Rational::from(&lo[1] + &hi[1]) / 2u32,
        ];
        for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            let clo = [
                if i == 0 {
                    lo[0].clone()
                } else {
                    mid[0].clone()
                },
                if j == 0 {
                    lo[1].clone()
                } else {
                    mid[1].clone()
                },
            ];
            let chi = [
                if i == 0 {
                    mid[0].clone()
                } else {
                    hi[0].clone()
                },
                if j == 0 {
                    mid[1].clone()
                } else {
                    hi[1].clone()
                },
            ];
            stack.push((clo, chi, depth + 1));
        }
    }
    cells.sort_by(|a, b| a.lo.cmp(&b.lo).then(a.hi.cmp(&b.hi)));
    cells
}

/// One candidate per distinct polynomial (up to a constant factor).
fn dedup(cands: Vec<Candidate>) -> Vec<Candidate> {
    let mut out: Vec<Candidate> = Vec::new();
    for c in cands {
        let (_, p) = c.poly.canonical();
        if !out.iter().any(|o| o.poly == p) {
            out.push(Candidate { poly: p, ..c });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_region_is_found_with_certified_cells_on_both_sides() {
        // f = 1 − (p + q) t on t ∈ [0, 1]: admissible exactly for p + q ≤ 1
        let (t, p, q) = (Sym::var("t"), Sym::var("p"), Sym::var("q"));
        let f = Sym::one() - &((p + &q) * &t);
        let r = |n: i64| Rational::from(n);
        let fs = [f];
        let reg = region(
            &fs,
            &["f"],
            false,
            ["p", "q"],
            ([r(-2), r(-2)], [r(2), r(2)]),
            [&[], &[]],
            5,
            |lo, hi| classify(&fs, false, ["p", "q"], lo, hi),
        );
        let inside = reg.count(|k| *k == CellKind::Inside);
        let outside = reg.count(|k| matches!(k, CellKind::Outside { .. }));
        assert!(inside > 0 && outside > 0, "{inside} {outside}");
        for c in &reg.cells {
            let s_lo = Rational::from(&c.lo[0] + &c.lo[1]);
            let s_hi = Rational::from(&c.hi[0] + &c.hi[1]);
            match &c.kind {
                CellKind::Inside => assert!(s_hi <= 1),
                CellKind::Outside { value, .. } => {
                    assert!(s_lo >= 1 && *value < 0);
                }
                CellKind::Boundary => assert!(s_lo <= 1 && s_hi >= 1),
            }
        }
        // the boundary conditions include p + q − 1 (the value at t = 1)
        let line = (Sym::var("p") + &Sym::var("q") - &Sym::one())
            .numerator()
            .clone();
        assert!(
            reg.boundary.iter().any(|c| c.poly == line),
            "{:?}",
            reg.boundary
        );
    }
}
