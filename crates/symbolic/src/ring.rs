//! [`Sym`] as a [`trig_core::Ring`]: operators, constants and the symbolic
//! atoms.

use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::ops::Pow;
use rug::{Integer, Rational};
use trig_core::{Atoms, Ring};

use crate::sym::Sym;
use crate::var::{COS, EXP, PI, SIN, T};

/// The atoms `s`, `c`, `t`, `E` as variables, to evaluate a catalog
/// formula symbolically: `Family::eval(&symbolic_atoms(), &[Sym::var("m")])`.
pub fn symbolic_atoms() -> Atoms<Sym> {
    Atoms {
        s: Sym::var(SIN),
        c: Sym::var(COS),
        t: Sym::var(T),
        e: Sym::var(EXP),
    }
}

/// The text `X` of a rational multiple `q·p` of one parameter symbol
/// (`alpha`, `alpha/2`, `3*beta`), when `x` is one: the argument of the
/// paired atoms `sin(X)`, `cos(X)` and of `exp(X)`.
fn parameter_multiple(x: &Sym) -> Option<String> {
    let vars = x.variables();
    let [p] = vars.iter().collect::<Vec<_>>()[..] else {
        return None;
    };
    let q = (x.clone() / &Sym::var(p)).as_rational()?;
    let forbidden = [SIN, COS, T, EXP, PI];
    if q == 0 || forbidden.contains(&p.as_str()) || p.contains('(') {
        return None;
    }
    let sign = if q < 0 { "-" } else { "" };
    let (num, den) = (q.numer().clone().abs(), q.denom().clone());
    let num = if num == 1 {
        String::new()
    } else {
        format!("{num}*")
    };
    let den = if den == 1 {
        String::new()
    } else {
        format!("/{den}")
    };
    Some(format!("{sign}{num}{p}{den}"))
}

/// `sin(kπ/12)` for `k = 0…6` (the first quadrant), with `sqrt(2)`,
/// `sqrt(3)` as atoms: `0, (√6 − √2)/4, 1/2, √2/2, √3/2, (√6 + √2)/4, 1`.
fn first_quadrant_sine(k: u32) -> Sym {
    let (r2, r3) = (Sym::var("sqrt(2)"), Sym::var("sqrt(3)"));
    let quarter = |x: Sym| x / &Sym::int(4);
    match k {
        0 => Sym::zero(),
        1 => quarter(r2.clone() * &r3 - &r2),
        2 => Sym::rational(Rational::from((1, 2))),
        3 => r2 / &Sym::int(2),
        4 => r3 / &Sym::int(2),
        5 => quarter(r2.clone() * &r3 + &r2),
        _ => Sym::one(),
    }
}

/// `sin(kπ/12)` for any integer `k` (by `sin(π − x) = sin x` and
/// `sin(x + π) = −sin x`).
fn sine_of_twelfths(k: u32) -> Sym {
    let k = k % 24;
    let (half, r) = (k / 12, k % 12);
    let v = first_quadrant_sine(if r <= 6 { r } else { 12 - r });
    if half == 1 { -v } else { v }
}

/// `(sin x, cos x)` exactly when `x` is a multiple of π/12 (values in
/// `ℚ(√2, √3)`).
fn twelfth_turn(x: &Sym) -> Option<(Sym, Sym)> {
    let k = if x.is_zero() {
        Rational::new()
    } else {
        (x.clone() / &Sym::pi()).as_rational()? * Rational::from(12)
    };
    if *k.denom() != 1 {
        return None;
    }
    let k = k.numer().mod_u(24);
    Some((sine_of_twelfths(k), sine_of_twelfths(k + 6)))
}

