//! Sparse symmetric systems solved as banded ones: a bandwidth-reducing
//! ordering (breadth-first, Cuthill–McKee style) and Gaussian elimination
//! with partial pivoting inside the band (LAPACK `dgbsv`'s algorithm:
//! pivoting widens the upper band by the lower bandwidth).
//!
//! Memory and time are `O(n·w)` and `O(n·w²)` for `n` unknowns and
//! bandwidth `w`, so the C¹ refinement of a million-point outline (a chain
//! or cycle of segments: `w` ≤ 9 after ordering) never forms a dense
//! `n × n` matrix.

use std::collections::BTreeMap;

/// A sparse matrix being assembled: entries by (row, column), summed.
#[derive(Debug, Clone, Default)]
pub struct Sparse {
    n: usize,
    entries: BTreeMap<(usize, usize), f64>,
}

impl Sparse {
    /// The zero `n × n` matrix.
    pub fn new(n: usize) -> Self {
        Sparse {
            n,
            entries: BTreeMap::new(),
        }
    }

    /// `a(i, j) += v`.
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        *self.entries.entry((i, j)).or_insert(0.0) += v;
    }

    /// Solves `A X = B` for the columns of `rhs` (`rhs[i]` is row `i`),
    /// the unknowns renumbered by `order` (`order[k]` is the unknown placed
    /// `k`-th; a permutation of `0..n`). `None` when a pivot vanishes
    /// relative to the largest entry (the system is singular to working
    /// precision) or a solution is not finite.
    pub fn solve<const C: usize>(
        &self,
        rhs: &[[f64; C]],
        order: &[usize],
    ) -> Option<Vec<[f64; C]>> {
        let n = self.n;
        let mut pos = vec![usize::MAX; n];
        for (k, &v) in order.iter().enumerate() {
            pos[v] = k;
        }
        if order.len() != n || pos.contains(&usize::MAX) {
            return None;
        }
        let (mut kl, mut ku) = (0, 0);
        for &(i, j) in self.entries.keys() {
            let (pi, pj) = (pos[i], pos[j]);
            kl = kl.max(pi.saturating_sub(pj));
            ku = ku.max(pj.saturating_sub(pi));
        }
        let mut band = Band::new(n, kl, ku);
        let mut scale = 0.0_f64;
        for (&(i, j), &v) in &self.entries {
            band.set(pos[i], pos[j], v);
            scale = scale.max(v.abs());
        }
        let mut b = vec![[0.0; C]; n];
        for (i, row) in rhs.iter().enumerate().take(n) {
            b[pos[i]] = *row;
        }
        let x = band.solve(&mut b, scale)?;
        let solution: Vec<[f64; C]> = (0..n).map(|i| x[pos[i]]).collect();
        solution
            .iter()
            .all(|r| r.iter().all(|v| v.is_finite()))
            .then_some(solution)
    }
}

/// A breadth-first ordering of the nodes `0..n` of a graph (edges as
/// pairs), each component started at a node of least degree: a path is
/// numbered end to end, a cycle alternately from both sides of its start,
/// so neighbours are at most two places apart.
pub fn breadth_first(n: usize, edges: &[(usize, usize)]) -> Vec<usize> {
    let mut adjacent = vec![Vec::new(); n];
    for &(a, b) in edges {
        if a != b && a < n && b < n {
            adjacent[a].push(b);
            adjacent[b].push(a);
        }
    }
    let mut seen = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let mut by_degree: Vec<usize> = (0..n).collect();
    by_degree.sort_by_key(|&v| (adjacent[v].len(), v));
    for start in by_degree {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut queue = std::collections::VecDeque::from([start]);
        while let Some(v) = queue.pop_front() {
            order.push(v);
            for &w in &adjacent[v] {
                if !seen[w] {
                    seen[w] = true;
                    queue.push_back(w);
                }
            }
        }
    }
    order
}

/// A band matrix with room for the fill of partial pivoting: row `i` holds
/// columns `i − kl ..= i + ku + kl`.
struct Band {
    n: usize,
    kl: usize,
    width: usize,
    data: Vec<f64>,
}

impl Band {
    fn new(n: usize, kl: usize, ku: usize) -> Self {
        let width = 2 * kl + ku + 1;
        Band {
            n,
            kl,
            width,
            data: vec![0.0; n * width],
        }
    }

    /// The last column row `i` can hold.
    fn last(&self, i: usize) -> usize {
        (i + self.width - self.kl - 1).min(self.n - 1)
    }

