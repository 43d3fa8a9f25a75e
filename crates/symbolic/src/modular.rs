//! A cheap proof that polynomials over ℚ are coprime, by a modular image.
//!
//! Let `G = gcd(f, n₁, …, n_k)` in `ℚ[x₁, …, x_r]` and `x` a variable of
//! `f`. A ring homomorphism `φ` that fixes `x`, sends every other variable
//! to an integer and reduces modulo a prime `p` (defined on every
//! coefficient that occurs, i.e. `p` divides no denominator) maps `G` to a
//! common divisor of `φ(f), φ(n₁), …` in `𝔽_p[x]`. Since `lc_x G` divides
//! `lc_x f`, when `φ(lc_x f) ≠ 0` the image keeps its degree:
//! `deg_x G = deg_x φ(G) ≤ deg gcd(φ(f), φ(n₁), …)`. So when that univariate
//! gcd is a constant for *every* variable `x` of `f`, `G` is free of all of
//! them, and `G` divides `f`, so `G` is a constant: `f` and the `nᵢ` are
//! coprime. (Scale `G` first to be `p`-primitive, so that `p ∤ G`; Gauss's
//! lemma makes `f/G` and `nᵢ/G` `p`-integral, so `φ(G)` divides their
//! images, and `φ(lc_x f) ≠ 0` keeps `deg_x φ(G) = deg_x G`.) The `nᵢ` may
//! involve `s` and `c`: they are sent to a point of the circle mod `p`, so
//! `φ` is a homomorphism of the quotient ring `ℚ[…][s, c]/(s² + c² − 1)`,
//! in which `p` stays prime (see [`proves_not_divisor`]), and the same
//! argument holds there; any other reduced atom makes the answer "not
//! proved". This is a proof, not a heuristic; when an image is unlucky (a
//! leading coefficient or a denominator vanishes mod `p`, or the images share
//! a factor by accident) the answer is only "not proved", and the exact
//! gcd decides.

use crate::poly::Poly;
use crate::var::{COS, SIN, Var};

use crate::residue::{P, Residue, inverse, pow};

/// True when `f` and all `others` are proved to have no nonconstant common
/// divisor (see the [module documentation](self)); false means "not proved".
pub fn coprime(f: &Poly, others: &[Poly]) -> bool {
    let mut images: Vec<Images> = others.iter().map(|_| Images::default()).collect();
    let mut pairs: Vec<(&Poly, &mut Images)> = others.iter().zip(&mut images).collect();
    coprime_to_images(f, &mut pairs)
}

/// [`coprime`] against polynomials given with their [`Images`], which keep
/// every image formed for the next call.
pub(crate) fn coprime_to_images(f: &Poly, others: &mut [(&Poly, &mut Images)]) -> bool {
    // `f` in ℚ[x₁, …] (a main variable `c` would leave `s` unpaired)
    if f.is_trig() {
        return false;
    }
    let vars = f.vars();
    if vars.is_empty() {
        return false;
    }
    for (n, images) in others.iter_mut() {
        images.form(n, &vars);
    }
    vars.iter().all(|&x| {
        let Some(mut g) = image(f, x).filter(|g| g.len() == f.degree_in_var(x) as usize + 1) else {
            return false;
        };
        for (_, images) in others.iter() {
            let Some(img) = images.get(x) else {
                return false;
            };
            g = gcd(g, img.clone());
            if g.len() == 1 {
                return true;
            }
        }
        g.len() == 1
    })
}

/// True when `f` is proved not to divide `n` in the quotient ring
/// `A = ℚ[x₁, …][s, c]/(s² + c² − 1)` (both free of the other reduced atoms
/// and of `sin(X)`, `cos(X)`); false means "not proved".
///
/// `φ` sends `s`, `c` to a point of the circle mod `p` (so it is a ring
/// homomorphism of `A` with `p`-integral coefficients, `A_(p)`), a variable
/// `x` of `f` other than `s`, `c` to itself and the others to integers.
/// `A_(p)/pA_(p) = 𝔽_p[x₁, …][s, c]/(s² + c² − 1)` is a domain (the conic
/// is irreducible for odd `p`), so `p` is prime in `A_(p)`. If `n = f·q`
/// with `n`, `f` in `A_(p)` and `φ(f) ≠ 0` (so `p ∤ f`), then `q ∈ A_(p)`:
/// writing `q = q'/pᵏ` with `p ∤ q'`, `k > 0` would give `p | f·q'`. Hence
/// `φ(n) = φ(f)·φ(q)`, and a nonzero remainder of `φ(n)` by a nonconstant
/// `φ(f)` in `𝔽_p[x]` proves `f ∤ n`.
pub fn proves_not_divisor(f: &Poly, n: &Poly) -> bool {
    let vars_f = f.vars();
    if !vars_f.iter().all(only_s_c) {
        return false;
    }
    let Some(&x) = vars_f.iter().find(|v| !v.is_trig()) else {
        return false;
    };
    let (Some(img_f), Some(img_n)) = (image(f, x), image(n, x)) else {
        return false;
    };
    img_f.len() > 1 && remainder(img_n, &img_f) != [0]
}

