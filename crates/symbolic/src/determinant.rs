//! The determinant of a square matrix of exact values.

use crate::sym::Sym;

impl Sym {
    /// `det m` of a square matrix of exact values, by Laplace expansion
    /// along the first row, skipping zero entries: `n!` products at most, so
    /// for the small matrices of Wronskians (a handful of functions).
    ///
    /// ```
    /// use trig_symbolic::Sym;
    /// let (a, b) = (Sym::var("a"), Sym::var("b"));
    /// let m = vec![vec![a.clone(), b.clone()], vec![b.clone(), a.clone()]];
    /// assert!(Sym::determinant(&m).equals(&(a.clone() * &a - b.clone() * &b)));
    /// ```
    pub fn determinant(m: &[Vec<Sym>]) -> Sym {
        match m.len() {
            0 => Sym::one(),
            1 => m[0][0].clone(),
            _ => (0..m.len())
                .filter(|&j| !m[0][j].is_zero())
                .map(|j| {
                    let minor: Vec<Vec<Sym>> = m[1..]
                        .iter()
                        .map(|row| {
                            row.iter()
                                .enumerate()
                                .filter(|(k, _)| *k != j)
                                .map(|(_, x)| x.clone())
                                .collect()
                        })
                        .collect();
                    let term = m[0][j].clone() * &Sym::determinant(&minor);
                    if j % 2 == 0 { term } else { -term }
                })
                .fold(Sym::zero(), |acc, t| acc + &t),
        }
    }
}