    fn at(&self, i: usize, j: usize) -> usize {
        i * self.width + (j + self.kl - i)
    }

    fn get(&self, i: usize, j: usize) -> f64 {
        self.data[self.at(i, j)]
    }

    fn set(&mut self, i: usize, j: usize, v: f64) {
        let k = self.at(i, j);
        self.data[k] = v;
    }

    /// Gaussian elimination with partial pivoting on `self` and `b`, then
    /// back substitution. `scale` is the largest entry.
    fn solve<const C: usize>(&mut self, b: &mut [[f64; C]], scale: f64) -> Option<Vec<[f64; C]>> {
        let n = self.n;
        let tiny = scale * f64::EPSILON * (n.max(1) as f64).sqrt();
        for k in 0..n {
            let below = (k + self.kl).min(n - 1);
            let p = (k..=below)
                .max_by(|&a, &c| self.get(a, k).abs().total_cmp(&self.get(c, k).abs()))?;
            if self.get(p, k).abs() <= tiny {
                return None;
            }
            let end = self.last(k);
            if p != k {
                for j in k..=end {
                    let (x, y) = (self.get(k, j), self.get(p, j));
                    self.set(k, j, y);
                    self.set(p, j, x);
                }
                b.swap(k, p);
            }
            let pivot = self.get(k, k);
            for i in k + 1..=below {
                let l = self.get(i, k) / pivot;
                if l == 0.0 {
                    continue;
                }
                self.set(i, k, 0.0);
                for j in k + 1..=end {
                    let v = self.get(i, j) - l * self.get(k, j);
                    self.set(i, j, v);
                }
                let bk = b[k];
                for (c, v) in b[i].iter_mut().enumerate() {
                    *v -= l * bk[c];
                }
            }
        }
        let mut x = vec![[0.0; C]; n];
        for k in (0..n).rev() {
            let mut r = b[k];
            for (j, xj) in x.iter().enumerate().take(self.last(k) + 1).skip(k + 1) {
                let a = self.get(k, j);
                for (v, xc) in r.iter_mut().zip(xj) {
                    *v -= a * xc;
                }
            }
            let pivot = self.get(k, k);
            x[k] = r.map(|v| v / pivot);
        }
        Some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// A cyclic tridiagonal system (the shape of a closed contour's joins)
    /// against nalgebra's dense LU.
    #[test]
    fn agrees_with_dense_lu_on_a_cycle() {
        let n = 40;
        let mut sparse = Sparse::new(n);
        let mut dense = DMatrix::<f64>::zeros(n, n);
        let mut edges = Vec::new();
        for i in 0..n {
            let j = (i + 1) % n;
            let v = 1.0 + (i as f64 * 0.37).sin();
            for (a, b, w) in [(i, i, 4.0 + v), (i, j, -v), (j, i, -v)] {
                sparse.add(a, b, w);
                dense[(a, b)] += w;
            }
            edges.push((i, j));
        }
        let rhs: Vec<[f64; 2]> = (0..n).map(|i| [i as f64, (i as f64).cos()]).collect();
        let order = breadth_first(n, &edges);
        let x = sparse.solve(&rhs, &order).expect("nonsingular");
        let lu = dense.lu();
        for c in 0..2 {
            let b = DVector::from_iterator(n, rhs.iter().map(|r| r[c]));
            let y = lu.solve(&b).expect("nonsingular");
            for i in 0..n {
                assert!(
                    (x[i][c] - y[i]).abs() < 1e-12,
                    "{i}: {} vs {}",
                    x[i][c],
                    y[i]
                );
            }
        }
    }

    #[test]
    fn a_cycle_is_ordered_with_neighbours_close() {
        let n = 10;
        let edges: Vec<(usize, usize)> = (0..n).map(|i| (i, (i + 1) % n)).collect();
        let order = breadth_first(n, &edges);
        let mut pos = vec![0; n];
        for (k, &v) in order.iter().enumerate() {
            pos[v] = k;
        }
        for &(a, b) in &edges {
            assert!(pos[a].abs_diff(pos[b]) <= 2, "{order:?}");
        }
    }

    #[test]
    fn a_singular_system_is_refused() {
        let mut s = Sparse::new(2);
        s.add(0, 0, 1.0);
        s.add(0, 1, 2.0);
        s.add(1, 0, 2.0);
        s.add(1, 1, 4.0);
        assert!(s.solve(&[[1.0], [1.0]], &[0, 1]).is_none());
    }
}