/// True for a variable that [`image`] maps respecting every relation:
/// anything but a reduced atom or a `sin(X)`, `cos(X)`, except `s`, `c`.
fn only_s_c(v: &Var) -> bool {
    !v.is_trig() || *v == Var::sin() || *v == Var::cos()
}

/// `φ(p)` as a polynomial in `x` over `𝔽_p` (coefficients lowest first, no
/// trailing zeros), or `None` when a denominator vanishes mod `p` or `p`
/// has a variable `φ` cannot map ([`only_s_c`]).
fn image(p: &Poly, main: Var) -> Option<Vec<u64>> {
    let mut images = Images::default();
    images.form(p, &[main]);
    images.get(main).cloned()
}

/// The images `φ(p)` of one polynomial `p` for several main variables, each
/// formed once, in one pass over the terms for all variables asked at once.
/// The caller passes the same `p` to every [`Images::form`].
#[derive(Debug, Default)]
pub(crate) struct Images {
    formed: Vec<(Var, Option<Vec<u64>>)>,
}

impl Images {
    /// The image with main variable `x`, when formed ([`Images::form`]) and
    /// defined.
    fn get(&self, x: Var) -> Option<&Vec<u64>> {
        self.formed
            .iter()
            .find(|(v, _)| *v == x)
            .and_then(|(_, img)| img.as_ref())
    }

    /// Forms the image for every variable of `mains` not formed yet. A
    /// term `q·Π vᵉ` adds `φ(q)·Π_{v ≠ x} φ(v)ᵉ` at the power `e_x` of `x`
    /// to the image with main variable `x`; the factors of the variables
    /// that are not asked for are multiplied once per term.
    pub(crate) fn form(&mut self, p: &Poly, mains: &[Var]) {
        let mains: Vec<Var> = mains
            .iter()
            .copied()
            .filter(|x| self.formed.iter().all(|(v, _)| v != x))
            .collect();
        if mains.is_empty() {
            return;
        }
        match images_of(p, &mains) {
            Some(all) => self
                .formed
                .extend(mains.into_iter().zip(all).map(|(x, mut img)| {
                    trim(&mut img);
                    (x, Some(img))
                })),
            None => self.formed.extend(mains.into_iter().map(|x| (x, None))),
        }
    }
}

/// The images of `p` with each of `mains` as main variable, untrimmed.
fn images_of(p: &Poly, mains: &[Var]) -> Option<Vec<Vec<u64>>> {
    let mut out: Vec<Vec<u64>> = mains
        .iter()
        .map(|&x| vec![0u64; p.degree_in_var(x) as usize + 1])
        .collect();
    // the residue each variable is sent to (where it is not the main one)
    let mut residues: Vec<(Var, u64)> = Vec::new();
    // per term: the main variables it has, with exponent and power residue
    let mut present: Vec<(usize, usize, u64)> = Vec::new();
    for (m, q) in p.terms() {
        let mut base = Residue::of_coef(q)?.value();
        present.clear();
        for (v, e) in m.factors() {
            let r = match residues.iter().find(|(w, _)| w == v) {
                Some(&(_, r)) => r,
                None => {
                    if !only_s_c(v) {
                        return None;
                    }
                    let r = substitute(v.name());
                    residues.push((*v, r));
                    r
                }
            };
            let power = pow(r, u64::from(e));
            match mains.iter().position(|x| x == v) {
                Some(i) => present.push((i, e as usize, power)),
                None => base = base * power % P,
            }
        }
        // the image for a main variable the term lacks gets the whole
        // value at power 0; one it has, the value without its own factor
        let whole = present
            .iter()
            .fold(base, |acc, (_, _, power)| acc * power % P);
        for (i, img) in out.iter_mut().enumerate() {
            let (k, value) = match present.iter().find(|(j, ..)| *j == i) {
                None => (0, whole),
                Some(&(_, k, _)) => (
                    k,
                    present
                        .iter()
                        .filter(|(j, ..)| *j != i)
                        .fold(base, |acc, (_, _, power)| acc * power % P),
                ),
            };
            img[k] = (img[k] + value) % P;
        }
    }
    Some(out)
}

/// The integer a variable other than the main one is sent to: a fixed
/// pseudo-random residue derived from its name (the same in every image);
/// `s` and `c` go to a point of the circle `s² + c² = 1` mod `p`
/// ([`circle`]), so that the image respects the relation.
fn substitute(name: &str) -> u64 {
    match name {
        SIN => return circle().0,
        COS => return circle().1,
        _ => {}
    }
    let hash = name.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    2 + hash % (P - 3)
}