/// `√q` exactly when the square-free part of the rational `q ≥ 0` is a
/// product of 2, 3, 5, 7: `q = (a/b)²·Π pᵢ` gives `(a/b)·Π sqrt(pᵢ)`;
/// `√0 = 0`.
fn exact_sqrt(q: &Rational) -> Option<Sym> {
    match q.cmp0() {
        std::cmp::Ordering::Less => return None,
        // zero is divisible by every prime: it has no square-free part
        std::cmp::Ordering::Equal => return Some(Sym::zero()),
        std::cmp::Ordering::Greater => {}
    }
    // √(n/d) = √(n·d)/d
    let mut n = Integer::from(q.numer() * q.denom());
    let mut root = Sym::rational(Rational::from((1, q.denom().clone())));
    // n ≥ 1 has at most log₂ n prime factors: each division below shrinks
    // it, and the count bounds the loop whatever n is
    let most = n.significant_bits();
    for p in [2u32, 3, 5, 7] {
        let mut e = 0;
        while e < most && n.is_divisible_u(p) {
            n /= p;
            e += 1;
        }
        root = root * &Sym::rational(Rational::from(Integer::from(p).pow(e / 2)));
        if e % 2 == 1 {
            root = root * &Sym::var(&format!("sqrt({p})"));
        }
    }
    n.is_perfect_square()
        .then(|| root * &Sym::rational(Rational::from(n.sqrt())))
}

impl Ring for Sym {
    fn int(&self, n: i64) -> Sym {
        Sym::int(n)
    }

    fn ratio(&self, num: i64, den: i64) -> Sym {
        Sym::rational(Rational::from((num, den)))
    }

    fn rational(&self, q: &Rational) -> Sym {
        Sym::rational(q.clone())
    }

    fn pi(&self) -> Sym {
        Sym::pi()
    }

    fn is_zero(&self) -> bool {
        Sym::is_zero(self)
    }

    fn is_exact_zero(&self) -> bool {
        Sym::is_zero(self)
    }

    /// Exact at multiples of π/12 (values in `ℚ(√2, √3)`); the paired symbols `sin(X)`, `cos(X)`
    /// for a rational multiple `X` of one parameter (independent of every
    /// other atom but for `sin² + cos² = 1`); `None` otherwise.
    fn try_sin_cos(&self) -> Option<(Sym, Sym)> {
        twelfth_turn(self).or_else(|| {
            let x = parameter_multiple(self)?;
            Some((
                Sym::var(&format!("sin({x})")),
                Sym::var(&format!("cos({x})")),
            ))
        })
    }

    /// `exp 0 = 1`; the symbol `exp(X)` for a rational multiple `X` of one
    /// parameter; `None` otherwise.
    fn try_exp(&self) -> Option<Sym> {
        if self.is_zero() {
            return Some(Sym::one());
        }
        parameter_multiple(self).map(|x| Sym::var(&format!("exp({x})")))
    }

    /// Exact square roots of rationals (`exact_sqrt`).
    fn try_sqrt(&self) -> Option<Sym> {
        exact_sqrt(&self.as_rational()?)
    }
}

fn divide(a: &Sym, b: &Sym) -> Sym {
    a.checked_div(b)
        .unwrap_or_else(|| panic!("Sym: division of {a} by exact zero (check is_zero first)"))
}

/// Implements `op` for `Sym op Sym`, `Sym op &Sym`, `&Sym op Sym` and
/// `&Sym op &Sym` from a function on references.
macro_rules! binary_op {
    ($Trait:ident, $method:ident, $f:expr) => {
        impl $Trait<&Sym> for &Sym {
            type Output = Sym;
            fn $method(self, rhs: &Sym) -> Sym {
                let f: fn(&Sym, &Sym) -> Sym = $f;
                f(self, rhs)
            }
        }
        impl $Trait<&Sym> for Sym {
            type Output = Sym;
            fn $method(self, rhs: &Sym) -> Sym {
                (&self).$method(rhs)
            }
        }
        impl $Trait<Sym> for Sym {
            type Output = Sym;
            fn $method(self, rhs: Sym) -> Sym {
                (&self).$method(&rhs)
            }
        }
        impl $Trait<Sym> for &Sym {
            type Output = Sym;
            fn $method(self, rhs: Sym) -> Sym {
                self.$method(&rhs)
            }
        }
    };
}

binary_op!(Add, add, |a, b| a.add_signed(b, false));
binary_op!(Sub, sub, |a, b| a.add_signed(b, true));
binary_op!(Mul, mul, |a, b| a.mul_ref(b));
binary_op!(Div, div, divide);

impl Neg for Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.negated()
    }
}