/// `(2k/(1 + k²), (1 − k²)/(1 + k²))` mod `p` for a fixed `k` (`1 + k²` is
/// never `0`: `p ≡ 3 mod 4`, so `−1` is not a square).
fn circle() -> (u64, u64) {
    const K: u64 = 1_234_567;
    let k2 = K * K % P;
    let d = inverse((1 + k2) % P);
    (2 * K % P * d % P, (1 + P - k2) % P * d % P)
}

fn trim(p: &mut Vec<u64>) {
    while p.len() > 1 && p.last() == Some(&0) {
        p.pop();
    }
}

/// The monic gcd in `𝔽_p[x]` (`[0]` for two zeros).
fn gcd(mut a: Vec<u64>, mut b: Vec<u64>) -> Vec<u64> {
    trim(&mut a);
    trim(&mut b);
    while b != [0] {
        let r = remainder(a, &b);
        a = b;
        b = r;
    }
    a
}

/// `a mod b`, `b ≠ 0`.
fn remainder(mut a: Vec<u64>, b: &[u64]) -> Vec<u64> {
    let db = b.len() - 1;
    let lead = inverse(b[db]);
    while a.len() > db && a != [0] {
        let da = a.len() - 1;
        let q = a[da] * lead % P;
        for (i, bi) in b.iter().enumerate() {
            let k = da - db + i;
            a[k] = (a[k] + P - q * bi % P) % P;
        }
        a.pop();
        trim(&mut a);
        if db == 0 {
            return vec![0];
        }
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(name: &str) -> Poly {
        Poly::var(name)
    }

    fn n(k: i64) -> Poly {
        Poly::int(k)
    }

    #[test]
    fn coprime_pairs_are_proved() {
        let (l, u) = (v("lambda"), v("mu"));
        let f = &(&l.pow(2) - &n(4)) * &u;
        let others = [&(&l + &n(3)) * &(&u + &n(1)), &l - &(&u * &n(-7))];
        assert!(coprime(&f, &others));
        // negative and fractional coefficients
        let g = &(&l * &n(-3)) + &Poly::constant(rug::Rational::from((1, 2)));
        assert!(coprime(&g, &[&l - &n(5)]));
    }

    #[test]
    fn a_common_factor_is_never_called_coprime() {
        let (l, u) = (v("lambda"), v("mu"));
        let common = &(&l * &u) - &n(2);
        let f = &common * &(&l + &n(1));
        let others = [&common * &(&u - &n(3)), &common * &common];
        assert!(!coprime(&f, &others));
        assert!(!coprime(&(&l + &n(2)), &[&l.pow(2) - &n(4)]));
    }

    #[test]
    fn coprime_against_numerators_with_s_and_c() {
        let (w, s, c) = (v("w0"), v("s"), v("c"));
        let f = &w + &n(1);
        assert!(coprime(&f, &[&(&w * &s) + &c]));
        assert!(!coprime(&(&w - &n(2)), &[&(&w - &n(2)) * &s]));
        assert!(!coprime(&f, &[&(&f * &s) * &s]));
        // f with c: not proved (whatever the numerator)
        assert!(!coprime(&(&w * &(&n(1) - &c)), &[&w + &n(3)]));
        // other reduced atoms: not proved
        assert!(!coprime(&f, &[&v("sqrt(2)") + &w]));
    }

    #[test]
    fn the_circle_point_is_on_the_circle() {
        let (s, c) = circle();
        assert_eq!((s * s + c * c) % P, 1);
    }

    #[test]
    fn non_divisors_are_proved_and_divisors_never_refused() {
        let (w, z, s, c) = (v("w0"), v("zeta"), v("s"), v("c"));
        // f = w·s + z·c + 1 divides f·(s − w) (reduced modulo s² + c² − 1)
        let f = &(&(&w * &s) + &(&z * &c)) + &n(1);
        let q = &s - &w;
        let product = &f * &q;
        assert!(!proves_not_divisor(&f, &product));
        assert_eq!(product.exact_div(&f), Some(q.clone()));
        // s² = (1 − c)(1 + c): w·(1 − c) divides w·s·s in the quotient ring
        let g = &w * &(&n(1) - &c);
        assert!(!proves_not_divisor(&g, &(&(&w * &s) * &s)));
        // not a divisor: f against f·q + 1
        assert!(proves_not_divisor(&f, &(&product + &n(1))));
        // other reduced atoms are left to the exact division
        let r = &v("sqrt(2)") + &w;
        assert!(!proves_not_divisor(&r, &n(1)));
    }

    #[test]
    fn modular_gcd() {
        // (x − 1)(x − 2) and (x − 1)(x + 5): gcd x − 1 (monic: P − 1 + x)
        let a = vec![2, P - 3, 1];
        let b = vec![P - 5, 4, 1];
        let g = gcd(a, b);
        assert_eq!(g.len(), 2);
        assert_eq!(g[0] * inverse(g[1]) % P, P - 1);
    }
}