impl Neg for &Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.clone().negated()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generic formula, as the catalog writes them.
    fn generic<T: Ring>(x: &T) -> T {
        let one = x.int(1);
        (x.clone() + &one) * &(x.clone() - &one) / &x.ratio(1, 2) - &x.square()
    }

    #[test]
    fn ring_constants_and_operators() {
        let m = Sym::var("m");
        // 2(m² − 1) − m² = m² − 2
        assert_eq!(generic(&m), m.clone() * &m - &Sym::int(2));
        assert_eq!(Ring::pi(&m), Sym::var("pi"));
        assert!(Ring::is_zero(&(m.clone() - m.clone())));
        assert_eq!(m.powi(3), &(&m * &m) * &m);
        assert_eq!(-&m + m.clone(), Sym::zero());
        assert_eq!(
            Ring::rational(&m, &Rational::from((2, 3))),
            Sym::int(2) / Sym::int(3)
        );
        assert_eq!(symbolic_atoms().t, Sym::var("t"));
    }

    #[test]
    fn transcendental_atoms() {
        let half = Sym::var("alpha") / &Sym::int(2);
        let (s, c) = half.try_sin_cos().unwrap();
        assert_eq!(
            (s.to_string(), c.to_string()),
            ("sin(alpha/2)".into(), "cos(alpha/2)".into())
        );
        // the pair obeys sin² + cos² = 1 in the normal form
        assert_eq!(s.clone() * &s + &(c.clone() * &c), Sym::one());
        assert_eq!(Sym::var("beta").try_exp().unwrap().to_string(), "exp(beta)");
        let three_halves_pi = Sym::pi() * &Sym::int(3) / &Sym::int(2);
        assert_eq!(
            three_halves_pi.try_sin_cos(),
            Some((Sym::int(-1), Sym::int(0)))
        );
        assert_eq!(Sym::zero().try_exp(), Some(Sym::one()));
        assert!(
            (Sym::var("alpha") * &Sym::var("beta"))
                .try_sin_cos()
                .is_none()
        );
        assert!(Sym::var("t").try_sin_cos().is_none());
        assert!((Sym::pi() / &Sym::int(5)).try_sin_cos().is_none());
        // exact values at multiples of π/12: sin(π/4) = √2/2, and
        // sin²(π/12) + cos²(π/12) = 1 in the normal form
        let (s4, c4) = (Sym::pi() / &Sym::int(4)).try_sin_cos().unwrap();
        assert_eq!(s4, c4);
        assert_eq!(s4.clone() * &s4, Sym::rational(Rational::from((1, 2))));
        for k in 0..24 {
            let (s, c) = (Sym::pi() * &Sym::int(k) / &Sym::int(12))
                .try_sin_cos()
                .unwrap();
            assert_eq!(s.clone() * &s + &(c.clone() * &c), Sym::one(), "k = {k}");
            let numeric = (k as f64 * std::f64::consts::PI / 12.0).sin();
            let value = s.eval(&0.0_f64, &|n| match n {
                "sqrt(2)" => Some(2f64.sqrt()),
                "sqrt(3)" => Some(3f64.sqrt()),
                _ => None,
            });
            assert!((value.unwrap() - numeric).abs() < 1e-15, "k = {k}");
        }
        // sin(π/6 + π/4) = sin(5π/12) by the addition formula
        let (s6, c6) = (Sym::pi() / &Sym::int(6)).try_sin_cos().unwrap();
        let (s5, _) = (Sym::pi() * &Sym::int(5) / &Sym::int(12))
            .try_sin_cos()
            .unwrap();
        assert_eq!(s6 * &c4 + &(c6 * &s4), s5);
        // square roots
        let r = Sym::rational(Rational::from((8, 3))).try_sqrt().unwrap();
        assert_eq!(r.clone() * &r, Sym::rational(Rational::from((8, 3))));
        assert_eq!(r.to_string(), "2/3*sqrt(2)*sqrt(3)");
        assert!(Sym::int(11).try_sqrt().is_none() && Sym::int(-4).try_sqrt().is_none());
        assert_eq!(Sym::int(49).try_sqrt(), Some(Sym::int(7)));
    }

    /// √0 is the value 0 (it used to loop: 0 is divisible by every prime).
    #[test]
    fn the_square_root_of_zero_is_zero() {
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send((Sym::zero().try_sqrt(), Sym::int(3).try_sqrt()));
        });
        let (zero, three) = rx
            .recv_timeout(std::time::Duration::from_secs(10))
            .expect("sqrt(0) returns");
        assert_eq!(zero, Some(Sym::zero()));
        assert_eq!(three.map(|r| r.to_string()), Some("sqrt(3)".into()));
    }
}
